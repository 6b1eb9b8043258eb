using System;
using NUnit.Framework;

namespace Lamella.Tests
{
    /// <summary>
    /// Shading designs through the binding (paper Sec. 6) on a small south-facing vertical facade (the plane y = 0,
    /// north +y, up +z) under the noon sun of late June at 47.4° north: strips orthogonal to the sun (θ = 90° ∓ the noon
    /// elevation, each quad's plane measured against the sun direction), the interior's direct-sun hours blocked (also
    /// from a given start field, which the session holds until the first step), the strips' verdict on a
    /// twisted facade, invalid arguments and start fields named.
    /// </summary>
    [TestFixture]
    public class ShadingTests
    {
        private const int Cells = 6;
        private const int Vertices = (Cells + 1) * (Cells + 1);
        /// <summary>Noon elevation on 21 June at 47.4° north: 90 − 47.4 + 23.44.</summary>
        private const double NoonElevation = 66.04;

        /// <summary>The facade y = twist · x · z over [−2, 2]² (6 × 6 cells).</summary>
        private static LamellaMesh Facade(double twist)
        {
            var xyz = new double[3 * Vertices];
            var triangles = new int[6 * Cells * Cells];
            for (int j = 0; j <= Cells; j++)
            {
                for (int i = 0; i <= Cells; i++)
                {
                    int v = j * (Cells + 1) + i;
                    double x = -2.0 + 4.0 * i / Cells, z = -2.0 + 4.0 * j / Cells;
                    xyz[3 * v] = x;
                    xyz[3 * v + 1] = twist * x * z;
                    xyz[3 * v + 2] = z;
                }
            }
            int t = 0;
            for (int j = 0; j < Cells; j++)
            {
                for (int i = 0; i < Cells; i++)
                {
                    int a = j * (Cells + 1) + i, b = a + 1, c = a + Cells + 2, d = a + Cells + 1;
                    foreach (int v in new[] { a, d, c, a, c, b }) triangles[t++] = v;
                }
            }
            return LamellaMesh.FromArrays(xyz, triangles);
        }

        /// <summary>Interior vertices block; the boundary is free (its samples see past the strips' ends).</summary>
        private static ShadingLabel[] Labels()
        {
            var labels = new ShadingLabel[Vertices];
            for (int v = 0; v < Vertices; v++)
            {
                int i = v % (Cells + 1), j = v / (Cells + 1);
                labels[v] = i == 0 || j == 0 || i == Cells || j == Cells ? ShadingLabel.Free : ShadingLabel.Block;
            }
            return labels;
        }

        private static ShadingSite Noon() => ShadingSite.Default().WithDates(6, 14, 6, 28).WithHours(11.5, 12.5);

        private static ShadingSolver Solved(LamellaMesh mesh)
        {
            var shading = new ShadingSolver(mesh, Noon(), Labels(), 0);
            ShadingReport report = shading.Report;
            for (int k = 0; k < 6 && !report.IsConverged; k++) report = shading.Step(10);
            return shading;
        }

        [Test]
        public void StripsOnAFacadeBlockTheNoonSun()
        {
            using (var mesh = Facade(0.0))
            using (var shading = Solved(mesh))
            using (var strips = shading.BuildStrips(6, 1.5))
            {
                ShadingReport report = shading.Report;
                Assert.Greater(report.Iterations, 0);
                Assert.AreEqual(Vertices - 4 * Cells, report.BlockVertices, "the interior vertices block");
                Assert.AreEqual(0, report.PassVertices);
                // The slope vote on a vertical south facade near noon: tangents orthogonal to the sun are horizontal,
                // slope 0 up to half a 5° bin.
                Assert.IsTrue(report.StartSlopeDegrees.HasValue);
                Assert.LessOrEqual(Math.Abs(report.StartSlopeDegrees.Value), 2.5);
                Assert.AreEqual(Vertices, shading.Field().Length);
                // Started near the horizontal, every quad's plane ends orthogonal to the noon sun itself.
                double e = NoonElevation * Math.PI / 180.0;
                CheckNoonBlocking(shading, strips, new[] { new[] { 0.0, -Math.Cos(e), Math.Sin(e) } });
            }
        }

