using System.Collections.Generic;
using System.IO;
using System.Linq;
using NUnit.Framework;
using SphFluid.Headless;
using SphFluid.Headless.Cli;
using SphFluid.Headless.Runs;
using SphFluid.Simulation;

namespace SphFluid.Tests.Runner
{
    /// <summary>--solver, DFSPH's tolerances and WCSPH's density: parsed, refused by name with their range, applied to the
    /// run and printed.</summary>
    public sealed class SolverOptionTests
    {
        static int Run(out string stderr, params string[] args)
        {
            var e = new StringWriter();
            int code = Program.Run(args, new StringWriter(), e);
            stderr = e.ToString();
            return code;
        }

        [TestCase("simulate")]
        [TestCase("bench")]
        public void AnUnknownSolverIsRefusedWithTheChoices(string command)
        {
            Assert.That(Run(out string err, command, RunnerPaths.Scene("PlayModeTest"), "--solver", "pcisph"), Is.EqualTo(ExitCodes.BadArguments));
            Assert.That(err, Does.Contain($"{command}: --solver must be one of wcsph | dfsph (was 'pcisph')"));
        }

        [TestCase("0", "--density-tolerance must be in [0.001, 10] % (was 0)")]
        [TestCase("tight", "--density-tolerance must be a number in [0.001, 10] % (was 'tight')")]
        public void ADensityToleranceOutOfRangeIsRefused(string value, string message)
        {
            Assert.That(Run(out string err, "simulate", RunnerPaths.Scene("PlayModeTest"), "--solver", "dfsph", "--density-tolerance", value), Is.EqualTo(ExitCodes.BadArguments));
            Assert.That(err, Does.Contain(message));
        }

        [TestCase("simulate", "0", "--divergence-tolerance must be in [0.01, 1000] %/s (was 0)")]
        [TestCase("bench", "2000", "--divergence-tolerance must be in [0.01, 1000] %/s (was 2000)")]
        [TestCase("simulate", "loose", "--divergence-tolerance must be a number in [0.01, 1000] %/s (was 'loose')")]
        public void ADivergenceToleranceOutOfTheSettingsRangeIsRefused(string command, string value, string message)
        {
            Assert.That(Run(out string err, command, RunnerPaths.Scene("PlayModeTest"), "--solver", "dfsph", "--divergence-tolerance", value), Is.EqualTo(ExitCodes.BadArguments));
            Assert.That(err, Does.Contain(message));
        }

        [TestCase("--density-tolerance", "0.1")]
        [TestCase("--divergence-tolerance", "30")]
        public void ADfsphToleranceForAWcsphRunIsRefusedInsteadOfIgnored(string option, string value)
        {
            Assert.That(Run(out string err, "simulate", RunnerPaths.Scene("PlayModeTest"), option, value, "--steps", "1"), Is.EqualTo(ExitCodes.BadArguments));
            Assert.That(err, Does.Contain(option + " applies to the DFSPH solver only"));
        }

        [TestCase("simulate")]
        [TestCase("bench")]
        public void AnUnknownWcsphDensityIsRefusedWithTheChoices(string command)
        {
            Assert.That(Run(out string err, command, RunnerPaths.Scene("PlayModeTest"), "--wcsph-density", "riemann"), Is.EqualTo(ExitCodes.BadArguments));
            Assert.That(err, Does.Contain($"{command}: --wcsph-density must be one of summation | delta-sph (was 'riemann')"));
        }

        [Test]
        public void AWcsphDensityForADfsphRunIsRefusedInsteadOfIgnored()
        {
            Assert.That(Run(out string err, "simulate", RunnerPaths.Scene("PlayModeTest"), "--solver", "dfsph", "--wcsph-density", "delta-sph", "--steps", "1"),
                Is.EqualTo(ExitCodes.BadArguments));
            Assert.That(err, Does.Contain("--wcsph-density applies to the WCSPH solver only"));
        }

