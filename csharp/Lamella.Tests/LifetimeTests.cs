using System;
using System.Threading;
using NUnit.Framework;

namespace Lamella.Tests
{
    /// <summary>Handles are released exactly once: by Dispose (twice is harmless) or, when leaked, by the finalizers.</summary>
    [TestFixture]
    public class LifetimeTests
    {
        private static void Collect()
        {
            GC.Collect();
            GC.WaitForPendingFinalizers();
            GC.Collect();
            GC.WaitForPendingFinalizers();
        }

        [Test]
        public void DisposingTwiceIsHarmlessAndUseAfterDisposeThrows()
        {
            Collect();
            long before = Library.DebugLiveHandles;
            var c = new Cylinder(12, 8, 5);
            var mesh = LamellaMesh.FromArrays(c.Xyz, c.Triangles);
            var field = new FieldSolver(mesh, c.InitialField, FieldParams.Default(Family.PseudoGeodesic, 60));
            var curves = LevelCurves.Uniform(field, 2, 1.0);
            var strips = Strips.Build(curves, StripParams.Default(60, 0.5));
            var guides = GuideCurves.Trace(mesh, new[] { BoundaryStarts.Nearest(mesh, 11, 0, 7) }, 60, 90);
            var search = new StartSearch(mesh, FieldParams.Default(Family.PseudoGeodesic, 60));
            Assert.AreEqual(before + 6, Library.DebugLiveHandles);
            foreach (IDisposable d in new IDisposable[] { search, guides, strips, curves, field, mesh })
            {
                d.Dispose();
                d.Dispose();
            }
            Assert.AreEqual(before, Library.DebugLiveHandles);
            Assert.Throws<ObjectDisposedException>(() => { var n = mesh.VertexCount; });
            Assert.Throws<ObjectDisposedException>(() => field.Step(1));
            Assert.Throws<ObjectDisposedException>(() => curves.Points());
            Assert.Throws<ObjectDisposedException>(() => { var n = strips.Count; });
            Assert.Throws<ObjectDisposedException>(() => guides.Points());
            Assert.Throws<ObjectDisposedException>(() => search.Step());
        }

        [Test]
        public void LeakedHandlesAreFreedByFinalizers()
        {
            Collect();
            Assert.AreEqual(0L, Library.DebugLiveHandles, "no handle may be alive between tests");
            long whileAlive = -1;
            // Created on a thread that then ends, so that no stack slot (Mono scans stacks conservatively)
            // keeps the leaked objects reachable.
            var worker = new Thread(() =>
            {
                var c = new Cylinder(12, 8, 9);
                var mesh = LamellaMesh.FromArrays(c.Xyz, c.Triangles);
                var field = new FieldSolver(mesh, c.InitialField, FieldParams.Default(Family.PseudoGeodesic, 60));
                field.Step(2);
                var curves = LevelCurves.Uniform(field, 2, 1.0);
                Strips.Build(curves, StripParams.Default(60, 0.5));
                FieldSolver.Load(field.Save());
                // A search, and a field taken from another one: both live on their own.
                new StartSearch(mesh, FieldParams.Default(Family.PseudoGeodesic, 60));
                var probed = new StartSearch(mesh, FieldParams.Default(Family.PseudoGeodesic, 60));
                while (probed.Step()) { }
                probed.TakeField();
                whileAlive = Library.DebugLiveHandles;
            });
            worker.Start();
            worker.Join();
            Assert.AreEqual(8L, whileAlive);
            Collect();
            Assert.AreEqual(0L, Library.DebugLiveHandles);
        }

        [Test]
        public void LeakedGuideCurvesAreFreedByFinalizers()
        {
            Collect();
            Assert.AreEqual(0L, Library.DebugLiveHandles, "no handle may be alive between tests");
            long whileAlive = -1, afterMeshDisposed = -1;
            int pointsWithoutMesh = -1;
            var worker = new Thread(() =>
            {
                var c = new Cylinder(12, 8, 9);
                var mesh = LamellaMesh.FromArrays(c.Xyz, c.Triangles);
                GuideCurves.Trace(mesh, new[] { BoundaryStarts.Nearest(mesh, 11, 0, 4), BoundaryStarts.Nearest(mesh, 11, 0, 10) }, 60, 90);
                var kept = GuideCurves.Trace(mesh, new[] { BoundaryStarts.Nearest(mesh, 11, 0, 7) }, 60, 90);
                whileAlive = Library.DebugLiveHandles;
                mesh.Dispose();
                // The guides hold their own reference to the surface: still usable without the mesh.
                afterMeshDisposed = Library.DebugLiveHandles;
                pointsWithoutMesh = kept.Points().Length;
            });
            worker.Start();
            worker.Join();
            Assert.AreEqual(3L, whileAlive);
            Assert.AreEqual(2L, afterMeshDisposed);
            Assert.Greater(pointsWithoutMesh, 3);
            Collect();
            Assert.AreEqual(0L, Library.DebugLiveHandles);
        }
    }
}
