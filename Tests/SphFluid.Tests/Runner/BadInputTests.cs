using System;
using System.IO;
using System.Linq;
using System.Text;
using NUnit.Framework;
using SphFluid.Headless;
using SphFluid.Headless.Cli;
using SphFluid.Simulation;

namespace SphFluid.Tests.Runner
{
    /// <summary>
    /// Every input the "Health" issue measured as a hang, a crash, a silently corrupt run or an exception name now ends
    /// quickly in exit 2 (argument) or 3 (scene) with a message naming the field, the file and the line. Each case runs
    /// the whole command line under a deadline; none of them reaches the device.
    /// </summary>
    public sealed class BadInputTests
    {
        const string Default = "OilAndWater";
        const string WaterTransform = "--- !u!4 &1104342179";
        const string OilTransform = "--- !u!4 &518734963";
        const string ContainerTransformId = "280459232";

        sealed class Outcome
        {
            public readonly int Code;
            public readonly string Stdout;
            public readonly string Stderr;

            public Outcome(int code, string stdout, string stderr)
            {
                Code = code;
                Stdout = stdout;
                Stderr = stderr;
            }
        }

        static Outcome Run(double seconds, params string[] args)
        {
            var outcome = Deadline.Within(seconds, () =>
            {
                var o = new StringWriter();
                var e = new StringWriter();
                int code = Program.Run(args, o, e);
                return new Outcome(code, o.ToString(), e.ToString());
            }, "sphfluid " + string.Join(" ", args.Select(a => a.Length > 60 ? a.Substring(0, 60) + "..." : a)));
            TestContext.Out.WriteLine($"exit {outcome.Code}: {outcome.Stderr}");
            Assert.That(outcome.Stderr, Does.Not.Contain("Exception"), "a message for the reader, never an exception type name");
            return outcome;
        }

        static Outcome Simulate(string scene, params string[] extra) =>
            Run(60, new[] { "simulate", scene, "--seconds", "0.01", "--out", RunnerPaths.ScratchFolder("bad-input-out") }.Concat(extra).ToArray());

        /// <summary>The default scene with <paramref name="find"/> replaced inside the one document that starts with
        /// <paramref name="header"/>; <paramref name="line"/> is the 1-based line of the edit.</summary>
        static string EditDocument(string header, string find, string replace, out int line, string? text = null) =>
            RunnerPaths.EditDocument(text ?? File.ReadAllText(RunnerPaths.Scene(Default)), header, find, replace, out line);

        static string Write(string text, string name = Default + ".unity")
        {
            string path = Path.Combine(RunnerPaths.ScratchFolder("bad-input"), name);
            File.WriteAllText(path, text);
            return path;
        }

        // ---------------------------------------------------------------- hangs

        [TestCase("simulate")]
        [TestCase("bench")]
        public void AnObjectThatIsItsOwnParentIsASceneError(string command)
        {
            string path = Write(EditDocument(WaterTransform, "m_Father: {fileID: 0}", "m_Father: {fileID: 1104342179}", out int line));

            var run = Run(60, command, path, "--steps", "1");

            Assert.That(run.Code, Is.EqualTo(ExitCodes.BadScene));
            Assert.That(run.Stderr, Does.Contain($"{path}:{line}: GameObject 'Water' &1485336898 is its own parent"));
        }

        [Test]
        public void TwoObjectsThatAreEachOthersParentAreASceneError()
        {
            string text = EditDocument(WaterTransform, "m_Father: {fileID: 0}", "m_Father: {fileID: 518734963}", out int line);
            string path = Write(EditDocument(OilTransform, "m_Father: {fileID: 0}", "m_Father: {fileID: 1104342179}", out _, text));

            var run = Simulate(path);

            Assert.That(run.Code, Is.EqualTo(ExitCodes.BadScene));
            Assert.That(run.Stderr, Does.Contain($"{path}:{line}: GameObjects 'Water' &1485336898 -> 'Oil' &305626396 -> 'Water' &1485336898 form a parent cycle"));
        }

        [TestCase("--diagnostics-every")]
        [TestCase("--frames-every")]
        public void AnOutputIntervalBelowTheMinimumIsRefused(string option)
        {
            var run = Simulate(RunnerPaths.Scene(Default), option, "1e-300");

            Assert.That(run.Code, Is.EqualTo(ExitCodes.BadArguments));
            Assert.That(run.Stderr, Does.Contain($"{option} must be in [0.0001, 3600] s (was 1E-300)"));
        }

