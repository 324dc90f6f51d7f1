using System;
using System.IO;
using System.Linq;
using NUnit.Framework;
using SphFluid.Simulation;
using SphFluid.Headless.Cli;
using SphFluid.Headless.Runs;

namespace SphFluid.Tests.Runner
{
    /// <summary>sphfluid study --quick on the small shipped tank: every configuration runs, has a finite error and cost,
    /// and the CSV, Markdown table and Pareto chart are written.</summary>
    public sealed class StudyRunTests
    {
        [Test]
        public void AQuickStudyWritesTheTableAndChartWithAFiniteErrorAndCostInEveryRow()
        {
            string outDir = RunnerPaths.ScratchFolder("study");
            var stdout = new StringWriter();
            var run = new StudyRun(StudyOptions.Parse(new[] { RunnerPaths.Scene("PlayModeTest"), "--quick", "--out", outDir }), stdout, new StringWriter())
            {
                Device = GpuTestDevice.Shared,
            };

            int code = run.Execute();

            Assert.That(code, Is.EqualTo(ExitCodes.Ok), stdout.ToString());
            Assert.That(run.Rows.Count, Is.EqualTo(8), "WCSPH x1 and DFSPH 1, 0.1, 0.01 % at scales 0.25 and 0.5");
            foreach (var row in run.Rows)
            {
                Assert.That(double.IsFinite(row.ObservableError), Is.True, row.Config.Label + " error");
                Assert.That(row.DensityErrorAverage.All(double.IsFinite), Is.True, row.Config.Label + " density error");
                Assert.That(row.WallMsPerSecond, Is.GreaterThan(0).And.LessThan(double.PositiveInfinity), row.Config.Label + " wall cost");
                Assert.That(double.IsFinite(row.GpuMsPerSecond), Is.True, row.Config.Label + " GPU cost");
                Assert.That(row.SubstepsPerSecond, Is.GreaterThan(0), row.Config.Label + " sub-steps");
            }
            string[] csv = File.ReadAllLines(Path.Combine(outDir, "study.csv"));
            Assert.That(csv.Length, Is.EqualTo(9));
            Assert.That(csv[0], Does.StartWith("solver,stiffness_factor,density_tolerance_pct,divergence_tolerance_pct_per_s,particles_scale,cfl,particles,water_density_error_avg"));
            Assert.That(csv.Count(l => l.EndsWith(",yes,ok", StringComparison.Ordinal)), Is.EqualTo(1), "one finest run");
            Assert.That(csv[0], Does.Contain(",solver_iterations_per_step,density_solves_cut_off,divergence_solves_cut_off,substeps_per_s,"));
            string markdown = File.ReadAllText(Path.Combine(outDir, "study.md"));
            Assert.That(markdown, Does.Contain("| DFSPH 0.01 % (ref) | 0.5 |"));
            Assert.That(markdown, Does.Contain("| iter/step | cut off (density / div.) | sub-steps/s |"));
            Assert.That(markdown, Does.Contain("energy drift = kinetic + potential energy at the end against the spawn's"), "the header says what the drift counts");
            Assert.That(markdown, Does.Not.Contain("NaN"), "a figure the scene lacks (one liquid: no layering) is a dash");
            foreach (var row in run.Rows)
                TestContext.Progress.WriteLine($"{row.Config.Label}, scale {row.Config.ParticleScale}: {row.SolverIterations:F1} iterations per sub-step, {row.DensitySolvesCutOff:P1} / {row.DivergenceSolvesCutOff:P1} of density / divergence solves cut off");
            Assert.That(run.Rows.Where(r => r.Config.Solver == PressureSolver.Wcsph).Select(r => r.DensitySolvesCutOff + r.DivergenceSolvesCutOff), Is.All.EqualTo(0.0));
            Assert.That(markdown.Contains("Cut off: these DFSPH rows"), Is.EqualTo(run.Rows.Any(r => r.DensitySolvesCutOff + r.DivergenceSolvesCutOff > 0)), "the note under the table");
            WrittenChart.Check(outDir, "study-pareto", "Accuracy for time: PlayModeTest", "wall time per simulated second (ms, log)",
                "observable error vs finest run (relative, log)", "WCSPH", "DFSPH");
        }

