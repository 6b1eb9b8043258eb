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
    /// stored in the .gh document, so a reopened document shows its last result without solving again.
    /// </summary>
    public class StripFieldComponent : LamellaComponent
    {
        private const string SessionKey = "LamellaSession";
        private const string SignatureKey = "LamellaSignature";

        private FieldSolver solver;
        private string signature;

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
            pManager.AddNumberParameter("Theta", "θ", "Target angle between the curves' binormals and the surface normal, in degrees, 0–180 (90: geodesics, 0: asymptotic curves). Default 60.", GH_ParamAccess.item, 60.0);
            pManager.AddVectorParameter("Direction", "D", "The start field is the height along this vector (unitless direction); its level curves should roughly follow the wanted strips. Default Z.", GH_ParamAccess.item, new Vector3d(0, 0, 1));
            pManager.AddNumberParameter("Spacing", "S", "Target distance between the levels F and F + 1, in document units (the gradient norm target is 1/S); 0 keeps the start field's mean gradient. Default 0.", GH_ParamAccess.item, 0.0);
            pManager.AddNumberParameter("Weights", "W", "Advanced: three weights λ_fair, λ_grad, λ_angle (paper Eq. 12), each ≥ 0, replacing the library's warm-up schedule and defaults. Unitless. Default: none (library defaults).", GH_ParamAccess.list);
            pManager[4].Optional = true;
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
        }

        protected override void Solve(IGH_DataAccess DA)
        {
            Mesh mesh = null;
            if (!DA.GetData(0, ref mesh) || mesh == null) return;
            double thetaDegrees = 60, spacing = 0;
            Vector3d direction = new Vector3d(0, 0, 1);
            int iterations = 5;
            bool reset = false, run = false;
            var weights = new List<double>();
            DA.GetData(1, ref thetaDegrees);
            DA.GetData(2, ref direction);
            DA.GetData(3, ref spacing);
            DA.GetDataList(4, weights);
            DA.GetData(5, ref iterations);
            DA.GetData(6, ref reset);
            DA.GetData(7, ref run);
            string problem = CheckInputs(spacing, weights, iterations);
            if (problem != null)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Error, problem);
                return;
            }

            double[] xyz;
            int[] triangles;
            RhinoConversion.MeshToArrays(mesh, out xyz, out triangles);
            var parameters = new List<double> { thetaDegrees, direction.X, direction.Y, direction.Z, spacing };
            parameters.AddRange(weights);
            string current = Signature.Of(xyz, triangles, parameters.ToArray());
            if (reset || solver == null || current != signature)
            {
                Restart(xyz, triangles, thetaDegrees, direction, spacing, weights);
                signature = current;
            }

            FieldReport report = solver.Report;
            if (run && !report.IsConverged)
            {
                report = solver.Step(iterations);
                if (!report.IsConverged) ScheduleNextStep();
            }
            Message = (report.IsConverged ? "converged · " : "") + string.Format(CultureInfo.InvariantCulture,
                "iteration {0} · E_angle {1:0.00e+0}", report.Iterations, report.EnergyAngle);
            if (report.SingularVertexCount > 0)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Warning, report.SingularVertexCount + " singular vertices: their level curves branch");
            }

            // The signature covers θ, so the session was solved for this θ (also after a document was reopened).
            DA.SetData(0, new FieldGoo(new FieldData(solver, thetaDegrees)));
            DA.SetDataList(1, solver.Values());
            DA.SetData(2, report.Describe());
            DA.SetData(3, report.AngleErrorMaxDegrees);
        }

        /// <summary>Null when the plain inputs are usable, else what is wrong (θ, mesh and direction are checked natively).</summary>
        private static string CheckInputs(double spacing, List<double> weights, int iterations)
        {
            if (!(spacing >= 0) || double.IsInfinity(spacing)) return "Spacing must be finite and ≥ 0 (0 keeps the start field's gradient)";
            if (weights.Count != 0 && weights.Count != 3) return "Weights takes three numbers (λ_fair, λ_grad, λ_angle) or none, not " + weights.Count;
            if (iterations < 1) return "Iterations must be at least 1";
            return null;
        }

        private void Restart(double[] xyz, int[] triangles, double thetaDegrees, Vector3d direction, double spacing, List<double> weights)
        {
            solver?.Dispose();
            solver = null;
            FieldParams parameters = FieldParams.Default(Family.PseudoGeodesic, thetaDegrees);
            parameters.GradientTarget = spacing > 0 ? 1.0 / spacing : 0.0;
            if (weights.Count == 3)
            {
                parameters.WarmUp = 0;
                parameters.Weights = new Weights(weights[0], weights[1], weights[2]);
            }
            using (var mesh = LamellaMesh.FromArrays(xyz, triangles))
            {
                solver = new FieldSolver(mesh, StartField.Height(xyz, direction.X, direction.Y, direction.Z), parameters);
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
            }
            return base.Write(writer);
        }

        public override bool Read(GH_IReader reader)
        {
            if (reader.ItemExists(SessionKey) && reader.ItemExists(SignatureKey) && NativeSetup.EnsureLoaded() == null)
            {
                try
                {
                    solver?.Dispose();
                    solver = FieldSolver.Load(reader.GetByteArray(SessionKey));
                    signature = reader.GetString(SignatureKey);
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
