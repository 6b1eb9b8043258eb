using System;
using System.Collections.Generic;
using System.Globalization;
using System.Threading;
using Lamella.Conversion;
using Lamella.Hosting;
using NUnit.Framework;

namespace Lamella.Tests
{
    /// <summary>The host-side bookkeeping of the Grasshopper plugin, without Grasshopper: result slots, live-solve pace, defaults, colours, labels.</summary>
    [TestFixture]
    public class HostingTests
    {
        private sealed class Counted : IDisposable
        {
            public int Disposals;
            public void Dispose() => Disposals++;
        }

        [Test]
        public void SlotsReleaseOnlyWhatTheyReplaceOrTrim()
        {
            var slots = new IterationSlots<Counted>();
            Counted a = new Counted(), b = new Counted(), c = new Counted(), d = new Counted();
            slots.Set(0, a);
            slots.Set(2, b);
            Assert.AreEqual(3, slots.Count);
            Assert.IsNull(slots[1]);
            Assert.IsNull(slots[7]);
            slots.Set(0, a);
            Assert.AreEqual(0, a.Disposals, "storing the same object again keeps it");
            slots.Set(0, c);
            Assert.AreEqual(1, a.Disposals, "a replaced result is released");
            slots.Set(1, d);
            slots.Trim(2);
            Assert.AreEqual(1, b.Disposals, "iteration 2 is gone");
            Assert.AreEqual(0, c.Disposals + d.Disposals, "iterations 0 and 1 stay");
            CollectionAssert.AreEqual(new[] { 0, 1 }, new List<KeyValuePair<int, Counted>>(slots.Stored()).ConvertAll(p => p.Key));
            slots.Dispose();
            Assert.AreEqual(1, c.Disposals);
            Assert.AreEqual(1, d.Disposals);
            Assert.AreEqual(0, slots.Count);
            Assert.Throws<ArgumentOutOfRangeException>(() => slots.Set(-1, a));
        }

        [Test]
        public void AnIterationKeepsEveryLinkOfItsChainUntilCleared()
        {
            var results = new IterationResults();
            Counted mesh = new Counted(), session = new Counted(), curves = new Counted(), other = new Counted();
            // One iteration builds a chain; keeping a later link must not release an earlier one.
            Assert.AreSame(mesh, results.Keep(0, mesh));
            results.Keep(0, session);
            results.Keep(0, curves);
            results.Keep(0, session);
            results.Keep(1, other);
            Assert.AreEqual(3, results.CountAt(0));
            Assert.AreEqual(1, results.CountAt(1));
            Assert.AreEqual(0, mesh.Disposals + session.Disposals + curves.Disposals + other.Disposals, "nothing released while the solution stands");
            results.Clear();
            Assert.AreEqual(new[] { 1, 1, 1, 1 }, new[] { mesh.Disposals, session.Disposals, curves.Disposals, other.Disposals }, "each released once");
            Assert.AreEqual(0, results.CountAt(0));
            Assert.Throws<ArgumentNullException>(() => results.Keep<Counted>(0, null));
            Assert.Throws<ArgumentOutOfRangeException>(() => results.Keep(-1, mesh));
        }

        [Test]
        public void SlotsReleaseNativeResults()
        {
            var grid = new Grid(8, 8, 1.0, 0, 0);
            long before = Library.DebugLiveHandles;
            using (var mesh = LamellaMesh.FromArrays(grid.Xyz, grid.Triangles()))
            using (var field = new FieldSolver(mesh, grid.Values((x, y) => x + 0.1 * y * y), FieldParams.Default(Family.PseudoGeodesic, 60)))
            {
                var slots = new IterationSlots<LevelCurves>();
                // One solution with three iterations (a list of three level counts), then one with a single iteration.
                for (int i = 0; i < 3; i++) slots.Set(i, LevelCurves.Uniform(field, i + 1, 0));
                Assert.AreEqual(before + 5, Library.DebugLiveHandles);
                LevelCurves kept = slots[0];
                slots.Trim(1);
                Assert.AreEqual(before + 3, Library.DebugLiveHandles);
                Assert.AreEqual(1, kept.Count, "iteration 0 is still readable");
                slots.Clear();
                Assert.AreEqual(before + 2, Library.DebugLiveHandles);
            }
            Assert.AreEqual(before, Library.DebugLiveHandles);
        }

