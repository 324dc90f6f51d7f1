using SphFluid.Simulation;
using UnityEngine;

namespace SphFluid.Runtime
{
    /// <summary>
    /// Drives its Transform (a <see cref="SphereObstacle"/>) back and forth along a straight path through the fluid by
    /// the core's <see cref="DriveLaw"/>, the same law the headless runner applies, on the fluid's simulated
    /// time (<see cref="FluidClock"/>): a hitch, a pause or a single step moves the sphere as far as the fluid.
    /// </summary>
    [AddComponentMenu("SPH Fluid/Sphere Driver")]
    public sealed class SphereDriver : MonoBehaviour
    {
        [SerializeField, Tooltip("The drive: travel, period and start delay, each declared once in DriveLaw.")]
        DriveLaw drive = new DriveLaw();

        [SerializeField, Tooltip("The fluid whose simulated time the law keeps: paused, single-stepped or slowed with it. Empty = the scene's Fluid; with none, real time.")]
        Fluid fluid = null;

        Vector3 _start;
        FluidClock _clock;

        /// <summary>The law, for scripts; a change applies from the next frame.</summary>
        public DriveLaw Drive => drive;

        void OnEnable()
        {
            _start = transform.position;
            _clock = new FluidClock(Fluid.AssignedOrFound(fluid));
        }

        void Update()
        {
            transform.position = _start + drive.Offset(_clock.Tick()).ToUnity();
        }

        void OnValidate() => ComponentValidation.Log(drive.Validate($"SphereDriver '{name}'"), this);
    }
}
