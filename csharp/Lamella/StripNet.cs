using System;
using Lamella.Interop;

namespace Lamella
{
    /// <summary>
    /// One node of a gridshell (<c>LmlNode</c>): where a strip of the first family crosses one of the second (paper
    /// Sec. 5.1); of a 3-web's, a <see cref="WebNode"/>, whose per-strip entries (index 0 and 1) are of its two
    /// <see cref="WebNode.Families"/>. Lengths in the mesh's unit, angles in degrees.
    /// </summary>
    public class Node
    {
        internal Node(NodeRecord r)
        {
            Vertex = checked((int)r.Vertex);
            Strips = new[] { checked((int)r.Strips[0]), checked((int)r.Strips[1]) };
            ArcLengths = (double[])r.ArcLengths.Clone();
            Position = (double[])r.Position.Clone();
            Axis = (double[])r.Axis.Clone();
            RulingAngleDegrees = r.RulingAngleDegrees;
            ConicalCurvature = new double?[2];
            DarbouxAngleDegrees = new double?[2];
            BinormalOffset = new double?[2];
            for (int k = 0; k < 2; k++)
            {
                if (r.DiagnosticsDefined[k] == 0) continue;
                ConicalCurvature[k] = r.ConicalCurvature[k];
                DarbouxAngleDegrees[k] = r.DarbouxAngleDegrees[k];
                BinormalOffset[k] = r.BinormalOffset[k];
            }
            SingularPointNear = new[] { r.SingularPointNear[0] != 0, r.SingularPointNear[1] != 0 };
        }

        /// <summary>Index of the crossing among the net's (or the web's) vertices.</summary>
        public int Vertex { get; }
        /// <summary>Index of the strip of each family (into that family's <see cref="Lamella.Strips"/>).</summary>
        public int[] Strips { get; }
        /// <summary>Arc length of the node along each strip's centre line from its first point: where the hole goes.</summary>
        public double[] ArcLengths { get; }
        /// <summary>The crossing on the surface (x, y, z).</summary>
        public double[] Position { get; }
        /// <summary>Unit node axis: the mean of the two strips' unit rulings at the node.</summary>
        public double[] Axis { get; }
        /// <summary>Angle between the two rulings as lines, in [0°, 90°]: 0 for a torsion-free node (Sec. 5.2).</summary>
        public double RulingAngleDegrees { get; }
        /// <summary>Each strip's conical curvature k = τ/κ at its centre-line vertex nearest to the node (Sec. 5.1); null where the strip is straight.</summary>
        public double?[] ConicalCurvature { get; }
        /// <summary>Each strip's angle atan |k| between binormal and the rectifying developable's ruling there; null where undefined.</summary>
        public double?[] DarbouxAngleDegrees { get; }
        /// <summary>Prop. 2's κ k² v² / 2 at half the strip width, per strip: the binormal point's distance from the developable; null where undefined.</summary>
        public double?[] BinormalOffset { get; }
        /// <summary>Per strip: the singular point of its ruling lies inside the strip or within one strip width of it (Prop. 1).</summary>
        public bool[] SingularPointNear { get; }
    }

    /// <summary>
    /// A gridshell as built from two strip families (<c>LmlStripNet</c>, paper Sec. 4.1 and 5.1): the quad net where the
    /// level curves carrying strips cross, and the nodes where the strips cross.
    /// </summary>
    public sealed class StripNet : IDisposable
    {
        private readonly StripNetHandle handle;

        /// <summary>The native net, for <see cref="BaseMeshSolver"/>.</summary>
        internal StripNetHandle Handle => handle;

        /// <summary>
        /// The net of <paramref name="net"/>'s two fields at the levels of <paramref name="first"/> (strips on field 0's
        /// level curves, <see cref="LevelCurves.OfNet"/>) and <paramref name="second"/> (field 1's), and their nodes.
        /// </summary>
        public StripNet(NetSolver net, Strips first, Strips second)
        {
            if (net == null) throw new ArgumentNullException(nameof(net));
            if (first == null) throw new ArgumentNullException(nameof(first));
            if (second == null) throw new ArgumentNullException(nameof(second));
            StripNetHandle created = null;
            Native.Check(net.Locked(h => NativeMethods.lml_strip_net_new(h, first.Handle, second.Handle, out created)));
            handle = created;
        }

        /// <summary>The net's vertices as x, y, z triples: the crossing of level i of field 0 with level j of field 1.</summary>
        public double[] Vertices() =>
            Native.Read((double[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_strip_net_vertices(handle, b, c, out n));

        /// <summary>The level indices (i, j) of each vertex, as pairs: rows share i, columns share j.</summary>
        public int[] Levels() =>
            Array.ConvertAll(Native.Read((uint[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_strip_net_levels(handle, b, c, out n)), i => checked((int)i));

        /// <summary>The quads as vertex-index quadruples: (i, j), (i, j + 1), (i + 1, j + 1), (i + 1, j).</summary>
        public int[] Quads() =>
            Array.ConvertAll(Native.Read((uint[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_strip_net_quads(handle, b, c, out n)), i => checked((int)i));

        /// <summary>The nodes: every crossing where both families carry a strip.</summary>
        public Node[] Nodes() =>
            Array.ConvertAll(Native.Read((NodeRecord[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_strip_net_nodes(handle, b, c, out n)), r => new Node(r));

        /// <summary>Releases the native net.</summary>
        public void Dispose() => handle.Dispose();
    }
}
