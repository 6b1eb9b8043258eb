using System;
using System.Collections.Generic;
using System.Globalization;
using Grasshopper.Kernel;
using Lamella.Conversion;
using Lamella.Hosting;
using Rhino.Geometry;

namespace Lamella.Grasshopper
{
    /// <summary>
    /// Reshape Surface: moves a mesh a little so that the level curves of a Strip Field become P-curves of the angle θ
    /// (paper Sec. 3.3, Fig. 17): the field's values stay fixed, the vertices move within a tolerance of the original
    /// surface. Live like Strip Field (Run: each solution steps within a time budget and outputs the moved surface and
    /// its deviation as they are) or one-shot (Solve); the session is kept across solutions while the mesh, the field's
    /// values, θ and Tolerance stay, and saved with the document: reopened, it shows the moved surface and continues
    /// where it stopped. With Alternate, field and surface steps run in turn (Sec. 3.3, <see cref="AlternatingSolver"/>):
    /// the field changes too; live or one-shot the same way, at most <see cref="MaxRounds"/> rounds of Max Iterations /
    /// <see cref="MaxRounds"/> iterations per step, a session of its own kept across solutions but not saved with the
    /// document (the library has no saved form of it). Field is the field on the moved surface for Level Curves: the
    /// alternation's new field, or without Alternate the input field's values.
    /// </summary>
    public class ReshapeSurfaceComponent : LiveComponent
    {
        private readonly LiveSessions<SolverSession<ReshapeSolver, ReshapeReport>> sessions = new LiveSessions<SolverSession<ReshapeSolver, ReshapeReport>>();
        private readonly DocumentSessions<ReshapeSolver, ReshapeReport> saved;
        private readonly LiveSessions<SolverSession<AlternatingSolver, AlternatingReport>> alternations = new LiveSessions<SolverSession<AlternatingSolver, AlternatingReport>>();
        private readonly ILiveSessions both;

        /// <summary>The most rounds of an alternation: each field and surface step runs at most Max Iterations / MaxRounds (rounded up) iterations.</summary>
        private const int MaxRounds = 10;

        public ReshapeSurfaceComponent()
            : base("Reshape Surface", "Reshape",
                "Moves the surface a little so that the level curves of a field become P-curves of θ (paper Sec. 3.3): the field's values stay fixed, the vertices move within Tolerance of the original surface (paper Table 3 weights). For a θ the surface has no family of, or to change θ of an existing design. Run reshapes live (the surface moves while it steps), Solve to convergence at once. Alternate runs field and surface steps in turn (paper Sec. 3.3): the field changes too.",
                "StripField")
        {
            saved = new DocumentSessions<ReshapeSolver, ReshapeReport>("LamellaReshapeSessions", sessions, solver => solver.Save(),
                (bytes, signature) => SolverSession.Of(ReshapeSolver.Load(bytes), signature));
            both = new BothSessions(sessions, alternations);
        }

        public override Guid ComponentGuid => new Guid("3f1d2c9e-6a47-4b1e-9c85-0d7e2b4a6f13");
        public override GH_Exposure Exposure => GH_Exposure.secondary;

        protected override ILiveSessions Sessions => both;

        protected override void RegisterInputParams(GH_InputParamManager pManager)
        {
            pManager.AddMeshParameter("Mesh", "M", "The surface the field was solved on (the same mesh as Strip Field's input, cleaned the same way).", GH_ParamAccess.item);
            LamellaParam<FieldGoo>.AddTo(pManager, new FieldParam(), "The field from Strip Field: its values stay fixed.");
            pManager.AddNumberParameter("Theta", "θ", "Target angle between the curves' binormals and the surface normal, in degrees, strictly between 0 and 180. Default: the field's θ.", GH_ParamAccess.item);
            pManager[2].Optional = true;
            pManager.AddNumberParameter("Tolerance", "T", "Largest distance of a vertex from the original surface, in percent of the bounding-box diagonal, > 0. Default 1.", GH_ParamAccess.item, 1.0);
            pManager.AddIntegerParameter("Max Iterations", "I", "The most solver iterations (a count, ≥ 1); live and one-shot solving stop there with a warning if not converged. With Alternate: at most 10 rounds, each field and surface step at most a tenth of it (rounded up); changing it starts the alternation over. Default 300.", GH_ParamAccess.item, 300);
            pManager.AddBooleanParameter("Solve", "Sv", SolveDescription("the reshape") + " Changing the mesh, the field's values, θ or Tolerance starts over.", GH_ParamAccess.item, false);
            // After Solve, so that documents saved before Run existed keep their Solve wires.
            pManager.AddBooleanParameter("Run", "Run", RunDescription("the reshape", "; every output shows the surface as it moves"), GH_ParamAccess.item, false);
            // Last, so that documents saved before it existed keep their wires.
            pManager.AddBooleanParameter("Alternate", "Alt", "Field and surface steps in turn (Sec. 3.3): the field may change too. Default false.", GH_ParamAccess.item, false);
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            pManager.AddMeshParameter("Mesh", "M", "The moved surface (the cleaned mesh's vertices and triangles), updated while Run steps.", GH_ParamAccess.item);
            pManager.AddNumberParameter("Deviation", "D", "Per vertex of the input mesh, its distance from the original surface (NaN at vertices no face uses).", GH_ParamAccess.list);
            pManager.AddNumberParameter("Max Deviation", "MD", "The largest deviation, in document units.", GH_ParamAccess.item);
            pManager.AddTextParameter("Report", "R", "Iterations, angle errors, deviation and edge-length change.", GH_ParamAccess.item);
            LamellaParam<FieldGoo>.AddTo(pManager, new FieldParam(),
                "The field on the moved surface, for Level Curves: with Alternate the alternation's new field, else the input field's values (they stay fixed). Built once the solve converges or stops, not while Run steps.");
        }

