using System.IO;
using System.Linq;
using System.Numerics;
using System.Xml;
using NUnit.Framework;
using SphFluid.Headless;
using SphFluid.Headless.Cli;
using SphFluid.Headless.Output;
using SphFluid.Headless.Runs;
using SphFluid.Headless.Scenes;
using SphFluid.Simulation;
using SphFluid.Tests.Output;

namespace SphFluid.Tests.Runner
{
    /// <summary>Particle export and the new measures against the GPU's own buffers and reductions.</summary>
    public sealed class ParticleExportRunTests
    {
        /// <param name="density">How the density is found, where a test needs one (default: the scene's).</param>
        static FluidSimulation OilAndWater(WcsphDensity? density = null)
        {
            var scene = SceneLoader.Load(RunnerPaths.Scene("OilAndWater"));
            ParticleScaling.ScaleBy(scene.Description, 0.1);
            if (density.HasValue) scene.Description.Settings.WcsphDensity = density.Value;
            return new FluidSimulation(GpuTestDevice.Shared, scene.Description);
        }

        /// <summary>Steps three frames and reads the particle and density buffers back.</summary>
        static (Particle[] Particles, Vector4[] Densities) AfterThreeFrames(FluidSimulation sim)
        {
            for (int frame = 0; frame < 3; frame++) sim.Step(1f / 60f);
            var particles = new Particle[sim.ParticleCount];
            var densities = new Vector4[sim.ParticleCount];
            sim.Particles.GetData(particles);
            sim.Densities.GetData(densities);
            return (particles, densities);
        }

        [Test]
        public void AVtuReadBackEqualsTheGpuBuffers()
        {
            using var sim = OilAndWater();
            var (particles, densities) = AfterThreeFrames(sim);
            string path = Path.Combine(RunnerPaths.ScratchFolder("gpu-vtu"), "particles_0000.vtu");

            VtuParticles.Write(path, sim.SimulatedTime, particles, densities);

            // Read the buffers again: the file must hold what the GPU holds, bit for bit.
            var gpuParticles = new Particle[sim.ParticleCount];
            var gpuDensities = new Vector4[sim.ParticleCount];
            sim.Particles.GetData(gpuParticles);
            sim.Densities.GetData(gpuDensities);
            var vtu = new VtuReader(path);
            float[] positions = vtu.Positions, velocities = vtu.PointData("velocity", 3), density = vtu.PointData("density"), pressure = vtu.PointData("pressure");
            uint[] phase = vtu.UInts("PointData/DataArray[@Name='phase']"), id = vtu.UInts("PointData/DataArray[@Name='id']");
            Assert.That(vtu.Points, Is.EqualTo(sim.ParticleCount));
            Assert.That(vtu.Time, Is.EqualTo(sim.SimulatedTime));
            int pressured = 0;
            for (int i = 0; i < sim.ParticleCount; i++)
            {
                var p = gpuParticles[i];
                Assert.That(new Vector3(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]), Is.EqualTo(p.Position), "position " + i);
                Assert.That(new Vector3(velocities[3 * i], velocities[3 * i + 1], velocities[3 * i + 2]), Is.EqualTo(p.Velocity), "velocity " + i);
                Assert.That(phase[i], Is.EqualTo(p.Phase));
                Assert.That(id[i], Is.EqualTo(p.Id));
                Assert.That(density[i], Is.EqualTo(gpuDensities[i].X), "density " + i);
                Assert.That(pressure[i], Is.EqualTo(gpuDensities[i].Y), "pressure " + i);
                if (pressure[i] > 0) pressured++;
            }
            Assert.That(density.Min(), Is.GreaterThan(100f), "real densities, not an empty buffer");
            Assert.That(pressured, Is.GreaterThan(0), "some particle is compressed, so pressure is exported too");
            Assert.That(phase.Distinct().Count(), Is.EqualTo(2));
        }

