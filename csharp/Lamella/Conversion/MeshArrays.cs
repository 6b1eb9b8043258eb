using System;
using System.Collections.Generic;

namespace Lamella.Conversion
{
    /// <summary>Face lists as CAD meshes hold them (triangles and quads) turned into the triangles the C ABI takes.</summary>
    public static class MeshArrays
    {
        /// <summary>
        /// Triangulates faces given as four corners each (a triangle repeats its third corner as the fourth, as
        /// Rhino's MeshFace does). A quad a b c d is split along its shorter diagonal, keeping the orientation.
        /// </summary>
        public static int[] Triangulate(double[] xyz, int[] faceCorners)
        {
            if (xyz == null) throw new ArgumentNullException(nameof(xyz));
            if (faceCorners == null) throw new ArgumentNullException(nameof(faceCorners));
            if (faceCorners.Length % 4 != 0) throw new ArgumentException("faceCorners holds " + faceCorners.Length + " indices, not 4 per face", nameof(faceCorners));
            int vertexCount = xyz.Length / 3;
            var triangles = new List<int>(faceCorners.Length * 3 / 2);
            for (int f = 0; f < faceCorners.Length / 4; f++)
            {
                int a = faceCorners[4 * f], b = faceCorners[4 * f + 1], c = faceCorners[4 * f + 2], d = faceCorners[4 * f + 3];
                foreach (int v in new[] { a, b, c, d })
                {
                    if (v < 0 || v >= vertexCount) throw new ArgumentOutOfRangeException(nameof(faceCorners), "face " + f + " refers to vertex " + v + ", but there are " + vertexCount + " vertices");
                }
                if (c == d)
                {
                    triangles.AddRange(new[] { a, b, c });
                }
                else if (SquaredDistance(xyz, a, c) <= SquaredDistance(xyz, b, d))
                {
                    triangles.AddRange(new[] { a, b, c, a, c, d });
                }
                else
                {
                    triangles.AddRange(new[] { a, b, d, b, c, d });
                }
            }
            return triangles.ToArray();
        }

        /// <summary>
        /// Faces of any number of corners (a web's triangles and a Kagome pattern's hexagons) as triangles: a triangle as
        /// it is, a larger face as a fan from its first corner (right for convex faces), keeping the orientation.
        /// </summary>
        public static int[] FanTriangles(IList<int[]> faces)
        {
            if (faces == null) throw new ArgumentNullException(nameof(faces));
            var triangles = new List<int>();
            for (int f = 0; f < faces.Count; f++)
            {
                int[] face = faces[f];
                if (face == null || face.Length < 3) throw new ArgumentException("face " + f + " has fewer than three corners", nameof(faces));
                for (int i = 1; i + 1 < face.Length; i++) triangles.AddRange(new[] { face[0], face[i], face[i + 1] });
            }
            return triangles.ToArray();
        }

        private static double SquaredDistance(double[] xyz, int i, int j)
        {
            double dx = xyz[3 * i] - xyz[3 * j], dy = xyz[3 * i + 1] - xyz[3 * j + 1], dz = xyz[3 * i + 2] - xyz[3 * j + 2];
            return dx * dx + dy * dy + dz * dz;
        }
    }
}
