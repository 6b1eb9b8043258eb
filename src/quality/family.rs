//! How well a set of curves forms the asked family, judged as an outside reviewer would: along
//! the curves themselves, at the scale of a few edges, against the smooth surface normal.
//!
//! The optimiser's own measure (the binormal of each vertex's level jet, or of the paper's
//! vertex star) is a diagnostic of the optimisation: it can be met by curves that are straight at
//! the scale of a few edges, whose binormal is undefined (`../shared/docs/fidelity-notes.md`
//! records a cylinder where the star measure said 0.11° RMS while the curves missed θ by 56°).
//! Here each curve is resampled at `spacing` (three mean edge lengths by default), the discrete
//! binormal of every three consecutive points (Eq. 1) is compared with the surface normal the
//! curve carries (interpolated from the mesh's second-order normals), and the signed angle of
//! Sec. 3.1 against the family's target gives the error.
//!
//! Points whose circle through their neighbours is larger than the model (radius above the
//! bounding-box diagonal) have no meaningful binormal. For geodesics and asymptotic curves such a
//! straight piece is exact (a straight line on a surface is both); for pseudo-geodesics of any
//! other angle it is a *degenerate* piece, counted apart: a family made of such pieces (the
//! rulings of a cylinder, say) satisfies the P-curve condition only in the limit and carries no
//! rectifying strip of the asked angle.

use serde::{Deserialize, Serialize};

use crate::curves::{CurveError, LevelCurve};
use crate::field::Family;
use crate::mesh::Vec3;

/// Default resampling step, in mean edge lengths.
pub const DEFAULT_SPACING_EDGES: f64 = 3.0;

/// What [`FamilyAngles::score`] adds per unit fraction of nearly straight points, in degrees.
pub const STRAIGHT_PENALTY_DEGREES: f64 = 10.0;

/// Where a curve misses its family most.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct WorstPoint {
    /// Index of the curve in the measured slice.
    pub curve: usize,
    pub point: [f64; 3],
    /// Angle error in degrees.
    pub error_degrees: f64,
    /// The measured signed angle in degrees.
    pub measured_degrees: f64,
}

/// The measure of one curve.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct CurveAngles {
    /// Resampled points with a binormal (or, for geodesics and asymptotic curves, straight ones).
    pub measured: usize,
    /// Pseudo-geodesics only: resampled points where the curve is straight (see the module).
    pub straight: usize,
    pub rms_error_degrees: f64,
    pub max_error_degrees: f64,
    /// Length of the curve.
    pub length: f64,
}

/// The measure of a family of curves.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct FamilyAngles {
    /// One entry per measured curve, in order.
    pub curves: Vec<CurveAngles>,
    /// Over all measured points.
    pub rms_error_degrees: f64,
    pub max_error_degrees: f64,
    pub worst: Option<WorstPoint>,
    pub measured: usize,
    pub straight: usize,
    /// Resampling step used, in the curves' length units.
    pub spacing: f64,
}

impl FamilyAngles {
    /// One figure to compare measures of the same family by, in degrees (lower is better): the
    /// RMS error plus a quarter of the largest, plus [`STRAIGHT_PENALTY_DEGREES`] per unit
    /// fraction of nearly straight points.
    pub fn score(&self) -> f64 {
        self.rms_error_degrees + 0.25 * self.max_error_degrees + STRAIGHT_PENALTY_DEGREES * self.straight_fraction()
    }

    /// Fraction of the inner resampled points that are straight (0 when none was sampled).
    pub fn straight_fraction(&self) -> f64 {
        let total = self.measured + self.straight;
        if total == 0 {
            0.0
        } else {
            self.straight as f64 / total as f64
        }
    }
}

/// Measures how well `curves` (with per-point surface normals, as
/// [`crate::curves::extract_level_curves`] gives them) form `family`, resampled at `spacing`;
/// points whose osculating circle is larger than `model_size` count as straight.
/// Errors: `spacing` not finite and positive, or a curve without a normal per point.
pub fn family_angles(curves: &[LevelCurve], family: Family, spacing: f64, model_size: f64) -> Result<FamilyAngles, CurveError> {
    let resampled: Vec<LevelCurve> = curves.iter().map(|curve| curve.resampled(spacing)).collect::<Result<_, _>>()?;
    let mut angles = polyline_family_angles(&resampled, family, model_size);
    angles.spacing = spacing;
    for (measure, curve) in angles.curves.iter_mut().zip(curves) {
        measure.length = curve.length();
    }
    Ok(angles)
}

