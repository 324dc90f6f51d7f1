using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Core.Simulation
{
    /// <summary>A sphere's radius is refused as the world radius, the field times its scale, which the field alone does not
    /// show: the note that the Console and the scene reader print beside the refusal says how the two relate.</summary>
    public sealed class RigidSphereTests
    {
        [Test]
        public void TheNoteSaysTheFieldTimesTheLargestScale()
        {
            Assert.That(RigidSphere.WorldRadiusNote(50f, 0.09f, new string[0]), Is.EqualTo(
                "(in the world: 50 times 0.09, the largest component of its scale in the world)"));
        }

        [Test]
        public void TheNoteNamesTheGameObjectsAboveWhoseScalesTakePart()
        {
            Assert.That(RigidSphere.WorldRadiusNote(100000f, 0.072f, new[] { "Container", "Rig" }), Is.EqualTo(
                "(in the world: 100000 times 0.072, the largest component of its scale in the world, " +
                "which the scales of 'Container', 'Rig' take part in)"));
        }

        [Test]
        public void AtAScaleOfOneTheFieldIsTheWorldRadiusAndThereIsNoNote()
        {
            Assert.That(RigidSphere.WorldRadiusNote(1001f, 1f, new[] { "Container" }), Is.Empty);
        }
    }
}
