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
    /// hydrostatic wall pressure, Morris viscosity or its strain-rate form, same-phase normals and tension, XSPH, and the clamp;
    /// it shares no code with them (the boundary samples come from the same BoundarySampling, the input both use).
    /// </summary>
    public sealed partial class ReferenceSph
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

            double friction = Container.Friction == WallFriction.NoSlip ? 1.0 : 0.0;
            bool strainRate = _settings.ViscousStress == ViscousStress.StrainRate;
            double stress = strainRate ? 2.0 : 1.0;
            if (strainRate) Rotations(particles, x, v, walls, xb, s.NumberDensity, friction).CopyTo(s.Rotation, 0);

            var gravity = new Double3(_settings.Gravity);
            // Each wall particle's pressure: the Shepard-weighted fluid pressure around it plus the hydrostatic term.
            var wallPressure = new double[walls.Length];
            for (int b = 0; b < walls.Length; b++)
                wallPressure[b] = Math.Max(0.0, ShepardAverage(xb[b], x, (f, fluidToWall) => s.Pressure[f] + s.Density[f] * Double3.Dot(gravity, fluidToWall)));
            double speedOfSound = Math.Sqrt(_settings.Stiffness * _settings.Gamma / MinRestDensity());
            double artificial = _settings.ArtificialViscosity * speedOfSound * 0.5 * _h;
            double wallArtificial = FluidSimulation.WallContactDamping * speedOfSound * 0.5 * _h;
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
                    var pairRotation = (s.Rotation[i] + s.Rotation[j]) * 0.5;
                    force += (v[i] - v[j] - Double3.Cross(pairRotation, rij)) * (2 * stress * mu / (di * s.NumberDensity[j]) * Double3.Dot(rij, gradient) / (r2 + 0.01 * _h2));
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
                    force += (v[i] - wallVelocity - Double3.Cross(s.Rotation[i], rib)) * (2 * stress * friction * phaseI.Viscosity * weight / (di * di) * Double3.Dot(rib, gradient) / (r2 + 0.01 * _h2));
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
    }
}
