using System.IO;
using System.Linq;

namespace SphFluid.Tests.Integrity
{
    /// <summary>Every scene the project ships: the demo's, and the package samples' (imported into other projects as they are).</summary>
    static class ShippedScenes
    {
        public static string[] All()
        {
            string root = GpuTestDevice.RepoRoot;
            var demo = Directory.GetFiles(Path.Combine(root, "Assets", "FluidDemo", "Scenes"), "*.unity");
            string samples = Path.Combine(root, "Packages", "com.sphfluid.fluid", "Samples~");
            var sample = Directory.Exists(samples) ? Directory.GetFiles(samples, "*.unity", SearchOption.AllDirectories) : new string[0];
            return demo.Concat(sample).OrderBy(p => p, System.StringComparer.Ordinal).ToArray();
        }
    }
}
