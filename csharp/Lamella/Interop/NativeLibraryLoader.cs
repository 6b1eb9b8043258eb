using System;
using System.Collections.Generic;
using System.IO;
using System.Runtime.InteropServices;

namespace Lamella
{
    /// <summary>The operating systems the native library is built for.</summary>
    public enum NativePlatform
    {
        /// <summary>Windows: <c>lamella_native.dll</c>.</summary>
        Windows,
        /// <summary>macOS: <c>liblamella_native.dylib</c>.</summary>
        MacOS,
        /// <summary>Linux: <c>liblamella_native.so</c>.</summary>
        Linux,
    }

    /// <summary>
    /// Loads the native library by full path before the first call, so that <c>[DllImport("lamella_native")]</c> finds
    /// it even when the host (Grasshopper) loaded the managed assembly from memory and would not search the plugin
    /// folder: <c>lamella_native.dll</c> with LoadLibrary on Windows, <c>liblamella_native.dylib</c> /
    /// <c>liblamella_native.so</c> with dlopen on macOS / Linux. Cargo builds the library as <c>lamella.dll</c> /
    /// <c>liblamella.*</c>; packaging copies it under the name above, because on Windows (case-insensitive file names)
    /// <c>lamella.dll</c> would be the same file as the managed <c>Lamella.dll</c> beside it.
    /// How the later <c>[DllImport]</c> calls bind to the loaded file depends on the runtime:
    /// .NET Framework on Windows finds the loaded module by name; .NET (Rhino 8) is given the handle through a
    /// DllImport resolver; Mono (Rhino 7 on macOS) searches the folder of Lamella.dll itself, so the native library
    /// must sit next to it there (a library loaded elsewhere is reported, not silently ignored).
    /// </summary>
    public static class NativeLibraryLoader
    {
        private static readonly object Gate = new object();
        private static string loadedPath;

        /// <summary>The file name of the native library on this operating system.</summary>
        public static string FileName => FileNameOn(CurrentPlatform());

        /// <summary>The file name of the native library on <paramref name="platform"/>.</summary>
        public static string FileNameOn(NativePlatform platform)
        {
            switch (platform)
            {
                case NativePlatform.Windows: return Interop.NativeMethods.Library + ".dll";
                case NativePlatform.MacOS: return "lib" + Interop.NativeMethods.Library + ".dylib";
                default: return "lib" + Interop.NativeMethods.Library + ".so";
            }
        }

        /// <summary>The path loaded by <see cref="Load"/>, or null before.</summary>
        public static string LoadedPath
        {
            get { lock (Gate) { return loadedPath; } }
        }

        /// <summary>
        /// Loads the native library from the first of <paramref name="folders"/> (and their per-platform subfolders
        /// such as <c>win-x64</c>, <c>osx</c>, <c>linux-x64</c>) that holds it, then checks its ABI version. Returns
        /// the full path; loading again is a no-op. Throws <see cref="DllNotFoundException"/> naming every path tried
        /// and the loader's error for each.
        /// </summary>
        public static string Load(params string[] folders)
        {
            if (folders == null) throw new ArgumentNullException(nameof(folders));
            lock (Gate)
            {
                if (loadedPath != null)
                {
                    return loadedPath;
                }
                var tried = new List<string>();
                foreach (string path in CandidatePaths(folders))
                {
                    if (!File.Exists(path))
                    {
                        tried.Add(path + " (no such file)");
                        continue;
                    }
                    string error = TryLoad(path);
                    if (error == null)
                    {
                        loadedPath = path;
                        CheckBinding(path);
                        return path;
                    }
                    tried.Add(path + " (" + error + ")");
                }
                throw new DllNotFoundException(
                    "the Lamella native library " + FileName + " could not be loaded; tried:" + Environment.NewLine + "  " +
                    string.Join(Environment.NewLine + "  ", tried));
            }
        }

        /// <summary>Makes the first [DllImport] call, which binds every later one, and checks the ABI version.</summary>
        private static void CheckBinding(string path)
        {
            try
            {
                Library.CheckAbiVersion();
            }
            catch (DllNotFoundException e)
            {
                throw new DllNotFoundException(
                    "the Lamella native library was loaded from " + path + " but [DllImport(\"" + Interop.NativeMethods.Library + "\")] did not bind to it (" +
                    e.Message + "); on Mono, place " + FileName + " next to Lamella.dll", e);
            }
        }