        /// <summary>A phase named "Oil, light | 2" (printable, so allowed) added a column to study.csv's header alone, its
        /// comma unquoted, and one to its study.md row, its '|' unescaped. The CSV takes the prefixes simulate's log uses,
        /// and the Markdown escapes the bar.</summary>
        [Test]
        public void APhaseNameWithACommaAndABarKeepsTheStudysColumns()
        {
            string scene = RunnerPaths.EditedScene("OilAndWater", ("      Name: Oil\n", "      Name: 'Oil, light | 2'\n"));
            string outDir = RunnerPaths.ScratchFolder("study-names");
            var run = new StudyRun(StudyOptions.Parse(new[] { scene, "--solvers", "wcsph", "--particles-scales", "0.1", "--seconds", "0.02", "--out", outDir }),
                new StringWriter(), new StringWriter()) { Device = GpuTestDevice.Shared };

            Assert.That(run.Execute(), Is.EqualTo(ExitCodes.Ok));
            string[] csv = File.ReadAllLines(Path.Combine(outDir, "study.csv"));
            Assert.That(csv[0], Does.Contain(",water_density_error_max,oil__light___2_density_error_avg,oil__light___2_density_error_max,"));
            Assert.That(csv.Select(line => line.Split(',').Length).Distinct(), Is.EqualTo(new[] { csv[0].Split(',').Length }), "as many fields in every row as in the header");
            string[] table = File.ReadAllLines(Path.Combine(outDir, "study.md")).Where(line => line.StartsWith("|", StringComparison.Ordinal)).ToArray();
            Assert.That(table, Has.Length.GreaterThanOrEqualTo(3));
            Assert.That(table.Select(Cells).Distinct(), Is.EqualTo(new[] { Cells(table[0]) }), "as many cells in every row as in the header");
            Assert.That(table[2], Does.Contain("Oil, light \\| 2 "));
        }

        /// <summary>Markdown's cells in a table row: its bars less those escaped.</summary>
        static int Cells(string row) => System.Text.RegularExpressions.Regex.Matches(row, @"(?<!\\)\|").Count - 1;

        /// <summary>RestingTank's DFSPH settings (Wendland C2 at 2.85 spacings with the papers' full step) are refused: its
        /// DFSPH rows run at 2 spacings with the cubic spline, and the header says why. OilAndWater's (relaxed to 0.3) fit, so
        /// its rows keep the scene's kernel and the header says nothing.</summary>
        [TestCase("RestingTank", "study: DFSPH refuses the scene's WendlandC2 at 0.07125 m (FluidSettings: SolverRelaxation must be in [0.05, 0.372046]")]
        [TestCase("OilAndWater", null)]
        public void DfsphRowsOfASceneWhoseDfsphSettingsDoNotFitRunAtTwoSpacingsAndSaySo(string scene, string? note)
        {
            string outDir = RunnerPaths.ScratchFolder("study-support");
            var stdout = new StringWriter();
            var run = new StudyRun(StudyOptions.Parse(new[] { RunnerPaths.Scene(scene), "--solvers", "dfsph", "--density-tolerances", "1",
                "--particles-scales", "0.1", "--seconds", "0.02", "--out", outDir }), stdout, new StringWriter())
            {
                Device = GpuTestDevice.Shared,
            };

            int code = run.Execute();

            Assert.That(code, Is.EqualTo(ExitCodes.Ok), stdout.ToString());
            Assert.That(run.Rows, Is.Not.Empty);
            foreach (var row in run.Rows)
            {
                Assert.That(row.Config.Solver, Is.EqualTo(PressureSolver.Dfsph), row.Config.Label);
                Assert.That(row.Failure, Is.Null, row.Config.Label);
            }
            if (note != null)
                Assert.That(stdout.ToString(), Does.Contain(note).And.Contain("): 0.05 m with the cubic spline instead (the DFSPH rows)"));
            else
                Assert.That(stdout.ToString(), Does.Not.Contain("DFSPH refuses"));
        }

