using System;
using System.Collections.Generic;
using Lamella.Conversion;
using NUnit.Framework;

namespace Lamella.Tests
{
    /// <summary>Sketched strokes made ready for the library, on plain arrays.</summary>
    [TestFixture]
    public class StrokeArraysTests
    {
        [Test]
        public void DensifyKeepsThePointsAndSplitsLongSegmentsEvenly()
        {
            // Segments of length 1, 2.5 and 0 (a repeated point).
            double[] stroke = { 0, 0, 0, 1, 0, 0, 1, 2.5, 0, 1, 2.5, 0 };
            double[] dense = StrokeArrays.Densify(stroke, 1.0);
            // 1 stays whole, 2.5 becomes ⌈2.5⌉ = 3 parts of 5/6, the zero-length segment stays.
            double[] expected = { 0, 0, 0, 1, 0, 0, 1, 2.5 / 3, 0, 1, 5.0 / 3, 0, 1, 2.5, 0, 1, 2.5, 0 };
            Assert.AreEqual(expected.Length, dense.Length);
            for (int i = 0; i < expected.Length; i++) Assert.AreEqual(expected[i], dense[i], 1e-15, "value " + i);
            for (int i = 1; i < dense.Length / 3; i++)
            {
                Assert.LessOrEqual(Vec.Distance(Vec.At(dense, i - 1), Vec.At(dense, i)), 1.0 + 1e-15);
            }
            // Already fine enough: unchanged.
            CollectionAssert.AreEqual(stroke, StrokeArrays.Densify(stroke, 3.0));
            // A single point and an empty stroke pass through.
            CollectionAssert.AreEqual(new double[] { 1, 2, 3 }, StrokeArrays.Densify(new double[] { 1, 2, 3 }, 0.1));
            CollectionAssert.IsEmpty(StrokeArrays.Densify(new double[0], 0.1));
        }

        [Test]
        public void DensifiedPointsLieOnTheOriginalSegments()
        {
            double[] stroke = { 0, 0, 0, 3, 4, 12 };
            double[] dense = StrokeArrays.Densify(stroke, 0.7);
            // Length 13: ⌈13 / 0.7⌉ = 19 parts, 20 points, each on the line at i/19 of the way.
            Assert.AreEqual(3 * 20, dense.Length);
            for (int i = 0; i < 20; i++)
            {
                double s = i / 19.0;
                Assert.Less(Vec.Distance(Vec.At(dense, i), new[] { 3 * s, 4 * s, 12 * s }), 1e-12, "point " + i);
            }
        }

        [Test]
        public void DensifyRejectsBadInput()
        {
            Assert.Throws<ArgumentException>(() => StrokeArrays.Densify(new double[4], 1));
            Assert.Throws<ArgumentOutOfRangeException>(() => StrokeArrays.Densify(new double[6], 0));
            Assert.Throws<ArgumentOutOfRangeException>(() => StrokeArrays.Densify(new double[6], double.NaN));
            Assert.Throws<ArgumentException>(() => StrokeArrays.Densify(new double[] { 0, 0, 0, double.PositiveInfinity, 0, 0 }, 1));
            Assert.Throws<ArgumentException>(() => StrokeArrays.Densify(new double[] { 0, 0, 0, 1e9, 0, 0 }, 1e-3));
        }

        [Test]
        public void MeanEdgeLengthCountsSharedEdgesOnce()
        {
            // The unit square as two triangles: four sides of 1 and the diagonal √2, the diagonal shared.
            double[] xyz = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0 };
            Assert.AreEqual((4 + Math.Sqrt(2)) / 5, StrokeArrays.MeanEdgeLength(xyz, new[] { 0, 1, 2, 0, 2, 3 }), 1e-15);
            Assert.AreEqual(0.0, StrokeArrays.MeanEdgeLength(xyz, new int[0]));
            Assert.Throws<ArgumentOutOfRangeException>(() => StrokeArrays.MeanEdgeLength(xyz, new[] { 0, 1, 4 }));
            Assert.Throws<ArgumentException>(() => StrokeArrays.MeanEdgeLength(xyz, new[] { 0, 1 }));
        }

        [Test]
        public void StrokesPackIntoPointsAndOffsets()
        {
            // The layout InitialField.FromStrokes hands to the library: points, then count + 1 offsets in points.
            var strokes = new List<double[]> { StrokeArrays.Densify(new double[] { 0, 0, 0, 2, 0, 0 }, 1), new double[] { 0, 1, 0, 1, 1, 0 } };
            Packed packed = Packing.Pack(strokes, 3);
            CollectionAssert.AreEqual(new[] { 0, 3, 5 }, packed.Offsets);
            CollectionAssert.AreEqual(new double[] { 0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1, 0 }, packed.Values);
        }
    }
}
