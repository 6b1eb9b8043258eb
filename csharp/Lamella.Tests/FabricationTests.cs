using System;
using System.IO;
using System.Linq;
using Lamella.Hosting;
using NUnit.Framework;

namespace Lamella.Tests
{
    /// <summary>
    /// The fabrication binding on real strips of the cylinder: presets, the plan's pieces covering each strip with the
    /// splice overlaps, the strain against the strips' own centre lines, the texts, the hosting table and files.
    /// </summary>
    [TestFixture]
    public class FabricationTests
    {
        private const double Thickness = 0.02;

        internal static Strips CylinderStrips(out LamellaMesh mesh, out FieldSolver field, out LevelCurves curves)
        {
            var c = new Cylinder(24, 14, 3);
            mesh = LamellaMesh.FromArrays(c.Xyz, c.Triangles);
            field = new FieldSolver(mesh, c.InitialField, FieldParams.Default(Family.PseudoGeodesic, 60));
            Assert.IsTrue(FieldStepping.ToConvergence(field, 300, () => false).Report.IsConverged);
            curves = LevelCurves.Uniform(field, 4, 1.0);
            return Strips.Build(curves, StripParams.Default(60, 0.5));
        }

        [Test]
        public void PresetsAndStockDefaults()
        {
            Material timber = Material.Preset("timber");
            Assert.AreEqual(11e9, timber.YoungsModulus);
            Assert.AreEqual(0.69e9, timber.ShearModulus);
            Assert.AreEqual(24e6, timber.AllowableStress);
            Assert.AreEqual(210e9, Material.Preset("steel").YoungsModulus);
            var error = Assert.Throws<LamellaException>(() => Material.Preset("cheese"));
            StringAssert.Contains("cheese", error.Message);
            Stock stock = Stock.Boards(4.8);
            Assert.AreEqual(4.8, stock.Length);
            Assert.AreEqual(0.0, stock.Width);
            Assert.AreEqual(0.3, stock.Overlap);
        }

