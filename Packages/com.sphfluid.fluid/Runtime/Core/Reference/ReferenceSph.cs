using System;
using System.Collections.Generic;
using System.Numerics;
using SphFluid.Simulation;

namespace SphFluid.Reference
{
    /// <summary>
    /// The solver's SPH in double precision and brute force (every pair, O(N^2)): used ONLY to check the GPU
    /// kernels on small cases, never shipped. It mirrors the kernels equation by equation
    /// (Shaders/Include/Sph*.hlsl): the cubic spline, density with boundary particles, pressure with the
    /// hydrostatic wall pressure, Morris viscosity, same-phase normals and tension, XSPH, and the clamp;
    /// it shares no code with them (the boundary samples come from the same BoundarySampling, the input both use).
    /// </summary>
    public sealed class ReferenceSph
    {
        readonly FluidSettings _settings;
        readonly PhaseProperties[] _phases;
        readonly BoundaryParticle[] _boundaryRest;
        readonly float[] _ownNumberDensities;
        readonly double _h, _h2, _surfaceForceScale, _flatWallNumberDensity;

        public ContainerDescription Container { get; set; }
        public List<RigidSphere> Obstacles { get; set; }

        public ReferenceSph(FluidSceneDescription scene)
        {
            _settings = scene.Settings;
            _phases = scene.BuildPhaseTable();
            _boundaryRest = BoundarySampling.Sample(scene);
            _ownNumberDensities = BoundarySampling.OwnNumberDensities(scene, _boundaryRest);
            Container = scene.Container.Clone();
            Obstacles = new List<RigidSphere>(scene.Obstacles ?? new List<RigidSphere>());
            _h = _settings.SmoothingRadius;
            _h2 = _h * _h;
            _surfaceForceScale = 1.0 / (_h * SurfaceLayerShare.For(_settings.SmoothingKernel, _h / _settings.ParticleSpacing));
            _flatWallNumberDensity = SmoothingKernels.FlatWallNumberDensity(_settings.SmoothingKernel, _settings.ParticleSpacing, _h);
            if (_settings.PressureSolver == PressureSolver.Dfsph && _settings.SolverIteration == SolverIteration.Chebyshev)
            {
                double depth = SpawnLayout.Depth(SpawnLayout.Generate(scene), _settings.Gravity, _settings.ParticleSpacing);
                _chebyshev = ChebyshevBounds.For(_settings.SmoothingKernel, _settings.ParticleSpacing, _h, _settings.SolverRelaxation, depth);
                _acceleratedDensitySolve = ChebyshevBounds.AcceleratesDensitySolve(_settings.DensityTolerance, depth, _settings.ParticleSpacing);
            }
        }

        /// <summary>The accelerated solve's eigenvalue bounds as FluidSimulation sets them from the spawn; null for Jacobi.</summary>
        readonly (double Low, double High)? _chebyshev;

        /// <summary>Whether the constant-density solve is accelerated as well as the divergence-free one.</summary>
        readonly bool _acceleratedDensitySolve;

        public IReadOnlyList<PhaseProperties> PhaseTable => _phases;

        double MinRestDensity()
        {
            double min = double.MaxValue;
            foreach (var phase in _phases) min = Math.Min(min, phase.RestDensity);
            return min;
        }

        public double Kernel(double r) => SmoothingKernels.Value(_settings.SmoothingKernel, r, _h);

        public Double3 Gradient(Double3 rij, double r) => rij * (SmoothingKernels.Derivative(_settings.SmoothingKernel, r, _h) / r);

        /// <summary>How much a normal of length |n| = H |grad c| counts: SphSurfaceTension.hlsl's smoothstep(0.05, 0.2, |n|).</summary>
        static double SurfaceWeight(double normalLength)
        {
            double t = Math.Min(1.0, Math.Max(0.0, (normalLength - 0.05) / 0.15));
            return t * t * (3.0 - 2.0 * t);
        }

        /// <summary>gradW of a pair, a coincident pair given the id-signed diagonal (SphPressureForce.hlsl).</summary>
        public Double3 PairGradient(Double3 rij, double r, uint idI, uint idJ)
        {
            double rr = Math.Max(r, 0.01 * _h);
            Double3 direction = r > 0 ? rij / r : new Double3(1, 1, 1) * ((idI > idJ ? 1.0 : -1.0) / Math.Sqrt(3.0));
            return Gradient(direction * rr, rr);
        }

