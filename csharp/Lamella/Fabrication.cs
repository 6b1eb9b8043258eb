using System;
using System.Runtime.InteropServices;
using Lamella.Interop;

namespace Lamella
{
    /// <summary>A strip material in pascals (<c>LmlMaterial</c>): each value finite and &gt; 0.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Material
    {
        /// <summary>Young's modulus E, Pa.</summary>
        public double YoungsModulus;
        /// <summary>Shear modulus G, Pa.</summary>
        public double ShearModulus;
        /// <summary>Allowable stress (compared with the von Mises stress of bending and torsion), Pa.</summary>
        public double AllowableStress;

        /// <summary>The library's preset "timber" (C24), "plywood" (birch), "steel" (S355) or "aluminium" (6082 T6).</summary>
        public static Material Preset(string name)
        {
            if (name == null) throw new ArgumentNullException(nameof(name));
            Material material;
            Native.Check(NativeMethods.lml_material_preset(Utf8.ToNative(name), out material));
            return material;
        }
    }

    /// <summary>The stock boards or sheets (<c>LmlStock</c>), in the strips' unit.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Stock
    {
        /// <summary>Length of a board, longer than twice <see cref="Overlap"/>.</summary>
        public double Length;
        /// <summary>Width of a board; 0: as wide as the widest piece (one row per board).</summary>
        public double Width;
        /// <summary>Splice overlap between consecutive pieces of a strip.</summary>
        public double Overlap;
        /// <summary>Gap between pieces on a board.</summary>
        public double Gap;

        /// <summary>The library's defaults for boards of <paramref name="length"/>: width 0, overlap 0.3, gap 0.01.</summary>
        public static Stock Boards(double length)
        {
            Stock stock;
            Native.Check(NativeMethods.lml_stock_default(length, out stock));
            return stock;
        }
    }

    /// <summary>One strip's bending and twisting check (<c>LmlStripCheck</c>).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct StripCheck
    {
        /// <summary>Largest bending strain t κ / 2.</summary>
        public double MaxStrain;
        /// <summary>Largest bending stress E t κ / 2, Pa.</summary>
        public double MaxBendingStress;
        /// <summary>Largest torsional shear stress G t τ, Pa.</summary>
        public double MaxShearStress;
        /// <summary>Largest utilisation √(σ² + 3 τ²) / allowable stress.</summary>
        public double MaxUtilisation;
        /// <summary>Index (within the strip) of the centre point of the largest utilisation.</summary>
        public ulong WorstPoint;
        /// <summary>Its arc length along the centre line.</summary>
        public double WorstArcLength;
        /// <summary>Its position in space.</summary>
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 3)] public double[] WorstPosition;
        /// <summary>Smallest bending radius; 0 for a straight strip.</summary>
        public double MinBendingRadius;
        /// <summary>Largest twist rate, rad per unit length.</summary>
        public double MaxTwistRate;
        /// <summary>1 when the utilisation exceeds 1 somewhere.</summary>
        public uint Overstressed;
    }

    /// <summary>One piece of a plan, a row of the bill of materials (<c>LmlPiece</c>).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Piece
    {
        /// <summary>Index of its strip.</summary>
        public ulong Strip;
        /// <summary>Its number along the strip, from 1.</summary>
        public ulong Number;
        /// <summary>Arc length of its start along the strip's centre line.</summary>
        public double Start;
        /// <summary>Arc length of its end.</summary>
        public double End;
        /// <summary>Centre-line length.</summary>
        public double Length;
        /// <summary>Width.</summary>
        public double Width;
        /// <summary>Smallest bending radius; 0 when straight.</summary>
        public double MinBendingRadius;
        /// <summary>Largest twist rate.</summary>
        public double MaxTwistRate;
        /// <summary>Largest utilisation.</summary>
        public double MaxUtilisation;
        /// <summary>Index of the piece spliced before it, −1 for none.</summary>
        public long Previous;
        /// <summary>Index of the piece spliced after it, −1 for none.</summary>
        public long Next;
        /// <summary>Board number, from 1.</summary>
        public ulong Board;
        /// <summary>Lower-left corner of its bounding box on the board.</summary>
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 2)] public double[] Position;
        /// <summary>Size of its bounding box.</summary>
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 2)] public double[] Size;
    }

    /// <summary>Totals of a plan (<c>LmlFabricationSummary</c>).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct FabricationSummary
    {
        /// <summary>Number of strips.</summary>
        public ulong Strips;
        /// <summary>Number of pieces.</summary>
        public ulong Pieces;
        /// <summary>Number of boards.</summary>
        public ulong Boards;
        /// <summary>Size of a board.</summary>
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 2)] public double[] BoardSize;
        /// <summary>The pieces' area over the boards'.</summary>
        public double MaterialYield;
        /// <summary>Number of strips over 100 % utilisation.</summary>
        public ulong OverstressedStrips;
    }

    /// <summary>The text outputs of a plan (<c>LML_FABRICATION_TEXT_*</c>).</summary>
    public enum FabricationText : uint
    {
        /// <summary>A piece's id, strip_&lt;i&gt;-&lt;k&gt;.</summary>
        PieceId = 0,
        /// <summary>cut.dxf (R12, millimetres).</summary>
        CutDxf = 1,
        /// <summary>cut.svg (millimetres).</summary>
        CutSvg = 2,
        /// <summary>bom.csv.</summary>
        BomCsv = 3,
    }

    /// <summary>
    /// The workshop plan of strips (<c>LmlFabrication</c>): the bending and twisting check of each strip for a material
    /// and thickness, the pieces cut from stock with splices, laid out on boards, the bill of materials and the cut files.
    /// Immutable; keeps no reference to the strips.
    /// </summary>
    public sealed class Fabrication : IDisposable
    {
        private readonly FabricationHandle handle;

        private Fabrication(FabricationHandle handle)
        {
            this.handle = handle;
        }

        /// <summary>Checks and cuts <paramref name="strips"/> in <paramref name="material"/> of <paramref name="thickness"/> from <paramref name="stock"/>.</summary>
        public static Fabrication Plan(Strips strips, Material material, double thickness, Stock stock)
        {
            if (strips == null) throw new ArgumentNullException(nameof(strips));
            FabricationHandle handle;
            Native.Check(NativeMethods.lml_fabrication_new(strips.Handle, ref material, thickness, ref stock, out handle));
            return new Fabrication(handle);
        }

        /// <summary>The plan's totals.</summary>
        public FabricationSummary Summary
        {
            get
            {
                FabricationSummary summary;
                Native.Check(NativeMethods.lml_fabrication_summary(handle, out summary));
                return summary;
            }
        }

        /// <summary>One check per strip, in strip order.</summary>
        public StripCheck[] StripChecks() =>
            Native.Read((StripCheck[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_fabrication_strip_checks(handle, b, c, out n));

        /// <summary>The pieces, strip by strip and along each strip.</summary>
        public Piece[] Pieces() => Native.Read((Piece[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_fabrication_pieces(handle, b, c, out n));

        /// <summary>A text output; <paramref name="index"/> selects the piece for <see cref="FabricationText.PieceId"/>.</summary>
        public string Text(FabricationText kind, int index = 0)
        {
            if (index < 0) throw new ArgumentOutOfRangeException(nameof(index));
            byte[] bytes = Native.Read((byte[] b, UIntPtr c, out UIntPtr n) =>
                NativeMethods.lml_fabrication_text(handle, (uint)kind, Native.Size(index), b, c, out n));
            return Utf8.FromTerminated(bytes);
        }

        /// <summary>Releases the native plan.</summary>
        public void Dispose() => handle.Dispose();
    }
}