        /// <summary>With at most two iterations every DFSPH solve makes exactly two corrections and is cut off (the fold
        /// declares convergence only after two), so the row must read 4 iterations per sub-step (2 of each solve) and every
        /// solve cut off: the solver's figures average the samples that follow sub-steps, not the spawn's.</summary>
        [Test]
        public void SolverFiguresAverageOnlyTheSamplesThatFollowSubsteps()
        {
            string scene = RunnerPaths.EditedScene("PlayModeTest", "    MaxSolverIterations: 100", "    MaxSolverIterations: 2");
            var run = new StudyRun(StudyOptions.Parse(new[] { scene, "--quick", "--solvers", "dfsph", "--density-tolerances", "1",
                "--particles-scales", "0.25", "--out", RunnerPaths.ScratchFolder("study-two-iterations") }), new StringWriter(), new StringWriter())
            {
                Device = GpuTestDevice.Shared,
            };

            Assert.That(run.Execute(), Is.EqualTo(ExitCodes.Ok));
            var row = run.Rows.Single();
            Assert.That(row.SolverIterations, Is.EqualTo(4.0).Within(1e-6));
            Assert.That(row.DensitySolvesCutOff, Is.EqualTo(1.0).Within(1e-6));
            Assert.That(row.DivergenceSolvesCutOff, Is.EqualTo(1.0).Within(1e-6));
        }

        /// <summary>Each --solver-iterations scheme gets DFSPH rows of its own, labelled and written to the CSV's solver column as
        /// the chart's series name them; WCSPH rows are not repeated. OilAndWater's 0.1 % rows at a quarter of its particles
        /// (1 040, 0.1 s): the Chebyshev solve takes fewer iterations per sub-step than the Jacobi solve.</summary>
        [Test]
        public void EachSolverIterationSchemeGetsDfsphRowsOfItsOwn()
        {
            string outDir = RunnerPaths.ScratchFolder("study-iterations");
            var run = new StudyRun(StudyOptions.Parse(new[] { RunnerPaths.Scene("OilAndWater"), "--quick", "--density-tolerances", "0.1",
                "--particles-scales", "0.25", "--solver-iterations", "jacobi,chebyshev", "--out", outDir }), new StringWriter(), new StringWriter())
            {
                Device = GpuTestDevice.Shared,
            };

            Assert.That(run.Execute(), Is.EqualTo(ExitCodes.Ok));
            Assert.That(run.Rows.Select(r => r.Config.Label), Is.EqualTo(new[] { "WCSPH k x1", "DFSPH 0.1 %", "DFSPH Chebyshev 0.1 %" }));
            var csv = File.ReadAllLines(Path.Combine(outDir, "study.csv")).Skip(1).Select(line => line.Split(',')[0]);
            Assert.That(csv, Is.EqualTo(new[] { "WCSPH", "DFSPH", "DFSPH Chebyshev" }));
            TestContext.Progress.WriteLine($"OilAndWater x0.25, 0.1 %: iterations per sub-step Jacobi {run.Rows[1].SolverIterations:F2}, Chebyshev {run.Rows[2].SolverIterations:F2}");
            Assert.That(run.Rows[2].SolverIterations, Is.LessThan(run.Rows[1].SolverIterations));
        }

