using System;
using System.Collections.Generic;
using System.Globalization;
using GH_IO.Serialization;
using Grasshopper.Kernel;
using Lamella.Conversion;
using Lamella.Hosting;
using Rhino.Geometry;

namespace Lamella.Grasshopper
{
    /// <summary>
    /// Strip Field: a P-curve field on a mesh (paper Sec. 3), one per iteration (list item or tree branch) of its
    /// inputs. Run solves live: each solution steps every unconverged field within a shared time budget and schedules
    /// the next solution after a delay as long as the last cycle kept Grasshopper busy; Escape stops it until Run is
    /// switched off and on. Solve solves to convergence within one solution (for Hops, Rhino.Compute, optimisers). A
    /// field restarts when its own inputs change or on Reset. The document keeps each field's values, θ, parameters,
    /// report and input signature (compressed), so a reopened document shows its fields without solving again. The
    /// start field comes from traced guides (paper Eq. 5–7), from sketched strokes, whose estimated θ then replaces the θ
    /// input (Sec. 3.2.2), or is the height along Direction; with none of them the library's start search chooses it
    /// (one candidate per live solution, all at once with Solve) and the message names the chosen start.
    /// </summary>
    public class StripFieldComponent : LiveComponent
    {
        /// <summary>The description of a mesh input, shared with Trace P-Curve.</summary>
        internal const string MeshDescription =
            "The surface: a mesh that is a topological disk, possibly with holes. A cleaned copy is used: vertices closer than the document tolerance are welded (unwelded polysurface meshes, texture seams), degenerate and repeated faces and unused vertices are removed, quads are split (a remark says what changed). Length unit: the document's.";

        private const string FieldsKey = "LamellaFields";
        private const int PreviewLevels = 12;

        private readonly FieldSessions sessions = new FieldSessions();
        private int converged;
        private string lastMessage;

        public StripFieldComponent()
            : base("Strip Field", "Field",
                "A scalar field on a mesh whose level curves are pseudo-geodesics: their binormals keep the angle θ to the surface normal (paper Sec. 3). Run solves live, Solve solves to convergence at once. One field per mesh / θ of a list or tree. The document stores each field's values (compressed, about 8 bytes per vertex), θ, parameters and report.",
                "StripField")
        {
        }

        public override Guid ComponentGuid => new Guid("aaddaf0a-9d77-4242-909b-a5dce7cbacf4");
        public override GH_Exposure Exposure => GH_Exposure.primary;

