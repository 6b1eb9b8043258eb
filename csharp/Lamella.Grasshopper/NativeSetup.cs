using System;
using System.IO;

namespace Lamella.Grasshopper
{
    /// <summary>
    /// Loads the native library from the plugin's own folder before the first call (once per session). The folder
    /// comes from Grasshopper's record of the library (its Location stays valid when the .gha was loaded from
    /// memory, where Assembly.Location is empty), then from the assembly itself.
    /// </summary>
    internal static class NativeSetup
    {
        private static readonly object Gate = new object();
        private static bool done;
        private static string error;

        /// <summary>Null when the library is loaded, else the message naming every path tried.</summary>
        public static string EnsureLoaded()
        {
            lock (Gate)
            {
                if (!done)
                {
                    done = true;
                    try
                    {
                        NativeLibraryLoader.Load(PluginFolders());
                    }
                    catch (Exception e)
                    {
                        error = e.Message;
                    }
                }
                return error;
            }
        }

        private static string[] PluginFolders()
        {
            string fromGrasshopper = null;
            try
            {
                var info = global::Grasshopper.Instances.ComponentServer.FindAssembly(LamellaInfo.LibraryId);
                fromGrasshopper = info == null ? null : Path.GetDirectoryName(info.Location);
            }
            catch (Exception)
            {
                // Not registered yet: fall back to the assembly's own location.
            }
            string own = typeof(NativeSetup).Assembly.Location;
            return new[] { fromGrasshopper, string.IsNullOrEmpty(own) ? null : Path.GetDirectoryName(own) };
        }
    }
}
