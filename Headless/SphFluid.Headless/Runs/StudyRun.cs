using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Numerics;
using System.Text;
using SphFluid.Compute;
using SphFluid.Headless.Cli;
using SphFluid.Headless.Output;
using SphFluid.Headless.Scenes;
using SphFluid.Simulation;
using SphFluid.Vulkan;

namespace SphFluid.Headless.Runs;

/// <summary>
/// <c>sphfluid study</c>: the accuracy-for-time study. Runs the scene once per configuration (solver and its stiffness or
/// tolerance, resolution, CFL number), measures how far each is from incompressible and from the finest configuration's
/// observables, and what each costs per simulated second; writes study.csv, study.md and the Pareto chart.
/// </summary>
public sealed class StudyRun(StudyOptions options, TextWriter stdout, TextWriter stderr)
{
    static readonly CultureInfo C = CultureInfo.InvariantCulture;
    const double FrameSeconds = 1.0 / 60.0;

    /// <summary>The most configurations one study runs. The matrix is the product of its options' lists, so a list
    /// given one value too many times over (two hundred scales by two hundred stiffnesses) asks for a hundred thousand
    /// runs; the default is 20, a broad study a few hundred.</summary>
    public const int MaxConfigurations = 1000;

    /// <summary>A device to use instead of opening one (tests share theirs); not disposed here. Null: the run opens its own.</summary>
    public IComputeDevice? Device { get; init; }

    /// <summary>One run of the matrix. <paramref name="DivergenceTolerance"/> is the DFSPH row's (%/s, the scene's unless the
    /// study was given its own); <paramref name="NamesDivergence"/>: the study was, so labels and series name it.</summary>
    public sealed record Configuration(PressureSolver Solver, double StiffnessFactor, double DensityTolerance, double ParticleScale, double Cfl,
        SolverIteration Iteration = SolverIteration.Jacobi, double DivergenceTolerance = double.NaN, bool NamesDivergence = false)
    {
        public string Label => Solver == PressureSolver.Dfsph
            ? string.Format(C, "{0} {1:G3} %{2}", SolverName, DensityTolerance, NamesDivergence ? string.Format(C, ", {0:G3} %/s", DivergenceTolerance) : "")
            : string.Format(C, "WCSPH k x{0:G3}", StiffnessFactor);

        /// <summary>The CSV's solver column: WCSPH, DFSPH (the Jacobi solve) or DFSPH Chebyshev.</summary>
        public string SolverName => Solver != PressureSolver.Dfsph ? "WCSPH" : Iteration == SolverIteration.Chebyshev ? "DFSPH Chebyshev" : "DFSPH";

        /// <summary>The chart's series: the solver, and the divergence tolerance where the study was given its own.</summary>
        public string Series => Solver == PressureSolver.Dfsph && NamesDivergence
            ? string.Format(C, "{0} at {1:G3} %/s", SolverName, DivergenceTolerance) : SolverName;
    }

    public sealed class Row(Configuration config, int particles, string[] phaseNames)
    {
        public readonly Configuration Config = config;
        public readonly int Particles = particles;
        public double SimulatedSeconds, WallSeconds, GpuMilliseconds;
        public int Substeps;
        public readonly string[] PhaseNames = phaseNames;
        public readonly double[] DensityErrorAverage = new double[phaseNames.Length], DensityErrorMax = new double[phaseNames.Length];
        public double DivergenceError, EnergyDrift, SolverIterations;

        /// <summary>DFSPH: the share of the simulated time whose constant-density solves were cut off at their rounds
        /// before their tolerance (SolveCutOffs.DensityShare); 0 with WCSPH. Above 0 the row's density error is not
        /// the tolerance's.</summary>
        public double DensitySolvesCutOff;

        /// <summary>The same for the divergence-free solves (SolveCutOffs.DivergenceShare).</summary>
        public double DivergenceSolvesCutOff;
        public double Layering, SurgeFront, Column;
        public double LayeringError, FrontError, ColumnError, ObservableError;

        /// <summary>Why the run became unhealthy; null while it is healthy.</summary>
        public string? Failure;

