using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace SphFluid.Tests.Rendering
{
    /// <summary>The outcome of compiling one stage: the SPIR-V file (null on failure) and every message.</summary>
    public sealed class StageCompileResult
    {
        public StageCompileResult(string? spirvPath, string messages)
        {
            SpirvPath = spirvPath;
            Messages = messages;
        }

        public string? SpirvPath { get; }
        public string Messages { get; }
        public bool Succeeded => SpirvPath != null;
    }

    /// <summary>
    /// Compiles one stage of a ShaderLab program with glslang's HLSL front end (the same front end the headless
    /// backend uses for the .compute kernels) and validates the SPIR-V with spirv-val. Unity's built-ins come
    /// from the test stand-in include folder, searched before the project's Shaders folder, as Unity searches
    /// its CGIncludes before paths relative to the shader.
    /// </summary>
    public static class GlslangShaderCheck
    {
        static readonly TimeSpan ToolTimeout = TimeSpan.FromSeconds(60);

        public static string StandInIncludeDir => Path.Combine(GpuTestDevice.RepoRoot, "Tests", "SphFluid.Tests", "Rendering", "UnityStandIn");

        public static string ShaderDir => Path.Combine(GpuTestDevice.RepoRoot, "Packages", "com.sphfluid.fluid", "Shaders");

        /// <summary>Ignores the test (with the reason) where a tool is not installed; Headless/test.sh installs them in CI.</summary>
        public static void RequireTool(string tool)
        {
            if (FindOnPath(tool) == null) Assert.Ignore(tool + " is not installed (apt-get install glslang-tools spirv-tools)");
        }

        public static string? FindOnPath(string tool)
        {
            foreach (string dir in (Environment.GetEnvironmentVariable("PATH") ?? "").Split(Path.PathSeparator))
            {
                if (dir.Length == 0) continue;
                string candidate = Path.Combine(dir, tool);
                if (File.Exists(candidate)) return candidate;
            }
            return null;
        }

        /// <summary>
        /// Compiles <paramref name="hlslFile"/> for one stage ("vert" or "frag") and entry point, then runs spirv-val.
        /// Messages name the .shader file and line when the source starts with a #line directive.
        /// </summary>
        public static StageCompileResult CompileStage(string hlslFile, string stage, string entry, IEnumerable<string> defines, string workDir)
        {
            string spv = Path.Combine(workDir, Path.GetFileNameWithoutExtension(hlslFile) + "." + stage + "." + entry + ".spv");
            var args = new List<string> { "-D", "-V", "--target-env", "vulkan1.1", "--auto-map-bindings", "--auto-map-locations",
                "-S", stage, "-e", entry, "-I" + StandInIncludeDir, "-I" + ShaderDir };
            args.AddRange(defines.Select(d => "-D" + d));
            args.Add(hlslFile);
            args.Add("-o");
            args.Add(spv);
            var (exit, output) = Run("glslangValidator", args);
            if (exit != 0 || !File.Exists(spv))
                return new StageCompileResult(null, "glslangValidator " + stage + " " + entry + " (exit " + exit + "):\n" + output.Trim());

            var (valExit, valOutput) = Run("spirv-val", new List<string> { "--target-env", "vulkan1.1", spv });
            if (valExit != 0)
                return new StageCompileResult(null, "spirv-val " + stage + " " + entry + " (exit " + valExit + "):\n" + valOutput.Trim());
            return new StageCompileResult(spv, output.Trim());
        }

        /// <summary>glslang's intermediate tree (-i) of one stage, for lints glslang itself does not perform.</summary>
        public static string IntermediateTree(string hlslFile, string stage, string entry, IEnumerable<string> defines, string workDir)
        {
            string spv = Path.Combine(workDir, Path.GetFileNameWithoutExtension(hlslFile) + "." + stage + ".tree.spv");
            var args = new List<string> { "-D", "-V", "-i", "--target-env", "vulkan1.1", "--auto-map-bindings", "--auto-map-locations",
                "-S", stage, "-e", entry, "-I" + StandInIncludeDir, "-I" + ShaderDir };
            args.AddRange(defines.Select(d => "-D" + d));
            args.Add(hlslFile);
            args.Add("-o");
            args.Add(spv);
            var (exit, output) = Run("glslangValidator", args);
            Assert.That(exit, Is.EqualTo(0), "glslangValidator -i " + stage + " " + entry + ":\n" + output);
            return output;
        }

        public static (int exitCode, string output) Run(string tool, IReadOnlyList<string> args)
        {
            var start = new ProcessStartInfo(tool)
            {
                RedirectStandardOutput = true,
                RedirectStandardError = true,
                UseShellExecute = false,
                CreateNoWindow = true,
            };
            foreach (string a in args) start.ArgumentList.Add(a);
            using (var process = Process.Start(start) ?? throw new InvalidOperationException(tool + " did not start"))
            {
                var stdout = process.StandardOutput.ReadToEndAsync();
                var stderr = process.StandardError.ReadToEndAsync();
                if (!process.WaitForExit((int)ToolTimeout.TotalMilliseconds))
                {
                    process.Kill(true);
                    return (-1, tool + " did not finish within " + ToolTimeout.TotalSeconds + " s");
                }
                process.WaitForExit();
                return (process.ExitCode, stdout.Result + stderr.Result);
            }
        }

        public static string NewWorkDir()
        {
            string dir = Path.Combine(Path.GetTempPath(), "sphfluid-render-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(dir);
            return dir;
        }

        public static void DeleteWorkDir(string dir)
        {
            try
            {
                if (dir != null && Directory.Exists(dir)) Directory.Delete(dir, true);
            }
            catch (IOException)
            {
                // A temp folder left behind is harmless; the test result must not depend on it.
            }
        }
    }
}
