//! Validation errors of a candidate triangle mesh ([`MeshError`]).
//!
//! Every variant names the offending element (vertex, face, edge, OBJ line) so that a
//! validation report can point at it. The paper (Sec. 7) requires the reference surface to be
//! a topological disk, possibly with holes; the last checks enforce exactly that.

use std::fmt;
use std::path::PathBuf;

/// A problem found in a candidate mesh, in an OBJ file, or while reading a file.
///
/// The constructors report the first problem in this order (the order of the variants):
/// array lengths, emptiness, non-finite coordinates, index range, repeated indices,
/// zero-area faces, isolated vertices, non-manifold edges, non-manifold vertices,
/// inconsistent orientation, several components, disk topology, folded edges, slivers, and finally
/// geometry that overflows `f64`. [`crate::mesh::diagnose`] reports all of them.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum MeshError {
    /// A flat input array's length is not a multiple of 3.
    ArrayLength { array: &'static str, len: usize },
    /// The mesh has no vertices.
    NoVertices,
    /// The mesh has no faces.
    NoFaces,
    /// Coordinate `axis` (0 = x, 1 = y, 2 = z) of `vertex` is NaN or infinite.
    NonFiniteCoordinate { vertex: usize, axis: usize },
    /// Corner `corner` of `face` refers to vertex `index`, but there are only `vertex_count` vertices.
    IndexOutOfRange { face: usize, corner: usize, index: u64, vertex_count: usize },
    /// `face` uses vertex `index` more than once.
    RepeatedIndex { face: usize, index: u32 },
    /// `face` has a zero-length edge or (numerically) zero area:
    /// twice its area is at most 1e-12 times its longest edge squared.
    ZeroAreaFace { face: usize },
    /// `vertex` is used by no face.
    IsolatedVertex { vertex: usize },
    /// The edge `(a, b)` (a < b) is shared by `face_count` > 2 faces; `face` is the third of them.
    NonManifoldEdge { a: u32, b: u32, face_count: usize, face: usize },
    /// The faces around `vertex` form `fans` > 1 separate fans (e.g. a bow-tie).
    NonManifoldVertex { vertex: usize, fans: usize },
    /// `face_a` and `face_b` both traverse their shared edge from `from` to `to`.
    InconsistentOrientation { face_a: usize, face_b: usize, from: u32, to: u32 },
    /// The mesh has `count` > 1 connected components; `vertex` belongs to the second one
    /// (components ordered by their smallest vertex index).
    MultipleComponents { count: usize, vertex: usize },
    /// The mesh is not a topological disk possibly with holes: it needs at least one boundary
    /// loop and Euler characteristic V − E + F = 2 − (number of boundary loops).
    NotDisk { euler_characteristic: i64, boundary_loops: usize },
    /// The faces `face_a` and `face_b` sharing the edge `(a, b)` fold onto each other: their
    /// normals make an angle of `angle_degrees`, more than
    /// [`crate::mesh::MAX_FOLD_DEGREES`] (an inverted or folded-over triangle, e.g. a vertex
    /// moved across its neighbours).
    FoldedEdge { a: u32, b: u32, face_a: usize, face_b: usize, angle_degrees: f64 },
    /// `face` has `ratio` (< [`crate::mesh::MIN_NEIGHBOUR_AREA_RATIO`]) times the area of its
    /// neighbour `neighbour`: a sliver, numerically degenerate next to it.
    SliverFace { face: usize, neighbour: usize, ratio: f64 },
    /// A quantity derived from `face` (area, normal, gradient, or the vertex data it feeds)
    /// overflows or underflows `f64` at this coordinate scale.
    GeometryOutOfRange { face: usize },
    /// A scale factor that is not finite and positive.
    InvalidScaleFactor { factor: f64 },
    /// A mesh error caused by the `v` or `f` statement on OBJ line `line` (1-based).
    ObjLine { line: usize, error: Box<MeshError> },
    /// OBJ line `line` (1-based) is malformed.
    ObjParse { line: usize, message: String },
    /// Reading the file at `path` failed.
    Io { path: PathBuf, kind: std::io::ErrorKind, message: String },
}

