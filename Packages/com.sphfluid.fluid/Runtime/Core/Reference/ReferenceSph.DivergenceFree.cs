using System;
using SphFluid.Simulation;

namespace SphFluid.Reference
{
    /// <summary>DFSPH in the reference: the factors, the two solves with the walls as unknowns, the wall contact and one sub-step.</summary>
    public sealed partial class ReferenceSph
    {
        /// <summary>The DFSPH factor alpha_i = 1 / (|G_i|^2 / m_i + sum_j |gradW_ij|^2 / m_j) (DivergenceFreeSolver.hlsl).</summary>
        public double[] DivergenceFreeFactors(Particle[] particles)
        {
            int n = particles.Length;
            var walls = PlacedBoundary();
            var factors = new double[n];
            for (int i = 0; i < n; i++)
            {
                var xi = new Double3(particles[i].Position);
                var sum = Double3.Zero;
                double squares = 0;
                for (int j = 0; j < n; j++)
                {
                    if (j == i) continue;
                    var rij = xi - new Double3(particles[j].Position);
                    double r = rij.Length();
                    if (r >= _h) continue;
                    var g = PairGradient(rij, r, particles[i].Id, particles[j].Id);
                    sum += g;
                    squares += g.LengthSquared() / _phases[particles[j].Phase].ParticleMass;
                }
                foreach (var wall in walls)
                {
                    var rib = xi - new Double3(wall.Position);
                    double r = rib.Length();
                    if (r >= _h) continue;
                    sum += PairGradient(rib, r, 1, 0) * WallWeight(wall, particles[i]);
                }
                double denominator = sum.LengthSquared() / _phases[particles[i].Phase].ParticleMass + squares;
                factors[i] = denominator > 1e-20 ? 1.0 / denominator : 0.0;
            }
            return factors;
        }

        /// <summary>Fewer neighbours than this leave a particle out of the divergence-free solve (DivergenceFreeSolver.hlsl).</summary>
        public const int DivergenceMinNeighbours = 20;

        /// <summary>D delta_i / Dt of every particle for the velocities <paramref name="v"/> (walls at their own).</summary>
        public double[] NumberDensityRates(Particle[] particles, Double3[] v) => NumberDensityRates(particles, v, out _);

        /// <summary>D delta_i / Dt, and each particle's fluid and wall neighbours within H.</summary>
        public double[] NumberDensityRates(Particle[] particles, Double3[] v, out int[] neighbours)
        {
            int n = particles.Length;
            var walls = PlacedBoundary();
            var rates = new double[n];
            neighbours = new int[n];
            for (int i = 0; i < n; i++)
            {
                var xi = new Double3(particles[i].Position);
                double rate = 0;
                for (int j = 0; j < n; j++)
                {
                    if (j == i) continue;
                    var rij = xi - new Double3(particles[j].Position);
                    double r = rij.Length();
                    if (r >= _h) continue;
                    rate += Double3.Dot(v[i] - v[j], PairGradient(rij, r, particles[i].Id, particles[j].Id));
                    neighbours[i]++;
                }
                foreach (var wall in walls)
                {
                    var rib = xi - new Double3(wall.Position);
                    double r = rib.Length();
                    if (r >= _h) continue;
                    rate += WallWeight(wall, particles[i]) * Double3.Dot(v[i] - new Double3(wall.Velocity), PairGradient(rib, r, 1, 0));
                    neighbours[i]++;
                }
                rates[i] = rate;
            }
            return rates;
        }

        /// <summary>
        /// The velocity change WCSPH's full step adds to each particle (FluidSolver's _VelocityCorrections, computed by the
        /// force pass of <paramref name="state"/> with the pressure on): XSPH's correction when <paramref name="xsph"/>, plus
        /// the wall contact of a particle closer to the walls than the flat-wall lattice (with summation density, only below
        /// rest density; SphBoundary.hlsl) on the velocity it would drift with next,
        /// v + a dt + dv_xsph. <paramref name="dt"/> is the sub-step's (0 outside a step, as after SetParticles).
        /// </summary>
        public Double3[] VelocityCorrections(Particle[] particles, ReferenceState state, double dt, bool xsph)
        {
            var corrections = new Double3[particles.Length];
            for (int i = 0; i < particles.Length; i++)
            {
                var correction = xsph ? state.Xsph[i] : Double3.Zero;
                bool contact = _settings.WcsphDensity == WcsphDensity.DeltaSph || state.Density[i] < _phases[particles[i].Phase].RestDensity;
                if (contact && state.WallNumberDensity[i] > _flatWallNumberDensity * _phases[(int)particles[i].Phase].WallWeightScale)
                {
                    var predicted = new Double3(particles[i].Velocity) + state.Acceleration[i] * dt + correction;
                    correction += ContactVelocity(predicted, state.WallGradientSum[i], state.WallVelocityRate[i]) - predicted;
                }
                corrections[i] = correction;
            }
            return corrections;
        }

