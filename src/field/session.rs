//! Saving a field optimisation and restoring it later, e.g. inside a design document:
//! the unit-scaled mesh, parameters, every variable (field and auxiliaries), the stage and the
//! solver's damping, behind a magic number and a format version. A restored session continues
//! bit for bit as the original would have.

use super::error::FieldError;
use super::field_solver::{stage_weights, validate_params, FieldSolver, Scales};
use super::params::FieldParams;
use super::report::StepReport;
use crate::mesh::TriMesh;
use crate::solver::DampingState;
use bincode::Options;
use serde::{Deserialize, Serialize};

/// First bytes of every saved session.
pub const SESSION_MAGIC: [u8; 4] = *b"LMLF";
/// Version of the session layout written by this library.
pub const SESSION_VERSION: u32 = 1;

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
    iterations: usize,
    converged: bool,
    damping: DampingState,
    last_report: StepReport,
}

fn encoding() -> impl Options {
    bincode::DefaultOptions::new().with_fixint_encoding().with_little_endian()
}

fn corrupt(message: impl Into<String>) -> FieldError {
    FieldError::CorruptData { message: message.into() }
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
            iterations: self.iterations,
            converged: self.converged,
            damping: self.lm.damping_state(),
            last_report: self.last_report.clone(),
        };
        let mut bytes = SESSION_MAGIC.to_vec();
        bytes.extend_from_slice(&SESSION_VERSION.to_le_bytes());
        // Invariant: serialising plain data into a Vec cannot fail.
        bytes.extend(encoding().serialize(&session).expect("session serialises"));
        bytes
    }

    /// Restores a session saved by [`FieldSolver::to_bytes`]. Truncated, corrupted or
    /// future-version data gives [`FieldError::CorruptData`] or
    /// [`FieldError::UnsupportedVersion`], never a panic.
    pub fn from_bytes(bytes: &[u8]) -> Result<FieldSolver, FieldError> {
        if bytes.len() < 8 || bytes[..4] != SESSION_MAGIC {
            return Err(corrupt("not a Lamella field session (bad magic number)"));
        }
        let version = u32::from_le_bytes([bytes[4], bytes[5], bytes[6], bytes[7]]);
        if version != SESSION_VERSION {
            return Err(FieldError::UnsupportedVersion { found: version, supported: SESSION_VERSION });
        }
        let body = &bytes[8..];
        let session: Session = encoding()
            .with_limit(body.len() as u64)
            .reject_trailing_bytes()
            .deserialize(body)
            .map_err(|e| corrupt(format!("session data: {e}")))?;
        validate_params(&session.params).map_err(|e| corrupt(format!("saved parameters: {e}")))?;
        let scales_ok = [session.scales.field, session.scales.length, session.gradient_target].iter().all(|v| v.is_finite() && *v > 0.0);
        if !scales_ok {
            return Err(corrupt("saved scale factors are not finite and positive"));
        }
        let mut solver = FieldSolver::assemble(session.unit_mesh, session.params, session.gradient_target, session.scales)?;
        if session.x.len() != solver.x.len() {
            return Err(corrupt(format!("{} saved variables, the mesh needs {}", session.x.len(), solver.x.len())));
        }
        if let Some(i) = session.x.iter().position(|v| !v.is_finite()) {
            return Err(corrupt(format!("saved variable {i} is not finite")));
        }
        if session.stage > solver.params.schedule.len() {
            return Err(corrupt(format!("saved stage {} does not exist", session.stage)));
        }
        solver.problem.set_weights(stage_weights(&solver.params, session.stage).1);
        solver.x = session.x;
        solver.stage = session.stage;
        solver.stage_iterations = session.stage_iterations;
        solver.slow_iterations = session.slow_iterations;
        solver.iterations = session.iterations;
        solver.converged = session.converged;
        solver.lm.restore_damping(session.damping);
        solver.last_report = session.last_report;
        Ok(solver)
    }
}
