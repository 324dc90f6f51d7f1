using System;
using System.Collections.Generic;

namespace SphFluid.Simulation
{
    /// <summary>The container and the obstacles as the scene moves them: validated, copied into the simulation's own
    /// description without garbage when only their placement changed, and made again on the GPU when their shape did.</summary>
    public sealed partial class FluidSimulation
    {
        /// <summary>Moves (or resizes) the container; its transform is uploaded before the next step.
        /// A moving container is pushed as a Unity Transform reads after it moved: where it stands at the end of the
        /// next <see cref="Step"/>, with the velocity and angular velocity that brought it there. Its walls start that
        /// step the step's time behind it, where the step before left them, and sweep up to it through the sub-steps.
        /// Callers push the container every frame, so an unchanged one returns before anything is copied or
        /// validated (it was validated when it was set).</summary>
        public void UpdateContainer(ContainerDescription container)
        {
            ThrowIfDisposed();
            if (container == null) throw new ArgumentNullException(nameof(container));
            var old = _scene.Container;
            if (old.SamePlacement(container) && old.Velocity == container.Velocity && old.AngularVelocity == container.AngularVelocity
                && old.Friction == container.Friction)
                return;
            // The container's rules read only the settings (its least size), so the probe holds nothing else;
            // probe and list are kept because a turning container changes every frame.
            _containerProbe.Settings = _scene.Settings;
            _containerProbe.Container = container;
            _containerErrors.Clear();
            _containerProbe.ValidateContainer(_containerErrors);
            _containerProbe.Container = null;
            if (_containerErrors.Count > 0) throw new ArgumentException(Join(_containerErrors));
            if (old.Size != container.Size && ResizedWallsProblem(old, container) is string tooMany)
                throw new ArgumentException("Container: Size " + ValidationRules.Format(container.Size) + " m: its " + tooMany);
            if (old.Size == container.Size && old.Friction == container.Friction)
            {
                // Only placement and motion differ: copied into the simulation's own description, not cloned.
                old.Position = container.Position;
                old.Rotation = container.Rotation;
                old.Velocity = container.Velocity;
                old.AngularVelocity = container.AngularVelocity;
                _containerChanged = true;
                return;
            }
            _scene.Container = container.Clone();
            _containerChanged = true;
            if (old.Size != container.Size)
            {
                RebuildGrid();
                CreateBoundary();
            }
            if (old.Friction != container.Friction)
                WriteConstants();
        }

        /// <summary>Whether the device holds the walls of the container resized (<see cref="DeviceCapacity"/>), asked before
        /// anything of the old container is replaced.</summary>
        string ResizedWallsProblem(ContainerDescription old, ContainerDescription resized)
        {
            var s = _scene.Settings;
            long obstacleWalls = _boundaryCount - BoundarySampling.ContainerCount(old.Size, s.ParticleSpacing, s.SmoothingRadius);
            return DeviceCapacity.Problem(0, BoundarySampling.ContainerCount(resized.Size, s.ParticleSpacing, s.SmoothingRadius) + obstacleWalls, _device);
        }

        /// <summary>Replaces the sphere obstacles (any count up to <see cref="FluidSceneDescription.MaxObstacles"/>).
        /// A moving sphere is pushed as the container is (<see cref="UpdateContainer"/>): its centre at the end of the
        /// next step, and the velocity that brought it there.
        /// Callers push the obstacles every frame, so the same spheres as now return before anything is copied,
        /// validated or uploaded.</summary>
        public void UpdateObstacles(IReadOnlyList<RigidSphere> obstacles)
        {
            ThrowIfDisposed();
            int count = obstacles == null ? 0 : obstacles.Count;
            var current = _scene.Obstacles;
            bool same = current.Count == count;
            for (int i = 0; same && i < count; i++)
            {
                RigidSphere now = current[i], next = obstacles[i];
                same = next != null && now.Name == next.Name && now.Center == next.Center && now.Radius == next.Radius
                       && now.Velocity == next.Velocity;
            }
            if (same) return;
            if (MovedOnly(obstacles, count)) return;

            var list = new List<RigidSphere>(count);
            for (int i = 0; i < count; i++) list.Add(obstacles[i]?.Clone());
            // The obstacles' rules read nothing else of the scene, so the probe holds only them.
            var probe = new FluidSceneDescription { Obstacles = list };
            var errors = new List<string>();
            foreach (var e in probe.Validate())
                if (e.Field.StartsWith("Obstacles", StringComparison.Ordinal)) errors.Add(e.Message);
            if (errors.Count > 0) throw new ArgumentException(string.Join("\n", errors));
            bool reshaped = !SameShapes(_scene.Obstacles, list);
            _scene.Obstacles = list;
            UploadObstacles();
            if (reshaped) CreateBoundary();
        }

