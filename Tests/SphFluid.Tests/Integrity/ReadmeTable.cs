using System;
using System.IO;
using NUnit.Framework;
using SphFluid.Headless.Output;

namespace SphFluid.Tests.Integrity
{
    /// <summary>A README table generated from the [Setting] declarations of a type: between its two markers the README must
    /// hold exactly what <see cref="SettingsTable.Markdown"/> writes, and the failure message gives the table to paste.</summary>
    static class ReadmeTable
    {
        public static void AssertIsTheDeclarations(string begin, string end, Type declared, string name)
        {
            string readme = File.ReadAllText(Path.Combine(GpuTestDevice.RepoRoot, "README.md")).Replace("\r\n", "\n");
            int start = readme.IndexOf(begin, StringComparison.Ordinal);
            int stop = readme.IndexOf(end, StringComparison.Ordinal);
            Assert.That(start, Is.GreaterThanOrEqualTo(0), "README.md lacks the marker " + begin);
            Assert.That(stop, Is.GreaterThan(start), "README.md lacks the marker " + end);
            string expected = SettingsTable.Markdown(declared);
            Assert.That(readme.Substring(start + begin.Length, stop - start - begin.Length), Is.EqualTo(expected),
                $"README's {name} table differs from the declarations; replace it with:\n" + expected);
        }
    }
}
