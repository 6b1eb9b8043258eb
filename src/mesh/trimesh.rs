//! The validated, immutable triangle mesh [`TriMesh`] with its precomputed
//! differential-geometry data.

use serde::{Deserialize, Serialize};

use std::sync::OnceLock;

use super::error::MeshError;
use super::local_quadric::{local_quadrics, LocalQuadric};
use super::gradient::face_gradients;
use super::normals::{face_normals_and_areas, vertex_normals};
use super::star::{Stars, VertexStar};
use super::topology::BoundaryEdge;
use super::triangle::Triangle;
use super::validation::{validate, ValidTopology};
use super::voronoi_area::{mixed_voronoi_areas, normalized};
use super::Vec3;

/// A triangle mesh that is a topological disk, possibly with holes (paper Sec. 7): manifold,
/// consistently oriented, connected, without degenerate faces or isolated vertices.
///
/// Immutable; all derived data (normals, areas, stars, gradients, boundary) is computed once at
/// construction, deterministically from positions and faces. Serialisation stores positions and
/// faces only; deserialisation re-validates and recomputes, giving an identical mesh.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(try_from = "MeshData")]
pub struct TriMesh {
    positions: Vec<Vec3>,
    faces: Vec<[u32; 3]>,
    edges: Vec<[u32; 2]>,
    face_normals: Vec<Vec3>,
    face_areas: Vec<f64>,
    vertex_normals: Vec<Vec3>,
    vertex_areas: Vec<f64>,
    normalized_vertex_areas: Vec<f64>,
    is_boundary: Vec<bool>,
    boundary_loops: Vec<Vec<u32>>,
    boundary_edges: Vec<BoundaryEdge>,
    stars: Stars,
    face_gradients: Vec<[Vec3; 3]>,
    mean_edge_length: f64,
    bounding_box: (Vec3, Vec3),
    smooth: SmoothGeometry,
}

/// The local quadrics and their normals, fitted on first use (a fit per vertex costs more than
/// everything else a mesh derives, and many meshes never need it).
#[derive(Clone, Debug, Default)]
struct SmoothGeometry(OnceLock<(Vec<LocalQuadric>, Vec<Vec3>)>);

impl PartialEq for SmoothGeometry {
    /// Derived from positions and faces alone, which the mesh's equality compares.
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

impl TriMesh {
    /// positions: xyz triples (len multiple of 3), triangles: index triples (len multiple of 3).
    pub fn from_arrays(positions: &[f64], triangles: &[u32]) -> Result<TriMesh, MeshError> {
        for (array, len) in [("positions", positions.len()), ("triangles", triangles.len())] {
            if len % 3 != 0 {
                return Err(MeshError::ArrayLength { array, len });
            }
        }
        let positions = positions.chunks_exact(3).map(Vec3::from_column_slice).collect();
        let faces = triangles.chunks_exact(3).map(|t| [t[0], t[1], t[2]]).collect();
        TriMesh::from_vertices_and_faces(positions, faces)
    }

    /// Validates (see [`crate::mesh::diagnose`] for the checks and their order) and builds the
    /// mesh, returning the first problem found.
    pub fn from_vertices_and_faces(positions: Vec<Vec3>, faces: Vec<[u32; 3]>) -> Result<TriMesh, MeshError> {
        let topology = validate(&positions, &faces)?;
        let mesh = TriMesh::build(positions, faces, topology);
        mesh.check_numeric_range()?;
        Ok(mesh)
    }