        /// <summary>Each --divergence-tolerances value gets DFSPH rows of its own, for every density tolerance, labelled and
        /// charted as a series of its own, its value in the CSV; without the option the rows run the scene's and say nothing of it.
        /// Checked on the scene itself: OilAndWater at a tenth of its particles (416), two frames.</summary>
        [Test]
        public void EachDivergenceToleranceGetsDfsphRowsOfItsOwn()
        {
            string outDir = RunnerPaths.ScratchFolder("study-divergence");
            var run = new StudyRun(StudyOptions.Parse(new[] { RunnerPaths.Scene("OilAndWater"), "--solvers", "dfsph", "--density-tolerances", "1", "0.1",
                "--divergence-tolerances", "10", "30", "--particles-scales", "0.1", "--cfl", "0.3", "--seconds", "0.02", "--out", outDir }),
                new StringWriter(), new StringWriter())
            {
                Device = GpuTestDevice.Shared,
            };

            Assert.That(run.Execute(), Is.EqualTo(ExitCodes.Ok));
            Assert.That(run.Rows.Select(r => r.Config.Label),
                Is.EqualTo(new[] { "DFSPH 1 %, 10 %/s", "DFSPH 1 %, 30 %/s", "DFSPH 0.1 %, 10 %/s", "DFSPH 0.1 %, 30 %/s" }));
            var tolerances = File.ReadAllLines(Path.Combine(outDir, "study.csv")).Skip(1).Select(line => line.Split(',')).Select(f => f[0] + " " + f[2] + " " + f[3]);
            Assert.That(tolerances, Is.EqualTo(new[] { "DFSPH 1 10", "DFSPH 1 30", "DFSPH 0.1 10", "DFSPH 0.1 30" }));
            Assert.That(run.Finest!.Config.Label, Is.EqualTo("DFSPH 0.1 %, 10 %/s"), "the tightest of both tolerances is the reference");
            WrittenChart.Check(outDir, "study-pareto", "Accuracy for time: OilAndWater", "wall time per simulated second (ms, log)",
                "observable error vs finest run (relative, log)", "DFSPH (density tolerance 1, 0.1 %; divergence 10 %/s)",
                "DFSPH (density tolerance 1, 0.1 %; divergence 30 %/s)");

            var plain = StudyOptions.Parse(new[] { "x.unity", "--density-tolerances", "0.1" });
            Assert.That(plain.DivergenceTolerances, Is.Empty, "the scene's");
            Assert.That(new StudyRun.Configuration(PressureSolver.Dfsph, 1, 0.1, 1, 0.3, SolverIteration.Chebyshev, 10).Label, Is.EqualTo("DFSPH Chebyshev 0.1 %"));
        }

        /// <summary>An option for one solver's rows, given while --solvers runs none of them, is refused before anything
        /// runs; --density-tolerances, --solver-iterations and --stiffness-factors used to be ignored.</summary>
        [TestCase("wcsph", "--divergence-tolerances", "30", "DFSPH", "dfsph")]
        [TestCase("wcsph", "--density-tolerances", "1", "DFSPH", "dfsph")]
        [TestCase("wcsph", "--solver-iterations", "chebyshev", "DFSPH", "dfsph")]
        [TestCase("dfsph", "--stiffness-factors", "2", "WCSPH", "wcsph")]
        public void AnOptionForRowsTheStudyDoesNotRunIsRefusedInsteadOfIgnored(string solvers, string option, string value, string rows, string add)
        {
            var error = Assert.Throws<UsageException>(() => StudyOptions.Parse(new[] { RunnerPaths.Scene("PlayModeTest"), "--solvers", solvers, option, value }));
            Assert.That(error!.Message, Is.EqualTo($"study: {option} applies to the {rows} rows, and --solvers runs none (add {add})"));
        }

