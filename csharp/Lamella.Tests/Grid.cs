using System;

namespace Lamella.Tests
{
    /// <summary>A planar test mesh: a grid of square cells in the XY plane, as CAD meshes hold it (four corners per quad).</summary>
    internal sealed class Grid
    {
        public readonly double[] Xyz;
        /// <summary>Four corners per cell, counter-clockwise seen from +z.</summary>
        public readonly int[] Quads;
        public int VertexCount => Xyz.Length / 3;

        /// <summary><paramref name="columns"/> × <paramref name="rows"/> cells of size <paramref name="cell"/>, the first vertex at (x0, y0).</summary>
        public Grid(int columns, int rows, double cell, double x0, double y0)
        {
            Xyz = new double[3 * (columns + 1) * (rows + 1)];
            for (int j = 0; j <= rows; j++)
            {
                for (int i = 0; i <= columns; i++)
                {
                    int v = j * (columns + 1) + i;
                    Xyz[3 * v] = x0 + cell * i;
                    Xyz[3 * v + 1] = y0 + cell * j;
                }
            }
            Quads = new int[4 * columns * rows];
            for (int j = 0; j < rows; j++)
            {
                for (int i = 0; i < columns; i++)
                {
                    int a = j * (columns + 1) + i, q = 4 * (j * columns + i);
                    Quads[q] = a;
                    Quads[q + 1] = a + 1;
                    Quads[q + 2] = a + columns + 2;
                    Quads[q + 3] = a + columns + 1;
                }
            }
        }

        /// <summary>The grid's quads split into triangles (see Conversion.MeshArrays.Triangulate).</summary>
        public int[] Triangles() => Conversion.MeshArrays.Triangulate(Xyz, Quads);

        /// <summary>f(x, y) at every vertex.</summary>
        public double[] Values(Func<double, double, double> f)
        {
            var values = new double[VertexCount];
            for (int v = 0; v < values.Length; v++) values[v] = f(Xyz[3 * v], Xyz[3 * v + 1]);
            return values;
        }
    }
}
