using System;
using System.Collections.Generic;
using Lamella.Conversion;
using NUnit.Framework;

namespace Lamella.Tests
{
    /// <summary>The pure array conversions used between CAD geometry and the C ABI, on plain arrays.</summary>
    [TestFixture]
    public class ConversionTests
    {
        [Test]
        public void TrianglesPassThroughAndQuadsSplitAlongTheShorterDiagonal()
        {
            // A triangle (0 1 2, fourth corner repeated) and a quad 1 3 4 2 whose diagonal 3–2 is shorter than 1–4.
            double[] xyz = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 2, 0, 0, 3, 3, 0 };
            int[] faces = { 0, 1, 2, 2, 1, 3, 4, 2 };
            int[] triangles = MeshArrays.Triangulate(xyz, faces);
            CollectionAssert.AreEqual(new[] { 0, 1, 2, 1, 3, 2, 3, 4, 2 }, triangles);
            // Every triangle keeps the +z orientation of its face.
            for (int t = 0; t < triangles.Length / 3; t++)
            {
                double[] a = Vec.At(xyz, triangles[3 * t]), b = Vec.At(xyz, triangles[3 * t + 1]), c = Vec.At(xyz, triangles[3 * t + 2]);
                Assert.Greater(Vec.Cross(Vec.Sub(b, a), Vec.Sub(c, a))[2], 0, "triangle " + t);
            }
        }

        [Test]
        public void TriangulatedQuadsCoverTheQuadsArea()
        {
            // A unit square split either way has area 1 in two triangles of area 1/2.
            double[] xyz = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0 };
            int[] triangles = MeshArrays.Triangulate(xyz, new[] { 0, 1, 2, 3 });
            Assert.AreEqual(6, triangles.Length);
            for (int t = 0; t < 2; t++)
            {
                double[] a = Vec.At(xyz, triangles[3 * t]), b = Vec.At(xyz, triangles[3 * t + 1]), c = Vec.At(xyz, triangles[3 * t + 2]);
                Assert.AreEqual(0.5, 0.5 * Vec.Norm(Vec.Cross(Vec.Sub(b, a), Vec.Sub(c, a))), 1e-15);
            }
        }

        [Test]
        public void TriangulateRejectsBadFaces()
        {
            Assert.Throws<ArgumentException>(() => MeshArrays.Triangulate(new double[9], new[] { 0, 1, 2 }));
            Assert.Throws<ArgumentOutOfRangeException>(() => MeshArrays.Triangulate(new double[9], new[] { 0, 1, 3, 3 }));
        }

        [Test]
        public void PolylinesPackAndUnpack()
        {
            var polylines = new List<double[]> { new double[] { 0, 0, 0, 1, 0, 0 }, new double[0], new double[] { 5, 5, 5, 6, 6, 6, 7, 7, 7 } };
            Packed packed = Packing.Pack(polylines, 3);
            CollectionAssert.AreEqual(new[] { 0, 2, 2, 5 }, packed.Offsets);
            Assert.AreEqual(15, packed.Values.Length);
            Assert.AreEqual(3, packed.Count);
            double[][] back = Packing.Unpack(packed);
            for (int i = 0; i < 3; i++) CollectionAssert.AreEqual(polylines[i], back[i]);
            Assert.Throws<ArgumentException>(() => Packing.Pack(new List<double[]> { new double[4] }, 3));
            Assert.Throws<ArgumentException>(() => Packing.Unpack(new Packed(new double[6], new[] { 0, 3 }, 3)));
            Assert.Throws<ArgumentException>(() => Packing.Unpack(new Packed(new double[6], new[] { 0, 2, 1 }, 3)));
        }

        [Test]
        public void IndexedPolylinesGatherTheirPoints()
        {
            double[] xyz = { 0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 3, 3 };
            Packed packed = Packing.Gather(xyz, new[] { new[] { 3, 0 }, new[] { 1, 2, 3 } });
            CollectionAssert.AreEqual(new[] { 0, 2, 5 }, packed.Offsets);
            CollectionAssert.AreEqual(new double[] { 3, 3, 3, 0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 3, 3 }, packed.Values);
            Assert.Throws<ArgumentOutOfRangeException>(() => Packing.Gather(xyz, new[] { new[] { 4 } }));
        }

        [Test]
        public void FacesOfAnySizeBecomeFansOfTriangles()
        {
            // A triangle and a hexagon (a Kagome pattern's faces): 1 + 4 triangles, each from the face's first corner.
            int[] triangles = MeshArrays.FanTriangles(new[] { new[] { 0, 1, 2 }, new[] { 3, 4, 5, 6, 7, 8 } });
            CollectionAssert.AreEqual(new[] { 0, 1, 2, 3, 4, 5, 3, 5, 6, 3, 6, 7, 3, 7, 8 }, triangles);
            Assert.Throws<ArgumentException>(() => MeshArrays.FanTriangles(new[] { new[] { 0, 1 } }));
        }

        /// <summary>Two strips in the C ABI's layout: 3 and 2 centre points, so 6 and 4 vertices, 2 and 1 quads.</summary>
        private static readonly int[] VertexOffsets = { 0, 6, 10 };
        private static readonly int[] QuadOffsets = { 0, 2, 3 };
        private static readonly int[] Quads = { 0, 1, 4, 3, 1, 2, 5, 4, 6, 7, 9, 8 };

        private static double[] Vertices()
        {
            // Strip 0 along x at y = ±0.5, strip 1 along x at z = 10, y = ±1.
            return new double[] { 0, 0.5, 0, 1, 0.5, 0, 2, 0.5, 0, 0, -0.5, 0, 1, -0.5, 0, 2, -0.5, 0, 0, 1, 10, 4, 1, 10, 0, -1, 10, 4, -1, 10 };
        }

        [Test]
        public void StripsSplitIntoMeshesWithLocalIndices()
        {
            StripMesh[] meshes = StripArrays.Split(Vertices(), 3, Quads, VertexOffsets, QuadOffsets);
            Assert.AreEqual(2, meshes.Length);
            Assert.AreEqual(18, meshes[0].Vertices.Length);
            CollectionAssert.AreEqual(new[] { 0, 1, 4, 3, 1, 2, 5, 4 }, meshes[0].Quads);
            CollectionAssert.AreEqual(new[] { 0, 1, 3, 2 }, meshes[1].Quads);
            CollectionAssert.AreEqual(new double[] { 0, 1, 10 }, new[] { meshes[1].Vertices[0], meshes[1].Vertices[1], meshes[1].Vertices[2] });
            // A quad reaching into another strip's vertices is refused.
            Assert.Throws<ArgumentException>(() => StripArrays.Split(Vertices(), 3, new[] { 0, 1, 7, 3, 1, 2, 5, 4, 6, 7, 9, 8 }, VertexOffsets, QuadOffsets));
        }

        [Test]
        public void RulingsJoinTheTwoBoundaries()
        {
            double[] segments = StripArrays.RulingSegments(Vertices(), VertexOffsets);
            Assert.AreEqual(5 * 6, segments.Length);
            // Strip 0, point 1: from left_1 (1, 0.5, 0) to right_1 (1, −0.5, 0).
            CollectionAssert.AreEqual(new double[] { 1, 0.5, 0, 1, -0.5, 0 }, new ArraySegment<double>(segments, 6, 6));
            // Strip 1, point 0: (0, 1, 10) to (0, −1, 10).
            CollectionAssert.AreEqual(new double[] { 0, 1, 10, 0, -1, 10 }, new ArraySegment<double>(segments, 18, 6));
        }

        [Test]
        public void FlatStripsAreStackedWithoutOverlapAndKeepTheirShape()
        {
            // Unrolled: both strips start at the origin along +x (overlapping before the layout).
            double[] flat = { 0, 0.5, 1, 0.5, 2, 0.5, 0, -0.5, 1, -0.5, 2, -0.5, 0, 1, 4, 1, 0, -1, 4, -1 };
            double[] xyz = StripArrays.LayOutFlat(flat, VertexOffsets, 0.25);
            Assert.AreEqual(30, xyz.Length);
            // Strip 0 spans y in [0, 1], strip 1 starts 0.25 above it and spans [1.25, 3.25]; z = 0; x from 0.
            double top0 = double.NegativeInfinity, bottom1 = double.PositiveInfinity;
            for (int v = 0; v < 10; v++)
            {
                Assert.AreEqual(0.0, xyz[3 * v + 2]);
                if (v < 6) top0 = Math.Max(top0, xyz[3 * v + 1]); else bottom1 = Math.Min(bottom1, xyz[3 * v + 1]);
            }
            Assert.AreEqual(1.0, top0, 1e-15);
            Assert.AreEqual(1.25, bottom1, 1e-15);
            // Translations only: distances inside a strip are kept.
            for (int a = 6; a < 10; a++)
                for (int b = 6; b < 10; b++)
                    Assert.AreEqual(Vec.Distance2(flat, a, b), Vec.Distance(Vec.At(xyz, a), Vec.At(xyz, b)), 1e-12);
            Assert.Throws<ArgumentOutOfRangeException>(() => StripArrays.LayOutFlat(flat, VertexOffsets, double.NaN));
        }
    }
}