        /// <summary>SphBoundary.hlsl's WallContactVelocity: the velocity without its part along G_w that would compress the
        /// wall side, v . G_w - <paramref name="wallRate"/> &gt; 0.</summary>
        static Double3 ContactVelocity(Double3 v, Double3 g, double wallRate)
        {
            double rate = Double3.Dot(v, g) - wallRate, g2 = Double3.Dot(g, g);
            return rate > 0 && g2 > 1e-20 ? v - g * (rate / g2) : v;
        }

        /// <summary>DFSPH's wall contact (DivergenceFreeSolver.hlsl): a particle below its rest number density, or whose drift
        /// over <paramref name="dt"/> would end within <see cref="DivergenceFreeContactGap"/> spacings of a wall's face, loses the
        /// velocity along G_w = sum_b omega_b gradW_ib that would compress its wall side.</summary>
        public void WallContact(Particle[] particles, double[] numberDensity, Double3[] v, double dt)
        {
            var walls = PlacedBoundary();
            for (int i = 0; i < particles.Length; i++)
            {
                var xi = new Double3(particles[i].Position);
                if (numberDensity[i] >= RestNumberDensity(particles[i]) && WallGap(xi + v[i] * dt) >= DivergenceFreeContactGap * _settings.ParticleSpacing)
                    continue;
                var g = new Double3(0, 0, 0);
                double wallRate = 0;
                foreach (var wall in walls)
                {
                    var rib = xi - new Double3(wall.Position);
                    double r = rib.Length();
                    if (r >= _h) continue;
                    var gradient = PairGradient(rib, r, 1, 0) * WallWeight(wall, particles[i]);
                    g += gradient;
                    wallRate += Double3.Dot(new Double3(wall.Velocity), gradient);
                }
                v[i] = ContactVelocity(v[i], g, wallRate);
            }
        }

        /// <summary>Within this many spacings of a wall's face DFSPH's wall contact acts at any density (DivergenceFreeSolver.hlsl's
        /// DIVERGENCE_CONTACT_GAP).</summary>
        public const double DivergenceFreeContactGap = 0.25;

        /// <summary>SphBoundary.hlsl's WallGap: the distance from x to the nearest container face or sphere surface, m.</summary>
        double WallGap(Double3 x)
        {
            var q = ToLocal(x);
            var half = new Double3(Container.Size * 0.5f);
            double gap = double.MaxValue;
            for (int axis = 0; axis < 3; axis++) gap = Math.Min(gap, half[axis] - Math.Abs(q[axis]));
            foreach (var o in Obstacles) gap = Math.Min(gap, (x - new Double3(o.Center)).Length() - o.Radius);
            return gap;
        }

        /// <summary>Applies the pressure terms q of the fluid and <paramref name="wallQ"/> of the walls (indexed like
        /// <see cref="PlacedBoundary"/>) to the velocities: v_i -= (dt / m_i) (sum_j (q_i + q_j) gradW_ij + sum_b (omega_b q_i + q_b) gradW_ib).</summary>
        public void ApplyStiffness(Particle[] particles, Double3[] v, double[] q, double[] wallQ, double dt)
        {
            int n = particles.Length;
            var walls = PlacedBoundary();
            var dv = new Double3[n];
            for (int i = 0; i < n; i++)
            {
                var xi = new Double3(particles[i].Position);
                var sum = Double3.Zero;
                for (int j = 0; j < n; j++)
                {
                    if (j == i) continue;
                    var rij = xi - new Double3(particles[j].Position);
                    double r = rij.Length();
                    if (r >= _h) continue;
                    sum += PairGradient(rij, r, particles[i].Id, particles[j].Id) * (q[i] + q[j]);
                }
                for (int b = 0; b < walls.Length; b++)
                {
                    var rib = xi - new Double3(walls[b].Position);
                    double r = rib.Length();
                    if (r >= _h) continue;
                    sum += PairGradient(rib, r, 1, 0) * (WallWeight(walls[b], particles[i]) * q[i] + wallQ[b]);
                }
                dv[i] = sum * (-dt / _phases[particles[i].Phase].ParticleMass);
            }
            for (int i = 0; i < n; i++) v[i] += dv[i];
        }