impl fmt::Display for MeshError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            MeshError::ArrayLength { array, len } => {
                write!(f, "{array} array has length {len}, which is not a multiple of 3")
            }
            MeshError::NoVertices => write!(f, "mesh has no vertices"),
            MeshError::NoFaces => write!(f, "mesh has no faces"),
            MeshError::NonFiniteCoordinate { vertex, axis } => {
                let name = ["x", "y", "z"].get(*axis).copied().unwrap_or("?");
                write!(f, "vertex {vertex} has a non-finite {name} coordinate")
            }
            MeshError::IndexOutOfRange { face, corner, index, vertex_count } => write!(
                f,
                "face {face} corner {corner} refers to vertex {index}, but there are only {vertex_count} vertices"
            ),
            MeshError::RepeatedIndex { face, index } => {
                write!(f, "face {face} uses vertex {index} more than once")
            }
            MeshError::ZeroAreaFace { face } => {
                write!(f, "face {face} has zero area or a zero-length edge")
            }
            MeshError::IsolatedVertex { vertex } => write!(f, "vertex {vertex} is used by no face"),
            MeshError::NonManifoldEdge { a, b, face_count, face } => write!(
                f,
                "edge ({a}, {b}) is shared by {face_count} faces (non-manifold; face {face} is the third)"
            ),
            MeshError::NonManifoldVertex { vertex, fans } => write!(
                f,
                "faces around vertex {vertex} form {fans} separate fans (non-manifold vertex)"
            ),
            MeshError::InconsistentOrientation { face_a, face_b, from, to } => write!(
                f,
                "faces {face_a} and {face_b} both traverse edge {from} -> {to} (inconsistent orientation)"
            ),
            MeshError::MultipleComponents { count, vertex } => write!(
                f,
                "mesh has {count} connected components; vertex {vertex} belongs to the second"
            ),
            MeshError::NotDisk { euler_characteristic, boundary_loops } => write!(
                f,
                "mesh is not a topological disk with holes: Euler characteristic {euler_characteristic} \
                 with {boundary_loops} boundary loop(s) (need at least one loop and χ = 2 − loops)"
            ),
            MeshError::FoldedEdge { a, b, face_a, face_b, angle_degrees } => write!(
                f,
                "faces {face_a} and {face_b} fold over at edge ({a}, {b}): their normals are {angle_degrees:.1}° apart \
                 (more than {}°; an inverted or folded-over triangle)",
                super::MAX_FOLD_DEGREES
            ),
            MeshError::SliverFace { face, neighbour, ratio } => write!(
                f,
                "face {face} is a sliver: its area is {ratio:.1e} times that of its neighbour face {neighbour} \
                 (less than {:e}; move its vertices apart or remove it)",
                super::MIN_NEIGHBOUR_AREA_RATIO
            ),
            MeshError::GeometryOutOfRange { face } => write!(
                f,
                "geometry of face {face} overflows or underflows f64 at this coordinate scale"
            ),
            MeshError::InvalidScaleFactor { factor } => {
                write!(f, "scale factor {factor} is not finite and positive")
            }
            MeshError::ObjLine { line, error } => write!(f, "OBJ line {line}: {error}"),
            MeshError::ObjParse { line, message } => write!(f, "OBJ line {line}: {message}"),
            MeshError::Io { path, message, .. } => {
                write!(f, "cannot read {}: {message}", path.display())
            }
        }
    }
}

impl std::error::Error for MeshError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            MeshError::ObjLine { error, .. } => Some(error.as_ref()),
            _ => None,
        }
    }
}

/// The mesh element an error is about, used to map errors back to OBJ lines.
pub(crate) enum Culprit {
    Vertex(usize),
    Face(usize),
}

impl MeshError {
    /// The vertex or face this error names, if any.
    pub(crate) fn culprit(&self) -> Option<Culprit> {
        match *self {
            MeshError::NonFiniteCoordinate { vertex, .. }
            | MeshError::IsolatedVertex { vertex }
            | MeshError::NonManifoldVertex { vertex, .. }
            | MeshError::MultipleComponents { vertex, .. } => Some(Culprit::Vertex(vertex)),
            MeshError::IndexOutOfRange { face, .. }
            | MeshError::RepeatedIndex { face, .. }
            | MeshError::ZeroAreaFace { face }
            | MeshError::NonManifoldEdge { face, .. }
            | MeshError::SliverFace { face, .. }
            | MeshError::GeometryOutOfRange { face } => Some(Culprit::Face(face)),
            MeshError::FoldedEdge { face_b, .. } => Some(Culprit::Face(face_b)),
            MeshError::InconsistentOrientation { face_b, .. } => Some(Culprit::Face(face_b)),
            _ => None,
        }
    }
}
