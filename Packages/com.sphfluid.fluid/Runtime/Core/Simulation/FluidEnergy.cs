using System.Collections.Generic;
using System.Numerics;

namespace SphFluid.Simulation
{
    /// <summary>
    /// Mechanical energy of the particles, summed in double precision on the host from a particle read-back:
    /// kinetic sum m v^2 / 2 plus gravitational potential -sum m g . x (zero at the world origin; only its
    /// change matters). The elastic energy stored in compression is left out, so a fluid that only falls,
    /// compresses and splashes never gains mechanical energy beyond what its spawn state stored.
    /// </summary>
    public static class FluidEnergy
    {
        /// <summary>Kinetic plus potential energy, J; NaN when a particle is non-finite.</summary>
        public static double Mechanical(IReadOnlyList<Particle> particles, IReadOnlyList<PhaseProperties> phases, Vector3 gravity)
        {
            double total = 0.0;
            for (int i = 0; i < particles.Count; i++)
            {
                var p = particles[i];
                double m = phases[(int)p.Phase].ParticleMass;
                double v2 = (double)p.Velocity.X * p.Velocity.X + (double)p.Velocity.Y * p.Velocity.Y + (double)p.Velocity.Z * p.Velocity.Z;
                double height = -((double)gravity.X * p.Position.X + (double)gravity.Y * p.Position.Y + (double)gravity.Z * p.Position.Z);
                total += m * (0.5 * v2 + height);
            }
            return total;
        }
    }
}
