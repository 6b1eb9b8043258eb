//! How well curves keep a constant slope β about an axis `d` (Sec. 5.2.3, Eq. 22), judged along
//! the curves: each curve resampled at `spacing`, the tangent at an inner point taken as the chord
//! between its neighbours, its slope `asin |t·d|` against `|β|`, wherever the surface normal the
//! curve carries leaves the slope reachable ([`crate::field::slope_reachable`]); the other points
//! are counted apart (beyond the isophote no tangent has the slope).

use serde::{Deserialize, Serialize};

use crate::curves::{resample_all, CurveError, LevelCurve};
use crate::field::slope_reachable;
use crate::mesh::Vec3;

/// The measure of a family of curves against a slope.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct SlopeAngles {
    /// Slope errors in degrees over the measured points.
    pub rms_error_degrees: f64,
    pub max_error_degrees: f64,
    /// Where the error is largest.
    pub worst: Option<[f64; 3]>,
    /// Inner points where the slope is reachable (measured).
    pub measured: usize,
    /// Inner points beyond the isophote (or its margin), not measured.
    pub unreachable: usize,
    /// Resampling step used.
    pub spacing: f64,
}

/// Measures `curves` (with per-point surface normals) against the slope `slope_degrees` about the
/// unit `axis`, resampled at `spacing`. Errors: a spacing that is not finite and positive, or a
/// curve without a normal per point.
pub fn slope_angles(curves: &[LevelCurve], axis: &Vec3, slope_degrees: f64, spacing: f64) -> Result<SlopeAngles, CurveError> {
    let mut result = SlopeAngles { spacing, ..SlopeAngles::default() };
    let mut sum_squares = 0.0;
    for curve in resample_all(curves, spacing)? {
        for (w, normal) in curve.points.windows(3).zip(&curve.normals[1..]) {
            if !slope_reachable(normal, axis, slope_degrees) {
                result.unreachable += 1;
                continue;
            }
            let Some(t) = (w[2] - w[0]).try_normalize(0.0) else { continue };
            let error = (t.dot(axis).abs().min(1.0).asin().to_degrees() - slope_degrees.abs()).abs();
            sum_squares += error * error;
            result.measured += 1;
            if error > result.max_error_degrees || result.worst.is_none() {
                result.max_error_degrees = result.max_error_degrees.max(error);
                result.worst = Some([w[1].x, w[1].y, w[1].z]);
            }
        }
    }
    if result.measured > 0 {
        result.rms_error_degrees = (sum_squares / result.measured as f64).sqrt();
    }
    Ok(result)
}