        [Test]
        public void AFifoAsTheSceneIsRefusedWithoutOpeningIt()
        {
            string path = Path.Combine(RunnerPaths.ScratchFolder("fifo"), "Pipe.unity");
            RunnerPaths.Pipe(path);

            var run = Simulate(path);

            Assert.That(run.Code, Is.EqualTo(ExitCodes.BadScene));
            Assert.That(run.Stderr, Does.Contain($"{path}: is empty or not a regular file (a device, a pipe or a /proc file); expected a text file of 1 byte to 16 MiB"));
        }

        [Test]
        public void ATwoMegabyteSceneWithAnUnclosedBraceEndsInALocatedError()
        {
            string text = EditDocument(WaterTransform, "m_LocalScale: {x: 0.3, y: 0.2, z: 0.12}", "m_LocalScale: {x: 0.3,", out int line);
            var big = new StringBuilder(text.Length + 2_100_000);
            int insert = text.IndexOf('\n', text.IndexOf("m_LocalScale: {x: 0.3,", StringComparison.Ordinal)) + 1;
            big.Append(text, 0, insert);
            for (int i = 0; big.Length < 2_000_000; i++) big.Append("    pad").Append(i).Append(": 1,\n");
            big.Append(text, insert, text.Length - insert);
            string path = Write(big.ToString());

            var run = Simulate(path);

            Assert.That(run.Code, Is.EqualTo(ExitCodes.BadScene));
            Assert.That(run.Stderr, Does.Contain($"{path}:{line}: unclosed '{{'"));
        }

        [Test]
        public void ATwoMegabyteSceneWithAnUnclosedQuoteEndsInALocatedError()
        {
            string text = File.ReadAllText(RunnerPaths.Scene(Default));
            int at = text.IndexOf("      Name: Oil\n", StringComparison.Ordinal);
            int line = text.Take(at).Count(c => c == '\n') + 1;
            var big = new StringBuilder(text.Length + 2_100_000).Append(text, 0, at).Append("      Name: \"Oil\n");
            for (int i = 0; big.Length < 2_000_000; i++) big.Append("    more words ").Append(i).Append('\n');
            string path = Write(big.ToString());

            var run = Simulate(path);

            Assert.That(run.Code, Is.EqualTo(ExitCodes.BadScene));
            Assert.That(run.Stderr, Does.Contain($"unclosed quoted string: the value of 'Name' (line {line}) has no closing quote"));
            Assert.That(run.Stderr, Does.Contain(path + ":"));
        }

        // ---------------------------------------------------------------- crashes

        [Test]
        public void FlowCollectionsNestedThirtyThousandDeepAreRefusedAtTheDepthLimit()
        {
            var deep = new StringBuilder("Name: ");
            for (int i = 0; i < 30000; i++) deep.Append("{a: ");
            deep.Append('1').Append('}', 30000);
            string path = Write(EditDocument("--- !u!114 &287989891", "Name: Oil", deep.ToString(), out int line));

            var run = Simulate(path);

            Assert.That(run.Code, Is.EqualTo(ExitCodes.BadScene));
            Assert.That(run.Stderr, Does.Contain($"{path}:{line}: nested deeper than 64 levels"));
            Assert.That(run.Stderr.Length, Is.LessThan(2000), "one message, not a stack trace");
        }

        [Test]
        public void DevZeroAsTheSceneIsRefusedWithoutReadingIt()
        {
            if (!File.Exists("/dev/zero")) Assert.Ignore("no /dev/zero here");

            var run = Simulate("/dev/zero");

            Assert.That(run.Code, Is.EqualTo(ExitCodes.BadScene));
            Assert.That(run.Stderr, Does.Contain("/dev/zero: is empty or not a regular file"));
        }

        // ---------------------------------------------------------------- corrupt scenes

        [Test]
        public void ADuplicatedGameObjectFileIdIsRefusedBeforeSimulating()
        {
            string text = File.ReadAllText(RunnerPaths.Scene(Default)).Replace("--- !u!1 &305626396", "--- !u!1 &1485336898");
            int line = text.Split('\n').ToList().FindLastIndex(l => l == "--- !u!1 &1485336898") + 1;
            string path = Write(text);

            var run = Simulate(path);

            Assert.That(run.Code, Is.EqualTo(ExitCodes.BadScene));
            Assert.That(run.Stderr, Does.Contain($"{path}:{line}: anchor &1485336898 is used by more than one document"));
        }

