using System;
using System.Collections.Generic;
using System.Linq;
using Lamella.Conversion;
using NUnit.Framework;

namespace Lamella.Tests
{
    /// <summary>
    /// Base-mesh optimisation through the binding (paper Sec. 3.5) with torsion-free nodes (Sec. 5.2.1, Eq. 21): the net
    /// of ±45° helices on the cylinder, perturbed and optimised back, judged from outside (on the cylinder, geodesic
    /// against its exact normal, node ruling angles, planar strips sharing the rulings at the nodes); a saved session
    /// stepping on to the same bits; the rows and columns of a quad mesh; a strip net's quad net as the start; invalid
    /// arguments.
    /// </summary>
    [TestFixture]
    public class BaseMeshTests
    {
        /// <summary>The largest |angle − 90°| between a polyline's discrete binormal and the cylinder's exact normal at its inner vertices.</summary>
        private static double WorstGeodesicError(double[] xyz, int[][] lines)
        {
            double worst = 0;
            foreach (int[] line in lines)
            {
                for (int a = 1; a + 1 < line.Length; a++)
                {
                    worst = Math.Max(worst, Math.Abs(Cylinder.BinormalAngle(Vec.At(xyz, line[a - 1]), Vec.At(xyz, line[a]), Vec.At(xyz, line[a + 1])) - 90));
                }
            }
            return worst;
        }

        /// <summary>The angle in degrees between two directions as lines.</summary>
        private static double LineAngle(double[] a, double[] b) => Vec.Degrees(Math.Abs(Vec.Dot(a, b)) / (Vec.Norm(a) * Vec.Norm(b)));

        [Test]
        public void APerturbedNetOfHelicesIsRestoredToATorsionFreeGeodesicNet()
        {
            // A reference cell about half the net's spacing (on cells as wide as the net's, its facets hold the nodes off torsion-free).
            var cylinder = new Cylinder(72, 40, 7);
            var net = new HelixNet(0.02);
            using (var reference = LamellaMesh.FromArrays(cylinder.Xyz, cylinder.Triangles))
            using (var solver = new BaseMeshSolver(reference, net.Points, net.Rows, net.Columns, 90.0, 90.0, true))
            {
                BaseMeshReport initial = solver.InitialReport, report = solver.Report;
                Assert.AreEqual(0, initial.Iterations);
                CollectionAssert.AreEqual(new[] { 90.0, 90.0 }, initial.TargetDegrees);
                Assert.IsFalse(initial.IsTorsionFree);
                Assert.Greater(initial.NodeRulingAngleMaxDegrees, 10.0);
                while (report.Iterations < 300 && !report.IsConverged) report = solver.Step(10);
                Assert.IsTrue(report.IsConverged, report.Describe());
                Assert.IsTrue(report.FamiliesMet && report.IsTorsionFree, report.Describe());
                Assert.LessOrEqual(report.NodeRulingAngleMaxDegrees, 0.5);
                Assert.AreEqual(report.Iterations, solver.Step(10).Iterations, "a converged session does not step");

                // From outside: on the cylinder (the reference lies between it and its chords: sagitta of the widest cell,
                // 10 (1 − cos(0.75 · 150°/72)) = 0.0037), geodesic against its exact normal.
                double[] xyz = solver.Positions();
                Assert.AreEqual(net.Points.Length, xyz.Length);
                for (int v = 0; v < xyz.Length / 3; v++)
                {
                    Assert.AreEqual(Cylinder.Radius, Math.Sqrt(xyz[3 * v] * xyz[3 * v] + xyz[3 * v + 1] * xyz[3 * v + 1]), 0.0037 + 0.002);
                }
                Assert.LessOrEqual(WorstGeodesicError(xyz, net.Rows), 1.0);
                Assert.LessOrEqual(WorstGeodesicError(xyz, net.Columns), 1.0);

                // The nodes: every vertex inside a row and a column; the report's maximum is theirs.
                BaseMeshNode[] nodes = solver.Nodes();
                BaseMeshNode[] defined = nodes.Where(n => n.RulingAngleDegrees.HasValue).ToArray();
                Assert.AreEqual(report.NodeCount, defined.Length);
                Assert.AreEqual(report.NodeRulingAngleMaxDegrees, defined.Max(n => n.RulingAngleDegrees.Value));
                foreach (BaseMeshNode node in defined) Assert.AreEqual(1.0, Vec.Norm(node.Axis), 1e-9);

                // The strips: acceptable, planar quads, and at every node the row's and the column's rulings at the
                // node's reported angle.
                var rulingAt = new Dictionary<int, double[]>[] { new Dictionary<int, double[]>(), new Dictionary<int, double[]>() };
                for (int k = 0; k < 2; k++)
                {
                    int[][] lines = k == 0 ? net.Rows : net.Columns;
                    using (Strips strips = solver.BuildStrips(k, 0.3, 1.0))
                    {
                        Assert.IsTrue(strips.Verdict.IsAcceptable, strips.Verdict.ToString());
                        double[] vertices = strips.Vertices(), rulings = strips.Rulings();
                        int[] quads = strips.Quads(), offsets = strips.PointOffsets();
                        for (int q = 0; q < quads.Length; q += 4)
                        {
                            double[] a = Vec.At(vertices, quads[q]);
                            double[] u = Vec.Sub(Vec.At(vertices, quads[q + 1]), a), w = Vec.Sub(Vec.At(vertices, quads[q + 2]), a), x = Vec.Sub(Vec.At(vertices, quads[q + 3]), a);
                            Assert.Less(Math.Abs(Vec.Dot(u, Vec.Cross(w, x))) / (Vec.Norm(u) * Vec.Norm(w) * Vec.Norm(x)), 1e-9, "a planar quad");
                        }
                        StripMetrics[] metrics = strips.Metrics();
                        for (int s = 0; s < metrics.Length; s++)
                        {
                            int[] line = lines[metrics[s].Curve];
                            for (int i = 0; i < line.Length; i++) rulingAt[k][line[i]] = Vec.At(rulings, offsets[s] + i);
                        }
                    }
                }
                foreach (BaseMeshNode node in defined)
                {
                    Assert.AreEqual(node.RulingAngleDegrees.Value, LineAngle(rulingAt[0][node.Vertex], rulingAt[1][node.Vertex]), 1e-6);
                }
            }
        }

