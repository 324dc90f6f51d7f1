using UnityEngine;

namespace SphFluid.Runtime
{
    /// <summary>Spins its Transform (the rotating-container scene's box) at a steady angular speed.</summary>
    public sealed class ContainerSpinner : MonoBehaviour
    {
        [SerializeField, Tooltip("Axis of rotation, world space (need not be normalised).")]
        Vector3 axis = Vector3.forward;

        [SerializeField, Range(-360f, 360f), Tooltip("Angular speed, degrees per second; negative turns the other way.")]
        float angularSpeed = 30f;

        [SerializeField, Min(0f), Tooltip("Seconds after start before spinning, so the fluid can settle first.")]
        float startDelay = 1f;

        float _elapsed;

        public float AngularSpeed => angularSpeed;

        void OnEnable() => _elapsed = 0f;

        void Update()
        {
            _elapsed += Time.deltaTime;
            if (_elapsed < startDelay || axis.sqrMagnitude < 1e-12f) return;
            transform.Rotate(axis.normalized, angularSpeed * Time.deltaTime, Space.World);
        }

        void OnValidate()
        {
            if (axis.sqrMagnitude < 1e-12f)
                Debug.LogError($"ContainerSpinner '{name}': axis must be non-zero (was {axis})", this);
        }
    }
}
