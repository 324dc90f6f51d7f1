using System.Collections.Generic;
using NUnit.Framework;
using SphFluid.Runtime;
using SphFluid.Simulation;
using UnityEngine;
using NVector3 = System.Numerics.Vector3;

namespace SphFluid.Tests.EditMode
{
    /// <summary>The simulator refills one description per container and sphere every frame: the refill must
    /// write what <c>Describe</c> writes, into the object it is given, and keep what it is told to keep.</summary>
    public sealed class ComponentDescriptionTests
    {
        readonly List<GameObject> _objects = new List<GameObject>();

        [TearDown]
        public void DestroyObjects()
        {
            foreach (GameObject o in _objects)
                if (o != null) Object.DestroyImmediate(o);
            _objects.Clear();
        }

        T Add<T>(string objectName, Vector3 position, Vector3 scale) where T : Component
        {
            var o = new GameObject(objectName);
            o.transform.SetPositionAndRotation(position, Quaternion.Euler(0f, 0f, 30f));
            o.transform.localScale = scale;
            _objects.Add(o);
            return o.AddComponent<T>();
        }

        [Test]
        public void ContainerRefill_WritesThePlacementIntoTheGivenObject_AndKeepsItsVelocities()
        {
            FluidContainer tank = Add<FluidContainer>("Tank", new Vector3(1f, 2f, 3f), new Vector3(0.4f, -0.3f, 0.2f));
            var reused = new ContainerDescription { Velocity = new NVector3(0.5f, 0f, 0f), AngularVelocity = new NVector3(0f, 0f, 2f) };

            ContainerDescription filled = tank.DescribeInto(reused);
            ContainerDescription fresh = tank.Describe();

            Assert.That(filled, Is.SameAs(reused));
            Assert.That(filled.Position, Is.EqualTo(new NVector3(1f, 2f, 3f)));
            Assert.That(filled.Size, Is.EqualTo(new NVector3(0.4f, 0.3f, 0.2f)), "the size is the absolute lossy scale");
            Assert.That(filled.SamePlacement(fresh), Is.True, "the refill and a fresh description agree");
            Assert.That(filled.Velocity, Is.EqualTo(new NVector3(0.5f, 0f, 0f)), "velocities are the simulator's to set");
            Assert.That(filled.AngularVelocity, Is.EqualTo(new NVector3(0f, 0f, 2f)));
        }

        [Test]
        public void SphereRefill_WritesCentreRadiusAndVelocity_AndKeepsTheName()
        {
            SphereObstacle ball = Add<SphereObstacle>("Ball", new Vector3(0.1f, 0.2f, 0.3f), new Vector3(0.08f, 0.05f, 0.02f));
            var reused = new RigidSphere { Name = "Ball" };

            RigidSphere filled = ball.DescribeInto(reused, new Vector3(0f, -1f, 0f));

            Assert.That(filled, Is.SameAs(reused));
            Assert.That(filled.Name, Is.EqualTo("Ball"));
            Assert.That(filled.Center, Is.EqualTo(new NVector3(0.1f, 0.2f, 0.3f)));
            Assert.That(filled.Radius, Is.EqualTo(0.04f).Within(1e-7f), "radius 0.5 times the largest scale, 0.08");
            Assert.That(filled.Velocity, Is.EqualTo(new NVector3(0f, -1f, 0f)));
            Assert.That(ball.Describe(Vector3.zero).Name, Is.EqualTo("Ball"), "Describe still names the sphere");
        }
    }
}
