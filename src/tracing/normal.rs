//! The surface normal at a point on an edge.
//!
//! Choice: the angle-weighted vertex normals of the edge's ends ([`TriMesh::vertex_normals`]),
//! interpolated linearly in the edge parameter and normalised. Unlike the authors' code (the
//! plain average of the two ends, reference notes §1.3) it varies continuously along the edge
//! and equals the vertex normal at a vertex, so a curve passing near a vertex sees no jump.

use crate::mesh::{EdgePoint, TriMesh, Vec3};

/// `normalize((1 − t)·n_a + t·n_b)` at `point`; `None` if an index is out of range or that
/// sum vanishes.
pub(crate) fn point_normal(mesh: &TriMesh, point: &EdgePoint) -> Option<Vec3> {
    let normals = mesh.vertex_normals();
    let [a, b] = point.edge.map(|v| normals.get(v as usize));
    a?.lerp(b?, point.t).try_normalize(0.0)
}