        protected override void RegisterInputParams(GH_InputParamManager pManager)
        {
            pManager.AddMeshParameter("Mesh", "M", MeshDescription, GH_ParamAccess.item);
            pManager.AddNumberParameter("Theta", "θ", "Target angle between the curves' binormals and the surface normal, in degrees, 0–180 (90: geodesics, 0: asymptotic curves). Replaced by the estimate from Strokes when they are connected. Default 60.", GH_ParamAccess.item, 60.0);
            pManager.AddVectorParameter("Direction", "D", "Optional, without Guides or Strokes: the start field is the height along this vector (unitless direction), whose level curves should roughly follow the wanted strips. Default: none: the library's start search tries heights along the surface's principal directions (and, if none leads to the family, guides from each boundary side), solves briefly from each and continues from the best (named in a remark).", GH_ParamAccess.item);
            pManager[2].Optional = true;
            LamellaParam<GuidesGoo>.AddTo(pManager, new GuidesParam(), "Optional guides from Trace P-Curve, traced on this mesh, ordered and not crossing: the start field interpolates them (guide i on the level F = i, paper Eq. 5–7) and, when Spacing is 0, their spacing sets the gradient target. Default: none.");
            pManager[3].Optional = true;
            pManager.AddCurveParameter("Strokes", "St", "Optional curves sketched on (or near, within a mesh edge of) the surface along the wanted strips, at least two, not crossing, in the order the family should run: the start field follows them and the θ they suggest replaces the θ input (shown in the message and the θ output). Not together with Guides. Default: none.", GH_ParamAccess.list);
            pManager[4].Optional = true;
            pManager.AddNumberParameter("Spacing", "S", "Target distance between the levels F and F + 1, in document units (the gradient norm target is 1/S); 0 keeps the start field's mean gradient. Default 0.", GH_ParamAccess.item, 0.0);
            pManager.AddNumberParameter("Weights", "W", "Advanced: three weights λ_fair, λ_grad, λ_angle (paper Eq. 12), each ≥ 0, replacing the library's warm-up schedule and defaults. Unitless. Default: none (library defaults).", GH_ParamAccess.list);
            pManager[6].Optional = true;
            pManager.AddIntegerParameter("Max Iterations", "I", "The most solver iterations a field may run (a count, ≥ 1); live and one-shot solving stop there with a warning if not converged. Default 1000.", GH_ParamAccess.item, 1000);
            pManager.AddBooleanParameter("Reset", "R", "True starts the fields over from their start fields. Default false.", GH_ParamAccess.item, false);
            pManager.AddBooleanParameter("Run", "Run", RunDescription("the fields", ""), GH_ParamAccess.item, false);
            pManager.AddBooleanParameter("Solve", "Sv", SolveDescription("each field"), GH_ParamAccess.item, false);
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            LamellaParam<FieldGoo>.AddTo(pManager, new FieldParam(), "The field (a shared native solver session) for Level Curves.");
            pManager.AddNumberParameter("Values", "V", "The field value at each vertex of the input mesh (field units: about 1 per Spacing; NaN at vertices no face uses).", GH_ParamAccess.list);
            pManager.AddTextParameter("Report", "R", "Iterations, stage, energies (paper Eq. 6, 8, 11), angle errors, singular vertices.", GH_ParamAccess.item);
            pManager.AddNumberParameter("Angle Error", "E", "Maximum |θ_measured − θ| over the measured vertices, in degrees.", GH_ParamAccess.item);
            pManager.AddNumberParameter("Theta", "θ", "The θ being solved for, in degrees: the θ input, or the angle estimated from the Strokes.", GH_ParamAccess.item);
            pManager.AddMeshParameter("Preview", "P", "The input mesh coloured by the field (blue: low, red: high), updated while solving.", GH_ParamAccess.item);
            pManager.AddCurveParameter("Level Preview", "LP", "A few level curves of the current field (" + PreviewLevels.ToString(CultureInfo.InvariantCulture) + " uniform levels), updated while solving.", GH_ParamAccess.list);
            pManager.AddPointParameter("Singular Points", "X", "The singular vertices, where level curves branch (none in a good field).", GH_ParamAccess.list);
            pManager.AddVectorParameter("Binormals", "B", "The unit binormal of the level curve at each vertex of the input mesh (zero at boundary and singular vertices).", GH_ParamAccess.list);
        }

        protected override ILiveSessions Sessions => sessions;

        protected override string NotConvergedHint => "raise it, or check θ and the start field";

        protected override void BeginSolution()
        {
            base.BeginSolution();
            converged = 0;
            lastMessage = null;
        }

        protected override void EndSolution()
        {
            base.EndSolution();
            Message = sessions.Iterations == 1 ? lastMessage : string.Format(CultureInfo.InvariantCulture, "{0} fields · {1} converged", sessions.Iterations, converged);
        }

        /// <summary>One iteration: the field of its inputs, stepped as Run and Solve ask.</summary>
        protected override void SolveLive(IGH_DataAccess DA)
        {
            int iteration = DA.Iteration;
            Mesh mesh = null;
            if (!DA.GetData(0, ref mesh) || mesh == null) return;
            double thetaDegrees = 60, spacing = 0;
            Vector3d direction = new Vector3d(0, 0, 1);
            GuidesData guides;
            var strokeCurves = new List<Curve>();
            int maxIterations = 1000;
            bool reset = false, run = false, solveNow = false;
            var weights = new List<double>();
            DA.GetData(1, ref thetaDegrees);
            // Not given: the start search chooses the start (unless guides or strokes give it).
            bool directionGiven = DA.GetData(2, ref direction);
            if (!TryGooValue<GuidesGoo, GuidesData>(DA, 3, "Lamella guides", out guides)) return;
            DA.GetDataList(4, strokeCurves);
            DA.GetData(5, ref spacing);
            DA.GetDataList(6, weights);
            DA.GetData(7, ref maxIterations);
            DA.GetData(8, ref reset);
            DA.GetData(9, ref run);
            DA.GetData(10, ref solveNow);
            string problem = CheckInputs(spacing, weights, maxIterations, guides, strokeCurves);
            if (problem != null)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Error, problem);
                return;
            }

