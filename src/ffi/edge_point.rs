//! `LmlEdgePoint`: a point on a mesh edge, the currency of start points and traced curves.

use crate::mesh::EdgePoint;

/// The point `(1 − t)·p_a + t·p_b` on the mesh edge `[a, b]` (zero-based vertex indices).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LmlEdgePoint {
    pub a: u32,
    pub b: u32,
    pub t: f64,
}

impl From<&EdgePoint> for LmlEdgePoint {
    fn from(p: &EdgePoint) -> LmlEdgePoint {
        LmlEdgePoint { a: p.edge[0], b: p.edge[1], t: p.t }
    }
}

impl From<&LmlEdgePoint> for EdgePoint {
    fn from(p: &LmlEdgePoint) -> EdgePoint {
        EdgePoint { edge: [p.a, p.b], t: p.t }
    }
}
