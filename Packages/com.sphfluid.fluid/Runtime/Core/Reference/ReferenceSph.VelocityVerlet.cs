using System;
using SphFluid.Simulation;

namespace SphFluid.Reference
{
    /// <summary>WCSPH's sub-step in the reference: Velocity Verlet, particle shifting and delta-SPH's density rates.</summary>
    public sealed partial class ReferenceSph
    {
        /// <summary>Particle shifting (ParticleShifting.hlsl) of <paramref name="particles"/> whose number densities
        /// <paramref name="state"/> holds: dr = -A h |v| dt gradC, along (not across) free surfaces and phase interfaces,
        /// capped at 5 % of the spacing.</summary>
        public Double3[] Shifts(Particle[] particles, ReferenceState state, double dt)
        {
            int n = particles.Length;
            var shifts = new Double3[n];
            var walls = PlacedBoundary();
            double coefficient = _settings.ParticleShifting * 0.5 * _h;
            for (int i = 0; i < n; i++)
            {
                var xi = new Double3(particles[i].Position);
                double volumeI = 1.0 / state.NumberDensity[i];
                var gradient = Double3.Zero;
                var otherPhases = Double3.Zero;
                double divergence = 0;
                for (int j = 0; j < n; j++)
                {
                    var rij = xi - new Double3(particles[j].Position);
                    double r2 = rij.LengthSquared();
                    if (r2 >= _h2 || j == i) continue;
                    var g = PairGradient(rij, Math.Sqrt(r2), particles[i].Id, particles[j].Id) / state.NumberDensity[j];
                    gradient += g;
                    divergence -= Double3.Dot(rij, g);
                    if (particles[j].Phase != particles[i].Phase) otherPhases += g;
                }
                foreach (var wall in walls)
                {
                    var rib = xi - new Double3(wall.Position);
                    double r2 = rib.LengthSquared();
                    if (r2 >= _h2) continue;
                    var g = PairGradient(rib, Math.Sqrt(r2), 1, 0) * (WallWeight(wall, particles[i]) * volumeI);
                    gradient += g;
                    divergence -= Double3.Dot(rib, g);
                }
                var shift = gradient * -(coefficient * new Double3(particles[i].Velocity).Length() * dt);
                if (divergence < 2.8 && gradient.Length() > 0) shift = Tangential(shift, gradient / gradient.Length());
                if (otherPhases.Length() > 0) shift = Tangential(shift, otherPhases / otherPhases.Length());
                double cap = 0.05 * _settings.ParticleSpacing;
                double length = shift.Length();
                shifts[i] = length > cap ? shift * (cap / length) : shift;
            }
            return shifts;
        }

        static Double3 Tangential(Double3 v, Double3 n) => v - n * Double3.Dot(v, n);

        /// <summary>One Velocity Verlet sub-step as FluidSimulation runs it: kick-drift and clamp with the
        /// accelerations of <paramref name="current"/>, forces at the new positions, kick plus XSPH, damping, clamp,
        /// then the particle shift and clamp when shifting is on.
        /// Returns the new particles and their evaluated state (before the shift).</summary>
        public Particle[] Substep(Particle[] particles, ReferenceState current, double dt, bool xsph, out ReferenceState next) =>
            Substep(particles, current, dt, xsph, null, out next);

