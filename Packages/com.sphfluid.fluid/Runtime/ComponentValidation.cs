using System;
using System.Collections.Generic;
using SphFluid.Simulation;
using UnityEngine;

namespace SphFluid.Runtime
{
    /// <summary>
    /// Checks one component through the engine-free core, the single source of truth for ranges and
    /// their wording: the component is put into an otherwise empty scene description and only the
    /// core's messages about that component are kept.
    /// </summary>
    public static class ComponentValidation
    {
        /// <summary>A container so large that any sane box or sphere lies inside it.</summary>
        const float RoomSize = 1000f;

        public static IReadOnlyList<ValidationError> SettingsErrors(FluidSettings settings) => settings.Validate();

        /// <summary>Errors about the box and its phase; its size and placement depend on the simulator's
        /// spacing and container, so they are checked when the simulation starts.</summary>
        public static IReadOnlyList<ValidationError> SpawnBoxErrors(FluidBlock box)
        {
            var scene = new FluidSceneDescription
            {
                Container = new ContainerDescription(box.Center, System.Numerics.Quaternion.Identity,
                    new System.Numerics.Vector3(RoomSize)),
            };
            scene.SpawnBoxes.Add(box);
            return Keep(scene.Validate(), "SpawnBoxes[0]", "SpawnBoxes[0].Size", "SpawnBoxes[0].Center");
        }

        public static IReadOnlyList<ValidationError> ObstacleErrors(RigidSphere obstacle)
        {
            var scene = new FluidSceneDescription();
            scene.Obstacles.Add(obstacle);
            return Keep(scene.Validate(), "Obstacles[0]");
        }

        public static IReadOnlyList<ValidationError> ContainerErrors(ContainerDescription container)
        {
            var scene = new FluidSceneDescription { Container = container };
            return Keep(scene.Validate(), "Container");
        }

        static IReadOnlyList<ValidationError> Keep(IReadOnlyList<ValidationError> errors, string prefix, params string[] except)
        {
            var kept = new List<ValidationError>();
            foreach (ValidationError e in errors)
            {
                if (!e.Field.StartsWith(prefix, StringComparison.Ordinal)) continue;
                if (Array.IndexOf(except, e.Field) >= 0) continue;
                kept.Add(e);
            }
            return kept;
        }

        /// <summary>Logs each message with the component as context (click the line to select it). A sphere's
        /// <paramref name="radiusNote"/> follows the refusal of its radius, which quotes the world radius, not the field.</summary>
        public static void Log(IReadOnlyList<ValidationError> errors, UnityEngine.Object context, string radiusNote = "")
        {
            foreach (ValidationError e in errors)
            {
                bool radius = radiusNote.Length > 0 && e.Field.EndsWith("." + nameof(RigidSphere.Radius), StringComparison.Ordinal);
                Debug.LogError($"{e.Message} [{context.GetType().Name} on '{context.name}', field {e.Field}{(radius ? " " + radiusNote : "")}]", context);
            }
        }
    }
}
