using System.Collections.Generic;
using System.Text;

namespace SphFluid.Simulation
{
    /// <summary>
    /// Which effects a scene needs, hence which keyword variants and passes run: the planner's answer,
    /// a value tests inspect and the headless runner prints.
    /// </summary>
    public sealed class SimulationPlan
    {
        public int PhaseCount { get; }
        public int ObstacleCount { get; }

        /// <summary>More than one phase: per-neighbour phase lookups and viscosity mixing (MULTIPHASE).</summary>
        public bool Multiphase { get; }

        /// <summary>Some phase has SurfaceTension &gt; 0: normals pass and cohesion/curvature (SURFACE_TENSION).</summary>
        public bool SurfaceTension { get; }

        /// <summary>XsphEpsilon &gt; 0: XSPH velocity correction in the force pass (XSPH).</summary>
        public bool Xsph { get; }

        /// <summary>At least one sphere obstacle: its boundary particles are placed and sorted every frame it moves,
        /// and the sphere clamp runs (OBSTACLES).</summary>
        public bool Obstacles { get; }

        /// <summary>The pressure solver whose passes run: WCSPH's equation of state or DFSPH's two iterative solves.</summary>
        public PressureSolver PressureSolver { get; }

        /// <summary>ParticleShifting &gt; 0: the shift passes run after every sub-step.</summary>
        public bool Shifting { get; }

        /// <summary>WCSPH with WcsphDensity = DeltaSph: the number density is carried and integrated (SphDensityDiffusion.hlsl),
        /// with the DensityRate pass before the drift.</summary>
        public bool DeltaSph { get; }

        /// <summary>WCSPH's neighbour passes read lists that FindNeighbours fills after each sort (NeighbourCapacity.InUse:
        /// one lane per particle); DFSPH's always do.</summary>
        public bool NeighbourLists { get; }

        /// <summary>Sub-steps may pass the explicit viscous limit: those solve the viscosity implicitly
        /// (<see cref="Simulation.ImplicitViscosity"/>), DFSPH's after its constant-density solve, WCSPH's after each half kick.</summary>
        public bool ImplicitViscosity { get; }

        /// <summary>The physical viscosity is the strain rate's stress (<see cref="ViscousStress.StrainRate"/>) and some phase
        /// has one: a Rotations pass before the forces finds each particle's rigid rotation, which the viscous pair term leaves
        /// out (SphViscosity.hlsl).</summary>
        public bool StrainRateViscosity { get; }

        /// <summary>VelocityDamping &gt; 0.</summary>
        public bool Damping { get; }

        /// <summary>The container moved since the last frame: its transform is uploaded again.</summary>
        public bool UploadContainerTransform { get; }

        /// <summary>Enabled keywords of FluidSolver.compute (a subset of <see cref="SolverKeywords.All"/>).</summary>
        public IReadOnlyList<string> Keywords { get; }

        /// <summary>The passes of one sub-step, in dispatch order (<see cref="PassNames"/>).</summary>
        public IReadOnlyList<string> SubstepPasses { get; }

        /// <summary>The passes run once per frame, in order (before and after the sub-steps).</summary>
        public IReadOnlyList<string> FramePasses { get; }

