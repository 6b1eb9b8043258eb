//! The angle assignment function `θ(F)` of the varying-angle families (Sec. 3.2, Fig. 16): a
//! polynomial of degree 3 fitted by least squares to the data `(F_v, θ_v)` measured at the
//! vertices.

use nalgebra::{Matrix4, Vector4};
use serde::{Deserialize, Serialize};

/// `θ(F) = c0 + c1 s + c2 s² + c3 s³` in degrees, with the field value normalised to
/// `s = (2F − F_min − F_max)/(F_max − F_min)`, so that `s ∈ [−1, 1]` over the range of the field
/// the profile was fitted to (this keeps the fit well conditioned whatever the field's scale).
/// Outside that range the cubic is extrapolated.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct AngleProfile {
    coefficients: [f64; 4],
    field_min: f64,
    /// `> field_min` (checked by `fit`, the only constructor).
    field_max: f64,
}

impl AngleProfile {
    /// The least-squares cubic through the samples `(F, θ in degrees)`. `None` unless the samples
    /// are finite and hold at least four distinct field values (otherwise the cubic is not unique).
    pub fn fit(samples: &[(f64, f64)]) -> Option<AngleProfile> {
        if samples.iter().any(|(f, theta)| !(f.is_finite() && theta.is_finite())) {
            return None;
        }
        let field_min = samples.iter().map(|s| s.0).fold(f64::INFINITY, f64::min);
        let field_max = samples.iter().map(|s| s.0).fold(f64::NEG_INFINITY, f64::max);
        // The samples are finite here, so the range is empty exactly when max ≤ min.
        if field_max <= field_min {
            return None;
        }
        let frame = AngleProfile { coefficients: [0.0; 4], field_min, field_max };
        // Normal equations in the normalised variable, accumulated in sample order.
        let mut normal = Matrix4::zeros();
        let mut rhs = Vector4::zeros();
        for &(f, theta) in samples {
            let powers = frame.powers(f);
            normal += powers * powers.transpose();
            rhs += powers * theta;
        }
        let c = normal.cholesky()?.solve(&rhs);
        let profile = AngleProfile { coefficients: [c[0], c[1], c[2], c[3]], ..frame };
        // Fewer than four distinct values make the normal matrix singular up to rounding; the
        // Cholesky factor may then still exist with a meaningless, huge solution.
        let distinct = count_distinct(samples.iter().map(|s| s.0));
        (distinct >= 4 && profile.coefficients.iter().all(|c| c.is_finite())).then_some(profile)
    }

    /// `c0..c3` in degrees.
    pub fn coefficients(&self) -> [f64; 4] {
        self.coefficients
    }

    /// `(F_min, F_max)`: the range of the fitted samples' field values, mapped to `s ∈ [−1, 1]`.
    pub fn field_range(&self) -> (f64, f64) {
        (self.field_min, self.field_max)
    }

    /// `θ(F)` in degrees.
    pub fn evaluate(&self, field_value: f64) -> f64 {
        let [c0, c1, c2, c3] = self.coefficients;
        let s = self.normalized(field_value);
        c0 + s * (c1 + s * (c2 + s * c3))
    }

    /// `θ` at the same relative position `s` across the family when the field now spans
    /// `range` (its current minimum and maximum, `max > min`): the profile follows a relabelling
    /// of the level sets (a shift or scale of F) instead of sliding along them.
    pub fn evaluate_in(&self, field_value: f64, range: (f64, f64)) -> f64 {
        let (min, max) = range;
        let original = self.field_min + (field_value - min) / (max - min) * (self.field_max - self.field_min);
        self.evaluate(original)
    }

    /// The profile multiplied by `factor` (e.g. `1 − 5 %`, the lowering of Sec. 3.2).
    pub fn scaled(&self, factor: f64) -> AngleProfile {
        AngleProfile { coefficients: self.coefficients.map(|c| c * factor), ..*self }
    }

    fn normalized(&self, field_value: f64) -> f64 {
        (2.0 * field_value - self.field_min - self.field_max) / (self.field_max - self.field_min)
    }

    fn powers(&self, field_value: f64) -> Vector4<f64> {
        let s = self.normalized(field_value);
        Vector4::new(1.0, s, s * s, s * s * s)
    }
}

/// Number of distinct values (exact comparison).
fn count_distinct(values: impl Iterator<Item = f64>) -> usize {
    let mut sorted: Vec<f64> = values.collect();
    sorted.sort_by(f64::total_cmp);
    sorted.dedup();
    sorted.len()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn recovers_a_cubic_exactly() {
        let theta = |f: f64| 40.0 - 3.0 * f + 0.5 * f * f - 0.02 * f * f * f;
        let samples: Vec<(f64, f64)> = (0..30).map(|i| 10.0 + 0.37 * i as f64).map(|f| (f, theta(f))).collect();
        let profile = AngleProfile::fit(&samples).expect("enough samples");
        for f in [10.0, 12.3, 19.0, 20.73] {
            assert!((profile.evaluate(f) - theta(f)).abs() < 1e-9, "at {f}: {} vs {}", profile.evaluate(f), theta(f));
        }
        assert!((profile.scaled(0.95).evaluate(15.0) - 0.95 * theta(15.0)).abs() < 1e-9);
    }

    #[test]
    fn residuals_of_noisy_data_are_orthogonal_to_every_cubic() {
        // The least-squares optimality condition: Σ r_i F_i^k = 0 for k = 0..3.
        let samples: Vec<(f64, f64)> = (0..40).map(|i| (i as f64 * 0.1, 30.0 + if i % 3 == 0 { 2.0 } else { -1.3 } + 0.01 * i as f64)).collect();
        let profile = AngleProfile::fit(&samples).expect("enough samples");
        for k in 0..4 {
            let moment: f64 = samples.iter().map(|&(f, theta)| (theta - profile.evaluate(f)) * f.powi(k)).sum();
            let scale: f64 = samples.iter().map(|&(f, theta)| (theta * f.powi(k)).abs()).sum();
            assert!(moment.abs() < 1e-10 * scale, "moment {k}: {moment}");
        }
    }

    #[test]
    fn too_few_distinct_values_give_none() {
        let samples = [(1.0, 10.0), (2.0, 11.0), (3.0, 12.0), (3.0, 13.0), (1.0, 10.0)];
        assert_eq!(AngleProfile::fit(&samples), None);
        assert_eq!(AngleProfile::fit(&[(1.0, f64::NAN), (2.0, 1.0), (3.0, 1.0), (4.0, 1.0)]), None);
    }
}
