namespace SphFluid.Reference
{
    /// <summary>Per-particle results of <see cref="ReferenceSph.Evaluate"/>, indexed like its input.</summary>
    public sealed class ReferenceState
    {
        public readonly double[] NumberDensity, Density, Pressure;
        public readonly Double3[] Normal, Acceleration, Xsph;

        /// <summary>Each particle's rigid rotation Omega = curl v / 2, rad/s, for the strain rate's viscous stress; zero for
        /// Morris's.</summary>
        public readonly Double3[] Rotation;

        /// <summary>The wall part of each particle's continuity equation (SphBoundary.hlsl's wall contact):
        /// G_w = sum_b omega_b gradW_ib and sum_b omega_b v_b . gradW_ib.</summary>
        public readonly Double3[] WallGradientSum;
        public readonly double[] WallVelocityRate;

        /// <summary>The walls' part of each particle's number density, sum_b omega_b W_ib.</summary>
        public readonly double[] WallNumberDensity;

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
            Rotation = new Double3[count];
            WallGradientSum = new Double3[count];
            WallVelocityRate = new double[count];
            WallNumberDensity = new double[count];
            InternalForce = new Double3[count];
        }
    }
}