        [Test]
        public void TheWcsphDensityOverridesTheScenesAndIsPrinted()
        {
            var scene = new FluidSceneDescription { Settings = new FluidSettings() };
            Assert.That(scene.Settings.WcsphDensity, Is.EqualTo(WcsphDensity.Summation));

            SimulateOptions.Parse(new[] { "x.unity", "--wcsph-density", "Delta-SPH" }).Solver.ApplyTo(scene, "simulate");

            Assert.That(scene.Settings.WcsphDensity, Is.EqualTo(WcsphDensity.DeltaSph));
            Assert.That(SolverChoice.Describe(scene.Settings), Does.EndWith("gamma 7, delta-SPH density)"));
            Assert.That(SolverChoice.Describe(new FluidSettings()), Does.EndWith("gamma 7, summation density)"));
            Assert.That(SimulateOptions.Parse(new[] { "x.unity" }).Solver.Density, Is.Null, "without --wcsph-density the scene's density runs");
        }

        [TestCase("simulate")]
        [TestCase("bench")]
        public void AnUnknownViscousStressIsRefusedWithTheChoices(string command)
        {
            Assert.That(Run(out string err, command, RunnerPaths.Scene("PlayModeTest"), "--viscous-stress", "cauchy"), Is.EqualTo(ExitCodes.BadArguments));
            Assert.That(err, Does.Contain($"{command}: --viscous-stress must be one of laplacian | strain-rate (was 'cauchy')"));
        }

        [Test]
        public void TheViscousStressOverridesTheScenesUnderEitherSolver()
        {
            var scene = new FluidSceneDescription { Settings = new FluidSettings() };
            Assert.That(scene.Settings.ViscousStress, Is.EqualTo(ViscousStress.Laplacian));

            SimulateOptions.Parse(new[] { "x.unity", "--viscous-stress", "strain-rate" }).Solver.ApplyTo(scene, "simulate");
            Assert.That(scene.Settings.ViscousStress, Is.EqualTo(ViscousStress.StrainRate));

            SimulateOptions.Parse(new[] { "x.unity", "--solver", "dfsph", "--viscous-stress", "laplacian" }).Solver.ApplyTo(scene, "simulate");
            Assert.That(scene.Settings.ViscousStress, Is.EqualTo(ViscousStress.Laplacian));
            Assert.That(SimulateOptions.Parse(new[] { "x.unity" }).Solver.Stress, Is.Null, "without --viscous-stress the scene's stress runs");
        }

        [Test]
        public void TheChoiceOverridesTheScenesSettings()
        {
            var options = SimulateOptions.Parse(new[] { "x.unity", "--solver", "DFSPH", "--density-tolerance", "0.01", "--divergence-tolerance", "30" });
            var scene = new FluidSceneDescription { Settings = new FluidSettings() };

            options.Solver.ApplyTo(scene, "simulate");

            Assert.That(scene.Settings.PressureSolver, Is.EqualTo(PressureSolver.Dfsph));
            Assert.That(scene.Settings.DensityTolerance, Is.EqualTo(0.01f));
            Assert.That(scene.Settings.DivergenceTolerance, Is.EqualTo(30f));
            Assert.That(SimulateOptions.Parse(new[] { "x.unity" }).Solver.Solver, Is.Null, "without --solver the scene's solver runs");
        }

        [Test]
        public void TheRunHeaderAndSummaryNameTheSolver()
        {
            string outDir = RunnerPaths.ScratchFolder("solver-header");
            var stdout = new StringWriter();
            var run = new SimulateRun(SimulateOptions.Parse(new[] { RunnerPaths.Scene("PlayModeTest"), "--steps", "1", "--solver", "dfsph", "--density-tolerance", "0.05", "--divergence-tolerance", "25", "--out", outDir, "--quiet" }),
                stdout, new StringWriter()) { Device = GpuTestDevice.Shared, InteractiveProgress = false };

            Assert.That(run.Execute(), Is.EqualTo(ExitCodes.Ok), stdout.ToString());
            Assert.That(stdout.ToString(), Does.Contain("solver: DFSPH (density tolerance 0.05 %, divergence tolerance 25 %/s"));
            Assert.That(stdout.ToString(), Does.Contain("done (DFSPH)"));
            Assert.That(File.ReadAllText(Path.Combine(outDir, "summary.txt")), Does.Contain("solver: DFSPH"));
        }

