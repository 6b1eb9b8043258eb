using System;
using System.Collections.Generic;
using System.Globalization;
using Lamella.Interop;

namespace Lamella
{
    /// <summary>
    /// The state of a <see cref="BaseMeshSolver"/> (<c>LmlBaseMeshReport</c>), measured from outside: each family's angle
    /// at the net's own vertices against the reference's smooth normal, the distance from the reference, the ruling angle
    /// at the nodes. Lengths in the net's units, angles in degrees; index 0 is the rows, 1 the columns (a web's diagonals:
    /// <see cref="BaseMeshSolver.FamilyReport"/>(2)).
    /// </summary>
    public sealed class BaseMeshReport
    {
        internal BaseMeshReport(BaseMeshReportRecord r)
        {
            Iterations = checked((long)r.Iterations);
            IsConverged = r.Converged != 0;
            TargetDegrees = (double[])r.TargetDegrees.Clone();
            AngleErrorRmsDegrees = (double[])r.AngleErrorRmsDegrees.Clone();
            AngleErrorMaxDegrees = (double[])r.AngleErrorMaxDegrees.Clone();
            MeasuredVertices = new[] { checked((long)r.MeasuredVertices[0]), checked((long)r.MeasuredVertices[1]) };
            StraightVertices = new[] { checked((long)r.StraightVertices[0]), checked((long)r.StraightVertices[1]) };
            MaxDeviation = r.MaxDeviation;
            RmsDeviation = r.RmsDeviation;
            MaxDeviationPercent = r.MaxDeviationPercent;
            NodeCount = checked((long)r.NodeCount);
            NodeRulingAngleMaxDegrees = r.NodeRulingAngleMaxDegrees;
            NodeRulingAngleRmsDegrees = r.NodeRulingAngleRmsDegrees;
            FamiliesMet = r.FamiliesMet != 0;
            IsTorsionFree = r.TorsionFree != 0;
            Energy = r.Energy;
        }

        /// <summary>Iterations run since the session was created.</summary>
        public long Iterations { get; }
        /// <summary>True when converged (further steps do nothing).</summary>
        public bool IsConverged { get; }
        /// <summary>Each family's target along its polylines' direction: θ, or 180° − θ for a pseudo-geodesic family whose polylines run the other way.</summary>
        public double[] TargetDegrees { get; }
        /// <summary>RMS of each family's |θ_measured − target| over its measured vertices.</summary>
        public double[] AngleErrorRmsDegrees { get; }
        /// <summary>Largest angle error of each family.</summary>
        public double[] AngleErrorMaxDegrees { get; }
        /// <summary>Inner vertices of each family where the angle was measured.</summary>
        public long[] MeasuredVertices { get; }
        /// <summary>Inner vertices of each family where the polyline is straight (a miss for a pseudo-geodesic family).</summary>
        public long[] StraightVertices { get; }
        /// <summary>Largest distance of a vertex from the reference.</summary>
        public double MaxDeviation { get; }
        /// <summary>RMS distance of the vertices from the reference.</summary>
        public double RmsDeviation { get; }
        /// <summary><see cref="MaxDeviation"/> in % of the reference's bounding-box diagonal.</summary>
        public double MaxDeviationPercent { get; }
        /// <summary>Nodes (vertices inside a row and a column) whose two strips both exist.</summary>
        public long NodeCount { get; }
        /// <summary>Largest angle between the two strips' rulings at a node: 0 where every node is torsion-free (Sec. 5.2.1).</summary>
        public double NodeRulingAngleMaxDegrees { get; }
        /// <summary>RMS of the nodes' ruling angles.</summary>
        public double NodeRulingAngleRmsDegrees { get; }
        /// <summary>True when every measured vertex of every family (a web's diagonals too) is within 1° of its target (and no pseudo-geodesic family is straight anywhere).</summary>
        public bool FamiliesMet { get; }
        /// <summary>True when every node's ruling angle is at most 0.5°.</summary>
        public bool IsTorsionFree { get; }
        /// <summary>The weighted energy being minimised (on the net scaled to mean segment length 1).</summary>
        public double Energy { get; }

