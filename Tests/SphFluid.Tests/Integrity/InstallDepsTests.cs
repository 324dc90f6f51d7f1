using System.Diagnostics;
using System.IO;
using NUnit.Framework;

namespace SphFluid.Tests.Integrity
{
    /// <summary>
    /// Headless/install-deps.sh, which the README's commands run first: a switch it reads from the environment takes 0 or
    /// 1 and refuses anything else before it installs a package.
    /// </summary>
    public class InstallDepsTests
    {
        /// <summary>SPHFLUID_SYSTEM_LAVAPIPE=yes read as 0, and on Debian 12 the script went to bookworm-backports for the
        /// Mesa the caller had asked it to leave alone.</summary>
        [Test]
        public void ASystemLavapipeSwitchOtherThan0Or1IsRefusedByName()
        {
            var start = new ProcessStartInfo("bash") { WorkingDirectory = GpuTestDevice.RepoRoot, RedirectStandardOutput = true, RedirectStandardError = true };
            start.ArgumentList.Add(Path.Combine("Headless", "install-deps.sh"));
            start.Environment["SPHFLUID_SYSTEM_LAVAPIPE"] = "yes";
            using var process = Process.Start(start)!;
            var output = process.StandardOutput.ReadToEndAsync();
            var error = process.StandardError.ReadToEndAsync();
            bool exited = process.WaitForExit(30_000);
            if (!exited) process.Kill(true);
            Assert.That(exited, Is.True, "install-deps.sh did not finish within 30 s");
            Assert.That(process.ExitCode, Is.EqualTo(2), output.Result + error.Result);
            Assert.That(error.Result, Is.EqualTo("install-deps: SPHFLUID_SYSTEM_LAVAPIPE must be 0 (take Mesa 25 from bookworm-backports on " +
                "Debian 12) or 1 (keep the release's lavapipe), or unset (was 'yes')\n"));
            Assert.That(output.Result, Is.Empty, "nothing installed");
        }
    }
}
