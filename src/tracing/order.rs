//! Whether a set of traced curves is ordered like the level sets `F = 1, 2, …, n` of one
//! function (Sec. 3.2.2): no crossings or self-intersections, and each curve lies between its
//! neighbours, i.e. curve `k` separates curves `k − 1` and `k + 1` on the surface.
//!
//! Separation is decided on the boundary: a curve from boundary to boundary cuts the disk in
//! two, and its end points split the boundary loop into two arcs; curves `k − 1` and `k + 1`
//! must start on different arcs.

use super::intersections::intersections;
use super::TracedCurve;
use crate::mesh::{EdgePoint, TriMesh};

/// Why a set of curves is not ordered; the first defect found, in this order of checks.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum OrderDefect {
    /// Curve `curve` intersects itself.
    SelfIntersection { curve: usize },
    /// Curves `first < second` cross or touch.
    Crossing { first: usize, second: usize },
    /// Curve `curve` (with neighbours on both sides) does not run from the boundary loop of its
    /// start back to that loop, so it does not cut the surface in two.
    OpenEnd { curve: usize },
    /// Curve `curve` does not separate curves `curve − 1` and `curve + 1`.
    NotBetween { curve: usize },
}

/// `Ok` if `curves` (traced on `mesh`) are ordered; otherwise the first defect.
pub fn check_order(mesh: &TriMesh, curves: &[TracedCurve]) -> Result<(), OrderDefect> {
    let report = intersections(mesh, curves);
    if let Some(c) = report.self_intersections.first() {
        return Err(OrderDefect::SelfIntersection { curve: c.curves[0] });
    }
    if let Some(c) = report.crossings.first() {
        return Err(OrderDefect::Crossing { first: c.curves[0], second: c.curves[1] });
    }
    let places = LoopPlaces::new(mesh);
    for k in 1..curves.len().saturating_sub(1) {
        let chord = |c: usize| -> Option<(usize, f64, f64)> {
            let points = curves[c].points();
            let (l0, start) = places.locate(points.first()?)?;
            let (l1, end) = places.locate(points.last()?)?;
            (l0 == l1).then_some((l0, start, end))
        };
        let (loop_index, x, y) = chord(k).ok_or(OrderDefect::OpenEnd { curve: k })?;
        let (lo, hi) = (x.min(y), x.max(y));
        let side = |c: usize| {
            let start = curves[c].points().first().and_then(|p| places.locate(p));
            start.filter(|(l, _)| *l == loop_index).map(|(_, s)| lo < s && s < hi)
        };
        match (side(k - 1), side(k + 1)) {
            (Some(before), Some(after)) if before != after => {}
            _ => return Err(OrderDefect::NotBetween { curve: k }),
        }
    }
    Ok(())
}

/// Arc-length positions along the boundary loops.
struct LoopPlaces {
    /// Per boundary vertex: its loop, its arc length from the loop's first vertex, the next
    /// vertex along the loop and the length of the edge to it.
    vertex: Vec<Option<LoopVertex>>,
    /// Length of each loop.
    loop_lengths: Vec<f64>,
}

#[derive(Clone, Copy)]
struct LoopVertex {
    loop_index: usize,
    arc: f64,
    next: u32,
    edge_length: f64,
}

impl LoopPlaces {
    fn new(mesh: &TriMesh) -> LoopPlaces {
        let positions = mesh.positions();
        let mut vertex = vec![None; mesh.vertex_count()];
        let mut loop_lengths = Vec::new();
        for (loop_index, boundary_loop) in mesh.boundary_loops().iter().enumerate() {
            let mut arc = 0.0;
            for (k, &v) in boundary_loop.iter().enumerate() {
                let next = boundary_loop[(k + 1) % boundary_loop.len()];
                // Internal invariant: loop vertices are mesh vertices.
                let edge_length = (positions[next as usize] - positions[v as usize]).norm();
                vertex[v as usize] = Some(LoopVertex { loop_index, arc, next, edge_length });
                arc += edge_length;
            }
            loop_lengths.push(arc);
        }
        LoopPlaces { vertex, loop_lengths }
    }

    /// (loop, arc length in `[0, loop length)`) of a point on a boundary edge or exactly at a
    /// boundary vertex; `None` elsewhere.
    fn locate(&self, point: &EdgePoint) -> Option<(usize, f64)> {
        let [a, b] = point.edge;
        let at = |v: u32| self.vertex.get(v as usize).copied().flatten();
        let (va, vb) = (at(a), at(b));
        let (from, t) = match (va, vb) {
            (Some(va), _) if va.next == b => (va, point.t),
            (_, Some(vb)) if vb.next == a => (vb, 1.0 - point.t),
            _ if point.t == 0.0 => (va?, 0.0),
            _ if point.t == 1.0 => (vb?, 0.0),
            _ => return None,
        };
        let length = self.loop_lengths[from.loop_index];
        Some((from.loop_index, (from.arc + t * from.edge_length) % length))
    }
}
