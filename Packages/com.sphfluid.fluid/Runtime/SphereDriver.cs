using SphFluid.Simulation;
using UnityEngine;

namespace SphFluid.Runtime
{
    /// <summary>
    /// Drives its Transform (a <see cref="SphereObstacle"/>) back and forth along a straight path through the fluid by
    /// the core's <see cref="SphereDrive"/> law, the same law the headless runner applies.
    /// </summary>
    public sealed class SphereDriver : MonoBehaviour
    {
        [SerializeField, Tooltip("The drive: travel, period and start delay, each declared once in SphereDrive.")]
        SphereDrive drive = new SphereDrive();

        Vector3 _start;
        double _elapsed;

        /// <summary>The law, for scripts; a change applies from the next frame.</summary>
        public SphereDrive Drive => drive;

        void OnEnable()
        {
            _start = transform.position;
            _elapsed = 0.0;
        }

        void Update()
        {
            _elapsed += Time.deltaTime;
            transform.position = _start + drive.Offset(_elapsed).ToUnity();
        }

        void OnValidate() => ComponentValidation.Log(drive.Validate($"SphereDriver '{name}'"), this);
    }
}
