using System;
using System.Collections.Generic;
using Lamella.Conversion;
using Rhino.Geometry;

namespace Lamella.Grasshopper
{
    /// <summary>
    /// Rhino geometry ↔ the flat arrays of the binding. Each function only copies numbers; the array logic
    /// (triangulating quads, cutting packed arrays, laying out flat strips) lives in Lamella.Conversion, tested on
    /// plain arrays.
    /// </summary>
    internal static class RhinoConversion
    {
        /// <summary>The mesh's vertices (x, y, z each) and its faces as triangles (quads split along the shorter diagonal).</summary>
        public static void MeshToArrays(Mesh mesh, out double[] xyz, out int[] triangles)
        {
            xyz = PointsToArray(mesh.Vertices.ToPoint3dArray());
            var corners = new int[4 * mesh.Faces.Count];
            for (int f = 0; f < mesh.Faces.Count; f++)
            {
                MeshFace face = mesh.Faces[f];
                corners[4 * f] = face.A;
                corners[4 * f + 1] = face.B;
                corners[4 * f + 2] = face.C;
                corners[4 * f + 3] = face.D;
            }
            triangles = MeshArrays.Triangulate(xyz, corners);
        }

        /// <summary>The points as x, y, z each.</summary>
        public static double[] PointsToArray(IList<Point3d> points)
        {
            var xyz = new double[3 * points.Count];
            for (int i = 0; i < points.Count; i++)
            {
                xyz[3 * i] = points[i].X;
                xyz[3 * i + 1] = points[i].Y;
                xyz[3 * i + 2] = points[i].Z;
            }
            return xyz;
        }

        /// <summary>
        /// A curve drawn on the surface as a stroke polyline (x, y, z per point) with points at most
        /// <paramref name="spacing"/> apart: a polyline keeps its corners and is densified, any other curve is divided
        /// into ⌈length / spacing⌉ arcs of equal length.
        /// </summary>
        public static double[] CurveToStroke(Curve curve, double spacing)
        {
            var polyline = curve as PolylineCurve;
            if (polyline != null)
            {
                var corners = new Point3d[polyline.PointCount];
                for (int i = 0; i < corners.Length; i++) corners[i] = polyline.Point(i);
                return StrokeArrays.Densify(PointsToArray(corners), spacing);
            }
            double segments = Math.Ceiling(curve.GetLength() / spacing);
            if (!(segments >= 1 && segments <= 1e6)) throw new ArgumentException("a stroke curve is not finite or over a million mesh edges long");
            Point3d[] points;
            curve.DivideByCount((int)segments, true, out points);
            if (points == null) throw new ArgumentException("a stroke curve could not be divided (is it valid?)");
            return PointsToArray(points);
        }

        public static Point3d Point(double[] xyz, int i) => new Point3d(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);

        /// <summary>One polyline curve per item of a packed point array (x, y, z per point).</summary>
        public static List<PolylineCurve> Polylines(double[] points, int[] offsets)
        {
            var curves = new List<PolylineCurve>();
            foreach (double[] item in Packing.Unpack(new Packed(points, offsets, 3)))
            {
                var vertices = new List<Point3d>(item.Length / 3);
                for (int i = 0; i < item.Length / 3; i++) vertices.Add(Point(item, i));
                curves.Add(new PolylineCurve(vertices));
            }
            return curves;
        }

        /// <summary>A quad mesh from vertices (x, y, z each) and four indices per quad.</summary>
        public static Mesh QuadMesh(double[] xyz, int[] quads)
        {
            var mesh = new Mesh();
            for (int i = 0; i < xyz.Length / 3; i++) mesh.Vertices.Add(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
            for (int q = 0; q < quads.Length / 4; q++) mesh.Faces.AddFace(quads[4 * q], quads[4 * q + 1], quads[4 * q + 2], quads[4 * q + 3]);
            mesh.Normals.ComputeNormals();
            mesh.Compact();
            return mesh;
        }

        /// <summary>One line per segment of six values (x0 y0 z0 x1 y1 z1).</summary>
        public static List<Line> Lines(double[] segments)
        {
            var lines = new List<Line>(segments.Length / 6);
            for (int i = 0; i < segments.Length / 6; i++) lines.Add(new Line(Point(segments, 2 * i), Point(segments, 2 * i + 1)));
            return lines;
        }
    }
}
