using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Numerics;
using SphFluid.Compute;
using SphFluid.Headless.Cli;
using SphFluid.Headless.Output;
using SphFluid.Headless.Scenes;
using SphFluid.Simulation;
using SphFluid.Sorting;
using SphFluid.Vulkan;

namespace SphFluid.Headless.Runs;

/// <summary>
/// <c>sphfluid simulate</c>: steps the scene in 60 Hz frames as the Fluid component would (the
/// container and spheres moved by their scripts before each frame, on simulated time), and writes what a
/// reader needs to judge the run: diagnostics lines and CSV, snapshots, the layering figure, a summary.
/// </summary>
public sealed class SimulateRun(SimulateOptions options, TextWriter stdout, TextWriter stderr)
{
    static readonly CultureInfo C = CultureInfo.InvariantCulture;

    /// <summary>A device to use instead of opening one (tests share theirs); not disposed here. Null: the run opens its own.</summary>
    public IComputeDevice? Device { get; init; }

    /// <summary>Draw the progress bar (default: when stderr is a terminal).</summary>
    public bool InteractiveProgress { get; init; } = ProgressReporter.StderrIsTerminal;

    /// <summary>Bytes free on the disk that holds a folder, or null where unknown (tests stand in for a full disk).</summary>
    public Func<string, long?> FreeBytes { get; init; } = OutputFolder.FreeBytes;

    /// <summary>What --solver changed besides the solver (<see cref="SolverChoice.FitSupport"/>), printed with the plan.</summary>
    string? _solverNote;

    /// <summary>The integrity check's problems on what the fluid is not read from, printed with the plan.</summary>
    string? _unreadProblems;

    /// <summary>What the run ended with (null until it ran).</summary>
    public RunSummary? Summary { get; private set; }

    public int Execute()
    {
        var checkedScene = SceneLoader.Open(options.ScenePath);
        _unreadProblems = checkedScene.UnreadProblems;
        var scene = checkedScene.Read(options.Solver.AsChange("simulate", note => _solverNote = note));
        var description = scene.Description;
        int sceneCount = SpawnLayout.TotalCount(description);

        // The device decides the scale (--cpu-particles-scale), so it opens before the scene is scaled and checked; the
        // output folder is claimed only once the scaled scene fits.
        IComputeDevice device = DeviceFactory.GivenOrOpen(Device, scene.PackageFolder, options.DeviceName, "simulate", stderr, out IDisposable? owned);
        try
        {
            bool onCpu = device is VulkanComputeDevice { DeviceType: "Cpu" } && options.CpuParticlesScale != 1.0;
            double scale = options.ParticlesScale * (onCpu ? options.CpuParticlesScale : 1.0);
            ParticleScaling.ScaleBy(description, scale);
            string scaleOption = onCpu ? "--particles-scale times --cpu-particles-scale" : "--particles-scale";
            SceneFit.RequireScaled(description, "simulate", scaleOption, scale.ToString("G6", C));
            SceneFit.RequireDevice(description, device, "simulate", scene.Path, scale == 1.0 ? null : scaleOption, scale.ToString("G6", C));
            using var output = OutputFolder.Claim(options.OutputDirectory ?? Path.Combine("Output", scene.Name), "--out", "simulate");
            RequireExportSpace(output, SpawnLayout.TotalCount(description));
            using var simulation = new FluidSimulation(device, description);
            string scaled = sceneCount == simulation.ParticleCount ? ""
                : string.Format(C, " (scene: {0}, scaled x{1:G4}{2})", sceneCount, scale, onCpu ? " on a CPU device: --cpu-particles-scale" : "");
            return Simulate(scene, simulation, device, output, scaled);
        }
        finally
        {
            owned?.Dispose();
        }
    }

    /// <summary>
    /// Refuses, before anything is simulated or exported, a run whose particle exports alone would not fit on the disk
    /// of --out: one export of 1M particles is 112 MB, so --export-every over a long run can fill a disk, and a full
    /// disk would stop the run part-way.
    /// </summary>
    void RequireExportSpace(OutputFolder output, long particles)
    {
        if (options.ExportEvery <= 0 || FreeBytes(output.Path) is not long free) return;
        double duration = options.Duration;
        long exports = options.Looks(options.ExportEvery);
        long each = ParticleExport.BytesPerExport(particles);
        if (exports * each <= free) return;
        long fit = free / each;
        throw new UsageException(string.Format(C,
            "simulate: --export-every {0:G4} s over {1:G4} s writes {2} exports of {3} particles, {4:F1} MB of .vtu and .ply, " +
            "but the disk holding --out '{5}' has {6:F1} MB free ({7}); export less often, simulate less time, or choose a " +
            "folder on a larger disk (no export was written)",
            options.ExportEvery, duration, exports, particles, exports * each / 1e6, output.Path, free / 1e6,
            fit == 0 ? "not one export fits" : fit == 1 ? "one export fits" : string.Format(C, "{0} exports fit, one every {1:G3} s", fit, duration / (fit - 1))));
    }

