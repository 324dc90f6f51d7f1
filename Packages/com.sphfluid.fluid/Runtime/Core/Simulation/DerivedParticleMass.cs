namespace SphFluid.Simulation
{
    /// <summary>
    /// The particle mass of a phase whose ParticleMass is 0: rest density times the volume each of its spawned
    /// particles stands for, so every spawn box carries rest density times its own volume at any spacing.
    /// </summary>
    /// <remarks>
    /// A phase's boxes fill their volume V_b with N_b lattice points (<see cref="SpawnLayout"/>), each standing for
    /// the cell c = sum V_b / sum N_b. Summation density gives that lattice a number density of delta0 s^3 / c, with
    /// delta0 the kernel sum on the cubic lattice of spacing s, so the mass m = (rho0 / delta0) (c / s^3) starts it
    /// at rest density. The cubic spline sums to 1 / s^3 on its lattice to 1e-4 (delta0 s^3 = 1), so m = rho0 c
    /// to that accuracy and the phase's mass is rho0 sum V_b. When a phase spans several boxes their cells differ
    /// by the rounding of the counts (kept small by choosing the counts that bring each cell closest to s^3), and
    /// the shared mass is exact for the phase as a whole. Particles a sphere obstacle displaces at spawn take their
    /// mass with them: the sphere displaces that fluid.
    /// </remarks>
    public static class DerivedParticleMass
    {
        /// <summary>Derived mass of <paramref name="phase"/>'s particles, kg; rho0 / delta0 if no box of it spawns any.</summary>
        public static double Of(FluidSceneDescription scene, PhaseDescription phase)
        {
            double nominal = phase.RestDensity / scene.RestNumberDensity();
            double volume = 0.0, count = 0.0;
            foreach (var box in scene.SpawnBoxes)
            {
                if (box?.Phase == null || box.Phase.Name != phase.Name) continue;
                long n = SpawnLayout.Count(scene.Settings, box);
                if (n <= 0) continue;
                volume += (double)box.Size.X * box.Size.Y * box.Size.Z;
                count += n;
            }
            if (count <= 0) return nominal;
            double s = scene.Settings.ParticleSpacing;
            return nominal * (volume / count) / (s * s * s);
        }
    }
}