        /// <summary>
        /// What strips on the plane facade must do against the noon sun: acceptable, θ within 5° of 90° ∓ the noon
        /// elevation, every quad's plane orthogonal to one of <paramref name="suns"/> within 5°, the block region's
        /// direct-sun hours blocked (at least 0.9, the mean of its vertices' fractions).
        /// </summary>
        private static void CheckNoonBlocking(ShadingSolver shading, Strips strips, double[][] suns)
        {
            Assert.IsTrue(strips.Verdict.IsAcceptable, strips.Verdict.Message);
            double[] thetas = shading.Thetas();
            Assert.AreEqual(strips.Count, thetas.Length);
            foreach (double theta in thetas)
            {
                Assert.Less(Math.Min(Math.Abs(theta - (90.0 + NoonElevation)), Math.Abs(theta - (90.0 - NoonElevation))), 5.0, "θ " + theta);
            }
            // Every quad's plane is orthogonal to one of the suns within a few degrees.
            double[] xyz = strips.Vertices();
            int[] quads = strips.Quads();
            Assert.Greater(quads.Length, 0);
            double worst = 0.0;
            for (int q = 0; q < quads.Length; q += 4)
            {
                double[] p0 = Vec.At(xyz, quads[q]), p1 = Vec.At(xyz, quads[q + 1]), p2 = Vec.At(xyz, quads[q + 2]), p3 = Vec.At(xyz, quads[q + 3]);
                double[] normal = Vec.Cross(Vec.Sub(p2, p0), Vec.Sub(p3, p1));
                double angle = double.PositiveInfinity;
                foreach (double[] sun in suns) angle = Math.Min(angle, Vec.Degrees(Math.Abs(Vec.Dot(normal, sun)) / Vec.Norm(normal)));
                worst = Math.Max(worst, angle);
            }
            Assert.Less(worst, 5.0);

            SunPathSummary summary = shading.Evaluate(strips, 0.05);
            Assert.AreEqual(30, summary.BlockSuns, "15 days × the hours 11.5 and 12.5");
            Assert.IsTrue(summary.BlockFraction.HasValue);
            Assert.GreaterOrEqual(summary.BlockFraction.Value, 0.9);
            Assert.IsNull(summary.PassFraction);
            double?[] fractions = shading.VertexFractions();
            Assert.AreEqual(Vertices, fractions.Length);
            ShadingLabel[] labels = Labels();
            double sum = 0.0;
            int count = 0;
            for (int v = 0; v < Vertices; v++)
            {
                Assert.IsTrue(fractions[v].HasValue);
                if (labels[v] != ShadingLabel.Block) continue;
                sum += fractions[v].Value;
                count++;
            }
            // Every sample sees the same suns on a plane: the region's fraction is its vertices' mean.
            Assert.AreEqual(summary.BlockFraction.Value, sum / count, 1e-12);
        }

        [Test]
        public void StripsOnATwistedFacadeMissTheirTheta()
        {
            using (var mesh = Facade(0.4))
            using (var shading = Solved(mesh))
            using (var strips = shading.BuildStrips(6, 1.5))
            {
                Verdict verdict = strips.Verdict;
                Assert.IsFalse(verdict.IsAcceptable);
                StringAssert.Contains("worst: strip", verdict.Message);
                Assert.Throws<NoAcceptableFamilyException>(strips.EnsureAcceptable);
            }
        }

        [Test]
        public void SiteTextsParseAsTheCliFlags()
        {
            ShadingSite parsed = ShadingSite.Default().WithDates("06-14..06-28").WithHours("11.5..12.5");
            ShadingSite built = Noon();
            Assert.AreEqual(new uint[] { 6, 14, 6, 28 }, new[] { parsed.FirstMonth, parsed.FirstDay, parsed.LastMonth, parsed.LastDay });
            Assert.AreEqual(new[] { built.FirstHour, built.LastHour, built.PassFirstHour, built.PassLastHour },
                new[] { parsed.FirstHour, parsed.LastHour, parsed.PassFirstHour, parsed.PassLastHour });
            Assert.Throws<FormatException>(() => ShadingSite.Default().WithDates("June"));
            Assert.Throws<FormatException>(() => ShadingSite.Default().WithHours("10..noon"));
            // Pass hours replace only the letting-through hours.
            ShadingSite pass = parsed.WithPassHours("8..9.5");
            Assert.AreEqual(new[] { 11.5, 12.5, 8.0, 9.5 }, new[] { pass.FirstHour, pass.LastHour, pass.PassFirstHour, pass.PassLastHour });
            Assert.Throws<FormatException>(() => parsed.WithPassHours("8-9"));
            // Blocked fractions are coloured over the fixed range [0, 1]: the ramp's ends, clamped, grey for none.
            int[] colours = Conversion.FieldColours.Argb(new[] { 0.0, 1.0, 1.5, double.NaN }, 0.0, 1.0);
            Assert.AreEqual(unchecked((int)0xFF313695), colours[0]);
            Assert.AreEqual(unchecked((int)0xFFA50026), colours[1]);
            Assert.AreEqual(colours[1], colours[2]);
            Assert.AreEqual(Conversion.FieldColours.Missing, colours[3]);
        }

        /// <summary>
        /// Sun directions (x east, y north, z up) of the hours 11.5 to 12.5 true solar time (hour angle H within ±7.5°, every
        /// 0.25°) at 47.4° north and declination 23.3° (late June): (−cos δ sin H, sin δ cos φ − cos δ cos H sin φ,
        /// sin δ sin φ + cos δ cos H cos φ).
        /// </summary>
        private static double[][] SunsOfTheHours()
        {
            double degree = Math.PI / 180.0, phi = 47.4 * degree, delta = 23.3 * degree;
            var suns = new double[61][];
            for (int k = 0; k < suns.Length; k++)
            {
                double h = (-7.5 + 0.25 * k) * degree;
                suns[k] = new[]
                {
                    -Math.Cos(delta) * Math.Sin(h),
                    Math.Sin(delta) * Math.Cos(phi) - Math.Cos(delta) * Math.Cos(h) * Math.Sin(phi),
                    Math.Sin(delta) * Math.Sin(phi) + Math.Cos(delta) * Math.Cos(h) * Math.Cos(phi),
                };
            }
            return suns;
        }