        [Test]
        public void HelicesOptimisedForConstantSlopeGetVerticalNodeAxes()
        {
            // A helix climbs its development's diagonal: 45° against the horizontal planes.
            var cylinder = new Cylinder(72, 40, 7);
            var net = new HelixNet(0.02);
            using (var reference = LamellaMesh.FromArrays(cylinder.Xyz, cylinder.Triangles))
            using (var solver = BaseMeshSolver.ConstantSlopes(reference, net.Points, net.Rows, net.Columns, 45.0, 45.0, new[] { 0.0, 0.0, 3.0 }))
            {
                BaseMeshReport report = solver.Report;
                while (report.Iterations < 300 && !report.IsConverged) report = solver.Step(10);
                Assert.IsTrue(report.FamiliesMet && report.IsTorsionFree, report.Describe());
                double[] xyz = solver.Positions();
                foreach (int[] line in net.Rows.Concat(net.Columns))
                {
                    for (int i = 0; i + 1 < line.Length; i++)
                    {
                        int a = line[i], b = line[i + 1];
                        double dx = xyz[3 * b] - xyz[3 * a], dy = xyz[3 * b + 1] - xyz[3 * a + 1], dz = xyz[3 * b + 2] - xyz[3 * a + 2];
                        double slope = Math.Abs(Math.Asin(dz / Math.Sqrt(dx * dx + dy * dy + dz * dz))) * 180.0 / Math.PI;
                        Assert.AreEqual(45.0, slope, 0.5);
                    }
                }
                BaseMeshNode[] nodes = solver.Nodes();
                Assert.Greater(nodes.Length, 200);
                foreach (BaseMeshNode node in nodes)
                {
                    Assert.LessOrEqual(node.RulingAngleDegrees.Value, 0.5);
                    Assert.GreaterOrEqual(Math.Abs(node.Axis[2]), Math.Cos(0.5 * Math.PI / 180.0));
                }
            }
            using (var reference = LamellaMesh.FromArrays(cylinder.Xyz, cylinder.Triangles))
            {
                var error = Assert.Throws<LamellaException>(() => BaseMeshSolver.ConstantSlopes(reference, net.Points, net.Rows, net.Columns, 45.0, 45.0, new double[3]));
                StringAssert.Contains("axis", error.Message);
                Assert.Throws<ArgumentException>(() => BaseMeshSolver.ConstantSlopes(reference, net.Points, net.Rows, net.Columns, 45.0, 45.0, new double[2]));
            }
        }

