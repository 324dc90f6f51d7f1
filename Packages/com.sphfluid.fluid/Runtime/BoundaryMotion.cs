using System.Collections.Generic;
using SphFluid.Simulation;
using Unity.Mathematics;
using UnityEngine;

namespace SphFluid.Runtime
{
    /// <summary>
    /// The container's and the spheres' motion as the simulation takes it: each goes where its Transform stands now,
    /// with the velocity that brought it there over the simulated frame, and the simulation sweeps it there from where
    /// the last frame left it. Keeps the last frame's poses, and refills its descriptions in place rather than making
    /// new ones: the per-frame push makes no garbage (the simulation copies what changed).
    /// </summary>
    sealed class BoundaryMotion
    {
        /// <summary>Fastest wall or sphere motion passed on, m/s and rad/s.</summary>
        const float MaxWallSpeed = 50f, MaxWallSpin = 50f;

        readonly FluidContainer _container;
        readonly ContainerDescription _containerDescription = new ContainerDescription();
        Vector3 _containerPosition;
        Quaternion _containerRotation;

        readonly List<SphereObstacle> _obstacles;
        readonly List<Vector3> _obstaclePositions = new List<Vector3>();
        readonly List<RigidSphere> _obstacleRows = new List<RigidSphere>();
        readonly List<RigidSphere> _obstacleDescriptions = new List<RigidSphere>();

        /// <summary>Follows <paramref name="container"/> and <paramref name="obstacles"/> from where they stand now.</summary>
        public BoundaryMotion(FluidContainer container, List<SphereObstacle> obstacles)
        {
            _container = container;
            _containerPosition = container.transform.position;
            _containerRotation = container.transform.rotation;
            _obstacles = obstacles;
            foreach (SphereObstacle sphere in obstacles)
            {
                _obstaclePositions.Add(sphere.transform.position);
                _obstacleRows.Add(sphere.Describe(Vector3.zero)); // its Name is read here, once
            }
        }

        /// <summary>Passes the walls' and spheres' poses to <paramref name="simulation"/>, moved over
        /// <paramref name="seconds"/> (0: put there at rest). Throws ArgumentException for a pose the simulation
        /// refuses.</summary>
        public void Push(FluidSimulation simulation, float seconds)
        {
            PushContainer(simulation, seconds);
            PushObstacles(simulation, seconds);
        }

        void PushContainer(FluidSimulation simulation, float seconds)
        {
            if (_container == null) return; // destroyed while running: the walls stay where it left them
            Transform t = _container.transform;
            Vector3 position = t.position;
            Quaternion rotation = t.rotation;
            ContainerDescription description = _container.DescribeInto(_containerDescription);
            description.Velocity = System.Numerics.Vector3.Zero;
            description.AngularVelocity = System.Numerics.Vector3.Zero;
            if (seconds > 0f)
            {
                // A teleport (editing the Transform) is not a motion the walls should fling fluid with.
                description.Velocity = Vector3.ClampMagnitude((position - _containerPosition) / seconds, MaxWallSpeed).ToNumerics();
                description.AngularVelocity = Vector3.ClampMagnitude(AngularVelocity(_containerRotation, rotation) / seconds, MaxWallSpin).ToNumerics();
            }
            _containerPosition = position;
            _containerRotation = rotation;
            simulation.UpdateContainer(description);
        }

        /// <summary>Rotation from <paramref name="from"/> to <paramref name="to"/> as axis times angle, rad (shortest way).</summary>
        static Vector3 AngularVelocity(Quaternion from, Quaternion to)
        {
            // The quaternion logarithm of the frame-to-frame turn is half its rotation vector; q and -q are the same
            // turn, so the short way round is the one with w >= 0.
            quaternion delta = math.mul(to, math.inverse(from));
            if (delta.value.w < 0f) delta.value = -delta.value;
            float3 rotation = 2f * math.log(delta).value.xyz;
            return math.all(math.isfinite(rotation)) ? (Vector3)rotation : Vector3.zero; // no turn: log is 0/0
        }

        void PushObstacles(FluidSimulation simulation, float seconds)
        {
            if (_obstacles.Count == 0) return;
            _obstacleDescriptions.Clear();
            for (int i = 0; i < _obstacles.Count; i++)
            {
                SphereObstacle sphere = _obstacles[i];
                if (sphere == null) continue; // destroyed while running: it simply stops pushing
                Vector3 position = sphere.transform.position;
                Vector3 velocity = seconds > 0f ? Vector3.ClampMagnitude((position - _obstaclePositions[i]) / seconds, MaxWallSpeed) : Vector3.zero;
                _obstaclePositions[i] = position;
                _obstacleDescriptions.Add(sphere.DescribeInto(_obstacleRows[i], velocity));
            }
            simulation.UpdateObstacles(_obstacleDescriptions);
        }
    }
}
