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
    /// What Optimise Net, Torsion-Free Net and Optimise Web share: a base-mesh session (paper Sec. 3.5) per iteration,
    /// kept across solutions while the cleaned reference, the net or web and its targets stay, solved live (Run: each
    /// solution steps it within a time budget and outputs the current iterate) or within one solution (Solve); once it
    /// has converged or stopped, each family's strips with their verdicts (building them every solution would cost about
    /// as much as an iteration or two, and judge strips against targets not met yet).
    /// </summary>
    public abstract class BaseMeshComponent : LiveComponent
    {
        private readonly LiveSessions<SolverSession<BaseMeshRun, BaseMeshReport>> sessions = new LiveSessions<SolverSession<BaseMeshRun, BaseMeshReport>>();
        private readonly DocumentSessions<BaseMeshRun, BaseMeshReport> saved;

        protected BaseMeshComponent(string name, string nickname, string description, string iconName)
            : base(name, nickname, description, iconName)
        {
            saved = new DocumentSessions<BaseMeshRun, BaseMeshReport>("LamellaBaseMeshSessions", sessions, run => run.Solver.Save(),
                (bytes, signature) => SolverSession.Of(new BaseMeshRun(BaseMeshSolver.Load(bytes), false), signature));
        }

        protected override ILiveSessions Sessions => sessions;

        /// <summary>
        /// Whether the sessions are kept in the document (whole, see <see cref="DocumentSessions{TSolver, TReport}"/>). Not
        /// for a component that shows the net as given beside the optimised one: those nodes are read before the first
        /// step and are not part of a session.
        /// </summary>
        protected virtual bool SessionsInDocument => true;

        protected override IDocumentState DocumentState => SessionsInDocument ? saved : null;

        /// <summary>The end of the descriptions of the outputs built only once the optimisation has converged or stopped.</summary>
        protected const string BuiltOnceStopped = " Empty while Run steps: built once the optimisation converges or stops.";

        /// <summary>The end of the descriptions of the outputs that show the current iterate.</summary>
        protected const string UpdatedWhileRunning = " Updated every solution while Run steps.";

        /// <summary>
        /// Registers Max Iterations, Width (optional) and Solve, the inputs every base-mesh component has after its own;
        /// <paramref name="design"/> names what is optimised ("net", "web"). <see cref="ReadInputs"/> reads them.
        /// </summary>
        protected static void RegisterSolveInputs(GH_InputParamManager pManager, string design)
        {
            pManager.AddIntegerParameter("Max Iterations", "I", "The most solver iterations (a count, ≥ 1); live and one-shot solving stop there with a warning if not converged. Default 300.", GH_ParamAccess.item, 300);
            int width = pManager.AddNumberParameter("Width", "W", "Width of each flat strip, in document units, > 0. Default: a round number near 2 % of the " + design + "'s extent (named in a remark).", GH_ParamAccess.item);
            pManager[width].Optional = true;
            pManager.AddBooleanParameter("Solve", "Sv", SolveDescription("the optimisation") + " Changing the reference, the " + design + " or its targets starts over; a higher Max Iterations continues, Width only rebuilds the strips.", GH_ParamAccess.item, false);
        }

        /// <summary>
        /// Registers Run and then the optional weights (after it, so that documents saved before either existed keep their
        /// wires); <paramref name="shows"/> names the outputs shown while it steps.
        /// </summary>
        protected static void RegisterRunInput(GH_InputParamManager pManager, string design, string shows)
        {
            pManager.AddBooleanParameter("Run", "Run", RunDescription("the " + design,
                "; meanwhile " + shows + " show the current iterate, and the strips are built once it converges or stops (at Max Iterations, on Escape, or when Run is switched off)"),
                GH_ParamAccess.item, false);
            foreach (var weight in Weights)
            {
                int index = pManager.AddNumberParameter(weight.Name, weight.Nickname, "Optional weight (paper Table 3 gives them per figure), finite and ≥ 0, on the " + design +
                    " scaled to mean segment length 1: " + weight.Description + " Changing it starts over.", GH_ParamAccess.item);
                pManager[index].Optional = true;
            }
        }

        /// <summary>The optional weight inputs after Run, in order: name, nickname, what it weighs (with its default).</summary>
        private static readonly (string Name, string Nickname, string Description)[] Weights =
        {
            ("Curve Weight", "WC", "the families' rows (normals, binormals, each family's angle). Default 1, > 0."),
            ("Fairness Weight", "WF", "fairness along every polyline. Default 0.001."),
            ("Closeness Weight", "WS", "the distance to the reference along its normal. Default 1."),
            ("Pull Weight", "WP", "the pull toward the positions as given: raise it (to 0.01, say) to keep the extent of a net that shrinks toward its centre where it cannot meet its families as placed. Default 0.0001."),
            ("Torsion Weight", "WT", "the torsion-free node rows (Eq. 21), with torsion-free nodes only. Default 1, > 0."),
        };

        /// <summary>The inputs every base-mesh component has: the reference (input 0), those of <see cref="RegisterSolveInputs"/> and Run.</summary>
        protected sealed class BaseMeshInputs
        {
            public Mesh Reference;
            public int MaxIterations = 300;
            /// <summary>The strip width; <see cref="WidthGiven"/> false: the default.</summary>
            public double Width = double.NaN;
            public bool WidthGiven;
            /// <summary>Solve (one-shot) and Run (live).</summary>
            public bool SolveNow, Run;
            /// <summary>The weights: the library's defaults, replaced by those given after Run.</summary>
            public BaseMeshWeights Weights = BaseMeshWeights.Default();
        }

        /// <summary>
        /// Reads the reference (input 0), Max Iterations, Width and Solve (from input <paramref name="maxIterations"/> on),
        /// Run (input <paramref name="run"/>) and the weights after it. Null when there is no reference, or with an error
        /// when Max Iterations is below 1.
        /// </summary>
        protected BaseMeshInputs ReadInputs(IGH_DataAccess DA, int maxIterations, int run)
        {
            var inputs = new BaseMeshInputs();
            if (!DA.GetData(0, ref inputs.Reference) || inputs.Reference == null) return null;
            DA.GetData(maxIterations, ref inputs.MaxIterations);
            inputs.WidthGiven = DA.GetData(maxIterations + 1, ref inputs.Width);
            DA.GetData(maxIterations + 2, ref inputs.SolveNow);
            DA.GetData(run, ref inputs.Run);
            double[] weights = { inputs.Weights.Curve, inputs.Weights.Fair, inputs.Weights.Close, inputs.Weights.Pull, inputs.Weights.Torsion };
            for (int w = 0; w < weights.Length; w++) DA.GetData(run + 1 + w, ref weights[w]);
            inputs.Weights = new BaseMeshWeights { Curve = weights[0], Fair = weights[1], Close = weights[2], Pull = weights[3], Torsion = weights[4] };
            if (inputs.MaxIterations < 1)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Error, "Max Iterations must be at least 1");
                return null;
            }
            return inputs;
        }

        /// <summary>
        /// The base-mesh session of this iteration (see <see cref="LiveComponent.LiveSession{T}"/>): kept while the cleaned
        /// reference, the vertices <paramref name="xyz"/>, the <paramref name="polylines"/> of each family,
        /// <paramref name="parameters"/> (the targets and switches) and the weights stay, else started by
        /// <paramref name="start"/> on the reference with the weights, with the nodes of the net as given when
        /// <paramref name="keepInitialNodes"/>. Null (with a remark)
        /// when neither Run nor Solve is on and these inputs have no session yet. <paramref name="design"/>: "net", "web".
        /// </summary>
        protected SolverSession<BaseMeshRun, BaseMeshReport> BaseMeshSession(IGH_DataAccess DA, BaseMeshInputs inputs, double[] xyz, int[][][] polylines,
            double[] parameters, string design, bool keepInitialNodes, Func<LamellaMesh, BaseMeshSolver> start)
        {
            CleanMesh clean = CleanMeshInput(inputs.Reference);
            BaseMeshWeights weights = inputs.Weights;
            var fingerprint = new List<double>(parameters) { weights.Curve, weights.Fair, weights.Close, weights.Pull, weights.Torsion, xyz.Length };
            fingerprint.AddRange(xyz);
            foreach (int[][] family in polylines)
            {
                fingerprint.Add(family.Length);
                foreach (int[] polyline in family)
                {
                    fingerprint.Add(polyline.Length);
                    foreach (int v in polyline) fingerprint.Add(v);
                }
            }
            string signature = Signature.Of(clean.Xyz, clean.Triangles, fingerprint.ToArray());
            if (SessionsInDocument) saved.Restore(DA.Iteration, signature);
            return LiveSession(DA, sessions, signature, inputs.Run, inputs.SolveNow, "optimise the " + design, () =>
            {
                using (LamellaMesh reference = LamellaMesh.FromArrays(clean.Xyz, clean.Triangles))
                {
                    BaseMeshSolver solver = start(reference);
                    try
                    {
                        solver.SetWeights(weights);
                    }
                    catch
                    {
                        solver.Dispose();
                        throw;
                    }
                    return SolverSession.Of(new BaseMeshRun(solver, keepInitialNodes), signature);
                }
            });
        }

        /// <summary>
        /// The component's message: the iteration (or "converged"), then <paramref name="details"/>.
        /// </summary>
        protected static string IterationMessage(BaseMeshReport report, string details) =>
            (report.IsConverged ? "converged · " : string.Format(CultureInfo.InvariantCulture, "iteration {0} · ", report.Iterations)) + details;

        /// <summary>
        /// Once the solve has converged or stopped (not <paramref name="step"/>.Continues): the strips of every family of
        /// <paramref name="solver"/>, Width wide (the default for the vertices <paramref name="xyz"/> when not given, named
        /// in a remark), one planar-quad mesh per strip in branch {k} of output <paramref name="stripsOutput"/>; returns
        /// each family's verdict as a line. A family that misses its angle gives an error with the library's message; its
        /// strips are output all the same (the designer sees where). While it runs on: nothing, no line.
        /// </summary>
        protected List<string> StripsOnceStopped(IGH_DataAccess DA, LiveStep<BaseMeshReport> step, BaseMeshSolver solver, BaseMeshInputs inputs, double[] xyz, int stripsOutput)
        {
            var verdicts = new List<string>();
            if (step.Continues) return verdicts;
            double width = inputs.WidthGiven ? inputs.Width : DefaultWidth(xyz);
            var meshes = new DataTree<object>();
            for (int k = 0; k < solver.FamilyCount; k++)
            {
                using (Strips strips = solver.BuildStrips(k, width))
                {
                    Verdict verdict = strips.Verdict;
                    string family = BaseMeshSolver.FamilyName(k);
                    if (!verdict.IsAcceptable) AddRuntimeMessage(GH_RuntimeMessageLevel.Error, family + ": " + verdict.Message);
                    verdicts.Add(family + ": " + verdict);
                    meshes.AddRange(RhinoConversion.QuadMeshes(StripArrays.Split(strips.Vertices(), 3, strips.Quads(), strips.VertexOffsets(), strips.QuadOffsets())), new GH_Path(k));
                }
            }
            DA.SetDataTree(stripsOutput, meshes);
            return verdicts;
        }

        /// <summary>The default strip width for the net's vertices <paramref name="xyz"/>, named in a remark.</summary>
        private double DefaultWidth(double[] xyz)
        {
            double width = StripDefaults.Width(xyz);
            AddRuntimeMessage(GH_RuntimeMessageLevel.Remark, string.Format(CultureInfo.InvariantCulture,
                "Width not set: {0:G6} ({1}; about {2:0.#} % of the net's extent)", width,
                RhinoConversion.DocumentUnits() ?? "document units", 100 * StripDefaults.WidthFraction));
            return width;
        }

        /// <summary>The optimised polylines of every family (vertex indices into <paramref name="xyz"/>), branch {k} per family.</summary>
        protected static DataTree<object> FamilyPolylines(double[] xyz, int[][][] polylines)
        {
            var curves = new DataTree<object>();
            for (int k = 0; k < polylines.Length; k++) curves.AddRange(RhinoConversion.Polylines(Packing.Gather(xyz, polylines[k])), new GH_Path(k));
            return curves;
        }
    }
}
