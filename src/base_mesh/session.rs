//! Saving a base-mesh optimisation and restoring it later (e.g. inside a design document): the
//! net as given, the reference surface, the parameters, each family's oriented target, the stage
//! (the families alone, or with the torsion-free rows of Eq. 21) and the net it started from,
//! every variable (positions, normals, binormals, side vectors, rulings), the vertices held past
//! the reference's boundary and the solver's damping, behind a magic number and a format version.
//! A restored session continues bit for bit as the original would have.

use super::error::BaseMeshError;
use super::net_mesh::NetMesh;
use super::params::BaseMeshParams;
use super::problem::vec3;
use super::report::{BaseMeshReport, Reference};
use super::solver::{assemble, has_inner_vertex, unit_scale, BaseMeshSolver};
use super::start::mirror_degrees;
use crate::field::{check_damping, framed, unframed, validate_lm, FieldError, MAX_SAVED_ITERATIONS};
use crate::mesh::{TriMesh, Vec3};
use crate::solver::{DampingState, LeastSquaresProblem};
use serde::{Deserialize, Serialize};

/// First bytes of every saved base-mesh session.
pub const BASE_MESH_SESSION_MAGIC: [u8; 4] = *b"LMLB";
/// Version of the base-mesh session layout written by this library.
pub const BASE_MESH_SESSION_VERSION: u32 = 2;

#[derive(Serialize, Deserialize)]
struct Session {
    /// The net as given (the caller's units): its vertices, rows and columns. Its scale to mean
    /// segment length 1 is derived again.
    positions: Vec<[f64; 3]>,
    rows: Vec<Vec<u32>>,
    columns: Vec<Vec<u32>>,
    /// A web's diagonals (none in a net).
    diagonals: Vec<Vec<u32>>,
    /// The reference surface as given.
    reference: TriMesh,
    params: BaseMeshParams,
    /// Each family's target along its polylines' direction.
    targets_degrees: Vec<f64>,
    /// The torsion-free rows of Eq. 21 are on.
    torsion_free: bool,
    /// The scaled net the stage started from (the pull target `v_start`): the net as given, or
    /// where the families settled when the torsion-free stage began.
    start: Vec<[f64; 3]>,
    x: Vec<f64>,
    held: Vec<bool>,
    iterations: usize,
    converged: bool,
    damping: DampingState,
    initial: BaseMeshReport,
    last_report: BaseMeshReport,
}

fn corrupt(message: impl Into<String>) -> BaseMeshError {
    BaseMeshError::CorruptData { message: message.into() }
}

/// An error of the session helpers shared with the field sessions, as a base-mesh error.
fn session_error(e: FieldError) -> BaseMeshError {
    match e {
        FieldError::CorruptData { message } => corrupt(message),
        FieldError::UnsupportedVersion { found, supported } => BaseMeshError::UnsupportedVersion { found, supported },
        other => corrupt(other.to_string()),
    }
}

fn xyz(points: &[Vec3]) -> Vec<[f64; 3]> {
    points.iter().map(|&p| p.into()).collect()
}

/// The saved report holds finite measures (errors, distances, angles and energy non-negative)
/// about the polylines and vertices of `net` (it is shown as it is until the next step).
fn check_report(report: &BaseMeshReport, net: &NetMesh) -> Result<(), BaseMeshError> {
    let (d, t) = (&report.deviation, &report.node_torsion);
    let mut measures = vec![report.energy, d.max, d.rms, d.max_percent, t.max_degrees, t.rms_degrees];
    let mut signed = report.targets_degrees.to_vec();
    for (k, family) in report.families.iter().enumerate() {
        if family.curves.len() > net.polylines(k).len() || family.worst.is_some_and(|w| w.curve >= family.curves.len()) {
            return Err(corrupt(format!("the saved report measures more curves of family {k} than the net has polylines")));
        }
        measures.extend([family.rms_error_degrees, family.max_error_degrees, family.spacing]);
        measures.extend(family.curves.iter().flat_map(|c| [c.rms_error_degrees, c.max_error_degrees, c.length]));
        if let Some(worst) = &family.worst {
            measures.push(worst.error_degrees);
            signed.extend(worst.point.iter().chain([&worst.measured_degrees]));
        }
    }
    if !measures.iter().all(|v| v.is_finite() && *v >= 0.0) || !signed.iter().all(|v| v.is_finite()) {
        return Err(corrupt("the saved report holds a negative or non-finite measure"));
    }
    let n = net.vertex_count();
    if d.worst_vertex >= n || t.worst_vertex.is_some_and(|v| v >= n) || t.nodes > n {
        return Err(corrupt(format!("the saved report names a vertex or node count beyond the net's {n} vertices")));
    }
    Ok(())
}

impl BaseMeshSolver {
    /// The whole session as bytes: magic `"LMLB"`, version (little-endian u32), then the state.
    pub fn to_bytes(&self) -> Vec<u8> {
        let session = Session {
            positions: xyz(self.given.positions()),
            rows: self.given.rows().to_vec(),
            columns: self.given.columns().to_vec(),
            diagonals: self.given.diagonals().to_vec(),
            reference: self.reference.mesh.clone(),
            params: self.params.clone(),
            targets_degrees: self.targets_degrees.clone(),
            torsion_free: self.problem.torsion_free,
            start: xyz(self.problem.net().positions()),
            x: self.x.clone(),
            held: self.held.clone(),
            iterations: self.iterations,
            converged: self.converged,
            damping: self.lm.damping_state(),
            initial: self.initial.clone(),
            last_report: self.last_report.clone(),
        };
        framed(BASE_MESH_SESSION_MAGIC, BASE_MESH_SESSION_VERSION, &session)
    }

