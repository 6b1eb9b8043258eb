using System;
using NUnit.Framework;

namespace Lamella.Tests
{
    /// <summary>
    /// A net of two families through the binding (paper Sec. 4.1): on the cylinder, the geodesic net of circles and
    /// rulings from turned heights, stepped to convergence and checked against the axis; invalid arguments.
    /// </summary>
    [TestFixture]
    public class NetTests
    {
        /// <summary>Mean over the triangles of the angle (degrees) between the field's gradient and the axis (z).</summary>
        private static double MeanAxisAngle(Cylinder c, double[] field)
        {
            double sum = 0.0;
            int counted = 0;
            for (int t = 0; t < c.Triangles.Length / 3; t++)
            {
                int i0 = c.Triangles[3 * t], i1 = c.Triangles[3 * t + 1], i2 = c.Triangles[3 * t + 2];
                var e1 = new double[3];
                var e2 = new double[3];
                for (int k = 0; k < 3; k++)
                {
                    e1[k] = c.Xyz[3 * i1 + k] - c.Xyz[3 * i0 + k];
                    e2[k] = c.Xyz[3 * i2 + k] - c.Xyz[3 * i0 + k];
                }
                double a11 = e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2];
                double a12 = e1[0] * e2[0] + e1[1] * e2[1] + e1[2] * e2[2];
                double a22 = e2[0] * e2[0] + e2[1] * e2[1] + e2[2] * e2[2];
                double d1 = field[i1] - field[i0], d2 = field[i2] - field[i0], det = a11 * a22 - a12 * a12;
                double a = (d1 * a22 - d2 * a12) / det, b = (d2 * a11 - d1 * a12) / det;
                double gx = a * e1[0] + b * e2[0], gy = a * e1[1] + b * e2[1], gz = a * e1[2] + b * e2[2];
                double norm = Math.Sqrt(gx * gx + gy * gy + gz * gz);
                if (norm > 0.0)
                {
                    sum += Math.Acos(Math.Min(1.0, Math.Abs(gz) / norm)) * 180.0 / Math.PI;
                    counted++;
                }
            }
            return counted > 0 ? sum / counted : 90.0;
        }

        /// <summary>
        /// The gridshell as built from the converged geodesic net of a cylinder: strips on six levels of each field, their
        /// quad net and nodes. Every crossing lies on the cylinder and carries a node whose rulings (the circle strip's
        /// along the axis, the ruling strip's around it) meet at right angles on average.
        /// </summary>
        private static void CheckStripNet(NetSolver net)
        {
            Assert.Throws<ArgumentOutOfRangeException>(() => LevelCurves.OfNet(net, 2, 6, 0.8));
            var parameters = StripParams.Default(90.0, 0.3);
            using (LevelCurves circles = LevelCurves.OfNet(net, 0, 6, 0.8), rulings = LevelCurves.OfNet(net, 1, 6, 0.8))
            using (Strips first = Strips.Build(circles, parameters), second = Strips.Build(rulings, parameters))
            using (var grid = new StripNet(net, first, second))
            {
                double[] xyz = grid.Vertices();
                int[] levels = grid.Levels();
                int[] quads = grid.Quads();
                Node[] nodes = grid.Nodes();
                int vertexCount = xyz.Length / 3;
                Assert.AreEqual(first.Count * second.Count, vertexCount);
                Assert.AreEqual((first.Count - 1) * (second.Count - 1), quads.Length / 4);
                Assert.AreEqual(vertexCount, nodes.Length);
                for (int v = 0; v < vertexCount; v++)
                {
                    Assert.AreEqual(Cylinder.Radius, Math.Sqrt(xyz[3 * v] * xyz[3 * v] + xyz[3 * v + 1] * xyz[3 * v + 1]), 0.08);
                }
                for (int q = 0; q < quads.Length; q += 4)
                {
                    int a = quads[q], c = quads[q + 2];
                    Assert.AreEqual(levels[2 * a] + 1, levels[2 * c]);
                    Assert.AreEqual(levels[2 * a + 1] + 1, levels[2 * c + 1]);
                }
                StripMetrics[][] metrics = { first.Metrics(), second.Metrics() };
                // The rulings of strips on the straight rulings are poorly determined (no curvature): single nodes
                // come out between about 50° and 90°, their mean near 90°.
                double meanAngle = 0.0;
                foreach (Node node in nodes)
                {
                    for (int k = 0; k < 3; k++)
                    {
                        Assert.AreEqual(xyz[3 * node.Vertex + k], node.Position[k]);
                    }
                    for (int k = 0; k < 2; k++)
                    {
                        Assert.That(node.ArcLengths[k], Is.InRange(0.0, metrics[k][node.Strips[k]].Length + 1e-9));
                    }
                    Assert.Greater(node.RulingAngleDegrees, 45.0);
                    meanAngle += node.RulingAngleDegrees / nodes.Length;
                    Assert.AreEqual(1.0, Math.Sqrt(node.Axis[0] * node.Axis[0] + node.Axis[1] * node.Axis[1] + node.Axis[2] * node.Axis[2]), 1e-9);
                    // Sec. 5.1 on the first family, horizontal circles: no torsion, so k = 0 and the binormal is the
                    // rectifying developable's ruling.
                    Assert.IsTrue(node.ConicalCurvature[0].HasValue, "a circle bends at every node");
                    Assert.Less(Math.Abs(node.ConicalCurvature[0].Value), 0.1);
                    Assert.Less(node.DarbouxAngleDegrees[0].Value, 6.0);
                    Assert.GreaterOrEqual(node.BinormalOffset[0].Value, 0.0);
                }
                Assert.Greater(meanAngle, 80.0);
            }
        }