        /// <summary>Only DFSPH rows that cut solves off are named under the table, each with its scale and CFL.</summary>
        [Test]
        public void TheCutOffNoteNamesOnlyTheDfsphRowsThatCutSolvesOff()
        {
            StudyRun.Row Row(PressureSolver solver, double tolerance, double share) =>
                new StudyRun.Row(new StudyRun.Configuration(solver, 1, tolerance, 0.5, 0.4), 100, new[] { "Water" }) { DensitySolvesCutOff = share };

            Assert.That(StudyRun.CutOffNote(new[] { Row(PressureSolver.Wcsph, 0, 0), Row(PressureSolver.Dfsph, 1, 0) }), Is.Null);
            string? note = StudyRun.CutOffNote(new[] { Row(PressureSolver.Dfsph, 1, 0), Row(PressureSolver.Dfsph, 0.01, 0.25), Row(PressureSolver.Dfsph, 0.001, 1) });
            Assert.That(note, Does.StartWith("Cut off: these DFSPH rows stopped solves at the iteration limit")
                .And.Contain("density error (density solves) or divergence error (divergence solves) can be above the tolerance asked for")
                .And.EndWith(": DFSPH 0.01 % (scale 0.5, CFL 0.4), DFSPH 0.001 % (scale 0.5, CFL 0.4)."));
        }

        /// <summary>The matrix is the product of the options' lists: 200 scales by 200 stiffnesses by 3 CFL numbers asked
        /// for 121 800 runs, and the study read the scene for each (100 s without a line before it was killed). A
        /// matrix past the limit is refused at once with its shape, before the scene's configurations are read.</summary>
        [Test]
        public void AMatrixPastTheLimitIsRefusedWithItsShape()
        {
            string[] Values(int n) => Enumerable.Range(0, n).Select(i => (1 + i * 0.01).ToString(System.Globalization.CultureInfo.InvariantCulture)).ToArray();
            var args = new[] { RunnerPaths.Scene("PlayModeTest"), "--out", RunnerPaths.ScratchFolder("study"), "--cfl", "0.1", "0.2", "0.3" }
                .Append("--stiffness-factors").Concat(Values(200)).Append("--particles-scales").Concat(Values(200)).ToArray();
            var run = new StudyRun(StudyOptions.Parse(args), new StringWriter(), new StringWriter()) { Device = GpuTestDevice.Shared };

            var thrown = Deadline.Within(10, () => Deadline.Thrown(() => run.Execute()), "refusing the matrix");

            Assert.That(thrown, Is.InstanceOf<UsageException>());
            Assert.That(thrown!.Message, Is.EqualTo($"study: the matrix has 121800 configurations, more than the {StudyRun.MaxConfigurations} one study runs: " +
                "200 --particles-scales x 3 --cfl x (200 --stiffness-factors + 3 --density-tolerances x 1 --divergence-tolerances x 1 --solver-iterations); " +
                "give those options fewer values"));
        }

        [Test]
        public void StudyOptionsAreRefusedByName()
        {
            var error = Assert.Throws<UsageException>(() => StudyOptions.Parse(new[] { "x.unity", "--density-tolerances", "1", "50" }));
            Assert.That(error.Message, Does.Contain("study: --density-tolerances must be in [0.001, 10] % (was 50)"));
            error = Assert.Throws<UsageException>(() => StudyOptions.Parse(new[] { "x.unity", "--divergence-tolerances", "10", "0" }));
            Assert.That(error.Message, Does.Contain("study: --divergence-tolerances must be in [0.01, 1000] %/s (was 0)"));
            error = Assert.Throws<UsageException>(() => StudyOptions.Parse(new[] { "x.unity", "--solvers", "sph" }));
            Assert.That(error.Message, Does.Contain("--solvers must be wcsph and/or dfsph (was 'sph')"));
            error = Assert.Throws<UsageException>(() => StudyOptions.Parse(new[] { "x.unity", "--solver-iterations", "gauss" }));
            Assert.That(error.Message, Does.Contain("--solver-iterations must be jacobi and/or chebyshev (was 'gauss')"));
            // A configuration of a microsecond or less once ran no frame and still made a row.
            error = Assert.Throws<UsageException>(() => StudyOptions.Parse(new[] { "x.unity", "--seconds", "1e-6" }));
            Assert.That(error.Message, Does.Contain("study: --seconds must be in [0.0001, 60] s (was 1E-06)"));
            Assert.That(StudyOptions.Parse(new[] { "x.unity", "--quick" }).ParticleScales, Is.EqualTo(new[] { 0.25, 0.5 }));
        }
    }
}