        /// <summary>Several lines: iterations, each family's angle error against its target, the deviation, the nodes.</summary>
        public string Describe() =>
            string.Format(CultureInfo.InvariantCulture,
                "{0}\niterations {1}, energy {2:0.###e+0}\nrows: {3:0.###}° max, {4:0.###}° RMS off {5:0.###}° ({6} vertices); columns: {7:0.###}° max, {8:0.###}° RMS off {9:0.###}° ({10} vertices){11}\n" +
                "deviation from the reference: max {12:0.####} ({13:0.###} % of its diagonal), RMS {14:0.####}\nnode ruling angles: max {15:0.###}°, RMS {16:0.###}° over {17} nodes{18}",
                IsConverged ? "converged" : "not converged", Iterations, Energy,
                AngleErrorMaxDegrees[0], AngleErrorRmsDegrees[0], TargetDegrees[0], MeasuredVertices[0],
                AngleErrorMaxDegrees[1], AngleErrorRmsDegrees[1], TargetDegrees[1], MeasuredVertices[1], FamiliesMet ? ", families met" : ", families not met",
                MaxDeviation, MaxDeviationPercent, RmsDeviation,
                NodeRulingAngleMaxDegrees, NodeRulingAngleRmsDegrees, NodeCount, IsTorsionFree ? ", torsion-free" : "");

        /// <inheritdoc />
        public override string ToString() =>
            string.Format(CultureInfo.InvariantCulture, "iteration {0}, angle error {1:0.###}° / {2:0.###}°, node ruling angle {3:0.###}°{4}",
                Iterations, AngleErrorMaxDegrees[0], AngleErrorMaxDegrees[1], NodeRulingAngleMaxDegrees, IsConverged ? ", converged" : "");
    }

    /// <summary>
    /// One family's part of a <see cref="BaseMeshReport"/> (<c>LmlBaseMeshFamilyReport</c>, from
    /// <see cref="BaseMeshSolver.FamilyReport"/>): its angle measured at its polylines' inner vertices against the
    /// reference's smooth normal. Angles in degrees.
    /// </summary>
    public sealed class BaseMeshFamilyReport
    {
        internal BaseMeshFamilyReport(int family, BaseMeshFamilyReportRecord r)
        {
            Family = family;
            TargetDegrees = r.TargetDegrees;
            AngleErrorRmsDegrees = r.AngleErrorRmsDegrees;
            AngleErrorMaxDegrees = r.AngleErrorMaxDegrees;
            MeasuredVertices = checked((long)r.MeasuredVertices);
            StraightVertices = checked((long)r.StraightVertices);
        }

        /// <summary>The family: 0 the rows, 1 the columns, 2 a web's diagonals.</summary>
        public int Family { get; }
        /// <summary>The family's target along its polylines' direction (θ or 180° − θ; a slope for a constant-slope family).</summary>
        public double TargetDegrees { get; }
        /// <summary>RMS of |θ_measured − target| over the measured vertices.</summary>
        public double AngleErrorRmsDegrees { get; }
        /// <summary>Largest |θ_measured − target|.</summary>
        public double AngleErrorMaxDegrees { get; }
        /// <summary>Inner vertices of the family's polylines where the angle was measured (straight ones included for geodesics and asymptotic curves, with no error).</summary>
        public long MeasuredVertices { get; }
        /// <summary>Inner vertices where the polyline is straight (a miss for a pseudo-geodesic family).</summary>
        public long StraightVertices { get; }

        /// <summary>The family's name in texts: "rows", "columns" or "diagonals".</summary>
        public string Name => BaseMeshSolver.FamilyName(Family);

        /// <inheritdoc />
        public override string ToString() =>
            string.Format(CultureInfo.InvariantCulture, "{0}: {1:0.###}° max, {2:0.###}° RMS off {3:0.###}° ({4} vertices)",
                Name, AngleErrorMaxDegrees, AngleErrorRmsDegrees, TargetDegrees, MeasuredVertices);
    }

    /// <summary>
    /// A node of an optimised net (<c>LmlBaseMeshNode</c>): a vertex inside a row and a column, with the angle between
    /// the rulings of its row's and its column's strips there (paper Sec. 5.2.1).
    /// </summary>
    public sealed class BaseMeshNode
    {
        internal BaseMeshNode(BaseMeshNodeRecord r)
        {
            Vertex = checked((int)r.Vertex);
            if (r.Defined == 0) return;
            RulingAngleDegrees = r.RulingAngleDegrees;
            Axis = (double[])r.Axis.Clone();
        }

