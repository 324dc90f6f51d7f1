namespace SphFluid.Simulation
{
    /// <summary>Decides from a scene which effects are simulated: the GPU only pays for what the scene asks for.</summary>
    public static class PipelinePlanner
    {
        /// <param name="forced">Effects to run although the scene does not need them (the benchmark's measure of what
        /// each decision saves); null for none.</param>
        /// <param name="neighbourLists">WCSPH's passes read neighbour lists found after each sort (NeighbourCapacity.InUse).</param>
        public static SimulationPlan Plan(FluidSceneDescription scene, bool containerMoved, PlanOverrides forced = null, bool neighbourLists = false)
        {
            var phases = scene.Phases();
            bool tension = false;
            foreach (var phase in phases)
                if (phase.SurfaceTension > 0f) tension = true;
            int obstacles = scene.Obstacles == null ? 0 : scene.Obstacles.Count;
            var settings = scene.Settings;
            bool shifting = settings.ParticleShifting > 0f;
            bool deltaSph = settings.WcsphDensity == WcsphDensity.DeltaSph;
            // A step is as long as MaxTimeStep at most (TimeStepController), so the solve can only pay off below it.
            var timeStep = TimeStepController.ForScene(scene);
            bool implicitViscosity = ImplicitViscosity.PaysOff(settings.PressureSolver, settings.MaxTimeStep, timeStep.ViscousTimeStep,
                ImplicitViscosity.LatticeRowSum(settings.SmoothingKernel, settings.ParticleSpacing, settings.SmoothingRadius),
                timeStep.OperatorViscosity);
            bool strainRate = settings.ViscousStress == ViscousStress.StrainRate && timeStep.MaxKinematicViscosity > 0f;
            if (forced == null)
                return new SimulationPlan(phases.Count, obstacles, tension, settings.XsphEpsilon > 0f,
                    settings.VelocityDamping > 0f, containerMoved, settings.PressureSolver, shifting: shifting, deltaSph: deltaSph,
                    neighbourLists: neighbourLists, implicitViscosity: implicitViscosity, strainRateViscosity: strainRate);
            return new SimulationPlan(phases.Count, obstacles, tension || forced.SurfaceTension, settings.XsphEpsilon > 0f || forced.Xsph,
                settings.VelocityDamping > 0f, containerMoved || forced.ContainerMoving, settings.PressureSolver, forced.Multiphase, forced.Obstacles,
                shifting, deltaSph, neighbourLists, implicitViscosity, strainRate);
        }
    }
}