        /// <summary>The same spheres (count, names, radii) at new centres or speeds, as a driven sphere is every frame:
        /// checked with the sphere rules under names made once, and copied into the simulation's own descriptions, so
        /// that nothing is allocated. False when more than that changed (the caller then replaces the list).</summary>
        bool MovedOnly(IReadOnlyList<RigidSphere> obstacles, int count)
        {
            var current = _scene.Obstacles;
            if (current.Count != count) return false;
            for (int i = 0; i < count; i++)
            {
                RigidSphere now = current[i], next = obstacles[i];
                if (next == null || now.Name != next.Name || now.Radius != next.Radius) return false;
            }
            if (_obstacleNamesFor != current)
            {
                _obstacleNames = new string[count, 2];
                for (int i = 0; i < count; i++)
                {
                    _obstacleNames[i, 0] = FluidSceneDescription.ObstacleOwner(current[i]);
                    _obstacleNames[i, 1] = FluidSceneDescription.ObstaclePath(i);
                }
                _obstacleNamesFor = current;
            }
            _obstacleErrors.Clear();
            for (int i = 0; i < count; i++)
                FluidSceneDescription.ValidateObstacle(_obstacleErrors, obstacles[i], _obstacleNames[i, 0], _obstacleNames[i, 1]);
            if (_obstacleErrors.Count > 0) throw new ArgumentException(Join(_obstacleErrors));
            for (int i = 0; i < count; i++)
            {
                current[i].Center = obstacles[i].Center;
                current[i].Velocity = obstacles[i].Velocity;
            }
            UploadObstacles();
            return true;
        }

        /// <summary>Same count and radii: the boundary particles only move with the spheres.</summary>
        static bool SameShapes(IReadOnlyList<RigidSphere> a, IReadOnlyList<RigidSphere> b)
        {
            int na = a == null ? 0 : a.Count, nb = b == null ? 0 : b.Count;
            if (na != nb) return false;
            for (int i = 0; i < na; i++)
                if (a[i].Radius != b[i].Radius) return false;
            return true;
        }

        void UploadObstacles()
        {
            var rows = _obstacleRows;
            int count = _scene.Obstacles == null ? 0 : _scene.Obstacles.Count;
            for (int i = 0; i < count; i++)
                rows[i] = new Obstacle(_scene.Obstacles[i]);
            if (count == 0) rows[0] = default;
            _buffers.Obstacles.SetData(rows, 0, 0, Math.Max(count, 1));
            _constants[0].ObstacleCount = (uint)count;
            _constantsChanged = true;
            _boundaryMoved = true;
            _obstaclesMoved = true;
        }

        /// <summary>The spheres moved by their velocities for <paramref name="elapsed"/> seconds from this frame's centres
        /// (negative: before they got there), recorded in order with the sub-steps' dispatches (<see cref="AdvanceWalls"/>).</summary>
        void WriteObstacles(float elapsed)
        {
            int count = _scene.Obstacles == null ? 0 : _scene.Obstacles.Count;
            if (count == 0) return;
            var rows = _obstacleRows;
            for (int i = 0; i < count; i++)
            {
                var sphere = _scene.Obstacles[i];
                rows[i] = new Obstacle(sphere) { Center = sphere.Center + sphere.Velocity * elapsed };
            }
            _device.UpdateBuffer(_buffers.Obstacles, rows);
            _boundaryMoved = true;
        }

        static string Join(List<ValidationError> errors)
        {
            var messages = new string[errors.Count];
            for (int i = 0; i < messages.Length; i++) messages[i] = errors[i].Message;
            return string.Join("\n", messages);
        }
    }
}
