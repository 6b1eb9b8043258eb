//! Candidate parameters of the quadratic angle equation Eq. 4 along an edge: its real roots,
//! or the extremum where the parabola only nearly touches
//! zero (double roots lost to rounding, and the asymptotic case θ → 0 whose cone degenerates).

/// Relative size below which a leading coefficient counts as zero.
const NEGLIGIBLE: f64 = 1e-12;
/// A discriminant below this fraction of `b²` is a double root split by rounding (e.g. a
/// straight continuation across coplanar faces, where Eq. 4 degenerates to `‖N(t)‖² = 0`).
const DOUBLE_ROOT: f64 = 1e-12;

/// Up to two parameters `t` of `a·t² + b·t + c`: its two real roots; for a (nearly) double
/// root or no real root, the extremum `−b / 2a` (the caller accepts it only if the angle it
/// realises is within tolerance).
/// A degree-one polynomial gives its root; a constant gives nothing.
pub(crate) fn candidate_parameters(a: f64, b: f64, c: f64) -> Vec<f64> {
    let scale = a.abs().max(b.abs()).max(c.abs());
    if !(a.is_finite() && b.is_finite() && c.is_finite() && scale > 0.0) {
        return Vec::new();
    }
    let (a, b, c) = (a / scale, b / scale, c / scale);
    if a.abs() <= NEGLIGIBLE {
        return if b.abs() > NEGLIGIBLE { vec![-c / b] } else { Vec::new() };
    }
    let discriminant = b * b - 4.0 * a * c;
    if discriminant <= DOUBLE_ROOT * b * b {
        return vec![-b / (2.0 * a)];
    }
    // Numerically stable pair: q = −(b + sign(b)·√D)/2, roots q/a and c/q.
    let q = -0.5 * (b + b.signum() * discriminant.sqrt());
    if q == 0.0 {
        return vec![0.0];
    }
    vec![q / a, c / q]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn roots_extrema_and_degenerate_cases() {
        let mut roots = candidate_parameters(1.0, -3.0, 2.0);
        roots.sort_by(f64::total_cmp);
        assert!((roots[0] - 1.0).abs() < 1e-15 && (roots[1] - 2.0).abs() < 1e-15);
        assert_eq!(candidate_parameters(1.0, -2.0, 1.0 + 1e-9), vec![1.0]);
        assert_eq!(candidate_parameters(1.0, -2.0, 1.0 - 1e-15), vec![1.0]);
        assert_eq!(candidate_parameters(0.0, 2.0, -1.0), vec![0.5]);
        assert!(candidate_parameters(0.0, 0.0, 1.0).is_empty());
        assert!(candidate_parameters(0.0, 0.0, 0.0).is_empty());
        assert!(candidate_parameters(f64::NAN, 1.0, 1.0).is_empty());
        let tiny = candidate_parameters(1e-300, -3e-300, 2e-300);
        assert!(tiny.iter().any(|t| (t - 1.0).abs() < 1e-12));
    }
}
