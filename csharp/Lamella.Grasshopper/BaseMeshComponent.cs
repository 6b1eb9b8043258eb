using System;
using System.Collections.Generic;
using System.Globalization;
using Grasshopper;
using Grasshopper.Kernel;
using Grasshopper.Kernel.Data;
using Lamella.Conversion;
using Lamella.Hosting;

namespace Lamella.Grasshopper
{
    /// <summary>
    /// What Optimise Net and Optimise Web share: a base-mesh session (paper Sec. 3.5) stepped within one solution, the
    /// default strip width, and each family's strips with their verdicts.
    /// </summary>
    public abstract class BaseMeshComponent : LamellaComponent
    {
        protected BaseMeshComponent(string name, string nickname, string description, string iconName)
            : base(name, nickname, description, iconName)
        {
        }

        /// <summary>
        /// <paramref name="width"/> when it was given, else the default strip width for the net's vertices
        /// <paramref name="xyz"/>, named in a remark.
        /// </summary>
        protected double StripWidth(bool widthGiven, double width, double[] xyz)
        {
            if (widthGiven) return width;
            width = StripDefaults.Width(xyz);
            AddRuntimeMessage(GH_RuntimeMessageLevel.Remark, string.Format(CultureInfo.InvariantCulture,
                "Width not set: {0:G6} ({1}; about {2:0.#} % of the net's extent)", width,
                RhinoConversion.DocumentUnits() ?? "document units", 100 * StripDefaults.WidthFraction));
            return width;
        }

        /// <summary>Steps <paramref name="solver"/> until it converges, <paramref name="maxIterations"/> or Escape; a warning when it did not converge.</summary>
        protected BaseMeshReport SolveBaseMesh(BaseMeshSolver solver, int maxIterations)
        {
            BaseMeshReport report = solver.Report;
            while (report.Iterations < maxIterations && !report.IsConverged)
            {
                if (GH_Document.IsEscapeKeyDown()) break;
                report = solver.Step((int)Math.Min(10, maxIterations - report.Iterations));
            }
            if (!report.IsConverged)
                AddRuntimeMessage(GH_RuntimeMessageLevel.Warning, string.Format(CultureInfo.InvariantCulture, "not converged after {0} iterations", report.Iterations));
            return report;
        }

        /// <summary>
        /// The strips of every family of <paramref name="solver"/>, <paramref name="width"/> wide: one planar-quad mesh per
        /// strip in branch {k} of <paramref name="meshes"/>, each family's verdict in <paramref name="verdicts"/>. A family
        /// that misses its angle gives an error with the library's message; its strips are output all the same (the
        /// designer sees where).
        /// </summary>
        protected void BuildFamilyStrips(BaseMeshSolver solver, double width, DataTree<object> meshes, List<string> verdicts)
        {
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
