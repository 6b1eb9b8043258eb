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
            Assert.AreEqual(Environment.OSVersion.Platform == PlatformID.Win32NT ? "lamella_native.dll" : "liblamella_native.so", NativeLibraryLoader.FileName);
            Assert.AreEqual("lamella_native.dll", NativeLibraryLoader.FileNameOn(NativePlatform.Windows));
            Assert.AreEqual("liblamella_native.dylib", NativeLibraryLoader.FileNameOn(NativePlatform.MacOS));
            Assert.AreEqual("liblamella_native.so", NativeLibraryLoader.FileNameOn(NativePlatform.Linux));
        }

        /// <summary>
        /// Windows and the default macOS file systems ignore case: the native library must not share a file name with any
        /// managed assembly that sits in the same folder (Lamella.dll, Lamella.Grasshopper.gha), or one overwrites the
        /// other and [DllImport] may bind to the managed module.
        /// </summary>
        [Test]
        public void NativeFileNamesDifferFromTheManagedOnesIgnoringCase()
        {
            string managed = typeof(LamellaMesh).Assembly.GetName().Name;
            Assert.AreEqual("Lamella", managed);
            foreach (NativePlatform platform in Enum.GetValues(typeof(NativePlatform)))
            {
                string native = NativeLibraryLoader.FileNameOn(platform);
                foreach (string file in new[] { managed + ".dll", "Lamella.Grasshopper.gha", "Lamella.Grasshopper.dll" })
                {
                    Assert.IsFalse(string.Equals(native, file, StringComparison.OrdinalIgnoreCase), native + " vs " + file);
                    Assert.IsFalse(string.Equals(Path.GetFileNameWithoutExtension(native), Path.GetFileNameWithoutExtension(file), StringComparison.OrdinalIgnoreCase),
                        "a DllImport by base name could resolve " + native + " to " + file);
                }
            }
        }
    }
}