        [Test]
        public void CpuCompressionMatchesTheGpuReduction()
        {
            // Summation: its free surface is under-dense from the first step, so the expansion measure has work (the
            // scene's delta-SPH carries the hydrostatic spawn density there).
            using var sim = OilAndWater(WcsphDensity.Summation);
            var (particles, densities) = AfterThreeFrames(sim);
            var settings = sim.Scene.Settings;

            var measures = FluidMeasures.Measure(sim.SimulatedTime, particles, densities, sim.PhaseRows, sim.Scene.Container, settings.Gravity, settings.ParticleSpacing, settings.SmoothingRadius);
            var report = sim.ReadDiagnostics();

            for (int k = 0; k < 2; k++)
            {
                Assert.That(measures.Phases[k].Count, Is.EqualTo(report.Phases[k].Count));
                Assert.That(measures.Phases[k].CompressionAverage, Is.EqualTo(report.Phases[k].AverageDensityError).Within(1e-5), report.Phases[k].Name);
                Assert.That(measures.Phases[k].CompressionMax, Is.EqualTo(report.Phases[k].MaxDensityError).Within(1e-6), report.Phases[k].Name);
                Assert.That(measures.Phases[k].ExpansionAverage, Is.GreaterThan(0.0), "the free surface is under-dense");
            }
        }

        [Test]
        public void SimulateExportsOnItsOwnScheduleAndIndexesTheExports()
        {
            string outDir = RunnerPaths.ScratchFolder("export-run");
            var stdout = new StringWriter();
            var stderr = new StringWriter();
            var options = SimulateOptions.Parse(new[] { RunnerPaths.Scene("PlayModeTest"), "--seconds", "0.05", "--export-every", "0.025", "--out", outDir, "--quiet" });
            var run = new SimulateRun(options, stdout, stderr) { Device = GpuTestDevice.Shared, InteractiveProgress = false };

            int code = run.Execute();

            Assert.That(code, Is.EqualTo(ExitCodes.Ok), stdout + "\n" + stderr);
            // 60 Hz frames: exports at t = 0, at the first frame past 0.025 s (0.0333) and at 0.05 s.
            var pvd = new XmlDocument();
            pvd.Load(Path.Combine(outDir, "particles.pvd"));
            var sets = pvd.SelectNodes("/VTKFile/Collection/DataSet").OrFail("the .pvd's DataSets").Cast<XmlElement>().ToArray();
            Assert.That(sets.Select(s => s.GetAttribute("file")).ToArray(), Is.EqualTo(new[] { "particles_0000.vtu", "particles_0001.vtu", "particles_0002.vtu" }));
            Assert.That(double.Parse(sets[1].GetAttribute("timestep"), System.Globalization.CultureInfo.InvariantCulture), Is.EqualTo(2.0 / 60).Within(1e-4));
            var last = new VtuReader(Path.Combine(outDir, "particles_0002.vtu"));
            Assert.That(last.Points, Is.EqualTo(192));
            var summary = run.Summary.OrFail("the run's summary");
            Assert.That(last.Time, Is.EqualTo(summary.SimulatedSeconds).Within(1e-9));
            Assert.That(new PlyReader(Path.Combine(outDir, "particles_0002.ply")).Vertices, Is.EqualTo(192));
            Assert.That(File.Exists(Path.Combine(outDir, "particles_0003.vtu")), Is.False);
            Assert.That(summary.Exports, Is.EqualTo(3));
            string summaryText = File.ReadAllText(Path.Combine(outDir, "summary.txt"));
            Assert.That(summaryText, Does.Contain("particles_0000.vtu/.ply .. particles_0002.vtu/.ply, particles.pvd"));
            Assert.That(summaryText, Does.Contain("surge front: "));
            Assert.That(stdout.ToString(), Does.Contain(" PE="));
            Assert.That(stdout.ToString(), Does.Contain("3 particle export(s)"));
            Assert.That(stdout.ToString(), Does.Contain("; exports every 0.025 s: 3 of 0.02 MB"), "the run line says what the exports take");
        }

