//! The nodes of a gridshell (paper Sec. 5.1): where a strip of one family crosses a strip of
//! another. At each crossing of the net ([`super::QuadNet`]) or web ([`super::Web`]) the strip of
//! each family built on that level is located, and the node gets both families, both strip ids, its arc length along each strip's centre
//! line, the node axis (the mean of the two strips' rulings there), the angle between the two
//! rulings (0 for a torsion-free node, Sec. 5.2), and each strip's Sec. 5.1 diagnostics at its
//! centre-line vertex nearest to the node (conical curvature, binormal–ruling angle, Prop. 2's
//! offset, the singular point of the ruling).

use super::quad_net::QuadNet;
use super::web::Web;
use crate::mesh::Vec3;
use crate::strips::{RectifyingStrip, StripPattern, VertexDiagnostics};

/// One node.
#[derive(Clone, Debug, PartialEq)]
pub struct Node {
    /// Index of the crossing in [`QuadNet::vertices`] (or [`Web::vertices`]).
    pub vertex: usize,
    /// The two families that cross here, the smaller first (`[0, 1]` in a net; a 3-web's
    /// vertex where all three cross has a node for each pair).
    pub families: [usize; 2],
    /// Index of the strip of each of the two families (into its pattern's `strips`).
    pub strips: [usize; 2],
    /// Arc length of the node along each strip's centre line, from its first point.
    pub arc_lengths: [f64; 2],
    /// The crossing on the surface.
    pub position: Vec3,
    /// Unit node axis: the mean of the two strips' unit rulings at the node (the second taken
    /// with the sign that agrees with the first).
    pub axis: Vec3,
    /// Angle between the two rulings as lines, in degrees (`[0°, 90°]`).
    pub ruling_angle_degrees: f64,
    /// Each strip's diagnostics (Sec. 5.1) at its centre-line vertex nearest to the node.
    pub diagnostics: [VertexDiagnostics; 2],
}

/// Where a point projects on a strip's centre line.
struct OnStrip {
    distance: f64,
    arc_length: f64,
    ruling: Vec3,
    /// The centre-line vertex nearest to the point.
    vertex: usize,
}

/// The nodes of `net` with the strips `patterns[k]` of each family (built on the levels
/// `net.levels[k]`). A crossing becomes a node when each family has a strip on its level within
/// `tolerance` (a length) of it; others (e.g. where a strip was skipped) are left out.
pub fn net_nodes(net: &QuadNet, patterns: [&StripPattern; 2], tolerance: f64) -> Vec<Node> {
    let finder = NodeFinder::new(&patterns, tolerance);
    net.vertices
        .iter()
        .enumerate()
        .filter_map(|(index, v)| finder.node(index, &v.position, [(0, net.levels[0][v.i]), (1, net.levels[1][v.j])]))
        .collect()
}

/// The nodes of `web` with the strips `patterns[k]` of each family (built on the levels
/// `web.levels.levels[k]`): at each vertex, one node per pair of families crossing there (three
/// at a 3-web's vertex, one at a Kagome pattern's), as [`net_nodes`].
pub fn web_nodes(web: &Web, patterns: [&StripPattern; 3], tolerance: f64) -> Vec<Node> {
    let finder = NodeFinder::new(&patterns, tolerance);
    let mut nodes = Vec::new();
    for (index, vertex) in web.vertices.iter().enumerate() {
        let through: Vec<(usize, f64)> = (0..3).filter_map(|k| vertex.levels[k].map(|l| (k, web.levels.levels[k][l]))).collect();
        for (x, &first) in through.iter().enumerate() {
            for &second in &through[x + 1..] {
                nodes.extend(finder.node(index, &vertex.position, [first, second]));
            }
        }
    }
    nodes
}

/// Finds the strips through a crossing and makes the node of two of them.
struct NodeFinder<'a> {
    patterns: &'a [&'a StripPattern],
    /// Per family and strip, the diagnostics of every centre-line vertex.
    diagnostics: Vec<Vec<Vec<VertexDiagnostics>>>,
    tolerance: f64,
}

