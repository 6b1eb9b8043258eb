using System;
using System.Linq;
using NUnit.Framework;

namespace Lamella.Tests
{
    /// <summary>
    /// 3-webs through the binding (paper Sec. 4.2), judged from outside on the hyperbolic paraboloid z = xy/5: the AAG
    /// web (θ 0, 0, 90) from the default start of its first two families, solved; Eq. 18 recomputed from the three fields;
    /// the web of triangles and the Kagome pattern of the same session with their nodes on the surface; the session saved
    /// and restored to the bit; refused requests.
    /// </summary>
    [TestFixture]
    public class WebTests
    {
        private const double HalfWidth = 5.0;
        private const int Cells = 22;
        private const int Count = 8;
        private static readonly double[] Thetas = { 0.0, 0.0, 90.0 };

        private Grid hypar;
        private LamellaMesh mesh;
        private double[][] start;
        private NetSolver web;
        private NetReport report;
        /// <summary>The largest range of the three fields as the web started (their common scale: mean ‖∇‖ 1).</summary>
        private double startRange;

        /// <summary>The largest distance of a point of the triangulated z = xy/5 from the surface: xy's linear interpolant on a cell's triangle is off by at most cell² / 4.</summary>
        private static double SurfaceTolerance
        {
            get
            {
                double cell = 2 * HalfWidth / Cells;
                return cell * cell / 20.0 + 1e-9;
            }
        }

        [TestFixtureSetUp]
        public void Solve()
        {
            // 22 × 22 cells of 0.45 over [−5, 5]²: 529 vertices, lifted onto z = xy/5.
            hypar = new Grid(Cells, Cells, 2 * HalfWidth / Cells, -HalfWidth, -HalfWidth);
            for (int v = 0; v < hypar.VertexCount; v++) hypar.Xyz[3 * v + 2] = hypar.Xyz[3 * v] * hypar.Xyz[3 * v + 1] / 5.0;
            mesh = LamellaMesh.FromArrays(hypar.Xyz, hypar.Triangles());
            start = NetSolver.DefaultStart(mesh, Thetas[0], Thetas[1]);
            web = NetSolver.Web(mesh, Thetas[0], Thetas[1], Thetas[2], start[0], start[1], 30.0);
            startRange = Enumerable.Range(0, 3).Max(k => Range(web.Field(k)));
            report = web.Report;
            for (int k = 0; k < 30 && !report.IsConverged; k++) report = web.Step(10);
            Console.WriteLine("AAG web on z = xy/5 ({0} vertices): {1} iterations, converged {2}", hypar.VertexCount, report.Iterations, report.IsConverged);
        }

        [TestFixtureTearDown]
        public void Release()
        {
            if (web != null) web.Dispose();
            if (mesh != null) mesh.Dispose();
        }

        private static double Range(double[] values) => values.Max() - values.Min();

        /// <summary>The largest distance of the plan points (x, y of <paramref name="xyz"/> at <paramref name="line"/>) from their principal line, and their extent along it.</summary>
        private static double PlanDeviation(double[] xyz, int[] line, out double length)
        {
            double mx = line.Average(v => xyz[3 * v]), my = line.Average(v => xyz[3 * v + 1]);
            double sxx = line.Sum(v => (xyz[3 * v] - mx) * (xyz[3 * v] - mx));
            double syy = line.Sum(v => (xyz[3 * v + 1] - my) * (xyz[3 * v + 1] - my));
            double sxy = line.Sum(v => (xyz[3 * v] - mx) * (xyz[3 * v + 1] - my));
            double angle = 0.5 * Math.Atan2(2 * sxy, sxx - syy), ux = Math.Cos(angle), uy = Math.Sin(angle);
            double[] along = line.Select(v => (xyz[3 * v] - mx) * ux + (xyz[3 * v + 1] - my) * uy).ToArray();
            length = along.Max() - along.Min();
            return line.Max(v => Math.Abs(-(xyz[3 * v] - mx) * uy + (xyz[3 * v + 1] - my) * ux));
        }

