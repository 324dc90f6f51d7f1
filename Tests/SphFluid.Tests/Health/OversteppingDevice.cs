using SphFluid.Compute;

namespace SphFluid.Tests.Health
{
    /// <summary>
    /// A device that runs every sub-step <see cref="Factor"/> times longer than the solver asked for: the kind of
    /// bug a broken time-step controller would be. No scene that validation lets through is unstable on its own,
    /// so this is how a test proves the health check catches a blow-up through the runner.
    /// </summary>
    sealed class OversteppingDevice : ForwardingDevice
    {
        readonly int _timeStepId;

        public OversteppingDevice(IComputeDevice inner, float factor) : base(inner)
        {
            Factor = factor;
            _timeStepId = inner.PropertyId("_TimeStep");
        }

        public float Factor { get; }

        public override void SetFloat(IComputeProgram program, int propertyId, float value) =>
            Inner.SetFloat(program, propertyId, propertyId == _timeStepId ? value * Factor : value);
    }
}