        [Test]
        public void TheGeodesicNetOfACylinderIsItsCirclesAndRulings()
        {
            var cylinder = new Cylinder(16, 10, 11);
            double[][] starts = cylinder.TiltedCirclesAndRulings();
            double[] first = starts[0], second = starts[1];
            using (var mesh = LamellaMesh.FromArrays(cylinder.Xyz, cylinder.Triangles))
            using (var net = new NetSolver(mesh, 90.0, 90.0, first, second, 30.0, 90.0))
            {
                Assert.AreEqual(0, net.Report.Iterations);
                net.Step(3);
                using (var restored = NetSolver.Load(net.Save()))
                {
                    // A saved session steps on in step with the original, to the bit.
                    CollectionAssert.AreEqual(net.Field(0), restored.Field(0));
                    Assert.AreEqual(net.Step(4).Iterations, restored.Step(4).Iterations);
                    CollectionAssert.AreEqual(net.Field(0), restored.Field(0));
                    CollectionAssert.AreEqual(net.Field(1), restored.Field(1));
                }
                var error = Assert.Throws<LamellaException>(() => NetSolver.Load(new byte[] { 76, 77, 76, 78 }));
                Assert.AreEqual(Status.CorruptData, error.Status);
                NetReport report = net.Report;
                for (int k = 0; k < 20 && !report.IsConverged; k++)
                {
                    report = net.Step(10);
                }
                Assert.IsTrue(report.IsConverged);
                Assert.Less(report.AngleErrorRmsDegrees[0], 1.0);
                Assert.Less(report.AngleErrorRmsDegrees[1], 1.0);
                Assert.Greater(report.MeanIntersectionDegrees, 80.0);
                Assert.Less(MeanAxisAngle(cylinder, net.Field(0)), 3.0);
                Assert.Less(Math.Abs(90.0 - MeanAxisAngle(cylinder, net.Field(1))), 3.0);
                CheckStripNet(net);
                Assert.Throws<ArgumentOutOfRangeException>(() => net.Field(2));
            }
        }

        [Test]
        public void TheDefaultStartGivesTwoCrossingFields()
        {
            var cylinder = new Cylinder(16, 10, 11);
            using (var mesh = LamellaMesh.FromArrays(cylinder.Xyz, cylinder.Triangles))
            {
                double[][] fields = NetSolver.DefaultStart(mesh, 90.0, 90.0);
                Assert.AreEqual(2, fields.Length);
                Assert.AreEqual(cylinder.VertexCount, fields[0].Length);
                using (var net = new NetSolver(mesh, 90.0, 90.0, fields[0], fields[1]))
                {
                    Assert.GreaterOrEqual(net.Report.MeanIntersectionDegrees, 45.0);
                }
                var error = Assert.Throws<LamellaException>(() => NetSolver.DefaultStart(mesh, 90.0, 200.0));
                StringAssert.Contains("theta", error.Message);
            }
        }

        [Test]
        public void InvalidArgumentsAreRefusedByName()
        {
            var cylinder = new Cylinder(8, 6, 3);
            using (var mesh = LamellaMesh.FromArrays(cylinder.Xyz, cylinder.Triangles))
            {
                var field = cylinder.InitialField;
                var error = Assert.Throws<LamellaException>(() => new NetSolver(mesh, 90.0, 90.0, field, field, 95.0));
                StringAssert.Contains("min_intersection_degrees", error.Message);
                error = Assert.Throws<LamellaException>(() => new NetSolver(mesh, 200.0, 90.0, field, field));
                StringAssert.Contains("theta", error.Message);
                Assert.Throws<ArgumentException>(() => new NetSolver(mesh, 90.0, 90.0, field, new double[1]));
            }
        }
    }
}