        [Test]
        public void ASavedSessionStepsOnToTheSameBits()
        {
            var cylinder = new Cylinder(36, 20, 7);
            var net = new HelixNet(0.02);
            using (var reference = LamellaMesh.FromArrays(cylinder.Xyz, cylinder.Triangles))
            using (var solver = new BaseMeshSolver(reference, net.Points, net.Rows, net.Columns, 90.0, 90.0, true))
            {
                solver.Step(3);
                byte[] bytes = solver.Save();
                CollectionAssert.AreEqual(new byte[] { 76, 77, 76, 66 }, bytes.Take(4).ToArray(), "the magic \"LMLB\"");
                using (var restored = BaseMeshSolver.Load(bytes))
                {
                    CollectionAssert.AreEqual(bytes, restored.Save());
                    CollectionAssert.AreEqual(solver.Positions(), restored.Positions());
                    Assert.AreEqual(solver.InitialReport.Describe(), restored.InitialReport.Describe());
                    BaseMeshReport mine = solver.Step(5), theirs = restored.Step(5);
                    Assert.AreEqual(8, theirs.Iterations);
                    Assert.AreEqual(mine.Describe(), theirs.Describe());
                    Assert.AreEqual(mine.Energy, theirs.Energy);
                    CollectionAssert.AreEqual(solver.Positions(), restored.Positions(), "the same bits after stepping on");
                }
                var error = Assert.Throws<LamellaException>(() => BaseMeshSolver.Load(bytes.Take(bytes.Length - 1).ToArray()));
                Assert.AreEqual(Status.CorruptData, error.Status);
                error = Assert.Throws<LamellaException>(() => BaseMeshSolver.Load(new byte[] { 76, 77, 76, 78 }));
                Assert.AreEqual(Status.CorruptData, error.Status);
                byte[] netMagic = (byte[])bytes.Clone();
                netMagic[3] = 78; // "LMLN", a net session's magic
                error = Assert.Throws<LamellaException>(() => BaseMeshSolver.Load(netMagic));
                StringAssert.Contains("not a Lamella base-mesh session", error.NativeMessage);
                Assert.Throws<ArgumentNullException>(() => BaseMeshSolver.Load(null));
            }
        }