        /// <summary>
        /// Strips of every family at the web's levels (θ 0, 0, 90), and the web of <paramref name="kagome"/>;
        /// <paramref name="check"/> reads them with the web's vertices, vertex levels and faces, then what holds for both
        /// patterns is checked (<see cref="CheckPolylinesAndNodes"/>).
        /// </summary>
        private void WithStripWeb(bool kagome, Action<Strips[], StripWeb, double[], int?[][], int[][]> check)
        {
            var curves = new LevelCurves[3];
            var strips = new Strips[3];
            try
            {
                for (int k = 0; k < 3; k++)
                {
                    curves[k] = LevelCurves.OfWeb(web, k, Count, Count, kagome, 0.3);
                    CollectionAssert.AreEqual(web.WebLevels(Count, Count, kagome, k), curves[k].Levels().Distinct().ToArray(), "family " + k + ": the curves lie on the web's levels");
                    strips[k] = Strips.Build(curves[k], StripParams.Default(Thetas[k], 0.25));
                }
                var built = new StripWeb(web, Count, Count, kagome, strips[0], strips[1], strips[2]);
                using (built)
                {
                    double[] xyz = built.Vertices();
                    int?[][] levels = built.VertexLevels();
                    Assert.AreEqual(xyz.Length / 3, levels.Length);
                    check(strips, built, xyz, levels, built.Faces());
                    CheckPolylinesAndNodes(strips, built, xyz, levels);
                }
                built.Dispose();
                Assert.Throws<ObjectDisposedException>(() => built.Vertices());
            }
            finally
            {
                foreach (Strips s in strips) if (s != null) s.Dispose();
                foreach (LevelCurves c in curves) if (c != null) c.Dispose();
            }
        }

        /// <summary>
        /// What holds for both patterns: each polyline runs along its level (every vertex names it), the vertices lie on
        /// z = xy/5, and every node is a crossing of two distinct families in ascending order, on the surface, at a
        /// vertex both families pass, with a unit axis and each arc length within its strip.
        /// </summary>
        private static void CheckPolylinesAndNodes(Strips[] strips, StripWeb built, double[] xyz, int?[][] levels)
        {
            for (int v = 0; v < xyz.Length / 3; v++)
            {
                Assert.AreEqual(xyz[3 * v] * xyz[3 * v + 1] / 5.0, xyz[3 * v + 2], SurfaceTolerance, "vertex " + v + " off z = xy/5");
            }
            for (int k = 0; k < 3; k++)
            {
                int[][] polylines = built.Polylines(k);
                int[] polylineLevels = built.PolylineLevels(k);
                Assert.AreEqual(polylines.Length, polylineLevels.Length);
                Assert.GreaterOrEqual(polylines.Length, 5, "family " + k);
                for (int p = 0; p < polylines.Length; p++)
                {
                    Assert.GreaterOrEqual(polylines[p].Length, 2);
                    foreach (int v in polylines[p]) Assert.AreEqual(polylineLevels[p], levels[v][k], "family " + k + ", polyline " + p);
                }
            }
            StripMetrics[][] metrics = strips.Select(s => s.Metrics()).ToArray();
            WebNode[] nodes = built.Nodes();
            Assert.Greater(nodes.Length, 50);
            foreach (WebNode node in nodes)
            {
                int a = node.Families[0], b = node.Families[1];
                Assert.That(a, Is.InRange(0, 2));
                Assert.That(b, Is.InRange(0, 2));
                Assert.Less(a, b, "two distinct families, the smaller first");
                Assert.IsTrue(levels[node.Vertex][a].HasValue && levels[node.Vertex][b].HasValue, "both families pass the node's vertex");
                for (int c = 0; c < 3; c++) Assert.AreEqual(xyz[3 * node.Vertex + c], node.Position[c]);
                Assert.AreEqual(node.Position[0] * node.Position[1] / 5.0, node.Position[2], SurfaceTolerance, "a node off z = xy/5");
                Assert.AreEqual(1.0, Vec.Norm(node.Axis), 1e-9);
                Assert.That(node.RulingAngleDegrees, Is.InRange(0.0, 90.0));
                for (int i = 0; i < 2; i++)
                {
                    Assert.That(node.ArcLengths[i], Is.InRange(0.0, metrics[node.Families[i]][node.Strips[i]].Length + 1e-9));
                }
            }
        }

