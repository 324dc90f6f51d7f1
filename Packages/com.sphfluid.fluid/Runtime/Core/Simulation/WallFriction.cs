namespace SphFluid.Simulation
{
    /// <summary>The tangential condition of the container's walls and the obstacles (SphBoundary.hlsl).</summary>
    public enum WallFriction
    {
        /// <summary>Free slip: the walls push the fluid only along their normal.</summary>
        Slip = 0,

        /// <summary>No slip: the fluid's viscosity acts against the wall's velocity, as at a real wall.</summary>
        NoSlip = 1,
    }
}