        [Test]
        public void PlanCoversEachStripAndWritesItsFiles()
        {
            LamellaMesh mesh;
            FieldSolver field;
            LevelCurves curves;
            using (Strips strips = CylinderStrips(out mesh, out field, out curves))
            using (mesh)
            using (field)
            using (curves)
            {
                Stock stock = Stock.Boards(6.0);
                Material timber = Material.Preset("timber");
                var bad = Assert.Throws<LamellaException>(() => Fabrication.Plan(strips, timber, -1.0, stock));
                StringAssert.Contains("thickness", bad.Message);
                Stock tooShort = stock;
                tooShort.Length = 0.5;
                StringAssert.Contains("stock_length", Assert.Throws<LamellaException>(() => Fabrication.Plan(strips, timber, Thickness, tooShort)).Message);
                using (Fabrication plan = Fabrication.Plan(strips, timber, Thickness, stock))
                {
                    FabricationSummary summary = plan.Summary;
                    Assert.AreEqual((ulong)strips.Count, summary.Strips);
                    StripCheck[] checks = plan.StripChecks();
                    Piece[] pieces = plan.Pieces();
                    Assert.AreEqual(summary.Pieces, (ulong)pieces.Length);
                    Assert.Greater(pieces.Length, strips.Count, "strips longer than 6 m are split");
                    StripMetrics[] metrics = strips.Metrics();
                    int[] offsets = strips.PointOffsets();
                    double[] centres = strips.Centres();
                    for (int s = 0; s < strips.Count; s++)
                    {
                        Piece[] mine = pieces.Where(p => p.Strip == (ulong)s).ToArray();
                        double covered = mine.Sum(p => p.Length);
                        Assert.AreEqual(metrics[s].Length + stock.Overlap * (mine.Length - 1), covered, 1e-9 * covered);
                        Assert.IsTrue(mine.All(p => p.Size[0] <= stock.Length && p.Board >= 1 && p.Board <= summary.Boards));
                        // The strain is t/2 over the smallest bending radius, at most t/2 times the curvature of some three
                        // consecutive centre points (circumcircle), and the radius at least the smallest such circle's.
                        double most = 0;
                        for (int i = offsets[s] + 1; i + 1 < offsets[s + 1]; i++)
                            most = Math.Max(most, 1.0 / Circumradius(Vec.At(centres, i - 1), Vec.At(centres, i), Vec.At(centres, i + 1)));
                        Assert.LessOrEqual(checks[s].MaxStrain, 0.5 * Thickness * most * (1 + 1e-9));
                        Assert.AreEqual(0.5 * Thickness / checks[s].MinBendingRadius, checks[s].MaxStrain, 1e-12);
                        Assert.AreEqual(timber.YoungsModulus * checks[s].MaxStrain, checks[s].MaxBendingStress, 1e-6 * checks[s].MaxBendingStress);
                    }
                    Assert.AreEqual("strip_0-1", plan.Text(FabricationText.PieceId, 0));
                    StringAssert.Contains("AC1009", plan.Text(FabricationText.CutDxf));
                    Assert.Throws<LamellaException>(() => plan.Text(FabricationText.PieceId, pieces.Length));

                    string[][] rows = FabricationTable.BomRows(plan);
                    Assert.AreEqual(pieces.Length, rows.Length);
                    Assert.IsTrue(rows.All(r => r.Length == FabricationTable.Columns.Length));
                    string[] csv = plan.Text(FabricationText.BomCsv).Trim().Split('\n');
                    for (int k = 0; k < rows.Length; k++) Assert.AreEqual(rows[k][0], csv[k + 1].Split(',')[0]);
                    Piece spliced = pieces.First(p => p.Next >= 0);
                    int index = Array.IndexOf(pieces, spliced);
                    StringAssert.Contains(rows[spliced.Next][0], rows[index][6]);

                    string folder = Path.Combine(Path.GetTempPath(), "lamella-fabrication-" + Guid.NewGuid().ToString("N"));
                    try
                    {
                        string[] paths = FabricationTable.WriteFiles(plan, folder);
                        Assert.AreEqual(3, paths.Length);
                        Assert.AreEqual(plan.Text(FabricationText.CutDxf), File.ReadAllText(paths[0]));
                        StringAssert.StartsWith("<?xml", File.ReadAllText(paths[1]));
                    }
                    finally
                    {
                        Directory.Delete(folder, true);
                    }
                }
            }
        }

        private static double Circumradius(double[] a, double[] b, double[] c)
        {
            double ab = Distance(a, b), bc = Distance(b, c), ca = Distance(c, a);
            double s = 0.5 * (ab + bc + ca);
            double area = Math.Sqrt(Math.Max(0, s * (s - ab) * (s - bc) * (s - ca)));
            return area > 0 ? ab * bc * ca / (4 * area) : double.PositiveInfinity;
        }

        private static double Distance(double[] p, double[] q) => Math.Sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));

        [Test]
        public void UtilisationColoursRampFromGreenToRed()
        {
            CollectionAssert.AreEqual(new byte[] { 0, 166, 0 }, FabricationTable.UtilisationRgb(0));
            CollectionAssert.AreEqual(new byte[] { 255, 217, 0 }, FabricationTable.UtilisationRgb(0.5));
            CollectionAssert.AreEqual(new byte[] { 255, 102, 0 }, FabricationTable.UtilisationRgb(1.0));
            CollectionAssert.AreEqual(new byte[] { 217, 0, 26 }, FabricationTable.UtilisationRgb(1.2));
            CollectionAssert.AreEqual(new byte[] { 217, 0, 26 }, FabricationTable.UtilisationRgb(double.NaN));
            Assert.AreEqual(unchecked((int)0xFFFF6600u), FabricationTable.UtilisationArgb(1.0));
        }
    }
}
