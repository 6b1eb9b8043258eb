//! The quality measures of Table 4, per strip and over a whole pattern.
use super::frenet::{discrete_binormals, unit_edges};
use super::unrolling::{straightness, Unrolling};
use super::surface_distance::{SurfacePoint, SurfaceProjector};
use crate::field::Family;
use crate::mesh::Vec3;
use serde::{Deserialize, Serialize};

/// Table 4 measures of one strip.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct StripMetrics {
    /// Max over inner vertices of `|θ_measured − θ|` in degrees, with `θ_measured` the signed angle
    /// `acos(sign(b·u) (b·n))` between the discrete binormal of the final polyline (Eq. 1) and the
    /// surface normal at the closest surface point (`u = n × t`, `t` the outer bisector); vertices
    /// where the polyline is straight (its circle through the neighbours larger than the surface's
    /// bounding-box diagonal) have no binormal and are left out.
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
    /// Max over the quads of the error of the strip's own angle: the quad's plane should be
    /// the rectifying plane, whose normal makes the angle 90° − θ with the surface normal. The
    /// quad's in-plane direction across the centre line (`ê_j × N_j`, N the quad normal) is
    /// measured with the signed angle of Sec. 3.1 against the smooth surface normal at the quad.
    /// Unlike `max_diff_theta_degrees` it is defined where the centre line is straight.
    pub max_quad_angle_error_degrees: f64,
    /// The quad with that error (index along the strip) and its centre.
    pub worst_quad: usize,
    pub worst_quad_point: [f64; 3],
    /// Length of the longest ruling segment from the centre line to a boundary, over the strip width.
    pub max_ruling_over_width: f64,
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
    pub max_quad_angle_error_degrees: f64,
    pub max_ruling_over_width: f64,
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
            max_quad_angle_error_degrees: m.max_quad_angle_error_degrees.max(s.max_quad_angle_error_degrees),
            max_ruling_over_width: m.max_ruling_over_width.max(s.max_ruling_over_width),
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
    /// Offsets from the centre vertices to the left boundary along the rulings.
    pub offsets: &'a [Vec3],
    /// The strip width.
    pub width: f64,
}

/// A strip as its centre line, unit rulings, boundary offsets (centre to the boundary on the
/// rulings' side) and flat unrolling, before it is placed against the surface.
pub struct StripShape<'a> {
    pub centre: &'a [Vec3],
    pub rulings: &'a [Vec3],
    pub offsets: &'a [Vec3],
    pub unrolling: &'a Unrolling,
    pub width: f64,
}

impl StripMetrics {
    /// The measures of `shape` against the surface `projector` projects onto (normals and
    /// distances at the centre points' closest points; a point that cannot be projected, i.e.
    /// a non-finite one, counts as infinitely far).
    pub fn on_surface(projector: &SurfaceProjector, shape: &StripShape, theta_degrees: f64, diagonal: f64) -> StripMetrics {
        let unprojected = |p: &Vec3| SurfacePoint { point: *p, normal: Vec3::z(), distance: f64::INFINITY };
        let surface: Vec<SurfacePoint> = shape.centre.iter().map(|p| projector.project(p).unwrap_or_else(|| unprojected(p))).collect();
        let normals: Vec<Vec3> = surface.iter().map(|s| s.normal).collect();
        let distances: Vec<f64> = surface.iter().map(|s| s.distance).collect();
        let geometry = StripGeometry {
            centre: shape.centre,
            rulings: shape.rulings,
            normals: &normals,
            distances: &distances,
            unrolling: shape.unrolling,
            offsets: shape.offsets,
            width: shape.width,
        };
        StripMetrics::measure(&geometry, theta_degrees, diagonal)
    }

    /// The Table 4 measures of a strip lying at `strip`, for the family of target angle
    /// `theta_degrees` ([`Family::from_theta`]: at 0°, 90° and 180° the quad angle has no sign);
    /// `appro_percent` relates the distances to `diagonal` (the surface's bounding-box diagonal).
    pub fn measure(strip: &StripGeometry, theta_degrees: f64, diagonal: f64) -> StripMetrics {
        let family = Family::from_theta(theta_degrees);
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
            // Where the centre line is straight at the model's scale its binormal is noise: the
            // quad-plane measure below covers such stretches.
            let (incoming, outgoing) = (strip.centre[i] - strip.centre[i - 1], strip.centre[i + 1] - strip.centre[i]);
            let lengths = incoming.norm() * outgoing.norm() * (incoming + outgoing).norm();
            if incoming.cross(&outgoing).norm() * 2.0 * diagonal <= lengths {
                continue;
            }
            let n = strip.normals[i];
            let Some(u) = n.cross(&(edges[i - 1] + edges[i])).try_normalize(0.0) else { continue };
            let sign = if b.dot(&u) < 0.0 { -1.0 } else { 1.0 };
            let measured = (sign * b.dot(&n)).clamp(-1.0, 1.0).acos().to_degrees();
            metrics.max_diff_theta_degrees = metrics.max_diff_theta_degrees.max(family.angle_error_degrees(measured, theta_degrees));
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
            if let Some(error) = quad_angle_error(e, &quad_normal, &(strip.normals[j] + strip.normals[j + 1]), family, theta_degrees) {
                if error > metrics.max_quad_angle_error_degrees || j == 0 {
                    metrics.max_quad_angle_error_degrees = metrics.max_quad_angle_error_degrees.max(error);
                    let centre = (strip.centre[j] + strip.centre[j + 1]) * 0.5;
                    metrics.worst_quad = j;
                    metrics.worst_quad_point = [centre.x, centre.y, centre.z];
                }
            }
        }
        if strip.width > 0.0 {
            metrics.max_ruling_over_width = strip.offsets.iter().map(|o| o.norm()).fold(0.0, f64::max) / strip.width;
        }
        metrics
    }
}

/// The error in degrees of a quad's angle: its in-plane direction across the centre line,
/// `b = ê × N̂`, against the surface normal `n` (unnormalised sums are fine), with the signed
/// angle of Sec. 3.1 (`u = n × ê`); `None` for a degenerate quad.
fn quad_angle_error(edge: &Vec3, quad_normal: &Vec3, normal: &Vec3, family: Family, theta_degrees: f64) -> Option<f64> {
    let n = normal.try_normalize(0.0)?;
    let b = edge.cross(&quad_normal.try_normalize(0.0)?).try_normalize(0.0)?;
    let u = n.cross(edge).try_normalize(0.0)?;
    let sign = if b.dot(&u) < 0.0 { -1.0 } else { 1.0 };
    let measured = (sign * b.dot(&n)).clamp(-1.0, 1.0).acos().to_degrees();
    Some(family.angle_error_degrees(measured, theta_degrees))
}
