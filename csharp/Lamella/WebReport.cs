using System.Globalization;
using Lamella.Interop;

namespace Lamella
{
    /// <summary>
    /// The state of a 3-web (<see cref="NetSolver.Web"/>) after a step beyond what its <see cref="NetReport"/> says of the
    /// first two families (<c>LmlWebReport</c>): how well F + G + H = 0 (Eq. 18) holds, the third family's angle error and
    /// how it crosses the other two. Angles in degrees; index 0 of the pairs: the third family against the first, 1:
    /// against the second.
    /// </summary>
    public sealed class WebReport
    {
        internal WebReport(WebReportRecord r)
        {
            AngleErrorRmsDegrees = r.AngleErrorRmsDegrees;
            AngleErrorMaxDegrees = r.AngleErrorMaxDegrees;
            SingularVertexCount = checked((long)r.SingularVertexCount);
            ResidualMax = r.ResidualMax;
            ResidualRms = r.ResidualRms;
            ThirdFamilyFactor = r.ThirdFamilyFactor;
            MinIntersectionDegrees = (double[])(r.MinIntersectionDegrees ?? new double[2]).Clone();
            MeanIntersectionDegrees = (double[])(r.MeanIntersectionDegrees ?? new double[2]).Clone();
            FacesBelowMin = new[] { checked((long)r.FacesBelowMin[0]), checked((long)r.FacesBelowMin[1]) };
        }

        /// <summary>RMS of the third family's angle error |θ_measured − θ| over its measured vertices.</summary>
        public double AngleErrorRmsDegrees { get; }
        /// <summary>Largest angle error of the third family.</summary>
        public double AngleErrorMaxDegrees { get; }
        /// <summary>Singular vertices of the third field.</summary>
        public long SingularVertexCount { get; }
        /// <summary>Largest |F + G + H| over the vertices (Eq. 18), relative to the largest of the three fields' ranges.</summary>
        public double ResidualMax { get; }
        /// <summary>RMS of |F + G + H| over the vertices, relative as <see cref="ResidualMax"/>.</summary>
        public double ResidualRms { get; }
        /// <summary>The factor on the third field's terms in the weight stage in force: it grows to 1 at the final stage.</summary>
        public double ThirdFamilyFactor { get; }
        /// <summary>Smallest unsigned angle at which the third family crosses the first (0) and the second (1) over the faces.</summary>
        public double[] MinIntersectionDegrees { get; }
        /// <summary>Area-weighted mean unsigned angle at which the third family crosses the first (0) and the second (1).</summary>
        public double[] MeanIntersectionDegrees { get; }
        /// <summary>Faces where the third family crosses the first (0) or the second (1) below the minimum angle.</summary>
        public long[] FacesBelowMin { get; }

        /// <summary>
        /// The whole web in a few lines: <paramref name="net"/> (the same session's <see cref="NetSolver.Report"/>) for
        /// the iterations and the first two families, this report for Eq. 18 and the third, and the crossings of every
        /// pair against <paramref name="minIntersectionDegrees"/>.
        /// </summary>
        public string Describe(NetReport net, double minIntersectionDegrees)
        {
            if (net == null) throw new System.ArgumentNullException(nameof(net));
            return string.Format(CultureInfo.InvariantCulture,
                "{0} iterations{1}; angle error RMS {2:0.###}° / {3:0.###}° / {4:0.###}° (max {5:0.###}° / {6:0.###}° / {7:0.###}°)\n" +
                "F + G + H (Eq. 18): max {8:0.##e+0}, RMS {9:0.##e+0} of the fields' range; third family's weight factor {10:0.###}\n" +
                "crossings (min {11:0.#}°): 1×2 min {12:0.#}°, mean {13:0.#}° ({14} faces below); 1×3 min {15:0.#}°, mean {16:0.#}° ({17} faces below); " +
                "2×3 min {18:0.#}°, mean {19:0.#}° ({20} faces below)",
                net.Iterations, net.IsConverged ? ", converged" : "",
                net.AngleErrorRmsDegrees[0], net.AngleErrorRmsDegrees[1], AngleErrorRmsDegrees,
                net.AngleErrorMaxDegrees[0], net.AngleErrorMaxDegrees[1], AngleErrorMaxDegrees,
                ResidualMax, ResidualRms, ThirdFamilyFactor, minIntersectionDegrees,
                net.MinIntersectionDegrees, net.MeanIntersectionDegrees, net.FacesBelowMin,
                MinIntersectionDegrees[0], MeanIntersectionDegrees[0], FacesBelowMin[0],
                MinIntersectionDegrees[1], MeanIntersectionDegrees[1], FacesBelowMin[1]);
        }
    }
}
