using System;
using Lamella.Conversion;
using NUnit.Framework;

namespace Lamella.Tests
{
    /// <summary>Closed level curves come out closed: the library lists a loop's points once and flags it; the conversion repeats the first point.</summary>
    [TestFixture]
    public class LevelLoopTests
    {
        [Test]
        public void CirclesCloseAndArcsStayOpen()
        {
            // F = x² + y² on the square [−1, 1]²: levels 0.25 and 0.5 are circles inside, 1.5 gives four corner arcs.
            var grid = new Grid(20, 20, 0.1, -1, -1);
            double[] f = grid.Values((x, y) => x * x + y * y);
            using (var mesh = LamellaMesh.FromArrays(grid.Xyz, grid.Triangles()))
            using (var field = new FieldSolver(mesh, f, FieldParams.Default(Family.PseudoGeodesic, 60)))
            using (var curves = LevelCurves.AtLevels(field, new[] { 0.25, 0.5, 1.5 }, 0))
            {
                bool[] closed = curves.Closed();
                double[] levels = curves.Levels();
                Assert.AreEqual(6, curves.Count, "two circles and four corner arcs");
                var raw = new Packed(curves.Points(), curves.Offsets(), 3);
                Packed loops = Packing.CloseLoops(raw, closed);
                for (int i = 0; i < curves.Count; i++)
                {
                    int n = raw.Offsets[i + 1] - raw.Offsets[i], m = loops.Offsets[i + 1] - loops.Offsets[i];
                    double[] first = Vec.At(loops.Values, loops.Offsets[i]), last = Vec.At(loops.Values, loops.Offsets[i + 1] - 1);
                    if (levels[i] < 1)
                    {
                        Assert.IsTrue(closed[i], "the circle at level " + levels[i]);
                        Assert.AreEqual(n + 1, m);
                        CollectionAssert.AreEqual(first, last, "a closed polyline ends where it starts");
                        Assert.Greater(Vec.Distance(first, Vec.At(loops.Values, loops.Offsets[i + 1] - 2)), 0, "the first point is repeated once, not doubled");
                        for (int k = loops.Offsets[i]; k < loops.Offsets[i + 1]; k++)
                        {
                            double[] p = Vec.At(loops.Values, k);
                            Assert.AreEqual(Math.Sqrt(levels[i]), Math.Sqrt(p[0] * p[0] + p[1] * p[1]), 0.01, "on the circle");
                        }
                    }
                    else
                    {
                        Assert.IsFalse(closed[i], "a corner arc at level " + levels[i]);
                        Assert.AreEqual(n, m, "an open polyline is unchanged");
                        Assert.Greater(Vec.Distance(first, last), 0.3, "arc ends (1, 0.71) and (0.71, 1)");
                    }
                }
            }
        }

        [Test]
        public void CloseLoopsChecksItsFlags()
        {
            var packed = new Packed(new double[] { 0, 0, 0, 1, 0, 0, 1, 1, 0 }, new[] { 0, 3 }, 3);
            CollectionAssert.AreEqual(new double[] { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0 }, Packing.CloseLoops(packed, new[] { true }).Values);
            Assert.Throws<ArgumentException>(() => Packing.CloseLoops(packed, new bool[2]));
        }
    }
}
