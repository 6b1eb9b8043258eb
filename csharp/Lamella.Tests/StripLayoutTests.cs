using System;
using System.Collections.Generic;
using Lamella.Conversion;
using Lamella.Hosting;
using NUnit.Framework;

namespace Lamella.Tests
{
    /// <summary>Fabrication output of strips: outlines, the flat layout on a plane, labels that match strip and flat twin.</summary>
    [TestFixture]
    public class StripLayoutTests
    {
        [Test]
        public void OutlineRunsLeftForwardThenRightBack()
        {
            // One strip of three centre points: left 0 1 2, right 3 4 5 (x, y per vertex).
            double[] flat = { 0, 0, 1, 0, 2, 0, 0, 1, 1, 1, 2, 1 };
            Packed outline = StripArrays.Outlines(flat, 2, new[] { 0, 6 });
            CollectionAssert.AreEqual(new[] { 0, 7 }, outline.Offsets);
            CollectionAssert.AreEqual(new double[] { 0, 0, 1, 0, 2, 0, 2, 1, 1, 1, 0, 1, 0, 0 }, outline.Values);
            Assert.AreEqual(2.0, Math.Abs(ShoelaceArea(outline.Values, 2, 0, 7)), 1e-15, "the 2 × 1 strip");
            Assert.Throws<ArgumentException>(() => StripArrays.Outlines(new double[10], 2, new[] { 0, 5 }), "an odd vertex count is not a strip");
        }

        [Test]
        public void OnPlaneKeepsDistancesAndLiesInThePlane()
        {
            double[] origin = { 1, 2, 3 }, x = { 0, Math.Sqrt(0.5), Math.Sqrt(0.5) }, y = { 1, 0, 0 };
            double[] xy = { 0, 0, 0, 3, 0, 0, 3, 4, 0 };
            double[] placed = StripArrays.OnPlane(xy, origin, x, y);
            CollectionAssert.AreEqual(origin, Vec.At(placed, 0));
            Assert.AreEqual(3.0, Vec.Distance(Vec.At(placed, 0), Vec.At(placed, 1)), 1e-12);
            Assert.AreEqual(5.0, Vec.Distance(Vec.At(placed, 0), Vec.At(placed, 2)), 1e-12);
            double[] normal = Vec.Cross(x, y);
            for (int i = 0; i < 3; i++) Assert.AreEqual(0, Vec.Dot(Vec.Sub(Vec.At(placed, i), origin), normal), 1e-12);
            Assert.Throws<ArgumentException>(() => StripArrays.OnPlane(xy, origin, new[] { double.NaN, 0, 0 }, y));
        }

        [Test]
        public void MiddlePointsAndLabels()
        {
            double[] points = { 0, 0, 0, 1, 0, 0, 2, 0, 0, 5, 5, 5 };
            double[] middles = StripArrays.MiddlePoints(points, new[] { 0, 3, 3, 4 });
            CollectionAssert.AreEqual(new double[] { 1, 0, 0 }, new[] { middles[0], middles[1], middles[2] });
            Assert.IsTrue(double.IsNaN(middles[3]), "an empty item has no middle");
            CollectionAssert.AreEqual(new double[] { 5, 5, 5 }, new[] { middles[6], middles[7], middles[8] });
            CollectionAssert.AreEqual(new[] { "S0", "S1", "S2" }, StripLabels.Labels(3));
        }