        /// <summary>
        /// Eq. 18 recomputed from the three fields as read through the binding: within 1e-6 of the fields' final range (and
        /// of the range they started with: the fields keep their scale), and the report's residual recomputed the same way.
        /// </summary>
        [Test]
        public void TheAagWebOfAHyperbolicParaboloidHoldsEq18()
        {
            Assert.AreEqual(3, web.FamilyCount);
            Assert.IsTrue(report.IsConverged, "converged within 300 iterations");
            double[][] fields = { web.Field(0), web.Field(1), web.Field(2) };
            double range = fields.Max(f => Range(f)), worst = 0.0;
            for (int v = 0; v < hypar.VertexCount; v++)
            {
                double sum = Math.Abs(fields[0][v] + fields[1][v] + fields[2][v]);
                Assert.LessOrEqual(sum, 1e-6 * startRange, "F + G + H at vertex " + v);
                worst = Math.Max(worst, sum);
            }
            Assert.LessOrEqual(worst, 1e-6 * range, "F + G + H against the fields' final range " + range);
            Assert.Greater(range, 0.2 * startRange, "the fields keep their scale");
            WebReport w = web.WebReport();
            Console.WriteLine("Eq. 18: max |F + G + H| {0:e3} ({1:e3} of the start's range {2:g4}, {3:e3} of the final range {4:g4}; reported {5:e3}, RMS {6:e3}); third family {7:0.###}° RMS, {8:0.###}° max; factor {9}",
                worst, worst / startRange, startRange, worst / range, range, w.ResidualMax, w.ResidualRms, w.AngleErrorRmsDegrees, w.AngleErrorMaxDegrees, w.ThirdFamilyFactor);
            Console.WriteLine(w.Describe(report, 30.0));
            Assert.AreEqual(worst / range, w.ResidualMax, 1e-9 * w.ResidualMax, "the reported residual is max |F + G + H| over the largest range");
            Assert.LessOrEqual(w.ResidualRms, w.ResidualMax);
            Assert.AreEqual(1.0, w.ThirdFamilyFactor, "the third family has its full weight at the final stage");
            Assert.Less(w.AngleErrorRmsDegrees, 5.0);
            Assert.LessOrEqual(w.AngleErrorRmsDegrees, w.AngleErrorMaxDegrees);
            for (int i = 0; i < 2; i++)
            {
                Assert.That(w.MinIntersectionDegrees[i], Is.InRange(0.0, 90.0));
                Assert.That(w.MeanIntersectionDegrees[i], Is.InRange(w.MinIntersectionDegrees[i], 90.0));
                Assert.GreaterOrEqual(w.FacesBelowMin[i], 0);
            }
            StringAssert.Contains("F + G + H (Eq. 18)", w.Describe(report, 30.0));
        }

        [Test]
        public void TheWebOfTrianglesRunsAlongTheRulingsAndItsNodesLieOnTheSurface()
        {
            WithStripWeb(false, (strips, built, xyz, levels, faces) =>
            {
                Assert.Greater(faces.Length, 50);
                Assert.IsTrue(faces.All(f => f.Length == 3), "a 3-web's faces are triangles");
                int triple = 0;
                foreach (int?[] l in levels)
                {
                    int set = l.Count(i => i.HasValue);
                    Assert.That(set, Is.InRange(2, 3));
                    if (set == 3) triple++;
                }
                Assert.Greater(triple, xyz.Length / 3 / 2, "most vertices are crossings of all three families");
                // The first two families of the AAG web are the rulings: straight in plan.
                double worstBend = 0.0;
                for (int k = 0; k < 2; k++)
                {
                    foreach (int[] line in built.Polylines(k))
                    {
                        double length;
                        double deviation = PlanDeviation(xyz, line, out length);
                        if (length < 2.0) continue;
                        Assert.LessOrEqual(deviation, 0.005 * length, "family " + k + ": a polyline bends");
                        worstBend = Math.Max(worstBend, deviation / length);
                    }
                }
                WebNode[] nodes = built.Nodes();
                Console.WriteLine("web: {0} vertices ({1} triple), {2} triangles, {3} nodes; rulings straight to {4:0.###} % of their length; strips {5} / {6} / {7}",
                    xyz.Length / 3, triple, faces.Length, nodes.Length, 100 * worstBend, strips[0].Count, strips[1].Count, strips[2].Count);
                // Every pair of families crosses somewhere.
                foreach (int[] pair in new[] { new[] { 0, 1 }, new[] { 0, 2 }, new[] { 1, 2 } })
                {
                    Assert.IsTrue(nodes.Any(n => n.Families[0] == pair[0] && n.Families[1] == pair[1]), "no node of families " + pair[0] + " and " + pair[1]);
                }
            });
        }