        /// <summary>A script guid that no .meta has, or that is not 32 hex digits at all, is refused at its line rather
        /// than the box being dropped as a missing script.</summary>
        [TestCase("0123456789abcdef0123456789abcdef", "references guid 0123456789abcdef0123456789abcdef, which no .meta in the project has")]
        [TestCase("0123456789abcdefNaN9abcdef012345", "has malformed guid '0123456789abcdefNaN9abcdef012345'")]
        public void ASpawnBoxWithAnUnknownScriptGuidIsRefusedInsteadOfDropped(string unknown, string problem)
        {
            string guid = RunnerPaths.Project.ScriptGuid("SpawnBox");
            string path = Write(EditDocument("--- !u!114 &287989891", "guid: " + guid, "guid: " + unknown, out int line));

            var run = Simulate(path);

            Assert.That(run.Code, Is.EqualTo(ExitCodes.BadScene));
            Assert.That(run.Stderr, Does.Contain($"{path}:{line}: &287989891 MonoBehaviour.m_Script {problem}"));
        }

        /// <summary>Whether a spawn box counts follows its m_Enabled; a value Unity never writes was read as "enabled".</summary>
        [Test]
        public void ASpawnBoxEnabledFlagThatIsNoBoolIsRefusedAtItsLine()
        {
            string path = Write(EditDocument("--- !u!114 &287989891", "m_Enabled: 1", "m_Enabled: 0x10", out int line));

            var run = Simulate(path);

            Assert.That(run.Code, Is.EqualTo(ExitCodes.BadScene));
            Assert.That(run.Stderr, Does.Contain($"{path}:{line}: MonoBehaviour &287989891 m_Enabled must be 0 or 1 (was '0x10')"));
        }

        // ---------------------------------------------------------------- exit 1 before

        [Test]
        public void AParticleScaleThatShrinksNoContainerBelowTwoSpacingsNamesTheOption()
        {
            var run = Simulate(RunnerPaths.Scene(Default), "--particles-scale", "0.01");

            Assert.That(run.Code, Is.EqualTo(ExitCodes.BadArguments));
            Assert.That(run.Stderr, Does.Contain("simulate: --particles-scale 0.01 is out of range for this scene: it needs a particle spacing of 0.06962 m"));
            Assert.That(run.Stderr, Does.Contain("Container: each Size component must be in [0.139248, 1000] m"));
        }

        [Test]
        public void BenchParticlesBeyondTheFinestSpacingNamesTheOption()
        {
            var run = Run(120, "bench", RunnerPaths.Scene(Default), "--particles", "16777216", "--steps", "1", "--warmup", "0");

            Assert.That(run.Code, Is.EqualTo(ExitCodes.BadArguments));
            Assert.That(run.Stderr, Does.Contain("bench: --particles 16777216 is out of range for this scene"));
            Assert.That(run.Stderr, Does.Contain("ParticleSpacing must be in [0.001, 1] m"));
            Assert.That(run.Stdout, Does.Not.Contain("| particles |"), "refused before measuring anything");
        }

        [Test]
        public void AThousandMetreContainerNamesTheContainerAndTheSupportRadius()
        {
            const string scale = "m_LocalScale: {x: 0.6, y: 0.4, z: 0.12}";
            string path = Write(EditDocument("--- !u!4 &280459232", scale, "m_LocalScale: {x: 1000, y: 1000, z: 1000}", out int line));

            var run = Simulate(path);

            Assert.That(run.Code, Is.EqualTo(ExitCodes.BadScene));
            Assert.That(run.Stderr, Does.Contain($"{path}:{line}: the fluid scene is invalid"));
            Assert.That(run.Stderr, Does.Contain("GameObject 'Container', Transform.m_LocalScale and GameObject 'Fluid', Fluid.settings.SmoothingRadius"));
            Assert.That(run.Stderr, Does.Contain("46788 x 46788 x 46788 = 1.02E+014 cells"));
        }

