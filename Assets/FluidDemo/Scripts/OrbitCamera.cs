using UnityEngine;
using UnityEngine.InputSystem;

namespace SphFluid.Demo
{
    /// <summary>Orbits its Transform (the camera) around a pivot: drag with the right mouse button, zoom with the wheel.</summary>
    public sealed class OrbitCamera : MonoBehaviour
    {
        [SerializeField, Tooltip("The point orbited and looked at, m, world space.")]
        Vector3 pivot = new Vector3(0f, 0.25f, 0f);

        [SerializeField, Range(0.01f, 2f), Tooltip("Degrees turned per pixel of mouse movement.")]
        float orbitSpeed = 0.25f;

        [SerializeField, Range(0.01f, 0.5f), Tooltip("Fraction of the distance one wheel notch zooms.")]
        float zoomStep = 0.1f;

        [SerializeField, Min(0.01f), Tooltip("Closest distance to the pivot, m.")]
        float minDistance = 0.2f;

        [SerializeField, Min(0.01f), Tooltip("Farthest distance from the pivot, m.")]
        float maxDistance = 20f;

        [SerializeField, Range(-89f, 89f), Tooltip("Lowest elevation, degrees (negative looks up from below).")]
        float minPitch = -80f;

        [SerializeField, Range(-89f, 89f), Tooltip("Highest elevation, degrees.")]
        float maxPitch = 85f;

        InputAction _orbit, _look, _zoom;
        float _yaw, _pitch, _distance;

        void OnEnable()
        {
            // Start from where the scene put the camera, looking at the pivot.
            Vector3 toPivot = pivot - transform.position;
            _distance = Mathf.Clamp(toPivot.magnitude, minDistance, Mathf.Max(minDistance, maxDistance));
            Vector3 direction = toPivot.sqrMagnitude > 1e-12f ? toPivot.normalized : Vector3.forward;
            _pitch = Mathf.Clamp(-Mathf.Asin(Mathf.Clamp(direction.y, -1f, 1f)) * Mathf.Rad2Deg, minPitch, maxPitch);
            _yaw = Mathf.Atan2(direction.x, direction.z) * Mathf.Rad2Deg;

            _orbit = new InputAction("Orbit", InputActionType.Button, "<Mouse>/rightButton");
            _look = new InputAction("Look", InputActionType.Value, "<Pointer>/delta", expectedControlType: "Vector2");
            _zoom = new InputAction("Zoom", InputActionType.Value, "<Mouse>/scroll", expectedControlType: "Vector2");
            _orbit.Enable();
            _look.Enable();
            _zoom.Enable();
        }

        void OnDisable()
        {
            _orbit?.Dispose();
            _look?.Dispose();
            _zoom?.Dispose();
            _orbit = _look = _zoom = null;
        }

        void LateUpdate()
        {
            bool moved = false;
            if (_orbit.IsPressed())
            {
                Vector2 delta = _look.ReadValue<Vector2>();
                if (delta != Vector2.zero)
                {
                    _yaw += delta.x * orbitSpeed;
                    _pitch = Mathf.Clamp(_pitch - delta.y * orbitSpeed, minPitch, maxPitch);
                    moved = true;
                }
            }
            float scroll = _zoom.ReadValue<Vector2>().y;
            if (scroll != 0f)
            {
                // The wheel's units differ by platform and package version: one step per frame with scroll.
                _distance *= scroll > 0f ? 1f - zoomStep : 1f / (1f - zoomStep);
                _distance = Mathf.Clamp(_distance, minDistance, Mathf.Max(minDistance, maxDistance));
                moved = true;
            }
            if (!moved) return; // leave the scene's framing alone until the user moves
            Quaternion rotation = Quaternion.Euler(_pitch, _yaw, 0f);
            transform.SetPositionAndRotation(pivot - rotation * Vector3.forward * _distance, rotation);
        }

        void OnValidate()
        {
            if (minPitch > maxPitch)
                Debug.LogError($"OrbitCamera '{name}': minPitch must be <= maxPitch (was {minPitch} > {maxPitch})", this);
            if (minDistance > maxDistance)
                Debug.LogError($"OrbitCamera '{name}': minDistance must be <= maxDistance (was {minDistance} > {maxDistance})", this);
        }
    }
}
