//! The flat unrolling of a strip of planar quads (Fig. 20) and its straightness `e_straight`
//! (Table 4).
//!
//! Quad `j` spans the rulings at `c_j` and `c_{j+1}`; its intrinsic angles are `α_j⁺ = ∠(d_j, e_j)`
//! and `α_{j+1}⁻ = ∠(d_{j+1}, −e_j)`. Laying the quads out one after another, each isometrically,
//! turns the centre line at vertex `i` by `π − (α_i⁻ + α_i⁺)`: exactly straight when the rulings
//! lie in the outer bisecting planes (Eq. 16).
use crate::mesh::Vec3;

/// A strip laid flat: 2D centre line and boundaries, one point per polyline vertex.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Unrolling {
    pub centre: Vec<[f64; 2]>,
    /// Boundary on the side the rulings point to.
    pub left: Vec<[f64; 2]>,
    pub right: Vec<[f64; 2]>,
    /// Length of the centre line (equal in 3D and in the plane).
    pub length: f64,
}

impl Unrolling {
    /// The flat strip's width: the mean distance between its two boundaries, measured across the
    /// centre line's end-to-end direction (0 for a strip of fewer than two points).
    pub fn width(&self) -> f64 {
        let (Some(first), Some(last)) = (self.centre.first(), self.centre.last()) else { return 0.0 };
        let (dx, dy) = (last[0] - first[0], last[1] - first[1]);
        let length = dx.hypot(dy);
        if !(length > 0.0) || self.left.is_empty() {
            return 0.0;
        }
        let across = |p: &[f64; 2], q: &[f64; 2]| ((p[0] - q[0]) * -dy + (p[1] - q[1]) * dx).abs() / length;
        self.left.iter().zip(&self.right).map(|(l, r)| across(l, r)).sum::<f64>() / self.left.len() as f64
    }
}

fn angle(a: &Vec3, b: &Vec3) -> f64 {
    a.cross(b).norm().atan2(a.dot(b))
}

fn rotate(v: [f64; 2], angle: f64) -> [f64; 2] {
    let (s, c) = angle.sin_cos();
    [c * v[0] - s * v[1], s * v[0] + c * v[1]]
}

/// Unrolls the strip with centre line `centre` and boundary points `centre[i] ± offsets[i]`
/// (`offsets[i]` along the ruling at `c_i`). Needs at least 2 points; fewer give an empty unrolling.
pub fn unroll(centre: &[Vec3], offsets: &[Vec3]) -> Unrolling {
    let n = centre.len().min(offsets.len());
    if n < 2 {
        return Unrolling::default();
    }
    let mut out = Unrolling::default();
    let mut point = [0.0, 0.0];
    let mut direction = [1.0, 0.0];
    for i in 0..n {
        // The ruling's direction in the plane: measured from the outgoing edge (from the incoming
        // one at the last vertex).
        let ruling = if i + 1 < n {
            rotate(direction, angle(&offsets[i], &(centre[i + 1] - centre[i])))
        } else {
            rotate(direction, std::f64::consts::PI - angle(&offsets[i], &(centre[i - 1] - centre[i])))
        };
        let reach = offsets[i].norm();
        out.centre.push(point);
        out.left.push([point[0] + reach * ruling[0], point[1] + reach * ruling[1]]);
        out.right.push([point[0] - reach * ruling[0], point[1] - reach * ruling[1]]);
        if i + 1 < n {
            let edge = centre[i + 1] - centre[i];
            let length = edge.norm();
            point = [point[0] + length * direction[0], point[1] + length * direction[1]];
            out.length += length;
            if i + 2 < n {
                let before = angle(&offsets[i + 1], &-edge);
                let after = angle(&offsets[i + 1], &(centre[i + 2] - centre[i + 1]));
                direction = rotate(direction, std::f64::consts::PI - before - after);
            }
        }
    }
    out
}

/// Largest distance of 2D points from their principal (least-squares) line, divided by `length`
/// (0 for fewer than 2 points or a zero length).
pub fn straightness(points: &[[f64; 2]], length: f64) -> f64 {
    if points.len() < 2 || length.is_nan() || length <= 0.0 {
        return 0.0;
    }
    let n = points.len() as f64;
    let mean = points.iter().fold([0.0, 0.0], |m, p| [m[0] + p[0] / n, m[1] + p[1] / n]);
    let (mut sxx, mut sxy, mut syy) = (0.0, 0.0, 0.0);
    for p in points {
        let (x, y) = (p[0] - mean[0], p[1] - mean[1]);
        sxx += x * x;
        sxy += x * y;
        syy += y * y;
    }
    let axis = 0.5 * (2.0 * sxy).atan2(sxx - syy);
    let (dx, dy) = (axis.cos(), axis.sin());
    points.iter().map(|p| ((p[0] - mean[0]) * dy - (p[1] - mean[1]) * dx).abs()).fold(0.0, f64::max) / length
}