        /// <summary>A container outside its own size range was refused by the neighbour grid, which asked for a support
        /// radius of kilometres (or, at a scale of 0, a size "finite and > 0"); the container's range says what to change.</summary>
        [TestCase("{x: 1000000000, y: 1000000000, z: 1000000000}", "(was (1E+09, 1E+09, 1E+09))")]
        [TestCase("{x: 0, y: 0, z: 0}", "(was (0, 0, 0))")]
        [TestCase("{x: 1001, y: 0.4, z: 0.12}", "(was (1001, 0.4, 0.12))")]
        public void AContainerOutsideItsSizeRangeIsRefusedForItsRange(string scale, string was)
        {
            string path = Write(EditDocument("--- !u!4 &280459232", "m_LocalScale: {x: 0.6, y: 0.4, z: 0.12}", "m_LocalScale: " + scale, out int line));

            var run = Simulate(path);

            Assert.That(run.Code, Is.EqualTo(ExitCodes.BadScene));
            Assert.That(run.Stderr, Does.Contain($"{path}:{line}: GameObject 'Container', Transform.m_LocalScale: each Size component must be in " +
                "[0.03, 1000] m (two particle spacings or more) " + was));
            Assert.That(run.Stderr, Does.Not.Contain("CellGrid"));
        }

        // ---------------------------------------------------------------- text that acts on a terminal

        /// <summary>A scene's double-quoted "\e[2J" is an escape sequence once parsed; as a phase name it was printed on
        /// every diagnostics line, clearing the terminal. It is refused at its line, and the message shows it escaped.</summary>
        [Test]
        public void APhaseNameHoldingAnEscapeSequenceIsRefusedAtItsLineAndShownEscaped()
        {
            string path = Write(EditDocument("--- !u!114 &287989891", "Name: Oil", "Name: \"Oil\\e[2J\\e[31m\"", out int line));

            var run = Simulate(path);

            Assert.That(run.Code, Is.EqualTo(ExitCodes.BadScene));
            Assert.That(run.Stderr, Does.Contain($"{path}:{line}: GameObject 'Oil', SpawnBox.spawn.Phase.Name: Name must be " +
                "printable text, without control characters (was 'Oil\\u001B[2J\\u001B[31m', U+001B at character 4)"));
            AssertNothingActsOnATerminal(run);
        }

        /// <summary>A file that is no scene is refused with its first line quoted, control characters escaped: the quote once
        /// carried a binary file's bytes to the terminal as they were.</summary>
        [Test]
        public void AFileOfControlCharactersIsQuotedEscaped()
        {
            string path = Write("\u001B[2J\u001B]0;title\u0007\r\u202Eelif\n");

            var run = Simulate(path);

            Assert.That(run.Code, Is.EqualTo(ExitCodes.BadScene));
            Assert.That(run.Stderr, Does.Contain($"{path}:1: content before the first '--- !u!' document: '\\u001B[2J\\u001B]0;title\\u0007\\u000D\\u202Eelif'"));
            AssertNothingActsOnATerminal(run);
        }

        static void AssertNothingActsOnATerminal(Outcome run) =>
            Assert.That((run.Stdout + run.Stderr).Where(c => c != '\n' && !PrintableText.IsPrintable(c)).Select(c => $"U+{(int)c:X4}"), Is.Empty);

        /// <summary>A Transform value that is no number is named with its file, line and field; a number where the axes'
        /// mapping belongs was once blamed as a non-finite first axis ("must be a finite number (was '-0')").</summary>
        [TestCase("m_LocalScale: {x: 0.3,", "m_LocalScale: {x: abc,", "Transform.m_LocalScale.x must be a finite number (was 'abc')")]
        [TestCase("m_LocalScale: {x: 0.3, y: 0.2, z: 0.12}", "m_LocalScale: -0", "Transform.m_LocalScale must be {x: <number>, y: <number>, z: <number>} (was '-0')")]
        public void ABadTransformValueNamesTheFileLineAndField(string from, string to, string message)
        {
            string path = Write(EditDocument(WaterTransform, from, to, out int line));

            var run = Simulate(path);

            Assert.That(run.Code, Is.EqualTo(ExitCodes.BadScene));
            Assert.That(run.Stderr, Does.Contain($"{path}:{line}: GameObject 'Water', {message}"));
        }

