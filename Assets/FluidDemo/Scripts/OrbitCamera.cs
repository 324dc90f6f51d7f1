using UnityEngine;
using UnityEngine.InputSystem;

namespace SphFluid.Demo
{
    /// <summary>Orbits its Transform (the camera) around a pivot: drag with the right mouse button, zoom with the wheel.</summary>
    public sealed class OrbitCamera : MonoBehaviour
    {
        // Each range is declared once: the inspector clamps what is typed there (a slider, or the distances' Min), OnValidate
        // refuses a scene file's hand-edited value outside it, and the orbit uses the value clamped into it.
        const float MinOrbitSpeed = 0.01f, MaxOrbitSpeed = 2f;
        const float MinZoomStep = 0.01f, MaxZoomStep = 0.5f;
        const float MinDistanceLimit = 0.01f, MaxDistanceLimit = 10000f;
        const float PitchLimit = 89f;

        [SerializeField, Tooltip("The point orbited and looked at, m, world space.")]
        Vector3 pivot = new Vector3(0f, 0.25f, 0f);

        [SerializeField, Range(MinOrbitSpeed, MaxOrbitSpeed), Tooltip("Degrees turned per pixel of mouse movement.")]
        float orbitSpeed = 0.25f;

        [SerializeField, Range(MinZoomStep, MaxZoomStep), Tooltip("Fraction of the distance one wheel notch zooms.")]
        float zoomStep = 0.1f;

        [SerializeField, Min(MinDistanceLimit), Tooltip("Closest distance to the pivot, m.")]
        float minDistance = 0.2f;

        [SerializeField, Min(MinDistanceLimit), Tooltip("Farthest distance from the pivot, m.")]
        float maxDistance = 20f;

        [SerializeField, Range(-PitchLimit, PitchLimit), Tooltip("Lowest elevation, degrees (negative looks up from below).")]
        float minPitch = -80f;

        [SerializeField, Range(-PitchLimit, PitchLimit), Tooltip("Highest elevation, degrees.")]
        float maxPitch = 85f;

        InputAction _orbit, _look, _zoom;
        float _yaw, _pitch, _distance;

        float Closest => Within(minDistance, MinDistanceLimit, MaxDistanceLimit);
        float Farthest => Within(maxDistance, Closest, MaxDistanceLimit);
        float LowestPitch => Within(minPitch, -PitchLimit, PitchLimit);
        float HighestPitch => Within(maxPitch, LowestPitch, PitchLimit);
        float OrbitSpeed => Within(orbitSpeed, MinOrbitSpeed, MaxOrbitSpeed);

        /// <summary>Clamps like Mathf.Clamp, but a NaN, which Mathf.Clamp passes through, becomes <paramref name="min"/>.</summary>
        static float Within(float value, float min, float max) => value >= min ? Mathf.Min(value, max) : min;

        void OnEnable()
        {
            // Start from where the scene put the camera, looking at the pivot.
            Vector3 toPivot = pivot - transform.position;
            _distance = Mathf.Clamp(toPivot.magnitude, Closest, Farthest);
            Vector3 direction = toPivot.sqrMagnitude > 1e-12f ? toPivot.normalized : Vector3.forward;
            _pitch = Mathf.Clamp(-Mathf.Asin(Mathf.Clamp(direction.y, -1f, 1f)) * Mathf.Rad2Deg, LowestPitch, HighestPitch);
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
                    _yaw += delta.x * OrbitSpeed;
                    _pitch = Mathf.Clamp(_pitch - delta.y * OrbitSpeed, LowestPitch, HighestPitch);
                    moved = true;
                }
            }
            float scroll = _zoom.ReadValue<Vector2>().y;
            if (scroll != 0f)
            {
                // The wheel's units differ by platform and package version: one step per frame with scroll.
                float step = Within(zoomStep, MinZoomStep, MaxZoomStep);
                _distance = Mathf.Clamp(_distance * (scroll > 0f ? 1f - step : 1f / (1f - step)), Closest, Farthest);
                moved = true;
            }
            if (!moved) return; // leave the scene's framing alone until the user moves
            Quaternion rotation = Quaternion.Euler(_pitch, _yaw, 0f);
            transform.SetPositionAndRotation(pivot - rotation * Vector3.forward * _distance, rotation);
        }

        void OnValidate()
        {
            Refuse(nameof(orbitSpeed), orbitSpeed, MinOrbitSpeed, MaxOrbitSpeed, " degrees per pixel");
            Refuse(nameof(zoomStep), zoomStep, MinZoomStep, MaxZoomStep, "");
            Refuse(nameof(minDistance), minDistance, MinDistanceLimit, MaxDistanceLimit, " m");
            Refuse(nameof(maxDistance), maxDistance, MinDistanceLimit, MaxDistanceLimit, " m");
            Refuse(nameof(minPitch), minPitch, -PitchLimit, PitchLimit, " degrees");
            Refuse(nameof(maxPitch), maxPitch, -PitchLimit, PitchLimit, " degrees");
            if (!(float.IsFinite(pivot.x) && float.IsFinite(pivot.y) && float.IsFinite(pivot.z)))
                Debug.LogError($"OrbitCamera '{name}': pivot must be finite (was {pivot})", this);
            if (minPitch > maxPitch)
                Debug.LogError($"OrbitCamera '{name}': minPitch must be <= maxPitch (was {minPitch} > {maxPitch})", this);
            if (minDistance > maxDistance)
                Debug.LogError($"OrbitCamera '{name}': minDistance must be <= maxDistance (was {minDistance} > {maxDistance})", this);
        }

        /// <summary>A value a scene file was edited to outside its slider's range; the orbit uses it clamped into the range.</summary>
        void Refuse(string field, float value, float min, float max, string unit)
        {
            if (!(value >= min && value <= max))
                Debug.LogError($"OrbitCamera '{name}': {field} must be in [{min}, {max}]{unit} (was {value}); it is used clamped into the range", this);
        }
    }
}
