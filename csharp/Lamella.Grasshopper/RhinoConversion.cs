using System;
using System.Collections.Generic;
using System.Drawing;
using Lamella.Conversion;
using Rhino.Geometry;

namespace Lamella.Grasshopper
{
    /// <summary>
    /// Rhino geometry ↔ the flat arrays of the binding. Each function only copies numbers; the array logic (cleaning
    /// and triangulating meshes, closing loops, cutting packed arrays, laying out flat strips) lives in
    /// Lamella.Conversion, tested on plain arrays.
    /// </summary>
    internal static class RhinoConversion
    {
        /// <summary>
        /// A cleaned copy of the mesh for the library (see <see cref="CleanMesh"/>): vertices within
        /// <paramref name="tolerance"/> welded, degenerate and repeated triangles and unused vertices removed, quads split.
        /// </summary>
        public static CleanMesh Clean(Mesh mesh, double tolerance)
        {
            double[] xyz = PointsToArray(mesh.Vertices.ToPoint3dArray());
            return CleanMesh.FromFaces(xyz, FaceCorners(mesh), tolerance);
        }

        /// <summary>The mesh's faces as four corners each (a triangle repeats its third corner), indices into its vertices.</summary>
        public static int[] FaceCorners(Mesh mesh)
        {
            var corners = new int[4 * mesh.Faces.Count];
            for (int f = 0; f < mesh.Faces.Count; f++)
            {
                MeshFace face = mesh.Faces[f];
                corners[4 * f] = face.A;
                corners[4 * f + 1] = face.B;
                corners[4 * f + 2] = face.C;
                corners[4 * f + 3] = face.D;
            }
            return corners;
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

        /// <summary>One point per three values.</summary>
        public static List<Point3d> Points(double[] xyz)
        {
            var points = new List<Point3d>(xyz.Length / 3);
            for (int i = 0; i < xyz.Length / 3; i++) points.Add(Point(xyz, i));
            return points;
        }

        /// <summary>One vector per three values.</summary>
        public static List<Vector3d> Vectors(double[] xyz)
        {
            var vectors = new List<Vector3d>(xyz.Length / 3);
            for (int i = 0; i < xyz.Length / 3; i++) vectors.Add(new Vector3d(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]));
            return vectors;
        }

        /// <summary>One polyline curve per item of packed points (x, y, z per point); a closed item repeats its first point (see <see cref="Packing.CloseLoops"/>).</summary>
        public static List<PolylineCurve> Polylines(Packed polylines)
        {
            var curves = new List<PolylineCurve>(polylines.Count);
            foreach (double[] item in Packing.Unpack(polylines)) curves.Add(new PolylineCurve(Points(item)));
            return curves;
        }

        /// <summary>A quad mesh: four indices into <paramref name="xyz"/> per quad.</summary>
        public static Mesh QuadMesh(double[] xyz, int[] quads) => FaceMesh(xyz, quads, 4);

        /// <summary>A triangle mesh (each triangle a face whose last two corners coincide, Rhino's triangle form).</summary>
        public static Mesh TriangleMesh(double[] xyz, int[] triangles) => FaceMesh(xyz, triangles, 3);

        /// <summary>The mesh of the faces of <paramref name="corners"/> indices each, with normals.</summary>
        private static Mesh FaceMesh(double[] xyz, int[] faces, int corners)
        {
            var mesh = new Mesh();
            for (int i = 0; i < xyz.Length / 3; i++) mesh.Vertices.Add(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
            for (int f = 0; f < faces.Length / corners; f++)
            {
                int k = corners * f;
                mesh.Faces.AddFace(faces[k], faces[k + 1], faces[k + 2], faces[k + corners - 1]);
            }
            mesh.Normals.ComputeNormals();
            mesh.Compact();
            return mesh;
        }

        /// <summary>One quad mesh per strip.</summary>
        public static List<Mesh> QuadMeshes(StripMesh[] strips)
        {
            var meshes = new List<Mesh>(strips.Length);
            foreach (StripMesh strip in strips) meshes.Add(QuadMesh(strip.Vertices, strip.Quads));
            return meshes;
        }

        /// <summary>A copy of <paramref name="mesh"/> with one colour (opaque ARGB) per vertex.</summary>
        public static Mesh ColouredCopy(Mesh mesh, int[] argb)
        {
            Mesh copy = mesh.DuplicateMesh();
            copy.VertexColors.SetColors(Array.ConvertAll(argb, Color.FromArgb));
            return copy;
        }

        /// <summary>One line per segment of six values (x0 y0 z0 x1 y1 z1).</summary>
        public static List<Line> Lines(double[] segments)
        {
            var lines = new List<Line>(segments.Length / 6);
            for (int i = 0; i < segments.Length / 6; i++) lines.Add(new Line(Point(segments, 2 * i), Point(segments, 2 * i + 1)));
            return lines;
        }

        /// <summary>The active Rhino document's model unit (e.g. "Meters"), or null without one (Rhino.Compute, Hops).</summary>
        public static string DocumentUnits()
        {
            try
            {
                Rhino.RhinoDoc document = Rhino.RhinoDoc.ActiveDoc;
                return document == null ? null : document.ModelUnitSystem.ToString();
            }
            catch (Exception)
            {
                return null;
            }
        }

        /// <summary>Points given on the XY plane (x, y, z each) placed on <paramref name="plane"/> (see <see cref="StripArrays.OnPlane"/>).</summary>
        public static double[] OnPlane(double[] xyz, Plane plane)
        {
            Point3d o = plane.Origin;
            Vector3d x = plane.XAxis, y = plane.YAxis;
            return StripArrays.OnPlane(xyz, new[] { o.X, o.Y, o.Z }, new[] { x.X, x.Y, x.Z }, new[] { y.X, y.Y, y.Z });
        }
    }
}
