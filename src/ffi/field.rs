//! `LmlField`: a field solver session (paper Sec. 3.2.2), stepped like an SQLite statement:
//! create, step until converged (reading the field or changing weights in between), free.

use super::failure::Failure;
use super::field_params::{LmlFieldParams, LmlWeights};
use super::guard::guarded;
use super::layout::flat_xyz;
use super::mesh::LmlMesh;
use super::raw::{copy_out, handle, handle_mut, input, release, Out};
use super::report::LmlReport;
use super::status::LmlStatus;
use crate::field::FieldSolver;
use crate::mesh::TriMesh;
use std::sync::Arc;

/// A field optimisation session (opaque): a copy of the mesh, the scalar field, the auxiliary
/// variables and the solver state. Create it with `lml_field_new` or `lml_field_load`, release
/// it with `lml_field_free`.
pub struct LmlField {
    pub(crate) solver: FieldSolver,
    /// The surface in the caller's units, shared (read-only) with the curves extracted from it.
    pub(crate) mesh: Arc<TriMesh>,
}

impl LmlField {
    /// A handle around `solver`. The mesh is always derived from the solver, so a restored
    /// session yields the same curves, bit for bit, as the one that was saved.
    pub(crate) fn new(solver: FieldSolver) -> LmlField {
        let mesh = Arc::new(solver.mesh());
        LmlField { solver, mesh }
    }
}

/// Starts a field optimisation whose level sets should form the family of `params`.
///
/// - `mesh`: the surface; the session keeps its own copy, so the mesh may be freed afterwards.
/// - `initial_field`: `n` doubles, one value per mesh vertex (in vertex order), not constant,
///   each finite with magnitude at most 1e100; e.g. a height function whose level curves
///   roughly follow the wanted direction. Copied.
/// - `params`: filled by `lml_field_params_default` and possibly edited. Copied.
/// - `out`: receives the new session, owned by the caller (release with `lml_field_free`);
///   set to NULL on failure.
///
/// Returns `LML_STATUS_OK`; `LML_STATUS_INVALID_ARGUMENT` (NULL pointer, `n` ≠ vertex count,
/// a non-finite value or one beyond ±1e100 (the message names the vertex and the value),
/// parameter out of range (named)); `LML_STATUS_SINGULAR_FIELD` (constant field, no level
/// curves).
#[no_mangle]
pub unsafe extern "C" fn lml_field_new(
    mesh: *const LmlMesh,
    initial_field: *const f64,
    n: usize,
    params: *const LmlFieldParams,
    out: *mut *mut LmlField,
) -> LmlStatus {
    guarded(|| {
        // SAFETY (all blocks): the pointer contracts are those documented above.
        let mut out = unsafe { Out::new(out, "out") }?;
        out.set(std::ptr::null_mut());
        let mesh = unsafe { handle(mesh, "mesh") }?;
        let initial_field = unsafe { input(initial_field, n, "initial_field") }?;
        let params = unsafe { handle(params, "params") }?.to_params()?;
        out.set_owned(LmlField::new(FieldSolver::new(&mesh.mesh, initial_field, params)?));
        Ok(LmlStatus::Ok)
    })
}

/// Releases a session. NULL is accepted and ignored. The handle must not be used (or freed) again.
#[no_mangle]
pub unsafe extern "C" fn lml_field_free(field: *mut LmlField) {
    guarded(|| {
        // SAFETY: `field` is NULL or a live handle from lml_field_new / lml_field_load.
        unsafe { release(field) };
        Ok(LmlStatus::Ok)
    });
}

/// Runs at most `max_iterations` Levenberg–Marquardt iterations (0 only reports) and writes the
/// state to `*report` (optional: NULL skips it).
fn run(field: &mut LmlField, max_iterations: u32, report: Option<Out<LmlReport>>) -> Result<bool, Failure> {
    let max = usize::try_from(max_iterations).unwrap_or(usize::MAX);
    let step = field.solver.step(max)?;
    if let Some(mut report) = report {
        report.set(LmlReport::from(&step));
    }
    Ok(step.converged)
}

/// Runs at most `max_iterations` iterations of the optimisation and reports its state in
/// `*report` (caller-owned; may be NULL when not wanted; written when the call returns
/// `LML_STATUS_MORE` or `LML_STATUS_CONVERGED`). Between steps the caller may read the field,
/// change the weights, save the session, or stop.
///
/// Returns `LML_STATUS_MORE` (not converged yet: step again), `LML_STATUS_CONVERGED` (further
/// steps do nothing), `LML_STATUS_INVALID_ARGUMENT` (NULL or misaligned pointer), or
/// `LML_STATUS_DID_NOT_CONVERGE` (an iteration failed numerically; the field keeps its last
/// good state).
#[no_mangle]
pub unsafe extern "C" fn lml_field_step(field: *mut LmlField, max_iterations: u32, report: *mut LmlReport) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle used by this thread only; `report` NULL or writable.
        let field = unsafe { handle_mut(field, "field") }?;
        let report = unsafe { Out::optional(report, "report") }?;
        Ok(if run(field, max_iterations, report)? { LmlStatus::Converged } else { LmlStatus::More })
    })
}

