using System;
using System.Linq;
using NUnit.Framework;

namespace Lamella.Tests
{
    /// <summary>
    /// The viewer page of real strips on the cylinder through the binding: self-contained, every strip with its
    /// figures, the title escaped, the utilisation of a fabrication plan, the same bytes twice, bad input refused.
    /// </summary>
    [TestFixture]
    public class ViewTests
    {
        private static int Occurrences(string text, string part)
        {
            int count = 0;
            for (int at = text.IndexOf(part, StringComparison.Ordinal); at >= 0; at = text.IndexOf(part, at + part.Length, StringComparison.Ordinal)) count++;
            return count;
        }

        [Test]
        public void PageShowsEveryStripAndLoadsNothing()
        {
            LamellaMesh mesh;
            FieldSolver field;
            LevelCurves curves;
            using (Strips strips = FabricationTests.CylinderStrips(out mesh, out field, out curves))
            using (mesh)
            using (field)
            using (curves)
            using (Fabrication plan = Fabrication.Plan(strips, Material.Preset("timber"), 0.02, Stock.Boards(6.0)))
            {
                string html = strips.ViewHtml(curves, null, "cylinder <C#>");
                StringAssert.StartsWith("<!DOCTYPE html>", html);
                foreach (string forbidden in new[] { "http://", "https://", "src=" }) StringAssert.DoesNotContain(forbidden, html);
                StringAssert.Contains("<title>cylinder &lt;C#&gt; · Lamella</title>", html);
                Assert.AreEqual(2, Occurrences(html, "</script>"));
                for (int s = 0; s < strips.Count; s++) Assert.AreEqual(1, Occurrences(html, "\"name\":\"strip_" + s + "\""), "strip_" + s);
                Assert.AreEqual(strips.Count, Occurrences(html, "\"max_quad_angle_error_degrees\":"));
                StringAssert.Contains("\"has_utilisation\":false", html);
                Assert.AreEqual(html, strips.ViewHtml(curves, null, "cylinder <C#>"), "the same inputs give the same page");

                double[] utilisation = plan.StripChecks().Select(c => c.MaxUtilisation).ToArray();
                string stressed = strips.ViewHtml(curves, utilisation);
                StringAssert.Contains("\"has_utilisation\":true", stressed);
                StringAssert.Contains("<title>Lamella strips · Lamella</title>", stressed);

                var wrongCount = Assert.Throws<LamellaException>(() => strips.ViewHtml(curves, new[] { 0.5 }.Concat(utilisation).ToArray()));
                StringAssert.Contains("utilisation_count", wrongCount.Message);
                utilisation[0] = double.NaN;
                var notFinite = Assert.Throws<LamellaException>(() => strips.ViewHtml(curves, utilisation));
                StringAssert.Contains("strip 0 (`strip_0`): utilisation NaN is not finite", notFinite.Message);
                Assert.Throws<ArgumentNullException>(() => strips.ViewHtml(null));
            }
        }
    }
}