    int Simulate(LoadedScene scene, FluidSimulation sim, IComputeDevice device, OutputFolder output, string scaled)
    {
        var description = scene.Description;
        var settings = description.Settings;
        var phases = sim.PhaseRows;
        var restContainer = description.Container.Clone();
        var restObstacles = description.Obstacles.Select(o => o.Clone()).ToList();
        int frames = options.FrameCount;
        double duration = options.Duration;

        stdout.WriteLine($"scene: {scene.Path} ({scene.Name}): fluid '{scene.SimulatorObject}', container '{scene.ContainerObject}' "
            + string.Format(C, "{0:G4} x {1:G4} x {2:G4} m", restContainer.Size.X, restContainer.Size.Y, restContainer.Size.Z)
            + $", {description.SpawnBoxes.Count} spawn box(es), {description.Obstacles.Count} obstacle(s)"
            + (scene.Motion.MovesContainer ? string.Format(C, ", container spins {0:G3} deg/s after {1:G3} s", scene.Motion.ContainerSpin.AngularSpeed, scene.Motion.ContainerSpin.StartDelay) : "")
            + (scene.Motion.MovesObstacles ? $", {scene.Motion.SphereDrives.Count} driven sphere(s)" : ""));
        stdout.WriteLine(string.Format(C, "particles: {0}{1} (spacing {2:G4} m, support {3:G4} m); phases: {4}",
            sim.ParticleCount, scaled,
            settings.ParticleSpacing, settings.SmoothingRadius,
            string.Join(", ", sim.Phases.Select((p, k) => string.Format(C, "{0} {1} rho0 {2:G4} kg/m^3 mu {3:G3} Pa s", p.Name, CountOf(description, k, sim), p.RestDensity, p.Viscosity)))));
        // The cell count sets the sort's scan (PrefixSum: one dispatch up to its SmallLength), which the README's 60 Hz
        // figures cite.
        stdout.WriteLine(string.Format(C, "grid: {0} x {1} x {2} = {3} cells of {4:G4} m (h/{5}, {6} margin cells a side)",
            sim.Grid.DimX, sim.Grid.DimY, sim.Grid.DimZ, sim.Grid.CellCount, sim.Grid.CellSize, CellGrid.CellsPerSupport, CellGrid.MarginCells));
        stdout.WriteLine(sim.Plan.ToString());
        stdout.WriteLine(SolverChoice.Describe(settings, sim));
        if (_solverNote != null) stdout.WriteLine(_solverNote);
        if (FreeVolume.Warning(description) is string crowded) stderr.WriteLine($"simulate: warning: {crowded}");
        if (_unreadProblems != null) stderr.WriteLine($"simulate: warning: {_unreadProblems}");
        stdout.WriteLine(string.Format(C, "device: {0}", DeviceFactory.Describe(device)));
        stdout.WriteLine(string.Format(C, "run: {0:G4} s simulated in {1} frames of {2:G4} ms; output: {3}", duration, frames, options.FrameSeconds * 1000, Path.GetFullPath(output.Path))
            + (options.ExportEvery > 0 ? string.Format(C, "; exports every {0:G4} s: {1} of {2:F2} MB", options.ExportEvery,
                options.Looks(options.ExportEvery), ParticleExport.BytesPerExport(sim.ParticleCount) / 1e6) : ""));
        stdout.Flush();

        var views = new List<(SnapshotView View, string Prefix)> { (new SnapshotView(ViewAxis.Side, restContainer, scene.Motion.MovesContainer, options.ImageWidth), "frame") };
        if (options.TopView) views.Add((new SnapshotView(ViewAxis.Top, restContainer, scene.Motion.MovesContainer, options.ImageWidth), "top"));

        var particles = new Particle[sim.ParticleCount];
        var densities = new Vector4[sim.ParticleCount];
        var layering = new List<FluidMeasures>();
        var export = options.ExportEvery > 0 ? new ParticleExport(output) : null;
        var progress = options.Quiet ? new ProgressReporter(null, false, duration, "s") : new ProgressReporter(stderr, InteractiveProgress, duration, "s");
        using var csv = new DiagnosticsCsv(output.PathOf("diagnostics.csv"), sim.Phases);
        var clock = Stopwatch.StartNew();
        int snapshots = 0, frame = 0, substeps = 0, cappedFrames = 0;
        double nextSnapshot = 0, nextDiagnostics = 0, nextExport = 0;
        DiagnosticsReport? first = null, last = null;
        var cutOffs = new SolveCutOffs();
        string? failure = null;
        var container = restContainer;
        IReadOnlyList<RigidSphere> obstacles = restObstacles;
        StepReport step = StepReport.None;
        var health = new HealthCheck(description, sim.ParticleCount);

        void Observe(bool force)
        {
            double t = sim.SimulatedTime;
            bool diagnose = force || t >= nextDiagnostics - 1e-9;
            bool snap = force || t >= nextSnapshot - 1e-9;
            // Exports keep to their own schedule (0, S, 2S ...): the forced last look adds none.
            bool exportNow = export != null && t >= nextExport - 1e-9;
            if (!diagnose && !snap && !exportNow) return;
            sim.Particles.GetData(particles);
            if (diagnose || exportNow) sim.Densities.GetData(densities);
            if (diagnose)
            {
                var report = sim.ReadDiagnostics();
                var sample = FluidMeasures.Measure(t, particles, densities, phases, container, settings.Gravity, settings.ParticleSpacing, settings.SmoothingRadius);
                layering.Add(sample);
                csv.Append(new DiagnosticsRow(t, frame, step, report, sample));
                progress.Interrupt();
                stdout.WriteLine(DiagnosticsLine(t, frame, step, report, sample, sim.Phases));
                stdout.Flush();
                first ??= report;
                last = report;
                cutOffs.Observe(report);
                failure ??= Health(health, report, particles);
                while (nextDiagnostics <= t + 1e-9) nextDiagnostics += options.DiagnosticsEvery;
            }
            if (snap)
            {
                foreach (var (view, prefix) in views)
                {
                    var image = SnapshotRenderer.Render(view, particles, phases, container, obstacles, settings.ParticleSpacing);
                    output.Write(string.Format(C, "{0}_{1:D4}.png", prefix, snapshots), file => PngEncoder.Write(file, image));
                }
                snapshots++;
                while (nextSnapshot <= t + 1e-9) nextSnapshot += options.SnapshotEvery;
            }
            if (exportNow && export != null)
            {
                export.Write(t, particles, densities);
                while (nextExport <= t + 1e-9) nextExport += options.ExportEvery;
            }
        }

        Observe(force: true);
        WarnIfTheOutputsOutgrowTheDisk(output, export);
        while (failure == null && (options.Frames > 0 ? frame < frames : sim.SimulatedTime < duration - 1e-6))
        {
            float frameSeconds = Math.Max(1e-6f,
                (float)(options.Frames > 0 ? options.FrameSeconds : Math.Min(options.FrameSeconds, duration - sim.SimulatedTime)));
            // Where the laws put the walls at the frame's end, as a Unity Transform reads them (UpdateContainer).
            double start = sim.SimulatedTime, end = start + frameSeconds;
            if (scene.Motion.MovesContainer)
            {
                container = scene.Motion.ContainerOver(restContainer, start, end);
                sim.UpdateContainer(container);
            }
            if (scene.Motion.MovesObstacles)
            {
                obstacles = scene.Motion.ObstaclesOver(restObstacles, start, end);
                sim.UpdateObstacles(obstacles);
            }
            health.ObserveDrivers(container, obstacles);
            step = sim.Step(frameSeconds);
            frame++;
            substeps += step.Substeps;
            if (step.Capped) cappedFrames++;
            // The time step's free max-speed read-back catches a blow-up between diagnostics: check at once.
            Observe(force: sim.TimeStep.MaxSpeed > health.SpeedBound);
            progress.Report(Math.Min(sim.SimulatedTime, duration), string.Format(C, "frame {0}, {1} sub-steps of {2:F3} ms", frame, step.Substeps, step.TimeStep * 1000));
        }
        if (layering.Count == 0 || layering[^1].Time < sim.SimulatedTime - 1e-9 || snapshots == 0) Observe(force: true);
        progress.Finish();
        double wall = clock.Elapsed.TotalSeconds;

        if (sim.Phases.Count > 1)
            LayeringChart.Build(scene.Name, layering, sim.Phases).Save(output, LayeringChart.Stem);

        Summary = new RunSummary(scene, sim, DeviceFactory.Describe(device), sim.SimulatedTime, frame, substeps, cappedFrames, wall, snapshots,
            first, last, layering.Count > 0 ? layering[^1] : null, failure, Path.GetFullPath(output.Path))
        {
            Exports = export?.Count ?? 0,
            Settings = settings,
            CutOffs = cutOffs,
        };
        output.WriteText("summary.txt", Summary.ToText());
        stdout.WriteLine(Summary.OneLine());
        if (Summary.CutOffWarning() is string warning) stderr.WriteLine($"simulate: warning: {warning}");
        if (failure != null)
        {
            stderr.WriteLine($"simulate: {failure}");
            return ExitCodes.SimulationFailed;
        }
        return ExitCodes.Ok;
    }