        /// <summary>The relaxation of a wall particle's Jacobi step (DivergenceFreeSolver.hlsl's WALL_RELAXATION).</summary>
        public const double WallRelaxation = 0.5;

        /// <summary>The wall particles' relaxation in the accelerated solve, as a share of the fluid's (CHEBYSHEV_WALL_SHARE).</summary>
        public const double ChebyshevWallShare = 1.0 / 3.0;

        /// <summary>One round's step for every unknown: the compression-only Jacobi step (<paramref name="jacobi"/>), or in an
        /// <paramref name="accelerated"/> solve the projected, accelerated one from the signed step, the unknown's last step (in
        /// <paramref name="step"/>, overwritten) and the q it summed in this solve (DivergenceFreeSolver.hlsl).</summary>
        void RoundSteps(bool accelerated, double[] step, double[] summed, Func<int, double> jacobi, Func<int, double> signedStep, double weightBeta, double weightGamma)
        {
            for (int i = 0; i < step.Length; i++)
                step[i] = accelerated
                    ? Math.Max(summed[i] + weightBeta * step[i] + weightGamma * signedStep(i), 0.0) - summed[i]
                    : jacobi(i);
        }

        /// <summary>(beta, gamma, rho) of a Chebyshev round from the last round's rho (0 before the first).</summary>
        static (double Beta, double Gamma, double Rho) ChebyshevWeights(double previousRho, double low, double high)
        {
            double theta = 0.5 * (high + low), delta = 0.5 * (high - low), sigma = theta / delta;
            if (previousRho <= 0.0) return (0.0, 1.0 / theta, 1.0 / sigma);
            double rho = 1.0 / (2.0 * sigma - previousRho);
            return (rho * previousRho, 2.0 * rho / delta, rho);
        }

        /// <summary>The fluid share of delta0 above which a wall particle takes a whole Jacobi step (WALL_FULL_SHARE).</summary>
        public const double WallFullShare = 0.25;

        /// <summary>Each wall particle as an unknown of the DFSPH solves, indexed like <see cref="PlacedBoundary"/>.</summary>
        public sealed class WallSolveState
        {
            public double[] NumberDensity = Array.Empty<double>(), Factor = Array.Empty<double>(), Rest = Array.Empty<double>(), Q = Array.Empty<double>();
        }

        /// <summary>Every wall particle's number density (fluid and walls), DFSPH factor and rest number density
        /// (DivergenceFreeSolver.hlsl, BoundaryDensityFactor).</summary>
        public WallSolveState WallUnknowns(Particle[] particles)
        {
            var walls = PlacedBoundary();
            var state = new WallSolveState
            {
                NumberDensity = new double[walls.Length], Factor = new double[walls.Length], Rest = new double[walls.Length], Q = new double[walls.Length],
            };
            for (int b = 0; b < walls.Length; b++)
            {
                var xb = new Double3(walls[b].Position);
                double fluid = 0, wall = 0, squares = 0, rest = 0, scale = 0;
                foreach (var p in particles)
                {
                    var rfb = new Double3(p.Position) - xb;
                    double r = rfb.Length();
                    if (r >= _h) continue;
                    double w = Kernel(r);
                    fluid += w;
                    rest += w * RestNumberDensity(p);
                    scale += w * _phases[(int)p.Phase].WallWeightScale;
                    squares += PairGradient(rfb, r, 1, 0).LengthSquared() / _phases[p.Phase].ParticleMass;
                }
                // A sphere's own shells at rest from the sampling, as the GPU's WallNumberDensity takes them.
                wall = _ownNumberDensities[b];
                foreach (var other in walls)
                    if (CountsInWallSum(walls[b], other))
                        wall += other.Weight * Kernel((xb - new Double3(other.Position)).Length());
                state.NumberDensity[b] = fluid + (fluid > 0 ? scale / fluid : 1.0) * wall;
                state.Rest[b] = fluid > 0 ? rest / fluid : 0.0;
                double share = Math.Min(1.0, fluid / (WallFullShare * Math.Max(state.Rest[b], 1e-20)));
                state.Factor[b] = squares > 1e-20 ? share / squares : 0.0;
            }
            return state;
        }

        /// <summary>SphBoundary.hlsl's CountsInWallSum: the container's lattice, outside the wall particle's own sphere.</summary>
        bool CountsInWallSum(BoundaryParticle wall, BoundaryParticle other)
        {
            if (other.Owner != BoundaryParticle.ContainerOwner) return false;
            if (wall.Owner == BoundaryParticle.ContainerOwner) return true;
            var sphere = Obstacles[(int)wall.Owner];
            return (new Double3(other.Position) - new Double3(sphere.Center)).Length() >= sphere.Radius;
        }

