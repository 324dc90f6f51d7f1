namespace SphFluid.Simulation
{
    /// <summary>Decides from a scene which effects are simulated: the GPU only pays for what the scene asks for.</summary>
    public static class PipelinePlanner
    {
        public static SimulationPlan Plan(FluidSceneDescription scene, bool containerMoved)
        {
            var phases = scene.Phases();
            bool tension = false;
            foreach (var phase in phases)
                if (phase.SurfaceTension > 0f) tension = true;
            int obstacles = scene.Obstacles == null ? 0 : scene.Obstacles.Count;
            var settings = scene.Settings;
            return new SimulationPlan(phases.Count, obstacles, tension, settings.XsphEpsilon > 0f,
                settings.VelocityDamping > 0f, containerMoved, settings.ParticleShifting > 0f);
        }
    }
}
