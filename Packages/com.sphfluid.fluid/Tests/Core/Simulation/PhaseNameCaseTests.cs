using System.Linq;
using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Core.Simulation
{
    /// <summary>"Water" and "water" were two phases whose diagnostics columns had one name; such a scene is refused.</summary>
    public sealed class PhaseNameCaseTests
    {
        [Test]
        public void NamesThatDifferOnlyByCaseAreRefusedNamingBothBoxesAndTheRule()
        {
            var scene = SimulationTestScenes.OilOnWater();
            scene.SpawnBoxes[1].Name = "Top";
            scene.SpawnBoxes[1].Phase.Name = "water";
            var errors = scene.Validate();
            Assert.That(errors.Select(e => e.Message).ToArray(), Has.Member(
                "SpawnBox 'Top': phase name 'water' differs from phase 'Water' of SpawnBox 'Water' only by letter case; " +
                "phase names must differ by more than case (use the same name for the same liquid)"));
            Assert.That(errors.Select(e => e.Field).ToArray(), Has.Member("SpawnBoxes[1].Phase.Name"));
        }

        [Test]
        public void TheSameNameInTwoBoxesIsOnePhaseAndAccepted()
        {
            var scene = SimulationTestScenes.OilOnWater();
            scene.SpawnBoxes[1].Phase = SimulationTestScenes.Water();
            Assert.That(scene.Validate(), Is.Empty);
            Assert.That(scene.Phases().Count, Is.EqualTo(1));
        }

        [Test]
        public void NamesThatDifferByMoreThanCaseAreAccepted()
        {
            var scene = SimulationTestScenes.OilOnWater();
            scene.SpawnBoxes[1].Phase.Name = "Waters";
            Assert.That(scene.Validate(), Is.Empty);
        }
    }
}
