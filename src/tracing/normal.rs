//! The surface normal at a point on an edge.
//!
//! Choice: the angle-weighted vertex normals of the edge's ends ([`TriMesh::vertex_normals`]),
//! interpolated linearly in the edge parameter and normalised. Unlike the authors' code (the
//! plain average of the two ends, reference notes §1.3) it varies continuously along the edge
//! and equals the vertex normal at a vertex, so a curve passing near a vertex sees no jump.

use crate::mesh::{EdgePoint, TriMesh, Vec3};

/// `normalize((1 − t)·n_a + t·n_b)` at `point` (valid indices); `None` if that sum vanishes.
pub(crate) fn point_normal(mesh: &TriMesh, point: &EdgePoint) -> Option<Vec3> {
    let normals = mesh.vertex_normals();
    let [a, b] = point.edge;
    // Internal invariant: traced points lie on mesh edges.
    normals[a as usize].lerp(&normals[b as usize], point.t).try_normalize(0.0)
}
