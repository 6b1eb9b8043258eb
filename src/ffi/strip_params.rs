//! `LmlStripParams`: target angle, width and optimisation settings of the strips as a plain C struct.

use super::failure::Failure;
use super::guard::guarded;
use super::raw::Out;
use super::status::LmlStatus;
use crate::strips::{StripParams, StripWeights};

/// The weights λ of the strip energies (paper Sec. 3.4), each finite and ≥ 0 (`planarity` > 0);
/// each residual is multiplied by √λ. Lengths inside them are in units of a polyline's mean
/// edge length, so the defaults suit any scale.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LmlStripWeights {
    /// Eq. 8 on polyline vertices: the binormal keeps the angle θ to the surface normal; with the
    /// planarity weight (√(angle × planarity)), Eq. 8 on the quad normals too, so that the quads
    /// themselves keep 90° − θ to the surface normal.
    pub angle: f64,
    /// Eq. 9 on polyline vertices: the binormal is a unit vector orthogonal to both edges.
    pub binormal: f64,
    /// Distance of the polyline vertices from the surface (default 0.01: the centre line may leave
    /// the surface a little where θ, planar quads and a straight unrolling cannot all hold on it;
    /// `Appro` of the metrics says by how much).
    pub surface: f64,
    /// Tangential drift of the vertices along the surface.
    pub slide: f64,
    /// Fairness `c_{i−1} − 2c_i + c_{i+1}` (binormal stage and first rectifying round only).
    pub fair: f64,
    /// Eq. 16–17: rulings in the outer bisecting planes, planar quads.
    pub planarity: f64,
    /// Proximity of the rulings to their initial guess (first rectifying round only).
    pub ruling_anchor: f64,
}

/// Most binormal-strip rounds (`LmlStripParams.binormal_rounds`). (A literal, so that the header
/// can show it; equal to the library's limit.)
pub const LML_MAX_STRIP_ROUNDS: u32 = 32;

/// Most iterations of one strip stage (`LmlStripParams.iterations_per_round`,
/// `final_iterations`, `polish_iterations`); with `LML_MAX_STRIP_ROUNDS` a strip runs at most
/// 17500 iterations. (A literal, equal to the library's limit.)
pub const LML_MAX_STRIP_ITERATIONS: u32 = 500;

/// Parameters of a strip computation. Fill it with `lml_strip_params_default`, then change
/// fields as needed. Lengths are in the mesh's unit, angles in degrees. (No padding: the four
/// 32-bit fields come first.)
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LmlStripParams {
    /// Binormal-strip stage: rounds of (project onto the surface, optimise), 0 to
    /// `LML_MAX_STRIP_ROUNDS` (32). Default 8.
    pub binormal_rounds: u32,
    /// Levenberg–Marquardt iterations per binormal round and in the first rectifying round, 0 to
    /// `LML_MAX_STRIP_ITERATIONS` (500). Default 15.
    pub iterations_per_round: u32,
    /// Iterations of the final rectifying round, 0 to `LML_MAX_STRIP_ITERATIONS`. Default 60.
    pub final_iterations: u32,
    /// Iterations of the closing polish (positions held, rulings solved for planar quads), 0 to
    /// `LML_MAX_STRIP_ITERATIONS`. Default 30.
    pub polish_iterations: u32,
    /// Target angle θ between binormal and surface normal, in [0, 180]: the θ of the field the
    /// curves come from.
    pub theta_degrees: f64,
    /// Width of the flat strip (distance between its two straight boundaries), finite and > 0.
    pub width: f64,
    /// Largest angle error in degrees, in (0, 180), of a quad of an acceptable pattern: beyond it
    /// (or with flipped quads) `lml_strips_new` returns `LML_STATUS_NO_ACCEPTABLE_FAMILY`. Default 2.
    pub tolerance_degrees: f64,
    pub weights: LmlStripWeights,
}

impl From<StripWeights> for LmlStripWeights {
    fn from(w: StripWeights) -> LmlStripWeights {
        let StripWeights { angle, binormal, surface, slide, fair, planarity, ruling_anchor } = w;
        LmlStripWeights { angle, binormal, surface, slide, fair, planarity, ruling_anchor }
    }
}

impl From<LmlStripWeights> for StripWeights {
    fn from(w: LmlStripWeights) -> StripWeights {
        let LmlStripWeights { angle, binormal, surface, slide, fair, planarity, ruling_anchor } = w;
        StripWeights { angle, binormal, surface, slide, fair, planarity, ruling_anchor }
    }
}

fn count(value: u32) -> usize {
    usize::try_from(value).unwrap_or(usize::MAX)
}

impl LmlStripParams {
    /// The library's parameters; range checks are left to the strip computation, whose
    /// messages name the parameter.
    pub(crate) fn to_params(self) -> StripParams {
        StripParams {
            theta_degrees: self.theta_degrees,
            width: self.width,
            weights: self.weights.into(),
            binormal_rounds: count(self.binormal_rounds),
            iterations_per_round: count(self.iterations_per_round),
            final_iterations: count(self.final_iterations),
            polish_iterations: count(self.polish_iterations),
            tolerance_degrees: self.tolerance_degrees,
        }
    }
}

/// Saturates a library count into the struct's 32-bit field.
fn count_u32(value: usize) -> u32 {
    u32::try_from(value).unwrap_or(u32::MAX)
}

/// Fills `*out` with the library's defaults for strips of width `width` whose binormals keep the
/// angle `theta_degrees` to the surface normal (see the fields of `LmlStripParams`).
///
/// Returns `LML_STATUS_OK`, or `LML_STATUS_INVALID_ARGUMENT` (NULL `out`, θ not finite or
/// outside [0, 180], width not finite or ≤ 0); `*out` is left unchanged on failure.
#[no_mangle]
pub unsafe extern "C" fn lml_strip_params_default(theta_degrees: f64, width: f64, out: *mut LmlStripParams) -> LmlStatus {
    guarded(|| {
        // SAFETY: `out` is writable by contract.
        let mut out = unsafe { Out::new(out, "out") }?;
        if !(theta_degrees.is_finite() && (0.0..=180.0).contains(&theta_degrees)) {
            return Err(Failure::argument("theta_degrees", format!("must lie in [0, 180], got {theta_degrees}")));
        }
        if !(width.is_finite() && width > 0.0) {
            return Err(Failure::argument("width", format!("must be finite and > 0, got {width}")));
        }
        let defaults = StripParams::new(theta_degrees, width);
        out.set(LmlStripParams {
            binormal_rounds: count_u32(defaults.binormal_rounds),
            iterations_per_round: count_u32(defaults.iterations_per_round),
            final_iterations: count_u32(defaults.final_iterations),
            polish_iterations: count_u32(defaults.polish_iterations),
            theta_degrees,
            width,
            tolerance_degrees: defaults.tolerance_degrees,
            weights: defaults.weights.into(),
        });
        Ok(LmlStatus::Ok)
    })
}

#[cfg(test)]
mod tests {
    #[test]
    fn the_iteration_limits_are_the_library_limits() {
        assert_eq!(usize::try_from(super::LML_MAX_STRIP_ROUNDS), Ok(crate::strips::MAX_STRIP_ROUNDS));
        assert_eq!(usize::try_from(super::LML_MAX_STRIP_ITERATIONS), Ok(crate::strips::MAX_STRIP_ITERATIONS));
    }
}