        /// <summary>D delta_b / Dt of every wall particle, sum_f (v_f - v_b) . gradW_fb, for the fluid velocities <paramref name="v"/>.</summary>
        public double[] WallNumberDensityRates(Particle[] particles, Double3[] v)
        {
            var walls = PlacedBoundary();
            var rates = new double[walls.Length];
            for (int b = 0; b < walls.Length; b++)
            {
                var xb = new Double3(walls[b].Position);
                for (int f = 0; f < particles.Length; f++)
                {
                    var rfb = new Double3(particles[f].Position) - xb;
                    double r = rfb.Length();
                    if (r >= _h) continue;
                    rates[b] += Double3.Dot(v[f] - new Double3(walls[b].Velocity), PairGradient(rfb, r, 1, 0));
                }
            }
            return rates;
        }

        /// <summary>The fluid's q summed so far in the constant-density solve (<paramref name="applied"/>, this round's step included),
        /// Shepard-weighted at every wall particle: the floor under its q_b (DivergenceFreeSolver.hlsl's WallStepAtLeast); 0 where no
        /// fluid reaches it.</summary>
        double[] WallExtrapolatedStiffness(Particle[] particles, double[] applied)
        {
            var walls = PlacedBoundary();
            var x = new Double3[particles.Length];
            for (int f = 0; f < particles.Length; f++) x[f] = new Double3(particles[f].Position);
            var stiffness = new double[walls.Length];
            for (int b = 0; b < walls.Length; b++)
                stiffness[b] = ShepardAverage(new Double3(walls[b].Position), x, (f, _) => applied[f]);
            return stiffness;
        }

        /// <summary>The kernel-weighted average at <paramref name="at"/> of <paramref name="value"/>(f, at - x_f) over the fluid
        /// particles within the support (Shepard's interpolation, as the walls' pressures take it); 0 where none reaches.</summary>
        double ShepardAverage(Double3 at, Double3[] x, Func<int, Double3, double> value)
        {
            double sum = 0, weights = 0;
            for (int f = 0; f < x.Length; f++)
            {
                var fluidToPoint = at - x[f];
                double r = fluidToPoint.Length();
                if (r >= _h) continue;
                double w = Kernel(r);
                sum += value(f, fluidToPoint) * w;
                weights += w;
            }
            return weights > 0 ? sum / weights : 0.0;
        }

        /// <summary>omega_ib, wall particle b's volume at fluid particle i's rest number density (SphBoundary.hlsl's WallWeight).</summary>
        double WallWeight(BoundaryParticle wall, Particle particle) => wall.Weight * (double)_phases[(int)particle.Phase].WallWeightScale;

        double RestNumberDensity(Particle p) => _phases[p.Phase].RestDensity / (double)_phases[p.Phase].ParticleMass;

