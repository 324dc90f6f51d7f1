using System;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Numerics;
using System.Xml;
using NUnit.Framework;
using SphFluid.Headless.Output;
using SphFluid.Simulation;
using SphFluid.Tests.Runner;

namespace SphFluid.Tests.Output
{
    /// <summary>The .vtu, .ply and .pvd writers, read back by the independent readers of this folder.</summary>
    public sealed class ParticleExportTests
    {
        static (Particle[] Particles, Vector4[] Densities) Sample(int n, int seed)
        {
            var random = new Random(seed);
            float Next() => (float)(random.NextDouble() * 2 - 1);
            var particles = new Particle[n];
            var densities = new Vector4[n];
            for (int i = 0; i < n; i++)
            {
                particles[i] = new Particle(new Vector3(Next(), Next(), Next()), new Vector3(Next(), Next(), Next()) * 3f, (uint)(i % 3), (uint)(n - 1 - i));
                densities[i] = new Vector4(1000f + 50f * Next(), 400f * Next(), 30f + Next(), Next());
            }
            return (particles, densities);
        }

        [Test]
        public void AVtuHoldsEveryParticlesPositionAndFields()
        {
            var (particles, densities) = Sample(101, 1);
            string path = Path.Combine(RunnerPaths.ScratchFolder("vtu"), "particles_0000.vtu");

            VtuParticles.Write(path, 0.125, particles, densities);

            var vtu = new VtuReader(path);
            Assert.That(vtu.Points, Is.EqualTo(101));
            Assert.That(vtu.Cells, Is.EqualTo(101));
            Assert.That(vtu.Time, Is.EqualTo(0.125));
            float[] positions = vtu.Positions, velocities = vtu.PointData("velocity", 3), density = vtu.PointData("density"), pressure = vtu.PointData("pressure");
            uint[] phase = vtu.UInts("PointData/DataArray[@Name='phase']"), id = vtu.UInts("PointData/DataArray[@Name='id']");
            Assert.That(positions.Length, Is.EqualTo(303));
            for (int i = 0; i < particles.Length; i++)
            {
                var p = particles[i];
                Assert.That(new Vector3(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]), Is.EqualTo(p.Position), "position " + i);
                Assert.That(new Vector3(velocities[3 * i], velocities[3 * i + 1], velocities[3 * i + 2]), Is.EqualTo(p.Velocity), "velocity " + i);
                Assert.That(phase[i], Is.EqualTo(p.Phase));
                Assert.That(id[i], Is.EqualTo(p.Id));
                Assert.That(density[i], Is.EqualTo(densities[i].X));
                Assert.That(pressure[i], Is.EqualTo(densities[i].Y));
            }
            Assert.That(vtu.Longs("Cells/DataArray[@Name='connectivity']"), Is.EqualTo(Enumerable.Range(0, 101).Select(i => (long)i).ToArray()));
            Assert.That(vtu.Longs("Cells/DataArray[@Name='offsets']"), Is.EqualTo(Enumerable.Range(1, 101).Select(i => (long)i).ToArray()));
            Assert.That(vtu.Raw("Cells/DataArray[@Name='types']", "UInt8", 1), Is.All.EqualTo((byte)1), "VTK_VERTEX cells");
        }

        [Test]
        public void APlyHoldsTheNamedPropertiesInBinaryLittleEndian()
        {
            var (particles, densities) = Sample(57, 2);
            string path = Path.Combine(RunnerPaths.ScratchFolder("ply"), "particles_0000.ply");

            PlyParticles.Write(path, 0.5, particles, densities);

            var ply = new PlyReader(path);
            Assert.That(ply.Vertices, Is.EqualTo(57));
            Assert.That(ply.Properties.Select(p => p.Type + " " + p.Name).ToArray(), Is.EqualTo(new[]
            {
                "float x", "float y", "float z", "float vx", "float vy", "float vz", "uint phase", "float density", "float pressure",
            }));
            for (int i = 0; i < particles.Length; i++)
            {
                var p = particles[i];
                var expected = new double[] { p.Position.X, p.Position.Y, p.Position.Z, p.Velocity.X, p.Velocity.Y, p.Velocity.Z, p.Phase, densities[i].X, densities[i].Y };
                Assert.That(ply.Rows[i], Is.EqualTo(expected), "vertex " + i);
            }
        }

