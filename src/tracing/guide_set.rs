//! A set of guide curves for the level-set initialisation (Sec. 3.2.1–3.2.2): P-curves traced
//! from evenly spaced points of one side of the outer boundary, numbered so that a field taking
//! the value `i` on guide `i` has the asked signed angle.

use super::seeding::{boundary_segments, evenly_spaced_starts, DEFAULT_CORNER_TURN_DEGREES};
use super::{TraceError, TraceOptions, TracedCurve, Tracer};
use crate::mesh::TriMesh;

/// Traced guides and the boundary side they start from.
#[derive(Clone, Debug)]
pub struct GuideSet {
    pub curves: Vec<TracedCurve>,
    /// Index of the side among the sides of the outer loop (split at corners of
    /// [`DEFAULT_CORNER_TURN_DEGREES`]).
    pub side: usize,
}

/// Traces `count` P-curves of angle `theta` (degrees) from evenly spaced points of side `side`
/// of the outer boundary (`None`: the longest side), each leaving it at `start_angle` (degrees).
///
/// A curve's side vector `u = n × t` (Sec. 3.1) points to its left. The boundary runs with the
/// surface on its left, so a curve leaving it into the surface has its left against the
/// boundary's direction: the guides are numbered against the order of their starts along the
/// loop, so that the field with value i on guide i grows to each curve's left and its family
/// has the signed angle θ (not 180° − θ). Errors: those of the seeding and of each trace (the
/// error of guide `i` is returned with its index).
pub fn trace_guide_set(mesh: &TriMesh, count: usize, side: Option<usize>, start_angle: f64, theta: f64) -> Result<GuideSet, (Option<usize>, TraceError)> {
    let segments = boundary_segments(mesh, 0, DEFAULT_CORNER_TURN_DEGREES).map_err(|e| (None, e))?;
    let side = side.unwrap_or_else(|| longest_side(mesh, segments.iter().map(|s| s.vertices())));
    let starts = evenly_spaced_starts(mesh, &segments, side, count).map_err(|e| (None, e))?;
    let tracer = Tracer::new(mesh);
    let curves = starts
        .iter()
        .rev()
        .enumerate()
        .map(|(i, start)| tracer.trace(start, theta, start_angle, &TraceOptions::default()).map_err(|e| (Some(i), e)))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(GuideSet { curves, side })
}

/// Index of the side with the greatest length (the first of equals).
fn longest_side<'a>(mesh: &TriMesh, sides: impl Iterator<Item = &'a [u32]>) -> usize {
    let p = mesh.positions();
    let lengths = sides.map(|v| v.windows(2).map(|w| (p[w[1] as usize] - p[w[0] as usize]).norm()).sum::<f64>());
    lengths.enumerate().fold((0, f64::NEG_INFINITY), |best, (i, l)| if l > best.1 { (i, l) } else { best }).0
}
