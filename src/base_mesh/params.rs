//! What a base-mesh optimisation aims at (paper Sec. 3.5, 5.2.1): the family of each polyline
//! direction, whether the nodes must be torsion-free (Eq. 21), and the weights.

use super::error::BaseMeshError;
use crate::field::Family;
use crate::mesh::Vec3;
use crate::solver::LmOptions;
use serde::{Deserialize, Serialize};

/// The weights of the terms, on the net scaled to mean segment length 1.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct BaseMeshWeights {
    /// The curve conditions: vertex normals (`n·t₁ = n·t₂ = 0`, `‖n‖ = 1`), binormals
    /// (`b·e = 0` on both segments, `‖b‖ = 1`) and each family's own rows (P: Eq. 8–10 with `n`
    /// a variable; G: `n·b = 0`; A: `n·e = 0`). Default 1.
    pub curve: f64,
    /// Fairness `‖v_back − 2v + v_front‖²` along each polyline. Default 1e-3 (Table 3).
    pub fair: f64,
    /// Closeness: the distance `(v − v*)·n*` to the reference surface along its normal at the
    /// closest point `v*` (and, past the reference's boundary, the tangential offset). Default 1.
    pub close: f64,
    /// The pull `‖v − v_start‖²` to the start positions. Default 1e-4.
    pub pull: f64,
    /// The torsion-free node rows of Eq. 21 (only with [`BaseMeshParams::torsion_free`]). Default 1.
    pub torsion: f64,
}

impl Default for BaseMeshWeights {
    fn default() -> Self {
        BaseMeshWeights { curve: 1.0, fair: 1e-3, close: 1.0, pull: 1e-4, torsion: 1.0 }
    }
}

/// Parameters of a base-mesh optimisation.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct BaseMeshParams {
    /// The family of the rows and of the columns, and of a web's diagonals (taken by name,
    /// [`Family::by_name`]): pseudo-geodesic, geodesic, asymptotic, or of constant slope against
    /// an axis with a fixed slope (Sec. 5.2.3: two such families about one axis make a net whose
    /// node axes are all parallel to it, torsion-free). Two for a net, three for a web.
    pub families: Vec<Family>,
    /// Ask for torsion-free nodes (Eq. 21): a common ruling at every node, in the rectifying
    /// plane of both polylines, and developable strips between consecutive rulings (nets of two
    /// families only).
    pub torsion_free: bool,
    /// With torsion-free nodes: optimise the families alone until they settle, then add the
    /// rows of Eq. 21 (default, `true`); `false` puts them on from the first iteration.
    pub families_first: bool,
    pub weights: BaseMeshWeights,
    /// A family counts as met when every measured vertex is within this many degrees of its
    /// angle (the verdict of the report). Default 1°.
    pub tolerance_degrees: f64,
    /// Converged when an iteration lowers the energy by less than this fraction. Default 1e-6.
    pub relative_tolerance: f64,
    /// Levenberg–Marquardt settings.
    pub lm: LmOptions,
}

impl BaseMeshParams {
    /// Defaults for the rows' family `rows` and the columns' family `columns`.
    pub fn new(rows: Family, columns: Family) -> BaseMeshParams {
        BaseMeshParams {
            families: vec![rows.by_name(), columns.by_name()],
            torsion_free: false,
            families_first: true,
            weights: BaseMeshWeights::default(),
            tolerance_degrees: 1.0,
            relative_tolerance: 1e-6,
            lm: LmOptions::default(),
        }
    }

    /// Defaults for a 3-web (Table 1's AAG, AGG, PPG, …): the families of its rows, columns and
    /// diagonals.
    pub fn web(rows: Family, columns: Family, diagonals: Family) -> BaseMeshParams {
        BaseMeshParams { families: vec![rows.by_name(), columns.by_name(), diagonals.by_name()], ..BaseMeshParams::new(rows, columns) }
    }

    /// Checks every parameter, naming the first one out of range.
    pub fn validate(&self) -> Result<(), BaseMeshError> {
        let invalid = |name: &'static str, message: String| Err(BaseMeshError::InvalidParameter { name, message });
        if !(2..=3).contains(&self.families.len()) {
            return invalid("families", format!("a net has two families and a web three, got {}", self.families.len()));
        }
        if self.torsion_free && self.families.len() == 3 {
            return invalid("torsion_free", "torsion-free nodes (Eq. 21) are held for nets of two families only, not for a web".into());
        }
        for family in &self.families {
            match family.by_name() {
                Family::PseudoGeodesic { theta_degrees } if !(theta_degrees.is_finite() && theta_degrees > 0.0 && theta_degrees < 180.0) => {
                    return invalid("families", format!("a pseudo-geodesic angle must lie in [0°, 180°], got {theta_degrees}"));
                }
                Family::ConstantSlope { free_slope: true, .. } => {
                    return invalid("families", "the base-mesh optimisation holds constant-slope families with a fixed slope only".into());
                }
                Family::ConstantSlope { axis, slope_degrees, .. } => {
                    if !(axis.iter().all(|a| a.is_finite()) && Vec3::from(axis).norm() > 0.0) {
                        return invalid("families", format!("a constant-slope axis must be finite and non-zero, got {axis:?}"));
                    }
                    if !(slope_degrees.is_finite() && slope_degrees.abs() < 90.0) {
                        return invalid("families", format!("a slope must lie in (−90°, 90°), got {slope_degrees}"));
                    }
                }
                _ => {}
            }
        }
        let w = &self.weights;
        for (name, value) in [("weights.curve", w.curve), ("weights.fair", w.fair), ("weights.close", w.close), ("weights.pull", w.pull), ("weights.torsion", w.torsion)] {
            if !(value.is_finite() && value >= 0.0) {
                return invalid(name, format!("must be finite and ≥ 0, got {value}"));
            }
        }
        if w.curve <= 0.0 {
            return invalid("weights.curve", "must be > 0".into());
        }
        if self.torsion_free && w.torsion <= 0.0 {
            return invalid("weights.torsion", "must be > 0 for torsion-free nodes".into());
        }
        if !(self.tolerance_degrees.is_finite() && self.tolerance_degrees > 0.0 && self.tolerance_degrees < 90.0) {
            return invalid("tolerance_degrees", format!("must lie in (0°, 90°), got {}", self.tolerance_degrees));
        }
        if !(self.relative_tolerance.is_finite() && (0.0..1.0).contains(&self.relative_tolerance)) {
            return invalid("relative_tolerance", format!("must lie in [0, 1), got {}", self.relative_tolerance));
        }
        crate::field::validate_lm(&self.lm).map_err(|e| match e {
            crate::field::FieldError::InvalidParameter { name, message } => BaseMeshError::InvalidParameter { name, message },
            other => BaseMeshError::InvalidParameter { name: "lm", message: other.to_string() },
        })
    }
}
