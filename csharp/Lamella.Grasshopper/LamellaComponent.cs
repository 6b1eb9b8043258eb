using System;
using System.Drawing;
using Grasshopper.Kernel;
using Grasshopper.Kernel.Types;

namespace Lamella.Grasshopper
{
    /// <summary>
    /// The common frame of the Lamella components: tab "Lamella", icon by name, the native library loaded before
    /// the first call, and every failure (bad input, a native status, a replaced upstream result) turned into a
    /// component error instead of an exception.
    /// </summary>
    public abstract class LamellaComponent : GH_Component
    {
        private readonly string iconName;

        protected LamellaComponent(string name, string nickname, string description, string iconName)
            : base(name, nickname, description, "Lamella", "Strips")
        {
            this.iconName = iconName;
        }

        protected override Bitmap Icon => Icons.Load(iconName);

        protected sealed override void SolveInstance(IGH_DataAccess DA)
        {
            string loadError = NativeSetup.EnsureLoaded();
            if (loadError != null)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Error, loadError);
                return;
            }
            try
            {
                Solve(DA);
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

        /// <summary>The component's work; inputs already read by the caller are checked here.</summary>
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
    }
}
