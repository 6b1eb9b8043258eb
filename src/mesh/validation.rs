//! Validation of a candidate mesh: every check of [`MeshError`], in a fixed order.
//!
//! Order (the constructors report the first failure, [`diagnose`] all of them):
//! 1. no vertices, no faces;
//! 2. non-finite coordinates (by vertex, then axis);
//! 3. index out of range, then repeated index (by face, then corner);
//! 4. zero-area faces (faces with valid indices and finite corners);
//! 5. isolated vertices;
//! 6. non-manifold edges, non-manifold vertices, inconsistent orientation
//!    (on the faces with valid indices);
//! 7. more than one connected component;
//! 8. not a disk with holes (only checked once the faces are all valid and form a connected,
//!    consistently oriented manifold, since boundary loops and χ are meaningless otherwise);
//! 9. folded edges: neighbouring faces whose normals are more than [`MAX_FOLD_DEGREES`] apart
//!    (inverted or folded-over triangles), then slivers: faces whose area is less than
//!    [`MIN_NEIGHBOUR_AREA_RATIO`] times a neighbour's (both checked on the same oriented
//!    manifold);
//! 10. derived geometry out of the range of f64 (checked on the built mesh, so only when
//!     everything else passed).

use super::error::MeshError;
use super::topology::{self, BoundaryEdge, EdgeTable};
use super::triangle::Triangle;
use super::trimesh::TriMesh;
use super::Vec3;

/// Topology of a mesh that passed validation.
pub(crate) struct ValidTopology {
    pub(crate) edges: Vec<[u32; 2]>,
    pub(crate) boundary_edges: Vec<BoundaryEdge>,
    /// Unordered boundary loops (see [`topology::trace_boundary_loops`]).
    pub(crate) boundary_loops: Vec<Vec<u32>>,
}

/// Collects errors; in "first only" mode the checks stop after the first failing stage.
struct Findings {
    errors: Vec<MeshError>,
    first_only: bool,
}

impl Findings {
    fn stop(&self) -> bool {
        self.first_only && !self.errors.is_empty()
    }
}

/// Every problem in a candidate mesh (not only the first), for a validation report.
/// Empty if and only if [`super::TriMesh::from_vertices_and_faces`] accepts the input.
pub fn diagnose(positions: &[Vec3], faces: &[[u32; 3]]) -> Vec<MeshError> {
    let mut findings = Findings { errors: Vec::new(), first_only: false };
    run_checks(positions, faces, &mut findings);
    if findings.errors.is_empty() {
        // The last check (numeric range of the derived geometry) needs the built mesh.
        if let Err(error) = TriMesh::from_vertices_and_faces(positions.to_vec(), faces.to_vec()) {
            findings.errors.push(error);
        }
    }
    findings.errors
}

/// Validates the mesh, returning its topology or the first problem in the documented order.
pub(crate) fn validate(positions: &[Vec3], faces: &[[u32; 3]]) -> Result<ValidTopology, MeshError> {
    let mut findings = Findings { errors: Vec::new(), first_only: true };
    let topology = run_checks(positions, faces, &mut findings);
    match (findings.errors.into_iter().next(), topology) {
        (Some(error), _) => Err(error),
        (None, Some(topology)) => Ok(topology),
        // Internal invariant: without errors the checks reach the end and return the topology.
        (None, None) => unreachable!("validation ended without topology or error"),
    }
}

/// Runs the checks in order; returns the topology if every check was reached and passed.
fn run_checks(positions: &[Vec3], faces: &[[u32; 3]], findings: &mut Findings) -> Option<ValidTopology> {
    if positions.is_empty() {
        findings.errors.push(MeshError::NoVertices);
    }
    if faces.is_empty() {
        findings.errors.push(MeshError::NoFaces);
    }
    if findings.stop() {
        return None;
    }
    let finite: Vec<bool> = positions.iter().map(|p| p.iter().all(|c| c.is_finite())).collect();
    for (vertex, p) in positions.iter().enumerate() {
        for axis in (0..3).filter(|&axis| !p[axis].is_finite()) {
            findings.errors.push(MeshError::NonFiniteCoordinate { vertex, axis });
        }
    }
    if findings.stop() {
        return None;
    }
    let index_ok = check_indices(positions.len(), faces, &mut findings.errors);
    if findings.stop() {
        return None;
    }
    for (face, corners) in faces.iter().enumerate() {
        if index_ok[face]
            && corners.iter().all(|&i| finite[i as usize])
            && Triangle::of(positions, corners).is_degenerate()
        {
            findings.errors.push(MeshError::ZeroAreaFace { face });
        }
    }
    if findings.stop() {
        return None;
    }
    let mut used = vec![false; positions.len()];
    for corners in faces {
        for &i in corners.iter().filter(|&&i| (i as usize) < positions.len()) {
            used[i as usize] = true;
        }
    }
    for vertex in (0..positions.len()).filter(|&v| !used[v]) {
        findings.errors.push(MeshError::IsolatedVertex { vertex });
    }
    if findings.stop() {
        return None;
    }
    let errors_before_topology = findings.errors.len();

    let valid_faces = || faces.iter().enumerate().filter(|(f, _)| index_ok[*f]);
    let table = EdgeTable::new(valid_faces());
    findings.errors.extend(table.non_manifold_edges());
    findings.errors.extend(table.non_manifold_vertices(faces.len()));
    findings.errors.extend(table.orientation_conflicts());
    let manifold_and_oriented = findings.errors.len() == errors_before_topology;
    if findings.stop() {
        return None;
    }
    let components = topology::component_representatives(positions.len(), valid_faces().map(|(_, c)| c));
    if components.len() > 1 {
        findings.errors.push(MeshError::MultipleComponents {
            count: components.len(),
            vertex: components[1],
        });
    }
    let all_faces_valid = index_ok.iter().all(|&ok| ok);
    if findings.stop() || !manifold_and_oriented || !all_faces_valid || components.len() != 1 {
        return None;
    }
    let boundary_edges = table.boundary_edges();
    let boundary_loops = topology::trace_boundary_loops(positions.len(), &boundary_edges);
    let used_count = used.iter().filter(|&&u| u).count();
    if let Err(error) =
        topology::disk_check(used_count, table.edge_count(), faces.len(), boundary_loops.len())
    {
        findings.errors.push(error);
    }
    if findings.stop() {
        return None;
    }
    findings.errors.extend(folded_edges(positions, faces, &table));
    if findings.stop() {
        return None;
    }
    findings.errors.extend(slivers(positions, faces, &table));
    if !findings.errors.is_empty() {
        return None;
    }
    Some(ValidTopology { edges: table.edges(), boundary_edges, boundary_loops })
}

