namespace SphFluid.Simulation
{
    /// <summary>Names of the pipeline's passes: the GPU timing ranges (BeginSample) and the plan's pass list.</summary>
    public static class PassNames
    {
        public const string UploadContainer = "UploadContainer";
        public const string PlaceBoundary = "PlaceBoundary";
        public const string DensityRate = "DensityRate";
        public const string HalfStep = "HalfStep";
        public const string HalfKick = "HalfKick";
        public const string HalfDrift = "HalfDrift";
        public const string Sort = "Sort";
        public const string DensityPressure = "DensityPressure";
        public const string WallPressure = "WallPressure";
        public const string Normals = "Normals";
        public const string Rotations = "Rotations";
        public const string Forces = "Forces";
        public const string FullStep = "FullStep";
        public const string NonPressureForces = "NonPressureForces";
        public const string PredictVelocity = "PredictVelocity";
        public const string ViscositySolve = "ViscositySolve";
        public const string DensitySolve = "DensitySolve";
        public const string Drift = "Drift";
        public const string FindNeighbours = "FindNeighbours";
        public const string DensityFactor = "DensityFactor";
        public const string DivergenceSolve = "DivergenceSolve";
        public const string ParticleShift = "ParticleShift";
        public const string ApplyShift = "ApplyShift";
        public const string MotionReduction = "MotionReduction";
        public const string Diagnostics = "Diagnostics";
    }

    /// <summary>The <c>multi_compile_local</c> keywords of FluidSolver.compute.</summary>
    public static class SolverKeywords
    {
        public const string Multiphase = "MULTIPHASE";
        public const string SurfaceTension = "SURFACE_TENSION";
        public const string Xsph = "XSPH";
        public const string Obstacles = "OBSTACLES";

        public static readonly string[] All = { Multiphase, SurfaceTension, Xsph, Obstacles };
    }
}
