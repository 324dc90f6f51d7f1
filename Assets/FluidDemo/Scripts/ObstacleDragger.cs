using SphFluid.Runtime;
using UnityEngine;
using UnityEngine.InputSystem;

namespace SphFluid.Demo
{
    /// <summary>
    /// Drags a <see cref="SphereObstacle"/> with the left mouse button: press on a sphere, move it on the plane
    /// through its centre facing the camera. The simulator turns the motion into the sphere's velocity.
    /// </summary>
    public sealed class ObstacleDragger : MonoBehaviour
    {
        [SerializeField, Tooltip("Camera the pointer looks through; empty = this object's Camera, else the main camera.")]
        Camera targetCamera = null;

        InputAction _press, _point;
        SphereObstacle _held;
        Plane _plane;
        Vector3 _grabOffset;

        void OnEnable()
        {
            _press = new InputAction("Drag", InputActionType.Button, "<Mouse>/leftButton");
            _point = new InputAction("Point", InputActionType.Value, "<Pointer>/position", expectedControlType: "Vector2");
            _press.Enable();
            _point.Enable();
        }

        void OnDisable()
        {
            _press?.Dispose();
            _point?.Dispose();
            _press = _point = null;
            _held = null;
        }

        Camera ViewCamera()
        {
            if (targetCamera != null) return targetCamera;
            // TryGetComponent: in the editor, GetComponent of a missing component makes a placeholder object every call.
            return TryGetComponent(out Camera own) ? own : Camera.main;
        }

        void Update()
        {
            Camera view = ViewCamera();
            if (view == null) return;
            Ray ray = view.ScreenPointToRay(_point.ReadValue<Vector2>());

            if (_press.WasPressedThisFrame())
            {
                _held = Pick(ray);
                if (_held != null)
                {
                    Vector3 centre = _held.transform.position;
                    _plane = new Plane(-view.transform.forward, centre);
                    _grabOffset = _plane.Raycast(ray, out float enter) ? centre - ray.GetPoint(enter) : Vector3.zero;
                }
            }
            if (_held != null && _press.IsPressed() && _plane.Raycast(ray, out float distance))
                _held.transform.position = ray.GetPoint(distance) + _grabOffset;
            if (!_press.IsPressed()) _held = null;
        }

        /// <summary>The nearest sphere the ray hits, or null.</summary>
        static SphereObstacle Pick(Ray ray)
        {
            SphereObstacle best = null;
            float bestDistance = float.PositiveInfinity;
            foreach (SphereObstacle sphere in FindObjectsByType<SphereObstacle>(FindObjectsSortMode.None))
            {
                if (!sphere.isActiveAndEnabled) continue;
                float r = sphere.WorldRadius;
                Vector3 oc = ray.origin - sphere.transform.position;
                float b = Vector3.Dot(oc, ray.direction);
                float disc = b * b - (oc.sqrMagnitude - r * r);
                if (disc < 0f) continue;
                float root = Mathf.Sqrt(disc);
                float t = -b - root;
                if (t < 0f) t = -b + root;
                if (t < 0f || t >= bestDistance) continue;
                bestDistance = t;
                best = sphere;
            }
            return best;
        }
    }
}