        /// <summary>A spawn box too thin once placed was named by its GameObject and Transform field but by no line.</summary>
        [Test]
        public void ASpawnBoxTooThinIsNamedAtItsScaleLine()
        {
            string path = Write(EditDocument(WaterTransform, "m_LocalScale: {x: 0.3, y: 0.2, z: 0.12}", "m_LocalScale: {x: 0.3, y: 0.2, z: 0.001}", out int line));

            var run = Simulate(path);

            Assert.That(run.Code, Is.EqualTo(ExitCodes.BadScene));
            Assert.That(run.Stderr, Does.Contain($"{path}:{line}: GameObject 'Water', Transform.m_LocalScale: each Size component must be in"));
        }

        /// <summary>Under a scaled parent the box's own scale is fine and its world size is not: the message names the
        /// parent whose Transform counts too.</summary>
        [Test]
        public void ASpawnBoxUnderAParentNamesTheParent()
        {
            // Water under the container, as Unity writes a parent: the child in the parent's m_Children and no longer a root.
            string text = EditDocument(WaterTransform, "m_Father: {fileID: 0}", "m_Father: {fileID: " + ContainerTransformId + "}", out _);
            text = EditDocument("--- !u!4 &" + ContainerTransformId, "m_Children: []", "m_Children:\n  - {fileID: 1104342179}", out _, text);
            text = EditDocument("SceneRoots:", "  - {fileID: 1104342179}\n", "", out _, text);
            string path = Write(text);
            int line = File.ReadAllLines(path).Select((l, i) => (l, i)).Skip(LineOf(path, WaterTransform))
                .First(l => l.l.Contains("m_LocalScale")).i + 1;

            var run = Simulate(path);

            Assert.That(run.Code, Is.EqualTo(ExitCodes.BadScene));
            Assert.That(run.Stderr, Does.Contain($"{path}:{line}: GameObject 'Water', Transform.m_LocalScale (in the world, under 'Container', whose Transforms count too): each Size component must be in"));
        }

        static int LineOf(string path, string text) => Array.FindIndex(File.ReadAllLines(path), l => l.StartsWith(text, StringComparison.Ordinal));

        /// <summary>A zero rotation was reported against the container's scale and the support radius, a tiny one as a
        /// spawn box's NaN rotation with no line; each is now named at its own line.</summary>
        [TestCase("--- !u!4 &280459232", "Container", "{x: 0, y: 0, z: 0, w: 0}", "length 0")]
        [TestCase(WaterTransform, "Water", "{x: 0, y: 0, z: 0, w: 1e-30}", "length 1E-30")]
        [TestCase(WaterTransform, "Water", "{x: 0, y: 0, z: 0, w: 2}", "length 2")]
        public void ARotationThatIsNoUnitQuaternionIsNamedAtItsLine(string header, string name, string rotation, string length)
        {
            string path = Write(EditDocument(header, "m_LocalRotation: {x: 0, y: 0, z: 0, w: 1}", "m_LocalRotation: " + rotation, out int line));

            var run = Simulate(path);

            Assert.That(run.Code, Is.EqualTo(ExitCodes.BadScene));
            Assert.That(run.Stderr, Does.Contain($"{path}:{line}: GameObject '{name}', Transform.m_LocalRotation must be a unit quaternion (length in [0.99, 1.01]) (was {rotation}, {length})"));
        }

        [TestCase("\"\\uD800\"", "invalid Unicode surrogates")]
        [TestCase("\"\\U7FFFFFFF\"", "invalid Unicode character escape code")]
        public void ABadEscapeNamesTheFileAndLine(string value, string reason)
        {
            string path = Write(EditDocument("--- !u!114 &287989891", "Name: Oil", "Name: " + value, out int line));

            var run = Simulate(path);

            Assert.That(run.Code, Is.EqualTo(ExitCodes.BadScene));
            Assert.That(run.Stderr, Does.Contain($"{path}:{line}: "));
            Assert.That(run.Stderr, Does.Contain(reason));
        }

        // ---------------------------------------------------------------- smaller defects

        [TestCase("--- !u!114 &1249553504", "particleRadiusScale: 1.2", "particleRadiusScale: 5", "Fluid.particleRadiusScale must be in [0.25, 3] half spacings (was 5)")]
        [TestCase("--- !u!114 &1249553504", "maxFrameTime: 0.0333333", "maxFrameTime: 0", "Fluid.maxFrameTime must be in [0.001, 0.1] s (was 0)")]
        public void InspectorRangesTheRunnerUsedToSkipAreChecked(string header, string find, string replace, string message) =>
            AssertRefusedAtTheEditedLine(header, find, replace, "GameObject '", message);

