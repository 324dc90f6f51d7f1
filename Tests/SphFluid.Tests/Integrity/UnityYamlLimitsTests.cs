using System.Diagnostics;
using System.Text;
using NUnit.Framework;
using SphFluid.Tests.Runner;
using SphFluid.UnityFiles.Yaml;

namespace SphFluid.Tests.Integrity
{
    /// <summary>
    /// Hostile or broken text must end in a located error quickly: the parser runs in time linear in the text and
    /// refuses nesting past <see cref="UnityYamlParser.MaxDepth"/>. Each input is generated here, never committed.
    /// </summary>
    public sealed class UnityYamlLimitsTests
    {
        const string Header = "%YAML 1.1\n%TAG !u! tag:unity3d.com,2011:\n--- !u!114 &1\nMonoBehaviour:\n  m_Name: x\n";

        static UnityYamlException ParseError(string text, string path, double seconds, out double elapsed)
        {
            var clock = Stopwatch.StartNew();
            var error = Deadline.Within(seconds, () => Deadline.Thrown(() => UnityYamlFile.Parse(text, path)), "parsing " + path);
            elapsed = clock.Elapsed.TotalSeconds;
            TestContext.Out.WriteLine($"{path}: {text.Length} chars refused in {elapsed:F2} s: {error?.Message}");
            Assert.That(error, Is.TypeOf<UnityYamlException>(), error?.ToString());
            return (UnityYamlException)error;
        }

        [Test]
        public void Flow_collections_nested_thirty_thousand_deep_stop_at_the_depth_limit()
        {
            var line = new StringBuilder("  deep: ");
            for (int i = 0; i < 30000; i++) line.Append("{a: ");
            line.Append('1').Append('}', 30000);
            Assert.That(line.Length, Is.GreaterThan(150000), "a 150 KB line");

            var error = ParseError(Header + line + "\n", "Deep.unity", 30, out _);

            Assert.That(error.Message, Does.StartWith("Deep.unity:6: nested deeper than 64 levels"));
            Assert.That(error.LineNumber, Is.EqualTo(6));
        }

        [Test]
        public void A_two_megabyte_unclosed_brace_is_reported_where_it_opened()
        {
            var text = new StringBuilder(Header).Append("  open: {\n");
            for (int i = 0; text.Length < 2_000_000; i++) text.Append("    key").Append(i).Append(": 1,\n");

            var error = ParseError(text.ToString(), "Brace.unity", 60, out double seconds);

            Assert.That(error.Message, Does.StartWith("Brace.unity:6: unclosed '{': no matching '}' before line"));
            Assert.That(seconds, Is.LessThan(60), "the old line-joining parser took over 120 s here");
        }

        [Test]
        public void A_two_megabyte_unclosed_quote_names_the_key_it_belongs_to()
        {
            var text = new StringBuilder(Header).Append("  open: \"starts here\n");
            for (int i = 0; text.Length < 2_000_000; i++) text.Append("    and goes on ").Append(i).Append('\n');

            var error = ParseError(text.ToString(), "Quote.unity", 60, out _);

            Assert.That(error.Message, Does.Contain("unclosed quoted string: the value of 'open' (line 6) has no closing quote"));
        }

        [Test]
        public void A_mapping_of_two_hundred_thousand_keys_builds_in_linear_time()
        {
            var text = new StringBuilder(Header);
            for (int i = 0; i < 200_000; i++) text.Append("  k").Append(i).Append(": ").Append(i).Append('\n');

            var file = Deadline.Within(60, () => UnityYamlFile.Parse(text.ToString(), "Wide.unity"), "parsing 200 000 keys");

            Assert.That(file.Find(1).OrFail("document 1").Root.Entries.Count, Is.EqualTo(200_001));
            Assert.That(file.Find(1).OrFail("document 1").Root.GetLong("k199999"), Is.EqualTo(199_999L));
        }

        [Test]
        public void A_flow_mapping_that_runs_into_the_next_key_is_a_located_error_not_a_library_crash()
        {
            // YamlDotNet throws a bare exception here instead of its YamlException (its issue #541).
            var error = ParseError(Header + "  m_LocalScale: {x: 0.3,\n  m_Children: []\n", "Flow.unity", 30, out _);

            Assert.That(error.Message, Does.StartWith("Flow.unity:6: unclosed '{': no matching '}'"));
        }

        [TestCase("\"\\uD800\"", "Unicode")]
        [TestCase("\"\\U7FFFFFFF\"", "Unicode")]
        [TestCase("&anchor 1", "anchors, aliases and tags")]
        [TestCase("!!str 1", "anchors, aliases and tags")]
        public void Bad_escapes_and_anchors_are_located_errors(string value, string reason)
        {
            var error = ParseError(Header + "  phaseName: " + value + "\n", "Escape.unity", 30, out _);

            Assert.That(error.Message, Does.StartWith("Escape.unity:6: "));
            Assert.That(error.Message, Does.Contain(reason));
        }
    }
}
