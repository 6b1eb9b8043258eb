using System;
using System.IO;
using Lamella.Interop;
using NUnit.Framework;

namespace Lamella.Tests
{
    /// <summary>Every failure status of the C ABI surfaces as a <see cref="LamellaException"/> carrying the status and the native message.</summary>
    [TestFixture]
    public class ErrorTests
    {
        // The unit square as two triangles.
        private static readonly double[] Square = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0 };
        private static readonly int[] SquareTriangles = { 0, 1, 2, 0, 2, 3 };

        private static LamellaException Expect(Status status, TestDelegate call, string inMessage)
        {
            var e = Assert.Throws<LamellaException>(call);
            Assert.AreEqual(status, e.Status);
            Assert.IsNotEmpty(e.NativeMessage);
            StringAssert.Contains(inMessage, e.NativeMessage);
            StringAssert.Contains(Library.StatusName(status), e.Message);
            StringAssert.Contains(e.NativeMessage, e.Message);
            return e;
        }

        [Test]
        public void InvalidArgument()
        {
            Expect(Status.InvalidArgument, () => FieldParams.Default(Family.PseudoGeodesic, 200), "180");
            Expect(Status.InvalidArgument, () => StripParams.Default(60, -1), "width");
            string missing = Path.Combine(Path.GetTempPath(), "lamella-no-such-file.obj");
            Expect(Status.InvalidArgument, () => LamellaMesh.ReadObj(missing), "lamella-no-such-file.obj");
            // A search for θ out of range: refused by the constructor (as the header promises) or, today, by a step before
            // any candidate is scored.
            var beyond = FieldParams.Default(Family.PseudoGeodesic, 60);
            beyond.ThetaDegrees = 200;
            var c = new Cylinder(12, 8, 3);
            using (var mesh = LamellaMesh.FromArrays(c.Xyz, c.Triangles))
            {
                Expect(Status.InvalidArgument, () =>
                {
                    using (var search = new StartSearch(mesh, beyond))
                    {
                        while (search.Step()) Assert.IsNull(search.Winner);
                    }
                }, "theta");
            }
        }

        [Test]
        public void InvalidMesh()
        {
            var e = Expect(Status.InvalidMesh, () => LamellaMesh.FromArrays(Square, new[] { 0, 1, 9 }), "9");
            StringAssert.Contains("vertex", e.NativeMessage);
            Expect(Status.InvalidMesh, () => LamellaMesh.FromArrays(new[] { 0, 0, double.NaN, 1, 0, 0, 0, 1, 0 }, new[] { 0, 1, 2 }), "vertex 0");
        }

