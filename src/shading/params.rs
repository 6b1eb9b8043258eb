//! Weights and settings of the shading design (Eq. 25, Table 2).

use super::earth_frame::EarthFrame;
use super::error::ShadingError;
use super::labels::VertexLabel;
use super::light_region::LightRegion;
use crate::solver::LmOptions;

/// The weights λ of Eq. 25 on the normalised problem (mean edge 1, mean `‖∇F‖` 1), with the
/// light weight per effect, and the weight of the constraint rows that define the auxiliaries
/// (`b`, `l` in the region, `n^p`).
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct ShadingWeights {
    pub fair: f64,
    pub grad: f64,
    /// λ_3 of `E_block` (Eq. 26).
    pub light_block: f64,
    /// λ_3 of `E_light` (Eq. 27).
    pub light_pass: f64,
    pub constraint: f64,
}

impl ShadingWeights {
    /// Table 2, Fig. 36(a) (blocking): λ_fair 0.1, λ_grad 0.3, λ_3 1e-3; pass vertices of a
    /// mixed design get λ_3 3e-3, Fig. 36(b)'s ratio of λ_3 to λ_fair (3e-4 to 0.01) at these
    /// regularisers: with Fig. 36(b)'s own 3e-4 a pass region weighed ten times less against the
    /// fairness than in a letting-through design, and on a curved facade (a quarter-cylinder
    /// wall, pass on its east third) its strips blocked 45 % of the morning sun instead of
    /// about 25 %. Constraints at 1.
    pub fn blocking() -> ShadingWeights {
        ShadingWeights { fair: 0.1, grad: 0.3, light_block: 1e-3, light_pass: 3e-3, constraint: 1.0 }
    }

    /// Table 2, Fig. 36(b) (letting through): λ_fair 0.01, λ_grad 0.1, λ_3 3e-4 (1e-3 for any
    /// block vertex); constraints at 1.
    pub fn passing() -> ShadingWeights {
        ShadingWeights { fair: 0.01, grad: 0.1, light_block: 1e-3, light_pass: 3e-4, constraint: 1.0 }
    }

    /// [`ShadingWeights::blocking`] when some vertex of `labels` blocks, else
    /// [`ShadingWeights::passing`].
    pub fn for_labels(labels: &[VertexLabel]) -> ShadingWeights {
        if labels.contains(&VertexLabel::Block) { ShadingWeights::blocking() } else { ShadingWeights::passing() }
    }

    pub(crate) fn validate(&self) -> Result<(), ShadingError> {
        let named = [("weights.fair", self.fair), ("weights.grad", self.grad), ("weights.light_block", self.light_block), ("weights.light_pass", self.light_pass)];
        for (name, value) in named {
            if !(value.is_finite() && value >= 0.0) {
                return Err(ShadingError::invalid(name, format!("must be finite and ≥ 0, got {value}")));
            }
        }
        if !(self.constraint.is_finite() && self.constraint > 0.0) {
            return Err(ShadingError::invalid("weights.constraint", format!("must be finite and > 0, got {}", self.constraint)));
        }
        Ok(())
    }
}

/// Settings of a shading design.
#[derive(Clone, Debug, PartialEq)]
pub struct ShadingParams {
    /// The site's earth-axis frame in the model ([`EarthFrame::new`] or [`super::Site::frame`]).
    pub frame: EarthFrame,
    /// `R_l` of the blocking vertices.
    pub block_region: LightRegion,
    /// `R_l` of the letting-through vertices.
    pub pass_region: LightRegion,
    pub weights: ShadingWeights,
    /// Converged after [`crate::field::SETTLING_ITERATIONS`] iterations in a row that each lower
    /// `E_tot` by less than this fraction (or on a stopping rule of Levenberg–Marquardt).
    pub relative_tolerance: f64,
    pub lm: LmOptions,
}

impl ShadingParams {
    /// Blocking weights (Table 2), the same region for blocking and letting through.
    pub fn new(frame: EarthFrame, region: LightRegion) -> ShadingParams {
        ShadingParams { frame, block_region: region, pass_region: region, weights: ShadingWeights::blocking(), relative_tolerance: 1e-3, lm: LmOptions::default() }
    }

    pub(crate) fn validate(&self) -> Result<(), ShadingError> {
        self.block_region.validate()?;
        self.pass_region.validate()?;
        self.weights.validate()?;
        if !(self.relative_tolerance.is_finite() && self.relative_tolerance >= 0.0) {
            return Err(ShadingError::invalid("relative_tolerance", "must be finite and ≥ 0".to_string()));
        }
        crate::field::validate_lm(&self.lm)?;
        Ok(())
    }
}
