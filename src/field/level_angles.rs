//! The angle a family actually achieves, level by level (Fig. 16, bottom left): the signed angle
//! between the binormal and the surface normal measured along extracted level curves.
//!
//! Each level curve (see [`crate::curves::extract_level_curves`]) is resampled at equal arc-length
//! steps first, so that the discrete binormal `(p_i − p_{i−1}) × (p_{i+1} − p_i)` is taken over
//! chords of a chosen length rather than over the arbitrarily short pieces between mesh edges.
//! End points of open curves have no binormal and are skipped.

use super::darboux::LevelFrame;
use crate::curves::{extract_level_curves, CurveError, LevelCurve};
use crate::mesh::{TriMesh, Vec3};
use serde::{Deserialize, Serialize};

/// Below this `‖chord × chord‖` (relative to the squared spacing) the polyline is straight at a point.
const STRAIGHT: f64 = 1e-12;

/// Angles measured along the level curves of one level value.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct LevelAngles {
    pub level: f64,
    /// Number of points measured along the level's curves.
    pub samples: usize,
    /// Smallest, largest and mean signed angle in degrees; `None` when no point was measured.
    pub range: Option<AngleRange>,
}

/// Smallest, largest and mean of a set of angles in degrees.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct AngleRange {
    pub min_degrees: f64,
    pub max_degrees: f64,
    pub mean_degrees: f64,
}

/// The angles along the level curves of `field` at each of `levels`, measured at points resampled
/// `spacing` apart (in the mesh's length units). Errors are those of the curve extraction and
/// resampling (field length, non-finite or out-of-range levels, invalid spacing).
pub fn level_angles(mesh: &TriMesh, field: &[f64], levels: &[f64], spacing: f64) -> Result<Vec<LevelAngles>, CurveError> {
    let curves = extract_level_curves(mesh, field, levels)?;
    let mut out = Vec::with_capacity(levels.len());
    for &level in levels {
        let mut angles = Vec::new();
        // Curves come level by level, each carrying its exact level value.
        for curve in curves.iter().filter(|c| c.level == level) {
            curve_angles(&curve.resampled(spacing)?, &mut angles);
        }
        out.push(LevelAngles { level, samples: angles.len(), range: AngleRange::of(&angles) });
    }
    Ok(out)
}

impl AngleRange {
    fn of(angles: &[f64]) -> Option<AngleRange> {
        if angles.is_empty() {
            return None;
        }
        Some(AngleRange {
            min_degrees: angles.iter().copied().fold(f64::INFINITY, f64::min),
            max_degrees: angles.iter().copied().fold(f64::NEG_INFINITY, f64::max),
            mean_degrees: angles.iter().sum::<f64>() / angles.len() as f64,
        })
    }
}

/// Appends the signed angle at every point of `curve` that has two neighbours and a defined binormal.
fn curve_angles(curve: &LevelCurve, angles: &mut Vec<f64>) {
    let n = curve.points.len();
    if n < 3 || curve.normals.len() != n {
        return;
    }
    let inner = if curve.closed { 0..n } else { 1..n - 1 };
    for i in inner {
        let (prev, next) = ((i + n - 1) % n, (i + 1) % n);
        let (a, b, c) = (curve.points[prev], curve.points[i], curve.points[next]);
        if let Some(angle) = point_angle(a, b, c, curve.normals[i]) {
            angles.push(angle);
        }
    }
}

/// The signed angle at `b` of the polyline `a → b → c` with surface normal `normal`.
fn point_angle(a: Vec3, b: Vec3, c: Vec3, normal: Vec3) -> Option<f64> {
    let (incoming, outgoing) = (b - a, c - b);
    let scale = incoming.norm() * outgoing.norm();
    let cross = incoming.cross(&outgoing);
    let binormal = (cross.norm() > STRAIGHT * scale).then(|| cross.normalize());
    let tangent = (c - a).try_normalize(0.0)?;
    let side = normal.cross(&tangent).try_normalize(0.0)?;
    LevelFrame { tangent, normal, side, binormal }.signed_angle_degrees()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_circle_on_a_sphere_has_the_angle_of_its_plane() {
        // The circle z = R cos ψ on the sphere of radius R: binormal ±z, normal p/R, so
        // cos θ = ±cos ψ; the side vector n × t points toward the pole when the circle runs
        // counter-clockwise seen from +z, and then θ = ψ.
        let (radius, psi) = (2.0_f64, 0.6_f64);
        let count = 40;
        let points: Vec<Vec3> = (0..count)
            .map(|i| {
                let phi = std::f64::consts::TAU * i as f64 / count as f64;
                Vec3::new(radius * psi.sin() * phi.cos(), radius * psi.sin() * phi.sin(), radius * psi.cos())
            })
            .collect();
        let normals = points.iter().map(|p| p / radius).collect();
        let curve = LevelCurve { level: 0.0, points, normals, closed: true, singular_vertices: vec![] };
        let mut angles = Vec::new();
        curve_angles(&curve, &mut angles);
        assert_eq!(angles.len(), count);
        for angle in angles {
            assert!((angle - psi.to_degrees()).abs() < 1e-9, "{angle}° vs {}°", psi.to_degrees());
        }
    }
}