        /// <summary>Fields the runner does not read (Unity's alone) passed whatever they held; they must be what Unity
        /// writes for the type their script declares. On the Fluid such a value refuses the scene; on another component
        /// (the demo's readout, on the Fluid's own GameObject) it is a warning at its line, and the scene runs, as in
        /// Unity (<see cref="UnreadObjectTests"/>).</summary>
        [TestCase("--- !u!114 &1249553504", "requestDiagnostics: 1", "requestDiagnostics: abc", "requestDiagnostics must be 0 or 1 (a bool) (was 'abc')")]
        public void UnityOnlyFieldsMustHoldWhatUnityWritesForTheirType(string header, string find, string replace, string message) =>
            AssertRefusedAtTheEditedLine(header, find, replace, "MonoBehaviour &", message);

        [TestCase("--- !u!114 &482617472", "fontSize: 14", "fontSize: 1e30", "fontSize must be a whole number in the range of an int (was '1e30')")]
        [TestCase("--- !u!114 &482617472", "visible: 1", "visible: 2", "visible must be 0 or 1 (a bool) (was '2')")]
        public void AnotherComponentsFieldThatUnityWouldNotWriteIsAWarningAtItsLine(string header, string find, string replace, string message)
        {
            string path = Write(EditDocument(header, find, replace, out int line));

            var run = Simulate(path);

            Assert.That(run.Code, Is.EqualTo(ExitCodes.Ok));
            Assert.That(run.Stderr, Does.Contain($"simulate: warning: {path}: the integrity check finds 1 problem(s) on objects the fluid is not read from"));
            Assert.That(run.Stderr, Does.Contain($"{path}:{line}: MonoBehaviour &"));
            Assert.That(run.Stderr, Does.Contain(message));
        }

        /// <summary>Edits one line of the default scene's document <paramref name="header"/>: the run must be refused as a
        /// scene error located at that line, its text starting with <paramref name="located"/> and holding <paramref name="message"/>.</summary>
        static void AssertRefusedAtTheEditedLine(string header, string find, string replace, string located, string message)
        {
            string path = Write(EditDocument(header, find, replace, out int line));

            var run = Simulate(path);

            Assert.That(run.Code, Is.EqualTo(ExitCodes.BadScene));
            Assert.That(run.Stderr, Does.Contain($"{path}:{line}: {located}"));
            Assert.That(run.Stderr, Does.Contain(message));
        }

        /// <summary>A sphere that covers every spawn point once reached the GPU with no particle ("unexpected failure",
        /// exit 1): it is a scene error at the sphere's radius.</summary>
        [Test]
        public void ASphereThatSwallowsTheFluidIsRefusedAtItsRadius()
        {
            string path = RunnerPaths.EditedScene("SphereWake", "\n  radius: 0.5\n", "\n  radius: 50\n");
            int line = Array.IndexOf(File.ReadAllLines(path), "  radius: 50") + 1;

            var run = Simulate(path);

            Assert.That(run.Code, Is.EqualTo(ExitCodes.BadScene));
            Assert.That(run.Stderr, Does.Contain($"{path}:{line}: GameObject 'Sphere', SphereObstacle.radius " +
                "(in the world: 50 times 0.09, the largest component of its scale in the world): the sphere obstacles ('Sphere' of world radius 4.5 m"));
            Assert.That(run.Stderr, Does.Contain("so the scene would spawn no particle"));
        }

