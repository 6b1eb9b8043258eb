//! What a net optimisation reports after each call to `step`.

use crate::field::StepReport;
use serde::{Deserialize, Serialize};

/// How the two families cross, over the faces where both gradients are defined.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct IntersectionReport {
    /// Smallest and area-weighted mean unsigned intersection angle, in degrees (`[0°, 90°]`).
    pub min_degrees: f64,
    pub mean_degrees: f64,
    /// Faces crossing below the minimum angle of the parameters.
    pub faces_below_min: usize,
    /// The unweighted target-angle rows' energy (0 without a target) and the minimum-angle rows'.
    pub target_energy: f64,
    pub min_energy: f64,
}

/// How a 3-web holds together (Eq. 18) and how its third family crosses the other two.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct WebReport {
    /// Largest and RMS `|F + G + H|` over the vertices, relative to the largest of the three
    /// fields' ranges.
    pub residual_max: f64,
    pub residual_rms: f64,
    /// The factor on the third field's terms in the weight stage in force.
    pub third_family_factor: f64,
    /// How the third family crosses the first and the second (minimum-angle rows only).
    pub intersections: [IntersectionReport; 2],
}

/// State of a net optimisation after a `step`.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct NetReport {
    /// Iterations run since the solver was created, and by this call.
    pub iterations: usize,
    pub iterations_this_step: usize,
    /// Index of the weight stage in force (`schedule.len()` for the final weights).
    pub stage: usize,
    /// Each family's own report (energies, angle errors, singular vertices, flips) in field order.
    pub families: Vec<StepReport>,
    /// How the first two families cross.
    pub intersection: IntersectionReport,
    /// A 3-web's Eq. 18 residual and third-family crossings; `None` for a net.
    pub web: Option<WebReport>,
    /// The weighted energy the solver minimises.
    pub total_energy: f64,
    /// Levenberg–Marquardt damping μ after the last iteration.
    pub damping: f64,
    /// The final stage has converged; further steps do nothing.
    pub converged: bool,
}
