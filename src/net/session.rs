//! Saving a net optimisation and restoring it later (e.g. inside a design document): the
//! mesh as given, the fields' scale factors, the parameters, the intersection term's oriented target, every variable
//! (both fields and their auxiliaries), the weight stage and the solver's damping, behind a magic
//! number and a format version. A restored session continues bit for bit as the original would
//! have.

use super::params::NetParams;
use super::report::NetReport;
use super::solver::NetSolver;
use crate::field::{check_damping, corrupt, framed, unframed, FieldError, FIELD_VALUE_LIMIT, MAX_SAVED_ITERATIONS};
use crate::mesh::TriMesh;
use crate::solver::DampingState;
use serde::{Deserialize, Serialize};

/// First bytes of every saved net session.
pub const NET_SESSION_MAGIC: [u8; 4] = *b"LMLN";
/// Version of the net session layout written by this library.
pub const NET_SESSION_VERSION: u32 = 2;

#[derive(Serialize, Deserialize)]
struct Session {
    /// The mesh as given (the caller's units); its unit-scaled copy is derived again.
    mesh: TriMesh,
    field_scales: Vec<f64>,
    params: NetParams,
    /// The intersection term's oriented target `(cos γ, sin γ)`.
    target: (f64, f64),
    x: Vec<f64>,
    stage: usize,
    stage_iterations: usize,
    slow_iterations: usize,
    iterations: usize,
    converged: bool,
    damping: DampingState,
    last_report: NetReport,
}

impl NetSolver {
    /// The whole session as bytes: magic `"LMLN"`, version (little-endian u32), then the state.
    pub fn to_bytes(&self) -> Vec<u8> {
        let session = Session {
            mesh: self.given.clone(),
            field_scales: self.field_scales.clone(),
            params: self.params.clone(),
            target: self.problem.intersection().target,
            x: self.x.clone(),
            stage: self.stage,
            stage_iterations: self.stage_iterations,
            slow_iterations: self.slow_iterations,
            iterations: self.iterations,
            converged: self.converged,
            damping: self.lm.damping_state(),
            last_report: self.last_report.clone(),
        };
        framed(NET_SESSION_MAGIC, NET_SESSION_VERSION, &session)
    }

