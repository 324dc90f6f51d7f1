using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using NUnit.Framework;

namespace SphFluid.Tests.Runner
{
    /// <summary>One of the repository's bash scripts run as the README runs it, from the repository's root.</summary>
    public static class RepositoryScript
    {
        /// <summary>Runs <paramref name="script"/> (a path from the root) with <paramref name="arguments"/> and the
        /// <paramref name="environment"/> variables set. Both streams are read at once and the wait is bounded: a script
        /// that hung fails the test instead of stalling the run.</summary>
        public static (int ExitCode, string Output, string Error) Run(string script, IEnumerable<string> arguments,
            IReadOnlyDictionary<string, string>? environment = null)
        {
            var start = new ProcessStartInfo("bash")
            {
                WorkingDirectory = GpuTestDevice.RepoRoot,
                RedirectStandardOutput = true,
                RedirectStandardError = true,
            };
            start.ArgumentList.Add(script);
            foreach (string argument in arguments) start.ArgumentList.Add(argument);
            if (environment != null)
                foreach (var (name, value) in environment) start.Environment[name] = value;
            using var process = Process.Start(start)!;
            var output = process.StandardOutput.ReadToEndAsync();
            var error = process.StandardError.ReadToEndAsync();
            bool exited = process.WaitForExit(30_000);
            if (!exited) process.Kill(true);
            Assert.That(exited, Is.True, $"{Path.GetFileName(script)} did not finish within 30 s");
            return (process.ExitCode, output.Result, error.Result);
        }
    }
}