    /// Computes all derived data of a validated mesh.
    fn build(positions: Vec<Vec3>, faces: Vec<[u32; 3]>, topology: ValidTopology) -> TriMesh {
        let ValidTopology { edges, boundary_edges, boundary_loops: loops } = topology;
        let (face_normals, face_areas) = face_normals_and_areas(&positions, &faces);
        let vertex_normals = vertex_normals(&positions, &faces, &face_normals);
        let vertex_areas = mixed_voronoi_areas(&positions, &faces, &face_areas);
        let normalized_vertex_areas = normalized(&vertex_areas);
        let mut boundary_next = vec![None; positions.len()];
        for e in &boundary_edges {
            boundary_next[e.from as usize] = Some(e.to);
        }
        let is_boundary = boundary_next.iter().map(Option::is_some).collect();
        let stars = Stars::new(positions.len(), &faces, &boundary_next);
        let face_gradients = face_gradients(&positions, &faces, &face_normals, &face_areas);
        let edge_length = |e: &[u32; 2]| (positions[e[1] as usize] - positions[e[0] as usize]).norm();
        let mean_edge_length = edges.iter().map(edge_length).sum::<f64>() / edges.len() as f64;
        // Summed in increasing order, so loops with the same edge lengths tie exactly.
        let loop_length = |l: &Vec<u32>| {
            let mut lengths: Vec<f64> = (0..l.len()).map(|i| edge_length(&[l[i], l[(i + 1) % l.len()]])).collect();
            lengths.sort_by(f64::total_cmp);
            lengths.iter().sum::<f64>()
        };
        // Outer (longest) loop first; ties by vertex count, then by start vertex.
        let mut keyed: Vec<(f64, Vec<u32>)> = loops.into_iter().map(|l| (loop_length(&l), l)).collect();
        keyed.sort_by(|(la, a), (lb, b)| lb.total_cmp(la).then(b.len().cmp(&a.len())).then(a[0].cmp(&b[0])));
        let boundary_loops: Vec<Vec<u32>> = keyed.into_iter().map(|(_, l)| l).collect();
        let bounding_box = positions.iter().skip(1).fold((positions[0], positions[0]), |(lo, hi), p| {
            (lo.inf(p), hi.sup(p))
        });
        TriMesh {
            positions,
            faces,
            edges,
            face_normals,
            face_areas,
            vertex_normals,
            vertex_areas,
            normalized_vertex_areas,
            is_boundary,
            boundary_loops,
            boundary_edges,
            stars,
            face_gradients,
            mean_edge_length,
            bounding_box,
            smooth: SmoothGeometry::default(),
        }
    }

    /// Rejects geometry whose derived quantities left the finite, positive range of f64
    /// (extreme coordinate scales); names a face, for a vertex quantity the first face of its star.
    fn check_numeric_range(&self) -> Result<(), MeshError> {
        let face_ok = |f: usize| {
            let area = self.face_areas[f];
            area > 0.0
                && area.is_finite()
                && self.face_normals[f].iter().all(|c| c.is_finite())
                && self.face_gradients[f].iter().all(|g| g.iter().all(|c| c.is_finite()))
        };
        if let Some(face) = (0..self.faces.len()).find(|&f| !face_ok(f)) {
            return Err(MeshError::GeometryOutOfRange { face });
        }
        let vertex_ok = |v: usize| {
            let (area, weight) = (self.vertex_areas[v], self.normalized_vertex_areas[v]);
            area > 0.0
                && area.is_finite()
                && weight > 0.0
                && weight.is_finite()
                && self.vertex_normals[v].iter().all(|c| c.is_finite())
        };
        if let Some(v) = (0..self.positions.len()).find(|&v| !vertex_ok(v)) {
            // Internal invariant: no vertex is isolated, so every star has a face.
            return Err(MeshError::GeometryOutOfRange { face: self.star(v).faces[0] as usize });
        }
        if !(self.mean_edge_length > 0.0 && self.mean_edge_length.is_finite()) {
            return Err(MeshError::GeometryOutOfRange { face: 0 });
        }
        Ok(())
    }

    pub fn vertex_count(&self) -> usize {
        self.positions.len()
    }

    pub fn face_count(&self) -> usize {
        self.faces.len()
    }

    pub fn positions(&self) -> &[Vec3] {
        &self.positions
    }

    /// Faces as vertex index triples, in winding order.
    pub fn faces(&self) -> &[[u32; 3]] {
        &self.faces
    }

    /// Undirected edges `[a, b]` with a < b, sorted.
    pub fn edges(&self) -> &[[u32; 2]] {
        &self.edges
    }

    /// Unit face normals, (p1 − p0) × (p2 − p0) normalised (right-hand rule on the winding).
    pub fn face_normals(&self) -> &[Vec3] {
        &self.face_normals
    }

    pub fn face_areas(&self) -> &[f64] {
        &self.face_areas
    }

    /// Unit vertex normals: corner-angle-weighted sum of face normals, normalised.
    pub fn vertex_normals(&self) -> &[Vec3] {
        &self.vertex_normals
    }