    /// <summary>
    /// Once the first snapshots are written, and so their size is known, warns where the snapshots and exports still to
    /// come would not fit on the disk of --out: a long run at the default --frames-every writes four PNGs a simulated
    /// second, and would otherwise stop with a file error only when the disk fills.
    /// </summary>
    void WarnIfTheOutputsOutgrowTheDisk(OutputFolder output, ParticleExport? export)
    {
        if (FreeBytes(output.Path) is not long free) return;
        long SizeOf(string name)
        {
            var file = new FileInfo(Path.Combine(output.Path, name));
            return file.Exists ? file.Length : 0;
        }
        long snapshotBytes = SizeOf("frame_0000.png") + SizeOf("top_0000.png");
        long snapshotsToCome = options.Looks(options.SnapshotEvery); // less the first, plus a last look: one too many at most
        long exportsToCome = export == null ? 0 : options.Looks(options.ExportEvery) - export.Count;
        long exportBytes = SizeOf("particles_0000.vtu") + SizeOf("particles_0000.ply");
        long needed = snapshotsToCome * snapshotBytes + exportsToCome * exportBytes;
        if (needed <= free) return;
        stderr.WriteLine(string.Format(C,
            "simulate: warning: {0} more snapshot(s) ({1:F0} KB each) and {2} more export(s) need about {3:F1} MB, more than the " +
            "{4:F1} MB free on the disk holding --out '{5}'; the run will stop with a file error when the disk fills (raise " +
            "--frames-every or --export-every, or free some space)",
            snapshotsToCome, snapshotBytes / 1e3, exportsToCome, needed / 1e6, free / 1e6, output.Path));
    }