        [Test]
        public void NotADisk()
        {
            // Two triangles that share nothing: two components.
            double[] xyz = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 5, 0, 0, 6, 0, 0, 5, 1, 0 };
            Expect(Status.NotADisk, () => LamellaMesh.FromArrays(xyz, new[] { 0, 1, 2, 3, 4, 5 }), "component");
        }

        [Test]
        public void SingularField()
        {
            using (var mesh = LamellaMesh.FromArrays(Square, SquareTriangles))
            {
                Expect(Status.SingularField, () => new FieldSolver(mesh, new double[4], FieldParams.Default(Family.Geodesic, 0)), "constant");
                // A search with no scored candidate has no field to give; it stays usable.
                using (var search = new StartSearch(mesh, FieldParams.Default(Family.PseudoGeodesic, 60)))
                {
                    Expect(Status.SingularField, () => search.TakeField(), "no candidate start");
                    Assert.IsFalse(search.IsFieldTaken);
                    Assert.IsNull(search.Winner);
                }
            }
        }

        /// <summary>
        /// Not a failure of the call (the strips are built) but the one status a caller can ask to have thrown:
        /// <see cref="Strips.EnsureAcceptable"/> throws the typed exception with the verdict and the native message.
        /// </summary>
        [Test]
        public void NoAcceptableFamily()
        {
            var c = new Cylinder(12, 8, 3);
            using (var mesh = LamellaMesh.FromArrays(c.Xyz, c.Triangles))
            using (var field = new FieldSolver(mesh, c.InitialField, FieldParams.Default(Family.PseudoGeodesic, 60)))
            using (var curves = LevelCurves.Uniform(field, 3, 1.0))
            {
                // A plane angle error of a millionth of a degree is beyond any strip on a triangle mesh.
                StripParams strict = StripParams.Default(60, 0.5);
                strict.ToleranceDegrees = 1e-6;
                using (var strips = Strips.Build(curves, strict))
                {
                    Assert.Greater(strips.Count, 0, "built all the same");
                    var e = Assert.Throws<NoAcceptableFamilyException>(strips.EnsureAcceptable);
                    Assert.AreEqual(Status.NoAcceptableFamily, e.Status);
                    StringAssert.StartsWith("no acceptable family: ", e.NativeMessage);
                    StringAssert.Contains("by more than 0.000001°", e.NativeMessage);
                    StringAssert.Contains(Library.StatusName(Status.NoAcceptableFamily), e.Message);
                    Assert.IsFalse(e.Verdict.IsAcceptable);
                    Assert.AreEqual(1e-6, e.Verdict.ToleranceDegrees);
                    Assert.Greater(e.Verdict.StripsMissingTheta, 0);
                }
                // Out of (0, 180) the tolerance is refused.
                strict.ToleranceDegrees = 0;
                Expect(Status.InvalidArgument, () => Strips.Build(curves, strict), "tolerance_degrees");
            }
        }

        [Test]
        public void DidNotConverge()
        {
            var c = new Cylinder(12, 8, 3);
            using (var mesh = LamellaMesh.FromArrays(c.Xyz, c.Triangles))
            using (var field = new FieldSolver(mesh, c.InitialField, FieldParams.Default(Family.PseudoGeodesic, 60)))
            {
                Expect(Status.DidNotConverge, () => field.Solve(1), "not converged");
                // The session stays usable.
                Assert.AreEqual(2UL, field.Step(1).Iterations);
            }
        }

        [Test]
        public void BufferTooSmall()
        {
            // The wrappers size every buffer; the raw call shows the status would surface too.
            using (var mesh = LamellaMesh.FromArrays(Square, SquareTriangles))
            {
                UIntPtr needed;
                Expect(Status.BufferTooSmall, () => Native.Check(NativeMethods.lml_mesh_positions(mesh.Handle, new double[2], new UIntPtr(2), out needed)), "12");
            }
        }

        [Test]
        public void CorruptData()
        {
            Expect(Status.CorruptData, () => FieldSolver.Load(new byte[] { 1, 2, 3, 4, 5 }), "");
            Expect(Status.CorruptData, () => FieldSolver.Load(new byte[0]), "");
        }

        [Test]
        public void InternalError()
        {
            Expect(Status.InternalError, Library.DebugTriggerPanic, "panic");
            // The library is still fine after a caught panic.
            Assert.AreEqual(Library.BindingAbiVersion, Library.AbiVersion);
        }

        [Test]
        public void InvalidGuides()
        {
            var c = new Cylinder(12, 8, 3);
            using (var mesh = LamellaMesh.FromArrays(c.Xyz, c.Triangles))
            using (var one = GuideCurves.Trace(mesh, new[] { BoundaryStarts.Nearest(mesh, 11, 0, 7) }, 60, 90))
            {
                double target;
                Expect(Status.InvalidGuides, () => InitialField.FromGuides(mesh, one, out target), "at least 2");
            }
        }

        [Test]
        public void InvalidStrokes()
        {
            var c = new Cylinder(12, 8, 3);
            using (var mesh = LamellaMesh.FromArrays(c.Xyz, c.Triangles))
            {
                double theta;
                // One stroke along the patch's middle height.
                var middle = new double[] { 10 * Math.Cos(0.5), 10 * Math.Sin(0.5), 7, 10 * Math.Cos(1.0), 10 * Math.Sin(1.0), 7.5 };
                Expect(Status.InvalidStrokes, () => InitialField.FromStrokes(mesh, new[] { middle }, out theta), "at least 2");
                // Two strokes, the second's point 1 far outside the surface.
                var far = new double[] { 10 * Math.Cos(0.5), 10 * Math.Sin(0.5), 3, 30, 30, 3 };
                Expect(Status.InvalidStrokes, () => InitialField.FromStrokes(mesh, new[] { middle, far }, out theta), "stroke 1, point 1");
            }
        }

        [Test]
        public void GuideArgumentsAreInvalidArguments()
        {
            var c = new Cylinder(12, 8, 3);
            using (var mesh = LamellaMesh.FromArrays(c.Xyz, c.Triangles))
            {
                EdgePoint start = BoundaryStarts.Nearest(mesh, 11, 0, 7);
                // Start 1 lies on an interior edge (vertices 14 and 15 of the 13 x 9 grid's second row).
                Expect(Status.InvalidArgument, () => GuideCurves.Trace(mesh, new[] { start, new EdgePoint(14, 15, 0.5) }, 60, 90), "starts[1]");
                Expect(Status.InvalidArgument, () => GuideCurves.Trace(mesh, new[] { start }, 200, 90), "theta_degrees");
                Expect(Status.InvalidArgument, () => GuideCurves.Trace(mesh, new[] { start }, 60, 0), "start_angle_degrees");
                var options = TraceOptions.Default();
                options.MaxTurnDegrees = 120;
                Expect(Status.InvalidArgument, () => GuideCurves.Trace(mesh, new[] { start }, 60, 90, options), "max_turn_degrees");
                Expect(Status.InvalidArgument, () => BoundaryStarts.At(mesh, 0, 1.5), "1.5");
                Expect(Status.InvalidArgument, () => BoundaryStarts.SegmentCount(mesh, 3), "loop 3");
                Expect(Status.InvalidArgument, () => BoundaryStarts.EvenlySpaced(mesh, 0, 30, 9, 2), "segment 9");
                double theta;
                // Offsets that decrease.
                Expect(Status.InvalidArgument, () => InitialField.FromStrokes(mesh, new double[] { 10, 0, 3, 10, 0, 4 }, new[] { 0, 2, 1 }, out theta), "offset");
                // Guides traced on another mesh.
                var other = new Cylinder(14, 8, 3);
                using (var otherMesh = LamellaMesh.FromArrays(other.Xyz, other.Triangles))
                using (var guides = GuideCurves.Trace(otherMesh, new[] { BoundaryStarts.Nearest(otherMesh, 11, 0, 4), BoundaryStarts.Nearest(otherMesh, 11, 0, 10) }, 60, 90))
                {
                    double target;
                    Expect(Status.InvalidArgument, () => InitialField.FromGuides(mesh, guides, out target), "135 vertices");
                }
            }
        }

        [Test]
        public void EveryFailureStatusIsCovered()
        {
            // Each negative status, and NoAcceptableFamily (the success EnsureAcceptable throws on), has a test method of its name above.
            foreach (Status status in Enum.GetValues(typeof(Status)))
            {
                if ((int)status >= 0 && status != Status.NoAcceptableFamily) continue;
                Assert.IsNotNull(typeof(ErrorTests).GetMethod(status.ToString()), "no test for " + status);
            }
        }

        [Test]
        public void ManagedArgumentsAreCheckedBeforeTheCall()
        {
            Assert.Throws<ArgumentException>(() => LamellaMesh.FromArrays(new double[4], SquareTriangles));
            Assert.Throws<ArgumentOutOfRangeException>(() => LamellaMesh.FromArrays(Square, new[] { 0, -1, 2 }));
            Assert.Throws<ArgumentNullException>(() => FieldSolver.Load(null));
            Assert.Throws<ArgumentNullException>(() => GuideCurves.Trace(null, new EdgePoint[0], 60, 90));
            Assert.Throws<ArgumentNullException>(() => new StartSearch(null, FieldParams.Default(Family.PseudoGeodesic, 60)));
            Assert.Throws<ArgumentNullException>(() => Utf8.FromTerminated(null));
            using (var square = LamellaMesh.FromArrays(Square, SquareTriangles))
            {
                double theta;
                Assert.Throws<ArgumentOutOfRangeException>(() => BoundaryStarts.EvenlySpaced(square, 0, 30, 0, -1));
                Assert.Throws<ArgumentOutOfRangeException>(() => InitialField.FromStrokes(square, new double[6], new[] { 0, -2 }, out theta));
                Assert.Throws<ArgumentException>(() => InitialField.FromStrokes(square, new double[5], new[] { 0, 1 }, out theta));
                using (var search = new StartSearch(square, FieldParams.Default(Family.PseudoGeodesic, 60)))
                {
                    Assert.Throws<ArgumentOutOfRangeException>(() => search.Candidate(-1));
                    // Past the candidates probed so far: the library names the index.
                    Expect(Status.InvalidArgument, () => search.Candidate(0), "out of range");
                }
            }
        }
    }
}