/// As [`family_angles`], at the curves' own vertices (no resampling; `spacing` is left 0): for
/// polylines whose vertices are the points that matter, such as the rows and columns of a base
/// mesh (Sec. 3.5). Curves need a normal per point.
pub fn polyline_family_angles(curves: &[LevelCurve], family: Family, model_size: f64) -> FamilyAngles {
    let theta = family.theta_degrees();
    let straight_is_exact = !matches!(family, Family::PseudoGeodesic { .. });
    let mut family_angles = FamilyAngles::default();
    let mut sum_squares = 0.0;
    for (index, curve) in curves.iter().enumerate() {
        let mut angles = CurveAngles { length: curve.length(), ..CurveAngles::default() };
        let mut curve_squares = 0.0;
        for (point, measured) in inner_angles(curve, model_size) {
            let error = match measured {
                Some(measured) => Some((family.angle_error_degrees(measured, theta), measured)),
                None if straight_is_exact => Some((0.0, theta)),
                None => None,
            };
            let Some((error, measured)) = error else {
                angles.straight += 1;
                continue;
            };
            angles.measured += 1;
            curve_squares += error * error;
            angles.max_error_degrees = angles.max_error_degrees.max(error);
            if family_angles.worst.is_none_or(|w| error > w.error_degrees) {
                family_angles.worst = Some(WorstPoint { curve: index, point: [point.x, point.y, point.z], error_degrees: error, measured_degrees: measured });
            }
        }
        if angles.measured > 0 {
            angles.rms_error_degrees = (curve_squares / angles.measured as f64).sqrt();
        }
        sum_squares += curve_squares;
        family_angles.measured += angles.measured;
        family_angles.straight += angles.straight;
        family_angles.max_error_degrees = family_angles.max_error_degrees.max(angles.max_error_degrees);
        family_angles.curves.push(angles);
    }
    if family_angles.measured > 0 {
        family_angles.rms_error_degrees = (sum_squares / family_angles.measured as f64).sqrt();
    }
    family_angles
}

/// Each inner point of a resampled curve with its signed angle, `None` where the curve is
/// straight (osculating circle larger than `model_size`).
fn inner_angles(curve: &LevelCurve, model_size: f64) -> Vec<(Vec3, Option<f64>)> {
    let n = curve.points.len();
    if n < 3 {
        return Vec::new();
    }
    let inner = if curve.closed { 0..n } else { 1..n - 1 };
    inner
        .filter_map(|i| {
            let (a, b, c) = (curve.points[(i + n - 1) % n], curve.points[i], curve.points[(i + 1) % n]);
            let (incoming, outgoing, chord) = (b - a, c - b, c - a);
            let cross = incoming.cross(&outgoing);
            let lengths = incoming.norm() * outgoing.norm() * chord.norm();
            if lengths.is_nan() || lengths <= 0.0 {
                return None;
            }
            // Circumradius |a||b||c| / (2 |a × b|).
            if cross.norm() * 2.0 * model_size <= lengths {
                return Some((b, None));
            }
            let binormal = cross.normalize();
            let tangent = chord.normalize();
            let normal = curve.normals[i];
            let side = normal.cross(&tangent).try_normalize(0.0)?;
            let sign = if binormal.dot(&side) < 0.0 { -1.0 } else { 1.0 };
            Some((b, Some((sign * binormal.dot(&normal)).clamp(-1.0, 1.0).acos().to_degrees())))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn helix(pitch: f64, points: usize) -> LevelCurve {
        // Radius 1 helix around z, normals of the cylinder (radial).
        let p: Vec<Vec3> = (0..points).map(|i| {
            let t = i as f64 * 0.05;
            Vec3::new(t.cos(), t.sin(), pitch * t)
        }).collect();
        let normals = p.iter().map(|q| Vec3::new(q.x, q.y, 0.0).normalize()).collect();
        LevelCurve { level: 0.0, points: p, normals, closed: false, singular_vertices: Vec::new() }
    }

    #[test]
    fn helices_are_geodesics_of_the_cylinder() {
        let curves = vec![helix(0.3, 200)];
        let measure = family_angles(&curves, Family::Geodesic, 0.1, 10.0).unwrap();
        assert!(measure.measured > 50);
        assert!(measure.max_error_degrees < 0.05, "{measure:?}");
        let off = family_angles(&curves, Family::PseudoGeodesic { theta_degrees: 60.0 }, 0.1, 10.0).unwrap();
        assert!((off.max_error_degrees - 30.0).abs() < 0.05, "{off:?}");
    }

    #[test]
    fn straight_rulings_are_degenerate_pseudo_geodesics_but_exact_geodesics() {
        let p: Vec<Vec3> = (0..50).map(|i| Vec3::new(1.0, 0.0, i as f64 * 0.1)).collect();
        let curve = LevelCurve { level: 0.0, normals: vec![Vec3::x(); p.len()], points: p, closed: false, singular_vertices: Vec::new() };
        let pg = family_angles(std::slice::from_ref(&curve), Family::PseudoGeodesic { theta_degrees: 60.0 }, 0.3, 10.0).unwrap();
        assert_eq!(pg.measured, 0);
        assert!(pg.straight > 10 && pg.straight_fraction() == 1.0);
        let geodesic = family_angles(&[curve], Family::Geodesic, 0.3, 10.0).unwrap();
        assert_eq!(geodesic.straight, 0);
        assert_eq!(geodesic.max_error_degrees, 0.0);
    }
}
