//! A gridshell as built: the quad net at the levels that carry strips in both families, and its
//! nodes (paper Sec. 4.1 and 5.1). The front ends that hold two strip patterns (the C ABI) get the
//! net and the nodes in one call.

use super::nodes::{net_nodes, Node};
use super::quad_net::{quad_net_at, QuadNet};
use crate::field::{validate_field, FieldError};
use crate::mesh::TriMesh;
use crate::strips::StripPattern;

/// How far (in mean edge lengths) a crossing may lie from a strip's centre line and still be a
/// node of it: a strip's centre line is the optimised curve, which leaves the level curve by a
/// fraction of an edge.
pub const NODE_TOLERANCE_EDGES: f64 = 2.0;

/// The quad net of two fields and the nodes of their strips.
#[derive(Clone, Debug, PartialEq)]
pub struct StripNet {
    pub net: QuadNet,
    pub nodes: Vec<Node>,
}

/// The levels of `pattern`'s strips, increasing and without repeats.
pub fn strip_levels(pattern: &StripPattern) -> Vec<f64> {
    let mut levels: Vec<f64> = pattern.strips.iter().map(|s| s.level).collect();
    levels.sort_by(f64::total_cmp);
    levels.dedup();
    levels
}

/// The net of `f` and `g` (one value per vertex of `mesh`) at the levels of the strips
/// `patterns[0]` (built on `f`'s level curves) and `patterns[1]` (on `g`'s), and the nodes where
/// those strips cross ([`net_nodes`], within [`NODE_TOLERANCE_EDGES`] mean edge lengths).
///
/// Errors: a field of the wrong length, with a non-finite or out-of-range value (naming the
/// vertex), or constant.
pub fn strip_net(mesh: &TriMesh, f: &[f64], g: &[f64], patterns: [&StripPattern; 2]) -> Result<StripNet, FieldError> {
    validate_field(mesh, f)?;
    validate_field(mesh, g)?;
    let net = quad_net_at(mesh, f, g, patterns.map(strip_levels));
    let nodes = net_nodes(&net, patterns, NODE_TOLERANCE_EDGES * mesh.mean_edge_length());
    Ok(StripNet { net, nodes })
}