        /// <summary>
        /// Real strips on a solved cylinder, laid out on a tilted plane: each flat outline is a closed polyline enclosing
        /// exactly the strip's flat quads, outlines do not overlap, and each flat label point lies on its own strip.
        /// </summary>
        [Test]
        public void FlatLayoutOfRealStripsOnAPlane()
        {
            const double gap = 0.4;
            var c = new Cylinder(24, 14, 3);
            using (var mesh = LamellaMesh.FromArrays(c.Xyz, c.Triangles))
            using (var field = new FieldSolver(mesh, c.InitialField, FieldParams.Default(Family.PseudoGeodesic, 60)))
            {
                Assert.IsTrue(FieldStepping.ToConvergence(field, 300, () => false).Report.IsConverged);
                using (var curves = LevelCurves.Uniform(field, 4, 1.0))
                using (var strips = Strips.Build(curves, StripParams.Default(60, 0.5)))
                {
                    int[] vertexOffsets = strips.VertexOffsets(), pointOffsets = strips.PointOffsets(), quadOffsets = strips.QuadOffsets();
                    Assert.GreaterOrEqual(strips.Count, 3);
                    double[] unrolled = strips.UnrolledVertices();
                    double[] shifts = StripArrays.FlatLayoutShifts(unrolled, vertexOffsets, gap);
                    CollectionAssert.AreEqual(StripArrays.LayOutFlat(unrolled, vertexOffsets, gap), StripArrays.Shift(unrolled, vertexOffsets, shifts));
                    double[] origin = { 10, 20, 30 }, x = { Math.Sqrt(0.5), Math.Sqrt(0.5), 0 }, y = { 0, 0, 1 };
                    // In plane coordinates (x along X, y along Y) the layout is the XY layout; on the plane it is that, placed.
                    double[] xyLayout = StripArrays.Shift(unrolled, vertexOffsets, shifts);
                    double[] onPlane = StripArrays.OnPlane(xyLayout, origin, x, y);
                    double[] centres = StripArrays.Shift(strips.UnrolledCentres(), pointOffsets, shifts);
                    double[] labels = StripArrays.MiddlePoints(centres, pointOffsets);
                    Packed outlines = StripArrays.Outlines(xyLayout, 3, vertexOffsets), placedOutlines = StripArrays.Outlines(onPlane, 3, vertexOffsets);
                    StripMesh[] quads = StripArrays.Split(xyLayout, 3, strips.Quads(), vertexOffsets, quadOffsets);
                    double previousTop = double.NegativeInfinity;
                    for (int s = 0; s < strips.Count; s++)
                    {
                        int first = outlines.Offsets[s], last = outlines.Offsets[s + 1] - 1;
                        Assert.AreEqual(vertexOffsets[s + 1] - vertexOffsets[s] + 1, last - first + 1);
                        CollectionAssert.AreEqual(Vec.At(placedOutlines.Values, first), Vec.At(placedOutlines.Values, last), "closed on the plane");
                        double area = 0;
                        for (int q = 0; q < quads[s].Quads.Length / 4; q++)
                        {
                            var corners = new List<double>();
                            for (int k = 0; k < 4; k++) corners.AddRange(Vec.At(quads[s].Vertices, quads[s].Quads[4 * q + k]));
                            area += Math.Abs(ShoelaceArea(corners.ToArray(), 3, 0, 4));
                        }
                        Assert.AreEqual(area, Math.Abs(ShoelaceArea(outlines.Values, 3, first, last + 1)), 1e-9 * area, "the outline encloses the strip's quads");
                        double bottom = double.PositiveInfinity, top = double.NegativeInfinity;
                        for (int k = first; k <= last; k++)
                        {
                            bottom = Math.Min(bottom, outlines.Values[3 * k + 1]);
                            top = Math.Max(top, outlines.Values[3 * k + 1]);
                        }
                        Assert.GreaterOrEqual(bottom - previousTop, gap - 1e-9, "strip " + s + " clears the one before by the gap");
                        previousTop = top;
                        Assert.IsTrue(Inside(outlines.Values, first, last, labels[3 * s], labels[3 * s + 1]), "label of strip " + s + " on its strip");
                    }
                }
            }
        }

        /// <summary>Signed area of the XY projection of a polygon given by points [first, end) with <paramref name="dimension"/> values each (closed or not).</summary>
        private static double ShoelaceArea(double[] points, int dimension, int first, int end)
        {
            double area = 0;
            for (int i = first; i < end; i++)
            {
                int j = i + 1 < end ? i + 1 : first;
                area += points[dimension * i] * points[dimension * j + 1] - points[dimension * j] * points[dimension * i + 1];
            }
            return 0.5 * area;
        }

        /// <summary>Whether (x, y) lies inside the closed XY polygon [first, last] (x, y, z per point; last repeats first).</summary>
        private static bool Inside(double[] p, int first, int last, double x, double y)
        {
            bool inside = false;
            for (int i = first; i < last; i++)
            {
                double xi = p[3 * i], yi = p[3 * i + 1], xj = p[3 * (i + 1)], yj = p[3 * (i + 1) + 1];
                if ((yi > y) != (yj > y) && x < (xj - xi) * (y - yi) / (yj - yi) + xi) inside = !inside;
            }
            return inside;
        }
    }
}
