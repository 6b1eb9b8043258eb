//! The quality measures of Table 4, per strip and over a whole pattern.
use super::frenet::{discrete_binormals, unit_edges};
use super::unrolling::{straightness, Unrolling};
use crate::mesh::Vec3;
use serde::{Deserialize, Serialize};

/// Table 4 measures of one strip.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct StripMetrics {
    /// Max over inner vertices of `|θ_measured − θ|` in degrees, with `θ_measured` the signed angle
    /// `acos(sign(b·u) (b·n))` between the discrete binormal of the final polyline (Eq. 1) and the
    /// surface normal at the closest surface point (`u = n × t`, `t` the outer bisector).
    pub max_diff_theta_degrees: f64,
    /// Max distance of the unrolled centre points from their principal line, over the strip length.
    pub e_straight: f64,
    /// `E_planar = Σ det(d̂_j, d̂_{j+1}, ê_j)²` over the quads.
    pub e_planar: f64,
    /// `max |det(d̂_j, d̂_{j+1}, ê_j)|`: the per-quad planarity residual.
    pub max_planar: f64,
    /// Max distance of the base-curve vertices from the surface, in % of the surface's
    /// bounding-box diagonal.
    pub appro_percent: f64,
    /// Quads whose orientation flips (see [`super::StripWarning::FlippedQuads`]).
    pub flipped_quads: usize,
    /// Length of the centre line.
    pub length: f64,
}

/// Table 4 over all strips of a pattern: maxima, and the sum of `E_planar`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct PatternMetrics {
    /// |Strip|: the number of strips built.
    pub strip_count: usize,
    pub max_diff_theta_degrees: f64,
    pub max_e_straight: f64,
    pub e_planar: f64,
    pub max_planar: f64,
    pub appro_percent: f64,
    pub flipped_quads: usize,
}

impl PatternMetrics {
    /// Maxima (and the sum of `E_planar`) over the strips' metrics.
    pub fn from_strips<'a>(strips: impl Iterator<Item = &'a StripMetrics>) -> PatternMetrics {
        strips.fold(PatternMetrics::default(), |m, s| PatternMetrics {
            strip_count: m.strip_count + 1,
            max_diff_theta_degrees: m.max_diff_theta_degrees.max(s.max_diff_theta_degrees),
            max_e_straight: m.max_e_straight.max(s.e_straight),
            e_planar: m.e_planar + s.e_planar,
            max_planar: m.max_planar.max(s.max_planar),
            appro_percent: m.appro_percent.max(s.appro_percent),
            flipped_quads: m.flipped_quads + s.flipped_quads,
        })
    }
}

/// Where and how a strip lies, as the metrics need it.
pub struct StripGeometry<'a> {
    pub centre: &'a [Vec3],
    /// Unit rulings.
    pub rulings: &'a [Vec3],
    /// Unit surface normals at the closest surface points of the centre vertices.
    pub normals: &'a [Vec3],
    /// Distances of the centre vertices from the surface.
    pub distances: &'a [f64],
    pub unrolling: &'a Unrolling,
}

impl StripMetrics {
    /// The Table 4 measures of a strip lying at `strip`, for target angle `theta_degrees`;
    /// `appro_percent` relates the distances to `diagonal` (the surface's bounding-box diagonal).
    pub fn measure(strip: &StripGeometry, theta_degrees: f64, diagonal: f64) -> StripMetrics {
        let edges = unit_edges(strip.centre);
        let binormals = discrete_binormals(strip.centre);
        let mut metrics = StripMetrics {
            length: strip.unrolling.length,
            e_straight: straightness(&strip.unrolling.centre, strip.unrolling.length),
            appro_percent: 100.0 * strip.distances.iter().fold(0.0, |m: f64, &d| m.max(d)) / diagonal,
            ..StripMetrics::default()
        };
        for (i, b) in binormals.iter().enumerate() {
            let Some(b) = b else { continue };
            let n = strip.normals[i];
            let Some(u) = n.cross(&(edges[i - 1] + edges[i])).try_normalize(0.0) else { continue };
            let sign = if b.dot(&u) < 0.0 { -1.0 } else { 1.0 };
            let measured = (sign * b.dot(&n)).clamp(-1.0, 1.0).acos().to_degrees();
            metrics.max_diff_theta_degrees = metrics.max_diff_theta_degrees.max((measured - theta_degrees).abs());
        }
        let target = |i: usize| {
            let n = strip.normals[i];
            let t = edges[i.min(edges.len() - 1)];
            let (sin, cos) = theta_degrees.to_radians().sin_cos();
            n * cos + n.cross(&t) * sin
        };
        let mut previous_normal: Option<Vec3> = None;
        for (j, e) in edges.iter().enumerate() {
            let (d0, d1) = (strip.rulings[j], strip.rulings[j + 1]);
            let det = d0.dot(&d1.cross(e));
            metrics.e_planar += det * det;
            metrics.max_planar = metrics.max_planar.max(det.abs());
            let quad_normal = e.cross(&(d0 + d1));
            let flipped = d0.dot(&d1) <= 0.0
                || (d0 + d1).dot(&(target(j) + target(j + 1))) <= 0.0
                || previous_normal.is_some_and(|p| p.dot(&quad_normal) <= 0.0);
            metrics.flipped_quads += usize::from(flipped);
            previous_normal = Some(quad_normal);
        }
        metrics
    }
}