/// Largest angle between the normals of two faces sharing an edge, in degrees. Beyond it the
/// surface folds back onto itself there (a fold of 180° is a triangle turned over onto its
/// neighbour): the one-ring of a vertex is no longer a disk over its tangent plane, level curves
/// double back, and the field's normal equations become singular. Creases of a designed surface
/// stay far below it.
pub const MAX_FOLD_DEGREES: f64 = 120.0;

/// One [`MeshError::FoldedEdge`] per edge whose two faces' normals are more than
/// [`MAX_FOLD_DEGREES`] apart (faces consistently oriented, corners finite, areas non-zero).
fn folded_edges(positions: &[Vec3], faces: &[[u32; 3]], table: &EdgeTable) -> Vec<MeshError> {
    let limit = MAX_FOLD_DEGREES.to_radians().cos();
    table
        .interior_edges()
        .filter_map(|([a, b], face_a, face_b)| {
            let (na, _) = Triangle::of(positions, &faces[face_a]).normal_and_area();
            let (nb, _) = Triangle::of(positions, &faces[face_b]).normal_and_area();
            let cosine = na.dot(&nb).clamp(-1.0, 1.0);
            (cosine < limit).then(|| MeshError::FoldedEdge { a, b, face_a, face_b, angle_degrees: cosine.acos().to_degrees() })
        })
        .collect()
}

/// Smallest ratio of a face's area to the area of a face sharing an edge with it. A face far
/// smaller than its neighbours (a vertex a hair's breadth from an edge) passes the zero-area
/// test of its own shape but makes the linear systems of the initial fields singular in floating
/// point; graded meshes change areas by far less between neighbours.
pub const MIN_NEIGHBOUR_AREA_RATIO: f64 = 1e-8;

/// One [`MeshError::SliverFace`] per face whose area is less than
/// [`MIN_NEIGHBOUR_AREA_RATIO`] times that of a face sharing an edge with it (the first such
/// neighbour in edge order), in face order.
fn slivers(positions: &[Vec3], faces: &[[u32; 3]], table: &EdgeTable) -> Vec<MeshError> {
    let areas: Vec<f64> = faces.iter().map(|f| Triangle::of(positions, f).normal_and_area().1).collect();
    let mut found: Vec<Option<(usize, f64)>> = vec![None; faces.len()];
    for (_, a, b) in table.interior_edges() {
        let (small, large) = if areas[a] <= areas[b] { (a, b) } else { (b, a) };
        let ratio = areas[small] / areas[large];
        if ratio < MIN_NEIGHBOUR_AREA_RATIO && found[small].is_none() {
            found[small] = Some((large, ratio));
        }
    }
    found
        .iter()
        .enumerate()
        .filter_map(|(face, f)| f.map(|(neighbour, ratio)| MeshError::SliverFace { face, neighbour, ratio }))
        .collect()
}

/// Index range and repetition checks; returns which faces have valid, distinct indices.
fn check_indices(vertex_count: usize, faces: &[[u32; 3]], errors: &mut Vec<MeshError>) -> Vec<bool> {
    let mut repeats = Vec::new();
    let mut index_ok = vec![true; faces.len()];
    for (face, corners) in faces.iter().enumerate() {
        for (corner, &index) in corners.iter().enumerate() {
            if index as usize >= vertex_count {
                errors.push(MeshError::IndexOutOfRange {
                    face,
                    corner,
                    index: u64::from(index),
                    vertex_count,
                });
                index_ok[face] = false;
            }
        }
        let repeated = (0..3).find(|&c| corners[c] == corners[(c + 1) % 3]).map(|c| corners[c]);
        if let Some(index) = repeated {
            repeats.push(MeshError::RepeatedIndex { face, index });
            index_ok[face] = false;
        }
    }
    errors.extend(repeats);
    index_ok
}
