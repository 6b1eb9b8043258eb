//! Saving a surface optimisation and restoring it later (e.g. inside a design document): the
//! original surface, the fixed field, the parameters, every variable (positions, binormals, side
//! vectors), the tolerance guard and the solver's damping, behind a magic number and a format
//! version. A restored session continues bit for bit as the original would have.

use super::error::ReshapeError;
use super::linearisation::Linearisation;
use super::params::ReshapeParams;
use super::report::ReshapeReport;
use super::solver::ReshapeSolver;
use crate::field::{check_damping, corrupt, framed, unframed, MAX_SAVED_ITERATIONS};
use crate::mesh::{TriMesh, Vec3};
use crate::solver::DampingState;
use serde::{Deserialize, Serialize};

/// First bytes of every saved surface session.
pub const RESHAPE_SESSION_MAGIC: [u8; 4] = *b"LMLR";
/// Version of the surface session layout written by this library.
pub const RESHAPE_SESSION_VERSION: u32 = 1;

#[derive(Serialize, Deserialize)]
struct Session {
    /// The original surface, in the caller's units.
    original: TriMesh,
    field: Vec<f64>,
    params: ReshapeParams,
    /// The solver's variables (internal units: positions, then `[b, u]` per curve vertex).
    x: Vec<f64>,
    iterations: usize,
    slow_iterations: usize,
    guard_raises: usize,
    converged: bool,
    guard: f64,
    damping: DampingState,
    last_report: ReshapeReport,
}

impl ReshapeSolver {
    /// The whole session as bytes: magic `"LMLR"`, version (little-endian u32), then the state.
    pub fn to_bytes(&self) -> Vec<u8> {
        let session = Session {
            original: self.given.clone(),
            field: self.field.clone(),
            params: self.params.clone(),
            x: self.x.clone(),
            iterations: self.iterations,
            slow_iterations: self.slow_iterations,
            guard_raises: self.guard_raises,
            converged: self.converged,
            guard: self.problem.guard,
            damping: self.lm.damping_state(),
            last_report: self.last_report.clone(),
        };
        framed(RESHAPE_SESSION_MAGIC, RESHAPE_SESSION_VERSION, &session)
    }