        public double SubstepsPerSecond => Substeps / SimulatedSeconds;
        public double WallMsPerSecond => WallSeconds * 1000 / SimulatedSeconds;
        public double GpuMsPerSecond => GpuMilliseconds / SimulatedSeconds;
        public double RealTimeFactor => SimulatedSeconds / WallSeconds;
    }

    public List<Row> Rows { get; } = new();

    /// <summary>The scene file, read and checked once; each configuration reads its own description of it.</summary>
    SceneLoader.CheckedScene? _scene;

    /// <summary>What <see cref="SolverChoice.FitSupport"/> changed for the DFSPH rows, printed with the header; null if nothing.</summary>
    string? _supportNote;

    public int Execute()
    {
        // The matrix reads the scene's own CFL number and DFSPH settings; the scene is checked here as the first
        // solver asked runs it, and each configuration again as it runs.
        var first = options.Solvers[0];
        _scene = SceneLoader.Open(options.ScenePath);
        var scene = _scene.Read(new SceneChange("study with " + SolverChoice.ShortName(first),
            d => { d.Settings.PressureSolver = first; SolverChoice.FitSupport(d.Settings, "study"); }));
        var configs = Matrix(scene.Description.Settings);
        // Every configuration is made into a scene before the device opens: an impossible one is refused by name first.
        var descriptions = configs.Select(c => Describe(c)).ToList();
        using var output = OutputFolder.Claim(options.OutputDirectory ?? Path.Combine("Output", scene.Name + "-study"), "--out", "study");
        IComputeDevice device = DeviceFactory.GivenOrOpen(Device, scene.PackageFolder, options.DeviceName, "study", stderr, out IDisposable? owned);
        try
        {
            stdout.WriteLine(string.Format(C, "study: {0} on {1}; {2} configuration(s) of {3:G3} s simulated each{4}", scene.Path, DeviceFactory.Describe(device), configs.Count,
                options.Seconds, options.Quick ? " (--quick)" : ""));
            if (_supportNote != null) stdout.WriteLine(_supportNote + " (the DFSPH rows)");
            var crowded = descriptions.Select(FreeVolume.Warning).Where(w => w != null).ToList();
            if (crowded.Count > 0)
                stderr.WriteLine($"study: warning: {crowded.Count} of the configurations (their cut-off column shows the cost): {crowded[0]}");
            if (_scene.UnreadProblems is string unread) stderr.WriteLine($"study: warning: {unread}");
            for (int i = 0; i < configs.Count; i++)
            {
                double scale = configs[i].ParticleScale;
                SceneFit.RequireDevice(descriptions[i], device, "study", scene.Path, scale == 1.0 ? null : "--particles-scales", scale.ToString("G6", C));
            }
            for (int i = 0; i < configs.Count; i++)
            {
                var row = Run(scene, descriptions[i], configs[i], device);
                Rows.Add(row);
                stderr.WriteLine(string.Format(C, "study: [{0}/{1}] {2}, scale {3:G3}, CFL {4:G3}: {5} particles, {6:F0} wall ms per simulated s{7}",
                    i + 1, configs.Count, configs[i].Label, configs[i].ParticleScale, configs[i].Cfl, row.Particles, row.WallMsPerSecond,
                    row.Failure != null ? " FAILED: " + row.Failure : ""));
            }
            CompareWithFinest(scene.Description.Container);
            output.WriteText("study.csv", Csv());
            string table = Markdown(scene.Name, DeviceFactory.Describe(device));
            output.WriteText("study.md", table);
            stdout.Write(table);
            StudyParetoChart.Build(scene.Name, device.DeviceName, Rows).Save(output, StudyParetoChart.Stem);
            stdout.WriteLine();
            stdout.WriteLine($"files: {Path.GetFullPath(output.Path)}: study.csv, study.md, {StudyParetoChart.Stem}.png, {StudyParetoChart.Stem}.svg");
            return Rows.All(r => r.Failure == null) ? ExitCodes.Ok : ExitCodes.SimulationFailed;
        }
        finally
        {
            owned?.Dispose();
        }
    }

