using System;
using System.Collections.Generic;
using System.Globalization;
using GH_IO.Serialization;
using Grasshopper.Kernel;
using Lamella.Conversion;
using Rhino.Geometry;

namespace Lamella.Grasshopper
{
    /// <summary>
    /// Strip Field: a P-curve field on a mesh (paper Sec. 3), solved live. While Run is true each solution steps the
    /// native solver a few iterations and schedules the next solution, until converged (as Kangaroo does); the
    /// message shows the iteration and E_angle. Reset, or any change of the inputs, starts over. The session is
    /// stored in the .gh document, so a reopened document shows its last result without solving again. The start
    /// field is the height along Direction, or comes from traced guides (paper Eq. 5–7) or from sketched strokes,
    /// whose estimated θ then replaces the θ input (Sec. 3.2.2).
    /// </summary>
    public class StripFieldComponent : LamellaComponent
    {
        private const string SessionKey = "LamellaSession";
        private const string SignatureKey = "LamellaSignature";
        private const string ThetaKey = "LamellaTheta";

        private FieldSolver solver;
        private string signature;
        /// <summary>The θ the session solves for: the input, or the estimate from strokes.</summary>
        private double theta;

        public StripFieldComponent()
            : base("Strip Field", "Field",
                "A scalar field on a mesh whose level curves are pseudo-geodesics: their binormals keep the angle θ to the surface normal (paper Sec. 3). Set Run to true to solve live.",
                "StripField")
        {
        }

        public override Guid ComponentGuid => new Guid("aaddaf0a-9d77-4242-909b-a5dce7cbacf4");
        public override GH_Exposure Exposure => GH_Exposure.primary;

        protected override void RegisterInputParams(GH_InputParamManager pManager)
        {
            pManager.AddMeshParameter("Mesh", "M", "The surface: a mesh that is a topological disk, possibly with holes (quads are split into triangles). Length unit: the document's.", GH_ParamAccess.item);
            pManager.AddNumberParameter("Theta", "θ", "Target angle between the curves' binormals and the surface normal, in degrees, 0–180 (90: geodesics, 0: asymptotic curves). Replaced by the estimate from Strokes when they are connected. Default 60.", GH_ParamAccess.item, 60.0);
            pManager.AddVectorParameter("Direction", "D", "Without Guides or Strokes, the start field is the height along this vector (unitless direction); its level curves should roughly follow the wanted strips. Default Z.", GH_ParamAccess.item, new Vector3d(0, 0, 1));
            pManager.AddGenericParameter("Guides", "G", "Optional guides from Trace P-Curve, traced on this mesh, ordered and not crossing: the start field interpolates them (guide i on the level F = i, paper Eq. 5–7) and, when Spacing is 0, their spacing sets the gradient target. Default: none.", GH_ParamAccess.item);
            pManager[3].Optional = true;
            pManager.AddCurveParameter("Strokes", "St", "Optional curves sketched on (or near, within a mesh edge of) the surface along the wanted strips, at least two, not crossing, in the order the family should run: the start field follows them and the θ they suggest replaces the θ input (shown in the message and the θ output). Not together with Guides. Default: none.", GH_ParamAccess.list);
            pManager[4].Optional = true;
            pManager.AddNumberParameter("Spacing", "S", "Target distance between the levels F and F + 1, in document units (the gradient norm target is 1/S); 0 keeps the start field's mean gradient. Default 0.", GH_ParamAccess.item, 0.0);
            pManager.AddNumberParameter("Weights", "W", "Advanced: three weights λ_fair, λ_grad, λ_angle (paper Eq. 12), each ≥ 0, replacing the library's warm-up schedule and defaults. Unitless. Default: none (library defaults).", GH_ParamAccess.list);
            pManager[6].Optional = true;
            pManager.AddIntegerParameter("Iterations", "I", "Solver iterations per solution while running (a count). Default 5.", GH_ParamAccess.item, 5);
            pManager.AddBooleanParameter("Reset", "R", "True starts the solve over from the start field. Default false.", GH_ParamAccess.item, false);
            pManager.AddBooleanParameter("Run", "Run", "True steps the solver until it converges, one batch of iterations per solution. Default false.", GH_ParamAccess.item, false);
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            pManager.AddGenericParameter("Field", "F", "The field (a shared native solver session) for Level Curves.", GH_ParamAccess.item);
            pManager.AddNumberParameter("Values", "V", "The field value at each mesh vertex (field units: about 1 per Spacing).", GH_ParamAccess.list);
            pManager.AddTextParameter("Report", "R", "Iterations, stage, energies (paper Eq. 6, 8, 11), angle errors, singular vertices.", GH_ParamAccess.item);
            pManager.AddNumberParameter("Angle Error", "E", "Maximum |θ_measured − θ| over the measured vertices, in degrees.", GH_ParamAccess.item);
            pManager.AddNumberParameter("Theta", "θ", "The θ being solved for, in degrees: the θ input, or the angle estimated from the Strokes.", GH_ParamAccess.item);
        }

