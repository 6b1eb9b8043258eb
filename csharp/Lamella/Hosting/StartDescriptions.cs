using System.Globalization;
using System.Text;

namespace Lamella.Hosting
{
    /// <summary>What a host shows of a start search: progress, the chosen start, the candidates; culture-invariant text.</summary>
    public static class StartDescriptions
    {
        /// <summary>A short message while the search runs: "searching a start · 3 candidates probed".</summary>
        public static string Progress(Candidate[] probed) =>
            string.Format(CultureInfo.InvariantCulture, "searching a start · {0} candidate{1} probed", probed.Length, probed.Length == 1 ? "" : "s");

        /// <summary>The chosen start in a few words for a component message: "start: height (0.71, 0, 0.71)", "start: guides, side 2, 90°".</summary>
        public static string Short(Candidate chosen)
        {
            if (chosen.Kind == StartKind.Guides)
            {
                return string.Format(CultureInfo.InvariantCulture, "start: guides, side {0}, {1:0.#}°", chosen.Side, chosen.StartAngleDegrees);
            }
            double[] d = chosen.Direction;
            return string.Format(CultureInfo.InvariantCulture, "start: {0}height ({1:0.##}, {2:0.##}, {3:0.##})", chosen.IsNegated ? "minus " : "", d[0], d[1], d[2]);
        }

        /// <summary>The chosen start in full, for a remark: the library's text and how many candidates it was the best of.</summary>
        public static string Chosen(Candidate chosen, int candidates) =>
            string.Format(CultureInfo.InvariantCulture, "start search: {0} (candidate {1}, the best of {2})", chosen.Text, chosen.Index, candidates);

        /// <summary>
        /// A report: the field's (when there is a field) followed by every candidate probed, one line each, the chosen one
        /// (when there is one) marked with "*".
        /// </summary>
        public static string Report(Candidate[] candidates, int? chosen, FieldReport? report)
        {
            var text = new StringBuilder();
            if (report.HasValue) text.Append(report.Value.Describe()).Append("\n\n");
            text.Append(chosen.HasValue ? "start search:" : "searching a start (library start search):");
            foreach (Candidate c in candidates)
            {
                text.Append('\n').Append(c.Index == chosen ? "* " : "  ").Append(c.ToString());
            }
            return text.ToString();
        }
    }
}