        /// <summary>Under a scaled parent the sphere's world radius takes the parent's scale too: the message names it.</summary>
        [Test]
        public void ASphereUnderAParentNamesTheParentInItsRadius()
        {
            // The sphere under the container, as Unity writes a parent: the child in the parent's m_Children and no longer a root.
            string path = RunnerPaths.EditedScene("SphereWake",
                ("  - {fileID: 1486937963}\n", ""),
                ("m_LocalScale: {x: 0.09, y: 0.09, z: 0.09}\n  m_ConstrainProportionsScale: 0\n  m_Children: []\n  m_Father: {fileID: 0}",
                    "m_LocalScale: {x: 0.09, y: 0.09, z: 0.09}\n  m_ConstrainProportionsScale: 0\n  m_Children: []\n  m_Father: {fileID: 1764925814}"),
                ("m_LocalScale: {x: 0.8, y: 0.3, z: 0.16}\n  m_ConstrainProportionsScale: 0\n  m_Children: []",
                    "m_LocalScale: {x: 0.8, y: 0.3, z: 0.16}\n  m_ConstrainProportionsScale: 0\n  m_Children:\n  - {fileID: 1486937963}"),
                ("\n  radius: 0.5\n", "\n  radius: 100000\n"));
            int line = Array.IndexOf(File.ReadAllLines(path), "  radius: 100000") + 1;

            var run = Simulate(path);

            Assert.That(run.Code, Is.EqualTo(ExitCodes.BadScene));
            Assert.That(run.Stderr, Does.Contain($"{path}:{line}: GameObject 'Sphere', SphereObstacle.radius (in the world: 100000 times 0.072, the largest " +
                "component of its scale in the world, which the scales of 'Container' take part in): Radius must be in (0, 1000] m (was 7200)"));
        }

        /// <summary>The rule quotes the world radius, which the field alone does not show where the sphere is scaled; at a
        /// scale of 1 the field is the world radius and nothing is added.</summary>
        [Test]
        public void ARadiusRefusedAtAScaleOfOneNamesNoScale()
        {
            string path = RunnerPaths.EditedScene("SphereWake", ("\n  radius: 0.5\n", "\n  radius: 1001\n"),
                ("m_LocalScale: {x: 0.09, y: 0.09, z: 0.09}", "m_LocalScale: {x: 1, y: 1, z: 1}"));
            int line = Array.IndexOf(File.ReadAllLines(path), "  radius: 1001") + 1;

            var run = Simulate(path);

            Assert.That(run.Code, Is.EqualTo(ExitCodes.BadScene));
            Assert.That(run.Stderr, Does.Contain($"{path}:{line}: GameObject 'Sphere', SphereObstacle.radius: Radius must be in (0, 1000] m (was 1001)"));
        }

        /// <summary>Values Unity never writes that were read as something else: a fileID that is no integer as no
        /// reference at all (so the Fluid fell back to the scene's container, as if the field were unassigned), and a
        /// colour's alpha that holds no number as the default for a missing one, opaque.</summary>
        [TestCase("--- !u!114 &1249553504", "container: {fileID: 327545201}", "container: {fileID: abc}",
            "&1249553504 MonoBehaviour has a reference whose fileID 'abc' is not a 64-bit integer")]
        [TestCase("--- !u!114 &287989891", "a: 0.85", "a: abc", "GameObject 'Oil', SpawnBox.spawn.Phase.Color must be a colour {r, g, b, a}")]
        public void AValueReadAsAnotherIsRefusedAtItsLine(string header, string find, string replace, string located) =>
            AssertRefusedAtTheEditedLine(header, find, replace, located, located);

        /// <summary>Unity drops a key no field declares and keeps the field's default: a misspelt setting ran the scene at
        /// the default spacing (1 800 particles instead of 4 160), a misspelt alpha drew the oil opaque.</summary>
        [TestCase("--- !u!114 &1249553504", "ParticleSpacing: 0.015", "ParticleSpaceing: 0.015",
            "GameObject 'Fluid', Fluid.settings.ParticleSpaceing: no field of FluidSettings is named 'ParticleSpaceing', so Unity would drop it and keep the field's default (its fields: ParticleSpacing, SmoothingRadius,")]
        [TestCase("--- !u!114 &287989891", "RestDensity: 900", "RestDensty: 900",
            "GameObject 'Oil', SpawnBox.spawn.Phase.RestDensty: no field of FluidBlock.Phase is named 'RestDensty', so Unity would drop it and keep the field's default (its fields: Name, RestDensity, Viscosity,")]
        [TestCase("--- !u!114 &287989891", "a: 0.85", "alpha: 0.85", "GameObject 'Oil', SpawnBox.spawn.Phase.Color has no component 'alpha' (Unity writes r, g, b, a)")]
        [TestCase("--- !u!114 &1249553504", "y: -9.81", "w: -9.81", "GameObject 'Fluid', Fluid.settings.Gravity has no component 'w' (Unity writes x, y, z)")]
        public void AKeyUnityWouldDropIsRefusedAtItsLine(string header, string find, string replace, string located) =>
            AssertRefusedAtTheEditedLine(header, find, replace, located, located);