        [Test]
        public void ExportsThatWouldNotFitOnTheDiskAreRefusedBeforeTheRun()
        {
            string outDir = RunnerPaths.ScratchFolder("export-full-disk");
            var options = SimulateOptions.Parse(new[] { RunnerPaths.Scene("PlayModeTest"), "--seconds", "0.05", "--export-every", "0.025", "--out", outDir, "--quiet" });
            // Three exports of 192 particles take 3 x 21 536 bytes; the disk stands in with room for two.
            var run = new SimulateRun(options, new StringWriter(), new StringWriter())
                { Device = GpuTestDevice.Shared, InteractiveProgress = false, FreeBytes = _ => 50_000 };

            var refusal = Assert.Throws<UsageException>(() => run.Execute()).OrFail("the refusal");

            Assert.That(refusal.Message, Does.StartWith("simulate: --export-every 0.025 s over 0.05 s writes 3 exports of 192 particles, 0.1 MB of .vtu and .ply"));
            Assert.That(refusal.Message, Does.Contain($"the disk holding --out '{outDir}' has 0.1 MB free (2 exports fit, one every 0.05 s)"));
            Assert.That(Directory.EnumerateFiles(outDir, "particles*"), Is.Empty, "no export was written");
            Assert.That(run.Summary, Is.Null, "nothing was simulated");
        }

        [Test]
        public void SnapshotsThatWouldOutgrowTheDiskAreWarnedOfOnceTheFirstIsWritten()
        {
            string outDir = RunnerPaths.ScratchFolder("snapshots-full-disk");
            var options = SimulateOptions.Parse(new[] { RunnerPaths.Scene("PlayModeTest"), "--seconds", "0.05", "--frames-every", "0.0166", "--out", outDir, "--quiet" });
            var stderr = new StringWriter();
            // A disk with room for the first snapshot but not the three to come (the run itself writes to the real one).
            var run = new SimulateRun(options, new StringWriter(), stderr)
                { Device = GpuTestDevice.Shared, InteractiveProgress = false, FreeBytes = _ => 1_000 };

            int code = run.Execute();

            Assert.That(code, Is.EqualTo(ExitCodes.Ok), stderr.ToString());
            Assert.That(stderr.ToString(), Does.Match(@"simulate: warning: 4 more snapshot\(s\) \(\d+ KB each\) and 0 more export\(s\) need about 0\.\d MB, " +
                "more than the 0.0 MB free on the disk holding --out '.*'; the run will stop with a file error when the disk fills"));
        }

        [Test]
        public void TheHelpNamesTheExportAndTheMeasures()
        {
            var stdout = new StringWriter();

            int code = Program.Run(new[] { "simulate", "--help" }, stdout, new StringWriter());

            Assert.That(code, Is.EqualTo(ExitCodes.Ok));
            Assert.That(stdout.ToString(), Does.Contain("--export-every <S>"));
            Assert.That(stdout.ToString(), Does.Contain("particles.pvd"));
            Assert.That(stdout.ToString(), Does.Contain("(ordered - inverted) / pairs"));
            Assert.That(stdout.ToString(), Does.Contain("surge front"));
        }

        [TestCase("0", "--export-every must be in [0.0001, 3600] s (was 0)")]
        [TestCase("soon", "--export-every must be a number in [0.0001, 3600] s (was 'soon')")]
        public void ABadExportIntervalIsRefusedWithItsRange(string value, string message)
        {
            var stdout = new StringWriter();
            var stderr = new StringWriter();

            int code = Program.Run(new[] { "simulate", RunnerPaths.Scene("PlayModeTest"), "--export-every", value }, stdout, stderr);

            Assert.That(code, Is.EqualTo(ExitCodes.BadArguments));
            Assert.That(stderr.ToString(), Does.Contain(message));
        }
    }
}