    /// The osculating quadric of the surface at every vertex ([`LocalQuadric`]: second-order
    /// normal and second fundamental form from a fit over the two-ring), fitted on first use.
    pub fn local_quadrics(&self) -> &[LocalQuadric] {
        &self.smooth_geometry().0
    }

    /// Second-order unit vertex normals: those of the [`Self::local_quadrics`]. On irregular
    /// triangulations they are more accurate than [`Self::vertex_normals`] by an order of the edge
    /// length; they are the reference surface normals every quality measure uses.
    pub fn smooth_normals(&self) -> &[Vec3] {
        &self.smooth_geometry().1
    }

    fn smooth_geometry(&self) -> &(Vec<LocalQuadric>, Vec<Vec3>) {
        self.smooth.0.get_or_init(|| {
            let quadrics = local_quadrics(self);
            let normals = quadrics.iter().map(|q| q.normal).collect();
            (quadrics, normals)
        })
    }

    /// Mixed Voronoi areas (Meyer et al. 2003); they sum to the total area.
    pub fn vertex_areas(&self) -> &[f64] {
        &self.vertex_areas
    }

    /// Vertex areas scaled to mean 1 (the weights A of the angle energies, paper Sec. 3.2.2).
    pub fn normalized_vertex_areas(&self) -> &[f64] {
        &self.normalized_vertex_areas
    }

    /// Whether vertex `v` lies on the boundary. Panics if `v >= vertex_count()`.
    pub fn is_boundary_vertex(&self, v: usize) -> bool {
        self.is_boundary[v]
    }

    /// Boundary loops, each ordered along the boundary halfedges (interior on the left) and
    /// starting at its smallest vertex; the outer (geometrically longest) loop first.
    pub fn boundary_loops(&self) -> &[Vec<u32>] {
        &self.boundary_loops
    }

    /// Every boundary edge with its one face, oriented as in that face, in edge order.
    pub fn boundary_edges(&self) -> &[BoundaryEdge] {
        &self.boundary_edges
    }

    /// The ordered one-ring of vertex `v` (see [`VertexStar`]); an interior star starts at its
    /// smallest neighbour. Panics if `v >= vertex_count()`.
    pub fn star(&self, v: usize) -> VertexStar<'_> {
        self.stars.get(v)
    }

    /// Gradient on face `f` of the hat function of each corner (they sum to zero).
    /// Panics if `f >= face_count()`.
    pub fn face_gradients(&self, f: usize) -> &[Vec3; 3] {
        &self.face_gradients[f]
    }

    /// Mean length of the undirected edges.
    pub fn mean_edge_length(&self) -> f64 {
        self.mean_edge_length
    }

    /// Axis-aligned bounding box (min corner, max corner).
    pub fn bounding_box(&self) -> (Vec3, Vec3) {
        self.bounding_box
    }

    /// The face with the smallest corner angle, and that angle in degrees (the first such face
    /// on ties): where the mesh is closest to degenerate, named when a linear system built on it
    /// turns out singular.
    pub fn sharpest_corner(&self) -> (usize, f64) {
        let smallest = |f: usize| {
            let triangle = Triangle::of(&self.positions, &self.faces[f]);
            (0..3).map(|i| triangle.corner_angle(i)).fold(f64::INFINITY, f64::min)
        };
        let (face, angle) = (0..self.faces.len()).map(|f| (f, smallest(f))).fold((0, f64::INFINITY), |best, next| if next.1 < best.1 { next } else { best });
        (face, angle.to_degrees())
    }
}

/// The serialised form: positions and faces; everything else is recomputed.
#[derive(Serialize, Deserialize)]
#[serde(rename = "TriMesh")]
struct MeshData {
    positions: Vec<[f64; 3]>,
    faces: Vec<[u32; 3]>,
}

impl TryFrom<MeshData> for TriMesh {
    type Error = MeshError;

    fn try_from(data: MeshData) -> Result<TriMesh, MeshError> {
        TriMesh::from_vertices_and_faces(data.positions.into_iter().map(Vec3::from).collect(), data.faces)
    }
}

impl Serialize for TriMesh {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        MeshData {
            positions: self.positions.iter().map(|p| [p.x, p.y, p.z]).collect(),
            faces: self.faces.clone(),
        }
        .serialize(serializer)
    }
}
