using System;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace Lamella.Tests
{
    /// <summary>The explicit native loader (its Linux branch: dlopen by full path).</summary>
    [TestFixture]
    public class LoaderTests
    {
        [Test]
        public void FailureNamesEveryPathTriedThenTheRightFolderLoads()
        {
            string nowhere = Path.Combine(Path.GetTempPath(), "lamella-nowhere"), alsoNowhere = Path.Combine(Path.GetTempPath(), "lamella-elsewhere");
            var expected = NativeLibraryLoader.CandidatePaths(nowhere, alsoNowhere).ToList();
            Assert.AreEqual(4, expected.Count, "each folder and its platform subfolder");
            var e = Assert.Throws<DllNotFoundException>(() => NativeLibraryLoader.Load(nowhere, alsoNowhere));
            foreach (string path in expected) StringAssert.Contains(path, e.Message);
            Assert.IsNull(NativeLibraryLoader.LoadedPath);

            // A file that is not a library: the loader's own error is quoted.
            string bogus = Path.Combine(Path.GetTempPath(), "lamella-bogus-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(bogus);
            try
            {
                File.WriteAllText(Path.Combine(bogus, NativeLibraryLoader.FileName), "not a library");
                var bad = Assert.Throws<DllNotFoundException>(() => NativeLibraryLoader.Load(bogus));
                string line = bad.Message.Split('\n').Single(l => l.Contains(Path.Combine(bogus, NativeLibraryLoader.FileName) + " ("));
                StringAssert.DoesNotContain("no such file", line);
                StringAssert.Contains("file too short", line, "dlerror's message");
            }
            finally
            {
                Directory.Delete(bogus, true);
            }

            string here = AppDomain.CurrentDomain.BaseDirectory;
            string loaded = NativeLibraryLoader.Load(nowhere, here);
            Assert.AreEqual(Path.Combine(here, NativeLibraryLoader.FileName), loaded);
            Assert.AreEqual(loaded, NativeLibraryLoader.Load(nowhere), "loading again is a no-op");
        }

        [Test]
        public void FileNameFollowsThePlatform()
        {
            Assert.AreEqual(Environment.OSVersion.Platform == PlatformID.Win32NT ? "lamella.dll" : "liblamella.so", NativeLibraryLoader.FileName);
        }
    }
}
