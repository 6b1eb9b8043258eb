using System;
using System.Drawing;
using Grasshopper.Kernel;

namespace Lamella.Grasshopper
{
    /// <summary>The plugin's identity in Grasshopper.</summary>
    public class LamellaInfo : GH_AssemblyInfo
    {
        /// <summary>The library id (stable: documents and the native loader find the plugin by it).</summary>
        public static readonly Guid LibraryId = new Guid("5b1f1f2e-7a43-4d51-9a0e-3c2b6d8e4a10");

        public override string Name => "Lamella";
        public override string Description => "Rectifying strip patterns (Wang, Wang, Schling, Pottmann 2023): P-curve fields on meshes, level curves, developable strips and their unrollings.";
        public override Guid Id => LibraryId;
        public override string AuthorName => "Lamella contributors";
        public override string AuthorContact => "https://github.com/lamella";
        public override string Version => typeof(LamellaInfo).Assembly.GetName().Version.ToString();
        public override Bitmap Icon => Icons.Load("Lamella");
    }
}