    /// Restores a session saved by [`BaseMeshSolver::to_bytes`]. Truncated, corrupted or
    /// future-version data gives [`BaseMeshError::CorruptData`] or
    /// [`BaseMeshError::UnsupportedVersion`], never a panic. Every restored quantity is checked:
    /// the net as in [`NetMesh::new`] (with a vertex inside a polyline) and the reference as in
    /// [`TriMesh::from_vertices_and_faces`], parameters as in [`BaseMeshSolver::new`] (and 1 to
    /// [`crate::field::MAX_LM_TRIALS`] damped trials per iteration) and taken by name, each
    /// target the family's angle or its mirror, the stage one the parameters lead to, one start
    /// position and held flag per vertex (every vertex past the reference's boundary at the
    /// stage's start held), the variables finite and the positions finite in the caller's units,
    /// counters and damping in range, both saved reports finite and about the net's vertices.
    pub fn from_bytes(bytes: &[u8]) -> Result<BaseMeshSolver, BaseMeshError> {
        let session: Session = unframed(bytes, BASE_MESH_SESSION_MAGIC, BASE_MESH_SESSION_VERSION, "base-mesh").map_err(session_error)?;
        let params = session.params;
        params.validate().map_err(|e| corrupt(format!("saved parameters: {e}")))?;
        validate_lm(&params.lm).map_err(|e| corrupt(format!("saved parameters: {e}")))?;
        if let Some(k) = (0..params.families.len()).find(|&k| params.families[k] != params.families[k].by_name()) {
            return Err(corrupt(format!("saved family {k} ({:?}) is not taken by name", params.families[k])));
        }
        let positions: Vec<Vec3> = session.positions.into_iter().map(Vec3::from).collect();
        let given = if session.diagonals.is_empty() { NetMesh::new(positions, session.rows, session.columns) } else { NetMesh::web(positions, session.rows, session.columns, session.diagonals) }
            .map_err(|e| corrupt(format!("the saved net is not valid: {e}")))?;
        if !has_inner_vertex(&given) {
            return Err(corrupt("the saved net has no vertex inside a row or a column of three or more"));
        }
        let targets_degrees = session.targets_degrees;
        if targets_degrees.len() != params.families.len() || given.family_count() != params.families.len() {
            return Err(corrupt(format!("{} saved targets and a net of {} families for {} families", targets_degrees.len(), given.family_count(), params.families.len())));
        }
        for (k, (&target, &family)) in targets_degrees.iter().zip(&params.families).enumerate() {
            if target != family.theta_degrees() && target != mirror_degrees(family) {
                return Err(corrupt(format!("saved target {target}° of family {k} is neither its angle nor that angle read backwards")));
            }
        }
        let torsion_free = session.torsion_free;
        if (torsion_free && !params.torsion_free) || (params.torsion_free && !params.families_first && !torsion_free) {
            return Err(corrupt(format!("the saved stage (torsion-free rows {}) does not follow from the parameters", if torsion_free { "on" } else { "off" })));
        }
        if session.iterations > MAX_SAVED_ITERATIONS {
            return Err(corrupt(format!("saved iteration count {} exceeds {MAX_SAVED_ITERATIONS}", session.iterations)));
        }
        check_damping(session.damping).map_err(session_error)?;
        let n = given.vertex_count();
        if session.start.len() != n || session.held.len() != n {
            return Err(corrupt(format!("{} saved start positions and {} held flags for a net of {n} vertices", session.start.len(), session.held.len())));
        }
        if let Some(v) = session.start.iter().position(|p| !p.iter().all(|c| c.is_finite())) {
            return Err(corrupt(format!("the saved start of vertex {v} is not finite")));
        }
        check_report(&session.initial, &given)?;
        check_report(&session.last_report, &given)?;
        let scale = unit_scale(&given);
        let reference = Reference::new(&session.reference);
        let start = given.with_positions(session.start.into_iter().map(Vec3::from).collect());
        let mut held = session.held.clone();
        let (problem, mut lm) = assemble(&reference, start, scale, &params, &targets_degrees, torsion_free, &mut held)
            .map_err(|e| corrupt(format!("the saved net does not make a problem: {e}")))?;
        if let Some(v) = (0..n).find(|&v| held[v] != session.held[v]) {
            return Err(corrupt(format!("vertex {v} lay past the reference's boundary where the stage started, but is not held")));
        }
        if session.x.len() != problem.variable_count() {
            return Err(corrupt(format!("{} saved variables, the net needs {}", session.x.len(), problem.variable_count())));
        }
        if let Some(i) = session.x.iter().position(|v| !v.is_finite()) {
            return Err(corrupt(format!("saved variable {i} is not finite")));
        }
        let net = given.with_positions((0..n).map(|v| vec3(&session.x, 3 * v) / scale).collect());
        if let Some(v) = net.positions().iter().position(|p| !p.iter().all(|c| c.is_finite())) {
            return Err(corrupt(format!("vertex {v} is not finite in the net's units")));
        }
        let measures = reference.measure(&net, &params.families, &targets_degrees);
        lm.restore_damping(session.damping);
        Ok(BaseMeshSolver {
            given,
            reference,
            scale,
            problem,
            lm,
            params,
            x: session.x,
            targets_degrees,
            iterations: session.iterations,
            converged: session.converged,
            initial: session.initial,
            last_report: session.last_report,
            measures,
            held: session.held,
        })
    }
}