        /// <summary>A closed container that the fluid fills leaves DFSPH's constant-density solve nothing to give: cut down to
        /// the liquids' top, OilAndWater under DFSPH ran out of iterations in 51 % of its first 0.6 s. The run goes ahead,
        /// warned (FreeVolume), as do a bench and a study of it; WCSPH compresses instead.</summary>
        [Test]
        public void AFluidThatFillsItsClosedContainerIsWarnedOfUnderDfsph()
        {
            const string container = "--- !u!4 &" + ContainerTransformId;
            string text = EditDocument(container, "m_LocalPosition: {x: 0, y: 0.2, z: 0}", "m_LocalPosition: {x: 0, y: 0.1, z: 0}", out _);
            string path = Write(EditDocument(container, "m_LocalScale: {x: 0.6, y: 0.4, z: 0.12}", "m_LocalScale: {x: 0.6, y: 0.2, z: 0.12}", out _, text));

            var run = Simulate(path, "--solver", "dfsph");

            Assert.That(run.Code, Is.EqualTo(ExitCodes.Ok));
            Assert.That(run.Stderr, Does.Contain("simulate: warning: under DFSPH the fluid (0.0144 m^3) leaves 0 m^3 of the closed 0.0144 m^3 container free, " +
                "less than the 1.44E-05 m^3 (DensityTolerance 0.1 % of the fluid's volume)"));
            Assert.That(Simulate(path).Stderr, Does.Not.Contain("warning"), "WCSPH");
            Assert.That(Simulate(RunnerPaths.Scene(Default), "--solver", "dfsph").Stderr, Does.Not.Contain("warning"), "the scene as shipped");

            var bench = Run(60, "bench", path, "--solver", "dfsph", "--particles-scales", "0.1", "--warmup", "0", "--warmup-seconds", "0",
                "--steps", "1", "--skip-savings", "--out", RunnerPaths.ScratchFolder("bad-input-bench"));
            Assert.That(bench.Code, Is.EqualTo(ExitCodes.Ok));
            Assert.That(bench.Stderr, Does.Contain("bench: warning: under DFSPH the fluid (0.0144 m^3) leaves 0 m^3"));
            var study = Run(60, "study", path, "--solvers", "wcsph,dfsph", "--density-tolerances", "0.1", "--particles-scales", "0.1",
                "--cfl", "0.3", "--seconds", "0.01", "--out", RunnerPaths.ScratchFolder("bad-input-study"));
            Assert.That(study.Code, Is.EqualTo(ExitCodes.Ok));
            Assert.That(study.Stderr, Does.Contain("study: warning: 1 of the configurations (their cut-off column shows the cost): under DFSPH the fluid (0.0144 m^3) leaves 0 m^3"));
        }

        [Test]
        public void AColourChannelBeyondOneIsRefusedAtItsLineWithTheRange()
        {
            string path = Write(EditDocument("--- !u!114 &287989891", "r: 0.8900054", "r: 2", out int line));

            var run = Simulate(path);

            Assert.That(run.Code, Is.EqualTo(ExitCodes.BadScene));
            Assert.That(run.Stderr, Does.Contain(path + ": the fluid scene is invalid"));
            Assert.That(run.Stderr, Does.Contain($"{path}:{line}: GameObject 'Oil', SpawnBox.spawn.Phase.Color.r: Color.r must be in [0, 1] (was 2)"));
        }

        [Test]
        public void AFrameTooShortToStepIsRefusedInsteadOfMisreported()
        {
            var run = Simulate(RunnerPaths.Scene(Default), "--frame-seconds", "1e-300");

            Assert.That(run.Code, Is.EqualTo(ExitCodes.BadArguments));
            Assert.That(run.Stderr, Does.Contain("--frame-seconds must be in [0.0001, 0.1] s (was 1E-300)"));
        }

        [TestCase("")]
        [TestCase("4000,,8000")]
        public void AnEmptyParticleCountIsRefused(string value)
        {
            var run = Run(60, "bench", RunnerPaths.Scene(Default), "--particles", value);

            Assert.That(run.Code, Is.EqualTo(ExitCodes.BadArguments));
            Assert.That(run.Stderr, Does.Contain("--particles must be a whole number in [64, 16777216] (was '')"));
        }
    }
}
