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
            Assert.That(Messages(Add<FluidSimulator>("Fluid").ValidationErrors()), Is.Empty);
            Assert.That(Messages(Add<SpawnBox>("Water").ValidationErrors()), Is.Empty);
            Assert.That(Messages(Add<FluidContainer>("Tank").ValidationErrors()), Is.Empty);
            Assert.That(Messages(Add<SphereObstacle>("Ball").ValidationErrors()), Is.Empty);
        }

        [Test]
        public void SpawnBoxRefusesNegativeRestDensityNamingBoxFieldAndRange()
        {
            SpawnBox box = Add<SpawnBox>("Water");
            SerializedFields.Set(box, "restDensity", -3f);
            IReadOnlyList<ValidationError> errors = box.ValidationErrors();
            Assert.That(errors.Count, Is.EqualTo(1), Messages(errors));
            Assert.That(errors[0].Message, Is.EqualTo("SpawnBox 'Water': RestDensity must be in [1, 100000] kg/m^3 (was -3)"));
            Assert.That(errors[0].Field, Does.EndWith("Phase.RestDensity"));
        }

        [Test]
        public void SpawnBoxRefusesEveryPhaseFieldOutOfRange()
        {
            SpawnBox box = Add<SpawnBox>("Oil");
            SerializedFields.Set(box, "viscosity", -1f);
            SerializedFields.Set(box, "surfaceTension", 11f);
            SerializedFields.Set(box, "fresnelF0", 2f);
            SerializedFields.Set(box, "absorption", -0.5f);
            SerializedFields.Set(box, "jitter", 0.7f);
            SerializedFields.Set(box, "phaseName", "");
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
            SerializedFields.Set(box, "viscosity", -1f);
            LogAssert.Expect(LogType.Error, new Regex(@"SpawnBox 'Water': Viscosity must be in \[0, 1000\] Pa s \(was -1\)"));
            SerializedFields.InvokeOnValidate(box);
        }

        [Test]
        public void SpawnBoxDescribesItsTransformAndLinearColour()
        {
            SpawnBox box = Add<SpawnBox>("Water");
            box.transform.position = new Vector3(0.1f, 0.2f, 0.3f);
            box.transform.localScale = new Vector3(0.2f, -0.1f, 0.4f);
            SerializedFields.Set(box, "color", new Color(0.5f, 0.5f, 0.5f, 0.25f));
            SpawnBoxDescription d = box.Describe();
            Assert.That(d.Name, Is.EqualTo("Water"));
            Assert.That(d.Center.Y, Is.EqualTo(0.2f).Within(1e-6f));
            Assert.That(d.Size.Y, Is.EqualTo(0.1f).Within(1e-6f), "negative scale is a mirrored box of the same size");
            Assert.That(d.Phase.Color.X, Is.EqualTo(new Color(0.5f, 0.5f, 0.5f).linear.r).Within(1e-6f));
            Assert.That(d.Phase.Color.W, Is.EqualTo(0.25f).Within(1e-6f));
        }

        [Test]
        public void FluidSimulatorRefusesSettingsThroughTheCore()
        {
            FluidSimulator simulator = Add<FluidSimulator>("Fluid");
            SerializedFields.Set(simulator, "smoothingRadius", 0.2f);
            SerializedFields.Set(simulator, "maxSubsteps", 0);
            SerializedFields.Set(simulator, "gamma", 12f);
            string messages = Messages(simulator.ValidationErrors());
            Assert.That(messages, Does.Contain("FluidSettings: SmoothingRadius must be in"));
            Assert.That(messages, Does.Contain("MaxSubsteps must be in [1, 1000] (was 0)"));
            Assert.That(messages, Does.Contain("Gamma must be in [1, 10] (was 12)"));
        }

        [Test]
        public void FluidSimulatorSettingsMirrorFluidSettingsDefaults()
        {
            FluidSettings core = new FluidSettings();
            FluidSettings mirrored = Add<FluidSimulator>("Fluid").DescribeSettings();
            Assert.That(mirrored.ParticleSpacing, Is.EqualTo(core.ParticleSpacing));
            Assert.That(mirrored.SmoothingRadius, Is.EqualTo(core.SmoothingRadius));
            Assert.That(mirrored.Stiffness, Is.EqualTo(core.Stiffness));
            Assert.That(mirrored.Gamma, Is.EqualTo(core.Gamma));
            Assert.That(mirrored.Gravity, Is.EqualTo(core.Gravity));
            Assert.That(mirrored.XsphEpsilon, Is.EqualTo(core.XsphEpsilon));
            Assert.That(mirrored.ArtificialViscosity, Is.EqualTo(core.ArtificialViscosity));
            Assert.That(mirrored.ParticleShifting, Is.EqualTo(core.ParticleShifting));
            Assert.That(mirrored.VelocityDamping, Is.EqualTo(core.VelocityDamping));
            Assert.That(mirrored.CflNumber, Is.EqualTo(core.CflNumber));
            Assert.That(mirrored.MaxSubsteps, Is.EqualTo(core.MaxSubsteps));
            Assert.That(mirrored.MaxTimeStep, Is.EqualTo(core.MaxTimeStep));
            Assert.That(mirrored.MaxParticles, Is.EqualTo(core.MaxParticles));
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
