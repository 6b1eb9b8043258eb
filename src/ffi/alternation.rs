//! `LmlAlternation`: the alternating schedule of paper Sec. 3.3, field steps (the surface fixed)
//! and surface steps (the field fixed) in turn, stepped a few rounds at a time like
//! `LmlReshape`: create from a mesh and a field, step until converged, read the moved positions,
//! the field and the deviations, free.

use super::guard::guarded;
use super::layout::flat_xyz;
use super::mesh::LmlMesh;
use super::raw::{copy_out, handle, handle_mut, input, release, Out};
use super::report::LmlReport;
use super::reshape::{step_failure, LmlReshapeReport};
use super::status::LmlStatus;
use crate::field::FieldError;
use crate::reshape::{AlternatingParams, AlternatingReport, AlternatingSolver, ReshapeParams, Tolerance};

/// An alternating field and surface optimisation (opaque): the original surface, the moved one,
/// the field and the parameters of both kinds of step. Create it with `lml_alternation_new`,
/// release it with `lml_alternation_free`.
pub struct LmlAlternation {
    solver: AlternatingSolver,
}

/// The state of an alternation after `lml_alternation_step` (written by the library; the caller
/// owns the struct).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LmlAlternationReport {
    /// Rounds (a field step and a surface step each) run since the session was created.
    pub rounds: u64,
    /// Rounds run by the last call.
    pub rounds_this_step: u64,
    /// 1 when both steps of the last round converged (further steps do nothing), else 0.
    pub converged: u64,
    /// The last field step (its iterations counted from the start of that step; all zero before
    /// the first round).
    pub field: LmlReport,
    /// The last surface step: deviations from the original surface, in the mesh's units.
    pub surface: LmlReshapeReport,
}

impl From<&AlternatingReport> for LmlAlternationReport {
    fn from(r: &AlternatingReport) -> LmlAlternationReport {
        LmlAlternationReport {
            rounds: r.rounds as u64,
            rounds_this_step: r.rounds_this_step as u64,
            converged: u64::from(r.converged),
            field: LmlReport::from(&r.field),
            surface: LmlReshapeReport::from(&r.surface),
        }
    }
}

/// Starts field and surface steps in turn on `mesh` from `field`, towards P-curves of the angle
/// θ, with the default field parameters (`lml_field_params_default`'s) and the paper's Table 3
/// surface weights (Fig. 17(b)).
///
/// - `mesh`: the original surface (copied).
/// - `field`: `n` doubles, one per vertex (finite, not constant, magnitude at most 1e100). Copied.
/// - `theta_degrees`: the target angle, in [0°, 180°] (the field steps' family is that of θ:
///   asymptotic at 0° and 180°, geodesic at 90°).
/// - `tolerance`, `tolerance_is_fraction`: the bound on every vertex's distance from the
///   original surface, as in `lml_reshape_new`; it holds through every round.
/// - `iterations_per_step`: most iterations of each field step and of each surface step, ≥ 1.
/// - `out`: receives the new session (release with `lml_alternation_free`); NULL on failure.
///
/// Returns `LML_STATUS_OK`; `LML_STATUS_INVALID_ARGUMENT` (NULL pointer, `n` ≠ vertex count, a
/// value out of range, naming it); `LML_STATUS_SINGULAR_FIELD` (a constant field, or no interior
/// vertex with a regular level curve).
#[no_mangle]
pub unsafe extern "C" fn lml_alternation_new(
    mesh: *const LmlMesh,
    field: *const f64,
    n: usize,
    theta_degrees: f64,
    tolerance: f64,
    tolerance_is_fraction: u32,
    iterations_per_step: u32,
    out: *mut *mut LmlAlternation,
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
        let params = AlternatingParams {
            reshape: ReshapeParams { tolerance, ..ReshapeParams::new(theta_degrees) },
            iterations_per_step: usize::try_from(iterations_per_step).unwrap_or(usize::MAX),
            ..AlternatingParams::new(theta_degrees)
        };
        out.set_owned(LmlAlternation { solver: AlternatingSolver::new(&mesh.mesh, values, params)? });
        Ok(LmlStatus::Ok)
    })
}

