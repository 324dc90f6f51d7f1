using System;
using System.Globalization;
using System.Linq;
using System.Numerics;
using System.Text.RegularExpressions;
using SphFluid.Headless.Cli;
using SphFluid.Headless.Runs;
using SphFluid.Headless.Scenes;
using SphFluid.Simulation;
using SphFluid.Tests.Runner;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// The shipped RestingTank scene changed as a surface probe's fixture names it (<see cref="SurfaceSeicheProbe"/>,
    /// <see cref="SurfaceDispersionProbe"/>, <see cref="ViscousSeicheProbe"/>), so that one name means one
    /// configuration in each. The name lists its changes, comma-separated, from these: "dfsph" (the scene switched as
    /// <c>--solver dfsph</c> switches it), "Wendland C2 relaxed" (OilAndWater's DFSPH kernel: Wendland C2 at 2.85
    /// spacings, relaxation 0.3), "cubic spline" (at 2 spacings), "support S" (the scene's kernel reaching S spacings),
    /// "jittered" (a quarter spacing of spawn jitter), "free-slip" (walls that push only along their normals), "long
    /// tank" (the tank and its water twice as long), "narrow" (tank and water 0.1 m across), "strain rate" (the
    /// viscosity as the strain rate's stress, <see cref="ViscousStress.StrainRate"/>), "summation density" (WCSPH's
    /// density summed each sub-step, not carried), "no artificial viscosity", "no XSPH", "tight solves" (DFSPH's
    /// Chebyshev-accelerated solves to 0.01 % and 1 %/s, at most 1000 rounds each), "loose solves" (DFSPH's solves to 1 %
    /// and 100 %/s), "chebyshev" (DFSPH's solves Chebyshev-accelerated at the scene's tolerances), "max step S ms" (the
    /// largest sub-step S ms), "stiffness xF" (F times the Tait stiffness) and "half the spacing" (8 times the
    /// particles); "wcsph" is the scene as shipped, "half swing" is the dispersion probe's smaller kick and the viscous
    /// seiche probe's smaller tilt, "viscous step F" the viscous seiche probe's largest sub-step (F times its viscous
    /// run's explicit limit) and "V Pa s" that probe's viscous run, no changes to the scene. A name with any other part
    /// is refused, so that a mistyped fixture cannot run the shipped scene unnoticed.
    /// </summary>
    public static class SloshingTankConfiguration
    {
        static readonly string[] Known =
        {
            "wcsph", "dfsph", "Wendland C2 relaxed", "cubic spline", "jittered", "free-slip", "long tank", "narrow", "strain rate",
            "summation density", "no artificial viscosity", "no XSPH", "tight solves", "loose solves", "chebyshev", "half the spacing",
            "half swing",
        };
        static readonly Regex Support = new Regex(@"^support (\d+(\.\d+)?)$");
        static readonly Regex Stiffer = new Regex(@"^stiffness x(\d+(\.\d+)?)$");
        static readonly Regex LargestStep = new Regex(@"^max step (\d+(\.\d+)?) ms$");

        /// <summary>"viscous step F": read by <see cref="ViscousSeicheProbe"/>, not applied here.</summary>
        public static readonly Regex ViscousStep = new Regex(@"^viscous step (\d+(\.\d+)?)$");

        /// <summary>"V Pa s": the viscosity of <see cref="ViscousSeicheProbe"/>'s viscous run, not applied here.</summary>
        public static readonly Regex ProbeViscosity = new Regex(@"^(\d+(\.\d+)?) Pa s$");

        /// <summary>The configuration's changes, as its name lists them.</summary>
        public static string[] Parts(string configuration) => configuration.Split(',').Select(p => p.Trim()).ToArray();

        /// <summary>Whether the configuration names "half the spacing", wherever in the name: the probes then tilt the
        /// surface by two of the finer lattice's spacings, the same swing.</summary>
        public static bool HalvesTheSpacing(string configuration) => Parts(configuration).Contains("half the spacing");

        /// <summary>The RestingTank scene in the named configuration.</summary>
        public static FluidSceneDescription Load(string configuration)
        {
            var parts = Parts(configuration);
            var unknown = parts.Where(p => !Known.Contains(p) && !Support.IsMatch(p) && !Stiffer.IsMatch(p) && !LargestStep.IsMatch(p) && !ViscousStep.IsMatch(p) && !ProbeViscosity.IsMatch(p)).ToList();
            if (unknown.Count > 0)
                throw new ArgumentException($"'{configuration}': no such change to the sloshing tank: {string.Join(", ", unknown)}", nameof(configuration));
            var scene = SceneLoader.Load(RunnerPaths.Scene("RestingTank"), RunnerPaths.Project).Description;
            var water = scene.SpawnBoxes.Single();
            // Applied in this order whatever the name's: the solver's switch first, since it may fit the kernel to DFSPH's
            // band, and the particle scaling last, since it scales the tank's final spacing.
            if (parts.Contains("dfsph")) new SolverChoice { Solver = PressureSolver.Dfsph }.ApplyTo(scene, $"DFSPH RestingTank ({configuration})");
            var s = scene.Settings;
            if (parts.Contains("Wendland C2 relaxed"))
            {
                s.SmoothingKernel = KernelFamily.WendlandC2;
                s.SmoothingRadius = 2.85f * s.ParticleSpacing;
                s.SolverRelaxation = 0.3f;
            }
            if (parts.Contains("cubic spline"))
            {
                s.SmoothingKernel = KernelFamily.CubicSpline;
                s.SmoothingRadius = 2f * s.ParticleSpacing;
            }
            foreach (var match in parts.Select(p => Support.Match(p)).Where(m => m.Success))
                s.SmoothingRadius = float.Parse(match.Groups[1].Value, CultureInfo.InvariantCulture) * s.ParticleSpacing;
            foreach (var match in parts.Select(p => Stiffer.Match(p)).Where(m => m.Success))
                s.Stiffness *= float.Parse(match.Groups[1].Value, CultureInfo.InvariantCulture);
            if (parts.Contains("jittered")) water.Jitter = 0.25f;
            if (parts.Contains("free-slip")) scene.Container.Friction = WallFriction.Slip;
            if (parts.Contains("long tank"))
            {
                scene.Container.Size = new Vector3(2 * scene.Container.Size.X, scene.Container.Size.Y, scene.Container.Size.Z);
                water.Size = new Vector3(scene.Container.Size.X, water.Size.Y, water.Size.Z);
                water.Center = new Vector3(scene.Container.Position.X, water.Center.Y, water.Center.Z);
            }
            if (parts.Contains("narrow"))
            {
                scene.Container.Size = new Vector3(scene.Container.Size.X, scene.Container.Size.Y, 0.1f);
                water.Size = new Vector3(water.Size.X, water.Size.Y, 0.1f);
            }
            if (parts.Contains("strain rate")) s.ViscousStress = ViscousStress.StrainRate;
            if (parts.Contains("summation density")) s.WcsphDensity = WcsphDensity.Summation;
            if (parts.Contains("no artificial viscosity")) s.ArtificialViscosity = 0;
            if (parts.Contains("no XSPH")) s.XsphEpsilon = 0;
            if (parts.Contains("tight solves"))
            {
                s.SolverIteration = SolverIteration.Chebyshev;
                s.DensityTolerance = 0.01f;
                s.DivergenceTolerance = 1f;
                s.MaxSolverIterations = 1000;
            }
            if (parts.Contains("loose solves"))
            {
                s.DensityTolerance = 1f;
                s.DivergenceTolerance = 100f;
            }
            if (parts.Contains("chebyshev")) s.SolverIteration = SolverIteration.Chebyshev;
            foreach (var match in parts.Select(p => LargestStep.Match(p)).Where(m => m.Success))
                s.MaxTimeStep = float.Parse(match.Groups[1].Value, CultureInfo.InvariantCulture) / 1000f;
            if (HalvesTheSpacing(configuration)) ParticleScaling.ScaleBy(scene, 8);
            return scene;
        }
    }
}