        /// <param name="forceMultiphase">Run the MULTIPHASE variant for one phase (<see cref="PlanOverrides"/>).</param>
        /// <param name="forceObstacles">Run the OBSTACLES variant without spheres (<see cref="PlanOverrides"/>).</param>
        /// <param name="shifting">Run the particle-shifting passes after each WCSPH sub-step (ParticleShifting &gt; 0).</param>
        /// <param name="deltaSph">WCSPH carries the number density (WcsphDensity = DeltaSph).</param>
        /// <param name="neighbourLists">WCSPH's passes read neighbour lists (DFSPH's always do).</param>
        /// <param name="implicitViscosity">Sub-steps may pass the explicit viscous limit.</param>
        /// <param name="strainRateViscosity">The physical viscosity is the strain rate's stress and some phase has one.</param>
        public SimulationPlan(int phaseCount, int obstacleCount, bool surfaceTension, bool xsph, bool damping, bool uploadContainerTransform,
            PressureSolver pressureSolver = PressureSolver.Wcsph, bool forceMultiphase = false, bool forceObstacles = false, bool shifting = false,
            bool deltaSph = false, bool neighbourLists = false, bool implicitViscosity = false, bool strainRateViscosity = false)
        {
            StrainRateViscosity = strainRateViscosity;
            ImplicitViscosity = implicitViscosity;
            NeighbourLists = neighbourLists || pressureSolver == PressureSolver.Dfsph;
            PressureSolver = pressureSolver;
            Shifting = shifting && pressureSolver == PressureSolver.Wcsph;
            DeltaSph = deltaSph && pressureSolver == PressureSolver.Wcsph;
            PhaseCount = phaseCount;
            ObstacleCount = obstacleCount;
            Multiphase = phaseCount > 1 || forceMultiphase;
            SurfaceTension = surfaceTension;
            Xsph = xsph;
            Obstacles = obstacleCount > 0 || forceObstacles;
            Damping = damping;
            UploadContainerTransform = uploadContainerTransform;

            var keywords = new List<string>();
            if (Multiphase) keywords.Add(SolverKeywords.Multiphase);
            if (SurfaceTension) keywords.Add(SolverKeywords.SurfaceTension);
            if (Xsph) keywords.Add(SolverKeywords.Xsph);
            if (Obstacles) keywords.Add(SolverKeywords.Obstacles);
            Keywords = keywords;

            var passes = new List<string>();
            if (pressureSolver == PressureSolver.Dfsph)
            {
                // Symplectic Euler around the two solves (FluidSolver.compute): forces at the sub-step's start.
                if (SurfaceTension) passes.Add(PassNames.Normals);
                if (StrainRateViscosity) passes.Add(PassNames.Rotations);
                passes.Add(PassNames.NonPressureForces);
                passes.Add(PassNames.PredictVelocity);
                passes.Add(PassNames.DensitySolve);
                if (ImplicitViscosity) passes.Add(PassNames.ViscositySolve);
                passes.Add(PassNames.Drift);
                passes.Add(PassNames.Sort);
                passes.Add(PassNames.FindNeighbours);
                passes.Add(PassNames.DensityFactor);
                passes.Add(PassNames.DivergenceSolve);
            }
            else
            {
                if (ImplicitViscosity)
                {
                    // While the step passes the viscous limit; below it DensityRate and HalfStep run as in the other
                    // branch and Forces takes the viscosity. DensityRate reads the velocity the solve leaves.
                    passes.Add(PassNames.HalfKick);
                    passes.Add(PassNames.ViscositySolve);
                    if (DeltaSph) passes.Add(PassNames.DensityRate);
                    passes.Add(PassNames.HalfDrift);
                }
                else
                {
                    if (DeltaSph) passes.Add(PassNames.DensityRate);
                    passes.Add(PassNames.HalfStep);
                }
                passes.Add(PassNames.Sort);
                if (NeighbourLists) passes.Add(PassNames.FindNeighbours);
                passes.Add(PassNames.DensityPressure);
                passes.Add(PassNames.WallPressure);
                if (SurfaceTension) passes.Add(PassNames.Normals);
                if (StrainRateViscosity) passes.Add(PassNames.Rotations);
                passes.Add(PassNames.Forces);
                passes.Add(PassNames.FullStep);
                if (ImplicitViscosity) passes.Add(PassNames.ViscositySolve);
                if (Shifting)
                {
                    passes.Add(PassNames.ParticleShift);
                    passes.Add(PassNames.ApplyShift);
                }
            }
            SubstepPasses = passes;

            var frame = new List<string>();
            if (UploadContainerTransform) frame.Add(PassNames.UploadContainer);
            if (UploadContainerTransform || Obstacles) frame.Add(PassNames.PlaceBoundary);
            frame.Add(PassNames.MotionReduction);
            FramePasses = frame;
        }

        public bool IsKeywordEnabled(string keyword) => ((List<string>)Keywords).Contains(keyword);

        public bool Runs(string pass) => ((List<string>)SubstepPasses).Contains(pass) || ((List<string>)FramePasses).Contains(pass);

        public override string ToString()
        {
            var b = new StringBuilder();
            b.Append("plan: ").Append(PhaseCount).Append(PhaseCount == 1 ? " phase, " : " phases, ")
             .Append(ObstacleCount).Append(ObstacleCount == 1 ? " obstacle" : " obstacles");
            b.Append(" | solver: ").Append(PressureSolver == PressureSolver.Dfsph ? "DFSPH" : "WCSPH");
            if (StrainRateViscosity) b.Append(" | viscous stress: strain rate");
            if (ImplicitViscosity) b.Append(" | viscosity: implicit beyond its explicit step");
            b.Append(" | variants: ").Append(Keywords.Count == 0 ? "(none)" : string.Join(" ", Keywords));
            b.Append(" | sub-step: ").Append(string.Join(" > ", SubstepPasses));
            b.Append(" | damping: ").Append(Damping ? "on" : "off");
            b.Append(" | container transform: ").Append(UploadContainerTransform ? "upload" : "unchanged");
            return b.ToString();
        }
    }
}