        /// <summary>Every full path <see cref="Load"/> tries, in order.</summary>
        public static IEnumerable<string> CandidatePaths(params string[] folders)
        {
            string[] subfolders = PlatformSubfolders();
            foreach (string folder in folders)
            {
                if (string.IsNullOrEmpty(folder))
                {
                    continue;
                }
                yield return Path.Combine(folder, FileName);
                foreach (string sub in subfolders)
                {
                    yield return Path.Combine(Path.Combine(folder, sub), FileName);
                }
            }
        }

        private static NativePlatform CurrentPlatform()
        {
            if (Environment.OSVersion.Platform == PlatformID.Win32NT)
            {
                return NativePlatform.Windows;
            }
            // Mono reports macOS as PlatformID.Unix: RuntimeInformation tells them apart.
            return Unix.IsDarwin() ? NativePlatform.MacOS : NativePlatform.Linux;
        }

        private static string[] PlatformSubfolders()
        {
            string arch = Environment.Is64BitProcess ? (IsArm64() ? "arm64" : "x64") : "x86";
            switch (CurrentPlatform())
            {
                case NativePlatform.Windows: return new[] { "win-" + arch };
                case NativePlatform.MacOS: return new[] { "osx", "osx-" + arch };
                default: return new[] { "linux-" + arch };
            }
        }

        private static bool IsArm64() =>
            RuntimeInformation.ProcessArchitecture == Architecture.Arm64;

        /// <summary>Loads <paramref name="path"/>; null on success, else the loader's error.</summary>
        private static string TryLoad(string path)
        {
#if NETCOREAPP
            // .NET: load through the runtime and hand the handle to every [DllImport] of this assembly.
            IntPtr library;
            if (!NativeLibrary.TryLoad(path, out library))
            {
                return "NativeLibrary.TryLoad failed";
            }
            NativeLibrary.SetDllImportResolver(typeof(NativeLibraryLoader).Assembly,
                (name, assembly, searchPath) => name == Interop.NativeMethods.Library ? library : IntPtr.Zero);
            return null;
#else
            switch (CurrentPlatform())
            {
                case NativePlatform.Windows:
                    if (Kernel32.LoadLibraryW(path) != IntPtr.Zero)
                    {
                        return null;
                    }
                    return "LoadLibrary error " + Marshal.GetLastWin32Error();
                // dlerror is called first so that the runtime binds it (binding itself calls dlsym, which would
                // clear the message of a failed dlopen) and any stale message is cleared.
                case NativePlatform.MacOS:
                    MacDl.dlerror();
                    return DlopenResult(MacDl.dlopen(path, Unix.RtldNowGlobal), MacDl.dlerror);
                default:
                    LinuxDl.dlerror();
                    return DlopenResult(LinuxDl.dlopen(path, Unix.RtldNowGlobal), LinuxDl.dlerror);
            }
#endif
        }

        private static string DlopenResult(IntPtr handle, Func<IntPtr> dlerror)
        {
            if (handle != IntPtr.Zero)
            {
                return null;
            }
            string message = Marshal.PtrToStringAnsi(dlerror());
            return string.IsNullOrEmpty(message) ? "dlopen failed" : message;
        }

        private static class Kernel32
        {
            [DllImport("kernel32", CharSet = CharSet.Unicode, SetLastError = true)]
            public static extern IntPtr LoadLibraryW(string path);
        }

        private static class LinuxDl
        {
            // glibc: libdl.so.2 (a stub forwarding to libc since glibc 2.34, still shipped).
            [DllImport("libdl.so.2", CallingConvention = CallingConvention.Cdecl)]
            public static extern IntPtr dlopen(string path, int flags);
            [DllImport("libdl.so.2", CallingConvention = CallingConvention.Cdecl)]
            public static extern IntPtr dlerror();
        }

        private static class MacDl
        {
            [DllImport("libSystem.dylib", CallingConvention = CallingConvention.Cdecl)]
            public static extern IntPtr dlopen(string path, int flags);
            [DllImport("libSystem.dylib", CallingConvention = CallingConvention.Cdecl)]
            public static extern IntPtr dlerror();
        }

        private static class Unix
        {
            // RTLD_NOW | RTLD_GLOBAL: 0x2 | 0x100 on Linux, 0x2 | 0x8 on macOS.
            public static int RtldNowGlobal => IsDarwin() ? 0x2 | 0x8 : 0x2 | 0x100;

            public static bool IsDarwin() => RuntimeInformation.IsOSPlatform(OSPlatform.OSX);
        }
    }
}
