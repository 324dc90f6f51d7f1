using System.Collections.Generic;

namespace SphFluid.Simulation
{
    /// <summary>
    /// Effects to run although the scene does not need them: the benchmark's way to measure what each decision of
    /// <see cref="PipelinePlanner"/> saves, by timing the same scene with that effect forced on. A simulation never
    /// needs this; forcing changes cost only, not the result (a forced effect runs with the scene's zero coefficients).
    /// </summary>
    public sealed class PlanOverrides
    {
        /// <summary>The MULTIPHASE variant for a single phase (per-neighbour phase lookups and viscosity mixing).</summary>
        public bool Multiphase { get; set; }

        /// <summary>The normals pass and SURFACE_TENSION variant with every tension coefficient 0.</summary>
        public bool SurfaceTension { get; set; }

        /// <summary>The XSPH variant with the scene's XsphEpsilon (0 adds nothing).</summary>
        public bool Xsph { get; set; }

        /// <summary>The OBSTACLES variant without spheres (the sphere loop and clamp over none).</summary>
        public bool Obstacles { get; set; }

        /// <summary>The container treated as moving every frame: its transform uploaded and its wall particles placed
        /// and sorted again.</summary>
        public bool ContainerMoving { get; set; }

        public bool Any => Multiphase || SurfaceTension || Xsph || Obstacles || ContainerMoving;

        public override string ToString()
        {
            var on = new List<string>();
            if (Multiphase) on.Add("multiphase");
            if (SurfaceTension) on.Add("surface tension");
            if (Xsph) on.Add("XSPH");
            if (Obstacles) on.Add("obstacles");
            if (ContainerMoving) on.Add("moving container");
            return on.Count == 0 ? "none" : string.Join(", ", on);
        }
    }
}
