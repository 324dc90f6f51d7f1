using System.Collections.Generic;
using System.Reflection;
using NUnit.Framework;
using SphFluid.Runtime;
using UnityEngine;

namespace SphFluid.Tests.PlayMode
{
    /// <summary>
    /// The PlayMode tests' scene, built in code: a 0.3 m tank with a 0.12 m cube of water (6 x 6 x 6 particles)
    /// and, optionally, a sphere. No readout and no controls: only the fluid's own work runs each frame.
    /// </summary>
    internal sealed class TestTank
    {
        public const float Spacing = 0.02f;
        public const int ExpectedParticles = 6 * 6 * 6;
        public static readonly Vector3 ContainerCentre = new Vector3(0f, 0.15f, 0f);
        public static readonly Vector3 ContainerSize = new Vector3(0.3f, 0.3f, 0.3f);

        readonly List<GameObject> _objects = new List<GameObject>();

        /// <summary>Skips (inconclusive) where there are no compute shaders, e.g. under -nographics.</summary>
        public static void RequireGpu()
        {
            Assume.That(SystemInfo.supportsComputeShaders, Is.True, "needs a graphics device with compute shaders (run without -nographics)");
        }

        static void Set(object component, string field, object value)
        {
            FieldInfo info = component.GetType().GetField(field, BindingFlags.Instance | BindingFlags.NonPublic);
            Assert.That(info, Is.Not.Null, $"{component.GetType().Name} has no serialized field '{field}'");
            info.SetValue(component, value);
        }

        GameObject Create(string objectName, Vector3 position, Vector3 scale)
        {
            var o = new GameObject(objectName);
            o.transform.position = position;
            o.transform.localScale = scale;
            _objects.Add(o);
            return o;
        }

        /// <summary>Builds the tank and starts its simulator (wired before its OnEnable runs).</summary>
        public Fluid CreateFluid(bool withSphere)
        {
            FluidContainer container = Create("Tank", ContainerCentre, ContainerSize).AddComponent<FluidContainer>();
            Create("Water", new Vector3(0f, 0.1f, 0f), new Vector3(0.12f, 0.12f, 0.12f)).AddComponent<SpawnBox>();
            if (withSphere)
                Create("Ball", new Vector3(0.08f, 0.22f, 0f), new Vector3(0.08f, 0.08f, 0.08f)).AddComponent<SphereObstacle>();

            GameObject fluid = Create("Fluid", Vector3.zero, Vector3.one);
            fluid.SetActive(false);
            Fluid simulator = fluid.AddComponent<Fluid>();
            Set(simulator, "container", container);
            simulator.Settings.ParticleSpacing = Spacing;
            fluid.SetActive(true);
            return simulator;
        }

        /// <summary>The tank with its sphere, both set moving from the first frame: the container turns slowly about z
        /// (<see cref="ContainerSpinner"/>) and the sphere swings 0.1 m along x (<see cref="SphereDriver"/>).</summary>
        public Fluid CreateDrivenFluid()
        {
            Fluid simulator = CreateFluid(true);
            ContainerSpinner spinner = Find("Tank").AddComponent<ContainerSpinner>();
            spinner.Spin.AngularSpeed = 20f;
            spinner.Spin.StartDelay = 0f;
            SphereDriver driver = Find("Ball").AddComponent<SphereDriver>();
            driver.Drive.Travel = new System.Numerics.Vector3(-0.1f, 0f, 0f);
            driver.Drive.Period = 2f;
            driver.Drive.StartDelay = 0f;
            return simulator;
        }

        GameObject Find(string objectName)
        {
            GameObject found = _objects.Find(o => o != null && o.name == objectName);
            Assert.That(found, Is.Not.Null, $"the tank has no object '{objectName}'");
            return found;
        }

        /// <summary>Destroys every object this tank created (call from [TearDown]).</summary>
        public void Destroy()
        {
            foreach (GameObject o in _objects)
                if (o != null) Object.DestroyImmediate(o);
            _objects.Clear();
        }
    }
}
