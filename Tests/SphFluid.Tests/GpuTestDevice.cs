using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using NUnit.Framework;
using NUnit.Framework.Interfaces;
using SphFluid.Vulkan;

// Every test of the assembly ends with a check that the validation layer stayed silent during it.
[assembly: SphFluid.Tests.GpuValidationClean]

namespace SphFluid.Tests
{
    /// <summary>
    /// The one Vulkan device every GPU test shares (creating a device and JIT-compiling kernels is the
    /// slow part, so it happens once per test run). Shaders are found in Packages/com.sphfluid.fluid/Shaders and in
    /// every Tests/SphFluid.Tests/**/Shaders folder. Validation is on whenever the Khronos layer is
    /// installed; <see cref="AssertNoValidationMessages"/> checks it stayed silent.
    /// </summary>
    public static class GpuTestDevice
    {
        static readonly object Gate = new object();
        static VulkanComputeDevice? _device;
        static string? _unavailable;

        /// <summary>The repository root: the first folder above the test assembly holding both Assets and Headless.</summary>
        public static string RepoRoot { get; } = FindRepoRoot();

        /// <summary>Packages/com.sphfluid.fluid/Shaders, then every Shaders folder under Tests/SphFluid.Tests.</summary>
        public static IReadOnlyList<string> ShaderDirectories { get; } = FindShaderDirectories();

        /// <summary>The shared device; the test is ignored (with the reason) where no Vulkan driver exists.</summary>
        public static VulkanComputeDevice Shared
        {
            get
            {
                lock (Gate)
                {
                    if (_device == null && _unavailable == null)
                    {
                        try
                        {
                            bool validation = VulkanComputeDevice.IsValidationLayerAvailable();
                            _device = new VulkanComputeDevice(new VulkanComputeOptions
                            {
                                ShaderDirectories = ShaderDirectories,
                                Validation = validation,
                                SynchronizationValidation = validation,
                            });
                            AppDomain.CurrentDomain.ProcessExit += (s, e) => DisposeShared();
                        }
                        catch (VulkanUnavailableException e)
                        {
                            _unavailable = e.Message;
                        }
                    }
                    if (_device == null) Assert.Ignore("No Vulkan device: " + _unavailable);
                    return _device;
                }
            }
        }

        static VulkanComputeDevice? _unvalidated;

        /// <summary>
        /// A second device on the same driver without the validation layers, for the physics runs (Tests/SphFluid.Tests/Physics:
        /// hundreds of frames, measured against physics), whose passes the validated tests record in the same configurations for
        /// a few frames (the solver kernel and planner tests, SimulateRunTests over the shipped scenes, the hard cases): a long
        /// run repeats that recording, and the layers cost it 12 % under WCSPH (OilAndWater's separation test: 362 s with
        /// them, 319 s without, on lavapipe), the measured figures identical; under DFSPH no cost stands out from the spread
        /// of repeated runs (SphereWake's DFSPH test: 76 to 80 s with them, 75 to 82 s without, on an idle machine;
        /// Headless/tools/experiment.sh --baseline sphere-wake-unvalidated). Headless/test.sh holds this device to that: a kernel
        /// variant it ran must have run on <see cref="Shared"/> too (<see cref="VariantsFolderVariable"/>).
        /// Created on first use and released with <see cref="Shared"/>; ignored, like it, where no Vulkan driver exists.
        /// </summary>
        public static VulkanComputeDevice Unvalidated
        {
            get
            {
                _ = Shared; // the test is ignored here where no Vulkan driver exists
                lock (Gate)
                {
                    _unvalidated ??= new VulkanComputeDevice(new VulkanComputeOptions { ShaderDirectories = ShaderDirectories, Validation = false });
                    return _unvalidated;
                }
            }
        }

        /// <summary>True once <see cref="Shared"/> has been created (without creating it).</summary>
        public static bool IsCreated
        {
            get { lock (Gate) return _device != null; }
        }

        /// <summary>Fails with every message the validation layer has reported so far, then forgets them.</summary>
        public static void AssertNoValidationMessages()
        {
            VulkanComputeDevice? device;
            lock (Gate) device = _device;
            if (device == null) return;
            var messages = device.ValidationMessages;
            device.ClearValidationMessages();
            Assert.That(messages, Is.Empty, "Vulkan validation reported:\n" + string.Join("\n", messages));
        }

