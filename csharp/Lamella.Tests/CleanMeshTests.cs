using System;
using System.Globalization;
using System.Linq;
using System.Threading;
using Lamella.Conversion;
using NUnit.Framework;

namespace Lamella.Tests
{
    /// <summary>Mesh cleaning before the library sees a CAD mesh, and the vertex map back to the input.</summary>
    [TestFixture]
    public class CleanMeshTests
    {
        [Test]
        public void CleanMeshIsUsedVertexForVertex()
        {
            var grid = new Grid(6, 4, 1.0, 0, 0);
            CleanMesh clean = CleanMesh.FromFaces(grid.Xyz, grid.Quads, 1e-3);
            Assert.IsFalse(clean.Changed);
            Assert.IsNull(clean.Describe());
            CollectionAssert.AreEqual(grid.Xyz, clean.Xyz);
            CollectionAssert.AreEqual(grid.Triangles(), clean.Triangles);
            CollectionAssert.AreEqual(Enumerable.Range(0, grid.VertexCount).ToArray(), clean.VertexMap);
        }

        /// <summary>
        /// Two patches meshed separately (as Rhino meshes a polysurface) share a seam whose vertices are duplicated and
        /// off by 1e-6: the library sees two components, the clean copy one disk, and per-vertex values come back on
        /// both copies of each seam vertex.
        /// </summary>
        [Test]
        public void UnweldedPatchesBecomeOneSurface()
        {
            Grid left = new Grid(4, 4, 1.0, 0, 0), right = new Grid(4, 4, 1.0, 4, 0);
            double[] xyz = left.Xyz.Concat(right.Xyz).ToArray();
            for (int j = 0; j <= 4; j++) xyz[3 * (left.VertexCount + 5 * j)] += 1e-6; // the right patch's seam column
            int[] quads = left.Quads.Concat(right.Quads.Select(v => v + left.VertexCount)).ToArray();

            Assert.Throws<LamellaException>(() => LamellaMesh.FromArrays(xyz, MeshArrays.Triangulate(xyz, quads)).Dispose(), "two components");

            CleanMesh clean = CleanMesh.FromFaces(xyz, quads, 1e-4);
            Assert.AreEqual(5, clean.WeldedVertices);
            Assert.AreEqual(9 * 5, clean.VertexCount);
            Assert.AreEqual(2 * 8 * 4, clean.Triangles.Length / 3);
            StringAssert.Contains("5 coincident vertices welded (within 0.0001)", clean.Describe());
            using (var mesh = LamellaMesh.FromArrays(clean.Xyz, clean.Triangles))
            {
                Assert.AreEqual(45, mesh.VertexCount);
            }
            // Each right seam vertex maps to the left vertex it was welded to, which keeps its own position.
            for (int j = 0; j <= 4; j++)
            {
                int leftSeam = 5 * j + 4, rightSeam = left.VertexCount + 5 * j;
                Assert.AreEqual(clean.VertexMap[leftSeam], clean.VertexMap[rightSeam]);
                Assert.AreEqual(4.0, clean.Xyz[3 * clean.VertexMap[leftSeam]]);
            }
            double[] perClean = Enumerable.Range(0, clean.VertexCount).Select(v => (double)v).ToArray();
            double[] perInput = clean.ToInputVertices(perClean, 1, double.NaN);
            Assert.AreEqual(xyz.Length / 3, perInput.Length);
            for (int v = 0; v < perInput.Length; v++) Assert.AreEqual(clean.VertexMap[v], perInput[v]);
        }

