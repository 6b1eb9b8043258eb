//! A point on a mesh edge, the discrete unit of traced guide curves (paper Sec. 3.2.1: each
//! point of a traced P-curve lies on an edge of the mesh) and of their trace energy (Eq. 5).

use super::{TriMesh, Vec3};

/// The point `(1 − t)·p_a + t·p_b` on the edge `[a, b]` of a mesh, `t ∈ [0, 1]`.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct EdgePoint {
    /// The edge's end vertices `[a, b]` (any order; `t` is measured from `a`).
    pub edge: [u32; 2],
    /// Position along the edge: 0 at `a`, 1 at `b`.
    pub t: f64,
}

impl EdgePoint {
    /// The point's position on `mesh`, or `None` when an end vertex is not a vertex of `mesh`.
    pub fn position(&self, mesh: &TriMesh) -> Option<Vec3> {
        let positions = mesh.positions();
        let a = positions.get(self.edge[0] as usize)?;
        let b = positions.get(self.edge[1] as usize)?;
        Some(a.lerp(b, self.t))
    }
}
