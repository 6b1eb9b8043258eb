//! `LmlReshape`: a surface optimisation session (paper Sec. 3.3, Fig. 17), stepped like
//! `LmlField`: create from a mesh and a fixed field, step until converged, read the moved
//! positions and their deviations, free.

use super::failure::Failure;
use super::guard::guarded;
use super::layout::flat_xyz;
use super::mesh::LmlMesh;
use super::raw::{copy_out, handle, handle_mut, input, release, Out};
use super::status::LmlStatus;
use crate::field::FieldError;
use crate::reshape::{ReshapeError, ReshapeParams, ReshapeReport, ReshapeSolver, Tolerance};
use crate::solver::SolverError;

/// A surface optimisation session (opaque): the original surface, the fixed field, the moving
/// positions with their auxiliary variables and the solver state. Create it with
/// `lml_reshape_new`, release it with `lml_reshape_free`.
pub struct LmlReshape {
    solver: ReshapeSolver,
}

/// The state of a surface optimisation after `lml_reshape_step` (written by the library; the
/// caller owns the struct). Lengths in the mesh's units, angles in degrees; energies unweighted
/// on the problem scaled to mean edge length 1.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LmlReshapeReport {
    /// Iterations run since the session was created.
    pub iterations: u64,
    /// 1 when converged (further steps do nothing), else 0.
    pub converged: u64,
    /// RMS and maximum of |θ_measured − θ| over the curve vertices (the optimiser's own measure).
    pub angle_error_rms_degrees: f64,
    pub angle_error_max_degrees: f64,
    /// Largest and RMS distance of a vertex from the original surface, and its bound.
    pub max_deviation: f64,
    pub rms_deviation: f64,
    pub tolerance: f64,
    /// Largest relative change of an edge length.
    pub max_edge_change: f64,
    /// E^S_angle, E^S_fair, E^S_close (Eq. 14) and E^S_edge (Eq. 15).
    pub energy_angle: f64,
    pub energy_fair: f64,
    pub energy_close: f64,
    pub energy_edge: f64,
}

impl From<&ReshapeReport> for LmlReshapeReport {
    fn from(r: &ReshapeReport) -> LmlReshapeReport {
        LmlReshapeReport {
            iterations: r.iterations as u64,
            converged: u64::from(r.converged),
            angle_error_rms_degrees: r.angle_error_rms_degrees,
            angle_error_max_degrees: r.angle_error_max_degrees,
            max_deviation: r.max_deviation,
            rms_deviation: r.rms_deviation,
            tolerance: r.tolerance,
            max_edge_change: r.max_edge_change,
            energy_angle: r.energies.angle,
            energy_fair: r.energies.fair,
            energy_close: r.energies.close,
            energy_edge: r.energies.edge,
        }
    }
}

impl From<ReshapeError> for Failure {
    fn from(e: ReshapeError) -> Failure {
        match e {
            ReshapeError::Field(error) => Failure::from(error),
            ReshapeError::Solver(error) => Failure::from(FieldError::Solver(error)),
            ReshapeError::Mesh(error) => Failure::from(error),
            ReshapeError::InvalidParameter { .. } => Failure::new(LmlStatus::InvalidArgument, e.to_string()),
            ReshapeError::NoCurveVertices => Failure::new(LmlStatus::SingularField, e.to_string()),
        }
    }
}

/// What a failed surface step answers: `LML_STATUS_DID_NOT_CONVERGE` for an iteration that
/// failed numerically, else the error's own status.
pub(super) fn step_failure(e: ReshapeError) -> Failure {
    match e {
        ReshapeError::Solver(error @ (SolverError::NonFiniteResidual { .. } | SolverError::NonFiniteJacobian { .. } | SolverError::FactorizationFailed { .. })) => {
            Failure::new(LmlStatus::DidNotConverge, format!("reshape: {error}"))
        }
        other => Failure::from(other),
    }
}

