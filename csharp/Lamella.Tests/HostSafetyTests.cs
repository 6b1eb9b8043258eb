using System;
using System.IO;
using System.Runtime.Serialization.Formatters.Binary;
using System.Threading;
using NUnit.Framework;

namespace Lamella.Tests
{
    /// <summary>Misuse a host application may commit: one session shared by threads, exceptions carried across a serialisation boundary.</summary>
    [TestFixture]
    public class HostSafetyTests
    {
        /// <summary>
        /// Two threads stepping and reading one session: the lock makes the calls run one after another, so the result equals
        /// the same number of steps on one thread (steps are deterministic), and no call sees a half-updated native state.
        /// </summary>
        [Test]
        public void OneSessionSteppedFromTwoThreadsEqualsTheSequentialRun()
        {
            const int StepsPerThread = 4;
            var c = new Cylinder(12, 8, 3);
            using (var mesh = LamellaMesh.FromArrays(c.Xyz, c.Triangles))
            using (var shared = new FieldSolver(mesh, c.InitialField, FieldParams.Default(Family.PseudoGeodesic, 60)))
            using (var alone = new FieldSolver(mesh, c.InitialField, FieldParams.Default(Family.PseudoGeodesic, 60)))
            {
                Exception failure = null;
                ThreadStart work = () =>
                {
                    try
                    {
                        for (int i = 0; i < StepsPerThread; i++)
                        {
                            shared.Step(1);
                            Assert.AreEqual(c.InitialField.Length, shared.Values().Length);
                        }
                    }
                    catch (Exception e)
                    {
                        Interlocked.CompareExchange(ref failure, e, null);
                    }
                };
                var threads = new[] { new Thread(work), new Thread(work) };
                foreach (var t in threads) t.Start();
                foreach (var t in threads) t.Join();
                Assert.IsNull(failure, failure?.ToString());

                for (int i = 0; i < 2 * StepsPerThread; i++) alone.Step(1);
                Assert.AreEqual(alone.Report.Iterations, shared.Report.Iterations);
                Assert.AreEqual(alone.Values(), shared.Values());
            }
        }

        /// <summary>A disposed session throws a managed exception rather than touching freed native memory.</summary>
        [Test]
        public void ADisposedSessionThrowsInsteadOfCallingIntoFreedMemory()
        {
            var c = new Cylinder(12, 8, 3);
            using (var mesh = LamellaMesh.FromArrays(c.Xyz, c.Triangles))
            {
                var field = new FieldSolver(mesh, c.InitialField, FieldParams.Default(Family.PseudoGeodesic, 60));
                field.Dispose();
                field.Dispose();
                Assert.Throws<ObjectDisposedException>(() => field.Step(1));
            }
        }

        /// <summary>The status and the native message survive a serialisation round trip.</summary>
        [Test]
        public void LamellaExceptionSerialisesItsStatusAndMessage()
        {
            var thrown = Assert.Throws<LamellaException>(() => StripParams.Default(60, -1));
            var formatter = new BinaryFormatter();
            LamellaException restored;
            using (var stream = new MemoryStream())
            {
                formatter.Serialize(stream, thrown);
                stream.Position = 0;
                restored = (LamellaException)formatter.Deserialize(stream);
            }
            Assert.AreEqual(Status.InvalidArgument, restored.Status);
            Assert.AreEqual(thrown.NativeMessage, restored.NativeMessage);
            StringAssert.Contains("width", restored.NativeMessage);
            Assert.AreEqual(thrown.Message, restored.Message);
        }
    }
}