    List<Configuration> Matrix(FluidSettings scene)
    {
        var cfls = options.CflNumbers.Count > 0 ? options.CflNumbers
            : options.Quick ? new List<double> { scene.CflNumber } : new List<double> { scene.CflNumber, scene.CflNumber / 2 };
        bool namesDivergence = options.DivergenceTolerances.Count > 0;
        var divergences = namesDivergence ? options.DivergenceTolerances : new List<double> { scene.DivergenceTolerance };
        var iterations = options.SolverIterations.Count > 0 ? options.SolverIterations : new List<SolverIteration> { scene.SolverIteration };
        bool wcsph = options.Solvers.Contains(PressureSolver.Wcsph), dfsph = options.Solvers.Contains(PressureSolver.Dfsph);
        long rows = (wcsph ? options.StiffnessFactors.Count : 0) + (dfsph ? (long)options.DensityTolerances.Count * divergences.Count * iterations.Count : 0);
        long count = (long)options.ParticleScales.Count * cfls.Count * rows;
        if (count > MaxConfigurations)
        {
            var solvers = new List<string>();
            if (wcsph) solvers.Add($"{options.StiffnessFactors.Count} --stiffness-factors");
            if (dfsph) solvers.Add($"{options.DensityTolerances.Count} --density-tolerances x {divergences.Count} --divergence-tolerances x {iterations.Count} --solver-iterations");
            throw new UsageException($"study: the matrix has {count} configurations, more than the {MaxConfigurations} one study runs: " +
                $"{options.ParticleScales.Count} --particles-scales x {cfls.Count} --cfl x ({string.Join(" + ", solvers)}); give those options fewer values");
        }
        var configs = new List<Configuration>();
        foreach (double scale in options.ParticleScales)
            foreach (double cfl in cfls)
            {
                if (wcsph)
                    foreach (double k in options.StiffnessFactors) configs.Add(new Configuration(PressureSolver.Wcsph, k, 0, scale, cfl));
                if (dfsph)
                    foreach (double tolerance in options.DensityTolerances)
                        foreach (double divergence in divergences)
                            foreach (var iteration in iterations)
                                configs.Add(new Configuration(PressureSolver.Dfsph, 1, tolerance, scale, cfl, iteration, divergence, namesDivergence));
            }
        return configs;
    }

    /// <summary>The scene as one configuration runs it, validated so (a fresh read: each row owns its copy).</summary>
    FluidSceneDescription Describe(Configuration config)
    {
        string label = string.Format(C, "study configuration {0}, CFL {1:G3}", config.Label, config.Cfl);
        var description = _scene!.Read(new SceneChange(label, d => Configure(d.Settings, config))).Description;
        ParticleScaling.ScaleBy(description, config.ParticleScale);
        SceneFit.RequireScaled(description, "study", "--particles-scales", config.ParticleScale.ToString("G6", C));
        return description;
    }

    void Configure(FluidSettings settings, Configuration config)
    {
        settings.PressureSolver = config.Solver;
        if (config.Solver == PressureSolver.Dfsph)
        {
            settings.DensityTolerance = (float)config.DensityTolerance;
            settings.DivergenceTolerance = (float)config.DivergenceTolerance;
            settings.SolverIteration = config.Iteration;
        }
        string? note = SolverChoice.FitSupport(settings, "study");
        _supportNote ??= note;
        settings.Stiffness = (float)(settings.Stiffness * config.StiffnessFactor);
        settings.CflNumber = (float)config.Cfl;
    }