        /// <summary>
        /// One DFSPH sub-step as FluidSimulation runs it from a state without warm start, with exactly
        /// <paramref name="iterations"/> corrections per solve (MaxSolverIterations = 1 stops each solve after one): non-pressure
        /// forces, predicted velocity (XSPH, damping), constant-density solve, wall contact, drift and clamp, factors at the new positions,
        /// divergence-free solve, each with the wall particles as unknowns (the constant-density solve's q_b at least the fluid's around
        /// them, Shepard-weighted). Returns the new particles, the q each solve summed per
        /// particle and the q_b both solves summed per wall particle (indexed like <see cref="PlacedBoundary"/>).
        /// </summary>
        public Particle[] DivergenceFreeSubstep(Particle[] particles, double dt, bool xsph, int iterations,
            out double[] densityStiffness, out double[] divergenceStiffness, out double[] wallStiffness)
        {
            int n = particles.Length;
            var state = Evaluate(particles, false);
            var factors = DivergenceFreeFactors(particles);
            double damping = Math.Max(0, 1 - _settings.VelocityDamping * dt);
            var v = new Double3[n];
            for (int i = 0; i < n; i++)
            {
                var vi = new Double3(particles[i].Velocity) + state.Acceleration[i] * dt;
                if (xsph) vi += state.Xsph[i];
                v[i] = vi * damping;
            }
            double relaxation = _settings.SolverRelaxation;
            double wallRelaxation = ChebyshevWallShare * relaxation;
            densityStiffness = new double[n];
            var q = new double[n];
            var walls = WallUnknowns(particles);
            wallStiffness = new double[walls.Q.Length];
            var wallSummed = new double[walls.Q.Length];
            double rho = 0.0;
            for (int l = 0; l < iterations; l++)
            {
                var rates = NumberDensityRates(particles, v);
                var wallRates = WallNumberDensityRates(particles, v);
                var (beta, gamma, nextRho) = _acceleratedDensitySolve ? ChebyshevWeights(rho, _chebyshev.Value.Low, _chebyshev.Value.High) : (0.0, 0.0, 0.0);
                rho = nextRho;
                double[] excess = new double[n], wallExcess = new double[walls.Q.Length];
                for (int i = 0; i < n; i++)
                    excess[i] = state.NumberDensity[i] + dt * rates[i] - RestNumberDensity(particles[i]);
                for (int b = 0; b < walls.Q.Length; b++)
                    wallExcess[b] = walls.NumberDensity[b] + dt * wallRates[b] - walls.Rest[b];
                var w = walls;
                RoundSteps(_acceleratedDensitySolve, q, densityStiffness, i => relaxation * Math.Max(excess[i], 0.0) * factors[i] / (dt * dt),
                    i => relaxation * excess[i] * factors[i] / (dt * dt), beta, gamma);
                RoundSteps(_acceleratedDensitySolve, walls.Q, wallSummed, b => WallRelaxation * Math.Max(wallExcess[b], 0.0) * w.Factor[b] / (dt * dt),
                    b => w.Factor[b] > 0.0 ? wallRelaxation * wallExcess[b] * w.Factor[b] / (dt * dt) : 0.0, beta, gamma);
                for (int i = 0; i < n; i++) densityStiffness[i] += q[i];
                var fluidStiffness = WallExtrapolatedStiffness(particles, densityStiffness);
                for (int b = 0; b < walls.Q.Length; b++)
                {
                    walls.Q[b] = walls.Factor[b] > 0.0 ? Math.Max(walls.Q[b], fluidStiffness[b] - wallSummed[b]) : 0.0;
                    wallSummed[b] += walls.Q[b];
                    wallStiffness[b] += walls.Q[b];
                }
                ApplyStiffness(particles, v, q, walls.Q, dt);
            }
            var moved = new Particle[n];
            WallContact(particles, state.NumberDensity, v, dt);
            for (int i = 0; i < n; i++)
            {
                var x = new Double3(particles[i].Position) + v[i] * dt;
                var vi = v[i];
                Clamp(ref x, ref vi);
                v[i] = vi;
                moved[i] = new Particle(x.ToVector3(), vi.ToVector3(), particles[i].Phase, particles[i].Id);
            }
            factors = DivergenceFreeFactors(moved);
            walls = WallUnknowns(moved);
            divergenceStiffness = new double[n];
            Array.Clear(q, 0, n);
            wallSummed = new double[walls.Q.Length];
            rho = 0.0;
            for (int l = 0; l < iterations; l++)
            {
                var rates = NumberDensityRates(moved, v, out var neighbours);
                var wallRates = WallNumberDensityRates(moved, v);
                var (beta, gamma, nextRho) = _chebyshev.HasValue ? ChebyshevWeights(rho, _chebyshev.Value.Low, _chebyshev.Value.High) : (0.0, 0.0, 0.0);
                rho = nextRho;
                double[] rate = new double[n];
                for (int i = 0; i < n; i++)
                    rate[i] = neighbours[i] >= DivergenceMinNeighbours ? rates[i] : 0.0;
                var w = walls;
                RoundSteps(_chebyshev.HasValue, q, divergenceStiffness, i => relaxation * Math.Max(rate[i], 0.0) * factors[i] / dt,
                    i => relaxation * rate[i] * factors[i] / dt, beta, gamma);
                RoundSteps(_chebyshev.HasValue, walls.Q, wallSummed, b => WallRelaxation * Math.Max(wallRates[b], 0.0) * w.Factor[b] / dt,
                    b => w.Factor[b] > 0.0 ? wallRelaxation * wallRates[b] * w.Factor[b] / dt : 0.0, beta, gamma);
                for (int i = 0; i < n; i++) divergenceStiffness[i] += q[i];
                for (int b = 0; b < walls.Q.Length; b++)
                {
                    if (walls.Factor[b] <= 0.0) walls.Q[b] = 0.0;
                    wallSummed[b] += walls.Q[b];
                    wallStiffness[b] += walls.Q[b];
                }
                ApplyStiffness(moved, v, q, walls.Q, dt);
            }
            for (int i = 0; i < n; i++)
                moved[i] = new Particle(moved[i].Position, v[i].ToVector3(), moved[i].Phase, moved[i].Id);
            return moved;
        }
    }
}
