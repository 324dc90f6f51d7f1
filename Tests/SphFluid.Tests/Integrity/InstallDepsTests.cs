using System.Collections.Generic;
using System.IO;
using NUnit.Framework;
using SphFluid.Tests.Runner;

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
            var (exitCode, output, error) = RepositoryScript.Run(Path.Combine("Headless", "install-deps.sh"), new string[0],
                new Dictionary<string, string> { ["SPHFLUID_SYSTEM_LAVAPIPE"] = "yes" });
            Assert.That(exitCode, Is.EqualTo(2), output + error);
            Assert.That(error, Is.EqualTo("install-deps: SPHFLUID_SYSTEM_LAVAPIPE must be 0 (take Mesa 25 from bookworm-backports on " +
                "Debian 12) or 1 (keep the release's lavapipe), or unset (was 'yes')\n"));
            Assert.That(output, Is.Empty, "nothing installed");
        }
    }
}