    Row Run(LoadedScene scene, FluidSceneDescription description, Configuration config, IComputeDevice device)
    {
        using var sim = new FluidSimulation(device, description);
        var settings = description.Settings;
        var restContainer = description.Container.Clone();
        var restObstacles = description.Obstacles.Select(o => o.Clone()).ToList();
        var container = restContainer;
        var particles = new Particle[sim.ParticleCount];
        var densities = new Vector4[sim.ParticleCount];
        var health = new HealthCheck(description, sim.ParticleCount);
        int phases = sim.Phases.Count;
        var row = new Row(config, sim.ParticleCount, sim.Phases.Select(p => p.Name).ToArray());
        // State figures (density error, divergence, energy) are averaged over every sample, the spawn's included. The
        // solver's figures describe the sub-steps since the sample before, so only samples that follow sub-steps count
        // for them. The spawn's sample follows none, and a last sample repeated after the loop none either: averaged in,
        // the two read a 1 s run's iterations and cut-off shares low by 2 parts in 22. The cut-off shares are weighted by
        // the simulated time each sample covers, as simulate's summary and Unity's warning weigh them: the last interval
        // of a run is shorter than the others.
        int samples = 0, intervals = 0, substepsSampled = 0;
        double energy0 = double.NaN, energy = double.NaN, divergence = 0, iterations = 0;
        var cutOffs = new SolveCutOffs();
        FluidMeasures Sample()
        {
            var report = sim.ReadDiagnostics();
            sim.Particles.GetData(particles);
            sim.Densities.GetData(densities);
            var measures = FluidMeasures.Measure(sim.SimulatedTime, particles, densities, sim.PhaseRows, container, settings.Gravity, settings.ParticleSpacing, settings.SmoothingRadius);
            for (int k = 0; k < phases; k++)
            {
                row.DensityErrorAverage[k] += report.Phases[k].AverageDensityError;
                row.DensityErrorMax[k] = Math.Max(row.DensityErrorMax[k], report.Phases[k].MaxDensityError);
            }
            divergence += report.DivergenceError;
            cutOffs.Observe(report);
            if (row.Substeps > substepsSampled)
            {
                iterations += report.DensitySolveIterations + report.DivergenceSolveIterations;
                intervals++;
                substepsSampled = row.Substeps;
            }
            energy = report.KineticEnergy + measures.PotentialEnergy;
            if (double.IsNaN(energy0)) energy0 = energy;
            samples++;
            row.Failure ??= health.Check(report, particles)?.Message;
            return measures;
        }

        var last = Sample();
        var clock = Stopwatch.StartNew();
        int frame = 0;
        while (row.Failure == null && sim.SimulatedTime < options.Seconds - 1e-6)
        {
            float frameSeconds = (float)Math.Min(FrameSeconds, options.Seconds - sim.SimulatedTime + 1e-7);
            double start = sim.SimulatedTime, end = start + frameSeconds;
            if (scene.Motion.MovesContainer)
            {
                container = scene.Motion.ContainerOver(restContainer, start, end);
                sim.UpdateContainer(container);
            }
            if (scene.Motion.MovesObstacles) sim.UpdateObstacles(scene.Motion.ObstaclesOver(restObstacles, start, end));
            var step = sim.Step(frameSeconds);
            row.Substeps += step.Substeps;
            if (device is VulkanComputeDevice vulkan)
            {
                vulkan.WaitIdle();
                row.GpuMilliseconds += vulkan.LastDispatchTimings.Sum(t => t.Milliseconds);
            }
            frame++;
            if (frame % 3 == 0)
            {
                clock.Stop();
                last = Sample();
                clock.Start();
            }
        }
        row.WallSeconds = clock.Elapsed.TotalSeconds;
        row.SimulatedSeconds = sim.SimulatedTime;
        if (row.Substeps > substepsSampled) last = Sample(); // the sub-steps since the last sample, if any
        for (int k = 0; k < phases; k++) row.DensityErrorAverage[k] /= samples;
        row.DivergenceError = divergence / samples;
        int measured = Math.Max(intervals, 1);
        row.SolverIterations = iterations / measured;
        row.DensitySolvesCutOff = cutOffs.DensityShare;
        row.DivergenceSolvesCutOff = cutOffs.DivergenceShare;
        row.EnergyDrift = Math.Abs(energy0) > 0 ? (energy - energy0) / Math.Abs(energy0) : 0;
        row.Layering = last.LayeringIndex;
        row.SurgeFront = last.SurgeFront;
        row.Column = last.BackWallColumn;
        if (device is not VulkanComputeDevice) row.GpuMilliseconds = double.NaN;
        return row;
    }

