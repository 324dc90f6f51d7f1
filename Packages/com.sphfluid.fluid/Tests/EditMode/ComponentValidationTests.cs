using System.Collections.Generic;
using System.Text.RegularExpressions;
using NUnit.Framework;
using SphFluid.Runtime;
using SphFluid.Simulation;
using UnityEngine;
using UnityEngine.TestTools;

namespace SphFluid.Tests.EditMode
{
    /// <summary>Inspector values are refused by the engine-free core's validators, with the core's wording.</summary>
    public sealed class ComponentValidationTests
    {
        readonly List<GameObject> _objects = new List<GameObject>();

        [TearDown]
        public void DestroyObjects()
        {
            foreach (GameObject o in _objects)
                if (o != null) Object.DestroyImmediate(o);
            _objects.Clear();
        }

        T Add<T>(string objectName) where T : Component
        {
            var o = new GameObject(objectName);
            _objects.Add(o);
            return o.AddComponent<T>();
        }

        static string Messages(IReadOnlyList<ValidationError> errors)
        {
            var lines = new List<string>();
            foreach (ValidationError e in errors) lines.Add(e.Message);
            return string.Join("\n", lines);
        }

        [Test]
        public void DefaultsAreValid()
        {
            Assert.That(Messages(Add<Fluid>("Fluid").ValidationErrors()), Is.Empty);
            Assert.That(Messages(Add<SpawnBox>("Water").ValidationErrors()), Is.Empty);
            Assert.That(Messages(Add<FluidContainer>("Tank").ValidationErrors()), Is.Empty);
            Assert.That(Messages(Add<SphereObstacle>("Ball").ValidationErrors()), Is.Empty);
        }

        [Test]
        public void SpawnBoxRefusesNegativeRestDensityNamingBoxFieldAndRange()
        {
            SpawnBox box = Add<SpawnBox>("Water");
            box.Spawn.Phase.RestDensity = -3f;
            IReadOnlyList<ValidationError> errors = box.ValidationErrors();
            Assert.That(errors.Count, Is.EqualTo(1), Messages(errors));
            Assert.That(errors[0].Message, Is.EqualTo("SpawnBox 'Water': RestDensity must be in [1, 100000] kg/m^3 (was -3)"));
            Assert.That(errors[0].Field, Does.EndWith("Phase.RestDensity"));
        }

        [Test]
        public void SpawnBoxRefusesEveryPhaseFieldOutOfRange()
        {
            SpawnBox box = Add<SpawnBox>("Oil");
            box.Spawn.Phase.Viscosity = -1f;
            box.Spawn.Phase.SurfaceTension = 11f;
            box.Spawn.Phase.FresnelF0 = 2f;
            box.Spawn.Phase.Absorption = -0.5f;
            box.Spawn.Jitter = 0.7f;
            box.Spawn.Phase.Name = "";
            string messages = Messages(box.ValidationErrors());
            Assert.That(messages, Does.Contain("Viscosity must be in [0, 1000] Pa s (was -1)"));
            Assert.That(messages, Does.Contain("SurfaceTension must be in [0, 10] N/m (was 11)"));
            Assert.That(messages, Does.Contain("FresnelF0 must be in [0, 1]"));
            Assert.That(messages, Does.Contain("Absorption must be in [0, 10000] 1/m (was -0.5)"));
            Assert.That(messages, Does.Contain("Jitter must be in [0, 0.5]"));
            Assert.That(messages, Does.Contain("Name must be non-empty"));
        }

        [Test]
        public void SpawnBoxOnValidateLogsTheCoreMessage()
        {
            SpawnBox box = Add<SpawnBox>("Water");
            box.Spawn.Phase.Viscosity = -1f;
            LogAssert.Expect(LogType.Error, new Regex(@"SpawnBox 'Water': Viscosity must be in \[0, 1000\] Pa s \(was -1\)"));
            SerializedFields.InvokeOnValidate(box);
        }

