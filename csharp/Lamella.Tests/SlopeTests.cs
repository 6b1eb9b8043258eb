using System;
using NUnit.Framework;

namespace Lamella.Tests
{
    /// <summary>
    /// Constant-slope families through the binding (paper Sec. 5.2.3, Eq. 22) on the cylinder: about its axis the curves
    /// of slope β are helices, rising at β everywhere; about an axis across it the reachable region ends on the two
    /// rulings where the tangent planes themselves have the slope (plus the library's 3° margin).
    /// </summary>
    [TestFixture]
    public class SlopeTests
    {
        private const double Slope = 30.0;
        private static readonly double[] Z = { 0, 0, 1 };

        [Test]
        public void TheConstantSlopeCurvesOfACylinderAboutItsAxisAreHelices()
        {
            var cylinder = new Cylinder(26, 15, 7);
            using (var mesh = LamellaMesh.FromArrays(cylinder.Xyz, cylinder.Triangles))
            {
                double[] start = InitialField.FromSlope(mesh, Z, Slope);
                Assert.AreEqual(cylinder.VertexCount, start.Length);
                FieldParams parameters = FieldParams.ConstantSlope(Z, Slope, false);
                Assert.AreEqual(Family.ConstantSlope, parameters.Family);
                Assert.AreEqual(Slope, parameters.ThetaDegrees);
                using (var field = new FieldSolver(mesh, start, parameters))
                {
                    FieldReport report = field.Step(10);
                    for (int k = 0; k < 20 && !report.IsConverged; k++) report = field.Step(10);
                    Assert.IsTrue(report.IsConverged);
                    Assert.AreEqual(Slope, field.SlopeDegrees);
                    using (LevelCurves curves = LevelCurves.Uniform(field, 6, 1.0))
                    {
                        int[] offsets = curves.Offsets();
                        double[] points = curves.Points();
                        double worst = 0.0;
                        int measured = 0;
                        for (int c = 0; c + 1 < offsets.Length; c++)
                        {
                            for (int i = offsets[c] + 1; i + 1 < offsets[c + 1]; i++)
                            {
                                double dx = points[3 * i + 3] - points[3 * i - 3], dy = points[3 * i + 4] - points[3 * i - 2], dz = points[3 * i + 5] - points[3 * i - 1];
                                double slope = Math.Asin(Math.Abs(dz) / Math.Sqrt(dx * dx + dy * dy + dz * dz)) * 180.0 / Math.PI;
                                worst = Math.Max(worst, Math.Abs(slope - Slope));
                                measured++;
                            }
                        }
                        Assert.GreaterOrEqual(curves.Count, 4);
                        Assert.Greater(measured, 50);
                        Assert.Less(worst, 1.0, "worst slope error in degrees");
                    }
                }
            }
        }

        [Test]
        public void TheReachableRegionAboutACrossAxisEndsOnTwoRulings()
        {
            var cylinder = new Cylinder(26, 15, 7);
            using (var mesh = LamellaMesh.FromArrays(cylinder.Xyz, cylinder.Triangles))
            {
                using (LevelCurves all = LevelCurves.ReachableBoundary(mesh, Z, Slope))
                {
                    Assert.AreEqual(0, all.Count, "every tangent plane contains the axis");
                }
                using (LevelCurves boundary = LevelCurves.ReachableBoundary(mesh, new double[] { 3, 0, 0 }, Slope))
                {
                    Assert.AreEqual(2, boundary.Count);
                    int[] offsets = boundary.Offsets();
                    double[] points = boundary.Points();
                    var rulings = new[] { Slope + 3.0, 180.0 - (Slope + 3.0) };
                    var found = new int[2];
                    for (int c = 0; c < 2; c++)
                    {
                        double first = Math.Atan2(points[3 * offsets[c] + 1], points[3 * offsets[c]]) * 180.0 / Math.PI;
                        int r = Math.Abs(first - rulings[0]) < 45.0 ? 0 : 1;
                        found[r]++;
                        for (int i = offsets[c]; i < offsets[c + 1]; i++)
                        {
                            Assert.AreEqual(rulings[r], Math.Atan2(points[3 * i + 1], points[3 * i]) * 180.0 / Math.PI, 1.0);
                        }
                    }
                    CollectionAssert.AreEqual(new[] { 1, 1 }, found);
                }
            }
        }

        [Test]
        public void BadSlopeInputsAreRefusedNamingTheElement()
        {
            var cylinder = new Cylinder(8, 6, 3);
            using (var mesh = LamellaMesh.FromArrays(cylinder.Xyz, cylinder.Triangles))
            {
                Assert.Throws<ArgumentNullException>(() => InitialField.FromSlope(null, Z, Slope));
                Assert.Throws<ArgumentNullException>(() => InitialField.FromSlope(mesh, null, Slope));
                Assert.Throws<ArgumentException>(() => InitialField.FromSlope(mesh, new double[2], Slope));
                Assert.Throws<ArgumentNullException>(() => LevelCurves.ReachableBoundary(mesh, null, Slope));
                Assert.Throws<ArgumentNullException>(() => FieldParams.ConstantSlope(null, Slope, true));
                var e = Assert.Throws<LamellaException>(() => InitialField.FromSlope(mesh, new double[3], Slope));
                Assert.AreEqual(Status.InvalidArgument, e.Status);
                StringAssert.Contains("axis", e.NativeMessage);
                e = Assert.Throws<LamellaException>(() => LevelCurves.ReachableBoundary(mesh, Z, 90.0));
                StringAssert.Contains("slope_degrees", e.NativeMessage);
                e = Assert.Throws<LamellaException>(() => FieldParams.Default(Family.FreeSlope, -90.0));
                StringAssert.Contains("(−90, 90)", e.NativeMessage);
                // A free slope is fitted to the field: started at 20° on the helices of 30°, it finds 30°.
                double[] helices = InitialField.FromSlope(mesh, Z, Slope);
                using (var free = new FieldSolver(mesh, helices, FieldParams.ConstantSlope(Z, 20.0, true)))
                {
                    free.Step(1);
                    Assert.AreEqual(Slope, free.SlopeDegrees, 1.0);
                }
                using (var other = new FieldSolver(mesh, helices, FieldParams.Default(Family.PseudoGeodesic, 60.0)))
                {
                    e = Assert.Throws<LamellaException>(() => { double unused = other.SlopeDegrees; });
                    StringAssert.Contains("constant-slope", e.NativeMessage);
                }
                // The start search covers the families by angle and refuses a slope family by name.
                e = Assert.Throws<LamellaException>(() => new StartSearch(mesh, FieldParams.ConstantSlope(Z, Slope, false)));
                StringAssert.Contains("family", e.NativeMessage);
            }
        }
    }
}