        // A stiffness the speed-of-sound rule refuses (its bound is 1.2e7 Pa in PlayModeTest's tank) binds WCSPH only, so
        // the scene is checked as the run will use it: as written, then as --solver changes it, the refusal naming the line.
        const string SceneStiffness = "    Stiffness: 50000", TooStiff = "    Stiffness: 1000000000";

        [Test]
        public void ADfsphRunIsNotRefusedForAWcsphStiffnessItDoesNotUse()
        {
            string path = RunnerPaths.EditedScene("PlayModeTest", SceneStiffness, TooStiff);
            Assert.That(Run(out string asWritten, "simulate", path, "--steps", "1"), Is.EqualTo(ExitCodes.BadScene));
            Assert.That(asWritten, Does.Contain("Fluid.settings.Stiffness: Stiffness must be in [1, "));

            var stdout = new StringWriter();
            var run = new SimulateRun(SimulateOptions.Parse(new[] { path, "--steps", "1", "--solver", "dfsph", "--out", RunnerPaths.ScratchFolder("stiff-dfsph"), "--quiet" }),
                stdout, new StringWriter()) { Device = GpuTestDevice.Shared, InteractiveProgress = false };
            Assert.That(run.Execute(), Is.EqualTo(ExitCodes.Ok), stdout.ToString());
        }

        [TestCase("simulate", "--solver wcsph")]
        [TestCase("bench", "--solver wcsph")]
        [TestCase("simulate", "--solver wcsph --viscous-stress strain-rate")]
        public void AWcsphRunOfADfsphSceneIsRefusedForItsStiffnessNamingTheLine(string command, string arguments)
        {
            string path = RunnerPaths.EditedScene("PlayModeTest", (SceneStiffness, TooStiff), ("    PressureSolver: 0", "    PressureSolver: 1"));
            int line = File.ReadAllText(path).Split('\n').ToList().IndexOf(TooStiff) + 1;

            var args = new List<string> { command, path };
            args.AddRange(arguments.Split(' '));
            Assert.That(Run(out string err, args.ToArray()), Is.EqualTo(ExitCodes.BadScene));

            Assert.That(err, Does.Contain($"the fluid scene is invalid as {command} {arguments} runs it:"));
            Assert.That(err, Does.Contain($"PlayModeTest.unity:{line}: GameObject 'Fluid', Fluid.settings.Stiffness: Stiffness must be in [1, "));
            Assert.That(err, Does.Contain("(was 1E+09)"));
        }

        [Test]
        public void AStudyConfigurationTheSceneCannotRunIsRefusedByItsLabelAndTheLine()
        {
            string path = RunnerPaths.EditedScene("PlayModeTest", SceneStiffness, "    Stiffness: 10000000");
            int line = File.ReadAllText(path).Split('\n').ToList().IndexOf("    Stiffness: 10000000") + 1;

            Assert.That(Run(out string err, "study", path, "--quick", "--solvers", "wcsph", "--stiffness-factors", "1", "100"), Is.EqualTo(ExitCodes.BadScene));

            Assert.That(err, Does.Contain("the fluid scene is invalid as study configuration WCSPH k x100, CFL "));
            Assert.That(err, Does.Contain($"PlayModeTest.unity:{line}: GameObject 'Fluid', Fluid.settings.Stiffness: Stiffness must be in [1, "));
            Assert.That(err, Does.Contain("(was 1E+09)"));
        }

        [Test]
        public void TheArgumentsAreNamedAsTheyAreWritten()
        {
            Assert.That(SimulateOptions.Parse(new[] { "x.unity" }).Solver.AsChange("simulate", _ => { }), Is.Null, "no change without options");
            var options = SimulateOptions.Parse(new[] { "x.unity", "--solver", "DFSPH", "--density-tolerance", "0.05", "--divergence-tolerance", "30",
                "--solver-iteration", "chebyshev", "--viscous-stress", "strain-rate" });
            Assert.That(options.Solver.AsChange("simulate", _ => { })!.Label,
                Is.EqualTo("simulate --solver dfsph --density-tolerance 0.05 --divergence-tolerance 30 --solver-iteration chebyshev --viscous-stress strain-rate"));
            Assert.That(SimulateOptions.Parse(new[] { "x.unity", "--wcsph-density", "delta-sph" }).Solver.Arguments(), Is.EqualTo("--wcsph-density delta-sph"));
        }
    }
}