        /// <summary>The boundary particles placed with the current container and obstacles (world space).</summary>
        public BoundaryParticle[] PlacedBoundary()
        {
            var placed = new BoundaryParticle[_boundaryRest.Length];
            for (int b = 0; b < placed.Length; b++)
            {
                var rest = _boundaryRest[b];
                var p = rest;
                if (rest.Owner == BoundaryParticle.ContainerOwner)
                {
                    var x = ToWorldDirection(new Double3(rest.Position)) + new Double3(Container.Position);
                    p.Position = x.ToVector3();
                    p.Velocity = WallVelocity(x).ToVector3();
                }
                else
                {
                    var o = Obstacles[(int)rest.Owner];
                    p.Position = (new Double3(o.Center) + new Double3(rest.Position)).ToVector3();
                    p.Velocity = o.Velocity;
                }
                placed[b] = p;
            }
            return placed;
        }

        /// <summary>The wall's outward normal at a placed boundary particle: the container faces it lies beyond, or
        /// towards the sphere's centre.</summary>
        Double3 WallNormal(BoundaryParticle wall)
        {
            var x = new Double3(wall.Position);
            if (wall.Owner == BoundaryParticle.ContainerOwner)
            {
                var q = ToLocal(x);
                var half = new Double3(Container.Size * 0.5f);
                var beyond = Double3.Zero;
                for (int axis = 0; axis < 3; axis++)
                    beyond[axis] = Math.Max(Math.Abs(q[axis]) - half[axis], 0.0) * Math.Sign(q[axis]);
                double length = beyond.Length();
                return length > 0 ? ToWorldDirection(beyond / length) : Double3.Zero;
            }
            var inward = new Double3(Obstacles[(int)wall.Owner].Center) - x;
            double l = inward.Length();
            return l > 0 ? inward / l : Double3.Zero;
        }

        /// <summary>Density, pressure, normals, accelerations and XSPH corrections of a particle state
        /// (as FluidSimulation.ComputeForces leaves them). Normals are zero when no phase has surface tension.</summary>
        public ReferenceState Evaluate(Particle[] particles) => Evaluate(particles, true);

        /// <summary>As <see cref="Evaluate(Particle[])"/>; without <paramref name="withPressure"/> the accelerations leave out
        /// the pressure and the artificial viscosities (DFSPH's non-pressure forces, FluidSolver's NonPressureForces).</summary>
        public ReferenceState Evaluate(Particle[] particles, bool withPressure) => Evaluate(particles, withPressure, null);