    /// <summary>Observable errors against the finest configuration run: the largest particle scale, then the smallest CFL,
    /// then the tightest DFSPH density tolerance and divergence tolerance (or the stiffest WCSPH when no DFSPH ran). Lengths are relative to the
    /// container's length (front) and height (column); the layering index to its range of 2.</summary>
    void CompareWithFinest(ContainerDescription container)
    {
        var finest = Rows.Where(r => r.Failure == null)
            .OrderByDescending(r => r.Config.ParticleScale).ThenBy(r => r.Config.Cfl)
            .ThenByDescending(r => r.Config.Solver == PressureSolver.Dfsph ? 1 : 0)
            .ThenBy(r => r.Config.Solver == PressureSolver.Dfsph ? r.Config.DensityTolerance : -r.Config.StiffnessFactor)
            .ThenBy(r => r.Config.Solver == PressureSolver.Dfsph ? r.Config.DivergenceTolerance : 0)
            .FirstOrDefault();
        foreach (var r in Rows)
        {
            if (finest == null) { r.ObservableError = double.NaN; continue; }
            r.LayeringError = double.IsFinite(r.Layering) && double.IsFinite(finest.Layering) ? Math.Abs(r.Layering - finest.Layering) / 2 : 0;
            r.FrontError = Math.Abs(r.SurgeFront - finest.SurgeFront) / container.Size.X;
            r.ColumnError = Math.Abs(r.Column - finest.Column) / container.Size.Y;
            r.ObservableError = Math.Max(r.LayeringError, Math.Max(r.FrontError, r.ColumnError));
        }
        Finest = finest;
    }

    /// <summary>The configuration the others are compared with; null when every configuration failed.</summary>
    public Row? Finest { get; private set; }

    string Csv()
    {
        var b = new StringBuilder();
        int phases = Rows[0].PhaseNames.Length;
        b.Append("solver,stiffness_factor,density_tolerance_pct,divergence_tolerance_pct_per_s,particles_scale,cfl,particles");
        // A phase name as it is ("Oil, light") would add a column to the header alone: the prefixes simulate's log uses.
        foreach (string p in DiagnosticsCsv.ColumnPrefixes(Rows[0].PhaseNames)) b.Append(C, $",{p}_density_error_avg,{p}_density_error_max");
        b.AppendLine(",divergence_error,energy_drift,layering_index,surge_front_m,column_m,layering_error,front_error,column_error,observable_error,"
            + "solver_iterations_per_step,density_solves_cut_off,divergence_solves_cut_off,substeps_per_s,gpu_ms_per_s,wall_ms_per_s,real_time_factor,finest,status");
        foreach (var r in Rows)
        {
            bool dfsph = r.Config.Solver == PressureSolver.Dfsph;
            b.Append(string.Format(C, "{0},{1:G6},{2:G6},{3:G6},{4:G6},{5:G6},{6}", r.Config.SolverName, r.Config.StiffnessFactor,
                dfsph ? r.Config.DensityTolerance : double.NaN, dfsph ? r.Config.DivergenceTolerance : double.NaN, r.Config.ParticleScale, r.Config.Cfl, r.Particles));
            for (int k = 0; k < phases; k++) b.Append(string.Format(C, ",{0:G6},{1:G6}", r.DensityErrorAverage[k], r.DensityErrorMax[k]));
            b.AppendLine(string.Format(C, ",{0:G6},{1:G6},{2:G6},{3:G6},{4:G6},{5:G6},{6:G6},{7:G6},{8:G6},{9:G6},{10:G6},{11:G6},{12:G6},{13:G6},{14:G6},{15:G6},{16},{17}",
                r.DivergenceError, r.EnergyDrift, r.Layering, r.SurgeFront, r.Column, r.LayeringError, r.FrontError, r.ColumnError, r.ObservableError,
                r.SolverIterations, r.DensitySolvesCutOff, r.DivergenceSolvesCutOff, r.SubstepsPerSecond, r.GpuMsPerSecond, r.WallMsPerSecond, r.RealTimeFactor, r == Finest ? "yes" : "no",
                r.Failure == null ? "ok" : "failed: " + r.Failure.Replace(',', ';')));
        }
        return b.ToString();
    }