        [Test]
        public void TheQuadsOfANetGiveItsRowsAndColumns()
        {
            // A grid's quads start along its x rows: the rows are its rows, each along increasing x.
            var grid = new Grid(4, 3, 1.0, 0.0, 0.0);
            int[][][] lines = NetPolylines.FromQuads(grid.Quads, grid.VertexCount);
            Assert.AreEqual(4, lines[0].Length);
            CollectionAssert.AreEqual(new[] { 5, 6, 7, 8, 9 }, lines[0][1]);
            Assert.AreEqual(5, lines[1].Length);
            CollectionAssert.AreEqual(new[] { 2, 7, 12, 17 }, lines[1][2]);
            // Where each quad starts does not matter once the first quad is fixed.
            int[] turned = (int[])grid.Quads.Clone();
            for (int q = 4; q < turned.Length; q += 8)
            {
                int first = turned[q];
                Array.Copy(turned, q + 1, turned, q, 3);
                turned[q + 3] = first;
            }
            int[][][] again = NetPolylines.FromQuads(turned, grid.VertexCount);
            CollectionAssert.AreEqual(lines[0], again[0]);
            CollectionAssert.AreEqual(lines[1], again[1]);
            // The helix net's quads give back its rows and columns.
            var net = new HelixNet(0.0);
            int[][][] helices = NetPolylines.FromQuads(net.Quads, net.Points.Length / 3);
            CollectionAssert.AreEquivalent(net.Rows.Where(r => r.Length > 2).Select(r => string.Join(",", r)), helices[0].Where(r => r.Length > 2).Select(r => string.Join(",", r)));
            CollectionAssert.AreEquivalent(net.Columns.Where(c => c.Length > 2).Select(c => string.Join(",", c)), helices[1].Where(c => c.Length > 2).Select(c => string.Join(",", c)));

            var error = Assert.Throws<ArgumentException>(() => NetPolylines.FromQuads(new[] { 0, 1, 2, 2 }, 3));
            StringAssert.Contains("quad 0 repeats vertex 2", error.Message);
            error = Assert.Throws<ArgumentException>(() => NetPolylines.FromQuads(new[] { 0, 1, 2, 7 }, 4));
            StringAssert.Contains("refers to vertex 7", error.Message);
            // A ring of quads: its rows close.
            error = Assert.Throws<ArgumentException>(() => NetPolylines.FromQuads(new[] { 0, 1, 4, 3, 1, 2, 5, 4, 2, 0, 3, 5 }, 6));
            StringAssert.Contains("closes", error.Message);
            // Three quads around an inner vertex: no rows and columns.
            error = Assert.Throws<ArgumentException>(() => NetPolylines.FromQuads(new[] { 0, 1, 2, 3, 0, 3, 4, 5, 0, 5, 6, 1 }, 7));
            StringAssert.Contains("do not form a net", error.Message);
        }

        [Test]
        public void PolylinesAsPointsWeldIntoAWeb()
        {
            // A 3 × 3 grid: rows along x, columns along y, diagonals x + y = const; the points of each polyline copied.
            Func<int, int, double[]> at = (i, j) => new double[] { i, j, 0.1 * i * j };
            Func<IEnumerable<double[]>, double[]> line = points => points.SelectMany(p => p).ToArray();
            var rows = Enumerable.Range(0, 3).Select(j => line(Enumerable.Range(0, 3).Select(i => at(i, j)))).ToArray();
            var columns = Enumerable.Range(0, 3).Select(i => line(Enumerable.Range(0, 3).Select(j => at(i, j)))).ToArray();
            var diagonals = Enumerable.Range(1, 3).Select(sum => line(Enumerable.Range(0, 3).Where(i => sum - i >= 0 && sum - i < 3).Select(i => at(i, sum - i)))).ToArray();
            WeldedNet web = NetPolylines.FromPoints(new[] { rows, columns, diagonals }, 0.0);
            Assert.AreEqual(9, web.VertexCount);
            Assert.AreEqual(9 + 9 + 7 - 9, web.WeldedPoints);
            CollectionAssert.AreEqual(new[] { 0, 1, 2 }, web.Polylines[0][0]);
            CollectionAssert.AreEqual(new[] { 0, 3, 6 }, web.Polylines[1][0]);
            CollectionAssert.AreEqual(new[] { 3, 1 }, web.Polylines[2][0]);
            CollectionAssert.AreEqual(at(2, 1), Vec.At(web.Xyz, web.Polylines[0][1][2]));
            // Within a tolerance: points moved by less than it weld to the first.
            double[] moved = (double[])columns[1].Clone();
            moved[3] += 1e-4;
            WeldedNet near = NetPolylines.FromPoints(new[] { rows, new[] { columns[0], moved, columns[2] }, diagonals }, 1e-3);
            Assert.AreEqual(9, near.VertexCount);
            Assert.AreEqual(10, NetPolylines.FromPoints(new[] { rows, new[] { columns[0], moved, columns[2] }, diagonals }, 0.0).VertexCount);
            var error = Assert.Throws<ArgumentException>(() => NetPolylines.FromPoints(new[] { rows, columns, diagonals }, 1.5));
            StringAssert.Contains("rows[0]: points 0 and 1 are within the weld tolerance", error.Message);
            error = Assert.Throws<ArgumentException>(() => NetPolylines.FromPoints(new[] { rows, columns, new[] { new double[] { 0, 0, 0 } } }, 0.0));
            StringAssert.Contains("diagonals[0] has 1 points", error.Message);
            error = Assert.Throws<ArgumentException>(() => NetPolylines.FromPoints(new[] { rows, new[] { new double[] { 0, 0, double.NaN, 1, 1, 1 } } }, 0.0));
            StringAssert.Contains("columns[0] has a non-finite coordinate", error.Message);
        }

