using System;
using System.Collections.Generic;
using System.Numerics;

namespace SphFluid.Simulation
{
    /// <summary>
    /// The Tait fluid's speed of sound c = sqrt(k gamma / rho0) must suit the speeds of the scene, v: a fall along
    /// the container's diagonal D, sqrt(2 |g| D), plus the fastest spawn velocity, container wall and sphere.
    /// <list type="bullet">
    /// <item>Subsonic: v &lt;= c of the densest phase (the lowest c). Beyond it an impact compresses the fluid by tens
    ///   of per cent, the pressure stiffens with (rho / rho0)^gamma and the step planned from c no longer resolves it
    ///   (gravity 1000 m/s^2 reached 702 m/s in a 0.5 m tank with c = 22 m/s).</item>
    /// <item>Not needlessly stiff: c of the lightest phase (the highest c) &lt;= <see cref="MaxSoundRatio"/>
    ///   max(v, 1 m/s). Weakly compressible SPH takes c about ten times the flow speed (Monaghan 1994, "Simulating
    ///   free surface flows with SPH"); a hundred times keeps the density error near (v / c)^2 = 1e-4 already,
    ///   and a stiffer fluid only turns the spawn lattice's small density noise into acoustic motion of about
    ///   c / 100 (stiffness 1e9 Pa, c = 2646 m/s, boiled a resting tank to 41 m/s) and multiplies the sub-steps.</item>
    /// </list>
    /// </summary>
    internal static class SpeedOfSoundRule
    {
        /// <summary>Largest ratio of the speed of sound to the scene's fastest speed.</summary>
        internal const float MaxSoundRatio = 100f;

        /// <summary>The scene speed below which the stiffness rule stops tightening, m/s (a scene at rest without gravity).</summary>
        internal const float MinSceneSpeed = 1f;

        /// <summary>rho / rho0 where a Mach-1 impact stops: the Tait pressure k ((rho / rho0)^gamma - 1) equals the
        /// stagnation pressure rho0 c^2 / 2 = k gamma / 2, so (rho / rho0)^gamma = 1 + gamma / 2 (1.24 at gamma = 7).
        /// The most compression a subsonic scene can cause: the health check and the particle-mass range use it.</summary>
        internal static double SonicImpactDensityRatio(float gamma) => Math.Pow(1.0 + 0.5 * gamma, 1.0 / gamma);

        /// <summary>c = sqrt(k gamma / rho0), m/s.</summary>
        internal static float SpeedOfSound(FluidSettings settings, float restDensity) =>
            (float)Math.Sqrt(settings.Stiffness * (double)settings.Gamma / Math.Max(restDensity, 1e-6f));

        /// <summary>Adds one error naming the field that makes the scene supersonic (gravity or the fastest spawn
        /// box), with its allowed range and the stiffness that would admit it. Needs valid settings, container and boxes.</summary>
        internal static void Validate(FluidSceneDescription scene, List<ValidationError> errors)
        {
            var settings = scene.Settings;
            PhaseDescription densest = null, lightest = null;
            foreach (var phase in scene.Phases())
            {
                if (densest == null || phase.RestDensity > densest.RestDensity) densest = phase;
                if (lightest == null || phase.RestDensity < lightest.RestDensity) lightest = phase;
            }
            if (densest == null) return;

            float c = SpeedOfSound(settings, densest.RestDensity);
            double diagonal = scene.Container.Size.Length();
            double fall = Math.Sqrt(2.0 * settings.Gravity.Length() * diagonal);
            int fastestBox = -1;
            float spawn = 0f;
            for (int b = 0; b < scene.SpawnBoxes.Count; b++)
            {
                float v = scene.SpawnBoxes[b].InitialVelocity.Length();
                if (v > spawn) { spawn = v; fastestBox = b; }
            }
            double drivers = scene.Container.Velocity.Length() + scene.Container.AngularVelocity.Length() * 0.5 * diagonal;
            if (scene.Obstacles != null)
            {
                double sphere = 0;
                foreach (var o in scene.Obstacles) if (o != null) sphere = Math.Max(sphere, o.Velocity.Length());
                drivers += sphere;
            }
            double fastest = fall + spawn + drivers;
            double scale = Math.Max(fastest, MinSceneSpeed);
            float cLight = SpeedOfSound(settings, lightest.RestDensity);
            if (cLight > MaxSoundRatio * scale)
            {
                double maxStiffness = Math.Pow(MaxSoundRatio * scale, 2) * lightest.RestDensity / settings.Gamma;
                errors.Add(new ValidationError("Settings.Stiffness",
                    "FluidSettings", $"Stiffness must be in [1, {ValidationRules.Format(maxStiffness)}] Pa for this scene: the speed of sound {ValidationRules.Format(cLight)} m/s of phase '{lightest.Name}' must be at most {ValidationRules.Format(MaxSoundRatio)} times the fastest speed the scene can reach, {ValidationRules.Format(fastest)} m/s (taken as at least {ValidationRules.Format(MinSceneSpeed)} m/s): free fall along the container's {ValidationRules.Format(diagonal)} m diagonal plus the fastest spawn box, walls and spheres; a stiffer fluid turns spawn noise into fast acoustic motion (was {ValidationRules.Format(settings.Stiffness)})"));
            }
            if (fastest <= c) return;

            // k such that c' = fastest: c'^2 = k gamma / rho0.
            double stiffness = fastest * fastest * densest.RestDensity / settings.Gamma;
            string because = $"free fall along the container's {ValidationRules.Format(diagonal)} m diagonal ({ValidationRules.Format(fall)} m/s) plus the fastest spawn box ({ValidationRules.Format(spawn)} m/s) and walls or spheres ({ValidationRules.Format(drivers)} m/s) must stay below the speed of sound {ValidationRules.Format(c)} m/s of phase '{densest.Name}'";
            string orStiffer = $", or Stiffness must be at least {ValidationRules.Format(stiffness)} Pa";
            if (fall >= spawn && fall >= drivers)
            {
                double left = Math.Max(0.0, c - spawn - drivers);
                double maxGravity = left * left / (2.0 * diagonal);
                errors.Add(new ValidationError("Settings.Gravity",
                    "FluidSettings", $"Gravity must have magnitude in [0, {ValidationRules.Format(maxGravity)}] m/s^2 for this scene{orStiffer}: {because} (was {ValidationRules.Format(settings.Gravity.Length())})"));
            }
            else if (spawn >= drivers && fastestBox >= 0)
            {
                var box = scene.SpawnBoxes[fastestBox];
                double maxSpawn = Math.Max(0.0, c - fall - drivers);
                errors.Add(new ValidationError($"SpawnBoxes[{fastestBox}].InitialVelocity",
                    $"SpawnBox '{box.Name}'", $"InitialVelocity must have magnitude in [0, {ValidationRules.Format(maxSpawn)}] m/s for this scene{orStiffer}: {because} (was {ValidationRules.Format(spawn)})"));
            }
            else
            {
                double maxDrivers = Math.Max(0.0, c - fall - spawn);
                errors.Add(new ValidationError("Container.Velocity",
                    "Container", $"the speed of its walls and spheres must be in [0, {ValidationRules.Format(maxDrivers)}] m/s for this scene{orStiffer}: {because} (was {ValidationRules.Format(drivers)})"));
            }
        }
    }
}