        [Test]
        public void EachExportAddsVtuAndPlyAndTheTimeIndexListsThemAll()
        {
            string dir = RunnerPaths.ScratchFolder("export");
            var output = OutputFolder.Claim(dir, "--out", "test");
            var export = new ParticleExport(output);
            var (first, firstDensities) = Sample(10, 3);
            var (second, secondDensities) = Sample(10, 4);

            export.Write(0.0, first, firstDensities);
            export.Write(0.25, second, secondDensities);
            output.Dispose(); // the run's end: its manifest is the next run's to read

            Assert.That(export.Count, Is.EqualTo(2));
            foreach (string name in new[] { "particles_0000.vtu", "particles_0000.ply", "particles_0001.vtu", "particles_0001.ply", "particles.pvd" })
                Assert.That(File.Exists(Path.Combine(dir, name)), Is.True, name);
            Assert.That(File.ReadAllLines(Path.Combine(dir, OutputFolder.ManifestName)), Is.SupersetOf(new[]
            {
                "particles_0000.vtu", "particles_0000.ply", "particles_0001.vtu", "particles_0001.ply", "particles.pvd",
            }), "a later run may delete exactly these");
            Assert.That(new VtuReader(Path.Combine(dir, "particles_0001.vtu")).Positions[0], Is.EqualTo(second[0].Position.X));

            var pvd = new XmlDocument();
            pvd.Load(Path.Combine(dir, "particles.pvd"));
            Assert.That(pvd.DocumentElement.OrFail("the .pvd's root").GetAttribute("type"), Is.EqualTo("Collection"));
            var sets = pvd.SelectNodes("/VTKFile/Collection/DataSet").OrFail("the .pvd's DataSets").Cast<XmlElement>().ToArray();
            Assert.That(sets.Select(s => s.GetAttribute("file")).ToArray(), Is.EqualTo(new[] { "particles_0000.vtu", "particles_0001.vtu" }));
            Assert.That(sets.Select(s => double.Parse(s.GetAttribute("timestep"), CultureInfo.InvariantCulture)).ToArray(), Is.EqualTo(new[] { 0.0, 0.25 }));
        }

        [TestCase(1)]
        [TestCase(1000)]
        [TestCase(4160)]
        public void AnExportsSizeIsKnownBeforeItIsWritten(int n)
        {
            string dir = RunnerPaths.ScratchFolder("export-size-" + n);
            using var output = OutputFolder.Claim(dir, "--out", "test");
            var export = new ParticleExport(output);
            var (particles, densities) = Sample(n, 5);

            export.Write(0.5, particles, densities);

            long written = new FileInfo(Path.Combine(dir, "particles_0000.vtu")).Length + new FileInfo(Path.Combine(dir, "particles_0000.ply")).Length;
            // The estimate leaves out the files' headers only: about a kilobyte of XML and 250 bytes of PLY.
            Assert.That(written - ParticleExport.BytesPerExport(n), Is.InRange(0, 2048), $"{written} bytes written");
        }

        [TestCase(0.3, 18, 0.05, 7)]
        [TestCase(0.05, 3, 0.025, 3)]
        [TestCase(1.0, 60, 0.001, 61)] // at most one a frame and one at the start
        [TestCase(0.5, 30, 10.0, 1)]
        public void ExportsComeAtTheStartAndEveryIntervalAFrameReaches(double seconds, int frames, double every, long exports) =>
            Assert.That(SphFluid.Headless.Cli.SimulateOptions.Looks(seconds, frames, every), Is.EqualTo(exports));

        [Test]
        public void ExportNamesBelongToTheRunner()
        {
            Assert.That(OutputFolder.IsRunnerName("particles_0012.vtu"), Is.True);
            Assert.That(OutputFolder.IsRunnerName("particles_0012.ply"), Is.True);
            Assert.That(OutputFolder.IsRunnerName("particles.pvd"), Is.True);
            Assert.That(OutputFolder.IsRunnerName("particles_12.vtu"), Is.False);
            Assert.That(OutputFolder.IsRunnerName("particles.vtu"), Is.False);
            Assert.That(OutputFolder.IsRunnerName("my_particles_0001.ply"), Is.False);
        }

        [Test]
        public void DensitiesOfAnotherLengthAreRefused()
        {
            var (particles, _) = Sample(4, 5);
            string dir = RunnerPaths.ScratchFolder("export-refused");

            Assert.That(() => VtuParticles.Write(Path.Combine(dir, "a.vtu"), 0, particles, new Vector4[3]), Throws.ArgumentException.With.Message.Contains("3 densities for 4 particles"));
            Assert.That(() => PlyParticles.Write(Path.Combine(dir, "a.ply"), 0, particles, new Vector4[3]), Throws.ArgumentException.With.Message.Contains("3 densities for 4 particles"));
            Assert.That(Directory.GetFiles(dir), Is.Empty, "nothing written for refused input");
        }
    }
}
