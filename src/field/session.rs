//! Saving a field optimisation and restoring it later, e.g. inside a design document:
//! the unit-scaled mesh, parameters, every variable (field and auxiliaries), the stage and the
//! solver's damping, behind a magic number and a format version. A restored session continues
//! bit for bit as the original would have.

use super::error::FieldError;
use super::field_solver::{stage_weights, validate_params, FieldSolver, Scales};
use super::params::FieldParams;
use super::plateau::Plateau;
use super::report::StepReport;
use crate::mesh::TriMesh;
use crate::solver::{DampingState, SplitWork};
use bincode::Options;
use serde::{Deserialize, Serialize};

/// First bytes of every saved session.
pub const SESSION_MAGIC: [u8; 4] = *b"LMLF";
/// Version of the session layout written by this library.
pub const SESSION_VERSION: u32 = 2;

#[derive(Serialize, Deserialize)]
struct Session {
    unit_mesh: TriMesh,
    scales: Scales,
    gradient_target: f64,
    params: FieldParams,
    x: Vec<f64>,
    stage: usize,
    stage_iterations: usize,
    slow_iterations: usize,
    plateau: Plateau,
    iterations: usize,
    converged: bool,
    damping: DampingState,
    last_report: StepReport,
}

fn encoding() -> impl Options {
    bincode::DefaultOptions::new().with_fixint_encoding().with_little_endian()
}

pub(crate) fn corrupt(message: impl Into<String>) -> FieldError {
    FieldError::CorruptData { message: message.into() }
}

/// `state` behind `magic` and a little-endian `u32` format `version`.
pub(crate) fn framed<T: Serialize>(magic: [u8; 4], version: u32, state: &T) -> Vec<u8> {
    let mut bytes = magic.to_vec();
    bytes.extend_from_slice(&version.to_le_bytes());
    // Invariant: serialising plain data into a Vec cannot fail.
    bytes.extend(encoding().serialize(state).expect("session serialises"));
    bytes
}

/// The state framed by [`framed`], checked: `what` names the kind of session in the messages.
/// Errors: `CorruptData` for another magic number, truncated, damaged or trailing bytes;
/// `UnsupportedVersion` for another format version.
pub(crate) fn unframed<T: serde::de::DeserializeOwned>(bytes: &[u8], magic: [u8; 4], version: u32, what: &str) -> Result<T, FieldError> {
    if bytes.len() < 8 || bytes[..4] != magic {
        return Err(corrupt(format!("not a Lamella {what} session (bad magic number)")));
    }
    let found = u32::from_le_bytes([bytes[4], bytes[5], bytes[6], bytes[7]]);
    if found != version {
        return Err(FieldError::UnsupportedVersion { found, supported: version });
    }
    let body = &bytes[8..];
    encoding().with_limit(body.len() as u64).reject_trailing_bytes().deserialize(body).map_err(|e| corrupt(format!("session data: {e}")))
}

/// The damping state is in range: μ finite and positive (or not set yet), ν finite and ≥ 1.
pub(crate) fn check_damping(damping: DampingState) -> Result<(), FieldError> {
    let DampingState { mu, nu } = damping;
    if !mu.is_none_or(|mu| mu.is_finite() && mu > 0.0) || !nu.is_finite() || nu < 1.0 {
        return Err(corrupt(format!("saved damping state (μ {mu:?}, ν {nu}) is out of range")));
    }
    Ok(())
}

/// Most iterations a restored session may have run (a bound far above any real run that keeps
/// the counters clear of overflow).
pub(crate) const MAX_SAVED_ITERATIONS: usize = 1 << 40;

/// The iteration counters and the damping state are in range.
fn check_counts(session: &Session) -> Result<(), FieldError> {
    if session.iterations > MAX_SAVED_ITERATIONS {
        return Err(corrupt(format!("saved iteration count {} exceeds {MAX_SAVED_ITERATIONS}", session.iterations)));
    }
    if session.stage_iterations > session.iterations || session.slow_iterations > session.iterations {
        return Err(corrupt("saved stage counters exceed the iteration count"));
    }
    if !session.plateau.is_valid() {
        return Err(corrupt("the saved measure of the level curves is out of range"));
    }
    check_damping(session.damping)
}

