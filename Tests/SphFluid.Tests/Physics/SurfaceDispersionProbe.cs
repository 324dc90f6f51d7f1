using System;
using System.Collections.Generic;
using System.Linq;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// The simulated free surface's dispersion relation: why <see cref="SurfaceSeicheTests"/>' tank sloshes faster than
    /// omega^2 = g k tanh(k h) says. A measurement run by name, `bash Headless/test.sh --filter
    /// FullyQualifiedName~SurfaceDispersionProbe`, which CI does not run.
    /// <para>
    /// The shipped RestingTank's water settles flat for <see cref="SettleSeconds"/>; then every particle is given the
    /// linear standing wave's velocity for mode n (n half wavelengths along the tank, k = n pi / L) at the instant its
    /// surface passes level, with k a = 0.1 (<see cref="Steepness"/>) so that the swing's own nonlinearity is the same
    /// small fraction for every mode. The mode's amplitude, a_n = 2 / (L W) sum_i V_i cos(k x_i) over the particles' volumes
    /// (the flat lattice's sum is exactly zero, and for an incompressible fluid it changes only by the surface's motion),
    /// is sampled every frame and a damped oscillation is fitted to it.
    /// </para>
    /// <para>
    /// What tells the candidate causes apart is how the excess of omega^2 over gravity's changes with k. A fluid whose
    /// own length is not the tank's shifts every mode's omega^2 by the same fraction; a uniform shear stiffness G adds
    /// (G / rho) k^2, a fraction growing as k; a surface tension sigma adds (sigma / rho) k^3, a fraction growing as k^2
    /// (Lamb, "Hydrodynamics", art. 267). The particle lattice's shear moduli grow with the pressure
    /// (<see cref="LatticeStability.ShearModulusRatio"/>), so with the depth as fast as a wave's strain decays, and add
    /// about the same fraction to every mode (<see cref="SurfaceSeiche.ElasticExcess"/>); each run prints that fraction
    /// and what the measurement leaves beside it. The probe prints each mode's excess and its ratio to the first
    /// mode's, to be read against 1 : 1 : 1, 1 : 2 : 3 and 1 : 4 : 9.
    /// </para>
    /// <para>
    /// Fixtures (<see cref="SloshingTankConfiguration"/>): WCSPH as shipped (Wendland C2 at 2.85 spacings); WCSPH with
    /// the cubic spline at 2 spacings (a lattice about three times as strong in shear); DFSPH as <c>--solver dfsph</c>
    /// runs the scene; the shipped scene spawned with a quarter spacing of jitter, which disorders the lattice that the
    /// crystal's shear stiffness needs; its walls free-slip, which push only along their normals; its swing halved (k a
    /// = 0.05), for a stiffness that depends on how far the particles move; the tank and its water twice as long (0.8
    /// m), whose second mode has the first mode's k in the shipped tank, to tell an error that follows k from one that
    /// follows the mode's shape; the tank narrowed to 0.1 m across at the scene's spacing and at half of it (8 times
    /// the particles), under each solver, to tell an error that follows the spacing from one that follows the tank; and
    /// the shipped kernel's support set to 2.7, 3, 3.5 and 4 spacings, where the lattice's stiffness against a stretch
    /// (C') swings from 8.6 % of the pressure to below zero and back while the kernel widens steadily.
    /// </para>
    /// </summary>
    [Explicit("a measurement, not a check: run it by name")]
    [TestFixture("wcsph")]
    [TestFixture("cubic spline")]
    [TestFixture("dfsph")]
    [TestFixture("jittered")]
    [TestFixture("free-slip")]
    [TestFixture("half swing")]
    [TestFixture("long tank")]
    [TestFixture("narrow")]
    [TestFixture("narrow, half the spacing")]
    [TestFixture("dfsph, narrow")]
    [TestFixture("dfsph, narrow, half the spacing")]
    [TestFixture("support 2.7")]
    [TestFixture("support 3.0")]
    [TestFixture("support 3.5")]
    [TestFixture("support 4.0")]
    public sealed class SurfaceDispersionProbe
    {
        const double SettleSeconds = 0.5, RecordSeconds = 1.5;
        readonly string _configuration;
        readonly SortedDictionary<int, double> _excess = new SortedDictionary<int, double>();

        /// <summary>k a of the kicked wave: a swing whose own nonlinearity changes the period by a fraction of order (k
        /// a)^2, the same for every mode.</summary>
        double Steepness => _configuration == "half swing" ? 0.05 : 0.1;

        public SurfaceDispersionProbe(string configuration) => _configuration = configuration;

        // One test a mode, so that a slow configuration's modes can run side by side (a filter on the test's name).
        [Test]
        public void TheFirstModeSloshesAtItsStandingWavePeriod() => Measure(1);

        [Test]
        public void TheSecondModeSloshesAtItsStandingWavePeriod() => Measure(2);

        [Test]
        public void TheThirdModeSloshesAtItsStandingWavePeriod() => Measure(3);

        [OneTimeTearDown]
        public void PrintTheExcessByMode()
        {
            if (_excess.Count == 0) return;
            string ratios = _excess.ContainsKey(1)
                ? "; against mode 1 " + string.Join(" : ", _excess.Values.Select(e => (e / _excess[1]).ToString("F2"))) +
                  " (a length error 1 : 1 : 1, a shear stiffness 1 : 2 : 3, a surface tension 1 : 4 : 9)"
                : "";
            TestContext.Progress.WriteLine($"surface dispersion ({_configuration}): omega^2 over theory's - 1 by mode " +
                string.Join(", ", _excess.Select(e => $"{e.Key}: {100 * e.Value:+0.00;-0.00} %")) + ratios);
        }

        void Measure(int mode)
        {
            var scene = SloshingTankConfiguration.Load(_configuration);
            var (measured, theory, report) = Run(scene, mode, Steepness);
            _excess[mode] = Math.Pow(measured / theory, 2) - 1;
            Assert.That(report.NanCount, Is.EqualTo(0));
            Assert.That(report.OutsideCount, Is.EqualTo(0));
        }

        /// <summary>Settles the tank, kicks mode <paramref name="mode"/> and returns the fitted and the theory's angular
        /// frequency for the water's measured depth.</summary>
        static (double Measured, double Theory, DiagnosticsReport Report) Run(FluidSceneDescription scene, int mode, double steepness)
        {
            var s = scene.Settings;
            var container = scene.Container;
            double length = container.Size.X, width = container.Size.Z, g = s.Gravity.Length(), k = mode * Math.PI / length;
            double left = container.Position.X - length / 2, floor = container.Position.Y - container.Size.Y / 2;
            using var sim = new FluidSimulation(GpuTestDevice.Unvalidated, scene);
            var particles = new Particle[sim.ParticleCount];
            var densities = new Vector4[sim.ParticleCount];
            var phase = sim.PhaseRows.Single();
            while (sim.SimulatedTime < SettleSeconds - 1e-6) sim.Step(1f / 60f);

            sim.Particles.GetData(particles);
            sim.Densities.GetData(densities);
            double volume = 0;
            for (int i = 0; i < particles.Length; i++) volume += phase.ParticleMass / densities[i].X;
            double depth = volume / (length * width), omega = SurfaceSeiche.AngularFrequency(length, depth, g, mode);
            double a = steepness / k, surface = floor + depth;
            for (int i = 0; i < particles.Length; i++)
            {
                // The potential flow of a standing wave whose surface a cos(k x) sin(omega t) passes level at t = 0.
                double x = particles[i].Position.X - left, z = particles[i].Position.Y - surface;
                double u = -a * omega * Math.Sin(k * x) * Math.Cosh(k * (z + depth)) / Math.Sinh(k * depth);
                double w = a * omega * Math.Cos(k * x) * Math.Sinh(k * (z + depth)) / Math.Sinh(k * depth);
                particles[i].Velocity += new Vector3((float)u, (float)w, 0f);
            }
            sim.SetParticles(particles);

            double start = sim.SimulatedTime;
            var times = new List<double>();
            var amplitudes = new List<double>();
            void Sample()
            {
                sim.Particles.GetData(particles);
                sim.Densities.GetData(densities);
                double sum = 0;
                for (int i = 0; i < particles.Length; i++)
                    sum += phase.ParticleMass / densities[i].X * Math.Cos(k * (particles[i].Position.X - left));
                times.Add(sim.SimulatedTime - start);
                amplitudes.Add(2 * sum / (length * width));
            }
            Sample();
            while (sim.SimulatedTime - start < RecordSeconds - 1e-6)
            {
                sim.Step(1f / 60f);
                Sample();
            }
            var report = sim.ReadDiagnostics();
            var fit = InternalSeiche.FitDampedOscillation(times, amplitudes, highestOmega: 2 * omega, highestGamma: 10);
            var crossings = InternalSeiche.ZeroCrossings(times, amplitudes.Select(v => v - amplitudes[0]).ToList());
            var (axis, diagonal) = ElasticInterfaceMode.ModulusRatios(s.SmoothingKernel, s.ParticleSpacing, s.SmoothingRadius);
            double elastic = SurfaceSeiche.ElasticExcess(k, depth, axis, diagonal);
            TestContext.Progress.WriteLine(
                $"surface dispersion ({s.PressureSolver}, {s.SmoothingKernel} at {s.SmoothingRadius / s.ParticleSpacing:F2} spacings, " +
                $"jitter {scene.SpawnBoxes.Single().Jitter} spacings, {scene.Container.Friction} walls), mode {mode} (k {k:F2}/m, a {1000 * a:F1} mm), N={sim.ParticleCount}: " +
                $"depth {1000 * depth:F1} mm; theory: period {2 * Math.PI / omega:F4} s; fitted over {RecordSeconds} s after {SettleSeconds} s " +
                $"of settling: period {2 * Math.PI / fit.Omega:F4} s ({100 * (omega / fit.Omega - 1):+0.00;-0.00} %; omega^2 " +
                $"{100 * (Math.Pow(fit.Omega / omega, 2) - 1):+0.00;-0.00} %), decay {fit.Gamma:F3}/s " +
                $"(RMS residual {1000 * fit.Residual:F2} mm of the swing's {1000 * amplitudes.Max(v => Math.Abs(v - amplitudes[0])):F2}); " +
                $"crossings at {string.Join(", ", crossings.Select(t => t.ToString("F3")))} s; the rest lattice's shear moduli per unit " +
                $"pressure C44 / p {axis:F4}, C' / p {diagonal:F4}, whose elasticity adds {100 * elastic:+0.00;-0.00} % to omega^2, leaving " +
                $"{100 * (Math.Pow(fit.Omega / omega, 2) - 1 - elastic):+0.00;-0.00} %; the kernel's RMS width along an axis " +
                $"{1000 * KernelWidth(s):F1} mm; {report}");
            return (fit.Omega, omega, report);
        }

        /// <summary>The kernel's RMS width along one axis, sqrt(integral of x^2 W dV / integral of W dV), m: the length
        /// whose square, times k^2, smoothing a field over the kernel takes off its response.</summary>
        static double KernelWidth(FluidSettings s)
        {
            const int steps = 20000;
            double h = s.SmoothingRadius, second = 0, zeroth = 0;
            for (int i = 0; i < steps; i++)
            {
                double r = (i + 0.5) * h / steps, shell = r * r * SmoothingKernels.Value(s.SmoothingKernel, r, h);
                second += r * r * shell;
                zeroth += shell;
            }
            return Math.Sqrt(second / zeroth / 3);
        }
    }
}