        /// <summary>The environment variable naming a folder where the assembly's teardown writes the kernel variants each device
        /// ran (<see cref="WriteDispatchedVariants"/>). Headless/test.sh sets it for both of its processes and fails the run
        /// when a variant ran on <see cref="Unvalidated"/> in either of them but on <see cref="Shared"/> in neither: a check in
        /// the teardown itself could not fail a run, since dotnet test reports a OneTimeTearDown's failure and exits 0.</summary>
        public const string VariantsFolderVariable = "SPHFLUID_VARIANTS_DIR";

        /// <summary>Writes validated.txt and unvalidated.txt, one kernel variant a line (VulkanComputeDevice.DispatchedVariants),
        /// into the folder <see cref="VariantsFolderVariable"/> names, if it names one.</summary>
        public static void WriteDispatchedVariants()
        {
            string? folder = Environment.GetEnvironmentVariable(VariantsFolderVariable);
            if (string.IsNullOrEmpty(folder)) return;
            VulkanComputeDevice? validated, unvalidated;
            lock (Gate)
            {
                validated = _device;
                unvalidated = _unvalidated;
            }
            Directory.CreateDirectory(folder);
            File.WriteAllLines(Path.Combine(folder, "validated.txt"), validated?.DispatchedVariants.OrderBy(v => v, StringComparer.Ordinal) ?? Enumerable.Empty<string>());
            File.WriteAllLines(Path.Combine(folder, "unvalidated.txt"), unvalidated?.DispatchedVariants.OrderBy(v => v, StringComparer.Ordinal) ?? Enumerable.Empty<string>());
        }

        internal static void DisposeShared()
        {
            lock (Gate)
            {
                _unvalidated?.Dispose();
                _unvalidated = null;
                _device?.Dispose();
                _device = null;
            }
        }

        static string FindRepoRoot()
        {
            var dir = new DirectoryInfo(Path.GetDirectoryName(typeof(GpuTestDevice).Assembly.Location) ?? TestContext.CurrentContext.TestDirectory);
            while (dir != null)
            {
                if (Directory.Exists(Path.Combine(dir.FullName, "Assets")) && Directory.Exists(Path.Combine(dir.FullName, "Headless"))) return dir.FullName;
                dir = dir.Parent;
            }
            throw new InvalidOperationException("Could not find the repository root (a folder with Assets/ and Headless/) above " + typeof(GpuTestDevice).Assembly.Location);
        }

        static IReadOnlyList<string> FindShaderDirectories()
        {
            var dirs = new List<string> { Path.Combine(RepoRoot, "Packages", "com.sphfluid.fluid", "Shaders") };
            string tests = Path.Combine(RepoRoot, "Tests", "SphFluid.Tests");
            if (Directory.Exists(tests))
            {
                dirs.AddRange(Directory.EnumerateDirectories(tests, "Shaders", SearchOption.AllDirectories)
                    .Where(d => !d.Contains(Path.DirectorySeparatorChar + "bin" + Path.DirectorySeparatorChar) && !d.Contains(Path.DirectorySeparatorChar + "obj" + Path.DirectorySeparatorChar))
                    .OrderBy(d => d, StringComparer.Ordinal));
            }
            return dirs;
        }
    }
}

namespace SphFluid.Tests
{
    /// <summary>After each test that ran while the shared GPU device existed: the Vulkan validation layer
    /// must have reported nothing (the issue asks for a suite free of validation messages, and a
    /// per-test check names the test that caused one). Applied to the whole assembly.</summary>
    [AttributeUsage(AttributeTargets.Assembly)]
    public sealed class GpuValidationCleanAttribute : Attribute, ITestAction
    {
        public ActionTargets Targets => ActionTargets.Test;

        public void BeforeTest(ITest test) { }

        public void AfterTest(ITest test)
        {
            if (GpuTestDevice.IsCreated) GpuTestDevice.AssertNoValidationMessages();
        }
    }
}

/// <summary>Assembly-wide: after the last test, the kernel variants each device ran are written where Headless/test.sh asks for
/// them (GpuTestDevice.VariantsFolderVariable), the validation layer must have stayed silent, the devices are released and
/// the runner tests' scratch folders removed.</summary>
[SetUpFixture]
public sealed class SuiteTeardown
{
    [OneTimeTearDown]
    public void ReleaseSharedDevice()
    {
        try
        {
            SphFluid.Tests.GpuTestDevice.WriteDispatchedVariants();
            SphFluid.Tests.GpuTestDevice.AssertNoValidationMessages();
        }
        finally
        {
            SphFluid.Tests.GpuTestDevice.DisposeShared();
            SphFluid.Tests.Runner.RunnerPaths.RemoveScratch();
        }
    }
}
