//! Rectifying strips along the level curves of a shading field. A shading field's curves are not
//! pseudo-geodesics of one angle: each curve gets its own angle θ, the median over its points of
//! the signed angle between the optimised binormal `b` (interpolated from the vertices) and the
//! surface normal, and its strip is built by [`rectifying_strips`] for that θ (Sec. 3.4). On a
//! straight curve this θ is what fixes the strip's plane (the rectifying plane `span(t, b)`).

use super::error::ShadingError;
use crate::curves::{extract_level_curves, resample_all, uniform_levels, LevelCurve};
use crate::mesh::{FaceBvh, TriMesh, Vec3};
use crate::strips::{rectifying_strips, PatternMetrics, StripParams, StripPattern, Verdict, MAX_APPRO_PERCENT};

/// The strips of a shading design.
#[derive(Clone, Debug)]
pub struct ShadingStrips {
    /// The resampled level curves.
    pub curves: Vec<LevelCurve>,
    /// θ of each curve in degrees (`None` where no binormal reaches it).
    pub thetas: Vec<Option<f64>>,
    /// The strips (their `curve` indexes `curves`), metrics and verdict over all of them.
    pub pattern: StripPattern,
}

impl ShadingStrips {
    /// What the strips miss (one line), `None` when they are acceptable: how many miss their
    /// curve's θ by more than the tolerance, have flipped quads or leave the surface, and the
    /// worst quad.
    pub fn miss(&self) -> Option<String> {
        let verdict = &self.pattern.verdict;
        if verdict.is_acceptable() {
            return None;
        }
        if verdict.empty {
            return Some("no strip could be built".to_string());
        }
        let mut parts = Vec::new();
        if !verdict.strips_missing_theta.is_empty() {
            let n = verdict.strips_missing_theta.len();
            let (noun, verb) = if n == 1 { ("strip", "misses its") } else { ("strips", "miss their") };
            parts.push(format!("{n} {noun} {verb} curve's θ by more than {}°", verdict.tolerance_degrees));
        }
        if !verdict.strips_with_flipped_quads.is_empty() {
            let n = verdict.strips_with_flipped_quads.len();
            parts.push(format!("{n} {}", if n == 1 { "strip has flipped quads" } else { "strips have flipped quads" }));
        }
        if !verdict.strips_off_surface.is_empty() {
            let n = verdict.strips_off_surface.len();
            parts.push(format!("{n} {} the surface by more than {MAX_APPRO_PERCENT} % of its diagonal", if n == 1 { "strip leaves" } else { "strips leave" }));
        }
        let worst = verdict.worst.map_or(String::new(), |w| {
            format!(" (worst: strip {} quad {} at ({:.3}, {:.3}, {:.3}), {:.2}° off)", w.strip, w.quad, w.point[0], w.point[1], w.point[2], w.error_degrees)
        });
        Some(format!("{}{worst}", parts.join(", ")))
    }
}

/// Strips along `count` equally spaced level curves of `field` with per-vertex `binormals`
/// ([`super::ShadingSolver::binormals`]; zero where undefined), of `width`, judged
/// with `tolerance_degrees` (the strips' verdict). Errors name the parameter.
pub fn shading_strips(mesh: &TriMesh, field: &[f64], binormals: &[Vec3], count: usize, width: f64, tolerance_degrees: f64) -> Result<ShadingStrips, ShadingError> {
    if binormals.len() != mesh.vertex_count() {
        return Err(ShadingError::invalid("binormals", format!("{} binormals for {} vertices", binormals.len(), mesh.vertex_count())));
    }
    let curve_error = |e: crate::curves::CurveError| ShadingError::invalid("field", format!("level curves: {e}"));
    let levels = uniform_levels(mesh, field, count).map_err(curve_error)?;
    let curves = extract_level_curves(mesh, field, &levels).map_err(curve_error)?;
    let curves = resample_all(&curves, mesh.mean_edge_length()).map_err(curve_error)?;
    let bvh = FaceBvh::new(mesh);
    let thetas: Vec<Option<f64>> = curves.iter().map(|c| curve_theta(mesh, &bvh, binormals, c)).collect();
    let mut pattern = StripPattern { strips: Vec::new(), skipped: Vec::new(), metrics: PatternMetrics::default(), verdict: Verdict::default() };
    for (index, (curve, theta)) in curves.iter().zip(&thetas).enumerate() {
        let Some(theta) = theta else { continue };
        let params = StripParams { tolerance_degrees, ..StripParams::new(*theta, width) };
        let one = rectifying_strips(mesh, std::slice::from_ref(curve), &params).map_err(|e| ShadingError::invalid("strips", e.to_string()))?;
        pattern.strips.extend(one.strips.into_iter().map(|mut s| {
            s.curve = index;
            s
        }));
        pattern.skipped.extend(one.skipped.into_iter().map(|mut s| {
            s.curve = index;
            s
        }));
    }
    pattern.metrics = PatternMetrics::from_strips(pattern.strips.iter().map(|s| &s.metrics));
    pattern.verdict = Verdict::judge(&pattern.strips, tolerance_degrees);
    Ok(ShadingStrips { curves, thetas, pattern })
}

/// The median over the curve's points of `atan2(b·u, b·n)` (`u = n × t`, `b` turned to `b·u ≥ 0`),
/// in [0°, 180°]; `None` where no point has a binormal.
fn curve_theta(mesh: &TriMesh, bvh: &FaceBvh, binormals: &[Vec3], curve: &LevelCurve) -> Option<f64> {
    let points = &curve.points;
    let mut angles: Vec<f64> = (0..points.len())
        .filter_map(|i| {
            let t = (points[(i + 1).min(points.len() - 1)] - points[i.saturating_sub(1)]).try_normalize(0.0)?;
            let n = curve.normals[i];
            let u = n.cross(&t);
            let hit = bvh.closest(mesh, &points[i])?;
            let corners = mesh.faces()[hit.face].map(|v| binormals[v as usize]);
            // Binormals are lines: align the corners' signs before interpolating.
            let reference = corners.iter().find(|b| b.norm_squared() > 0.0)?;
            let b: Vec3 = corners.iter().zip(hit.weights).map(|(b, w)| if b.dot(reference) < 0.0 { -b * w } else { b * w }).sum();
            let b = b.try_normalize(1e-9)?;
            let b = if b.dot(&u) < 0.0 { -b } else { b };
            Some(b.dot(&u).atan2(b.dot(&n)).to_degrees())
        })
        .collect();
    if angles.is_empty() {
        return None;
    }
    angles.sort_by(f64::total_cmp);
    Some(angles[angles.len() / 2])
}
