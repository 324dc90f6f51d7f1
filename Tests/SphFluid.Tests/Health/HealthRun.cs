using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Linq;
using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Health
{
    /// <summary>
    /// What became of one hard case: refused at validation (with the messages), or simulated in 60 Hz frames
    /// with the <see cref="HealthCheck"/> asked after every frame (the first problem, if any, and the largest
    /// figures seen).
    /// </summary>
    public sealed class HealthRun
    {
        const float Frame = 1f / 60f;

        public IReadOnlyList<string> Refusals { get; private set; } = Array.Empty<string>();
        HealthCheck? _check;
        DiagnosticsReport? _last;

        /// <summary>The first problem the check found; null while the run is healthy.</summary>
        public HealthProblem? Problem { get; private set; }
        public HealthCheck Check => _check ?? throw new InvalidOperationException("the scene was refused at validation: nothing was checked");
        public DiagnosticsReport Last => _last ?? throw new InvalidOperationException("the scene was refused at validation: nothing was simulated");
        public float FastestSeen { get; private set; }
        public float MostCompressed { get; private set; }
        public int Frames { get; private set; }
        public int Substeps { get; private set; }
        public double MostEnergyGained { get; private set; }

        public bool Refused => Refusals.Count > 0;

        /// <summary>Validates <paramref name="scene"/>; if valid, runs it for <paramref name="seconds"/> of simulated
        /// time (or <paramref name="maxFrames"/> frames, whichever comes first), moving its drivers with
        /// <paramref name="drive"/> (simulated time of the frame's end) before each frame.</summary>
        public static HealthRun Of(FluidSceneDescription scene, double seconds, int maxFrames = 120,
            Action<FluidSimulation, double>? drive = null)
        {
            var run = new HealthRun();
            run.Refusals = scene.Validate().Select(e => e.Message).ToArray();
            if (run.Refused)
            {
                TestContext.Out.WriteLine("refused: " + string.Join("\n  ", run.Refusals));
                return run;
            }
            var clock = Stopwatch.StartNew();
            using (var sim = new FluidSimulation(GpuTestDevice.Shared, scene))
            {
                run._check = new HealthCheck(scene, sim.ParticleCount);
                var particles = new Particle[sim.ParticleCount];
                run.Observe(sim, particles);
                while (run.Problem == null && sim.SimulatedTime < seconds - 1e-6 && run.Frames < maxFrames)
                {
                    drive?.Invoke(sim, sim.SimulatedTime + Frame);
                    run.Check.ObserveDrivers(sim.Scene.Container, sim.Scene.Obstacles);
                    var step = sim.Step(Frame);
                    run.Frames++;
                    run.Substeps += step.Substeps;
                    run.Observe(sim, particles);
                }
                TestContext.Out.WriteLine($"{run.Frames} frames, {run.Substeps} sub-steps, {sim.SimulatedTime:F3} s simulated in {clock.Elapsed.TotalSeconds:F1} s wall; "
                    + $"speed bound {run.Check.SpeedBound:G4} m/s, fastest {run.FastestSeen:G4} m/s, most compressed {run.MostCompressed:P2} (bounds {run.Check.MeanCompressionBound:P1} mean, {run.Check.MaxCompressionBound:P1} max), "
                    + $"largest energy growth {run.MostEnergyGained:G4} J (bound {run.Check.EnergyBound:G4} J{(run.Check.Driven ? ", not checked: driven" : "")}); last: {run.Last}"
                    + (run.Problem != null ? "\nPROBLEM: " + run.Problem.Message : ""));
            }
            return run;
        }

        void Observe(FluidSimulation sim, Particle[] particles)
        {
            sim.Particles.GetData(particles);
            _last = sim.ReadDiagnostics();
            FastestSeen = Math.Max(FastestSeen, float.IsNaN(Last.MaxSpeed) ? float.PositiveInfinity : Last.MaxSpeed);
            foreach (var p in Last.Phases) MostCompressed = Math.Max(MostCompressed, p.MaxDensityError);
            Problem ??= Check.Check(Last, particles);
            MostEnergyGained = Math.Max(MostEnergyGained, Check.EnergyGrowth);
        }
    }
}
