using System.IO;
using System.Linq;
using System.Text;
using NUnit.Framework;
using SphFluid.Tests.Runner;
using SphFluid.UnityFiles.Scenes;

namespace SphFluid.Tests.Integrity
{
    /// <summary>Parent cycles are found once each, in linear time, and no walk up the hierarchy loops on them.</summary>
    public sealed class ParentCycleTests
    {
        /// <summary>GameObject &amp;(10 i) with Transform &amp;(10 i + 1) one metre above its parent, whose m_Father is the Transform of object <c>fathers[i]</c> (-1: none).</summary>
        static UnityScene Scene(params int[] fathers)
        {
            var text = new StringBuilder("%YAML 1.1\n%TAG !u! tag:unity3d.com,2011:\n");
            for (int i = 0; i < fathers.Length; i++)
            {
                long go = 10L * (i + 1), t = go + 1, father = fathers[i] < 0 ? 0 : 10L * (fathers[i] + 1) + 1;
                text.Append($"--- !u!1 &{go}\nGameObject:\n  m_Component:\n  - component: {{fileID: {t}}}\n  m_Name: O{i}\n  m_IsActive: 1\n");
                text.Append($"--- !u!4 &{t}\nTransform:\n  m_GameObject: {{fileID: {go}}}\n  m_LocalPosition: {{x: 0, y: 1, z: 0}}\n  m_Father: {{fileID: {father}}}\n");
            }
            return UnityScene.Parse(text.ToString(), "Cycles.unity");
        }

        [Test]
        public void A_tree_has_no_cycle()
        {
            var scene = Scene(-1, 0, 1, 1);
            Assert.That(scene.ParentCycles(), Is.Empty);
            Assert.That(scene.FindGameObject("O3").OrFail("O3").HierarchyPath, Is.EqualTo("O0/O1/O3"));
        }

        [Test]
        public void Each_cycle_is_found_once_with_its_members_from_child_to_parent()
        {
            // O0 is its own parent; O1 -> O2 -> O3 -> O1; O4 hangs below the loop but is not part of it.
            var cycles = Scene(0, 2, 3, 1, 2).ParentCycles();

            Assert.That(cycles.Count, Is.EqualTo(2));
            Assert.That(cycles.Select(c => string.Join(",", c.Select(g => g.Name))), Is.EquivalentTo(new[] { "O0", "O1,O2,O3" }));
        }

        [Test]
        public void Walks_up_a_cyclic_hierarchy_end()
        {
            var scene = Scene(1, 2, 0);
            var path = Deadline.Within(10, () => scene.FindGameObject("O0").OrFail("O0").HierarchyPath, "HierarchyPath on a 3-cycle");
            Assert.That(path, Is.EqualTo("O2/O1/O0"));
            Assert.That(scene.FindGameObject("O1").OrFail("O1").SelfAndAncestors.Count(), Is.EqualTo(3));
        }

        [Test]
        public void Twenty_thousand_objects_in_one_loop_are_checked_in_linear_time()
        {
            var fathers = Enumerable.Range(0, 20_000).Select(i => i - 1).ToArray();
            fathers[0] = fathers.Length - 1; // close the chain into one loop
            var scene = Scene(fathers);

            var cycles = Deadline.Within(30, () => scene.ParentCycles(), "ParentCycles on 20 000 objects");

            Assert.That(cycles.Count, Is.EqualTo(1));
            Assert.That(cycles[0].Count, Is.EqualTo(20_000));
        }
    
        [Test]
        public void A_hierarchy_twenty_thousand_deep_composes_its_world_pose_without_recursion()
        {
            var scene = Scene(Enumerable.Range(0, 20_000).Select(i => i - 1).ToArray());

            var world = Deadline.Within(30, () => scene.FindGameObject("O19999").OrFail("O19999").World, "WorldTransformOf 20 000 levels deep");

            Assert.That(world.Position.Y, Is.EqualTo(20_000f), "one metre per level");
        }

        [Test]
        public void The_world_pose_of_an_object_in_a_cycle_is_a_named_error()
        {
            var scene = Scene(1, 0);

            var error = Deadline.Within(10, () => Deadline.Thrown(() => _ = scene.FindGameObject("O0").OrFail("O0").World), "WorldTransformOf on a 2-cycle");

            Assert.That(error, Is.TypeOf<InvalidDataException>());
            Assert.That(error.Message, Is.EqualTo("Cycles.unity: Transform &11 is its own ancestor (a parent cycle through m_Father)"));
        }
    }
}
