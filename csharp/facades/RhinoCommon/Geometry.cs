// COMPILE-TIME FACADE of RhinoCommon (never shipped): only the members Lamella.Grasshopper uses,
// with the real namespaces and signatures; every body throws.
using System;
using System.Collections.Generic;
using System.Drawing;
using Rhino.Geometry.Collections;

namespace Rhino
{
    public class RhinoDoc
    {
        internal RhinoDoc() { throw new NotSupportedException("facade"); }
        public static RhinoDoc ActiveDoc { get { throw new NotSupportedException("facade"); } }
        public UnitSystem ModelUnitSystem { get { throw new NotSupportedException("facade"); } }
    }

    // A few of the real values, with their real numbers (the plugin only prints the value it gets).
    public enum UnitSystem : byte { None = 0, Millimeters = 2, Meters = 4 }
}

namespace Rhino.Geometry
{
    public struct Point3d
    {
        public Point3d(double x, double y, double z) { throw new NotSupportedException("facade"); }
        public double X { get { throw new NotSupportedException("facade"); } set { throw new NotSupportedException("facade"); } }
        public double Y { get { throw new NotSupportedException("facade"); } set { throw new NotSupportedException("facade"); } }
        public double Z { get { throw new NotSupportedException("facade"); } set { throw new NotSupportedException("facade"); } }
    }

    public struct Vector3d
    {
        public Vector3d(double x, double y, double z) { throw new NotSupportedException("facade"); }
        public double X { get { throw new NotSupportedException("facade"); } set { throw new NotSupportedException("facade"); } }
        public double Y { get { throw new NotSupportedException("facade"); } set { throw new NotSupportedException("facade"); } }
        public double Z { get { throw new NotSupportedException("facade"); } set { throw new NotSupportedException("facade"); } }
    }

    public struct Plane
    {
        public static Plane WorldXY { get { throw new NotSupportedException("facade"); } }
        public Point3d Origin { get { throw new NotSupportedException("facade"); } set { throw new NotSupportedException("facade"); } }
        public Vector3d XAxis { get { throw new NotSupportedException("facade"); } set { throw new NotSupportedException("facade"); } }
        public Vector3d YAxis { get { throw new NotSupportedException("facade"); } set { throw new NotSupportedException("facade"); } }
    }

    public struct Line
    {
        public Line(Point3d from, Point3d to) { throw new NotSupportedException("facade"); }
    }

    public struct MeshFace
    {
        public int A { get { throw new NotSupportedException("facade"); } set { throw new NotSupportedException("facade"); } }
        public int B { get { throw new NotSupportedException("facade"); } set { throw new NotSupportedException("facade"); } }
        public int C { get { throw new NotSupportedException("facade"); } set { throw new NotSupportedException("facade"); } }
        public int D { get { throw new NotSupportedException("facade"); } set { throw new NotSupportedException("facade"); } }
    }

    public class GeometryBase
    {
        internal GeometryBase() { throw new NotSupportedException("facade"); }
    }

    public class Mesh : GeometryBase
    {
        public Mesh() { throw new NotSupportedException("facade"); }
        public MeshVertexList Vertices { get { throw new NotSupportedException("facade"); } }
        public MeshFaceList Faces { get { throw new NotSupportedException("facade"); } }
        public MeshVertexNormalList Normals { get { throw new NotSupportedException("facade"); } }
        public MeshVertexColorList VertexColors { get { throw new NotSupportedException("facade"); } }
        public bool Compact() { throw new NotSupportedException("facade"); }
        public Mesh DuplicateMesh() { throw new NotSupportedException("facade"); }
    }

    public class Curve : GeometryBase
    {
        internal Curve() { throw new NotSupportedException("facade"); }
        public double GetLength() { throw new NotSupportedException("facade"); }
        public double[] DivideByCount(int segmentCount, bool includeEnds, out Point3d[] points) { throw new NotSupportedException("facade"); }
    }

    public class PolylineCurve : Curve
    {
        public PolylineCurve(IEnumerable<Point3d> points) { throw new NotSupportedException("facade"); }
        public int PointCount { get { throw new NotSupportedException("facade"); } }
        public Point3d Point(int index) { throw new NotSupportedException("facade"); }
    }
}

namespace Rhino.Geometry.Collections
{
    public class MeshVertexList
    {
        internal MeshVertexList() { throw new NotSupportedException("facade"); }
        public int Count { get { throw new NotSupportedException("facade"); } set { throw new NotSupportedException("facade"); } }
        public int Add(double x, double y, double z) { throw new NotSupportedException("facade"); }
        public Rhino.Geometry.Point3d[] ToPoint3dArray() { throw new NotSupportedException("facade"); }
    }

    public class MeshFaceList
    {
        internal MeshFaceList() { throw new NotSupportedException("facade"); }
        public int Count { get { throw new NotSupportedException("facade"); } set { throw new NotSupportedException("facade"); } }
        public Rhino.Geometry.MeshFace this[int index] { get { throw new NotSupportedException("facade"); } set { throw new NotSupportedException("facade"); } }
        public int AddFace(int vertex1, int vertex2, int vertex3, int vertex4) { throw new NotSupportedException("facade"); }
    }

    public class MeshVertexColorList
    {
        internal MeshVertexColorList() { throw new NotSupportedException("facade"); }
        public bool SetColors(Color[] colors) { throw new NotSupportedException("facade"); }
    }

    public class MeshVertexNormalList
    {
        internal MeshVertexNormalList() { throw new NotSupportedException("facade"); }
        public bool ComputeNormals() { throw new NotSupportedException("facade"); }
    }
}
