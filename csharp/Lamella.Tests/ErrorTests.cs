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
        public void EveryFailureStatusIsCovered()
        {
            // Each negative status has a test method of its name above.
            foreach (Status status in Enum.GetValues(typeof(Status)))
            {
                if ((int)status >= 0) continue;
                Assert.IsNotNull(typeof(ErrorTests).GetMethod(status.ToString()), "no test for " + status);
            }
        }

        [Test]
        public void ManagedArgumentsAreCheckedBeforeTheCall()
        {
            Assert.Throws<ArgumentException>(() => LamellaMesh.FromArrays(new double[4], SquareTriangles));
            Assert.Throws<ArgumentOutOfRangeException>(() => LamellaMesh.FromArrays(Square, new[] { 0, -1, 2 }));
            Assert.Throws<ArgumentNullException>(() => FieldSolver.Load(null));
        }
    }
}
