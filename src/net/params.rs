//! What a net optimisation aims at (paper Sec. 4.1–4.2): one curve family per field (two for a
//! net, three for a 3-web), the weights of each field's terms (Eq. 12), of the
//! intersection-angle term between them and, for a 3-web, of Eq. 18 (`F + G + H = 0`).

use crate::field::{Family, FieldError, FieldParams};
use serde::{Deserialize, Serialize};

/// Least weight of a 3-web's `E_grad` terms (see [`NetParams::web`]).
pub const WEB_GRADIENT_WEIGHT: f64 = 1e-3;

/// Parameters of a net of two families or a 3-web of three.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct NetParams {
    /// The family of each field, taken by name ([`Family::by_name`]): two for a net (`F`, `G`),
    /// three for a 3-web, whose third family is the diagonal one (the paper's `G` in Eq. 18:
    /// `F + G + H = 0`, its level sets the diagonals `i + j = const` of the first two's net).
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
    /// 3-webs: weight of Eq. 18's row `F + G + H` per vertex (on the normalised problem, each
    /// field of mean `‖∇‖` 1). Default 1e4: held almost exactly (about 1e-7 of the fields'
    /// range), as the extracted web's third family is read from the first two (the diagonals),
    /// its strips from the third field.
    pub web_weight: f64,
    /// 3-webs: the factor on the third field's terms at the final weight stage. Default 1 (the
    /// authors' implementation uses 3; on z = xy/5 an AAG web's geodesics came out no closer with
    /// it, and Eq. 18 held less tightly).
    pub third_family_weight: f64,
    /// 3-webs: the factor on the third field's terms in the first weight stage, as a fraction of
    /// [`NetParams::third_family_weight`]. It grows geometrically to 1 at the final stage
    /// (Sec. 4.2: the third family joins gradually; the authors advise starting it small and
    /// growing it). Default 0.1; 1 holds it constant.
    pub third_family_start: f64,
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
            web_weight: 1e4,
            third_family_weight: 1.0,
            third_family_start: 0.1,
        }
    }

    /// Defaults for a 3-web of the families `f`, `h` and the diagonal family `g` (e.g. AAG:
    /// `web(A, A, G)`), as [`NetParams::new`] with Eq. 18 held.
    ///
    /// A web's fields are held to their gradient scale more firmly than a single field's (`E_grad`
    /// weight at least [`WEB_GRADIENT_WEIGHT`] in every stage): Eq. 18 and the fairness terms both
    /// shrink with the fields, and at the single-field weight 1e-5 the three fields drift toward
    /// constants (on z = xy/5 with 500 vertices their range fell from 22 to 0.2, where Eq. 18's
    /// residual relative to the range grows and the families degenerate).
    pub fn web(f: Family, h: Family, g: Family) -> NetParams {
        let mut params = NetParams { families: vec![f.by_name(), h.by_name(), g.by_name()], ..NetParams::new(f, h) };
        params.field.weights.grad = params.field.weights.grad.max(WEB_GRADIENT_WEIGHT);
        params.field.schedule.iter_mut().for_each(|stage| stage.weights.grad = stage.weights.grad.max(WEB_GRADIENT_WEIGHT));
        params
    }

    /// Whether these are the parameters of a 3-web (three families).
    pub fn is_web(&self) -> bool {
        self.families.len() == 3
    }

    /// The factor on the third field's terms in weight stage `stage`:
    /// `weight · start^((S − stage)/S)` for `S` warm-up stages ([`NetParams::third_family_weight`],
    /// [`NetParams::third_family_start`]).
    pub fn third_family_factor(&self, stage: usize) -> f64 {
        let stages = self.field.schedule.len();
        if stages == 0 || stage >= stages {
            return self.third_family_weight;
        }
        self.third_family_weight * self.third_family_start.powf((stages - stage) as f64 / stages as f64)
    }

    /// Checks every parameter, naming the first one out of range.
    pub fn validate(&self) -> Result<(), FieldError> {
        let invalid = |name: &'static str, message: String| Err(FieldError::InvalidParameter { name, message });
        if !(2..=3).contains(&self.families.len()) {
            return invalid("families", format!("a net has two families and a 3-web three, got {}", self.families.len()));
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
        if !(self.third_family_start.is_finite() && self.third_family_start > 0.0 && self.third_family_start <= 1.0) {
            return invalid("third_family_start", format!("must lie in (0, 1], got {}", self.third_family_start));
        }
        for (name, value) in [("intersection_weight", self.intersection_weight), ("min_intersection_weight", self.min_intersection_weight), ("web_weight", self.web_weight), ("third_family_weight", self.third_family_weight)] {
            if !(value.is_finite() && value >= 0.0) {
                return invalid(name, format!("must be finite and ≥ 0, got {value}"));
            }
        }
        Ok(())
    }
}
