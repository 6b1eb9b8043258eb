using System.Drawing;

namespace Lamella.Grasshopper
{
    /// <summary>The 24×24 icons embedded in the .gha as resources "Lamella.Grasshopper.Icons.&lt;name&gt;.png".</summary>
    internal static class Icons
    {
        public static Bitmap Load(string name)
        {
            var stream = typeof(Icons).Assembly.GetManifestResourceStream("Lamella.Grasshopper.Icons." + name + ".png");
            return stream == null ? null : new Bitmap(stream);
        }
    }
}
