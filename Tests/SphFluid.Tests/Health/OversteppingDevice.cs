using SphFluid.Compute;
using SphFluid.Simulation;

namespace SphFluid.Tests.Health
{
    /// <summary>
    /// A device that runs every sub-step <see cref="Factor"/> times longer than the solver asked for: the kind of
    /// bug a broken time-step controller would be. No scene that validation lets through is unstable on its own,
    /// so this is how a test proves the health check catches a blow-up through the runner.
    /// </summary>
    sealed class OversteppingDevice : ForwardingDevice
    {
        public OversteppingDevice(IComputeDevice inner, float factor) : base(inner)
        {
            Factor = factor;
        }

        public float Factor { get; }

        /// <summary>The solver's time step travels in its constant buffer (FluidConstants): each upload of it is
        /// stretched on the way to the GPU, while the simulation keeps planning with the step it chose.</summary>
        public override void UpdateBuffer<T>(IComputeBuffer buffer, T[] data)
        {
            if (data is FluidConstants[] constants)
            {
                var stretched = (FluidConstants[])constants.Clone();
                stretched[0].TimeStep *= Factor;
                Inner.UpdateBuffer(buffer, stretched);
                return;
            }
            Inner.UpdateBuffer(buffer, data);
        }
    }
}