        protected override void SolveLive(IGH_DataAccess DA)
        {
            Mesh input = null;
            if (!DA.GetData(0, ref input) || input == null) return;
            FieldData field = GooValue<FieldGoo, FieldData>(DA, 1, "Lamella field");
            if (field == null) return;
            double thetaDegrees = field.ThetaDegrees, tolerancePercent = 1.0;
            int maxIterations = 300;
            bool solveNow = false, run = false, alternate = false;
            DA.GetData(2, ref thetaDegrees);
            DA.GetData(3, ref tolerancePercent);
            DA.GetData(4, ref maxIterations);
            DA.GetData(5, ref solveNow);
            DA.GetData(6, ref run);
            DA.GetData(7, ref alternate);
            if (maxIterations < 1)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Error, "Max Iterations must be at least 1");
                return;
            }
            CleanMesh clean = CleanMeshInput(input);
            double[] values = field.Solver.Values();
            if (values.Length != clean.VertexCount)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Error, string.Format(CultureInfo.InvariantCulture,
                    "the field has {0} values but the cleaned mesh {1} vertices: connect the mesh the field was solved on", values.Length, clean.VertexCount));
                return;
            }
            if (alternate)
            {
                // This iteration's reshape session, if any, is not used while Alternate is on.
                sessions.Skip(DA.Iteration);
                SolveAlternating(DA, clean, values, thetaDegrees, tolerancePercent, maxIterations, solveNow, run);
                return;
            }
            alternations.Skip(DA.Iteration);
            var fingerprint = new List<double>(values) { values.Length, thetaDegrees, tolerancePercent };
            string signature = Signature.Of(clean.Xyz, clean.Triangles, fingerprint.ToArray());
            saved.Restore(DA.Iteration, signature);
            SolverSession<ReshapeSolver, ReshapeReport> session = LiveSession(DA, sessions, signature, run, solveNow, "reshape", () =>
            {
                using (LamellaMesh mesh = LamellaMesh.FromArrays(clean.Xyz, clean.Triangles))
                {
                    return SolverSession.Of(new ReshapeSolver(mesh, values, thetaDegrees, tolerancePercent / 100.0, true), signature);
                }
            });
            if (session == null) return;
            LiveStep<ReshapeReport> step = Advance(session, run, solveNow, maxIterations);
            ReshapeReport report = step.Outcome.Report;
            double[] xyz = session.Solver.Positions(), deviations = session.Solver.Deviations();
            Message = string.Format(CultureInfo.InvariantCulture, "{0}iteration {1} · max deviation {2:0.###} · θ error {3:0.##}° RMS",
                report.IsConverged ? "converged · " : "", report.Iterations, report.MaxDeviation, report.AngleErrorRmsDegrees);
            SetMovedSurface(DA, clean, xyz, deviations, report.MaxDeviation);
            DA.SetData(3, string.Format(CultureInfo.InvariantCulture,
                "{0} iterations{1}; vertex angle error {2:0.###}° RMS, {3:0.###}° max; deviation max {4:0.####}, RMS {5:0.####} (tolerance {6:0.####}); edge lengths change by up to {7:0.#} %",
                report.Iterations, report.IsConverged ? ", converged" : "", report.AngleErrorRmsDegrees, report.AngleErrorMaxDegrees,
                report.MaxDeviation, report.RmsDeviation, report.Tolerance, 100 * report.MaxEdgeChange));
            if (!step.Continues) SetField(DA, xyz, clean.Triangles, values, thetaDegrees);
        }

        /// <summary>
        /// One iteration with Alternate: the alternation of these inputs (its own session, not saved with the document),
        /// stepped as Run and Solve ask, one round at a time; the outputs as without Alternate, Field the new field.
        /// </summary>
        private void SolveAlternating(IGH_DataAccess DA, CleanMesh clean, double[] values, double thetaDegrees, double tolerancePercent,
            int maxIterations, bool solveNow, bool run)
        {
            int perStep = maxIterations / MaxRounds + (maxIterations % MaxRounds == 0 ? 0 : 1);
            var fingerprint = new List<double>(values) { values.Length, thetaDegrees, tolerancePercent, perStep };
            string signature = Signature.Of(clean.Xyz, clean.Triangles, fingerprint.ToArray());
            SolverSession<AlternatingSolver, AlternatingReport> session = LiveSession(DA, alternations, signature, run, solveNow, "alternate field and surface steps", () =>
            {
                using (LamellaMesh mesh = LamellaMesh.FromArrays(clean.Xyz, clean.Triangles))
                {
                    var solver = new AlternatingSolver(mesh, values, thetaDegrees, tolerancePercent / 100.0, true, perStep);
                    // Counted in iterations per step, so that Max Iterations caps the rounds (at most MaxRounds) and the messages speak of it.
                    var steps = new Steppable<AlternatingReport>(() => solver.Report, solver.Step, r => r.Rounds * perStep, r => r.IsConverged);
                    return new SolverSession<AlternatingSolver, AlternatingReport>(solver, steps, signature);
                }
            });
            if (session == null) return;
            LiveStep<AlternatingReport> step = Advance(session, run, solveNow, maxIterations);
            AlternatingReport report = step.Outcome.Report;
            ReshapeReport surface = report.Surface;
            FieldReport field = report.Field;
            double[] xyz = session.Solver.Positions(), deviations = session.Solver.Deviations();
            if (field.SingularVertexCount > 0)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Warning, field.SingularVertexCount.ToString(CultureInfo.InvariantCulture) + " singular vertices in the field: their level curves branch");
            }
            Message = string.Format(CultureInfo.InvariantCulture, "{0}round {1} · max deviation {2:0.###} · θ error {3:0.##}° RMS",
                report.IsConverged ? "converged · " : "", report.Rounds, surface.MaxDeviation, surface.AngleErrorRmsDegrees);
            SetMovedSurface(DA, clean, xyz, deviations, surface.MaxDeviation);
            DA.SetData(3, string.Format(CultureInfo.InvariantCulture,
                "{0} rounds{1} of at most {2} field and {2} surface iterations each; last field step: {3} iterations, angle error {4:0.###}° RMS, {5:0.###}° max, {6} singular vertices; " +
                "last surface step: {7} iterations, vertex angle error {8:0.###}° RMS, {9:0.###}° max; deviation max {10:0.####}, RMS {11:0.####} (tolerance {12:0.####}); edge lengths change by up to {13:0.#} %",
                report.Rounds, report.IsConverged ? ", converged" : "", perStep, field.IterationsThisStep, field.AngleErrorRmsDegrees, field.AngleErrorMaxDegrees,
                field.SingularVertexCount, surface.Iterations, surface.AngleErrorRmsDegrees, surface.AngleErrorMaxDegrees, surface.MaxDeviation,
                surface.RmsDeviation, surface.Tolerance, 100 * surface.MaxEdgeChange));
            if (!step.Continues) SetField(DA, xyz, clean.Triangles, session.Solver.Field(), thetaDegrees);
        }

        /// <summary>The moved surface, each input vertex's deviation and the largest (outputs 0 to 2).</summary>
        private static void SetMovedSurface(IGH_DataAccess DA, CleanMesh clean, double[] xyz, double[] deviations, double maxDeviation)
        {
            DA.SetData(0, RhinoConversion.TriangleMesh(xyz, clean.Triangles));
            DA.SetDataList(1, clean.ToInputVertices(deviations, 1, double.NaN));
            DA.SetData(2, maxDeviation);
        }

        /// <summary>
        /// Outputs <paramref name="values"/> as a field on the moved surface (a field session, not stepped, kept until the next
        /// solution), or a warning when the library refuses it: the other outputs stand.
        /// </summary>
        private void SetField(IGH_DataAccess DA, double[] xyz, int[] triangles, double[] values, double thetaDegrees)
        {
            try
            {
                using (LamellaMesh moved = LamellaMesh.FromArrays(xyz, triangles))
                {
                    FieldSolver solver = Keep(DA, new FieldSolver(moved, values, FieldParams.Default(Family.PseudoGeodesic, thetaDegrees)));
                    DA.SetData(4, new FieldGoo(new FieldData(solver, thetaDegrees)));
                }
            }
            catch (LamellaException e)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Warning, "no Field output: " + e.NativeMessage);
            }
        }

        protected override IDocumentState DocumentState => saved;

        /// <summary>The reshape sessions and the alternations as the one set of sessions <see cref="LiveComponent"/> drives.</summary>
        private sealed class BothSessions : ILiveSessions
        {
            private readonly ILiveSessions first, second;

            public BothSessions(ILiveSessions first, ILiveSessions second)
            {
                this.first = first;
                this.second = second;
            }

            public void BeginSolution()
            {
                first.BeginSolution();
                second.BeginSolution();
            }

            public void EndSolution()
            {
                first.EndSolution();
                second.EndSolution();
            }

            public int RunningCount() => first.RunningCount() + second.RunningCount();

            public void Skip(int iteration)
            {
                first.Skip(iteration);
                second.Skip(iteration);
            }

            public void Clear()
            {
                first.Clear();
                second.Clear();
            }
        }
    }
}