        [Test]
        public void DegenerateRepeatedAndUnusedAreRemovedAndReported()
        {
            var grid = new Grid(2, 2, 1.0, 0, 0);
            // Vertex 9 is used by nothing; vertex 10 sits on the edge 0–1, so the triangle 0 10 1 has zero area.
            double[] xyz = grid.Xyz.Concat(new[] { 50.0, 50, 0, 0.5, 0, 0 }).ToArray();
            int[] extra =
            {
                0, 10, 1, 1, // zero area
                4, 0, 1, 1, // the first triangle of the first quad again, turned
                2, 2, 5, 5, // a repeated corner
            };
            CleanMesh clean = CleanMesh.FromFaces(xyz, grid.Quads.Concat(extra).ToArray(), 1e-6);
            Assert.AreEqual(0, clean.WeldedVertices);
            Assert.AreEqual(2, clean.DegenerateTriangles);
            Assert.AreEqual(1, clean.RepeatedTriangles);
            Assert.AreEqual(2, clean.UnusedVertices);
            Assert.AreEqual(9, clean.VertexCount);
            CollectionAssert.AreEqual(grid.Triangles(), clean.Triangles);
            Assert.AreEqual(-1, clean.VertexMap[9]);
            Assert.AreEqual(-1, clean.VertexMap[10]);
            string remark = clean.Describe();
            StringAssert.Contains("2 degenerate triangles", remark);
            StringAssert.Contains("1 repeated triangle removed", remark);
            StringAssert.Contains("2 unused vertices dropped", remark);
            StringAssert.Contains("input mesh's 11 vertices", remark);
            double[] back = clean.ToInputVertices(new double[3 * 9], 3, double.NaN);
            Assert.IsTrue(double.IsNaN(back[3 * 9]) && double.IsNaN(back[3 * 10 + 2]));
            using (var mesh = LamellaMesh.FromArrays(clean.Xyz, clean.Triangles))
            {
                Assert.AreEqual(8, mesh.TriangleCount);
            }
        }

        [Test]
        public void QuadWithTwoWeldedCornersBecomesATriangle()
        {
            double[] xyz = { 0, 0, 0, 1, 0, 0, 1, 1e-9, 0, 0, 1, 0 };
            CleanMesh clean = CleanMesh.FromFaces(xyz, new[] { 0, 1, 2, 3 }, 1e-6);
            Assert.AreEqual(1, clean.WeldedVertices);
            Assert.AreEqual(0, clean.DegenerateTriangles);
            CollectionAssert.AreEqual(new[] { 0, 1, 2 }, clean.Triangles);
            CollectionAssert.AreEqual(new[] { 0, 1, 1, 2 }, clean.VertexMap);
        }

        [Test]
        public void ZeroToleranceWeldsIdenticalPositionsOnly()
        {
            double[] xyz = { 0, 0, 0, 1, 0, 0, 0, 1, 0, -0.0, 0, 0, 1e-12, 1, 0 };
            CleanMesh clean = CleanMesh.FromFaces(xyz, new[] { 0, 1, 2, 2, 3, 1, 4, 4 }, 0);
            Assert.AreEqual(1, clean.WeldedVertices, "−0 equals +0; 1e-12 away is another vertex");
            Assert.AreEqual(clean.VertexMap[0], clean.VertexMap[3]);
            Assert.AreNotEqual(clean.VertexMap[2], clean.VertexMap[4]);
        }

        [Test]
        public void BadInputIsNamed()
        {
            var nan = Assert.Throws<ArgumentException>(() => CleanMesh.FromFaces(new[] { 0, 0, 0, double.NaN, 0, 0, 0, 1, 0 }, new[] { 0, 1, 2, 2 }, 0.1));
            StringAssert.Contains("vertex 1", nan.Message);
            var range = Assert.Throws<ArgumentOutOfRangeException>(() => CleanMesh.FromFaces(new double[9], new[] { 0, 1, 3, 3 }, 0.1));
            StringAssert.Contains("face 0", range.Message);
            Assert.Throws<ArgumentOutOfRangeException>(() => CleanMesh.FromFaces(new double[9], new[] { 0, 1, 2, 2 }, -1));
            Assert.Throws<ArgumentOutOfRangeException>(() => CleanMesh.FromFaces(new double[9], new[] { 0, 1, 2, 2 }, double.NaN));
            Assert.Throws<ArgumentException>(() => CleanMesh.FromFaces(new double[9], new[] { 0, 1, 2 }, 0.1));
        }

        [Test]
        public void RemarkIsCultureInvariant()
        {
            CultureInfo saved = Thread.CurrentThread.CurrentCulture;
            try
            {
                Thread.CurrentThread.CurrentCulture = new CultureInfo("de-DE");
                double[] xyz = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1e-5 };
                StringAssert.Contains("within 0.0005", CleanMesh.FromFaces(xyz, new[] { 0, 1, 2, 2, 3, 1, 2, 2 }, 0.0005).Describe());
            }
            finally
            {
                Thread.CurrentThread.CurrentCulture = saved;
            }
        }
    }
}
