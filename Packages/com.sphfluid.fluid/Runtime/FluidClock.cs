using UnityEngine;

namespace SphFluid.Runtime
{
    /// <summary>
    /// The seconds a law of motion (<see cref="SphereDriver"/>, <see cref="ContainerSpinner"/>) has run, kept on a
    /// fluid's simulated time rather than the player's: it stands still while the fluid is paused or not running, moves
    /// one <see cref="Fluid.SingleStepSeconds"/> on a single step, and slows with the fluid when the sub-step cap holds
    /// it below real time. With no fluid it is real time.
    /// </summary>
    sealed class FluidClock
    {
        readonly Fluid _fluid;
        double _seconds;      // the law's time when the fluid stood at _fluidSeconds
        double _fluidSeconds;

        public FluidClock(Fluid fluid)
        {
            _fluid = fluid;
            _fluidSeconds = fluid != null ? fluid.SimulatedTime : 0.0;
        }

        /// <summary>Once a frame, from an Update that runs before the fluid's: the law's time where the fluid will
        /// stand after this frame.</summary>
        public double Tick()
        {
            if (_fluid == null) // none assigned or found, or destroyed since
            {
                _seconds += Time.deltaTime;
                return _seconds;
            }
            // Advanced by what the fluid simulated since the last frame, not by what it was told to: the two differ
            // when the sub-step cap bound. A respawn starts the fluid's time over; the law goes on from where it stands.
            double now = _fluid.SimulatedTime;
            if (now > _fluidSeconds) _seconds += now - _fluidSeconds;
            _fluidSeconds = now;
            return _seconds + _fluid.FrameSeconds;
        }
    }
}