    /// Restores a session saved by [`NetSolver::to_bytes`]. Truncated, corrupted or
    /// future-version data gives `CorruptData` or `UnsupportedVersion`, never a panic. Every
    /// restored quantity is checked: the mesh as in [`TriMesh::from_vertices_and_faces`],
    /// parameters as in [`NetSolver::new`], field scale factors normal and positive, the target a
    /// unit vector, variables finite and the fields within ±[`FIELD_VALUE_LIMIT`], counters and
    /// damping in range.
    pub fn from_bytes(bytes: &[u8]) -> Result<NetSolver, FieldError> {
        let session: Session = unframed(bytes, NET_SESSION_MAGIC, NET_SESSION_VERSION, "net")?;
        let mut params = session.params;
        params.validate().map_err(|e| corrupt(format!("saved parameters: {e}")))?;
        params.families.iter_mut().for_each(|f| *f = f.by_name());
        if let Some(scale) = session.field_scales.iter().find(|s| !(s.is_normal() && **s > 0.0)) {
            return Err(corrupt(format!("saved scale factor {scale:e} is not a normal positive number")));
        }
        if session.field_scales.len() != params.families.len() {
            return Err(corrupt(format!("{} saved field scales for {} families", session.field_scales.len(), params.families.len())));
        }
        let (c, s) = session.target;
        if !((c * c + s * s - 1.0).abs() <= 1e-9) {
            return Err(corrupt("the saved intersection target is not a unit vector"));
        }
        if session.iterations > MAX_SAVED_ITERATIONS || session.stage_iterations > session.iterations || session.slow_iterations > session.iterations {
            return Err(corrupt("saved iteration counters are out of range"));
        }
        if session.stage > params.field.schedule.len() {
            return Err(corrupt(format!("saved stage {} does not exist", session.stage)));
        }
        check_damping(session.damping)?;
        let mesh = TriMesh::from_vertices_and_faces(session.mesh.positions().to_vec(), session.mesh.faces().to_vec())
            .map_err(|e| corrupt(format!("the saved mesh is not valid: {e}")))?;
        let mut solver = NetSolver::assemble(mesh, params, session.target, session.field_scales, session.stage)?;
        if session.x.len() != solver.x.len() {
            return Err(corrupt(format!("{} saved variables, the mesh needs {}", session.x.len(), solver.x.len())));
        }
        if let Some(i) = session.x.iter().position(|v| !v.is_finite()) {
            return Err(corrupt(format!("saved variable {i} is not finite")));
        }
        for k in 0..solver.field_scales.len() {
            let start = solver.problem.field_start(k);
            let n = solver.problem.mesh().vertex_count();
            let scale = solver.field_scales[k];
            if let Some(vertex) = session.x[start..start + n].iter().position(|v| (v / scale).abs() > FIELD_VALUE_LIMIT) {
                return Err(corrupt(format!("saved field {k} at vertex {vertex} un-scales outside ±{FIELD_VALUE_LIMIT:e}")));
            }
        }
        let r = &session.last_report;
        if r.families.len() > solver.field_scales.len() || !(r.total_energy.is_finite() && r.damping.is_finite()) {
            return Err(corrupt("the saved report does not fit the session"));
        }
        solver.x = session.x;
        solver.stage_iterations = session.stage_iterations;
        solver.slow_iterations = session.slow_iterations;
        solver.iterations = session.iterations;
        solver.converged = session.converged;
        solver.lm.restore_damping(session.damping);
        solver.last_report = session.last_report;
        Ok(solver)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::Family;
    use crate::surfaces::hall_roof;

    fn solver() -> NetSolver {
        let mesh = hall_roof(300).into_mesh().expect("roof");
        let f: Vec<f64> = mesh.positions().iter().map(|p| p.x + 0.1 * p.y).collect();
        let g: Vec<f64> = mesh.positions().iter().map(|p| p.y - 0.1 * p.x).collect();
        let theta = Family::PseudoGeodesic { theta_degrees: 60.0 };
        let mut params = NetParams::new(theta, theta);
        params.intersection_degrees = Some(80.0);
        NetSolver::new(&mesh, &[f, g], params).expect("solver")
    }

    fn bits(solver: &NetSolver) -> Vec<u64> {
        solver.fields().iter().flatten().map(|v| v.to_bits()).collect()
    }

    #[test]
    fn a_restored_net_continues_bit_for_bit() {
        let mut original = solver();
        original.step(4).expect("steps");
        let bytes = original.to_bytes();
        let mut restored = NetSolver::from_bytes(&bytes).expect("restores");
        assert_eq!(restored.report(), original.report());
        assert_eq!(bits(&restored), bits(&original));
        assert_eq!(restored.to_bytes(), bytes);
        let (a, b) = (original.step(6).expect("steps"), restored.step(6).expect("steps"));
        assert_eq!(a, b);
        assert_eq!(bits(&restored), bits(&original));
    }

    #[test]
    fn a_restored_web_continues_bit_for_bit() {
        let mesh = hall_roof(300).into_mesh().expect("roof");
        let f: Vec<f64> = mesh.positions().iter().map(|p| p.x + 0.1 * p.y).collect();
        let h: Vec<f64> = mesh.positions().iter().map(|p| p.y - 0.1 * p.x).collect();
        let params = NetParams::web(Family::PseudoGeodesic { theta_degrees: 60.0 }, Family::PseudoGeodesic { theta_degrees: 60.0 }, Family::Geodesic);
        let mut original = NetSolver::new(&mesh, &[f, h], params).expect("solver");
        original.step(3).expect("steps");
        let mut restored = NetSolver::from_bytes(&original.to_bytes()).expect("restores");
        let (a, b) = (original.step(5).expect("steps"), restored.step(5).expect("steps"));
        assert_eq!(a, b);
        assert!(a.web.is_some());
        assert_eq!(bits(&restored), bits(&original));
    }

    #[test]
    fn damaged_bytes_are_corrupt_data_never_a_panic() {
        let bytes = solver().to_bytes();
        let corrupt_data = |b: &[u8]| matches!(NetSolver::from_bytes(b), Err(FieldError::CorruptData { .. }));
        assert!(corrupt_data(&[]));
        assert!(corrupt_data(&bytes[..bytes.len() - 3]));
        let mut field_session = bytes.clone();
        field_session[3] = b'F';
        assert!(corrupt_data(&field_session), "a field session is not a net session");
        let mut future = bytes.clone();
        future[4] = 7;
        assert!(matches!(NetSolver::from_bytes(&future), Err(FieldError::UnsupportedVersion { found: 7, .. })));
        for i in (8..bytes.len()).step_by(89) {
            let mut damaged = bytes.clone();
            damaged[i] ^= 0x5A;
            if let Ok(restored) = NetSolver::from_bytes(&damaged) {
                assert!(restored.fields().iter().flatten().all(|v| v.is_finite()));
            }
        }
    }
}
