using System;
using System.Collections.Generic;
using System.Globalization;
using Grasshopper;
using Grasshopper.Kernel;
using Grasshopper.Kernel.Data;
using Lamella.Conversion;
using Lamella.Hosting;
using Rhino.Geometry;

namespace Lamella.Grasshopper
{
    /// <summary>
    /// What Strip Net and Strip Web share: a net session (two families or a 3-web) per iteration, started from the
    /// default start and kept across solutions while the mesh, the θs and Min Angle stay, solved live (Run: the level
    /// curves of the current fields are shown while it steps) or within one solution (Solve); once it has converged or
    /// stopped, the strips of every family on its level curves with their verdicts, and the nodes as points, axes and text.
    /// </summary>
    public abstract class GridshellComponent : LiveComponent
    {
        private readonly LiveSessions<SolverSession<NetSolver, NetReport>> sessions = new LiveSessions<SolverSession<NetSolver, NetReport>>();
        private readonly DocumentSessions<NetSolver, NetReport> saved;

        protected GridshellComponent(string name, string nickname, string description, string iconName)
            : base(name, nickname, description, iconName)
        {
            saved = new DocumentSessions<NetSolver, NetReport>("LamellaNetSessions", sessions, solver => solver.Save(),
                (bytes, signature) => SolverSession.Of(NetSolver.Load(bytes), signature));
        }

        protected override IDocumentState DocumentState => saved;

        protected override ILiveSessions Sessions => sessions;

        /// <summary>The end of the descriptions of the outputs built only once the solve has converged or stopped.</summary>
        protected const string BuiltOnceStopped = " Empty while Run steps: built once the solve converges or stops.";

        /// <summary>
        /// Registers the inputs every gridshell has: Mesh, one θ per family (<paramref name="thetas"/>: description and
        /// default of each), Min Angle, Count, then <paramref name="extras"/> inputs that <paramref name="addExtras"/>
        /// (null for none) adds, then Width (optional), Max Iterations, Solve and Run (after Solve, so that documents
        /// saved before Run existed keep their Solve wires). <paramref name="design"/> names the design ("net", "web").
        /// <see cref="ReadInputs"/> reads them.
        /// </summary>
        protected static void RegisterGridshellInputs(GH_InputParamManager pManager, string design, string[] thetaDescriptions, double[] thetaDefaults,
            string minAngleDescription, string countDescription, int extras, Action<GH_InputParamManager> addExtras)
        {
            pManager.AddMeshParameter("Mesh", "M", "The surface (triangulated and cleaned like Strip Field's input).", GH_ParamAccess.item);
            for (int k = 0; k < thetaDefaults.Length; k++)
            {
                pManager.AddNumberParameter("Theta " + (k + 1), "θ" + (k + 1), thetaDescriptions[k], GH_ParamAccess.item, thetaDefaults[k]);
            }
            pManager.AddNumberParameter("Min Angle", "MA", minAngleDescription, GH_ParamAccess.item, 30.0);
            pManager.AddIntegerParameter("Count", "N", countDescription, GH_ParamAccess.item, 8);
            if (addExtras != null) addExtras(pManager);
            pManager.AddNumberParameter("Width", "W", "Width of each flat strip, in document units, > 0. Default: a round number near 2 % of the curves' extent (named in a remark).", GH_ParamAccess.item);
            pManager[thetaDefaults.Length + 3 + extras].Optional = true;
            pManager.AddIntegerParameter("Max Iterations", "I", "The most solver iterations (a count, ≥ 1); live and one-shot solving stop there with a warning if not converged. Default 300.", GH_ParamAccess.item, 300);
            pManager.AddBooleanParameter("Solve", "Sv", SolveDescription("the " + design) + " Changing the mesh, a θ or Min Angle starts over; Count, Width and the others only rebuild the strips.", GH_ParamAccess.item, false);
            pManager.AddBooleanParameter("Run", "Run", RunDescription("the " + design,
                "; meanwhile Curves shows the level curves of the current fields and Report the state, and the strips, the " + design + ", the nodes and Acceptable are built once it converges or stops (at Max Iterations, on Escape, or when Run is switched off)"),
                GH_ParamAccess.item, false);
        }