        [Test]
        public void AStripNetStartsAnOptimisationFromItsQuadNet()
        {
            // The geodesic net of a cylinder's circles and rulings, as in NetTests.
            var cylinder = new Cylinder(16, 10, 11);
            double[][] starts = cylinder.TiltedCirclesAndRulings();
            double[] first = starts[0], second = starts[1];
            var parameters = StripParams.Default(90.0, 0.3);
            using (var mesh = LamellaMesh.FromArrays(cylinder.Xyz, cylinder.Triangles))
            using (var net = new NetSolver(mesh, 90.0, 90.0, first, second, 30.0, 90.0))
            {
                for (int k = 0; k < 20 && !net.Step(10).IsConverged; k++) { }
                using (LevelCurves circles = LevelCurves.OfNet(net, 0, 6, 0.8), rulings = LevelCurves.OfNet(net, 1, 6, 0.8))
                using (Strips a = Strips.Build(circles, parameters), b = Strips.Build(rulings, parameters))
                using (var grid = new StripNet(net, a, b))
                using (var solver = new BaseMeshSolver(grid, mesh, 90.0, 90.0, false))
                {
                    double[] before = grid.Vertices(), start = solver.Positions();
                    Assert.AreEqual(before.Length, start.Length);
                    for (int i = 0; i < before.Length; i++) Assert.AreEqual(before[i], start[i], 1e-9);
                    // Circles and rulings are geodesics already, and their 6 x 6 crossings have 4 x 4 inner nodes.
                    BaseMeshReport report = solver.InitialReport;
                    Assert.IsTrue(report.FamiliesMet, report.Describe());
                    Assert.AreEqual(16, report.NodeCount);
                    report = solver.Step(10);
                    Assert.AreEqual(10, report.Iterations);
                    Assert.IsTrue(report.FamiliesMet, report.Describe());
                    // Still on the cylinder (within the reference's sagitta, 0.075); fairness may slide the vertices
                    // along their polylines, evening out the spacing of the levels.
                    double[] after = solver.Positions();
                    for (int v = 0; v < after.Length / 3; v++)
                    {
                        Assert.AreEqual(Cylinder.Radius, Math.Sqrt(after[3 * v] * after[3 * v] + after[3 * v + 1] * after[3 * v + 1]), 0.08);
                    }
                    var error = Assert.Throws<LamellaException>(() => new BaseMeshSolver(grid, mesh, 90.0, -1.0, false));
                    StringAssert.Contains("theta_degrees_columns", error.Message);
                }
            }
        }