/// The saved report holds finite, non-negative measures and vertex indices of the mesh (it is
/// shown as it is until the next step).
fn check_report(report: &StepReport, vertices: usize) -> Result<(), FieldError> {
    let e = &report.energies;
    let measures = [e.fair, e.grad, e.angle, e.frame, e.total, report.angle_error_rms_degrees, report.angle_error_max_degrees, report.damping];
    if !measures.iter().all(|v| v.is_finite() && *v >= 0.0) {
        return Err(corrupt("the saved report holds a negative or non-finite measure"));
    }
    if let Some(v) = report.singular_vertices.iter().find(|&&v| v as usize >= vertices) {
        return Err(corrupt(format!("the saved report names singular vertex {v}, but the mesh has {vertices} vertices")));
    }
    if report.measured_vertices > vertices {
        return Err(corrupt(format!("the saved report measured {} vertices, but the mesh has {vertices}", report.measured_vertices)));
    }
    Ok(())
}

impl FieldSolver {
    /// The whole session as bytes: magic, version (little-endian u32), then the state.
    pub fn to_bytes(&self) -> Vec<u8> {
        let session = Session {
            unit_mesh: self.problem.mesh().clone(),
            scales: self.scales,
            gradient_target: self.problem.gradient_target(),
            params: self.params.clone(),
            x: self.x.clone(),
            stage: self.stage,
            stage_iterations: self.stage_iterations,
            slow_iterations: self.slow_iterations,
            plateau: self.plateau,
            iterations: self.iterations,
            converged: self.converged,
            damping: self.lm.damping_state(),
            last_report: self.last_report.clone(),
        };
        framed(SESSION_MAGIC, SESSION_VERSION, &session)
    }

    /// Restores a session saved by [`FieldSolver::to_bytes`]. Truncated, corrupted or
    /// future-version data gives [`FieldError::CorruptData`] or
    /// [`FieldError::UnsupportedVersion`], never a panic. Every restored quantity is checked:
    /// parameters as in [`FieldSolver::new`], scale factors normal and positive, variables
    /// finite, the field within ±[`super::FIELD_VALUE_LIMIT`] and the mesh valid once
    /// un-scaled, counters and damping in range, the saved report finite and about the mesh's
    /// vertices.
    pub fn from_bytes(bytes: &[u8]) -> Result<FieldSolver, FieldError> {
        let session: Session = unframed(bytes, SESSION_MAGIC, SESSION_VERSION, "field")?;
        validate_params(&session.params).map_err(|e| corrupt(format!("saved parameters: {e}")))?;
        let scales = [("field scale", session.scales.field), ("length scale", session.scales.length), ("gradient target", session.gradient_target)];
        if let Some((name, value)) = scales.iter().find(|(_, v)| !(v.is_normal() && *v > 0.0)) {
            // Subnormal scales pass `> 0` but un-scale the field to ±inf.
            return Err(corrupt(format!("saved {name} {value:e} is not a normal positive number")));
        }
        check_counts(&session)?;
        let mut solver = FieldSolver::assemble(session.unit_mesh, session.params, session.gradient_target, session.scales, SplitWork::Span)?;
        if session.x.len() != solver.x.len() {
            return Err(corrupt(format!("{} saved variables, the mesh needs {}", session.x.len(), solver.x.len())));
        }
        if let Some(i) = session.x.iter().position(|v| !v.is_finite()) {
            return Err(corrupt(format!("saved variable {i} is not finite")));
        }
        if session.stage > solver.params.schedule.len() {
            return Err(corrupt(format!("saved stage {} does not exist", session.stage)));
        }
        let vertices = solver.problem.mesh().vertex_count();
        let limit = super::FIELD_VALUE_LIMIT;
        let unscaled = |v: &f64| v / session.scales.field;
        if let Some(vertex) = session.x[..vertices].iter().map(unscaled).position(|f| f.is_nan() || f.abs() > limit) {
            return Err(corrupt(format!("the saved field at vertex {vertex} un-scales to {:e}, outside ±{limit:e}", unscaled(&session.x[vertex]))));
        }
        solver.problem.mesh().try_scaled(1.0 / session.scales.length).map_err(|e| corrupt(format!("the saved mesh does not un-scale: {e}")))?;
        check_report(&session.last_report, vertices)?;
        solver.problem.set_weights(stage_weights(&solver.params, session.stage).1);
        solver.x = session.x;
        solver.stage = session.stage;
        solver.stage_iterations = session.stage_iterations;
        solver.slow_iterations = session.slow_iterations;
        solver.plateau = session.plateau;
        solver.iterations = session.iterations;
        solver.converged = session.converged;
        solver.lm.restore_damping(session.damping);
        solver.last_report = session.last_report;
        Ok(solver)
    }
}
