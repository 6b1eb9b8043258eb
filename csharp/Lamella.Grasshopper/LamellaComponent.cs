using System;
using System.Drawing;
using Grasshopper.Kernel;
using Grasshopper.Kernel.Types;
using Lamella.Hosting;

namespace Lamella.Grasshopper
{
    /// <summary>
    /// The common frame of the Lamella components: tab "Lamella", icon by name, the native library loaded before
    /// the first call, every failure (bad input, a native status, a replaced upstream result) turned into a component
    /// error instead of an exception, and the lifetime of native results: any number per iteration (list item or
    /// tree branch) of a solution, kept while downstream components read them, released when the next solution starts, when
    /// the component leaves its document or when the document closes.
    /// </summary>
    public abstract class LamellaComponent : GH_Component
    {
        private readonly string iconName;
        private readonly IterationResults results = new IterationResults();

        protected LamellaComponent(string name, string nickname, string description, string iconName)
            : base(name, nickname, description, LamellaInfo.Category, "Strips")
        {
            this.iconName = iconName;
        }

        protected override Bitmap Icon => Icons.Load(iconName);

        protected override void BeforeSolveInstance()
        {
            base.BeforeSolveInstance();
            Guard(BeginSolution);
        }

        protected override void AfterSolveInstance()
        {
            Guard(EndSolution);
            base.AfterSolveInstance();
        }

        public override void RemovedFromDocument(GH_Document document)
        {
            Guard(ReleaseNative);
            base.RemovedFromDocument(document);
        }

        public override void DocumentContextChanged(GH_Document document, GH_DocumentContext context)
        {
            if (context == GH_DocumentContext.Close) Guard(ReleaseNative);
            base.DocumentContextChanged(document, context);
        }

        /// <summary>A new solution starts: by default the previous solution's results are released.</summary>
        protected virtual void BeginSolution() => results.Clear();

        /// <summary>Every iteration of the solution has run.</summary>
        protected virtual void EndSolution()
        {
        }

        /// <summary>Releases every native object the component holds (removed from the document, or the document closes).</summary>
        protected virtual void ReleaseNative() => results.Clear();

        /// <summary>Keeps <paramref name="result"/> alive with this iteration's other results until the next solution, and returns it.</summary>
        protected T Keep<T>(IGH_DataAccess DA, T result) where T : class, IDisposable => results.Keep(DA.Iteration, result);

        protected sealed override void SolveInstance(IGH_DataAccess DA)
        {
            string loadError = NativeSetup.EnsureLoaded();
            if (loadError != null)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Error, loadError);
                return;
            }
            Guard(() => Solve(DA));
        }

        /// <summary>Runs <paramref name="work"/>, turning any exception into an error message.</summary>
        private void Guard(Action work)
        {
            try
            {
                work();
            }
            catch (LamellaException e)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Error, e.NativeMessage + " (" + Library.StatusName(e.Status) + ")");
            }
            catch (ObjectDisposedException)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Error, "the upstream result was replaced; it will be recomputed");
            }
            catch (Exception e)
            {
                // Contract with Grasshopper: never let an exception escape a component.
                AddRuntimeMessage(GH_RuntimeMessageLevel.Error, e.GetType().Name + ": " + e.Message);
            }
        }

        /// <summary>The component's work for one iteration; inputs already read by the caller are checked here.</summary>
        protected abstract void Solve(IGH_DataAccess DA);

        /// <summary>The value of a goo input, or null when it is missing or of another type (then with an error message).</summary>
        protected T GooValue<TGoo, T>(IGH_DataAccess DA, int index, string what) where TGoo : GH_Goo<T> where T : class
        {
            T value;
            TryGooValue<TGoo, T>(DA, index, what, out value);
            return value;
        }

        /// <summary>
        /// Reads a goo input into <paramref name="value"/> (null when nothing is connected). False, with an error message,
        /// when the input holds something else than <paramref name="what"/>.
        /// </summary>
        protected bool TryGooValue<TGoo, T>(IGH_DataAccess DA, int index, string what, out T value) where TGoo : GH_Goo<T> where T : class
        {
            value = null;
            IGH_Goo goo = null;
            if (!DA.GetData(index, ref goo) || goo == null)
            {
                return true;
            }
            var typed = goo as TGoo;
            if (typed == null || typed.Value == null)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Error, "input is a " + goo.TypeName + ", not " + what);
                return false;
            }
            value = typed.Value;
            return true;
        }

        /// <summary>
        /// The cleaned copy of a mesh input at the document's tolerance, with a remark saying what cleaning changed
        /// (see <see cref="Conversion.CleanMesh"/>).
        /// </summary>
        protected Conversion.CleanMesh CleanMeshInput(Rhino.Geometry.Mesh mesh)
        {
            Conversion.CleanMesh clean = RhinoConversion.Clean(mesh, WeldTolerance());
            string remark = clean.Describe();
            if (remark != null) AddRuntimeMessage(GH_RuntimeMessageLevel.Remark, remark);
            return clean;
        }

        /// <summary>The document's absolute tolerance, or 0 (weld identical positions only) when there is none.</summary>
        protected static double WeldTolerance()
        {
            double tolerance = DocumentTolerance();
            return tolerance >= 0 && !double.IsInfinity(tolerance) ? tolerance : 0;
        }
    }
}