        [Test]
        public void InvalidArgumentsAreRefusedByName()
        {
            var cylinder = new Cylinder(8, 6, 3);
            var net = new HelixNet(0.0);
            using (var reference = LamellaMesh.FromArrays(cylinder.Xyz, cylinder.Triangles))
            {
                var error = Assert.Throws<LamellaException>(() => new BaseMeshSolver(reference, net.Points, net.Rows, net.Columns, 200.0, 90.0, true));
                Assert.AreEqual(Status.InvalidArgument, error.Status);
                StringAssert.Contains("theta_degrees_rows", error.NativeMessage);
                int[][] rows = net.Rows.Select(r => (int[])r.Clone()).ToArray();
                rows[1][1] = 100000;
                error = Assert.Throws<LamellaException>(() => new BaseMeshSolver(reference, net.Points, rows, net.Columns, 90.0, 90.0, true));
                StringAssert.Contains("row 1 refers to vertex 100000", error.NativeMessage);
                double[] points = (double[])net.Points.Clone();
                points[3 * 3 + 2] = double.NaN;
                error = Assert.Throws<LamellaException>(() => new BaseMeshSolver(reference, points, net.Rows, net.Columns, 90.0, 90.0, true));
                StringAssert.Contains("vertex 3 has a non-finite coordinate", error.NativeMessage);
                rows[1][1] = -1;
                Assert.Throws<ArgumentOutOfRangeException>(() => new BaseMeshSolver(reference, net.Points, rows, net.Columns, 90.0, 90.0, true));
                Assert.Throws<ArgumentNullException>(() => new BaseMeshSolver(reference, net.Points, new int[][] { null }, net.Columns, 90.0, 90.0, true));
                Assert.Throws<ArgumentException>(() => new BaseMeshSolver(reference, new double[4], net.Rows, net.Columns, 90.0, 90.0, true));
                using (var solver = new BaseMeshSolver(reference, net.Points, net.Rows, net.Columns, 90.0, 90.0, false))
                {
                    Assert.Throws<ArgumentOutOfRangeException>(() => solver.Step(-1));
                    Assert.Throws<ArgumentOutOfRangeException>(() => solver.BuildStrips(2, 0.3));
                    error = Assert.Throws<LamellaException>(() => solver.BuildStrips(0, -1.0));
                    StringAssert.Contains("width", error.NativeMessage);
                }
            }
        }

        /// <summary>The largest distance between the points of two arrays of x, y, z per vertex.</summary>
        private static double LargestMove(double[] a, double[] b)
        {
            double largest = 0;
            for (int v = 0; v < a.Length / 3; v++)
            {
                largest = Math.Max(largest, Vec.Norm(new[] { a[3 * v] - b[3 * v], a[3 * v + 1] - b[3 * v + 1], a[3 * v + 2] - b[3 * v + 2] }));
            }
            return largest;
        }

        [Test]
        public void WeightsSetBeforeTheFirstStepSteerTheOptimisation()
        {
            var cylinder = new Cylinder(72, 40, 7);
            var net = new HelixNet(0.02);
            BaseMeshWeights defaults = BaseMeshWeights.Default();
            Assert.AreEqual(1.0, defaults.Curve);
            Assert.AreEqual(1e-3, defaults.Fair);
            Assert.AreEqual(1.0, defaults.Close);
            Assert.AreEqual(1e-4, defaults.Pull);
            Assert.AreEqual(1.0, defaults.Torsion);
            using (var reference = LamellaMesh.FromArrays(cylinder.Xyz, cylinder.Triangles))
            using (var held = new BaseMeshSolver(reference, net.Points, net.Rows, net.Columns, 90.0, 90.0, false))
            using (var free = new BaseMeshSolver(reference, net.Points, net.Rows, net.Columns, 90.0, 90.0, false))
            {
                Assert.AreEqual(defaults, held.Weights);
                BaseMeshWeights bad = defaults;
                bad.Pull = -1;
                var error = Assert.Throws<LamellaException>(() => held.SetWeights(bad));
                Assert.AreEqual(Status.InvalidArgument, error.Status);
                StringAssert.Contains("weights.pull", error.NativeMessage);
                Assert.AreEqual(defaults, held.Weights, "a refused weight leaves the session as it was");

                // A pull a million times the default holds every vertex where the net was given; the defaults move them
                // to restore the geodesics.
                BaseMeshWeights strong = defaults;
                strong.Pull = 100;
                held.SetWeights(strong);
                Assert.AreEqual(100.0, held.Weights.Pull);
                held.Step(10);
                free.Step(10);
                double heldMove = LargestMove(held.Positions(), net.Points), freeMove = LargestMove(free.Positions(), net.Points);
                Assert.Less(heldMove, 0.1 * freeMove, "moved by up to " + heldMove + " held, " + freeMove + " with the defaults");

                error = Assert.Throws<LamellaException>(() => held.SetWeights(defaults));
                StringAssert.Contains("first iteration", error.NativeMessage);
            }
        }
    }
}
