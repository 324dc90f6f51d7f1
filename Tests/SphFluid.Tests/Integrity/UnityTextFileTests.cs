using System.IO;
using NUnit.Framework;
using SphFluid.Tests.Runner;
using SphFluid.UnityFiles.Yaml;

namespace SphFluid.Tests.Integrity
{
    /// <summary>Only a regular file of 1 byte to 16 MiB is read, judged before it is opened; a link is judged by its target.</summary>
    public sealed class UnityTextFileTests
    {
        [Test]
        public void A_file_over_the_limit_is_refused_by_its_size_without_reading_it()
        {
            string path = Path.Combine(RunnerPaths.ScratchFolder("text-file"), "Huge.unity");
            using (var f = new FileStream(path, FileMode.CreateNew)) f.SetLength(UnityTextFile.MaxBytes + 1); // sparse: nothing written

            var error = Assert.Throws<IOException>(() => UnityTextFile.Read(path));

            Assert.That(error.Message, Is.EqualTo($"{path}: is 16777217 bytes; expected a text file of 1 byte to 16 MiB"));
        }

        [Test]
        public void A_folder_an_empty_file_and_a_missing_file_are_named()
        {
            string dir = RunnerPaths.ScratchFolder("text-file");
            string empty = Path.Combine(dir, "Empty.unity");
            File.WriteAllText(empty, "");

            Assert.That(Assert.Throws<IOException>(() => UnityTextFile.Read(dir)).Message, Is.EqualTo($"{dir}: is a folder; expected a text file of 1 byte to 16 MiB"));
            Assert.That(Assert.Throws<IOException>(() => UnityTextFile.Read(empty)).Message, Does.StartWith($"{empty}: is empty or not a regular file"));
            Assert.That(Assert.Throws<FileNotFoundException>(() => UnityTextFile.Read(Path.Combine(dir, "None.unity"))).Message, Does.EndWith("None.unity: no such file"));
        }

        [Test]
        public void A_link_is_read_through_to_its_regular_target()
        {
            string dir = RunnerPaths.ScratchFolder("text-file");
            string target = Path.Combine(dir, "Target.unity");
            File.WriteAllText(target, "%YAML 1.1\n");
            string link = Path.Combine(dir, "Link.unity");
            try { File.CreateSymbolicLink(link, target); }
            catch (IOException e) { Assert.Ignore("no symbolic links here: " + e.Message); }

            Assert.That(UnityTextFile.Read(link), Is.EqualTo("%YAML 1.1\n"));
        }

        /// <summary>A regular file is judged from one status read, and only a link is followed: a link to a folder still
        /// reads as a folder, and one to nothing as a link to nothing, by both reads.</summary>
        [Test]
        public void A_link_to_a_folder_or_to_nothing_is_named_so()
        {
            string dir = RunnerPaths.ScratchFolder("text-file");
            string toFolder = Path.Combine(dir, "Folder.unity");
            string toNothing = Path.Combine(dir, "Nothing.unity");
            try
            {
                File.CreateSymbolicLink(toFolder, dir);
                File.CreateSymbolicLink(toNothing, Path.Combine(dir, "None"));
            }
            catch (IOException e) { Assert.Ignore("no symbolic links here: " + e.Message); }

            foreach (var read in new System.Func<string, string>[] { UnityTextFile.Read, UnityTextFile.ReadMayBeEmpty })
            {
                Assert.That(Assert.Throws<IOException>(() => read(toFolder)).Message, Is.EqualTo($"{toFolder}: is a folder; expected a text file of 1 byte to 16 MiB"));
                Assert.That(Assert.Throws<FileNotFoundException>(() => read(toNothing)).Message, Is.EqualTo($"{toNothing}: is a link to nothing"));
            }
        }
    }
}
