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
    /// What Strip Net and Strip Web share: a net session (two families or a 3-web) started from the default start and
    /// solved within one solution, the strips of every family on its level curves with their verdicts, and the nodes as
    /// points, axes and text.
    /// </summary>
    public abstract class GridshellComponent : LamellaComponent
    {
        protected GridshellComponent(string name, string nickname, string description, string iconName)
            : base(name, nickname, description, iconName)
        {
        }

        /// <summary>
        /// Registers the inputs every gridshell has: Mesh, one θ per family (<paramref name="thetas"/>: description and
        /// default of each), Min Angle, Count, then <paramref name="extras"/> inputs that <paramref name="addExtras"/>
        /// (null for none) adds, then Width (optional), Max Iterations and Solve. <see cref="ReadInputs"/> reads them.
        /// </summary>
        protected static void RegisterGridshellInputs(GH_InputParamManager pManager, string[] thetaDescriptions, double[] thetaDefaults,
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
            pManager.AddIntegerParameter("Max Iterations", "I", "The most solver iterations (a count, ≥ 1). Default 300.", GH_ParamAccess.item, 300);
            pManager.AddBooleanParameter("Solve", "Sv", "True solves within this solution. Default false.", GH_ParamAccess.item, false);
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
            /// <summary>The index of the first input the component added itself.</summary>
            public int FirstExtra;
        }

        /// <summary>
        /// Reads the inputs of <see cref="RegisterGridshellInputs"/> (<paramref name="thetas"/>: the default θ of each family,
        /// <paramref name="extras"/>: the component's own inputs after Count, which it reads itself). Null, with an error or
        /// a remark, when there is no mesh, a count is out of range or Solve is false.
        /// </summary>
        protected GridshellInputs ReadInputs(IGH_DataAccess DA, double[] thetas, int extras, string design)
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
            bool solveNow = false;
            DA.GetData(5 + n + extras, ref solveNow);
            if (inputs.Count < 2 || inputs.MaxIterations < 1)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Error, inputs.Count < 2 ? "Count must be at least 2" : "Max Iterations must be at least 1");
                return null;
            }
            if (!solveNow)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Remark, "set Solve to true to design the " + design);
                return null;
            }
            return inputs;
        }

        /// <summary>
        /// The cleaned input mesh as a library mesh and the default start of the first two families
        /// (<see cref="NetSolver.DefaultStart"/>), both kept for this iteration.
        /// </summary>
        protected double[][] DefaultStart(IGH_DataAccess DA, GridshellInputs inputs, out LamellaMesh mesh)
        {
            CleanMesh clean = CleanMeshInput(inputs.Mesh);
            mesh = Keep(DA, LamellaMesh.FromArrays(clean.Xyz, clean.Triangles));
            return NetSolver.DefaultStart(mesh, inputs.Thetas[0], inputs.Thetas[1], inputs.MinAngle);
        }

        /// <summary>Steps <paramref name="net"/> (kept for this iteration) until it converges, <paramref name="maxIterations"/> or Escape; a warning when it did not converge.</summary>
        protected NetReport SolveNet(IGH_DataAccess DA, NetSolver net, int maxIterations)
        {
            Keep(DA, net);
            NetReport report = net.Report;
            while (report.Iterations < maxIterations && !report.IsConverged)
            {
                if (GH_Document.IsEscapeKeyDown()) break;
                report = net.Step((int)Math.Min(10, maxIterations - report.Iterations));
            }
            if (!report.IsConverged)
                AddRuntimeMessage(GH_RuntimeMessageLevel.Warning, string.Format(CultureInfo.InvariantCulture, "not converged after {0} iterations", report.Iterations));
            return report;
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