        /// <summary>
        /// Registers the outputs every gridshell has: Curves and Strip Meshes (a branch per family, as
        /// <paramref name="branches"/> says; while Run steps, Curves holds the level curves of the current fields, at
        /// <paramref name="levels"/>), the outputs <paramref name="addDesign"/> adds (the net or web), Nodes, Node Axes and
        /// Node Data (nicknames <paramref name="nodesNickname"/> and <paramref name="axesNickname"/>; the nodes and their
        /// strips as <paramref name="nodes"/> and <paramref name="nodeStrips"/> describe them), Acceptable and Report
        /// (<paramref name="report"/>). Everything but Curves and Report is built once the solve converges or stops.
        /// </summary>
        protected static void RegisterGridshellOutputs(GH_OutputParamManager pManager, string branches, string levels, Action<GH_OutputParamManager> addDesign,
            string nodesNickname, string axesNickname, string nodes, string nodeStrips, string report)
        {
            pManager.AddCurveParameter("Curves", "C", "The strips' centre lines: " + branches + "; while Run steps, the level curves of the current fields" + levels + " (the strips' curves to be).", GH_ParamAccess.tree);
            pManager.AddMeshParameter("Strip Meshes", "S", "One planar-quad mesh per strip: " + branches + "." + BuiltOnceStopped, GH_ParamAccess.tree);
            addDesign(pManager);
            pManager.AddPointParameter("Nodes", nodesNickname, nodes + BuiltOnceStopped, GH_ParamAccess.list);
            pManager.AddVectorParameter("Node Axes", axesNickname, "Per node, the unit node axis (the mean of the two strips' rulings there)." + BuiltOnceStopped, GH_ParamAccess.list);
            pManager.AddTextParameter("Node Data", "D", "Per node: " + nodeStrips + ", the arc length of the node along each (where its hole goes on the flat strip), the angle between the two rulings (0° for a torsion-free node) and, per strip, the angle atan |k| between its binormal and the ruling of its rectifying developable (Sec. 5.1), flagged where the ruling's singular point is near the strip." + BuiltOnceStopped, GH_ParamAccess.list);
            pManager.AddBooleanParameter("Acceptable", "A", "Per family, true when its strips meet θ within the library's tolerance without flipped quads." + BuiltOnceStopped, GH_ParamAccess.list);
            pManager.AddTextParameter("Report", "R", report + " (the verdicts once the strips are built).", GH_ParamAccess.item);
        }

        /// <summary>The inputs of <see cref="RegisterGridshellInputs"/>, read.</summary>
        protected sealed class GridshellInputs
        {
            public Mesh Mesh;
            /// <summary>θ of each family, in degrees.</summary>
            public double[] Thetas;
            public double MinAngle = 30.0;
            public int Count = 8;
            /// <summary>The strip width; <see cref="WidthGiven"/> false: the default.</summary>
            public double Width = double.NaN;
            public bool WidthGiven;
            public int MaxIterations = 300;
            /// <summary>Solve (one-shot) and Run (live).</summary>
            public bool SolveNow, Run;
            /// <summary>The index of the first input the component added itself.</summary>
            public int FirstExtra;
        }