        protected override void Solve(IGH_DataAccess DA)
        {
            Mesh mesh = null;
            if (!DA.GetData(0, ref mesh) || mesh == null) return;
            double thetaDegrees = 60, spacing = 0;
            Vector3d direction = new Vector3d(0, 0, 1);
            GuidesData guides;
            var strokeCurves = new List<Curve>();
            int iterations = 5;
            bool reset = false, run = false;
            var weights = new List<double>();
            DA.GetData(1, ref thetaDegrees);
            DA.GetData(2, ref direction);
            if (!TryGooValue<GuidesGoo, GuidesData>(DA, 3, "Lamella guides", out guides)) return;
            DA.GetDataList(4, strokeCurves);
            DA.GetData(5, ref spacing);
            DA.GetDataList(6, weights);
            DA.GetData(7, ref iterations);
            DA.GetData(8, ref reset);
            DA.GetData(9, ref run);
            string problem = CheckInputs(spacing, weights, iterations, guides, strokeCurves);
            if (problem != null)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Error, problem);
                return;
            }

            double[] xyz;
            int[] triangles;
            RhinoConversion.MeshToArrays(mesh, out xyz, out triangles);
            List<double[]> strokes = null;
            if (strokeCurves.Count > 0)
            {
                // Points every half edge, so that the library finds a stroke point in every triangle the stroke crosses.
                double strokeSpacing = 0.5 * StrokeArrays.MeanEdgeLength(xyz, triangles);
                strokes = strokeCurves.ConvertAll(curve => RhinoConversion.CurveToStroke(curve, strokeSpacing));
            }
            string current = Signature.Of(xyz, triangles, Fingerprint(thetaDegrees, direction, spacing, weights, guides, strokes));
            if (reset || solver == null || current != signature)
            {
                Restart(xyz, triangles, thetaDegrees, direction, spacing, weights, guides, strokes);
                signature = current;
            }
            if (guides != null && strokes == null && guides.ThetaDegrees != theta)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Remark, string.Format(CultureInfo.InvariantCulture,
                    "the guides were traced with θ = {0}°, the field is solved for θ = {1}°", guides.ThetaDegrees, theta));
            }

            FieldReport report = solver.Report;
            if (run && !report.IsConverged)
            {
                report = solver.Step(iterations);
                if (!report.IsConverged) ScheduleNextStep();
            }
            Message = (strokes != null ? string.Format(CultureInfo.InvariantCulture, "θ ≈ {0:0.#}° from strokes · ", theta) : "") +
                (report.IsConverged ? "converged · " : "") +
                string.Format(CultureInfo.InvariantCulture, "iteration {0} · E_angle {1:0.00e+0}", report.Iterations, report.EnergyAngle);
            if (report.SingularVertexCount > 0)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Warning, report.SingularVertexCount + " singular vertices: their level curves branch");
            }

            // The signature covers the inputs that decide θ, so the session was solved for this θ (also after a document was reopened).
            DA.SetData(0, new FieldGoo(new FieldData(solver, theta)));
            DA.SetDataList(1, solver.Values());
            DA.SetData(2, report.Describe());
            DA.SetData(3, report.AngleErrorMaxDegrees);
            DA.SetData(4, theta);
        }

        /// <summary>Null when the plain inputs are usable, else what is wrong (θ, mesh, direction, guides and strokes are checked natively).</summary>
        private static string CheckInputs(double spacing, List<double> weights, int iterations, GuidesData guides, List<Curve> strokes)
        {
            if (!(spacing >= 0) || double.IsInfinity(spacing)) return "Spacing must be finite and ≥ 0 (0 keeps the start field's gradient)";
            if (weights.Count != 0 && weights.Count != 3) return "Weights takes three numbers (λ_fair, λ_grad, λ_angle) or none, not " + weights.Count;
            if (iterations < 1) return "Iterations must be at least 1";
            if (guides != null && strokes.Count > 0) return "connect Guides or Strokes, not both: each gives a start field";
            if (strokes.Contains(null)) return "Strokes holds an empty item";
            return null;
        }

        /// <summary>
        /// Every input value that shapes the session besides the mesh, each list preceded by its length so that no two
        /// different inputs give the same sequence: θ (unless strokes replace it), direction, spacing, weights, the
        /// guides' points and offsets, the strokes' points.
        /// </summary>
        private static double[] Fingerprint(double thetaDegrees, Vector3d direction, double spacing, List<double> weights, GuidesData guides, List<double[]> strokes)
        {
            var values = new List<double>();
            Action<IList<double>> add = list => { values.Add(list.Count); values.AddRange(list); };
            add(strokes == null ? new[] { thetaDegrees } : new double[0]);
            add(new[] { direction.X, direction.Y, direction.Z, spacing });
            add(weights);
            add(guides == null ? new double[0] : guides.Guides.Points());
            add(guides == null ? new double[0] : Array.ConvertAll(guides.Guides.Offsets(), o => (double)o));
            values.Add(strokes == null ? 0 : strokes.Count);
            foreach (double[] stroke in strokes ?? new List<double[]>()) add(stroke);
            return values.ToArray();
        }

        private void Restart(double[] xyz, int[] triangles, double thetaDegrees, Vector3d direction, double spacing, List<double> weights,
            GuidesData guides, List<double[]> strokes)
        {
            solver?.Dispose();
            solver = null;
            using (var mesh = LamellaMesh.FromArrays(xyz, triangles))
            {
                double[] start;
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
                else
                {
                    start = StartField.Height(xyz, direction.X, direction.Y, direction.Z);
                }
                FieldParams parameters = FieldParams.Default(Family.PseudoGeodesic, thetaDegrees);
                parameters.GradientTarget = spacing > 0 ? 1.0 / spacing : gradientTarget;
                if (weights.Count == 3)
                {
                    parameters.WarmUp = 0;
                    parameters.Weights = new Weights(weights[0], weights[1], weights[2]);
                }
                solver = new FieldSolver(mesh, start, parameters);
                theta = thetaDegrees;
            }
        }

        private void ScheduleNextStep()
        {
            GH_Document document = OnPingDocument();
            document?.ScheduleSolution(1, new GH_Document.GH_ScheduleDelegate(ExpireForNextStep));
        }

        private void ExpireForNextStep(GH_Document document) => ExpireSolution(false);

        public override bool Write(GH_IWriter writer)
        {
            if (solver != null && signature != null)
            {
                writer.SetByteArray(SessionKey, solver.Save());
                writer.SetString(SignatureKey, signature);
                writer.SetDouble(ThetaKey, theta);
            }
            return base.Write(writer);
        }

        public override bool Read(GH_IReader reader)
        {
            if (reader.ItemExists(SessionKey) && reader.ItemExists(SignatureKey) && reader.ItemExists(ThetaKey) && NativeSetup.EnsureLoaded() == null)
            {
                try
                {
                    solver?.Dispose();
                    solver = FieldSolver.Load(reader.GetByteArray(SessionKey));
                    signature = reader.GetString(SignatureKey);
                    theta = reader.GetDouble(ThetaKey);
                }
                catch (LamellaException)
                {
                    // A damaged or foreign session: solve again from the inputs.
                    solver = null;
                    signature = null;
                }
            }
            return base.Read(reader);
        }
    }
}
