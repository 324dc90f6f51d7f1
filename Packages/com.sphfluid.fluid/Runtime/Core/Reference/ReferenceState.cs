namespace SphFluid.Reference
{
    /// <summary>Per-particle results of <see cref="ReferenceSph.Evaluate"/>, indexed like its input.</summary>
    public sealed class ReferenceState
    {
        public readonly double[] NumberDensity, Density, Pressure;
        public readonly Double3[] Normal, Acceleration, Xsph;

        /// <summary>Pressure + viscosity + tension force on each particle, N (no gravity, no boundary):
        /// sums to zero by Newton's third law.</summary>
        public readonly Double3[] InternalForce;

        public ReferenceState(int count)
        {
            NumberDensity = new double[count];
            Density = new double[count];
            Pressure = new double[count];
            Normal = new Double3[count];
            Acceleration = new Double3[count];
            Xsph = new Double3[count];
            InternalForce = new Double3[count];
        }
    }
}
