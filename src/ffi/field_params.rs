//! `LmlFieldParams`: the curve family and the weights of Eq. 12 as a plain C struct.

use super::failure::Failure;
use super::guard::guarded;
use super::raw::Out;
use super::status::LmlStatus;
use crate::field::{Family, FieldParams, Weights};

/// The curve family the level sets of a field should form (one of the `LML_FAMILY_*` constants).
pub type LmlFamily = u32;
/// Pseudo-geodesics: the binormal keeps the angle `theta_degrees` to the surface normal
/// (`E_angle`, paper Eq. 8–10).
pub const LML_FAMILY_PSEUDO_GEODESIC: LmlFamily = 0;
/// Geodesics, θ = 90° (`E_geo`, paper Eq. 13).
pub const LML_FAMILY_GEODESIC: LmlFamily = 1;
/// Asymptotic curves, θ = 0° (`E_asy`, paper Eq. 13).
pub const LML_FAMILY_ASYMPTOTIC: LmlFamily = 2;
/// Curves of constant slope about `LmlFieldParams.slope_axis` (paper Sec. 5.2.3, Eq. 22): unit
/// tangents `t` with `t·d = sin β`, `β = theta_degrees` in (−90°, 90°) the inclination against the
/// planes orthogonal to the axis `d`. Regions whose tangent planes are too close to orthogonal to
/// `d` carry no slope term (see `lml_curves_new_reachable_boundary`). Start such a field from
/// `lml_field_values_from_slope`; the start search (`lml_search_new`) refuses this family.
pub const LML_FAMILY_CONSTANT_SLOPE: LmlFamily = 3;
/// As `LML_FAMILY_CONSTANT_SLOPE`, with the slope β an unknown too, started at `theta_degrees`
/// (paper Sec. 5.2.3: "γ fixed or free"); the report's angles are measured against the slope
/// reached.
pub const LML_FAMILY_FREE_SLOPE: LmlFamily = 4;

/// The weights λ of the field energy (paper Eq. 12), each finite and ≥ 0. `angle` weighs the
/// curve term of the family (`E_angle`, `E_geo` or `E_asy`).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LmlWeights {
    pub fair: f64,
    pub grad: f64,
    pub angle: f64,
}

/// Parameters of a field optimisation. Fill it with `lml_field_params_default`, then change
/// fields as needed. Lengths are in the mesh's unit, angles in degrees. (No padding: the two
/// 32-bit fields come first.)
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LmlFieldParams {
    /// One of the `LML_FAMILY_*` constants.
    pub family: LmlFamily,
    /// 1: first run the library's short warm-up continuation (small λ_angle, larger λ_grad,
    /// paper Fig. 15), then `weights`; 0: use `weights` from the start. Default 1.
    pub warm_up: u32,
    /// Target angle between binormal and surface normal in degrees, in [0, 180]; used by
    /// `LML_FAMILY_PSEUDO_GEODESIC` (θ and 180° − θ are the two mirror families). For
    /// `LML_FAMILY_CONSTANT_SLOPE` and `LML_FAMILY_FREE_SLOPE`: the slope β in (−90, 90).
    /// Ignored by the other families.
    pub theta_degrees: f64,
    /// The final weights, held until convergence (default: λ_fair 1e-3, λ_grad 1e-5,
    /// λ_angle 30, on the normalised problem: the paper's Table 2 with a tenth of its λ_grad).
    pub weights: LmlWeights,
    /// Target gradient norm ‖∇F‖ of `E_grad` in field units per mesh length unit (strip
    /// spacing ≈ 1 / target); 0 keeps the mean gradient norm of the initial field. Default 0.
    pub gradient_target: f64,
    /// The final stage has converged when 3 iterations in a row each lower the weighted
    /// energy by less than this fraction. Finite, ≥ 0. Default 1e-2. It has also converged, whatever
    /// this fraction, when the curve terms fall to 1e-7, or (meshes of 1,000 vertices and more)
    /// when the level curves, measured from outside every 5 iterations once E_angle ≤ 1e-5, have
    /// not improved by 2 % in the last two measures.
    pub relative_tolerance: f64,
    /// The axis `d` of the constant-slope families (need not be unit; finite, not zero). Default
    /// (0, 0, 1). Ignored by the other families.
    pub slope_axis: [f64; 3],
}