        [Test]
        public void AKagomePatternCrossesInPairsWithHexagons()
        {
            WithStripWeb(true, (strips, built, xyz, levels, faces) =>
            {
                Assert.IsTrue(levels.All(l => l.Count(i => i.HasValue) == 2), "every vertex is the crossing of exactly two families");
                Assert.IsTrue(faces.All(f => f.Length == 3 || f.Length == 6), "faces are triangles and hexagons");
                int hexagons = faces.Count(f => f.Length == 6), triangles = faces.Length - hexagons;
                Assert.GreaterOrEqual(hexagons, 10);
                Assert.Greater(triangles, hexagons);
                Console.WriteLine("Kagome: {0} vertices, {1} triangles, {2} hexagons, {3} nodes", xyz.Length / 3, triangles, hexagons, built.Nodes().Length);
            });
        }

        [Test]
        public void AWebSessionSavedAndRestoredStepsOnToTheSameBits()
        {
            using (var fresh = NetSolver.Web(mesh, Thetas[0], Thetas[1], Thetas[2], start[0], start[1], 30.0))
            {
                fresh.Step(3);
                using (var restored = NetSolver.Load(fresh.Save()))
                {
                    Assert.AreEqual(3, restored.FamilyCount);
                    for (int k = 0; k < 3; k++) CollectionAssert.AreEqual(fresh.Field(k), restored.Field(k));
                    Assert.AreEqual(fresh.Step(4).Iterations, restored.Step(4).Iterations);
                    for (int k = 0; k < 3; k++) CollectionAssert.AreEqual(fresh.Field(k), restored.Field(k), "field " + k);
                    Assert.AreEqual(fresh.WebReport().ResidualMax, restored.WebReport().ResidualMax);
                    CollectionAssert.AreEqual(fresh.WebLevels(Count, Count, true, 2), restored.WebLevels(Count, Count, true, 2));
                }
            }
        }

        [Test]
        public void WebRequestsOnTheWrongSessionOrOutOfRangeAreRefused()
        {
            using (var net = new NetSolver(mesh, Thetas[0], Thetas[1], start[0], start[1]))
            {
                Assert.AreEqual(2, net.FamilyCount);
                var error = Assert.Throws<LamellaException>(() => net.WebReport());
                Assert.AreEqual(Status.InvalidArgument, error.Status);
                StringAssert.IsMatch("two families|third", error.NativeMessage);
                error = Assert.Throws<LamellaException>(() => net.WebLevels(Count, Count, false, 0));
                Assert.IsNotEmpty(error.NativeMessage);
                Assert.Throws<LamellaException>(() => LevelCurves.OfWeb(net, 0, Count, Count, false, 0.0));
                Assert.Throws<ArgumentOutOfRangeException>(() => net.Field(2));
            }
            var outOfRange = Assert.Throws<ArgumentOutOfRangeException>(() => web.Field(3));
            StringAssert.Contains("0, 1 and 2", outOfRange.Message);
            Assert.Throws<ArgumentOutOfRangeException>(() => web.Field(-1));
            Assert.Throws<ArgumentOutOfRangeException>(() => LevelCurves.OfNet(web, 3, Count, 0.0));
            Assert.Throws<ArgumentOutOfRangeException>(() => web.WebLevels(Count, Count, false, 3));
            Assert.Throws<ArgumentOutOfRangeException>(() => web.WebLevels(-1, Count, false, 0));
            var count = Assert.Throws<LamellaException>(() => web.WebLevels(0, Count, false, 0));
            StringAssert.Contains("count_f", count.NativeMessage);
            var theta = Assert.Throws<LamellaException>(() => NetSolver.Web(mesh, 0.0, 0.0, 200.0, start[0], start[1]));
            StringAssert.Contains("thetas[2]", theta.NativeMessage);
            Assert.Throws<ArgumentException>(() => NetSolver.Web(mesh, 0.0, 0.0, 90.0, start[0], new double[1]));
        }
    }
}
