using UnityEngine;

namespace SphFluid.Runtime
{
    /// <summary>
    /// Drives its Transform (a <see cref="SphereObstacle"/>) back and forth along a straight path through the
    /// fluid: position = start + travel * (1 - cos(2 pi t / period)) / 2, so it starts and turns at rest.
    /// </summary>
    public sealed class SphereDriver : MonoBehaviour
    {
        [SerializeField, Tooltip("From the start position to the far end of the path, m, world space.")]
        Vector3 travel = new Vector3(0.3f, 0f, 0f);

        [SerializeField, Min(0.1f), Tooltip("Seconds for one trip there and back, at least 0.1.")]
        float period = 4f;

        [SerializeField, Min(0f), Tooltip("Seconds after start before moving, so the fluid can settle first.")]
        float startDelay = 1f;

        Vector3 _start;
        float _elapsed;

        void OnEnable()
        {
            _start = transform.position;
            _elapsed = 0f;
        }

        void Update()
        {
            _elapsed += Time.deltaTime;
            float t = _elapsed - startDelay;
            if (t < 0f || period < 0.1f) return;
            float along = 0.5f - 0.5f * Mathf.Cos(2f * Mathf.PI * t / period);
            transform.position = _start + travel * along;
        }

        void OnValidate()
        {
            if (!(period >= 0.1f))
                Debug.LogError($"SphereDriver '{name}': period must be at least 0.1 s (was {period})", this);
        }
    }
}