        /// <summary>The vertex (index into <see cref="BaseMeshSolver.Positions"/>).</summary>
        public int Vertex { get; }
        /// <summary>Angle between the two rulings as lines, in [0°, 90°] (0: torsion-free); null where a polyline through the node carries no strip.</summary>
        public double? RulingAngleDegrees { get; }
        /// <summary>Unit node axis (x, y, z): the mean of the two unit rulings; null where <see cref="RulingAngleDegrees"/> is.</summary>
        public double[] Axis { get; }
    }

    /// <summary>
    /// Optimises a base mesh for strip structures (paper Sec. 3.5, <c>LmlBaseMesh</c>): a net of rows and columns, or a
    /// 3-web of rows, columns and diagonals (<see cref="Web"/>, <see cref="FromStripWeb"/>), is moved near a reference
    /// surface until each family of polylines is the asked curves (θ: 0° and 180° asymptotic curves, 90° geodesics, others
    /// pseudo-geodesics), for a net optionally with torsion-free nodes (Eq. 21): the strips of a node's row and column
    /// share its ruling. Then every polyline carries a developable strip of planar quads (<see cref="BuildStrips"/>).
    /// Stepped like <see cref="FieldSolver"/>; one thread at a time (calls are serialised by a lock).
    /// </summary>
    public sealed class BaseMeshSolver : IDisposable
    {
        private readonly BaseMeshHandle handle;
        private readonly object gate = new object();

        /// <summary>
        /// Starts from a net given as <paramref name="points"/> (x, y, z per vertex) and its polylines: each row and each
        /// column a list of vertex indices in order along it (at least two; a vertex on at most one row and one column).
        /// </summary>
        /// <exception cref="LamellaException">θ out of range (named), a non-finite point, a polyline referring to a vertex out of range or of fewer than two vertices, a vertex on two rows or two columns (named).</exception>
        public BaseMeshSolver(LamellaMesh reference, double[] points, int[][] rows, int[][] columns, double thetaRowsDegrees, double thetaColumnsDegrees,
            bool torsionFree)
        {
            if (reference == null) throw new ArgumentNullException(nameof(reference));
            if (points == null) throw new ArgumentNullException(nameof(points));
            if (points.Length % 3 != 0) throw new ArgumentException("points holds " + points.Length + " values, not a multiple of 3", nameof(points));
            uint[] lengths;
            uint[] vertices = Concatenate(new[] { rows, columns }, out lengths);
            Native.Check(NativeMethods.lml_base_mesh_new(reference.Handle, points, Native.Size(points.Length / 3), vertices, Native.Size(vertices.Length),
                lengths, Native.Size(rows.Length), Native.Size(columns.Length), thetaRowsDegrees, thetaColumnsDegrees, torsionFree ? 1u : 0u, out handle));
        }

        /// <summary>
        /// Starts from the quad net of a gridshell (<see cref="StripNet.Vertices"/>; rows share the level i of field 0,
        /// columns the level j of field 1), near <paramref name="reference"/> (usually the mesh the net was solved on).
        /// </summary>
        /// <exception cref="LamellaException">θ out of range (named), or a net with no row or column of three or more vertices.</exception>
        public BaseMeshSolver(StripNet net, LamellaMesh reference, double thetaRowsDegrees, double thetaColumnsDegrees, bool torsionFree)
        {
            if (net == null) throw new ArgumentNullException(nameof(net));
            if (reference == null) throw new ArgumentNullException(nameof(reference));
            Native.Check(NativeMethods.lml_base_mesh_from_strip_net(net.Handle, reference.Handle, thetaRowsDegrees, thetaColumnsDegrees,
                torsionFree ? 1u : 0u, out handle));
        }

        private BaseMeshSolver(BaseMeshHandle handle)
        {
            this.handle = handle;
        }

