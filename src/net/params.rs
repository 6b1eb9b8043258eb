//! What a net optimisation aims at (paper Sec. 4.1): one curve family per field, the weights of
//! each field's terms (Eq. 12) and of the intersection-angle term between them.

use crate::field::{Family, FieldError, FieldParams};
use serde::{Deserialize, Serialize};

/// Parameters of a net of two families.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct NetParams {
    /// The family of each field (`F` first, then `G`), taken by name ([`Family::by_name`]).
    pub families: Vec<Family>,
    /// Weights, warm-up schedule, tolerance and solver settings, shared by every field (its
    /// `family` and `gradient_target` are not used: each field keeps the mean `‖∇‖` of its start).
    pub field: FieldParams,
    /// Target intersection angle γ of the two families in degrees, in (0°, 180°), held as a weak
    /// term (rows 0 and 1 of [`super::intersection`]); `None`: only the minimum angle is held.
    pub intersection_degrees: Option<f64>,
    /// Weight of the target-angle rows. Default 1 (a weak term, as the authors advise).
    pub intersection_weight: f64,
    /// Minimum intersection angle in degrees, in [0°, 90°): faces where the families cross at a
    /// smaller angle pay `max(0, sin² γ_min − sin² γ)²`. Default 30°.
    pub min_intersection_degrees: f64,
    /// Weight of the minimum-angle row. Default 10.
    pub min_intersection_weight: f64,
}

impl NetParams {
    /// Defaults for the two families `f`, `g`: the single-field defaults of
    /// [`FieldParams::new`] for each, no target angle, a 30° minimum.
    pub fn new(f: Family, g: Family) -> NetParams {
        NetParams {
            families: vec![f.by_name(), g.by_name()],
            field: FieldParams::new(f),
            intersection_degrees: None,
            intersection_weight: 1.0,
            min_intersection_degrees: 30.0,
            min_intersection_weight: 10.0,
        }
    }

    /// Checks every parameter, naming the first one out of range.
    pub fn validate(&self) -> Result<(), FieldError> {
        let invalid = |name: &'static str, message: String| Err(FieldError::InvalidParameter { name, message });
        if self.families.len() != 2 {
            return invalid("families", format!("a net has two families, got {}", self.families.len()));
        }
        for family in &self.families {
            crate::field::validate_params(&FieldParams { family: *family, ..self.field.clone() })?;
            if let crate::field::Family::ConstantSlope { free_slope: true, .. } = family {
                return invalid("families", "a net holds constant-slope families with a fixed slope only".into());
            }
        }
        if let Some(gamma) = self.intersection_degrees {
            if !(gamma.is_finite() && gamma > 0.0 && gamma < 180.0) {
                return invalid("intersection_degrees", format!("must lie in (0°, 180°), got {gamma}"));
            }
        }
        if !(self.min_intersection_degrees.is_finite() && (0.0..90.0).contains(&self.min_intersection_degrees)) {
            return invalid("min_intersection_degrees", format!("must lie in [0°, 90°), got {}", self.min_intersection_degrees));
        }
        for (name, value) in [("intersection_weight", self.intersection_weight), ("min_intersection_weight", self.min_intersection_weight)] {
            if !(value.is_finite() && value >= 0.0) {
                return invalid(name, format!("must be finite and ≥ 0, got {value}"));
            }
        }
        Ok(())
    }
}