    string Markdown(string sceneName, string deviceName)
    {
        var b = new StringBuilder();
        b.AppendLine();
        b.AppendLine(string.Format(C, "Study of {0} on {1}: {2:G3} s simulated per configuration; density error |rho/rho0 - 1| avg / max per phase; "
            + "observable error = largest of |layering - ref| / 2, |front - ref| / length, |column - ref| / height against the finest run (ref); "
            + "energy drift = kinetic + potential energy at the end against the spawn's (a DFSPH spawn at rest density gives up about its "
            + "density tolerance's share of it settling into that compression in its first frames; a WCSPH spawn starts compressed)",
            sceneName, deviceName, options.Seconds));
        b.AppendLine();
        b.AppendLine("| configuration | scale | CFL | particles | density error avg / max | div. error | energy drift | layering | front m | column m | obs. error | iter/step | cut off (density / div.) | sub-steps/s | GPU ms/s | wall ms/s | real time |");
        b.AppendLine("|---|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
        foreach (var r in Rows)
        {
            // A '|' in a phase name would end the cell in Markdown.
            string density = string.Join("; ", r.PhaseNames.Select((p, k) => string.Format(C, "{0} {1:P2} / {2:P2}", MarkdownCell.Escape(p), r.DensityErrorAverage[k], r.DensityErrorMax[k])));
            string cutOff = r.Config.Solver == PressureSolver.Dfsph
                ? r.DensitySolvesCutOff.ToString("P1", C) + " / " + r.DivergenceSolvesCutOff.ToString("P1", C) : "-";
            // A scene of one liquid has no layering to measure (NaN in the CSV); the table says so with a dash, as for
            // a WCSPH row's cut-offs, rather than print NaN beside the figures it does have.
            string layering = double.IsFinite(r.Layering) ? r.Layering.ToString("F2", C) : "-";
            b.AppendLine(string.Format(C, "| {0}{1} | {2:G3} | {3:G3} | {4} | {5} | {6:G3} | {7:P2} | {8} | {9:F3} | {10:F3} | {11:G3} | {12:F1} | {13} | {14:F0} | {15:F0} | {16:F0} | {17:G3}x |",
                r.Config.Label, r == Finest ? " (ref)" : r.Failure != null ? " (FAILED)" : "", r.Config.ParticleScale, r.Config.Cfl, r.Particles, density,
                r.DivergenceError, r.EnergyDrift, layering, r.SurgeFront, r.Column, r.ObservableError, r.SolverIterations, cutOff, r.SubstepsPerSecond,
                r.GpuMsPerSecond, r.WallMsPerSecond, r.RealTimeFactor));
        }
        string? note = CutOffNote(Rows);
        if (note != null)
        {
            b.AppendLine();
            b.AppendLine(note);
        }
        return b.ToString();
    }

    /// <summary>The line under the table naming the DFSPH rows whose solves ran out of rounds; null when none did. Without
    /// it a tight tolerance's row reads as if it met its tolerance, at the same cost as a looser one that did.</summary>
    public static string? CutOffNote(IEnumerable<Row> rows)
    {
        var cut = rows.Where(r => r.Config.Solver == PressureSolver.Dfsph && (r.DensitySolvesCutOff > 0 || r.DivergenceSolvesCutOff > 0)).ToList();
        if (cut.Count == 0) return null;
        string names = string.Join(", ", cut.Select(r => string.Format(C, "{0} (scale {1:G3}, CFL {2:G3})", r.Config.Label, r.Config.ParticleScale, r.Config.Cfl)));
        return "Cut off: these DFSPH rows stopped solves at the iteration limit (MaxSolverIterations or the frame's budget of rounds) "
            + "before their tolerance, so their density error (density solves) or divergence error (divergence solves) can be above the "
            + "tolerance asked for: " + names + ".";
    }
}