        /// <summary>
        /// Reads the inputs of <see cref="RegisterGridshellInputs"/> (<paramref name="thetas"/>: the default θ of each family,
        /// <paramref name="extras"/>: the component's own inputs after Count, which it reads itself). Null when there is no
        /// mesh, or with an error when a count is out of range.
        /// </summary>
        protected GridshellInputs ReadInputs(IGH_DataAccess DA, double[] thetas, int extras)
        {
            var inputs = new GridshellInputs { Thetas = (double[])thetas.Clone() };
            if (!DA.GetData(0, ref inputs.Mesh) || inputs.Mesh == null) return null;
            int n = thetas.Length;
            for (int k = 0; k < n; k++) DA.GetData(1 + k, ref inputs.Thetas[k]);
            DA.GetData(1 + n, ref inputs.MinAngle);
            DA.GetData(2 + n, ref inputs.Count);
            inputs.FirstExtra = 3 + n;
            inputs.WidthGiven = DA.GetData(3 + n + extras, ref inputs.Width);
            DA.GetData(4 + n + extras, ref inputs.MaxIterations);
            DA.GetData(5 + n + extras, ref inputs.SolveNow);
            DA.GetData(6 + n + extras, ref inputs.Run);
            if (inputs.Count < 2 || inputs.MaxIterations < 1)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Error, inputs.Count < 2 ? "Count must be at least 2" : "Max Iterations must be at least 1");
                return null;
            }
            return inputs;
        }

        /// <summary>
        /// The net session of this iteration, stepped as Run and Solve ask (see <see cref="LiveComponent.LiveSession{T}"/>):
        /// kept while the cleaned mesh, the θs and Min Angle stay, else started by <paramref name="start"/> from the mesh and
        /// the default start of the first two families (<see cref="NetSolver.DefaultStart"/>). Null (with a remark) when
        /// neither Run nor Solve is on and these inputs have no session yet. <paramref name="design"/>: "net", "web".
        /// </summary>
        protected SolverSession<NetSolver, NetReport> NetSession(IGH_DataAccess DA, GridshellInputs inputs, string design, Func<LamellaMesh, double[][], NetSolver> start)
        {
            CleanMesh clean = CleanMeshInput(inputs.Mesh);
            var fingerprint = new List<double> { inputs.Thetas.Length };
            fingerprint.AddRange(inputs.Thetas);
            fingerprint.Add(inputs.MinAngle);
            string signature = Signature.Of(clean.Xyz, clean.Triangles, fingerprint.ToArray());
            saved.Restore(DA.Iteration, signature);
            return LiveSession(DA, sessions, signature, inputs.Run, inputs.SolveNow, "design the " + design, () =>
            {
                using (LamellaMesh mesh = LamellaMesh.FromArrays(clean.Xyz, clean.Triangles))
                {
                    return SolverSession.Of(start(mesh, NetSolver.DefaultStart(mesh, inputs.Thetas[0], inputs.Thetas[1], inputs.MinAngle)), signature);
                }
            });
        }

        /// <summary>
        /// Steps <paramref name="session"/> as Run and Solve ask. While it runs on (live, not converged, not stopped) only
        /// the iterate is output: Curves (output 0) the level curves of each family's <paramref name="curves"/>, branch {k},
        /// and <paramref name="reportOutput"/> the state (<paramref name="describe"/>), the message the iteration; then
        /// null. Else the report, for the component to build and output everything.
        /// </summary>
        protected NetReport AdvanceOrShowIterate(IGH_DataAccess DA, SolverSession<NetSolver, NetReport> session, GridshellInputs inputs,
            Func<int, LevelCurves> curves, int reportOutput, Func<NetReport, string> describe)
        {
            LiveStep<NetReport> step = Advance(session, inputs.Run, inputs.SolveNow, inputs.MaxIterations);
            NetReport report = step.Outcome.Report;
            if (!step.Continues) return report;
            var levels = new DataTree<object>();
            for (int k = 0; k < inputs.Thetas.Length; k++)
            {
                using (LevelCurves family = curves(k))
                {
                    levels.AddRange(LevelCurvesComponent.ClosedPolylines(family), new GH_Path(k));
                }
            }
            Message = string.Format(CultureInfo.InvariantCulture, "iteration {0} · crossing ≥ {1:0.#}°", report.Iterations, report.MinIntersectionDegrees);
            DA.SetDataTree(0, levels);
            DA.SetData(reportOutput, describe(report));
            return null;
        }

        /// <summary>The strips of every family of a gridshell and what the components output of them.</summary>
        protected sealed class FamilyStrips
        {
            /// <summary>The strips of family k.</summary>
            public Strips[] Strips;
            /// <summary>The strips' centre lines, branch {k} per family.</summary>
            public readonly DataTree<object> Curves = new DataTree<object>();
            /// <summary>One planar-quad mesh per strip, branch {k} per family.</summary>
            public readonly DataTree<object> Meshes = new DataTree<object>();
            /// <summary>Per family, whether its strips meet θ within the library's tolerance.</summary>
            public readonly List<bool> Acceptable = new List<bool>();
            /// <summary>Per family, "family k: " and its verdict.</summary>
            public readonly List<string> Verdicts = new List<string>();
        }

        /// <summary>
        /// Builds the strips of each family k (θ Thetas[k] of <paramref name="inputs"/>) on <paramref name="curves"/>(k), every
        /// result kept for this iteration. Without a width, the default for the first family's curves (a remark names it). A
        /// family that misses θ gives an error with the library's message; its strips are output all the same.
        /// </summary>
        protected FamilyStrips BuildStrips(IGH_DataAccess DA, GridshellInputs inputs, Func<int, LevelCurves> curves)
        {
            double[] thetas = inputs.Thetas;
            double width = inputs.Width;
            bool widthGiven = inputs.WidthGiven;
            var built = new FamilyStrips { Strips = new Strips[thetas.Length] };
            for (int k = 0; k < thetas.Length; k++)
            {
                LevelCurves levels = Keep(DA, curves(k));
                if (!widthGiven)
                {
                    width = StripDefaults.Width(levels.Points());
                    widthGiven = true;
                    AddRuntimeMessage(GH_RuntimeMessageLevel.Remark, string.Format(CultureInfo.InvariantCulture,
                        "Width not set: {0:G6} ({1}; about {2:0.#} % of the curves' extent)", width,
                        RhinoConversion.DocumentUnits() ?? "document units", 100 * StripDefaults.WidthFraction));
                }
                Strips strips = built.Strips[k] = Keep(DA, Strips.Build(levels, StripParams.Default(thetas[k], width)));
                Verdict verdict = strips.Verdict;
                if (!verdict.IsAcceptable) AddRuntimeMessage(GH_RuntimeMessageLevel.Error, "family " + (k + 1) + ": " + verdict.Message);
                built.Acceptable.Add(verdict.IsAcceptable);
                built.Verdicts.Add("family " + (k + 1) + ": " + verdict);
                built.Curves.AddRange(RhinoConversion.Polylines(new Packed(strips.Centres(), strips.PointOffsets(), 3)), new GH_Path(k));
                built.Meshes.AddRange(RhinoConversion.QuadMeshes(StripArrays.Split(strips.Vertices(), 3, strips.Quads(), strips.VertexOffsets(), strips.QuadOffsets())), new GH_Path(k));
            }
            return built;
        }

        /// <summary>
        /// Strip <paramref name="k"/>'s angle atan |k| at the node, "straight" where it has none, and a warning when the
        /// singular point of its ruling is near the strip.
        /// </summary>
        private static string DiagnosticText(Node node, int k)
        {
            string angle = node.DarbouxAngleDegrees[k].HasValue
                ? string.Format(CultureInfo.InvariantCulture, "{0:0.#}°", node.DarbouxAngleDegrees[k].Value)
                : "straight";
            return node.SingularPointNear[k] ? angle + " (singular point near)" : angle;
        }

        /// <summary>
        /// A node's strips (named <paramref name="first"/>&lt;i&gt; and <paramref name="second"/>&lt;j&gt;) with the arc
        /// length of the node along each, the angle between their rulings and each strip's Sec. 5.1 diagnostic.
        /// </summary>
        protected static string NodeText(Node node, string first, string second) =>
            string.Format(CultureInfo.InvariantCulture, "{0}{1} at {2:0.###}, {3}{4} at {5:0.###}; rulings {6:0.#}° apart; binormal to developable ruling (Sec. 5.1): {0} {7}, {3} {8}",
                first, node.Strips[0], node.ArcLengths[0], second, node.Strips[1], node.ArcLengths[1], node.RulingAngleDegrees,
                DiagnosticText(node, 0), DiagnosticText(node, 1));

        /// <summary>Sets the outputs <paramref name="points"/>, <paramref name="points"/> + 1 and + 2: the nodes' positions, axes and <paramref name="describe"/> of each.</summary>
        protected static void SetNodes<T>(IGH_DataAccess DA, int points, T[] nodes, Func<T, string> describe) where T : Node
        {
            var axes = new List<Vector3d>(nodes.Length);
            var data = new List<string>(nodes.Length);
            var positions = new double[3 * nodes.Length];
            for (int i = 0; i < nodes.Length; i++)
            {
                T node = nodes[i];
                Array.Copy(node.Position, 0, positions, 3 * i, 3);
                axes.Add(new Vector3d(node.Axis[0], node.Axis[1], node.Axis[2]));
                data.Add(describe(node));
            }
            DA.SetDataList(points, RhinoConversion.Points(positions));
            DA.SetDataList(points + 1, axes);
            DA.SetDataList(points + 2, data);
        }
    }
}