    static int CountOf(FluidSceneDescription scene, int phase, FluidSimulation sim)
    {
        long n = 0;
        foreach (var box in scene.SpawnBoxes)
            if (box.Phase.Name == sim.Phases[phase].Name) n += SpawnLayout.SpawnedCount(scene, box);
        return (int)n;
    }

    /// <summary>Why the state is unacceptable, or null: <see cref="HealthCheck"/> names the first bad time, phase and
    /// figure (non-finite, outside, lost, faster than the scene allows, over-compressed, energy from nowhere).</summary>
    static string? Health(HealthCheck health, DiagnosticsReport report, Particle[] particles) => health.Check(report, particles)?.Message;

    static string DiagnosticsLine(double t, int frame, StepReport step, DiagnosticsReport r, FluidMeasures m, IReadOnlyList<PhaseDescription> phases)
    {
        var line = string.Format(C, "t={0,6:F3} s frame={1,4} substeps={2,2} dt={3,6:F3} ms N={4} mass={5:G6} kg KE={6:G4} J PE={7:G4} J vmax={8:F3} m/s nan={9} out={10} clamped={11}",
            t, frame, step.Substeps, step.TimeStep * 1000, r.ParticleCount, r.TotalMass, r.KineticEnergy, m.PotentialEnergy, r.MaxSpeed, r.NanCount, r.OutsideCount, r.ClampHits);
        for (int k = 0; k < phases.Count; k++)
        {
            var p = m.Phases[k];
            line += string.Format(C, " | {0}: comp {1:P2}/{2:P2} exp {3:P2}/{4:P2} y {5:F3} m", phases[k].Name,
                p.CompressionAverage, p.CompressionMax, p.ExpansionAverage, p.ExpansionMax, p.MeanHeight);
            if (phases.Count > 1) line += string.Format(C, " floor {0:P0} wall {1:P0}", p.FloorShare, p.WallShare);
        }
        if (phases.Count > 1) line += string.Format(C, " | layering {0:F2} tilt {1:F3} m", m.LayeringIndex, m.InterfaceTilt);
        line += string.Format(C, " | front {0:F3} m column {1:F3} m", m.SurgeFront, m.BackWallColumn);
        // A solve cut off at its iteration limit leaves the error above the tolerance; said where it happens, not only
        // in diagnostics.csv.
        if (r.PressureSolver == PressureSolver.Dfsph)
            line += string.Format(C, " | DFSPH iterations density {0:F1} ({1:P0} cut off) divergence {2:F1} ({3:P0} cut off)",
                r.DensitySolveIterations, r.DensitySolvesCutOff, r.DivergenceSolveIterations, r.DivergenceSolvesCutOff);
        return line;
    }
}
