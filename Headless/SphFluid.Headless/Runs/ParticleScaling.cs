using System;
using SphFluid.Simulation;

namespace SphFluid.Headless.Runs;

/// <summary>
/// Changes how many particles a scene spawns without changing the scene: the spacing (and the support
/// radius with it, keeping h / s) shrinks or grows by the cube root of the factor, so every box holds the
/// same volume of fluid at a finer or coarser resolution.
/// </summary>
public static class ParticleScaling
{
    /// <summary>The largest particle-count multiplier the commands take: a 4 096-particle scene (the shipped scenes hold
    /// 1 440 to 8 008) scaled to the particle limit, 16 777 216. A larger scene scaled past that limit is refused by its
    /// own validation, which names MaxParticles. The GPU study runs OilAndWater's 4 160 particles at 1 M and 2 M (240 and
    /// 481; Headless/gpu-figures.sh).</summary>
    public const double MaxFactor = 4096;

    /// <summary>A copy of <paramref name="scene"/>'s settings scaled by <paramref name="factor"/> in particle count.</summary>
    public static void ScaleBy(FluidSceneDescription scene, double factor)
    {
        if (!(factor > 0) || !double.IsFinite(factor)) throw new ArgumentOutOfRangeException(nameof(factor), factor, "particle scale must be a finite number > 0");
        if (Math.Abs(factor - 1) < 1e-12) return;
        Apply(scene, scene.Settings.ParticleSpacing / (float)Math.Cbrt(factor));
    }

    /// <summary>Sets the spacing so the scene spawns about <paramref name="target"/> particles (within a few per cent:
    /// lattice counts are whole numbers per axis). Returns the count reached.</summary>
    public static int ScaleTo(FluidSceneDescription scene, int target)
    {
        if (target < 1) throw new ArgumentOutOfRangeException(nameof(target), target, "particle count must be >= 1");
        for (int i = 0; i < 6; i++)
        {
            int now = Count(scene);
            if (now == 0 || Math.Abs(now - target) <= target * 0.01) break;
            Apply(scene, scene.Settings.ParticleSpacing * (float)Math.Cbrt((double)now / target));
        }
        return Count(scene);
    }

    /// <summary>An explicit particle mass keeps its ratio to the derived one, which goes with the volume each
    /// particle stands for (<see cref="DerivedParticleMass"/>): the finer lattice must still start at the density the
    /// scene meant, and each box must still carry the same mass. Boxes of one phase share one mass, so the ratio is
    /// the phase's, looked up by name.</summary>
    static void ScaleExplicitMasses(FluidSceneDescription before, FluidSceneDescription after)
    {
        var ratios = new System.Collections.Generic.Dictionary<string, double>();
        foreach (var phase in before.Phases())
            ratios[phase.Name] = DerivedParticleMass.Of(after, phase) / DerivedParticleMass.Of(before, phase);
        foreach (var box in after.SpawnBoxes)
        {
            if (box.Phase == null || box.Phase.ParticleMass <= 0f) continue;
            box.Phase = box.Phase.Clone();
            box.Phase.ParticleMass = (float)(box.Phase.ParticleMass * ratios[box.Phase.Name]);
        }
    }

    static int Count(FluidSceneDescription scene)
    {
        long total = 0;
        foreach (var box in scene.SpawnBoxes) total += SpawnLayout.Count(scene.Settings, box);
        return (int)Math.Min(total, int.MaxValue);
    }

    /// <summary>Sets the spacing (and the support radius with it) and rescales explicit masses. The walls and
    /// obstacles are sampled from the spacing and support radius at run time (BoundarySampling), so they follow
    /// without a setting of their own.</summary>
    static void Apply(FluidSceneDescription scene, float spacing)
    {
        var before = new FluidSceneDescription
        {
            Settings = scene.Settings, SpawnBoxes = new System.Collections.Generic.List<FluidBlock>(scene.SpawnBoxes),
            Container = scene.Container, Obstacles = scene.Obstacles,
        };
        var settings = scene.Settings.Clone();
        float ratio = settings.SmoothingRadius / settings.ParticleSpacing;
        settings.ParticleSpacing = spacing;
        settings.SmoothingRadius = spacing * ratio;
        scene.Settings = settings;
        ScaleExplicitMasses(before, scene);
        long total = 0;
        foreach (var box in scene.SpawnBoxes) total += SpawnLayout.Count(settings, box);
        // The scene's MaxParticles guards a Unity session; asking for more particles here is the point.
        if (total > settings.MaxParticles) settings.MaxParticles = (int)Math.Min(16_777_216, total);
    }
}