        [Test]
        public void LiveSolveWaitsAsLongAsTheLastCycleWasBusy()
        {
            double now = 0;
            var live = new LiveSolve(() => now, 80, 10, 1000);
            live.SolutionStarted();
            Assert.AreEqual(10, live.NextDelayMs(), "no cycle measured yet: the shortest delay");
            now = 10 + 250; // the delay, then 250 ms of solver, downstream components and redraw
            live.SolutionStarted();
            Assert.AreEqual(250, live.LastBusyMs, 1e-9);
            Assert.AreEqual(250, live.NextDelayMs());
            now += 250 + 3000; // a slow downstream component
            live.SolutionStarted();
            Assert.AreEqual(1000, live.NextDelayMs(), "at most the longest delay");
            now += 1000 + 2;
            live.SolutionStarted();
            Assert.AreEqual(10, live.NextDelayMs(), "at least the shortest delay");
            Assert.AreEqual(20, live.BudgetPerSession(4), 1e-12, "running sessions share the budget");
            Assert.AreEqual(80, live.BudgetPerSession(0), 1e-12);
            Assert.IsTrue(live.RunSwitchedOn(), "Run goes on");
            Assert.IsFalse(live.RunSwitchedOn(), "and stays on");
            live.Cancel();
            Assert.IsTrue(live.Cancelled);
            live.RunSwitchedOff();
            Assert.IsFalse(live.Cancelled);
            Assert.IsTrue(live.RunSwitchedOn(), "on again after off");
            Assert.Throws<ArgumentOutOfRangeException>(() => new LiveSolve(() => 0, 0));
        }

        [Test]
        public void DefaultWidthIsARoundShareOfTheModelSize()
        {
            // A 40 × 24 m roof: 2 % of the 46.6 m diagonal is 0.93 → 1 m; the same roof in millimetres → 1000 mm.
            Assert.AreEqual(1.0, StripDefaults.Width(new double[] { 0, 0, 0, 40, 24, 0 }), 1e-12);
            Assert.AreEqual(1000.0, StripDefaults.Width(new double[] { 0, 0, 0, 40000, 24000, 0 }), 1e-9);
            Assert.AreEqual(0.5, StripDefaults.Gap(1.0));
            Assert.AreEqual(0.2, StripDefaults.Round(0.3), 1e-15);
            Assert.AreEqual(5.0, StripDefaults.Round(3.3), 1e-15);
            Assert.AreEqual(0.002, StripDefaults.Round(0.0021), 1e-18);
            Assert.AreEqual(10.0, StripDefaults.Round(8.0), 1e-15);
            Assert.Throws<ArgumentException>(() => StripDefaults.Width(new double[] { 1, 1, 1, 1, 1, 1 }), "a point has no size");
            Assert.Throws<ArgumentOutOfRangeException>(() => StripDefaults.Round(0));
        }

        [Test]
        public void FieldColoursSpanTheRange()
        {
            int[] colours = FieldColours.Argb(new[] { 2.0, 4.0, double.NaN, 3.0 });
            Assert.AreEqual(unchecked((int)0xFF313695), colours[0], "the minimum: first stop");
            Assert.AreEqual(unchecked((int)0xFFA50026), colours[1], "the maximum: last stop");
            Assert.AreEqual(FieldColours.Missing, colours[2]);
            Assert.AreEqual(unchecked((int)0xFFE0F3F8), colours[3], "the middle: middle stop");
            Assert.AreEqual(unchecked((int)0xFFE0F3F8), FieldColours.Argb(new[] { 7.0, 7.0 })[1], "a constant field: middle stop");
            foreach (int colour in colours) Assert.AreEqual(0xFF, (colour >> 24) & 0xFF, "opaque");
        }

        [Test]
        public void StripDescriptionsAreCultureInvariant()
        {
            CultureInfo saved = Thread.CurrentThread.CurrentCulture;
            try
            {
                Thread.CurrentThread.CurrentCulture = new CultureInfo("de-DE");
                var metrics = new[] { new StripMetrics { Curve = 3, Length = 12.5, MaxDiffThetaDegrees = 0.25, EStraight = 1.5e-4, MaxPlanar = 2e-9, ApproPercent = 0.125, MaxQuadAngleErrorDegrees = 1.5 } };
                string line = StripLabels.Describe(metrics)[0];
                StringAssert.StartsWith("S0 (curve 3): length 12.5, diff_θ 0.25°", line);
                StringAssert.Contains("Appro 0.125%", line);
                StringAssert.Contains("plane angle error 1.5°", line);
                StringAssert.DoesNotContain(",5", line);
                // The start search's words: directions and angles with points.
                var height = new Candidate(2, new Interop.CandidateRecord { Kind = 0, Negated = 1, Direction = new[] { 0.5, 0.25, 0.75 }, Scored = 1, Score = 1.5 }, "minus height along (0.500, 0.250, 0.750): score 1.50");
                Assert.AreEqual("start: minus height (0.5, 0.25, 0.75)", StartDescriptions.Short(height));
                StringAssert.EndsWith("(candidate 2, the best of 8)", StartDescriptions.Chosen(height, 8));
                var guides = new Candidate(9, new Interop.CandidateRecord { Kind = 1, Side = 2, StartAngleDegrees = 62.5, Rejected = 1 }, "guides from boundary side 2 at 62.5°: rejected: …");
                Assert.AreEqual("start: guides, side 2, 62.5°", StartDescriptions.Short(guides));
            }
            finally
            {
                Thread.CurrentThread.CurrentCulture = saved;
            }
        }
    }
}