        /// <summary>The height z tilted by a quarter of x (level curves at 14° to the horizontal): not the default start.</summary>
        private static double[] TiltedHeight()
        {
            var field = new double[Vertices];
            for (int v = 0; v < Vertices; v++) field[v] = (-2.0 + 4.0 * (v / (Cells + 1)) / Cells) + 0.25 * (-2.0 + 4.0 * (v % (Cells + 1)) / Cells);
            return field;
        }

        [Test]
        public void AGivenStartFieldIsHonoured()
        {
            using (var mesh = Facade(0.0))
            {
                double[] start = TiltedHeight();
                using (var shading = new ShadingSolver(mesh, Noon(), Labels(), 0, start))
                {
                    // Before any step the field is the start, up to the rounding of the solver's internal scaling (f · s / s).
                    double[] field = shading.Field();
                    Assert.AreEqual(start.Length, field.Length);
                    double largest = 0.0;
                    foreach (double f in start) largest = Math.Max(largest, Math.Abs(f));
                    for (int v = 0; v < Vertices; v++) Assert.AreEqual(start[v], field[v], 2 * 2.220446049250313e-16 * largest, "vertex " + v);
                    ShadingReport report = shading.Report;
                    Assert.AreEqual(0, report.Iterations);
                    Assert.IsNull(report.StartSlopeDegrees, "no constant-slope start");
                    for (int k = 0; k < 6 && !report.IsConverged; k++) report = shading.Step(10);
                    Assert.Greater(report.Iterations, 0);
                    // Started 14° off the horizontal, the curves need only turn until they are orthogonal to some sun of
                    // the hours (up to 7.5° off the horizontal at 11.5 h): each quad's plane against the nearest of them.
                    using (var strips = shading.BuildStrips(6, 1.5)) CheckNoonBlocking(shading, strips, SunsOfTheHours());
                }
            }
        }

        [Test]
        public void ABadStartFieldIsRefusedWithTheNativeMessage()
        {
            using (var mesh = Facade(0.0))
            {
                double[] start = TiltedHeight();
                start[11] = double.NaN;
                var error = Assert.Throws<LamellaException>(() => new ShadingSolver(mesh, Noon(), Labels(), 0, start));
                Assert.AreEqual(Status.InvalidArgument, error.Status);
                StringAssert.Contains("start_field", error.NativeMessage);
                StringAssert.Contains("vertex 11", error.NativeMessage);
                var constant = new double[Vertices];
                for (int v = 0; v < Vertices; v++) constant[v] = 1.5;
                error = Assert.Throws<LamellaException>(() => new ShadingSolver(mesh, Noon(), Labels(), 0, constant));
                Assert.AreEqual(Status.SingularField, error.Status);
                StringAssert.Contains("constant", error.NativeMessage);
                // Labels and start of the same wrong length: the native count check.
                error = Assert.Throws<LamellaException>(() => new ShadingSolver(mesh, Noon(), new ShadingLabel[Vertices - 1], 0, new double[Vertices - 1]));
                StringAssert.Contains("labels for 49 vertices", error.NativeMessage);
                // A start of another length than the labels never reaches the library (it reads as many values as labels).
                Assert.Throws<ArgumentException>(() => new ShadingSolver(mesh, Noon(), Labels(), 0, new double[Vertices - 1]));
                Assert.Throws<ArgumentNullException>(() => new ShadingSolver(mesh, Noon(), Labels(), 0, null));
            }
        }

        [Test]
        public void InvalidArgumentsAreRefusedByName()
        {
            using (var mesh = Facade(0.0))
            {
                ShadingSite site = Noon();
                site.LatitudeDegrees = double.NaN;
                var error = Assert.Throws<LamellaException>(() => new ShadingSolver(mesh, site, Labels(), 0));
                StringAssert.Contains("latitude", error.Message);
                error = Assert.Throws<LamellaException>(() => new ShadingSolver(mesh, Noon(), new ShadingLabel[Vertices - 1], 0));
                StringAssert.Contains("labels for 49 vertices", error.Message);
                ShadingLabel[] labels = Labels();
                labels[3] = (ShadingLabel)7;
                error = Assert.Throws<LamellaException>(() => new ShadingSolver(mesh, Noon(), labels, 0));
                StringAssert.Contains("labels[3]", error.Message);
                using (var shading = new ShadingSolver(mesh, Noon(), Labels(), 0))
                {
                    error = Assert.Throws<LamellaException>(() => shading.BuildStrips(6, double.NaN));
                    StringAssert.Contains("width", error.Message);
                    Assert.Throws<ArgumentNullException>(() => shading.Evaluate(null, 0.05));
                }
            }
        }
    }
}