        /// <summary>
        /// Starts from a net given as in the constructor, toward two families of constant slope about one axis (Sec.
        /// 5.2.2–5.2.3, <c>lml_base_mesh_new_slopes</c>): every segment at its family's slope β against the planes orthogonal
        /// to <paramref name="axis"/>, the axis in every rectifying plane, so every strip's rulings and every node's axis
        /// are parallel to it. The report's targets and errors are slopes then.
        /// </summary>
        /// <exception cref="LamellaException">A slope outside (−90°, 90°) or a zero axis (named), or the net refused as in the constructor.</exception>
        public static BaseMeshSolver ConstantSlopes(LamellaMesh reference, double[] points, int[][] rows, int[][] columns, double slopeRowsDegrees,
            double slopeColumnsDegrees, double[] axis)
        {
            if (reference == null) throw new ArgumentNullException(nameof(reference));
            if (points == null) throw new ArgumentNullException(nameof(points));
            if (axis == null) throw new ArgumentNullException(nameof(axis));
            if (points.Length % 3 != 0) throw new ArgumentException("points holds " + points.Length + " values, not a multiple of 3", nameof(points));
            if (axis.Length != 3) throw new ArgumentException("axis holds " + axis.Length + " values, not 3", nameof(axis));
            uint[] lengths;
            uint[] vertices = Concatenate(new[] { rows, columns }, out lengths);
            BaseMeshHandle handle;
            Native.Check(NativeMethods.lml_base_mesh_new_slopes(reference.Handle, points, Native.Size(points.Length / 3), vertices,
                Native.Size(vertices.Length), lengths, Native.Size(rows.Length), Native.Size(columns.Length), slopeRowsDegrees, slopeColumnsDegrees,
                axis, out handle));
            return new BaseMeshSolver(handle);
        }

        /// <summary>
        /// Starts from a 3-web (paper Sec. 3.5 on Sec. 4.2's webs, <c>lml_base_mesh_new_web</c>) given as
        /// <paramref name="points"/> (x, y, z per vertex) and its polylines, as in the constructor with the diagonals, the
        /// third family, after the columns (a vertex on at most one polyline of each family). Each family by its angle θ
        /// in [0°, 180°]: (0, 0, 90) asks for an AAG web, its rows and columns asymptotic, its diagonals geodesic. A web
        /// has no torsion-free option. The web's triangles are <see cref="Triangles"/>.
        /// </summary>
        /// <exception cref="LamellaException">θ out of range (named <c>thetas[i]</c>), no diagonal, a non-finite point, a polyline referring to a vertex out of range or of fewer than two vertices, a vertex on two polylines of one family (named).</exception>
        public static BaseMeshSolver Web(LamellaMesh reference, double[] points, int[][] rows, int[][] columns, int[][] diagonals,
            double thetaRowsDegrees, double thetaColumnsDegrees, double thetaDiagonalsDegrees)
        {
            if (reference == null) throw new ArgumentNullException(nameof(reference));
            if (points == null) throw new ArgumentNullException(nameof(points));
            if (points.Length % 3 != 0) throw new ArgumentException("points holds " + points.Length + " values, not a multiple of 3", nameof(points));
            uint[] lengths;
            uint[] vertices = Concatenate(new[] { rows, columns, diagonals }, out lengths);
            BaseMeshHandle handle;
            Native.Check(NativeMethods.lml_base_mesh_new_web(reference.Handle, points, Native.Size(points.Length / 3), vertices,
                Native.Size(vertices.Length), lengths, Native.Size(rows.Length), Native.Size(columns.Length), Native.Size(diagonals.Length),
                new[] { thetaRowsDegrees, thetaColumnsDegrees, thetaDiagonalsDegrees }, out handle));
            return new BaseMeshSolver(handle);
        }

        /// <summary>
        /// Starts from the web of a 3-web gridshell (<c>lml_base_mesh_from_strip_web</c>): its vertices are
        /// <see cref="StripWeb.Vertices"/>, its rows, columns and diagonals <see cref="StripWeb.Polylines"/> of families 0, 1
        /// and 2, near <paramref name="reference"/> (usually the mesh the 3-web was solved on); θ as in <see cref="Web"/>.
        /// </summary>
        /// <exception cref="LamellaException">θ out of range (named), or a web with no polyline of three or more vertices.</exception>
        public static BaseMeshSolver FromStripWeb(StripWeb web, LamellaMesh reference, double thetaRowsDegrees, double thetaColumnsDegrees,
            double thetaDiagonalsDegrees)
        {
            if (web == null) throw new ArgumentNullException(nameof(web));
            if (reference == null) throw new ArgumentNullException(nameof(reference));
            BaseMeshHandle handle;
            Native.Check(NativeMethods.lml_base_mesh_from_strip_web(web.Handle, reference.Handle,
                new[] { thetaRowsDegrees, thetaColumnsDegrees, thetaDiagonalsDegrees }, out handle));
            return new BaseMeshSolver(handle);
        }

