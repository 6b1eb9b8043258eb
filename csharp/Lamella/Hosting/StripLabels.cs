using System.Collections.Generic;
using System.Globalization;

namespace Lamella.Hosting
{
    /// <summary>Labels and one-line descriptions of strips for display and fabrication; culture-invariant text.</summary>
    public static class StripLabels
    {
        /// <summary>The label of strip <paramref name="index"/> (in the library's strip order): S0, S1, …</summary>
        public static string Label(int index) => "S" + index.ToString(CultureInfo.InvariantCulture);

        /// <summary>The labels of <paramref name="count"/> strips.</summary>
        public static List<string> Labels(int count)
        {
            var labels = new List<string>(count);
            for (int i = 0; i < count; i++) labels.Add(Label(i));
            return labels;
        }

        /// <summary>One line per strip: label, curve, length, diff_θ, e_straight, max planarity residual, Appro (paper Table 4), the strip plane's angle error (what the verdict judges) and warnings.</summary>
        public static List<string> Describe(StripMetrics[] metrics)
        {
            var lines = new List<string>(metrics.Length);
            for (int i = 0; i < metrics.Length; i++)
            {
                StripMetrics m = metrics[i];
                lines.Add(string.Format(CultureInfo.InvariantCulture,
                    "{0} (curve {1}): length {2:0.###}, diff_θ {3:0.###}°, e_straight {4:0.##e+0}, max planar {5:0.##e+0}, Appro {6:0.####}%, plane angle error {7:0.###}°, warnings {8}",
                    Label(i), m.Curve, m.Length, m.MaxDiffThetaDegrees, m.EStraight, m.MaxPlanar, m.ApproPercent, m.MaxQuadAngleErrorDegrees, m.Warnings));
            }
            return lines;
        }
    }
}