        [Test]
        public void SpawnBoxDescribesItsTransformAndLinearColour()
        {
            SpawnBox box = Add<SpawnBox>("Water");
            box.transform.position = new Vector3(0.1f, 0.2f, 0.3f);
            box.transform.localScale = new Vector3(0.2f, -0.1f, 0.4f);
            // As the inspector's colour drawer stores a pick: sRGB in, linear kept.
            box.Spawn.Phase.Color = new Color(0.5f, 0.5f, 0.5f, 0.25f).ToLinearSetting();
            FluidBlock d = box.Describe();
            Assert.That(d.Name, Is.EqualTo("Water"));
            Assert.That(d.Center.Y, Is.EqualTo(0.2f).Within(1e-6f));
            Assert.That(d.Size.Y, Is.EqualTo(0.1f).Within(1e-6f), "negative scale is a mirrored box of the same size");
            Assert.That(d.Phase.Color.r, Is.EqualTo(new Color(0.5f, 0.5f, 0.5f).linear.r).Within(1e-6f));
            Assert.That(d.Phase.Color.a, Is.EqualTo(0.25f).Within(1e-6f));
            Assert.That(box.Color.r, Is.EqualTo(0.5f).Within(1e-4f), "the inspector shows the pick again");
            d.Phase.Viscosity = 7f;
            Assert.That(box.Spawn.Phase.Viscosity, Is.Not.EqualTo(7f), "the description is a copy");
        }

        [Test]
        public void FluidRefusesSettingsThroughTheCore()
        {
            Fluid simulator = Add<Fluid>("Fluid");
            simulator.Settings.SmoothingRadius = 0.2f;
            simulator.Settings.MaxSubsteps = 0;
            simulator.Settings.Gamma = 12f;
            string messages = Messages(simulator.ValidationErrors());
            Assert.That(messages, Does.Contain("FluidSettings: SmoothingRadius must be in"));
            Assert.That(messages, Does.Contain("MaxSubsteps must be in [1, 1000] (was 0)"));
            Assert.That(messages, Does.Contain("Gamma must be in [1, 10] (was 12)"));
        }

        [Test]
        public void UnitySerializesEveryDeclaredSetting()
        {
            // A setting of a type Unity cannot serialize (System.Numerics.Vector3, a property) would silently reset
            // to its default in every scene.
            var serialized = new UnityEditor.SerializedObject(Add<Fluid>("Fluid"));
            foreach (DeclaredSetting declared in SettingRules.Declared(typeof(FluidSettings)))
                Assert.That(serialized.FindProperty("settings." + declared.Field.Name), Is.Not.Null, declared.Field.Name);
        }

        [Test]
        public void UnitySerializesEveryDeclaredSpawnBoxValue()
        {
            var serialized = new UnityEditor.SerializedObject(Add<SpawnBox>("Water"));
            foreach (SettingPath declared in SettingRules.DeclaredPaths(typeof(FluidBlock)))
                Assert.That(serialized.FindProperty("spawn." + declared.Path), Is.Not.Null, declared.Path);
        }

        [Test]
        public void SphereObstacleRefusesZeroRadius()
        {
            SphereObstacle sphere = Add<SphereObstacle>("Ball");
            SerializedFields.Set(sphere, "radius", 0f);
            Assert.That(Messages(sphere.ValidationErrors()), Does.Contain("Radius must be in (0, 1000] m (was 0)"));
        }

        [Test]
        public void SphereObstacleRadiusScalesLikeASphereCollider()
        {
            SphereObstacle sphere = Add<SphereObstacle>("Ball");
            sphere.transform.localScale = new Vector3(0.1f, 0.2f, 0.1f);
            Assert.That(sphere.WorldRadius, Is.EqualTo(0.1f).Within(1e-6f));
        }

        [Test]
        public void ContainerRefusesAFlatBox()
        {
            FluidContainer container = Add<FluidContainer>("Tank");
            container.transform.localScale = new Vector3(1f, 0f, 1f);
            Assert.That(Messages(container.ValidationErrors()), Does.Contain("Container: each Size component must be in"));
        }
    }
}
