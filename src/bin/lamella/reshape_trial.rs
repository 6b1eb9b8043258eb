//! The short reshape trials behind `design`'s verdict (paper Sec. 3.3): when no strip pattern of
//! θ is acceptable, how far would the surface have to move for one to be? Each trial moves the
//! surface with the field fixed for at most [`TRIAL_ITERATIONS`] iterations, builds the strips on
//! the moved surface as `reshape` does, and judges them with the same verdict. The first allows
//! [`TRIAL_TOLERANCE_PERCENT`] of the bounding-box diagonal. If it is acceptable, tighter ones
//! follow ([`TIGHTER_TRIAL_PERCENTS`], up to the first acceptable one): the surface moves as far
//! as the weak pull of `E^S_close` lets it, not as little as θ needs (z = xy/5 at θ = 30°: 1.2 %
//! of the diagonal used within 2 %, yet 0.25 % is enough). The tolerance named is that of the
//! tightest acceptable trial, so `lamella reshape` with it retraces that trial's iterations (and
//! may run more).
use crate::error::{CliError, CliResult};
use crate::strips_cmd::build_strips;
use lamella::mesh::TriMesh;
use lamella::reshape::{ReshapeParams, ReshapeSolver, Tolerance};
use serde_json::{json, Value};

/// Largest deviation the trials allow, per cent of the bounding-box diagonal.
pub const TRIAL_TOLERANCE_PERCENT: f64 = 2.0;
/// The tolerances tried, in order, after an acceptable first trial, per cent of the diagonal:
/// two more trials at most (each costs as much as the first).
pub const TIGHTER_TRIAL_PERCENTS: [f64; 2] = [0.5, 1.0];
/// Most surface iterations of each trial.
pub const TRIAL_ITERATIONS: usize = 60;

/// One trial: how the strips came out on the surface moved within `allowed_percent`.
pub struct TrialRun {
    /// The strips on the moved surface are acceptable.
    pub acceptable: bool,
    /// The tolerance this trial allowed, per cent of the diagonal.
    pub allowed_percent: f64,
    /// Largest distance of a moved vertex from the original surface, per cent of the diagonal.
    pub deviation_percent: f64,
    /// The strips' worst quad angle error on the moved surface (degrees).
    pub worst_degrees: f64,
    /// Surface iterations of this trial.
    pub iterations: usize,
}

/// What the trials found: the tightest acceptable one (or the first if none was), and what all
/// of them cost.
pub struct Trial {
    pub best: TrialRun,
    /// Surface iterations of all trials.
    pub iterations: usize,
    /// How many trials ran.
    pub trials: usize,
    pub seconds: f64,
}

/// Runs the trials for the level sets of `field` on `mesh`, their strips built and judged as
/// `design` built and judged its own (`strips` of `width`, `None` for the default, and
/// `angle_tolerance`). `Err` only when a trial cannot run at all (the reshape rejects the input).
pub fn reshape_trial(mesh: &TriMesh, field: &[f64], theta: f64, strips: usize, width: Option<f64>, angle_tolerance: f64) -> CliResult<Trial> {
    let started = std::time::Instant::now();
    let (low, high) = mesh.bounding_box();
    let diagonal = (high - low).norm();
    let trial = |allowed: f64| -> CliResult<TrialRun> {
        let params = ReshapeParams { tolerance: Tolerance::DiagonalFraction(allowed / 100.0), ..ReshapeParams::new(theta) };
        let mut solver = ReshapeSolver::new(mesh, field, params).map_err(|e| CliError::internal(format!("reshape trial: {e}")))?;
        while solver.iterations() < TRIAL_ITERATIONS && !solver.is_converged() {
            solver.step(TRIAL_ITERATIONS - solver.iterations()).map_err(|e| CliError::internal(format!("reshape trial: {e}")))?;
        }
        let run = build_strips(&solver.mesh(), field, theta, strips, width, angle_tolerance)?;
        Ok(TrialRun {
            acceptable: run.pattern.verdict.is_acceptable(),
            allowed_percent: allowed,
            deviation_percent: 100.0 * solver.report().max_deviation / diagonal,
            worst_degrees: run.pattern.metrics.max_quad_angle_error_degrees,
            iterations: solver.iterations(),
        })
    };
    let mut best = trial(TRIAL_TOLERANCE_PERCENT)?;
    let (mut iterations, mut trials) = (best.iterations, 1);
    if best.acceptable {
        for allowed in TIGHTER_TRIAL_PERCENTS {
            let tighter = trial(allowed)?;
            (iterations, trials) = (iterations + tighter.iterations, trials + 1);
            if tighter.acceptable {
                best = tighter;
                break;
            }
        }
    }
    Ok(Trial { best, iterations, trials, seconds: started.elapsed().as_secs_f64() })
}

impl Trial {
    /// What to try next, for the verdict's message; `session` is the design's session.bin.
    pub fn advice(&self, session: &str, theta: f64) -> String {
        let best = &self.best;
        if best.acceptable {
            format!(
                "a trial reshape within {} % of the surface's diagonal (moving it by up to {:.2} %) made the strips acceptable: lamella reshape --session {session} --theta {theta} --tolerance {}%",
                best.allowed_percent, best.deviation_percent, best.allowed_percent
            )
        } else {
            format!(
                "a trial reshape within {TRIAL_TOLERANCE_PERCENT} % of the surface's diagonal did not make the strips acceptable either (worst strip plane {:.1}° off): this θ needs another start or another surface",
                best.worst_degrees
            )
        }
    }

    /// The trial for report.json.
    pub fn to_json(&self) -> Value {
        let best = &self.best;
        json!({
            "allowed_percent": best.allowed_percent,
            "trials": self.trials,
            "iterations": self.iterations,
            "acceptable": best.acceptable,
            "deviation_percent": best.deviation_percent,
            "worst_strip_plane_degrees": best.worst_degrees,
            "seconds": self.seconds,
        })
    }
}