/// The default axis of the constant-slope families: the z axis.
const DEFAULT_SLOPE_AXIS: [f64; 3] = [0.0, 0.0, 1.0];

impl From<Weights> for LmlWeights {
    fn from(w: Weights) -> LmlWeights {
        LmlWeights { fair: w.fair, grad: w.grad, angle: w.angle }
    }
}

impl From<LmlWeights> for Weights {
    fn from(w: LmlWeights) -> Weights {
        Weights { fair: w.fair, grad: w.grad, angle: w.angle }
    }
}

fn family_of(code: LmlFamily, theta_degrees: f64, slope_axis: [f64; 3]) -> Result<Family, Failure> {
    let slope = |free_slope| Family::ConstantSlope { axis: slope_axis, slope_degrees: theta_degrees, free_slope };
    match code {
        LML_FAMILY_PSEUDO_GEODESIC => Ok(Family::PseudoGeodesic { theta_degrees }),
        LML_FAMILY_GEODESIC => Ok(Family::Geodesic),
        LML_FAMILY_ASYMPTOTIC => Ok(Family::Asymptotic),
        LML_FAMILY_CONSTANT_SLOPE => Ok(slope(false)),
        LML_FAMILY_FREE_SLOPE => Ok(slope(true)),
        other => Err(Failure::argument("family", format!("{other} is not an LML_FAMILY_* constant"))),
    }
}

impl LmlFieldParams {
    /// The library's parameters; range checks of the values are left to the field solver,
    /// whose messages name the parameter.
    pub(crate) fn to_params(self) -> Result<FieldParams, Failure> {
        let mut params = FieldParams::new(family_of(self.family, self.theta_degrees, self.slope_axis)?);
        match self.warm_up {
            0 => params.schedule.clear(),
            1 => {}
            other => return Err(Failure::argument("params.warm_up", format!("must be 0 or 1, got {other}"))),
        }
        params.weights = self.weights.into();
        params.gradient_target = (self.gradient_target != 0.0).then_some(self.gradient_target);
        params.relative_tolerance = self.relative_tolerance;
        Ok(params)
    }
}

/// Fills `*out` with the library's defaults for a curve family (see the fields of
/// `LmlFieldParams`). `theta_degrees` is the target angle for `LML_FAMILY_PSEUDO_GEODESIC`, the
/// slope β for `LML_FAMILY_CONSTANT_SLOPE` and `LML_FAMILY_FREE_SLOPE` (axis (0, 0, 1); change
/// `slope_axis` afterwards), and is ignored for the other families (their `theta_degrees` field
/// is set to 90 or 0).
///
/// Returns `LML_STATUS_OK`, or `LML_STATUS_INVALID_ARGUMENT` (NULL `out`, unknown family,
/// θ not finite or outside [0, 180], a slope not finite or outside (−90, 90)); `*out` is left
/// unchanged on failure.
#[no_mangle]
pub unsafe extern "C" fn lml_field_params_default(family: LmlFamily, theta_degrees: f64, out: *mut LmlFieldParams) -> LmlStatus {
    guarded(|| {
        // SAFETY: `out` is writable by contract.
        let mut out = unsafe { Out::new(out, "out") }?;
        let chosen = family_of(family, theta_degrees, DEFAULT_SLOPE_AXIS)?;
        let theta = chosen.theta_degrees();
        if let Family::ConstantSlope { .. } = chosen {
            if !(theta.is_finite() && theta.abs() < 90.0) {
                return Err(Failure::argument("theta_degrees", format!("a slope must lie in (−90, 90), got {theta}")));
            }
        } else if !(theta.is_finite() && (0.0..=180.0).contains(&theta)) {
            return Err(Failure::argument("theta_degrees", format!("must lie in [0, 180], got {theta}")));
        }
        let defaults = FieldParams::new(chosen);
        out.set(LmlFieldParams {
            family,
            theta_degrees: theta,
            weights: defaults.weights.into(),
            warm_up: u32::from(!defaults.schedule.is_empty()),
            gradient_target: defaults.gradient_target.unwrap_or(0.0),
            relative_tolerance: defaults.relative_tolerance,
            slope_axis: DEFAULT_SLOPE_AXIS,
        });
        Ok(LmlStatus::Ok)
    })
}
