//! A traced guide curve ([`TracedCurve`]) and why its tracing stopped ([`StopReason`]).

use crate::mesh::{EdgePoint, Vec3};

/// Why the tracer stopped.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum StopReason {
    /// The last point lies on the mesh boundary (a boundary edge or boundary vertex).
    Boundary,
    /// No candidate edge point satisfies Eq. 4 with the right sign, forward and farther than
    /// `d0`: a singular configuration (e.g. the P-curve family does not continue here).
    NoValidCandidate,
    /// The curve reached [`super::TraceOptions::max_length`].
    LengthLimit,
    /// The curve reached [`super::TraceOptions::max_points`].
    PointLimit,
}

/// A discrete P-curve traced on a mesh (Sec. 3.2.1): a polyline whose points lie on mesh edges,
/// from a start point on the boundary, in travel direction. Its side vector `u = n × t` points
/// to the left of the travel direction, seen from the side the normal points to; with that side
/// vector its signed binormal angle (Sec. 3.1) is the traced θ.
#[derive(Clone, Debug, PartialEq)]
pub struct TracedCurve {
    points: Vec<EdgePoint>,
    positions: Vec<Vec3>,
    stop: StopReason,
}

impl TracedCurve {
    /// Internal: `points` and `positions` have the same length (≥ 2).
    pub(crate) fn new(points: Vec<EdgePoint>, positions: Vec<Vec3>, stop: StopReason) -> TracedCurve {
        TracedCurve { points, positions, stop }
    }

    /// The points as edge points, edges given as `[a, b]` with `a < b`, `t` measured from `a`.
    pub fn points(&self) -> &[EdgePoint] {
        &self.points
    }

    /// The points' positions (caller units), one per point.
    pub fn positions(&self) -> &[Vec3] {
        &self.positions
    }

    /// Why tracing stopped.
    pub fn stop(&self) -> StopReason {
        self.stop
    }

    /// Polyline length.
    pub fn length(&self) -> f64 {
        self.positions.windows(2).map(|w| (w[1] - w[0]).norm()).sum()
    }
}