        /// <summary>As <see cref="Substep(Particle[], ReferenceState, double, bool, out ReferenceState)"/>; with
        /// <paramref name="numberDensities"/> (delta-SPH, indexed like the particles) the carried number densities are advanced
        /// in place as SphDensityDiffusion.hlsl does: half the continuity term before the drift with v + a dt / 2 and the
        /// diffusion, half after it with the half-step velocities.</summary>
        public Particle[] Substep(Particle[] particles, ReferenceState current, double dt, bool xsph, double[] numberDensities, out ReferenceState next)
        {
            int n = particles.Length;
            var moved = new Particle[n];
            var x = new Double3[n];
            var v = new Double3[n];
            for (int i = 0; i < n; i++)
                v[i] = new Double3(particles[i].Velocity) + current.Acceleration[i] * (0.5 * dt);
            if (numberDensities != null)
            {
                DensityRates(particles, v, numberDensities, out var before, out var diffusion);
                for (int i = 0; i < n; i++) numberDensities[i] += 0.5 * dt * before[i] + dt * diffusion[i];
            }
            for (int i = 0; i < n; i++)
            {
                x[i] = new Double3(particles[i].Position) + v[i] * dt;
                Clamp(ref x[i], ref v[i]);
                moved[i] = new Particle(x[i].ToVector3(), v[i].ToVector3(), particles[i].Phase, particles[i].Id);
            }
            if (numberDensities != null)
            {
                DensityRates(moved, v, numberDensities, out var after, out _);
                for (int i = 0; i < n; i++) numberDensities[i] += 0.5 * dt * after[i];
            }
            next = Evaluate(moved, true, numberDensities);
            var corrections = VelocityCorrections(moved, next, dt, xsph);
            double damping = Math.Max(0, 1 - _settings.VelocityDamping * dt);
            for (int i = 0; i < n; i++)
            {
                var vi = v[i] + next.Acceleration[i] * (0.5 * dt) + corrections[i];
                vi *= damping;
                var xi = x[i];
                Clamp(ref xi, ref vi);
                moved[i] = new Particle(xi.ToVector3(), vi.ToVector3(), particles[i].Phase, particles[i].Id);
            }
            if (_settings.ParticleShifting > 0f)
            {
                var shifts = Shifts(moved, next, dt);
                for (int i = 0; i < n; i++)
                {
                    var xi = new Double3(moved[i].Position) + shifts[i];
                    var vi = new Double3(moved[i].Velocity);
                    Clamp(ref xi, ref vi);
                    moved[i] = new Particle(xi.ToVector3(), vi.ToVector3(), moved[i].Phase, moved[i].Id);
                }
            }
            return moved;
        }

        // ------------------------------------------------------------------ delta-SPH

        /// <summary>The two terms of D delta_i / Dt (SphDensityDiffusion.hlsl) for velocities <paramref name="v"/> and carried
        /// number densities <paramref name="delta"/>: the continuity sum over fluid and boundary particles, and the diffusion
        /// xi h c0 sum_j 2 ((delta_j - delta_i) - (delta_j^H - delta_i^H)) (x_j - x_i) . gradW_ij / (r^2 + 0.01 H^2) / delta_j
        /// over the fluid, with the hydrostatic difference of the pair's mean rest density and rest number density.</summary>
        public void DensityRates(Particle[] particles, Double3[] v, double[] delta, out double[] continuity, out double[] diffusion)
        {
            int n = particles.Length;
            var walls = PlacedBoundary();
            continuity = new double[n];
            diffusion = new double[n];
            double speedOfSound = Math.Sqrt(_settings.Stiffness * _settings.Gamma / MinRestDensity());
            double coefficient = FluidSimulation.DensityDiffusionXi * 0.5 * _h * speedOfSound;
            double compliance = 1.0 / ((double)_settings.Gamma * _settings.Stiffness);
            var gravity = new Double3(_settings.Gravity);
            for (int i = 0; i < n; i++)
            {
                var xi = new Double3(particles[i].Position);
                var phaseI = _phases[particles[i].Phase];
                double rate = 0, diffuse = 0;
                for (int j = 0; j < n; j++)
                {
                    if (j == i) continue;
                    var rij = xi - new Double3(particles[j].Position);
                    double r2 = rij.LengthSquared();
                    if (r2 >= _h2) continue;
                    var gradient = PairGradient(rij, Math.Sqrt(r2), particles[i].Id, particles[j].Id);
                    rate += Double3.Dot(v[i] - v[j], gradient);
                    var phaseJ = _phases[particles[j].Phase];
                    double restNumberDensity = 0.5 * (phaseI.RestDensity / (double)phaseI.ParticleMass + phaseJ.RestDensity / (double)phaseJ.ParticleMass);
                    double restDensity = 0.5 * ((double)phaseI.RestDensity + phaseJ.RestDensity);
                    double hydrostatic = -restNumberDensity * restDensity * compliance * Double3.Dot(gravity, rij);
                    double psi = 2.0 * ((delta[j] - delta[i]) - hydrostatic);
                    diffuse += psi * -Double3.Dot(rij, gradient) / ((r2 + 0.01 * _h2) * delta[j]);
                }
                foreach (var wall in walls)
                {
                    var rib = xi - new Double3(wall.Position);
                    double r2 = rib.LengthSquared();
                    if (r2 >= _h2) continue;
                    rate += WallWeight(wall, particles[i]) * Double3.Dot(v[i] - new Double3(wall.Velocity), PairGradient(rib, Math.Sqrt(r2), 1, 0));
                }
                continuity[i] = rate;
                diffusion[i] = coefficient * diffuse;
            }
        }
    }
}