    /// Restores a session saved by [`ReshapeSolver::to_bytes`]. Truncated, corrupted or
    /// future-version data gives `ReshapeError::Field` with `CorruptData` or
    /// `UnsupportedVersion`, never a panic. Every restored quantity is checked: the surface,
    /// field and parameters as in [`ReshapeSolver::new`], the variables finite and their surface
    /// valid, counters, guard and damping in range, the saved report finite.
    pub fn from_bytes(bytes: &[u8]) -> Result<ReshapeSolver, ReshapeError> {
        let session: Session = unframed(bytes, RESHAPE_SESSION_MAGIC, RESHAPE_SESSION_VERSION, "surface")?;
        let invalid = |e: ReshapeError| ReshapeError::Field(corrupt(format!("saved surface, field or parameters: {e}")));
        let mut solver = ReshapeSolver::new(&session.original, &session.field, session.params).map_err(invalid)?;
        if session.x.len() != solver.x.len() {
            return Err(corrupt(format!("{} saved variables, the surface needs {}", session.x.len(), solver.x.len())).into());
        }
        if let Some(i) = session.x.iter().position(|v| !v.is_finite()) {
            return Err(corrupt(format!("saved variable {i} is not finite")).into());
        }
        if session.iterations > MAX_SAVED_ITERATIONS || session.slow_iterations > session.iterations || session.guard_raises > session.iterations {
            return Err(corrupt("saved iteration counters are out of range").into());
        }
        if !(session.guard.is_finite() && session.guard >= 1.0) {
            return Err(corrupt(format!("saved tolerance guard {} is not finite and ≥ 1", session.guard)).into());
        }
        check_damping(session.damping)?;
        let r = &session.last_report;
        let measures = [r.angle_error_rms_degrees, r.angle_error_max_degrees, r.max_deviation, r.rms_deviation, r.tolerance, r.max_edge_change, r.guard, r.damping];
        if !measures.iter().all(|v| v.is_finite() && *v >= 0.0) {
            return Err(corrupt("the saved report holds a negative or non-finite measure").into());
        }
        let vertices = solver.field.len();
        let positions: Vec<Vec3> = session.x.chunks_exact(3).take(vertices).map(Vec3::from_column_slice).collect();
        let moved = TriMesh::from_vertices_and_faces(positions, solver.problem.lin.mesh.faces().to_vec())
            .map_err(|e| corrupt(format!("the saved positions do not form a valid surface: {e}")))?;
        solver.problem.lin = Linearisation::new(moved, solver.problem.curves(), &solver.original);
        solver.x = session.x;
        solver.previous.copy_from_slice(&solver.x);
        solver.iterations = session.iterations;
        solver.slow_iterations = session.slow_iterations;
        solver.guard_raises = session.guard_raises;
        solver.converged = session.converged;
        solver.problem.guard = session.guard;
        solver.lm.restore_damping(session.damping);
        solver.last_report = session.last_report;
        Ok(solver)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::FieldError;
    use crate::reshape::Tolerance;
    use crate::surfaces::hall_roof;

    fn solver() -> ReshapeSolver {
        let mesh = hall_roof(300).into_mesh().expect("roof");
        let field: Vec<f64> = mesh.positions().iter().map(|p| p.x + 0.05 * p.y * p.y).collect();
        let params = ReshapeParams { tolerance: Tolerance::DiagonalFraction(0.01), ..ReshapeParams::new(50.0) };
        ReshapeSolver::new(&mesh, &field, params).expect("solver")
    }

    fn bits(solver: &ReshapeSolver) -> Vec<u64> {
        solver.positions().iter().flat_map(|p| p.iter().map(|v| v.to_bits()).collect::<Vec<_>>()).chain(solver.deviations().iter().map(|d| d.to_bits())).collect()
    }

    #[test]
    fn a_restored_session_continues_bit_for_bit() {
        let mut original = solver();
        original.step(6).expect("steps");
        let bytes = original.to_bytes();
        let mut restored = ReshapeSolver::from_bytes(&bytes).expect("restores");
        assert_eq!(restored.report(), original.report());
        assert_eq!(bits(&restored), bits(&original));
        assert_eq!(restored.to_bytes(), bytes, "saving the restored session gives the same bytes");
        let (a, b) = (original.step(8).expect("steps"), restored.step(8).expect("steps"));
        assert_eq!(a, b);
        assert!(a.max_deviation > 0.0, "the surface moved");
        assert_eq!(bits(&restored), bits(&original));
    }

    #[test]
    fn damaged_bytes_are_corrupt_data_never_a_panic() {
        let bytes = solver().to_bytes();
        let corrupt_data = |b: &[u8]| matches!(ReshapeSolver::from_bytes(b), Err(ReshapeError::Field(FieldError::CorruptData { .. })));
        assert!(corrupt_data(&[]));
        assert!(corrupt_data(&bytes[..bytes.len() / 2]));
        let mut field_session = bytes.clone();
        field_session[..4].copy_from_slice(b"LMLF");
        assert!(corrupt_data(&field_session), "a field session is not a surface session");
        let mut future = bytes.clone();
        future[4] = 9;
        assert!(matches!(ReshapeSolver::from_bytes(&future), Err(ReshapeError::Field(FieldError::UnsupportedVersion { found: 9, .. }))));
        // Every byte flipped in turn, on a sample of positions: an error or a valid session.
        for i in (8..bytes.len()).step_by(97) {
            let mut damaged = bytes.clone();
            damaged[i] ^= 0xA5;
            if let Ok(restored) = ReshapeSolver::from_bytes(&damaged) {
                assert!(restored.positions().iter().all(|p| p.iter().all(|v| v.is_finite())));
            }
        }
    }
}
