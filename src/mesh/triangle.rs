//! Elementary geometry of one triangle: edges, cross product, corner angles and cotangents.

use super::Vec3;

/// The three corner positions of a face, in winding order.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Triangle(pub [Vec3; 3]);

/// Relative zero-area threshold: a face is degenerate when twice its area is at most this
/// factor times its longest edge squared.
const ZERO_AREA_RELATIVE: f64 = 1e-12;

impl Triangle {
    /// Corner positions of `face` (indices must be valid).
    pub(crate) fn of(positions: &[Vec3], face: &[u32; 3]) -> Triangle {
        // Internal invariant: the caller has validated the indices.
        Triangle(face.map(|i| positions[i as usize]))
    }

    /// The edge opposite corner `i`, oriented along the winding: p[i+2] − p[i+1].
    pub(crate) fn opposite_edge(&self, i: usize) -> Vec3 {
        self.0[(i + 2) % 3] - self.0[(i + 1) % 3]
    }

    /// (p1 − p0) × (p2 − p0): twice the area times the unit normal of the winding.
    pub(crate) fn cross(&self) -> Vec3 {
        (self.0[1] - self.0[0]).cross(&(self.0[2] - self.0[0]))
    }

    /// Unit normal of the winding and the area, scaled before normalising so that tiny or huge
    /// coordinates do not underflow or overflow the squared norm.
    pub(crate) fn normal_and_area(&self) -> (Vec3, f64) {
        let cross = self.cross();
        let norm = scaled_norm(&cross);
        (cross / norm, 0.5 * norm)
    }

    /// Dot product and cross-product norm of the two edges leaving corner `i`.
    fn corner_dot_and_sine(&self, i: usize) -> (f64, f64) {
        let a = self.0[(i + 1) % 3] - self.0[i];
        let b = self.0[(i + 2) % 3] - self.0[i];
        (a.dot(&b), scaled_norm(&a.cross(&b)))
    }

    /// Interior angle at corner `i`, in [0, π].
    pub(crate) fn corner_angle(&self, i: usize) -> f64 {
        let (dot, sine) = self.corner_dot_and_sine(i);
        sine.atan2(dot)
    }

    /// Cotangent of the interior angle at corner `i` (finite for non-degenerate faces).
    pub(crate) fn corner_cot(&self, i: usize) -> f64 {
        let (dot, sine) = self.corner_dot_and_sine(i);
        dot / sine
    }

    /// Whether the angle at corner `i` is obtuse (> 90°).
    pub(crate) fn is_obtuse_at(&self, i: usize) -> bool {
        self.corner_dot_and_sine(i).0 < 0.0
    }

    /// Zero-length edge, or twice the area ≤ 1e-12 × (longest edge)².
    ///
    /// Scale invariant: the edges are computed from halved coordinates (no overflow) and
    /// divided by their largest component before the test (no underflow). NaN counts as degenerate.
    pub(crate) fn is_degenerate(&self) -> bool {
        let half = self.0.map(|p| p * 0.5);
        let edges = [half[1] - half[0], half[2] - half[1], half[0] - half[2]];
        if edges.iter().any(|e| e.iter().all(|&c| c == 0.0)) {
            return true;
        }
        let scale = edges.iter().map(|e| e.amax()).fold(0.0, f64::max);
        if !(scale > 0.0 && scale.is_finite()) {
            return true;
        }
        let [u, v, w] = edges.map(|e| e / scale);
        let longest_sq = u.norm_squared().max(v.norm_squared()).max(w.norm_squared());
        let twice_area = u.cross(&(-w)).norm();
        let threshold = ZERO_AREA_RELATIVE * longest_sq;
        twice_area.is_nan() || threshold.is_nan() || twice_area <= threshold
    }
}

/// Euclidean norm computed as max|v_i| · ‖v / max|v_i|‖ (no intermediate under- or overflow).
fn scaled_norm(v: &Vec3) -> f64 {
    let scale = v.amax();
    if scale > 0.0 {
        scale * (v / scale).norm()
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn degeneracy_is_scale_invariant() {
        let t = |s: f64| {
            Triangle([Vec3::zeros(), Vec3::new(s, 0.0, 0.0), Vec3::new(0.0, s, 0.0)])
        };
        for s in [1e-300, 1e-150, 1.0, 1e150, 1e300] {
            assert!(!t(s).is_degenerate(), "scale {s}");
        }
        let flat = Triangle([Vec3::zeros(), Vec3::new(1.0, 0.0, 0.0), Vec3::new(2.0, 1e-13, 0.0)]);
        assert!(flat.is_degenerate());
        let nan = Triangle([Vec3::zeros(), Vec3::new(f64::NAN, 0.0, 0.0), Vec3::new(0.0, 1.0, 0.0)]);
        assert!(nan.is_degenerate());
    }

    #[test]
    fn right_isoceles_angles_and_cotangents() {
        let t = Triangle([Vec3::zeros(), Vec3::new(1.0, 0.0, 0.0), Vec3::new(0.0, 1.0, 0.0)]);
        assert!((t.corner_angle(0) - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
        assert!((t.corner_angle(1) - std::f64::consts::FRAC_PI_4).abs() < 1e-15);
        assert!((t.corner_cot(1) - 1.0).abs() < 1e-15);
        assert!(t.corner_cot(0).abs() < 1e-15);
        assert!(!t.is_obtuse_at(0));
    }
}