/// Releases a session. NULL is accepted and ignored. The handle must not be used again.
#[no_mangle]
pub unsafe extern "C" fn lml_alternation_free(alternation: *mut LmlAlternation) {
    guarded(|| {
        // SAFETY: `alternation` is NULL or a live handle from lml_alternation_new.
        unsafe { release(alternation) };
        Ok(LmlStatus::Ok)
    });
}

/// Runs at most `max_rounds` rounds (fewer once a round converges) and writes the state to
/// `*report` (may be NULL).
///
/// Returns `LML_STATUS_MORE` (step again), `LML_STATUS_CONVERGED`, `LML_STATUS_INVALID_ARGUMENT`
/// (NULL or misaligned pointer) or `LML_STATUS_DID_NOT_CONVERGE` (a step failed numerically; the
/// session keeps the state of its last whole round).
#[no_mangle]
pub unsafe extern "C" fn lml_alternation_step(alternation: *mut LmlAlternation, max_rounds: u32, report: *mut LmlAlternationReport) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle used by this thread only; `report` NULL or writable.
        let alternation = unsafe { handle_mut(alternation, "alternation") }?;
        let report = unsafe { Out::optional(report, "report") }?;
        let step = alternation.solver.step(usize::try_from(max_rounds).unwrap_or(usize::MAX)).map_err(step_failure)?;
        if let Some(mut report) = report {
            report.set(LmlAlternationReport::from(&step));
        }
        Ok(if step.converged { LmlStatus::Converged } else { LmlStatus::More })
    })
}

/// Writes the state after the last step (or after creation) to `*report`.
/// Returns `LML_STATUS_OK` or `LML_STATUS_INVALID_ARGUMENT` (NULL argument).
#[no_mangle]
pub unsafe extern "C" fn lml_alternation_report(alternation: *const LmlAlternation, report: *mut LmlAlternationReport) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; writable `report`.
        let alternation = unsafe { handle(alternation, "alternation") }?;
        unsafe { Out::new(report, "report") }?.set(LmlAlternationReport::from(alternation.solver.report()));
        Ok(LmlStatus::Ok)
    })
}

/// Copies the current vertex positions (xyz per vertex, `3 n` doubles, in the mesh's units) into
/// `xyz` with the two-call pattern of `lml_reshape_positions`.
#[no_mangle]
pub unsafe extern "C" fn lml_alternation_positions(alternation: *const LmlAlternation, xyz: *mut f64, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `xyz` writable for `capacity` doubles; `needed` writable.
        let alternation = unsafe { handle(alternation, "alternation") }?;
        unsafe { copy_out(&flat_xyz(alternation.solver.mesh().positions()), xyz, capacity, needed, "xyz") }
    })
}

/// Copies the current field (`n` doubles, one per vertex) into `values` with the two-call
/// pattern of `lml_reshape_positions`.
#[no_mangle]
pub unsafe extern "C" fn lml_alternation_field(alternation: *const LmlAlternation, values: *mut f64, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `values` writable for `capacity` doubles; `needed` writable.
        let alternation = unsafe { handle(alternation, "alternation") }?;
        unsafe { copy_out(alternation.solver.field(), values, capacity, needed, "values") }
    })
}

/// Copies the distance of every vertex from the original surface (`n` doubles, the mesh's
/// units) into `values` with the two-call pattern of `lml_reshape_positions`.
#[no_mangle]
pub unsafe extern "C" fn lml_alternation_deviations(alternation: *const LmlAlternation, values: *mut f64, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `values` writable for `capacity` doubles; `needed` writable.
        let alternation = unsafe { handle(alternation, "alternation") }?;
        unsafe { copy_out(alternation.solver.deviations(), values, capacity, needed, "values") }
    })
}