        /// <summary>
        /// Restores a session saved with <see cref="Save"/> (<c>lml_base_mesh_load</c>); it continues bit for bit as the
        /// saved one would have.
        /// </summary>
        /// <exception cref="LamellaException"><see cref="Status.CorruptData"/> for damaged, truncated or foreign bytes (another kind of session, another format version).</exception>
        public static BaseMeshSolver Load(byte[] bytes)
        {
            if (bytes == null) throw new ArgumentNullException(nameof(bytes));
            BaseMeshHandle loaded;
            Native.Check(NativeMethods.lml_base_mesh_load(bytes, Native.Size(bytes.Length), out loaded));
            return new BaseMeshSolver(loaded);
        }

        /// <summary>
        /// The whole session as bytes (<c>lml_base_mesh_save</c>): the net as given, the reference, families, stage,
        /// positions with their auxiliary variables, solver state, the initial and the last report.
        /// </summary>
        public byte[] Save()
        {
            lock (gate)
            {
                return Native.Read((byte[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_base_mesh_save(handle, b, c, out n));
            }
        }

        /// <summary>The polylines of each family (rows, columns, diagonals) one after another as vertex indices, and their lengths.</summary>
        private static uint[] Concatenate(int[][][] families, out uint[] lengths)
        {
            var polylines = new List<int[]>();
            var names = new List<string>();
            for (int k = 0; k < families.Length; k++)
            {
                if (families[k] == null) throw new ArgumentNullException(FamilyName(k));
                for (int l = 0; l < families[k].Length; l++)
                {
                    string name = FamilyName(k) + "[" + l + "]";
                    if (families[k][l] == null) throw new ArgumentNullException(name, "a polyline is null");
                    polylines.Add(families[k][l]);
                    names.Add(name);
                }
            }
            lengths = new uint[polylines.Count];
            long total = 0;
            for (int l = 0; l < polylines.Count; l++)
            {
                lengths[l] = (uint)polylines[l].Length;
                total += polylines[l].Length;
            }
            var vertices = new uint[checked((int)total)];
            int at = 0;
            for (int l = 0; l < polylines.Count; l++)
            {
                foreach (int v in polylines[l])
                {
                    if (v < 0) throw new ArgumentOutOfRangeException(names[l], "vertex index " + v + " is negative");
                    vertices[at++] = (uint)v;
                }
            }
            return vertices;
        }

        /// <summary>"rows", "columns" or "diagonals": family <paramref name="k"/>'s polylines by name.</summary>
        public static string FamilyName(int k) => k == 0 ? "rows" : k == 1 ? "columns" : "diagonals";

        /// <summary>2 for a net of rows and columns, 3 for a web of rows, columns and diagonals.</summary>
        public int FamilyCount
        {
            get
            {
                lock (gate)
                {
                    uint count;
                    Native.Check(NativeMethods.lml_base_mesh_family_count(handle, out count));
                    return checked((int)count);
                }
            }
        }

        /// <summary>Throws unless <paramref name="k"/> is one of the session's families.</summary>
        private void CheckFamily(int k)
        {
            int count = FamilyCount;
            if (k < 0 || k >= count)
            {
                throw new ArgumentOutOfRangeException(nameof(k), k, count == 2 ? "a net has families 0 (rows) and 1 (columns)"
                    : "a web has families 0 (rows), 1 (columns) and 2 (diagonals)");
            }
        }

        /// <summary>The weights the session optimises with (<c>lml_base_mesh_weights</c>).</summary>
        public BaseMeshWeights Weights
        {
            get
            {
                lock (gate)
                {
                    BaseMeshWeights weights;
                    Native.Check(NativeMethods.lml_base_mesh_weights(handle, out weights));
                    return weights;
                }
            }
        }

        /// <summary>
        /// Replaces the weights before the first iteration (<c>lml_base_mesh_set_weights</c>): the same as a session started
        /// with them.
        /// </summary>
        /// <exception cref="LamellaException"><see cref="Status.InvalidArgument"/> for a weight out of range (named, e.g. <c>weights.pull</c>) or a session that has already iterated (<c>weights</c>); the session is then unchanged.</exception>
        public void SetWeights(BaseMeshWeights weights)
        {
            lock (gate)
            {
                Native.Check(NativeMethods.lml_base_mesh_set_weights(handle, ref weights));
            }
        }

        /// <summary>Runs at most <paramref name="maxIterations"/> iterations; returns the state (converged or not).</summary>
        public BaseMeshReport Step(int maxIterations)
        {
            if (maxIterations < 0) throw new ArgumentOutOfRangeException(nameof(maxIterations));
            lock (gate)
            {
                BaseMeshReportRecord record;
                Native.Check(NativeMethods.lml_base_mesh_step(handle, (uint)maxIterations, out record));
                return new BaseMeshReport(record);
            }
        }

        /// <summary>The state after the last step (or after creation).</summary>
        public BaseMeshReport Report
        {
            get
            {
                lock (gate)
                {
                    BaseMeshReportRecord record;
                    Native.Check(NativeMethods.lml_base_mesh_report(handle, out record));
                    return new BaseMeshReport(record);
                }
            }
        }

        /// <summary>The state of the net as given, before any iteration.</summary>
        public BaseMeshReport InitialReport
        {
            get
            {
                lock (gate)
                {
                    BaseMeshReportRecord record;
                    Native.Check(NativeMethods.lml_base_mesh_initial_report(handle, out record));
                    return new BaseMeshReport(record);
                }
            }
        }

        /// <summary>
        /// Family <paramref name="k"/>'s part (0: rows, 1: columns, 2: a web's diagonals) of the state after the last step (or
        /// after creation); for 0 and 1 the numbers at that index of <see cref="Report"/>.
        /// </summary>
        public BaseMeshFamilyReport FamilyReport(int k)
        {
            CheckFamily(k);
            lock (gate)
            {
                BaseMeshFamilyReportRecord record;
                Native.Check(NativeMethods.lml_base_mesh_family_report(handle, (uint)k, out record));
                return new BaseMeshFamilyReport(k, record);
            }
        }

        /// <summary>
        /// A web's triangles, three vertex indices (into <see cref="Positions"/>) each, one after another: the cycles of one
        /// segment of each family (in a 3-web the halves of the rows' and columns' quads, in a Kagome pattern its
        /// triangles). Empty for a net of rows and columns.
        /// </summary>
        public int[] Triangles()
        {
            lock (gate)
            {
                return Array.ConvertAll(Native.Read((uint[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_base_mesh_triangles(handle, b, c, out n)),
                    i => checked((int)i));
            }
        }

        /// <summary>The current vertex positions, x, y, z per vertex, in the order they were given.</summary>
        public double[] Positions()
        {
            lock (gate)
            {
                return Native.Read((double[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_base_mesh_positions(handle, b, c, out n));
            }
        }

        /// <summary>The nodes (every vertex inside a row and a column, in vertex order) with their ruling angles after the last step.</summary>
        public BaseMeshNode[] Nodes()
        {
            lock (gate)
            {
                return Array.ConvertAll(Native.Read((BaseMeshNodeRecord[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_base_mesh_nodes(handle, b, c, out n)),
                    r => new BaseMeshNode(r));
            }
        }

        /// <summary>
        /// The rectifying strips of family <paramref name="k"/> (0: rows, 1: columns, 2: a web's diagonals) on the current
        /// net: on every polyline the developable strip of planar quads fitted to the nodes' common rulings (a web's
        /// diagonals to their own), <paramref name="width"/> wide, judged with <paramref name="toleranceDegrees"/> against the
        /// family's target (<see cref="Strips.Verdict"/>; a strip's curve index is its polyline's index within the family).
        /// </summary>
        /// <exception cref="ArgumentOutOfRangeException"><paramref name="k"/> is not one of the session's <see cref="FamilyCount"/> families.</exception>
        /// <exception cref="LamellaException">Width or tolerance out of range (named).</exception>
        public Strips BuildStrips(int k, double width, double toleranceDegrees = 2.0)
        {
            CheckFamily(k);
            lock (gate)
            {
                StripsHandle strips;
                Status status = Native.Check(NativeMethods.lml_base_mesh_strips(handle, (uint)k, width, toleranceDegrees, out strips));
                return Strips.FromNative(strips, status);
            }
        }

        /// <summary>Releases the native session.</summary>
        public void Dispose() => handle.Dispose();
    }
}
