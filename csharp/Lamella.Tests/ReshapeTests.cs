using System;
using NUnit.Framework;

namespace Lamella.Tests
{
    /// <summary>
    /// Surface optimisation through the binding (paper Sec. 3.3): the cylinder moved towards a 45° family within an
    /// absolute tolerance, the deviations checked against the distance from the axis; invalid arguments.
    /// </summary>
    [TestFixture]
    public class ReshapeTests
    {
        [Test]
        public void TheCylinderMovesWithinTheTolerance()
        {
            var cylinder = new Cylinder(16, 10, 11);
            const double tolerance = 0.2;
            using (var mesh = LamellaMesh.FromArrays(cylinder.Xyz, cylinder.Triangles))
            using (var reshape = new ReshapeSolver(mesh, cylinder.InitialField, 45.0, tolerance, false))
            {
                Assert.AreEqual(0, reshape.Report.Iterations);
                Assert.AreEqual(tolerance, reshape.Report.Tolerance, 1e-12);
                ReshapeReport report = reshape.Report;
                for (int k = 0; k < 30 && !report.IsConverged; k++)
                {
                    report = reshape.Step(10);
                }
                Assert.Greater(report.Iterations, 0);
                Assert.Greater(report.MaxDeviation, 0.0);
                Assert.LessOrEqual(report.MaxDeviation, tolerance);
                double[] xyz = reshape.Positions();
                double[] deviations = reshape.Deviations();
                Assert.AreEqual(3 * cylinder.VertexCount, xyz.Length);
                Assert.AreEqual(cylinder.VertexCount, deviations.Length);
                double largest = 0.0;
                for (int v = 0; v < cylinder.VertexCount; v++)
                {
                    // The original surface lies between the cylinder and its chords (sagitta of the widest cell,
                    // 1.5 x 150°/16 wide, 10 (1 − cos 7.03°) = 0.075): a
                    // vertex's distance from it is at least its distance from the cylinder less that.
                    double radial = Math.Abs(Math.Sqrt(xyz[3 * v] * xyz[3 * v] + xyz[3 * v + 1] * xyz[3 * v + 1]) - Cylinder.Radius);
                    Assert.GreaterOrEqual(deviations[v], radial - 0.076);
                    Assert.LessOrEqual(deviations[v], tolerance);
                    largest = Math.Max(largest, deviations[v]);
                }
                Assert.AreEqual(report.MaxDeviation, largest);
            }
        }

        [Test]
        public void ASavedSessionContinuesBitForBit()
        {
            var cylinder = new Cylinder(16, 10, 11);
            using (var mesh = LamellaMesh.FromArrays(cylinder.Xyz, cylinder.Triangles))
            using (var reshape = new ReshapeSolver(mesh, cylinder.InitialField, 45.0, 0.2, false))
            {
                reshape.Step(5);
                byte[] bytes = reshape.Save();
                using (var restored = ReshapeSolver.Load(bytes))
                {
                    CollectionAssert.AreEqual(reshape.Positions(), restored.Positions());
                    ReshapeReport a = reshape.Step(5), b = restored.Step(5);
                    Assert.AreEqual(a.Iterations, b.Iterations);
                    Assert.Greater(a.MaxDeviation, 0.0);
                    Assert.AreEqual(a.MaxDeviation, b.MaxDeviation);
                    CollectionAssert.AreEqual(reshape.Positions(), restored.Positions(), "the same bits after stepping on");
                    CollectionAssert.AreEqual(reshape.Save(), restored.Save(), "the same session after stepping on");
                }
                var truncated = new byte[bytes.Length / 2];
                Array.Copy(bytes, truncated, truncated.Length);
                var error = Assert.Throws<LamellaException>(() => ReshapeSolver.Load(truncated));
                Assert.AreEqual(Status.CorruptData, error.Status);
                Assert.Throws<ArgumentNullException>(() => ReshapeSolver.Load(null));
            }
        }