impl<'a> NodeFinder<'a> {
    fn new(patterns: &'a [&'a StripPattern], tolerance: f64) -> Self {
        let diagnostics = patterns.iter().map(|p| p.strips.iter().map(RectifyingStrip::diagnostics).collect()).collect();
        NodeFinder { patterns, diagnostics, tolerance }
    }

    /// The node at crossing `index` (at `position`) of the strips of the two `(family, level)`s,
    /// if each has a strip on its level within the tolerance.
    fn node(&self, index: usize, position: &Vec3, crossing: [(usize, f64); 2]) -> Option<Node> {
        let [(k0, level0), (k1, level1)] = crossing;
        let (s0, a) = nearest_strip(self.patterns[k0], level0, position, self.tolerance)?;
        let (s1, b) = nearest_strip(self.patterns[k1], level1, position, self.tolerance)?;
        let second = if a.ruling.dot(&b.ruling) < 0.0 { -b.ruling } else { b.ruling };
        let axis = (a.ruling + second).try_normalize(0.0).unwrap_or(a.ruling);
        let ruling_angle_degrees = a.ruling.dot(&second).clamp(-1.0, 1.0).acos().to_degrees();
        let diagnostics = [self.diagnostics[k0][s0][a.vertex], self.diagnostics[k1][s1][b.vertex]];
        Some(Node { vertex: index, families: [k0, k1], strips: [s0, s1], arc_lengths: [a.arc_length, b.arc_length], position: *position, axis, ruling_angle_degrees, diagnostics })
    }
}

/// The strip on `level` whose centre line passes nearest to `point`, within `tolerance`.
fn nearest_strip(pattern: &StripPattern, level: f64, point: &Vec3, tolerance: f64) -> Option<(usize, OnStrip)> {
    let same_level = |l: f64| (l - level).abs() <= 1e-9 * level.abs().max(1.0);
    pattern
        .strips
        .iter()
        .enumerate()
        .filter(|(_, s)| same_level(s.level))
        .filter_map(|(id, s)| project(s, point).map(|on| (id, on)))
        .filter(|(_, on)| on.distance <= tolerance)
        .min_by(|a, b| a.1.distance.total_cmp(&b.1.distance))
}

/// The closest point of `strip`'s centre line to `point`, with its arc length and the ruling
/// interpolated there (normalised); `None` for a strip of fewer than two points.
fn project(strip: &RectifyingStrip, point: &Vec3) -> Option<OnStrip> {
    let c = &strip.centre;
    let mut best: Option<OnStrip> = None;
    let mut arc = 0.0;
    for s in 0..c.len().saturating_sub(1) {
        let edge = c[s + 1] - c[s];
        let length = edge.norm();
        let t = if length > 0.0 { ((point - c[s]).dot(&edge) / (length * length)).clamp(0.0, 1.0) } else { 0.0 };
        let distance = (c[s] + edge * t - point).norm();
        if best.as_ref().is_none_or(|b| distance < b.distance) {
            let ruling = (strip.rulings[s] * (1.0 - t) + strip.rulings[s + 1] * t).try_normalize(0.0).unwrap_or(strip.rulings[s]);
            best = Some(OnStrip { distance, arc_length: arc + t * length, ruling, vertex: if t < 0.5 { s } else { s + 1 } });
        }
        arc += length;
    }
    best
}

/// The point at arc length `arc` along a flat strip's centre line (clamped to its ends).
pub fn flat_point(centre: &[[f64; 2]], arc: f64) -> Option<[f64; 2]> {
    let mut left = arc.max(0.0);
    for pair in centre.windows(2) {
        let (a, b) = (pair[0], pair[1]);
        let length = (b[0] - a[0]).hypot(b[1] - a[1]);
        if left <= length && length > 0.0 {
            let t = left / length;
            return Some([a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]);
        }
        left -= length;
    }
    centre.last().copied()
}