            CleanMesh clean = CleanMeshInput(mesh);
            List<double[]> strokes = null;
            if (strokeCurves.Count > 0)
            {
                // Points every half edge, so that the library finds a stroke point in every triangle the stroke crosses.
                double strokeSpacing = 0.5 * StrokeArrays.MeanEdgeLength(clean.Xyz, clean.Triangles);
                strokes = strokeCurves.ConvertAll(curve => RhinoConversion.CurveToStroke(curve, strokeSpacing));
            }
            Vector3d? height = directionGiven ? direction : (Vector3d?)null;
            string signature = Signature.Of(clean.Xyz, clean.Triangles, Fingerprint(thetaDegrees, height, spacing, weights, guides, strokes));
            FieldSession session = Hold(sessions.Session(iteration, clean.Xyz, clean.Triangles, signature, reset,
                native => Start(native, clean, signature, thetaDegrees, height, spacing, weights, guides, strokes)));
            if (guides != null && strokes == null && guides.ThetaDegrees != session.ThetaDegrees)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Remark, string.Format(CultureInfo.InvariantCulture,
                    "the guides were traced with θ = {0}°, the field is solved for θ = {1}°", guides.ThetaDegrees, session.ThetaDegrees));
            }

            FieldReport report = Advance(session, run, solveNow, maxIterations).Outcome.Report;
            if (session.IsSearching)
            {
                // No field yet: say how far the search is; the next slices (Run) or Solve continue it.
                lastMessage = StartDescriptions.Progress(session.Candidates);
                DA.SetData(2, StartDescriptions.Report(session.Candidates, null, null));
                DA.SetData(4, session.ThetaDegrees);
                if (!run && !solveNow) AddRuntimeMessage(GH_RuntimeMessageLevel.Remark, "the start search runs with Run or Solve");
                return;
            }
            if (session.ChosenStart.HasValue)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Remark, StartDescriptions.Chosen(session.ChosenStart.Value, session.Candidates.Length));
                if (spacing > 0) AddRuntimeMessage(GH_RuntimeMessageLevel.Warning, "Spacing is not applied to a field from the start search (it keeps its start's spacing); connect Direction, Guides or Strokes to set it");
            }
            if (report.IsConverged) converged++;
            lastMessage = (strokes != null ? string.Format(CultureInfo.InvariantCulture, "θ ≈ {0:0.#}° from strokes · ", session.ThetaDegrees) : "") +
                (session.ChosenStart.HasValue ? StartDescriptions.Short(session.ChosenStart.Value) + " · " : "") +
                (report.IsConverged ? "converged · " : "") +
                string.Format(CultureInfo.InvariantCulture, "iteration {0} · E_angle {1:0.00e+0}", report.Iterations, report.EnergyAngle);
            if (report.SingularVertexCount > 0)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Warning, report.SingularVertexCount.ToString(CultureInfo.InvariantCulture) + " singular vertices: their level curves branch");
            }

            // The signature covers the inputs that decide θ, so the session was solved for this θ (also after a document was reopened).
            FieldSolver solver = session.Solver;
            double[] values = clean.ToInputVertices(session.Values(), 1, double.NaN);
            DA.SetData(0, new FieldGoo(new FieldData(solver, session.ThetaDegrees)));
            DA.SetDataList(1, values);
            DA.SetData(2, session.ChosenStart.HasValue ? StartDescriptions.Report(session.Candidates, session.ChosenStart.Value.Index, report) : report.Describe());
            DA.SetData(3, report.AngleErrorMaxDegrees);
            DA.SetData(4, session.ThetaDegrees);
            DA.SetData(5, RhinoConversion.ColouredCopy(mesh, FieldColours.Argb(values)));
            try
            {
                using (LevelCurves preview = LevelCurves.Uniform(solver, PreviewLevels, 0))
                {
                    DA.SetDataList(6, LevelCurvesComponent.ClosedPolylines(preview));
                }
            }
            catch (LamellaException e)
            {
                // The preview is a view of the field; a field without usable levels still is the field.
                AddRuntimeMessage(GH_RuntimeMessageLevel.Warning, "no level preview: " + e.NativeMessage);
            }
            var singular = new List<Point3d>();
            foreach (int v in solver.SingularVertices()) singular.Add(RhinoConversion.Point(clean.Xyz, v));
            DA.SetDataList(7, singular);
            DA.SetDataList(8, RhinoConversion.Vectors(clean.ToInputVertices(solver.Binormals(), 3, 0)));
        }

        /// <summary>Null when the plain inputs are usable, else what is wrong (θ, mesh, direction, guides and strokes are checked natively).</summary>
        private static string CheckInputs(double spacing, List<double> weights, int maxIterations, GuidesData guides, List<Curve> strokes)
        {
            if (!(spacing >= 0) || double.IsInfinity(spacing)) return "Spacing must be finite and ≥ 0 (0 keeps the start field's gradient)";
            if (weights.Count != 0 && weights.Count != 3) return "Weights takes three numbers (λ_fair, λ_grad, λ_angle) or none, not " + weights.Count;
            if (maxIterations < 1) return "Max Iterations must be at least 1";
            if (guides != null && strokes.Count > 0) return "connect Guides or Strokes, not both: each gives a start field";
            if (strokes.Contains(null)) return "Strokes holds an empty item";
            return null;
        }

        /// <summary>
        /// Every input value that shapes the session besides the mesh, each list preceded by its length so that no two
        /// different inputs give the same sequence: θ (unless strokes replace it), direction (if given), spacing, weights,
        /// the guides' points and offsets, the strokes' points.
        /// </summary>
        private static double[] Fingerprint(double thetaDegrees, Vector3d? direction, double spacing, List<double> weights, GuidesData guides, List<double[]> strokes)
        {
            var values = new List<double>();
            Action<IList<double>> add = list => { values.Add(list.Count); values.AddRange(list); };
            add(strokes == null ? new[] { thetaDegrees } : new double[0]);
            // With a direction the sequence is the one documents saved before the start search have (their Direction
            // kept its default Z), so their fields are restored; without one the length prefix tells the two apart.
            add(direction.HasValue ? new[] { direction.Value.X, direction.Value.Y, direction.Value.Z, spacing } : new[] { spacing });
            add(weights);
            add(guides == null ? new double[0] : guides.Guides.Points());
            add(guides == null ? new double[0] : Array.ConvertAll(guides.Guides.Offsets(), o => (double)o));
            values.Add(strokes == null ? 0 : strokes.Count);
            foreach (double[] stroke in strokes ?? new List<double[]>()) add(stroke);
            return values.ToArray();
        }

        /// <summary>
        /// A new session on <paramref name="mesh"/> from its start field: guides, strokes or the height along Direction;
        /// with none of them, a session that first runs the library's start search. θ 0° and 180° (asymptotic curves) and
        /// 90° (geodesics) need nothing special: the library names the family by θ.
        /// </summary>
        private static FieldSession Start(LamellaMesh mesh, CleanMesh clean, string signature, double thetaDegrees, Vector3d? direction,
            double spacing, List<double> weights, GuidesData guides, List<double[]> strokes)
        {
            double[] start = null;
            double gradientTarget = 0;
            if (guides != null)
            {
                guides.Guides.CheckOrder();
                start = InitialField.FromGuides(mesh, guides.Guides, out gradientTarget);
            }
            else if (strokes != null)
            {
                start = InitialField.FromStrokes(mesh, strokes, out thetaDegrees);
            }
            else if (direction.HasValue)
            {
                start = StartField.Height(clean.Xyz, direction.Value.X, direction.Value.Y, direction.Value.Z);
            }
            FieldParams parameters = FieldParams.Default(Family.PseudoGeodesic, thetaDegrees);
            parameters.GradientTarget = spacing > 0 ? 1.0 / spacing : gradientTarget;
            if (weights.Count == 3)
            {
                parameters.WarmUp = 0;
                parameters.Weights = new Weights(weights[0], weights[1], weights[2]);
            }
            return start == null ? FieldSession.Search(mesh, parameters, signature) : FieldSession.Start(mesh, start, parameters, signature);
        }

        /// <summary>Stores each field's values, θ, parameters, report and input signature (see <see cref="FieldArchive"/>), not the whole native session.</summary>
        public override bool Write(GH_IWriter writer)
        {
            try
            {
                byte[] bytes = sessions.Save();
                if (bytes != null) writer.SetByteArray(FieldsKey, bytes);
            }
            catch (Exception)
            {
                // A field that cannot be read back is not stored; the document saves without it and solves again.
            }
            return base.Write(writer);
        }

        public override bool Read(GH_IReader reader)
        {
            if (reader.ItemExists(FieldsKey))
            {
                try
                {
                    sessions.Load(reader.GetByteArray(FieldsKey));
                }
                catch (FormatException)
                {
                    // Damaged or from another format version: the fields are solved again from the inputs.
                }
            }
            return base.Read(reader);
        }
    }
}
