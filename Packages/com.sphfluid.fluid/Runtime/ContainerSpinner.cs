using SphFluid.Simulation;
using UnityEngine;

namespace SphFluid.Runtime
{
    /// <summary>Spins its Transform (the rotating-container scene's box) by the core's <see cref="SpinLaw"/>,
    /// the same law the headless runner applies, about a world axis through its own position, on the fluid's simulated
    /// time (<see cref="FluidClock"/>): a hitch, a pause or a single step turns it as far as the fluid.</summary>
    [AddComponentMenu("SPH Fluid/Container Spinner")]
    public sealed class ContainerSpinner : MonoBehaviour
    {
        [SerializeField, Tooltip("The spin: axis, angular speed and start delay, each declared once in SpinLaw.")]
        SpinLaw spin = new SpinLaw();

        [SerializeField, Tooltip("The fluid whose simulated time the law keeps: paused, single-stepped or slowed with it. Empty = the scene's Fluid; with none, real time.")]
        Fluid fluid = null;

        Quaternion _restRotation;
        FluidClock _clock;

        /// <summary>The law, for scripts; a change applies from the next frame.</summary>
        public SpinLaw Spin => spin;

        void OnEnable()
        {
            _restRotation = transform.rotation;
            _clock = new FluidClock(Fluid.AssignedOrFound(fluid));
        }

        void Update()
        {
            transform.rotation = spin.Turn(_clock.Tick()).ToUnity() * _restRotation;
        }

        void OnValidate() => ComponentValidation.Log(spin.Validate($"ContainerSpinner '{name}'"), this);
    }
}
