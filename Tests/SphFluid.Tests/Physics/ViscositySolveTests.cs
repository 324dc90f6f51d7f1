using System;
using System.Linq;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Headless.Cli;
using SphFluid.Headless.Scenes;
using SphFluid.Reference;
using SphFluid.Simulation;
using SphFluid.Tests.Runner;
using SphFluid.Tests.Solver;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// DFSPH's implicit viscosity solve (SphViscositySolve.hlsl) against the step it takes and against the explicit force
    /// it replaces beyond the explicit step: the solved velocities against the CPU's two stages on the reference force; a
    /// cellular flow in a box with free-slip walls, u = U sin(k x) cos(k z), w = -U cos(k x) sin(k z), k = pi / L,
    /// divergence-free, parallel to every wall and free of shear at them (in a continuum a Stokes mode decaying as
    /// exp(-2 nu k^2 t)), under the viscous step alone against the SPH operator's exact decay of it, and under the whole
    /// sub-step against the explicit force's converged decay; and OilAndWater's flow with its oil at 100 Pa s.
    /// </summary>
    public sealed class ViscositySolveTests
    {
        const float Spacing = 0.02f;
        const int Cells = 16;                 // L = 16 spacings along x and z
        const float Viscosity = 100f;         // Pa s: nu = 0.1 m^2/s, the explicit limit 1.27 ms
        const float U = 0.005f;               // m/s: Stokes flow (Re = U L / nu = 0.016)
        const double Seconds = 0.05;
        // Sub-steps a frame: the solves' budget of recorded rounds follows what earlier frames needed (SolveBudget), so
        // frames of 100 sub-steps record the full cap each and took this test twice as long.
        const int FrameSteps = 10;

        /// <summary>DFSPH with the shipped kernel (Wendland C2 at 2.85 spacings), no gravity and no XSPH.</summary>
        static FluidSettings Weightless()
        {
            var settings = SolverScenes.Coarse(Spacing);
            settings.PressureSolver = PressureSolver.Dfsph;
            settings.SmoothingKernel = KernelFamily.WendlandC2;
            settings.SmoothingRadius = 2.85f * Spacing;
            settings.SolverRelaxation = 0.3f;
            settings.Gravity = Vector3.Zero;
            settings.XsphEpsilon = 0f;
            return settings;
        }

        static FluidSceneDescription Box(PressureSolver solver = PressureSolver.Dfsph, float viscosity = Viscosity)
        {
            var settings = Weightless();
            settings.PressureSolver = solver;
            settings.MaxSubsteps = 1000;
            var size = new Vector3(Cells * Spacing, 8 * Spacing, Cells * Spacing);
            var water = SolverScenes.Box("Water", SolverScenes.Water(viscosity), Vector3.Zero, size, jitter: 0f);
            var scene = SolverScenes.Scene(settings, size, water);
            scene.Container.Friction = WallFriction.Slip;
            return scene;
        }

        static double K => Math.PI / (Cells * Spacing);

        static Vector3 Cell(Vector3 p)
        {
            float half = 0.5f * Cells * Spacing;
            double kx = K * (p.X + half), kz = K * (p.Z + half);
            return new Vector3((float)(Math.Sin(kx) * Math.Cos(kz)), 0f, (float)(-Math.Cos(kx) * Math.Sin(kz)));
        }

        /// <summary>The flow's amplitude: the particles' velocities projected on the mode, over its square.</summary>
        static double Amplitude(Particle[] particles)
        {
            double dot = 0.0, norm = 0.0;
            foreach (var p in particles)
            {
                var mode = Cell(p.Position);
                dot += Vector3.Dot(p.Velocity, mode);
                norm += Vector3.Dot(mode, mode);
            }
            return dot / norm;
        }

        /// <summary>The mode's amplitude over U after <paramref name="steps"/> sub-steps covering <paramref name="seconds"/>
        /// (<see cref="Seconds"/> unless given), the fluid's momentum over its mass times U, and the implicit solve's rounds a
        /// sub-step (0: explicit). With <paramref name="viscosityAlone"/> each (DFSPH) sub-step is only its start up to the
        /// drift (PredictVelocities: no pressure solve, no drift), so the viscous step acts alone on the particles where
        /// they spawned.</summary>
        static (double amplitude, double momentum, int rounds) Decay(int steps, bool viscosityAlone = false,
            PressureSolver solver = PressureSolver.Dfsph, float viscosity = Viscosity, double seconds = Seconds, bool validated = false)
        {
            var scene = Box(solver, viscosity);
            using var sim = new FluidSimulation(validated ? GpuTestDevice.Shared : GpuTestDevice.Unvalidated, scene);
            var particles = new Particle[sim.ParticleCount];
            sim.Particles.GetData(particles);
            for (int i = 0; i < particles.Length; i++)
                particles[i].Velocity = U * Cell(particles[i].Position);
            sim.SetParticles(particles);
            float dt = (float)(seconds / steps);
            if (viscosityAlone)
                for (int k = 0; k < steps; k++) sim.PredictVelocities(dt);
            else
                for (int done = 0; done < steps; done += FrameSteps)
                    sim.StepFixed(Math.Min(FrameSteps, steps - done), dt);
            sim.Particles.GetData(particles);
            var momentum = particles.Aggregate(Vector3.Zero, (sum, p) => sum + p.Velocity);
            var limit = sim.TimeStep.ViscousTimeStep;
            int rounds = sim.ViscositySolveRounds;
            TestContext.Progress.WriteLine($"{steps} {(viscosityAlone ? "viscous steps" : "steps")} of {1000 * dt:F3} ms ({dt / limit:F2} of the explicit limit, {rounds} rounds): " +
                $"amplitude {Amplitude(particles) / U:F4} U, momentum {momentum.Length() / particles.Length / U:E2} U");
            return (Amplitude(particles) / U, momentum.Length() / particles.Length / U, rounds);
        }

        /// <summary>The SPH viscous operator's own decay of the flow on the spawned particles, exactly: the operator A =
        /// -a, a the CPU reference's viscous acceleration (no gravity, no pressure; symmetric, since every particle has one
        /// mass), by Lanczos from the mode, whose Ritz values mu_i and weights w_i (the first components of the small
        /// matrix's eigenvectors, squared) give the mode's amplitude under any step that acts on each eigenvector alone:
        /// sum_i w_i f(mu_i). The mode is no eigenvector, so its decay is not exp(-(its Rayleigh quotient) t).</summary>
        sealed class OperatorSpectrum
        {
            public readonly double[] Rates, Weights;

            OperatorSpectrum(double[] rates, double[] weights) { Rates = rates; Weights = weights; }

            /// <summary>sum w_i mu_i: the mode's Rayleigh quotient, its initial decay rate.</summary>
            public double Rayleigh => Rates.Select((mu, i) => Weights[i] * mu).Sum();

            /// <summary>The mode's amplitude after a step that multiplies each eigenvector of rate mu by f(mu).</summary>
            public double Amplitude(Func<double, double> f) => Rates.Select((mu, i) => Weights[i] * f(mu)).Sum();

            public static OperatorSpectrum Of(FluidSceneDescription scene, Particle[] particles, int size)
            {
                var reference = new ReferenceSph(scene);
                int n = particles.Length;
                var moving = (Particle[])particles.Clone();
                Double3[] Apply(Double3[] x)
                {
                    for (int i = 0; i < n; i++) moving[i].Velocity = x[i].ToVector3();
                    var a = reference.Evaluate(moving, false).Acceleration;
                    return a.Select(ai => -ai).ToArray();
                }
                double Dot(Double3[] u, Double3[] w) => u.Select((ui, i) => Double3.Dot(ui, w[i])).Sum();
                var basis = new System.Collections.Generic.List<Double3[]>();
                var start = particles.Select(p => new Double3(p.Velocity)).ToArray();
                double norm = Math.Sqrt(Dot(start, start));
                basis.Add(start.Select(v => v / norm).ToArray());
                var alpha = new double[size];
                var beta = new double[size];
                for (int k = 0; k < size; k++)
                {
                    var w = Apply(basis[k]);
                    alpha[k] = Dot(w, basis[k]);
                    foreach (var q in basis) // full reorthogonalisation: the basis stays orthonormal in double precision
                    {
                        double c = Dot(w, q);
                        for (int i = 0; i < n; i++) w[i] -= q[i] * c;
                    }
                    if (k == size - 1) break;
                    beta[k] = Math.Sqrt(Dot(w, w));
                    basis.Add(w.Select(v => v / beta[k]).ToArray());
                }
                var tridiagonal = MathNet.Numerics.LinearAlgebra.Matrix<double>.Build.Dense(size, size);
                for (int k = 0; k < size; k++)
                {
                    tridiagonal[k, k] = alpha[k];
                    if (k + 1 < size) tridiagonal[k, k + 1] = tridiagonal[k + 1, k] = beta[k];
                }
                var evd = tridiagonal.Evd(MathNet.Numerics.LinearAlgebra.Symmetricity.Symmetric);
                var rates = Enumerable.Range(0, size).Select(i => evd.EigenValues[i].Real).ToArray();
                var weights = Enumerable.Range(0, size).Select(i => evd.EigenVectors[0, i] * evd.EigenVectors[0, i]).ToArray();
                return new OperatorSpectrum(rates, weights);
            }
        }

        /// <summary>The operator's spectrum as the mode sees it, on the spawned particles with the mode's velocities.</summary>
        static OperatorSpectrum Spectrum(PressureSolver solver = PressureSolver.Dfsph, float viscosity = Viscosity)
        {
            var scene = Box(solver, viscosity);
            using var sim = new FluidSimulation(GpuTestDevice.Unvalidated, scene);
            var particles = new Particle[sim.ParticleCount];
            sim.Particles.GetData(particles);
            for (int i = 0; i < particles.Length; i++)
                particles[i].Velocity = Cell(particles[i].Position);
            return OperatorSpectrum.Of(scene, particles, LanczosSteps);
        }

        const int LanczosSteps = 40; // every amplitude the tests read is the same to four places at 70

        /// <summary>A relative difference as a signed percentage with two decimals ("+0.00 %" when it rounds to zero).</summary>
        static string Signed(double fraction)
        {
            double percent = Math.Round(100.0 * fraction, 2);
            return (percent < 0 ? "-" : "+") + Math.Abs(percent).ToString("0.00", System.Globalization.CultureInfo.InvariantCulture) + " %";
        }

        /// <summary>The two stages on the GPU against the viscous operator's exact decay of the mode, the viscous step alone
        /// (no pressure solve, no drift) at 1.23, 4.9 and 9.8 explicit limits: the GPU's amplitude must be what the two
        /// stages' factor (1 - (1 - 2 gamma) x) / (1 + gamma x)^2, x = mu dt, gives on the operator's spectrum, to within the
        /// solve's tolerance, and that within 0.5 % of the exact decay sum w exp(-mu t); backward Euler's factor 1 / (1 + x)
        /// leaves the mode 4 % above it at 9.8 limits, which the test must be able to tell.</summary>
        [Test]
        public void TheViscousStepDecaysTheFlowAsTheViscousOperatorDoes()
        {
            var spectrum = Spectrum();
            double exact = spectrum.Amplitude(mu => Math.Exp(-mu * Seconds));
            double g = ImplicitViscosity.StageFraction;
            TestContext.Progress.WriteLine($"the operator's spectrum by {LanczosSteps} Lanczos steps: rates {spectrum.Rates.Min():F2} to " +
                $"{spectrum.Rates.Max():F0}/s, the mode's Rayleigh quotient {spectrum.Rayleigh:F2}/s (Stokes's 2 nu k^2: " +
                $"{2.0 * (Viscosity / 1000.0) * K * K:F2}/s); its exact amplitude at {Seconds} s {exact:F4} U, where " +
                $"exp(-Rayleigh t) gives {Math.Exp(-spectrum.Rayleigh * Seconds):F4} U");
            foreach (int steps in new[] { 32, 8, 4 })
            {
                var run = Decay(steps, viscosityAlone: true);
                double dt = Seconds / steps;
                double twoStages = spectrum.Amplitude(mu => Math.Pow((1.0 - (1.0 - 2.0 * g) * mu * dt) / Math.Pow(1.0 + g * mu * dt, 2), steps));
                double euler = spectrum.Amplitude(mu => Math.Pow(1.0 + mu * dt, -steps));
                TestContext.Progress.WriteLine($"  {steps} steps: the GPU's {run.amplitude:F4} U, the two stages' on the spectrum " +
                    $"{twoStages:F4} U ({Signed(run.amplitude / twoStages - 1)}), {Signed(twoStages / exact - 1)} from the exact; " +
                    $"backward Euler's {euler:F4} U ({Signed(euler / exact - 1)})");
                Assert.That(run.rounds, Is.GreaterThan(0), "the step is beyond the explicit limit");
                Assert.That(run.amplitude / twoStages - 1.0, Is.InRange(-2e-3, 2e-3), "the GPU takes the two stages' step");
                Assert.That(twoStages / exact - 1.0, Is.InRange(-5e-3, 5e-3), "the two stages' step is near exact");
                if (steps == 4)
                    Assert.That(euler / exact - 1.0, Is.GreaterThan(0.02), "backward Euler's would not be");
                Assert.That(run.momentum, Is.LessThan(1e-3), "free-slip walls take no momentum");
            }
        }

        /// <summary>
        /// The whole sub-step: the flow decays faster than the viscosity alone takes it (the mode's exact amplitude under
        /// the operator), since each sub-step's pressure takes its discretely divergent part, and how much it takes depends
        /// on the sub-step. The explicit force in 100 and 50 sub-steps agrees to 2 %: the converged decay. The two stages
        /// at 1.23, 4.9 and 9.8 explicit limits stay within a bound of it at every step. Under DFSPH (nu = 0.1 m^2/s over
        /// 0.05 s) they leave more of the flow the longer the step, the split between the viscous step and the pressure
        /// solves being first order: at 9.8 limits 10.0 % more than the converged decay, within 12 %, where backward Euler
        /// left 19 % (experiment viscosity-backward-euler). Under WCSPH (nu = 1 m^2/s over 5 ms, since its Tait pressure
        /// bounds the step near 1.7 ms), solving on each half kick: +0.7, -1.2 and -4.7 %, within 6 %
        /// (Headless/docs/physics.md, "Viscosity solved implicitly").
        /// </summary>
        [TestCase(PressureSolver.Dfsph, Viscosity, Seconds, 0.12)]
        [TestCase(PressureSolver.Wcsph, 10 * Viscosity, Seconds / 10, 0.06)]
        public void TheCellularFlowConvergesAsTheSubStepShrinks(PressureSolver solver, float viscosity, double seconds, double bound)
        {
            // The shortest run under the validation layer, so that every variant these runs take has run validated once.
            (double amplitude, double momentum, int rounds) Run(int steps) => Decay(steps, false, solver, viscosity, seconds, validated: steps == 4);
            var spectrum = Spectrum(solver, viscosity);
            double viscosityAlone = spectrum.Amplitude(mu => Math.Exp(-mu * seconds));
            var explicitRuns = new[] { Run(100), Run(50) };
            double converged = explicitRuns[0].amplitude;
            TestContext.Progress.WriteLine($"{solver}: the viscosity alone leaves {viscosityAlone:F4} U; the explicit force {converged:F4} U in 100 " +
                $"sub-steps, {explicitRuns[1].amplitude:F4} U in 50 ({Signed(explicitRuns[1].amplitude / converged - 1)})");
            Assert.That(explicitRuns.Select(r => r.rounds), Is.All.EqualTo(0), "within the explicit limit");
            Assert.That(explicitRuns[1].amplitude / converged - 1.0, Is.InRange(-0.02, 0.02), "converged in the sub-step");
            double previous = converged;
            foreach (int steps in new[] { 32, 8, 4 })
            {
                var run = Run(steps);
                double excess = run.amplitude / converged - 1.0;
                TestContext.Progress.WriteLine($"  {steps} steps: {run.amplitude:F4} U, {Signed(excess)} against the converged decay");
                Assert.That(run.rounds, Is.GreaterThan(0), "the step is beyond the explicit limit");
                if (solver == PressureSolver.Dfsph)
                    Assert.That(run.amplitude, Is.GreaterThan(previous), "the longer the step, the more of the flow it leaves");
                Assert.That(run.amplitude, Is.LessThan(viscosityAlone), "the pressure takes some of the flow");
                Assert.That(Math.Abs(excess), Is.LessThan(bound));
                Assert.That(run.momentum, Is.LessThan(1e-3), "free-slip walls take no momentum");
                previous = run.amplitude;
            }
        }

        /// <summary>
        /// How much of the cellular flow is a rigid rotation about its axis (y, through the box's centre): in a continuum
        /// 768 / pi^6 = 0.799 of its kinetic energy, the mode's projection on (z, 0, -x). A viscous stress does not act on a
        /// rigid rotation, so a viscosity that keeps angular momentum (ViscousStress.StrainRate; the experiment
        /// central-pair-viscosity) leaves that share to the pressure, which stops it only through the walls, since a
        /// square's corners cannot turn inside it. DFSPH's solves do so every sub-step; WCSPH's pressure crosses the box at
        /// its speed of sound, and its cellular flow above runs 5 ms (Headless/docs/known-limits.md, "Morris's viscosity,
        /// the default, brakes a spinning liquid"). The spawned particles' share must be the continuum's to 1 %.
        /// </summary>
        [Test]
        public void TheCellularFlowIsMostlyARigidRotation()
        {
            var scene = Box(PressureSolver.Wcsph, 10 * Viscosity);
            using var sim = new FluidSimulation(GpuTestDevice.Unvalidated, scene);
            var particles = new Particle[sim.ParticleCount];
            sim.Particles.GetData(particles);
            double along = 0.0, mode = 0.0, rotation = 0.0;
            foreach (var p in particles)
            {
                Vector3 m = Cell(p.Position), r = new Vector3(p.Position.Z, 0f, -p.Position.X);
                along += Vector3.Dot(m, r);
                mode += Vector3.Dot(m, m);
                rotation += Vector3.Dot(r, r);
            }
            double share = along * along / (mode * rotation), continuum = 768.0 / Math.Pow(Math.PI, 6);
            double side = Cells * Spacing, crossing = side / sim.TimeStep.SpeedOfSound;
            TestContext.Progress.WriteLine($"the cellular flow's kinetic energy in a rigid rotation about its axis: {share:F3} of it on the " +
                $"{particles.Length} particles, {continuum:F3} in a continuum; WCSPH's sound ({sim.TimeStep.SpeedOfSound:F2} m/s) crosses " +
                $"the {1000 * side:F0} mm box in {1000 * crossing:F1} ms");
            Assert.That(share / continuum - 1.0, Is.InRange(-0.01, 0.01));
        }

        /// <summary>The solve against the step it takes, in double precision on the CPU: Alexander's two stages
        /// (SphViscositySolve.hlsl) with gravity's kick v* - v_n as their forcing, each (I - h a) x = t solved by conjugate
        /// gradients with ReferenceSph's viscous acceleration a as the operator, in the mass-weighted inner product in which
        /// it is symmetric. A block of jittered water with a free surface and no-slip walls, random velocities, one
        /// prediction at ten times the explicit limit. The GPU's velocities must be the CPU's to within each stage's
        /// tolerance of its change, the first stage's error carried into the second's target dt / h - 1 times.</summary>
        /// Under the strain rate's stress the stages solve with Morris's operator doubled (the Laplacian reference's
        /// acceleration twice over), and the rotation term, ReferenceSph's strain-rate acceleration less that at the
        /// velocities the sub-step starts with, joins gravity in v* - v_n.
        [TestCase(false, ViscousStress.Laplacian)]
        [TestCase(true, ViscousStress.Laplacian)]
        [TestCase(true, ViscousStress.StrainRate)]
        public void ThePredictedVelocitiesAreTheTwoStageStepToItsTolerance(bool oilOnWater, ViscousStress stress)
        {
            var settings = Weightless();
            settings.Gravity = new Vector3(0f, -9.81f, 0f);
            settings.ViscousStress = stress;
            Assert.That(settings.VelocityDamping, Is.EqualTo(0f), "v* = v_n + g dt");
            var block = new Vector3(10 * Spacing, 8 * Spacing, 10 * Spacing);
            var container = new Vector3(10 * Spacing, 12 * Spacing, 10 * Spacing);
            var scene = oilOnWater
                ? SolverScenes.Scene(settings, container,
                    SolverScenes.Box("Water", SolverScenes.Water(0.05f), new Vector3(0f, -4 * Spacing, 0f), block * new Vector3(1f, 0.5f, 1f), jitter: 0.1f),
                    SolverScenes.Box("Oil", SolverScenes.Oil(Viscosity), new Vector3(0f, 0f, 0f), block * new Vector3(1f, 0.5f, 1f), seed: 2, jitter: 0.1f))
                : SolverScenes.Scene(settings, container,
                    SolverScenes.Box("Water", SolverScenes.Water(Viscosity), new Vector3(0f, -2 * Spacing, 0f), block, jitter: 0.1f));
            using var sim = new FluidSimulation(GpuTestDevice.Shared, scene);
            var particles = new Particle[sim.ParticleCount];
            sim.Particles.GetData(particles);
            var rng = new SolverScenes.Rng(7);
            for (int i = 0; i < particles.Length; i++)
                particles[i].Velocity = new Vector3(rng.Range(-1f, 1f), rng.Range(-1f, 1f), rng.Range(-1f, 1f)) * 0.01f;
            sim.SetParticles(particles);
            sim.Particles.GetData(particles);
            var before = particles.ToDictionary(p => p.Id, p => new Double3(p.Velocity));
            float dt = (float)(10.0 * sim.TimeStep.ViscousTimeStep);
            sim.PredictVelocities(dt);
            var solved = new Particle[particles.Length];
            sim.Particles.GetData(solved);
            particles = solved; // the CPU's stages in the order the GPU's sort left
            var start = particles.Select(p => before[p.Id]).ToArray();
            var laplacianScene = new FluidSceneDescription
            {
                Settings = settings.Clone(), SpawnBoxes = scene.SpawnBoxes, Container = scene.Container, Obstacles = scene.Obstacles,
            };
            laplacianScene.Settings.ViscousStress = ViscousStress.Laplacian;
            var reference = new ReferenceSph(laplacianScene);
            double stressScale = stress == ViscousStress.StrainRate ? 2.0 : 1.0;
            var rotationTerm = new Double3[start.Length];
            if (stress == ViscousStress.StrainRate)
            {
                var atStart = (Particle[])particles.Clone();
                for (int i = 0; i < atStart.Length; i++) atStart[i].Velocity = start[i].ToVector3();
                var full = new ReferenceSph(scene).Evaluate(atStart, false).Acceleration;
                var morris = reference.Evaluate(atStart, false).Acceleration;
                var gravity = new Double3(settings.Gravity);
                for (int i = 0; i < start.Length; i++) rotationTerm[i] = (full[i] - gravity) - (morris[i] - gravity) * stressScale;
            }
            var predicted = start.Select((v, i) => v + (new Double3(settings.Gravity) + rotationTerm[i]) * dt).ToArray();

            var masses = particles.Select(p => (double)reference.PhaseTable[(int)p.Phase].ParticleMass).ToArray();
            double h = ImplicitViscosity.StageFraction * dt;
            var firstTarget = start.Select((v, i) => v + (predicted[i] - v) * (h / dt)).ToArray();
            var first = StageOnTheCpu(reference, particles, masses, firstTarget, h * stressScale, settings.Gravity);
            var secondTarget = predicted.Select((v, i) => v + (first[i] - firstTarget[i]) * (dt / h - 1.0)).ToArray();
            var step = StageOnTheCpu(reference, particles, masses, secondTarget, h * stressScale, settings.Gravity);

            double error = 0.0, change = 0.0, firstChange = 0.0, secondChange = 0.0;
            for (int i = 0; i < particles.Length; i++)
            {
                error += masses[i] * (new Double3(solved[i].Velocity) - step[i]).LengthSquared();
                change += masses[i] * (step[i] - predicted[i]).LengthSquared();
                firstChange += masses[i] * (first[i] - firstTarget[i]).LengthSquared();
                secondChange += masses[i] * (step[i] - secondTarget[i]).LengthSquared();
            }
            double rotationShare = Math.Sqrt(masses.Select((m, i) => m * (rotationTerm[i] * dt).LengthSquared()).Sum() / change);
            double relative = Math.Sqrt(error / change);
            double bound = ImplicitViscosity.Tolerance * ((dt / h - 1.0) * Math.Sqrt(firstChange) + Math.Sqrt(secondChange)) / Math.Sqrt(change);
            TestContext.Progress.WriteLine($"{stress}, {particles.Length} particles, {dt / sim.TimeStep.ViscousTimeStep:F1} explicit limits, " +
                $"{sim.ViscositySolveRounds} rounds: the GPU's velocities are the CPU's two stages to {relative:E2} of the change " +
                $"(mass-weighted RMS; bound {bound:E2}); the rotation term moved v* by {rotationShare:E2} of it");
            Assert.That(Math.Sqrt(change / masses.Sum()), Is.GreaterThan(0.005), "the viscosity changed the velocities");
            Assert.That(relative, Is.LessThan(bound));
            if (stress == ViscousStress.StrainRate) Assert.That(rotationShare, Is.GreaterThan(10 * bound), "the case must test the rotation term");
        }

        /// <summary>x with (I - h a) x = target, a the CPU reference's viscous acceleration at the particles' places
        /// (its acceleration less gravity: linear in the velocities, with no tension and still walls), by conjugate gradients in the inner product
        /// sum m_i x_i . y_i, to 1e-6 of the target (the particles carry their velocities in single precision).</summary>
        static Double3[] StageOnTheCpu(ReferenceSph reference, Particle[] particles, double[] masses, Double3[] target, double h,
            Vector3 gravity)
        {
            int n = particles.Length;
            var moving = (Particle[])particles.Clone();
            Double3[] Apply(Double3[] x)
            {
                for (int i = 0; i < n; i++) moving[i].Velocity = x[i].ToVector3();
                var a = reference.Evaluate(moving, false).Acceleration;
                return x.Select((xi, i) => xi - (a[i] - new Double3(gravity)) * h).ToArray();
            }
            double Inner(Double3[] u, Double3[] w)
            {
                double sum = 0.0;
                for (int i = 0; i < n; i++) sum += masses[i] * Double3.Dot(u[i], w[i]);
                return sum;
            }
            var x = (Double3[])target.Clone();
            var applied = Apply(x);
            var r = target.Select((t, i) => t - applied[i]).ToArray();
            var p = (Double3[])r.Clone();
            double rr = Inner(r, r), stop = 1e-12 * Inner(target, target);
            for (int k = 0; k < 200 && rr > stop; k++)
            {
                var bp = Apply(p);
                double alpha = rr / Inner(p, bp);
                for (int i = 0; i < n; i++) { x[i] += p[i] * alpha; r[i] -= bp[i] * alpha; }
                double next = Inner(r, r);
                for (int i = 0; i < n; i++) p[i] = r[i] + p[i] * (next / rr);
                rr = next;
            }
            Assert.That(rr, Is.LessThanOrEqualTo(stop), "the CPU's conjugate gradients converged");
            return x;
        }

        /// <summary>A viscous liquid's flow that buoyancy drives: OilAndWater with its oil at 100 Pa s, whose explicit limit
        /// is 0.64 ms. Under DFSPH, solved implicitly at the scene's own 4.17 ms steps, its kinetic energy at 0.1 s must stay
        /// within 0.5 to 1.6 times the explicit force's at 0.64 ms steps (1.44: the split between the viscous step and the
        /// pressure solves is first order, Headless/docs/physics.md). WCSPH's own step, 1.85 ms, is 2.9 limits, where the
        /// solve's rounds cost more than the sub-steps they stand for (ImplicitViscosity.PaysOff), so it keeps the explicit
        /// force at the limit: no rounds, and the same energy to 1 %. (Solved there, it took 1.8 times the wall time at 1.04
        /// times the energy.) Under DFSPH with the
        /// viscosity solved before the constant-density solve instead, each step's pressure kick went undamped into the
        /// drift, a flow that viscosity holds ran 1 + lambda dt times its speed, and the fluid had 7.3 times the kinetic
        /// energy; with the two stages taking that kick before them instead of as their forcing, 2.6 times
        /// (SphViscositySolve.hlsl).</summary>
        [TestCase(PressureSolver.Dfsph, 0.5, 1.6)]
        [TestCase(PressureSolver.Wcsph, 0.99, 1.01)]
        public void ABuoyancyDrivenViscousFlowRunsAsWithTheExplicitForce(PressureSolver solver, double low, double high)
        {
            int rounds = 0;
            double KineticAt(string maxTimeStep)
            {
                var path = RunnerPaths.EditedScene("OilAndWater", "MaxTimeStep: 0.005\n", $"MaxTimeStep: {maxTimeStep}\n");
                var scene = SceneLoader.Load(path, RunnerPaths.Project).Description;
                Assert.That(new SolverChoice { Solver = solver }.ApplyTo(scene, $"{solver} OilAndWater"), Is.Null);
                foreach (var box in scene.SpawnBoxes)
                    if (box.Phase.Name == "Oil") box.Phase.Viscosity = 100f;
                using var sim = new FluidSimulation(GpuTestDevice.Unvalidated, scene);
                while (sim.SimulatedTime < 0.1 - 1e-6)
                    sim.Step(1f / 60f);
                double kinetic = sim.ReadDiagnostics().KineticEnergy;
                rounds = sim.ViscositySolveRounds;
                TestContext.Progress.WriteLine($"{solver}, steps of {1000 * sim.LastStep.TimeStep:F3} ms ({sim.LastStep.TimeStep / sim.TimeStep.ViscousTimeStep:F2} " +
                    $"explicit limits, {sim.ViscositySolveRounds} rounds): kinetic energy at 0.1 s {kinetic:E3} J");
                return kinetic;
            }
            double explicitForce = KineticAt("0.00064"), implicitSolve = KineticAt("0.005");
            Assert.That(implicitSolve / explicitForce, Is.InRange(low, high));
            Assert.That(rounds, solver == PressureSolver.Dfsph ? Is.GreaterThan(0) : Is.EqualTo(0), "the solve only where it pays off");
        }
    }
}
