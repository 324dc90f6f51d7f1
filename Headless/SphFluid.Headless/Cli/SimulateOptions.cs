using System;

namespace SphFluid.Headless.Cli;

/// <summary>The arguments of <c>sphfluid simulate</c>.</summary>
public sealed class SimulateOptions
{
    public const double DefaultSeconds = 3.0;
    public const double DefaultFrameSeconds = 1.0 / 60.0;

    /// <summary>
    /// Shortest frame and shortest output interval, s. The solver steps at least 1 microsecond per frame, and rows and
    /// snapshots come at frame ends: a shorter value would be misreported or would never advance the next output
    /// time (1e-300 added to 0.25 is 0.25), so it is refused rather than run.
    /// </summary>
    public const double MinInterval = 1e-4;

    public string ScenePath { get; set; }

    /// <summary>Simulated seconds to run (ignored when <see cref="Frames"/> is set).</summary>
    public double Seconds { get; set; } = DefaultSeconds;

    /// <summary>Frames of <see cref="FrameSeconds"/> to run instead of <see cref="Seconds"/>; 0 = use seconds.</summary>
    public int Frames { get; set; }

    /// <summary>Real time given to each frame (as a 60 Hz Unity frame), s; the solver covers it in adaptive sub-steps.</summary>
    public double FrameSeconds { get; set; } = DefaultFrameSeconds;

    /// <summary>Output folder; default Output/&lt;scene name&gt;.</summary>
    public string OutputDirectory { get; set; }

    public double SnapshotEvery { get; set; } = 0.25;
    public double DiagnosticsEvery { get; set; } = 0.25;

    /// <summary>Simulated seconds between particle exports (.vtu, .ply, .pvd); 0 = no export.</summary>
    public double ExportEvery { get; set; }

    /// <summary>Multiplies the scene's particle count (the spacing shrinks by its cube root).</summary>
    public double ParticlesScale { get; set; } = 1.0;

    /// <summary>Case-insensitive substring of the Vulkan adapter name.</summary>
    public string DeviceName { get; set; }

    public bool TopView { get; set; }
    public int ImageWidth { get; set; } = 640;
    public bool Quiet { get; set; }
    public bool Help { get; set; }

    public const string HelpText =
@"sphfluid simulate <scene.unity> [options]

Reads a Unity scene file (the FluidSimulator's settings, every SpawnBox with its world transform, the
FluidContainer, SphereObstacles, ContainerSpinner/SphereDriver motion) and simulates it on the headless
Vulkan backend. Writes diagnostics.csv, frame_NNNN.png snapshots, layering.png (multi-phase scenes) and
summary.txt into the output folder. The scene must be a regular file of at most 16 MiB that passes the
project's integrity check (the same check the test suite runs on every shipped scene).

Measures (console, diagnostics.csv, summary.txt): kinetic and potential energy; per phase the
compression max(0, rho/rho0 - 1) and expansion max(0, 1 - rho/rho0) (mean and max), the mean, bottom
and top height (along gravity from the container's lowest corner) and its share of the floor and wall
layers (particles within one spacing of the face); the layering index over pairs of different density,
(ordered - inverted) / pairs (1 = perfectly layered, 0 = mixed, -1 = upside down); the surge front
(container-local x from the back wall reached within 2 spacings of the floor) and the column height at
the back wall, spray ignored.

Options:
  --seconds S              simulated seconds to run, in (0, 3600] (default 3)
  --steps N                run N frames of --frame-seconds instead, N in [1, 1000000]
  --frame-seconds S        real time per frame, in [0.0001, 0.1] s (default 1/60, as a 60 Hz Unity frame)
  --out DIR                output folder (default Output/<scene name>). The run records what it writes in
                           DIR/.sphfluid-outputs and deletes only the files an earlier run recorded there;
                           a folder holding frame_NNNN.png, summary.txt ... that sphfluid did not write is
                           refused (exit 2) and left as it was
  --frames-every S         simulated seconds between PNG snapshots, in [0.0001, 3600] (default 0.25);
                           snapshots come at frame ends, so at most one per frame
  --diagnostics-every S    simulated seconds between diagnostics lines/CSV rows, in [0.0001, 3600] (default 0.25);
                           at most one row per frame
  --export-every S         simulated seconds between particle exports, in [0.0001, 3600] (default: none). Each
                           writes particles_NNNN.vtu (ParaView; inline base64 binary) and particles_NNNN.ply
                           (Blender, MeshLab; binary little-endian) with position, velocity, phase, density
                           and pressure, and particles.pvd indexes the .vtu files by time
  --particles-scale F      multiply the particle count by F, in [0.01, 100] (spacing and support shrink by F^(1/3))
  --device NAME            Vulkan adapter whose name contains NAME (default: SPHFLUID_VULKAN_DEVICE, else the best)
  --top-view               also write top_NNNN.png (looking down)
  --width PX               snapshot width in pixels, in [64, 4096] (default 640)
  --quiet                  no progress output
  --help                   this text

Exit codes: 0 ok, 1 no Vulkan device or unexpected failure, 2 bad arguments, 3 scene errors,
4 the run became unhealthy: non-finite, particles lost, or faster, more compressed or more
energetic than the scene allows (the message names the time, phase and figure).";

    public static SimulateOptions Parse(string[] args)
    {
        const string command = "simulate";
        var options = new SimulateOptions();
        var reader = new ArgumentReader(command, args);
        bool secondsGiven = false;
        while (reader.MoveNext(out string token))
        {
            switch (token)
            {
                case "--help": case "-h": options.Help = true; break;
                case "--seconds": options.Seconds = reader.Double(token, 0, 3600, true, "s"); secondsGiven = true; break;
                case "--steps": options.Frames = reader.Int(token, 1, 1_000_000); break;
                case "--frame-seconds": options.FrameSeconds = reader.Double(token, MinInterval, 0.1, false, "s"); break;
                case "--out": options.OutputDirectory = reader.Value(token); break;
                case "--frames-every": options.SnapshotEvery = reader.Double(token, MinInterval, 3600, false, "s"); break;
                case "--diagnostics-every": options.DiagnosticsEvery = reader.Double(token, MinInterval, 3600, false, "s"); break;
                case "--export-every": options.ExportEvery = reader.Double(token, MinInterval, 3600, false, "s"); break;
                case "--particles-scale": options.ParticlesScale = reader.Double(token, 0.01, 100, false, ""); break;
                case "--device": options.DeviceName = reader.Value(token); break;
                case "--top-view": options.TopView = true; break;
                case "--width": options.ImageWidth = reader.Int(token, 64, 4096); break;
                case "--quiet": options.Quiet = true; break;
                default:
                    if (ArgumentReader.IsOption(token)) throw reader.Unknown(token);
                    if (options.ScenePath != null) throw reader.Unknown(token);
                    options.ScenePath = token;
                    break;
            }
        }
        reader.Finish();
        if (options.Help) return options;
        if (string.IsNullOrWhiteSpace(options.ScenePath))
            throw new UsageException($"{command}: the scene file argument is missing (e.g. sphfluid simulate Assets/FluidDemo/Scenes/OilAndWater.unity)");
        if (secondsGiven && options.Frames > 0)
            throw new UsageException($"{command}: give either --seconds or --steps, not both");
        return options;
    }

    /// <summary>Frames the run takes.</summary>
    public int FrameCount => Frames > 0 ? Frames : Math.Max(1, (int)Math.Ceiling(Seconds / FrameSeconds - 1e-9));
}
