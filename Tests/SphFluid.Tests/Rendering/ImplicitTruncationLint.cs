using System.Collections.Generic;
using System.Text.RegularExpressions;

namespace SphFluid.Tests.Rendering
{
    /// <summary>
    /// Finds implicit vector truncations (float4 assigned to float3, float2 to float, ...) in glslang's
    /// intermediate tree (<c>glslangValidator -i</c>). glslang accepts them silently, FXC warns (X3206
    /// "implicit truncation of vector type") and some Unity platforms' compilers reject them, so the project
    /// writes .xyz explicitly. In the tree a truncation is a <c>Construct vecN</c>/<c>Construct float</c> node
    /// with a single, wider vector operand; an explicit (float3) cast looks the same and is reported too.
    /// </summary>
    public static class ImplicitTruncationLint
    {
        static readonly Regex NodeLine = new Regex("^(\\d+):(\\d+|\\?)( +)(.*)$");
        static readonly Regex ConstructNode = new Regex("^Construct (?:[iub]?vec(\\d)|float|int|uint|bool) \\(");
        static readonly Regex VectorType = new Regex("(\\d)-component vector of \\w+\\)\\s*$");

        /// <summary>One "line N: ..." entry per truncation in the unlinked tree of one stage.</summary>
        public static IReadOnlyList<string> Find(string intermediateTree)
        {
            var problems = new List<string>();
            string[] lines = intermediateTree.Replace("\r\n", "\n").Split('\n');
            var nodes = new List<(string line, int indent, string text)>();
            foreach (string raw in lines)
            {
                if (raw.StartsWith("Linked ", System.StringComparison.Ordinal)) break; // the linked tree repeats the same nodes
                var m = NodeLine.Match(raw);
                if (m.Success) nodes.Add((m.Groups[2].Value, m.Groups[3].Value.Length, m.Groups[4].Value));
            }
            for (int i = 0; i < nodes.Count; i++)
            {
                var construct = ConstructNode.Match(nodes[i].text);
                if (!construct.Success) continue;
                int width = construct.Groups[1].Success ? int.Parse(construct.Groups[1].Value) : 1;
                var children = new List<string>();
                for (int k = i + 1; k < nodes.Count && nodes[k].indent > nodes[i].indent; k++)
                    if (nodes[k].indent == nodes[i].indent + 2) children.Add(nodes[k].text);
                if (children.Count != 1) continue;
                var operand = VectorType.Match(children[0]);
                if (operand.Success && int.Parse(operand.Groups[1].Value) > width)
                    problems.Add("line " + nodes[i].line + ": " + operand.Groups[1].Value + "-component vector implicitly truncated to "
                        + width + " component" + (width == 1 ? "" : "s") + " (write the swizzle, e.g. .xyz)");
            }
            return problems;
        }
    }
}