        /// <summary>As <see cref="Evaluate(Particle[], bool)"/>; with <paramref name="numberDensities"/> (delta-SPH, indexed like the
        /// particles) each particle's number density is the one it carries instead of the kernel sum.</summary>
        public ReferenceState Evaluate(Particle[] particles, bool withPressure, double[] numberDensities)
        {
            double pressureOn = withPressure ? 1.0 : 0.0;
            int n = particles.Length;
            var s = new ReferenceState(n);
            var x = new Double3[n];
            var v = new Double3[n];
            for (int i = 0; i < n; i++) { x[i] = new Double3(particles[i].Position); v[i] = new Double3(particles[i].Velocity); }
            var walls = PlacedBoundary();
            var xb = new Double3[walls.Length];
            for (int b = 0; b < walls.Length; b++) xb[b] = new Double3(walls[b].Position);

            for (int i = 0; i < n; i++)
            {
                double delta = 0;
                for (int j = 0; j < n; j++) delta += Kernel((x[i] - x[j]).Length());
                for (int b = 0; b < walls.Length; b++) delta += WallWeight(walls[b], particles[i]) * Kernel((x[i] - xb[b]).Length());
                if (numberDensities != null) delta = numberDensities[i];
                var phase = _phases[particles[i].Phase];
                double rho = phase.ParticleMass * delta;
                double p = _settings.Stiffness * (Math.Pow(rho / phase.RestDensity, _settings.Gamma) - 1.0);
                s.NumberDensity[i] = delta;
                s.Density[i] = rho;
                s.Pressure[i] = Math.Max(p, 0.0);
            }

            bool tension = false;
            foreach (var phase in _phases) if (phase.SurfaceTension > 0) tension = true;
            for (int i = 0; i < n; i++)
            {
                var normal = Double3.Zero;
                for (int j = 0; j < n; j++)
                {
                    if (particles[j].Phase != particles[i].Phase) continue;
                    var rij = x[i] - x[j];
                    double r2 = rij.LengthSquared();
                    if (r2 >= _h2 || r2 <= 0) continue;
                    normal += Gradient(rij, Math.Sqrt(r2)) / s.NumberDensity[j];
                }
                s.Normal[i] = tension ? normal * _h : Double3.Zero;
            }

            var gravity = new Double3(_settings.Gravity);
            // Each wall particle's pressure: the Shepard-weighted fluid pressure around it plus the hydrostatic term.
            var wallPressure = new double[walls.Length];
            for (int b = 0; b < walls.Length; b++)
                wallPressure[b] = Math.Max(0.0, ShepardAverage(xb[b], x, (f, fluidToWall) => s.Pressure[f] + s.Density[f] * Double3.Dot(gravity, fluidToWall)));
            double speedOfSound = Math.Sqrt(_settings.Stiffness * _settings.Gamma / MinRestDensity());
            double artificial = _settings.ArtificialViscosity * speedOfSound * 0.5 * _h;
            double wallArtificial = FluidSimulation.WallContactDamping * speedOfSound * 0.5 * _h;
            double friction = Container.Friction == WallFriction.NoSlip ? 1.0 : 0.0;
            for (int i = 0; i < n; i++)
            {
                var phaseI = _phases[particles[i].Phase];
                double mi = phaseI.ParticleMass;
                double di = s.NumberDensity[i];
                double termI = s.Pressure[i] / (di * di);
                var force = Double3.Zero;
                var xsph = Double3.Zero;
                for (int j = 0; j < n; j++)
                {
                    if (j == i) continue;
                    var rij = x[i] - x[j];
                    double r2 = rij.LengthSquared();
                    if (r2 >= _h2) continue;
                    double r = Math.Sqrt(r2);
                    var phaseJ = _phases[particles[j].Phase];
                    double muI = phaseI.Viscosity, muJ = phaseJ.Viscosity;
                    double mu = muI + muJ > 0 ? 2 * muI * muJ / (muI + muJ) : 0;
                    var gradient = PairGradient(rij, r, particles[i].Id, particles[j].Id);
                    double termJ = s.Pressure[j] / (s.NumberDensity[j] * s.NumberDensity[j]);
                    force += gradient * (-(termI + termJ) * pressureOn);
                    force += (v[i] - v[j]) * (2 * mu / (di * s.NumberDensity[j]) * Double3.Dot(rij, gradient) / (r2 + 0.01 * _h2));
                    double approach = Math.Min(0.0, Double3.Dot(v[i] - v[j], rij)) / (r2 + 0.01 * _h2);
                    force += gradient * (pressureOn * artificial * 0.5 * (s.Density[i] + s.Density[j]) / (di * s.NumberDensity[j]) * approach);
                    if (tension && particles[j].Phase == particles[i].Phase && phaseI.SurfaceTension > 0)
                    {
                        // The continuum surface force, weighted by how clear both normals are (SphSurfaceTension.hlsl).
                        double ni = Math.Sqrt(s.Normal[i].LengthSquared()), nj = Math.Sqrt(s.Normal[j].LengthSquared());
                        double weight = SurfaceWeight(ni) * SurfaceWeight(nj);
                        if (weight > 0)
                        {
                            double divergence = weight * Double3.Dot(s.Normal[j] / nj - s.Normal[i] / ni, gradient) / s.NumberDensity[j];
                            force += s.Normal[i] * (-phaseI.SurfaceTension * _surfaceForceScale * divergence * mi / phaseI.RestDensity);
                        }
                    }
                    xsph += (v[j] - v[i]) * (2 * Kernel(r) / (di + s.NumberDensity[j]));
                }
                for (int b = 0; b < walls.Length; b++)
                {
                    var rib = x[i] - xb[b];
                    double r2 = rib.LengthSquared();
                    if (r2 >= _h2) continue;
                    double r = Math.Sqrt(r2);
                    var gradient = PairGradient(rib, r, 1, 0);
                    double weight = WallWeight(walls[b], particles[i]);
                    var wallVelocity = new Double3(walls[b].Velocity);
                    force += gradient * (-(weight * (s.Pressure[i] + wallPressure[b]) / (di * di)) * pressureOn);
                    force += (v[i] - wallVelocity) * (2 * friction * phaseI.Viscosity * weight / (di * di) * Double3.Dot(rib, gradient) / (r2 + 0.01 * _h2));
                    double approach = Math.Min(0.0, Double3.Dot(v[i] - wallVelocity, rib)) / (r2 + 0.01 * _h2);
                    force += gradient * (pressureOn * artificial * s.Density[i] * weight / (di * di) * approach);
                    var normal = WallNormal(walls[b]);
                    bool underDense = s.Density[i] < 0.97 * phaseI.RestDensity;
                    var intoWall = underDense ? normal * Math.Max(0.0, Double3.Dot(v[i] - wallVelocity, normal)) : Double3.Zero;
                    double contact = Math.Min(0.0, Double3.Dot(intoWall, rib)) / (r2 + 0.01 * _h2);
                    force += gradient * (pressureOn * wallArtificial * s.Density[i] * weight / (di * di) * contact);
                    s.WallGradientSum[i] += gradient * weight;
                    s.WallNumberDensity[i] += weight * Kernel(r);
                    s.WallVelocityRate[i] += weight * Double3.Dot(wallVelocity, gradient);
                }
                s.InternalForce[i] = force;
                s.Acceleration[i] = force / mi + gravity;
                s.Xsph[i] = xsph * _settings.XsphEpsilon;
            }
            return s;
        }