/// Starts moving `mesh` so that the level sets of `field` become P-curves of the angle θ, with
/// the paper's Table 3 weights (Fig. 17(b)).
///
/// - `mesh`: the original surface (copied).
/// - `field`: `n` doubles, one per vertex (held fixed; finite, not constant, magnitude at most
///   1e100). Copied.
/// - `theta_degrees`: the target angle, in [0°, 180°].
/// - `tolerance`: the largest distance of a vertex from the original surface, > 0: a length in
///   the mesh's units when `tolerance_is_fraction` is 0, else a fraction of the mesh's
///   bounding-box diagonal (0.005 for 0.5 %).
/// - `out`: receives the new session (release with `lml_reshape_free`); NULL on failure.
///
/// Returns `LML_STATUS_OK`; `LML_STATUS_INVALID_ARGUMENT` (NULL pointer, `n` ≠ vertex count, a
/// value out of range, naming it); `LML_STATUS_SINGULAR_FIELD` (a constant field, or no interior
/// vertex with a regular level curve).
#[no_mangle]
pub unsafe extern "C" fn lml_reshape_new(
    mesh: *const LmlMesh,
    field: *const f64,
    n: usize,
    theta_degrees: f64,
    tolerance: f64,
    tolerance_is_fraction: u32,
    out: *mut *mut LmlReshape,
) -> LmlStatus {
    guarded(|| {
        // SAFETY (all blocks): the pointer contracts are those documented above.
        let mut out = unsafe { Out::new(out, "out") }?;
        out.set(std::ptr::null_mut());
        let mesh = unsafe { handle(mesh, "mesh") }?;
        if n != mesh.mesh.vertex_count() {
            return Err(FieldError::FieldLength { expected: mesh.mesh.vertex_count(), actual: n }.into());
        }
        let values = unsafe { input(field, n, "field") }?;
        let tolerance = if tolerance_is_fraction != 0 { Tolerance::DiagonalFraction(tolerance) } else { Tolerance::Absolute(tolerance) };
        let params = ReshapeParams { tolerance, ..ReshapeParams::new(theta_degrees) };
        out.set_owned(LmlReshape { solver: ReshapeSolver::new(&mesh.mesh, values, params)? });
        Ok(LmlStatus::Ok)
    })
}

/// Releases a session. NULL is accepted and ignored. The handle must not be used again.
#[no_mangle]
pub unsafe extern "C" fn lml_reshape_free(reshape: *mut LmlReshape) {
    guarded(|| {
        // SAFETY: `reshape` is NULL or a live handle from lml_reshape_new.
        unsafe { release(reshape) };
        Ok(LmlStatus::Ok)
    });
}

/// Serialises the whole session (original surface, field, parameters, moved positions with their
/// auxiliary variables, tolerance guard, solver damping) as bytes: the magic `"LMLR"`, a
/// little-endian `uint32_t` format version, then the state. Portable across platforms; a restored
/// session continues bit for bit as the original would have.
///
/// Two-call pattern: `*needed` is always set to the byte count; if `out` is NULL or `capacity`
/// (in bytes) is smaller, nothing is copied and `LML_STATUS_BUFFER_TOO_SMALL` is returned. The
/// buffer stays owned by the caller.
/// Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL` or `LML_STATUS_INVALID_ARGUMENT`.
#[no_mangle]
pub unsafe extern "C" fn lml_reshape_save(reshape: *const LmlReshape, out: *mut u8, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `out` writable for `capacity` bytes; writable `needed`.
        let reshape = unsafe { handle(reshape, "reshape") }?;
        unsafe { copy_out(&reshape.solver.to_bytes(), out, capacity, needed, "out") }
    })
}

