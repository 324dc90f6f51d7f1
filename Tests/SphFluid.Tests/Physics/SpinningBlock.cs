using System.Numerics;
using SphFluid.Simulation;
using SphFluid.Tests.Solver;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// A cube of water 12 cm on a side, weightless, spawned on the lattice and set spinning rigidly about the vertical
    /// axis through its centre, in a container four times its side so that no wall comes near it within the runs' quarter
    /// second. Nothing outside acts on it, so its angular momentum about its centre of mass must stay what it was spawned
    /// with: the pressure and artificial viscosity are central pair forces and keep it, and a rigid rotation has no strain
    /// rate, so a Newtonian viscosity, whose stress is mu (grad v + grad v^T), does no work on it and exerts no torque.
    /// Every particle has the one phase's mass, so the sums are per unit particle mass.
    /// </summary>
    static class SpinningBlock
    {
        /// <summary>Spin, rad/s: the corners move at 0.17 m/s, and the outward pull w^2 r moves them under 1 cm in the
        /// quarter second.</summary>
        public const float Omega = 2f;

        public const float Side = 0.12f;

        public static FluidSceneDescription Scene(PressureSolver solver, float spacing, float viscosity,
            ViscousStress stress = ViscousStress.Laplacian)
        {
            var settings = SolverScenes.Coarse(spacing);
            settings.PressureSolver = solver;
            settings.ViscousStress = stress;
            settings.Gravity = Vector3.Zero;
            settings.XsphEpsilon = 0f; // XSPH's drift is not the particles' velocity; left out so the velocities carry all
            settings.MaxSubsteps = 1000;
            var block = new Vector3(Side);
            return SolverScenes.Scene(settings, 4f * block,
                SolverScenes.Box("Water", SolverScenes.Water(viscosity), Vector3.Zero, block, jitter: 0f));
        }

        /// <summary>The block's simulation with every particle set to the rigid rotation Omega about z through its centre;
        /// <paramref name="particles"/> holds them as spawned, spinning.</summary>
        public static FluidSimulation Spinning(PressureSolver solver, float spacing, float viscosity, out Particle[] particles,
            ViscousStress stress = ViscousStress.Laplacian)
        {
            var sim = new FluidSimulation(GpuTestDevice.Unvalidated, Scene(solver, spacing, viscosity, stress));
            particles = new Particle[sim.ParticleCount];
            sim.Particles.GetData(particles);
            for (int i = 0; i < particles.Length; i++)
                particles[i].Velocity = Vector3.Cross(new Vector3(0f, 0f, Omega), particles[i].Position);
            sim.SetParticles(particles);
            return sim;
        }

        /// <summary>The angular momentum about the vertical through the centre of mass, m^2/s per unit particle mass.</summary>
        public static double AngularMomentum(Particle[] particles)
        {
            Vector3 centre = Centre(particles);
            double l = 0.0;
            foreach (var p in particles)
            {
                Vector3 r = p.Position - centre;
                l += (double)r.X * p.Velocity.Y - (double)r.Y * p.Velocity.X;
            }
            return l;
        }

        /// <summary>The mean of x^2 + y^2 about the centre of mass, m^2: the moment of inertia over the mass.</summary>
        public static double MeanSquaredRadius(Particle[] particles)
        {
            Vector3 centre = Centre(particles);
            double sum = 0.0;
            foreach (var p in particles)
            {
                Vector3 r = p.Position - centre;
                sum += (double)r.X * r.X + (double)r.Y * r.Y;
            }
            return sum / particles.Length;
        }

        /// <summary>The mean velocity, m/s: the block's momentum over its mass.</summary>
        public static double Drift(Particle[] particles)
        {
            Vector3 sum = Vector3.Zero;
            foreach (var p in particles) sum += p.Velocity;
            return sum.Length() / particles.Length;
        }

        static Vector3 Centre(Particle[] particles)
        {
            Vector3 sum = Vector3.Zero;
            foreach (var p in particles) sum += p.Position;
            return sum / particles.Length;
        }
    }
}