namespace Lamella.Tests
{
    [TestFixture]
    public class SignatureTests
    {
        [Test]
        public void SignatureChangesWithAnyInputBit()
        {
            double[] xyz = { 0, 0, 0, 1, 0, 0, 0, 1, 0 };
            int[] tris = { 0, 1, 2 };
            string a = Signature.Of(xyz, tris, 60, 1);
            Assert.AreEqual(64, a.Length);
            Assert.AreEqual(a, Signature.Of((double[])xyz.Clone(), (int[])tris.Clone(), 60, 1), "deterministic");
            Assert.AreNotEqual(a, Signature.Of(xyz, tris, 60, 1.0000000000000002), "one ulp of a parameter");
            Assert.AreNotEqual(a, Signature.Of(new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 1e-300 }, tris, 60, 1), "a coordinate");
            Assert.AreNotEqual(a, Signature.Of(xyz, new[] { 0, 2, 1 }, 60, 1), "the orientation");
            Assert.AreNotEqual(a, Signature.Of(xyz, tris, 60), "the parameter count");
        }
    }
}

namespace Lamella.Tests
{
    [TestFixture]
    public class StartFieldTests
    {
        [Test]
        public void HeightAlongANormalisedDirection()
        {
            double[] xyz = { 1, 2, 3, -1, 0, 4 };
            CollectionAssert.AreEqual(new double[] { 3, 4 }, StartField.Height(xyz, 0, 0, 7));
            double[] diagonal = StartField.Height(xyz, 1, 1, 0);
            Assert.AreEqual(3 / Math.Sqrt(2), diagonal[0], 1e-15);
            Assert.AreEqual(-1 / Math.Sqrt(2), diagonal[1], 1e-15);
            Assert.Throws<ArgumentException>(() => StartField.Height(xyz, 0, 0, 0));
            Assert.Throws<ArgumentException>(() => StartField.Height(xyz, double.NaN, 0, 1));
        }
    }
}