        [Test]
        public void ADocumentKeepsItsReshapeSessionsWhole()
        {
            // What Reshape Surface stores in a Grasshopper document (Hosting.StoredSessions over SessionArchive): every
            // held session whole, handed back once to the iteration and inputs it was saved for.
            var cylinder = new Cylinder(16, 10, 11);
            var sessions = new Hosting.LiveSessions<Hosting.SolverSession<ReshapeSolver, ReshapeReport>>();
            sessions.BeginSolution();
            Hosting.SolverSession<ReshapeSolver, ReshapeReport> held;
            using (var mesh = LamellaMesh.FromArrays(cylinder.Xyz, cylinder.Triangles))
            {
                held = sessions.Session(1, "inputs", false, () => Hosting.SolverSession.Of(new ReshapeSolver(mesh, cylinder.InitialField, 45.0, 0.2, false), "inputs"));
            }
            held.Solver.Step(5);
            byte[] document = new Hosting.StoredSessions().Save(sessions, solver => solver.Save());
            Assert.IsNotNull(document);

            var reopened = new Hosting.StoredSessions();
            reopened.Load(document);
            var none = new Hosting.LiveSessions<Hosting.SolverSession<ReshapeSolver, ReshapeReport>>();
            CollectionAssert.AreEqual(document, reopened.Save(none, solver => solver.Save()), "saved again before any solution: unchanged");
            Assert.IsNull(reopened.Take(1, "other inputs"));
            Assert.IsNull(reopened.Take(0, "inputs"));
            byte[] bytes = reopened.Take(1, "inputs");
            Assert.IsNotNull(bytes);
            Assert.IsNull(reopened.Take(1, "inputs"), "handed out once");
            using (ReshapeSolver restored = ReshapeSolver.Load(bytes))
            {
                Assert.AreEqual(5, restored.Report.Iterations);
                CollectionAssert.AreEqual(held.Solver.Positions(), restored.Positions());
                restored.Step(3);
                held.Solver.Step(3);
                CollectionAssert.AreEqual(held.Solver.Positions(), restored.Positions(), "continues bit for bit");
            }
            reopened.EndSolution();
            Assert.IsNull(reopened.Save(none, solver => solver.Save()), "nothing kept after a solution took none");

            var truncated = new byte[document.Length - 5];
            Array.Copy(document, truncated, truncated.Length);
            Assert.Throws<FormatException>(() => Hosting.SessionArchive.Read(truncated));
            var field = (byte[])document.Clone();
            field[3] = (byte)'A';
            StringAssert.Contains("bad magic", Assert.Throws<FormatException>(() => reopened.Load(field)).Message);
            Assert.IsNull(reopened.Take(1, "inputs"), "nothing loaded from bad bytes");
            sessions.Clear();
        }

        [Test]
        public void InvalidArgumentsAreRefusedByName()
        {
            var cylinder = new Cylinder(8, 6, 3);
            using (var mesh = LamellaMesh.FromArrays(cylinder.Xyz, cylinder.Triangles))
            {
                var field = cylinder.InitialField;
                var error = Assert.Throws<LamellaException>(() => new ReshapeSolver(mesh, field, 200.0, 0.1, false));
                StringAssert.Contains("theta", error.Message);
                error = Assert.Throws<LamellaException>(() => new ReshapeSolver(mesh, field, 45.0, -1.0, true));
                StringAssert.Contains("tolerance", error.Message);
                Assert.Throws<LamellaException>(() => new ReshapeSolver(mesh, new double[3], 45.0, 0.1, false));
                Assert.Throws<ArgumentNullException>(() => new ReshapeSolver(mesh, null, 45.0, 0.1, false));
                using (var reshape = new ReshapeSolver(mesh, field, 45.0, 0.1, false))
                {
                    Assert.Throws<ArgumentOutOfRangeException>(() => reshape.Step(-1));
                }
            }
        }
    }
}
