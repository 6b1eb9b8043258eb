//! Stop limits and tolerances of the tracer ([`TraceOptions`]).

use super::TraceError;

/// Largest [`TraceOptions::max_points`]: 10,000,000 points (a few hundred MB per curve).
pub const MAX_TRACE_POINTS: usize = 10_000_000;

/// Limits and tolerances of [`super::Tracer::trace`]. Lengths are relative to the mesh's mean
/// edge length, so the defaults suit any unit.
#[derive(Clone, Debug, PartialEq)]
pub struct TraceOptions {
    /// Stop once the curve is at least this long (caller units); `f64::INFINITY` for no limit.
    pub max_length: f64,
    /// Stop once the curve has this many points (2 to [`MAX_TRACE_POINTS`]).
    pub max_points: usize,
    /// `d0` of Sec. 3.2.1 as a fraction of the mean edge length: the next point must be farther
    /// than `d0` from the current one, which keeps discrete osculating planes stable.
    pub min_step_ratio: f64,
    /// A root of Eq. 4 (or of the start-angle equation) is accepted if the angle it realises is
    /// within this many degrees of the target (0 < tolerance < 90).
    pub angle_tolerance_degrees: f64,
    /// A point within this fraction of its edge's length from an edge end is "near the vertex":
    /// the search for the next point then covers that vertex's whole one-ring (in `[0, 0.5)`).
    pub vertex_ratio: f64,
    /// Largest turn between consecutive segments, in degrees (0 < turn ≤ 90; the authors' code
    /// allows 90). A smooth curve turns by about κ·h per step; a much sharper turn jumps to
    /// another solution, e.g. onto the second asymptotic direction when θ = 0.
    pub max_turn_degrees: f64,
}

impl Default for TraceOptions {
    /// No length limit, 100 000 points, `d0` = 0.001 mean edge, 2° tolerance, 1 % vertex ratio
    /// (the tolerance and the vertex ratio of the authors' code, see the reference notes §4.3),
    /// turns up to 45°.
    fn default() -> Self {
        TraceOptions {
            max_length: f64::INFINITY,
            max_points: 100_000,
            min_step_ratio: 1e-3,
            angle_tolerance_degrees: 2.0,
            vertex_ratio: 0.01,
            max_turn_degrees: 45.0,
        }
    }
}

impl TraceOptions {
    /// Checks every field, naming the first bad one.
    pub(crate) fn validate(&self) -> Result<(), TraceError> {
        let bad = |name: &'static str, value: f64| Err(TraceError::InvalidOption { name, value });
        if self.max_length.is_nan() || self.max_length <= 0.0 {
            return bad("max_length", self.max_length);
        }
        if !(2..=MAX_TRACE_POINTS).contains(&self.max_points) {
            return bad("max_points", self.max_points as f64);
        }
        if !(self.min_step_ratio.is_finite() && self.min_step_ratio >= 0.0) {
            return bad("min_step_ratio", self.min_step_ratio);
        }
        let tolerance = self.angle_tolerance_degrees;
        if !(tolerance > 0.0 && tolerance < 90.0) {
            return bad("angle_tolerance_degrees", tolerance);
        }
        if !(self.vertex_ratio >= 0.0 && self.vertex_ratio < 0.5) {
            return bad("vertex_ratio", self.vertex_ratio);
        }
        if !(self.max_turn_degrees > 0.0 && self.max_turn_degrees <= 90.0) {
            return bad("max_turn_degrees", self.max_turn_degrees);
        }
        Ok(())
    }
}