/// Like `lml_field_step`, for callers that want the answer in one call: runs until convergence
/// but at most `max_iterations` iterations, and writes the final state to `*report` (may be NULL;
/// written unless an argument is invalid or an iteration failed numerically).
///
/// Returns `LML_STATUS_CONVERGED`, `LML_STATUS_DID_NOT_CONVERGE` (the budget was used up or an
/// iteration failed; the session stays usable and can be stepped on), or
/// `LML_STATUS_INVALID_ARGUMENT`.
#[no_mangle]
pub unsafe extern "C" fn lml_field_solve(field: *mut LmlField, max_iterations: u32, report: *mut LmlReport) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): as lml_field_step.
        let field = unsafe { handle_mut(field, "field") }?;
        let report = unsafe { Out::optional(report, "report") }?;
        if run(field, max_iterations, report)? {
            return Ok(LmlStatus::Converged);
        }
        let done = field.solver.iterations();
        Err(Failure::new(LmlStatus::DidNotConverge, format!("not converged within {max_iterations} iterations ({done} in all so far)")))
    })
}

/// Writes the state after the last step (or after creation / loading) to `*report`.
/// Returns `LML_STATUS_OK` or `LML_STATUS_INVALID_ARGUMENT` (NULL argument).
#[no_mangle]
pub unsafe extern "C" fn lml_field_report(field: *const LmlField, report: *mut LmlReport) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; writable `report`.
        let field = unsafe { handle(field, "field") }?;
        unsafe { Out::new(report, "report") }?.set(LmlReport::from(field.solver.report()));
        Ok(LmlStatus::Ok)
    })
}

/// Replaces the remaining weight schedule (warm-up stages included) by constant `weights`
/// (paper Eq. 12), held until convergence; the next step starts a new final stage, so a
/// converged session runs again.
///
/// Returns `LML_STATUS_OK` or `LML_STATUS_INVALID_ARGUMENT` (NULL field, a weight negative
/// or not finite (named)); on failure the session is unchanged.
#[no_mangle]
pub unsafe extern "C" fn lml_field_set_weights(field: *mut LmlField, weights: LmlWeights) -> LmlStatus {
    guarded(|| {
        // SAFETY: live handle used by this thread only.
        let field = unsafe { handle_mut(field, "field") }?;
        field.solver.set_weights(weights.into())?;
        Ok(LmlStatus::Ok)
    })
}

/// Copies the current field: one double per mesh vertex, in the scale of the initial field.
///
/// Two-call pattern: `*needed` is always set to the vertex count; if `out` is NULL or
/// `capacity` (in doubles) is smaller, nothing is copied and `LML_STATUS_BUFFER_TOO_SMALL` is
/// returned. The buffer stays owned by the caller.
/// Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL` or `LML_STATUS_INVALID_ARGUMENT`.
#[no_mangle]
pub unsafe extern "C" fn lml_field_values(field: *const LmlField, out: *mut f64, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `out` writable for `capacity` doubles; writable `needed`.
        let field = unsafe { handle(field, "field") }?;
        unsafe { copy_out(&field.solver.field(), out, capacity, needed, "out") }
    })
}

/// Copies the unit binormal of the level curve at each vertex: `3 * vertex_count` doubles,
/// `(x, y, z)` of vertex `i` at `out[3i..3i+3]`; zero vectors at boundary and singular vertices
/// and where the level curve is straight.
///
/// Two-call pattern as `lml_field_values` (`capacity` and `*needed` count doubles).
/// Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL` or `LML_STATUS_INVALID_ARGUMENT`.
#[no_mangle]
pub unsafe extern "C" fn lml_field_binormals(field: *const LmlField, out: *mut f64, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): as lml_field_values.
        let field = unsafe { handle(field, "field") }?;
        unsafe { copy_out(&flat_xyz(&field.solver.binormals()), out, capacity, needed, "out") }
    })
}

/// Copies the unit side vector `u` of the Darboux frame (paper Eq. 10) at each vertex, laid out
/// as `lml_field_binormals`; zero vectors at boundary and singular vertices.
///
/// Two-call pattern as `lml_field_values` (`capacity` and `*needed` count doubles).
/// Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL` or `LML_STATUS_INVALID_ARGUMENT`.
#[no_mangle]
pub unsafe extern "C" fn lml_field_side_vectors(field: *const LmlField, out: *mut f64, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): as lml_field_values.
        let field = unsafe { handle(field, "field") }?;
        unsafe { copy_out(&flat_xyz(&field.solver.side_vectors()), out, capacity, needed, "out") }
    })
}

/// Copies the indices of the singular vertices of the last report (interior vertices whose
/// level curve does not cross exactly two star edges).
///
/// Two-call pattern as `lml_field_values` (`capacity` and `*needed` count indices; `*needed`
/// may be 0, and then `out` may be NULL and the call succeeds).
/// Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL` or `LML_STATUS_INVALID_ARGUMENT`.
#[no_mangle]
pub unsafe extern "C" fn lml_field_singular_vertices(field: *const LmlField, out: *mut u32, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `out` writable for `capacity` indices; writable `needed`.
        let field = unsafe { handle(field, "field") }?;
        unsafe { copy_out(&field.solver.report().singular_vertices, out, capacity, needed, "out") }
    })
}
