//! The short reshape trial behind `design`'s verdict (paper Sec. 3.3): when no strip pattern of
//! θ is acceptable, how far would the surface have to move for one to be? The trial moves the
//! surface within [`TRIAL_TOLERANCE_PERCENT`] of its bounding-box diagonal for at most
//! [`TRIAL_ITERATIONS`] iterations with the field fixed, builds the strips on the moved surface as
//! `reshape` does, and judges them with the same verdict. The tolerance it names is the largest
//! deviation the trial needed, rounded up to a tenth of a per cent.
use crate::error::{CliError, CliResult};
use crate::strips_cmd::build_strips;
use lamella::mesh::TriMesh;
use lamella::reshape::{ReshapeParams, ReshapeSolver, Tolerance};
use serde_json::{json, Value};

/// Largest deviation the trial allows, per cent of the bounding-box diagonal.
pub const TRIAL_TOLERANCE_PERCENT: f64 = 2.0;
/// Most surface iterations of the trial.
pub const TRIAL_ITERATIONS: usize = 100;

/// What the trial found.
pub struct Trial {
    /// The strips on the moved surface are acceptable.
    pub acceptable: bool,
    /// Largest distance of a moved vertex from the original surface, per cent of the diagonal.
    pub deviation_percent: f64,
    /// The tolerance to ask `reshape` for (the deviation rounded up to 0.1 %).
    pub suggested_percent: f64,
    /// The strips' worst quad angle error on the moved surface (degrees).
    pub worst_degrees: f64,
    pub iterations: usize,
    pub seconds: f64,
}

/// Runs the trial for the level sets of `field` on `mesh`, its strips built and judged as
/// `design` built and judged its own (`strips` of `width`, `None` for the default, and
/// `angle_tolerance`). `Err` only when the trial cannot run at all (the reshape rejects the input).
pub fn reshape_trial(mesh: &TriMesh, field: &[f64], theta: f64, strips: usize, width: Option<f64>, angle_tolerance: f64) -> CliResult<Trial> {
    let started = std::time::Instant::now();
    let params = ReshapeParams { tolerance: Tolerance::DiagonalFraction(TRIAL_TOLERANCE_PERCENT / 100.0), ..ReshapeParams::new(theta) };
    let mut solver = ReshapeSolver::new(mesh, field, params).map_err(|e| CliError::internal(format!("reshape trial: {e}")))?;
    while solver.iterations() < TRIAL_ITERATIONS && !solver.is_converged() {
        solver.step(TRIAL_ITERATIONS - solver.iterations()).map_err(|e| CliError::internal(format!("reshape trial: {e}")))?;
    }
    let run = build_strips(&solver.mesh(), field, theta, strips, width, angle_tolerance)?;
    let (low, high) = mesh.bounding_box();
    let deviation_percent = 100.0 * solver.report().max_deviation / (high - low).norm();
    Ok(Trial {
        acceptable: run.pattern.verdict.is_acceptable(),
        deviation_percent,
        suggested_percent: ((10.0 * deviation_percent).ceil() / 10.0).max(0.1),
        worst_degrees: run.pattern.metrics.max_quad_angle_error_degrees,
        iterations: solver.iterations(),
        seconds: started.elapsed().as_secs_f64(),
    })
}

impl Trial {
    /// What to try next, for the verdict's message; `session` is the design's session.bin.
    pub fn advice(&self, session: &str, theta: f64) -> String {
        if self.acceptable {
            format!(
                "a trial reshape moved the surface by up to {:.2} % of its diagonal and made the strips acceptable: lamella reshape --session {session} --theta {theta} --tolerance {:.1}%",
                self.deviation_percent, self.suggested_percent
            )
        } else {
            format!(
                "a trial reshape within {TRIAL_TOLERANCE_PERCENT} % of the surface's diagonal did not make the strips acceptable either (worst strip plane {:.1}° off): this θ needs another start or another surface",
                self.worst_degrees
            )
        }
    }

    /// The trial for report.json.
    pub fn to_json(&self) -> Value {
        json!({
            "allowed_percent": TRIAL_TOLERANCE_PERCENT,
            "iterations": self.iterations,
            "acceptable": self.acceptable,
            "deviation_percent": self.deviation_percent,
            "suggested_tolerance_percent": self.suggested_percent,
            "worst_strip_plane_degrees": self.worst_degrees,
            "seconds": self.seconds,
        })
    }
}