/// Restores a session from `length` bytes written by `lml_reshape_save` (copied; the caller
/// keeps them). `out` receives the new session, owned by the caller (release with
/// `lml_reshape_free`); set to NULL on failure.
///
/// Every restored quantity is checked: surface, field and parameters as in `lml_reshape_new`,
/// every variable finite and the moved surface valid, counters, guard and damping in range.
///
/// Returns `LML_STATUS_OK`; `LML_STATUS_CORRUPT_DATA` (empty, truncated, damaged or inconsistent
/// bytes, a field session's bytes, or another format version: the message says which);
/// `LML_STATUS_INVALID_ARGUMENT` (NULL `out`, NULL `bytes` with a non-zero length).
#[no_mangle]
pub unsafe extern "C" fn lml_reshape_load(bytes: *const u8, length: usize, out: *mut *mut LmlReshape) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): writable `out`; `bytes` readable for `length` bytes.
        let mut out = unsafe { Out::new(out, "out") }?;
        out.set(std::ptr::null_mut());
        let bytes = unsafe { input(bytes, length, "bytes") }?;
        out.set_owned(LmlReshape { solver: ReshapeSolver::from_bytes(bytes)? });
        Ok(LmlStatus::Ok)
    })
}

/// Runs at most `max_iterations` iterations and writes the state to `*report` (may be NULL).
///
/// Returns `LML_STATUS_MORE` (step again), `LML_STATUS_CONVERGED`, `LML_STATUS_INVALID_ARGUMENT`
/// (NULL or misaligned pointer) or `LML_STATUS_DID_NOT_CONVERGE` (an iteration failed
/// numerically; the surface keeps its last good state).
#[no_mangle]
pub unsafe extern "C" fn lml_reshape_step(reshape: *mut LmlReshape, max_iterations: u32, report: *mut LmlReshapeReport) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle used by this thread only; `report` NULL or writable.
        let reshape = unsafe { handle_mut(reshape, "reshape") }?;
        let report = unsafe { Out::optional(report, "report") }?;
        let step = reshape.solver.step(usize::try_from(max_iterations).unwrap_or(usize::MAX)).map_err(step_failure)?;
        if let Some(mut report) = report {
            report.set(LmlReshapeReport::from(&step));
        }
        Ok(if step.converged { LmlStatus::Converged } else { LmlStatus::More })
    })
}

/// Writes the state after the last step (or after creation) to `*report`.
/// Returns `LML_STATUS_OK` or `LML_STATUS_INVALID_ARGUMENT` (NULL argument).
#[no_mangle]
pub unsafe extern "C" fn lml_reshape_report(reshape: *const LmlReshape, report: *mut LmlReshapeReport) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; writable `report`.
        let reshape = unsafe { handle(reshape, "reshape") }?;
        unsafe { Out::new(report, "report") }?.set(LmlReshapeReport::from(reshape.solver.report()));
        Ok(LmlStatus::Ok)
    })
}

/// Copies the current vertex positions (xyz per vertex, `3 n` doubles, in the mesh's units) into
/// `xyz` with the two-call pattern: `*needed` receives `3 n`; with `capacity` below it nothing is
/// copied and `LML_STATUS_BUFFER_TOO_SMALL` is returned (`xyz` may be NULL then). Returns
/// `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL` or `LML_STATUS_INVALID_ARGUMENT` (NULL
/// session or `needed`).
#[no_mangle]
pub unsafe extern "C" fn lml_reshape_positions(reshape: *const LmlReshape, xyz: *mut f64, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `xyz` writable for `capacity` doubles; `needed` writable.
        let reshape = unsafe { handle(reshape, "reshape") }?;
        unsafe { copy_out(&flat_xyz(&reshape.solver.positions()), xyz, capacity, needed, "xyz") }
    })
}

/// Copies the distance of every vertex from the original surface (`n` doubles, the mesh's
/// units) into `values` with the two-call pattern as `lml_reshape_positions`.
#[no_mangle]
pub unsafe extern "C" fn lml_reshape_deviations(reshape: *const LmlReshape, values: *mut f64, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `values` writable for `capacity` doubles; `needed` writable.
        let reshape = unsafe { handle(reshape, "reshape") }?;
        unsafe { copy_out(&reshape.solver.deviations(), values, capacity, needed, "values") }
    })
}
