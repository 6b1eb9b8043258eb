using System;
using System.Globalization;
using System.IO;

namespace Lamella.Hosting
{
    /// <summary>
    /// What a host shows of a fabrication plan, without Rhino: the bill of materials as rows of text (one branch per
    /// piece in a tree), the utilisation colour of each strip, and the cut files written to a folder.
    /// </summary>
    public static class FabricationTable
    {
        /// <summary>The column names of <see cref="BomRows"/>.</summary>
        public static readonly string[] Columns =
        {
            "id", "length", "width", "min bending radius", "max twist rate", "max utilisation", "splice partners", "board",
        };

        /// <summary>One row per piece (columns as <see cref="Columns"/>; numbers invariant, 4 decimals; a straight piece's radius empty).</summary>
        public static string[][] BomRows(Fabrication fabrication)
        {
            if (fabrication == null) throw new ArgumentNullException(nameof(fabrication));
            Piece[] pieces = fabrication.Pieces();
            var ids = new string[pieces.Length];
            for (int k = 0; k < pieces.Length; k++) ids[k] = fabrication.Text(FabricationText.PieceId, k);
            var rows = new string[pieces.Length][];
            for (int k = 0; k < pieces.Length; k++)
            {
                Piece p = pieces[k];
                string partners = string.Join(" ", Partner(ids, p.Previous), Partner(ids, p.Next)).Trim();
                rows[k] = new[]
                {
                    ids[k], Number(p.Length), Number(p.Width), p.MinBendingRadius > 0 ? Number(p.MinBendingRadius) : string.Empty,
                    Number(p.MaxTwistRate), Number(p.MaxUtilisation), partners, p.Board.ToString(CultureInfo.InvariantCulture),
                };
            }
            return rows;
        }

        private static string Partner(string[] ids, long index) => index >= 0 && index < ids.Length ? ids[index] : string.Empty;

        private static string Number(double value) => value.ToString("0.####", CultureInfo.InvariantCulture);

        /// <summary>
        /// The colour of a utilisation, as the library draws it in cut.svg: green at 0, yellow at 0.5, orange at 1, red beyond
        /// (and for a non-finite value).
        /// </summary>
        public static byte[] UtilisationRgb(double utilisation)
        {
            double u = double.IsNaN(utilisation) || double.IsInfinity(utilisation) ? 2.0 : Math.Max(0.0, utilisation);
            double[] rgb;
            if (u > 1.0) rgb = new[] { 0.85, 0.0, 0.1 };
            else if (u > 0.5) rgb = new[] { 1.0, 0.85 - 0.45 * (u - 0.5) / 0.5, 0.0 };
            else rgb = new[] { u / 0.5, 0.65 + 0.2 * u / 0.5, 0.0 };
            return new[] { Byte(rgb[0]), Byte(rgb[1]), Byte(rgb[2]) };
        }

        /// <summary><see cref="UtilisationRgb"/> as an opaque ARGB integer (for vertex colours).</summary>
        public static int UtilisationArgb(double utilisation)
        {
            byte[] rgb = UtilisationRgb(utilisation);
            return unchecked((int)0xFF000000u) | rgb[0] << 16 | rgb[1] << 8 | rgb[2];
        }

        private static byte Byte(double c) => (byte)Math.Round(255.0 * c, MidpointRounding.AwayFromZero);

        /// <summary>Writes cut.dxf, cut.svg and bom.csv into <paramref name="folder"/> (created if missing); returns their paths.</summary>
        public static string[] WriteFiles(Fabrication fabrication, string folder)
        {
            if (fabrication == null) throw new ArgumentNullException(nameof(fabrication));
            if (string.IsNullOrWhiteSpace(folder)) throw new ArgumentException("no folder given", nameof(folder));
            Directory.CreateDirectory(folder);
            string[] names = { "cut.dxf", "cut.svg", "bom.csv" };
            FabricationText[] kinds = { FabricationText.CutDxf, FabricationText.CutSvg, FabricationText.BomCsv };
            var paths = new string[names.Length];
            for (int i = 0; i < names.Length; i++)
            {
                paths[i] = Path.Combine(folder, names[i]);
                File.WriteAllText(paths[i], fabrication.Text(kinds[i]));
            }
            return paths;
        }
    }
}
