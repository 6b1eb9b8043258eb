using System;
using System.Drawing;
using System.Reflection;
using Grasshopper.Kernel;

namespace Lamella.Grasshopper
{
    /// <summary>The plugin's identity in Grasshopper and in the Yak package manager (name and version match manifest.yml).</summary>
    public class LamellaInfo : GH_AssemblyInfo
    {
        /// <summary>The library id (stable: documents and the native loader find the plugin by it).</summary>
        public static readonly Guid LibraryId = new Guid("5b1f1f2e-7a43-4d51-9a0e-3c2b6d8e4a10");

        /// <summary>The component tab.</summary>
        public const string Category = "Lamella";

        public override string Name => "Lamella";
        public override string Description => "Rectifying strip patterns (Wang, Wang, Schling, Pottmann 2023): P-curve fields on meshes, level curves, developable strips and their unrollings.";
        public override Guid Id => LibraryId;
        public override string AuthorName => "Lamella contributors";
        public override string AuthorContact => "https://github.com/lamella";
        /// <summary>The package version (semantic, as in manifest.yml; checked by scripts/test-csharp.sh).</summary>
        public override string Version => typeof(LamellaInfo).Assembly.GetCustomAttribute<AssemblyInformationalVersionAttribute>().InformationalVersion;
        public override Bitmap Icon => Icons.Load("Lamella");
    }

    /// <summary>Gives the Lamella tab its icon, short name and symbol before any component loads.</summary>
    public class LamellaCategory : GH_AssemblyPriority
    {
        public override GH_LoadingInstruction PriorityLoad()
        {
            try
            {
                var server = global::Grasshopper.Instances.ComponentServer;
                server.AddCategoryIcon(LamellaInfo.Category, Icons.Load("Lamella"));
                server.AddCategoryShortName(LamellaInfo.Category, "Lml");
                server.AddCategorySymbolName(LamellaInfo.Category, 'L');
            }
            catch (Exception)
            {
                // Cosmetic only: the components load without the tab icon.
            }
            return GH_LoadingInstruction.Proceed;
        }
    }
}