        // ------------------------------------------------------------------ boundaries

        Quaternion Rotation => Quaternion.Normalize(Container.Rotation);

        Double3 ToLocal(Double3 world) => Rotate(world - new Double3(Container.Position), Quaternion.Conjugate(Rotation));

        Double3 ToWorldDirection(Double3 local) => Rotate(local, Rotation);

        static Double3 Rotate(Double3 v, Quaternion q)
        {
            // v' = v + 2 w (u x v) + 2 u x (u x v), with u = (q.x, q.y, q.z), w = q.w (unit q).
            var u = new Double3(q.X, q.Y, q.Z);
            var t = Double3.Cross(u, v) * 2.0;
            return v + t * q.W + Double3.Cross(u, t);
        }

        Double3 ClampExtent => new Double3(Container.Size * 0.5f) - new Double3(1, 1, 1) * (FluidSimulation.ClampInset * (double)_settings.ParticleSpacing);

        Double3 WallVelocity(Double3 x) =>
            new Double3(Container.Velocity) + Double3.Cross(new Double3(Container.AngularVelocity), x - new Double3(Container.Position));

        public void Clamp(ref Double3 x, ref Double3 v)
        {
            foreach (var o in Obstacles)
            {
                var d = x - new Double3(o.Center);
                double dist = d.Length();
                double surface = o.Radius + FluidSimulation.ClampInset * (double)_settings.ParticleSpacing;
                if (dist >= surface) continue;
                var n = dist > 0 ? d / dist : new Double3(0, 1, 0);
                x = new Double3(o.Center) + n * surface;
                double inward = Double3.Dot(v - new Double3(o.Velocity), n);
                if (inward < 0) v -= n * inward;
            }
            var q = ToLocal(x);
            var H = ClampExtent;
            var clamped = q;
            bool any = false;
            for (int axis = 0; axis < 3; axis++)
            {
                double c = Math.Max(-H[axis], Math.Min(H[axis], q[axis]));
                if (c != q[axis]) any = true;
                clamped[axis] = c;
            }
            if (!any) return;
            x = ToWorldDirection(clamped) + new Double3(Container.Position);
            var wall = WallVelocity(x);
            var rel = Rotate(v - wall, Quaternion.Conjugate(Rotation));
            for (int axis = 0; axis < 3; axis++)
            {
                if (clamped[axis] == q[axis]) continue;
                double outward = q[axis] > 0 ? 1 : -1;
                if (rel[axis] * outward > 0) rel[axis] = 0;
            }
            v = wall + ToWorldDirection(rel);
        }

        // ------------------------------------------------------------------ integration

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

        // ------------------------------------------------------------------ divergence-free SPH

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
