//! `LmlNet`: a net session of two families (paper Sec. 4.1) or a 3-web of three (Sec. 4.2),
//! stepped like `LmlField`: create from two start fields, step until converged, read each field,
//! free.

use super::guard::guarded;
use super::mesh::LmlMesh;
use super::raw::{copy_out, handle, handle_mut, input, release, Out};
use super::status::LmlStatus;
use super::failure::Failure;
use crate::field::{Family, StepReport};
use crate::initialisation::{SearchError, SearchOptions};
use crate::mesh::TriMesh;
use crate::net::{net_start, NetParams, NetReport, NetSolver, WebReport};
use std::sync::Arc;

/// A net optimisation session (opaque): a copy of the mesh, the two fields (three for a 3-web),
/// their auxiliary variables and the solver state. Create it with `lml_net_new` or
/// `lml_web_new`, release it with `lml_net_free`.
pub struct LmlNet {
    solver: NetSolver,
    /// The surface, shared with the curves extracted from the net's fields.
    pub(crate) mesh: Arc<TriMesh>,
}

impl LmlNet {
    /// The number of families: 2 for a net, 3 for a 3-web.
    pub(crate) fn family_count(&self) -> usize {
        self.solver.params().families.len()
    }

    /// Field `k` (below the family count), or the failure naming `k`.
    pub(crate) fn field(&self, k: u32) -> Result<Vec<f64>, Failure> {
        match self.family_count() {
            count if (k as usize) < count => Ok(self.solver.field(k as usize)),
            2 => Err(Failure::argument("k", format!("a net of two families has fields 0 and 1, got {k}"))),
            _ => Err(Failure::argument("k", format!("a 3-web has fields 0, 1 and 2, got {k}"))),
        }
    }

    /// A 3-web's last report (after the last step, or the creation): its Eq. 18 residual and
    /// third-family crossings, and the third family's own report; the failure naming `net` for a
    /// net of two families.
    pub(crate) fn web_report(&self) -> Result<(&WebReport, &StepReport), Failure> {
        let report = self.solver.report();
        match (&report.web, report.families.get(2)) {
            (Some(web), Some(third)) => Ok((web, third)),
            _ => Err(not_a_web()),
        }
    }

    /// A 3-web's three fields, or the failure naming `net` for a net of two families.
    pub(crate) fn web_fields(&self) -> Result<[Vec<f64>; 3], Failure> {
        if self.family_count() != 3 {
            return Err(not_a_web());
        }
        Ok([0, 1, 2].map(|k| self.solver.field(k)))
    }
}

/// The failure of a web function given a net of two families.
fn not_a_web() -> Failure {
    Failure::argument("net", "is a net of two families, not a 3-web (create one with lml_web_new)")
}

/// The family of `theta_degrees` (the argument `name`) as `lml_net_new` reads it: 0° and 180°
/// asymptotic, 90° geodesic, else pseudo-geodesic; NaN or outside [0°, 180°] is refused.
pub(super) fn family(theta_degrees: f64, name: &str) -> Result<Family, Failure> {
    if !(0.0..=180.0).contains(&theta_degrees) {
        return Err(Failure::argument(name, format!("must lie in [0, 180], got {theta_degrees}")));
    }
    Ok(Family::from_theta(theta_degrees))
}

/// The parameters of a net (two `thetas`) or a 3-web (three: the third the diagonal family),
/// each θ given with its argument's name, with the default weights and the angles of
/// `lml_net_new`, checked.
fn params(thetas: &[(&str, f64)], min_intersection_degrees: f64, intersection_degrees: f64) -> Result<NetParams, Failure> {
    let families = thetas.iter().map(|&(name, theta)| family(theta, name)).collect::<Result<Vec<Family>, Failure>>()?;
    let mut params = match families[..] {
        [f, g] => NetParams::new(f, g),
        [f, h, g] => NetParams::web(f, h, g),
        _ => unreachable!("a net has two families and a 3-web three"),
    };
    params.min_intersection_degrees = min_intersection_degrees;
    params.intersection_degrees = (!intersection_degrees.is_nan()).then_some(intersection_degrees);
    params.validate()?;
    Ok(params)
}

/// A new session of the families `thetas` (read once the other arguments are checked; see
/// [`params`]) from the two start fields `initial_fields` (`2 n` doubles), handed to `out`: the
/// body of `lml_net_new` and `lml_web_new`.
///
/// # Safety
/// The pointer contracts of `lml_net_new`.
pub(super) unsafe fn create(
    mesh: *const LmlMesh,
    thetas: impl FnOnce() -> Result<Vec<(&'static str, f64)>, Failure>,
    initial_fields: *const f64,
    n: usize,
    min_intersection_degrees: f64,
    intersection_degrees: f64,
    out: *mut *mut LmlNet,
) -> Result<LmlStatus, Failure> {
    // SAFETY (all blocks): forwarded contracts.
    let mut out = unsafe { Out::new(out, "out") }?;
    out.set(std::ptr::null_mut());
    let mesh = unsafe { handle(mesh, "mesh") }?;
    if n != mesh.mesh.vertex_count() {
        return Err(Failure::argument("n", format!("{n} values per field, but the mesh has {} vertices", mesh.mesh.vertex_count())));
    }
    // 2 n cannot overflow: n is the vertex count of a mesh in memory.
    let fields = unsafe { input(initial_fields, 2 * n, "initial_fields") }?;
    let params = params(&thetas()?, min_intersection_degrees, intersection_degrees)?;
    let (first, second) = fields.split_at(n);
    let solver = NetSolver::new(&mesh.mesh, &[first.to_vec(), second.to_vec()], params)?;
    out.set_owned(LmlNet { solver, mesh: Arc::new(mesh.mesh.clone()) });
    Ok(LmlStatus::Ok)
}

/// The state of a net optimisation after `lml_net_step` (written by the library; the caller owns
/// the struct). Angles in degrees; index 0 is the first field, 1 the second (of a 3-web: F and H,
/// whose crossings the intersection fields describe; `lml_net_web_report` gives the third family).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LmlNetReport {
    /// Iterations run since the session was created.
    pub iterations: u64,
    /// 1 when the final stage has converged (further steps do nothing), else 0.
    pub converged: u64,
    /// RMS and maximum of each family's |θ_measured − θ| over its measured vertices.
    pub angle_error_rms_degrees: [f64; 2],
    pub angle_error_max_degrees: [f64; 2],
    /// Singular vertices of each field.
    pub singular_vertex_count: [u64; 2],
    /// Smallest and area-weighted mean unsigned intersection angle of the two families over the faces.
    pub min_intersection_degrees: f64,
    pub mean_intersection_degrees: f64,
    /// Faces where the families cross below the minimum angle.
    pub faces_below_min: u64,
    /// The weighted energy being minimised.
    pub energy_total: f64,
}

impl From<&NetReport> for LmlNetReport {
    fn from(r: &NetReport) -> LmlNetReport {
        let family = |k: usize| r.families.get(k);
        LmlNetReport {
            iterations: r.iterations as u64,
            converged: u64::from(r.converged),
            angle_error_rms_degrees: [0, 1].map(|k| family(k).map_or(0.0, |f| f.angle_error_rms_degrees)),
            angle_error_max_degrees: [0, 1].map(|k| family(k).map_or(0.0, |f| f.angle_error_max_degrees)),
            singular_vertex_count: [0, 1].map(|k| family(k).map_or(0, |f| f.singular_vertices.len() as u64)),
            min_intersection_degrees: r.intersection.min_degrees,
            mean_intersection_degrees: r.intersection.mean_degrees,
            faces_below_min: r.intersection.faces_below_min as u64,
            energy_total: r.total_energy,
        }
    }
}

/// Starts a net optimisation of two families with the default weights.
///
/// - `mesh`: the surface (copied).
/// - `theta_degrees_f`, `theta_degrees_g`: each family by its angle θ in [0°, 180°]: 0° and 180°
///   asymptotic curves, 90° geodesics, others pseudo-geodesics of that signed angle.
/// - `initial_fields`: `2 n` doubles, the first field's `n` values (one per vertex) then the
///   second's; each not constant, finite, magnitude at most 1e100. Copied.
/// - `min_intersection_degrees`: minimum intersection angle, in [0°, 90°) (30 by default in Rust).
/// - `intersection_degrees`: target intersection angle in (0°, 180°) held as a weak term, or NaN
///   for none.
/// - `out`: receives the new session (release with `lml_net_free`); NULL on failure.
///
/// Returns `LML_STATUS_OK`; `LML_STATUS_INVALID_ARGUMENT` (NULL pointer, `n` ≠ vertex count, a
/// value out of range, naming it); `LML_STATUS_SINGULAR_FIELD` (a constant field).
#[no_mangle]
pub unsafe extern "C" fn lml_net_new(
    mesh: *const LmlMesh,
    theta_degrees_f: f64,
    theta_degrees_g: f64,
    initial_fields: *const f64,
    n: usize,
    min_intersection_degrees: f64,
    intersection_degrees: f64,
    out: *mut *mut LmlNet,
) -> LmlStatus {
    guarded(|| {
        // SAFETY: the pointer contracts are those documented above.
        let thetas = || Ok(vec![("theta_degrees_f", theta_degrees_f), ("theta_degrees_g", theta_degrees_g)]);
        unsafe { create(mesh, thetas, initial_fields, n, min_intersection_degrees, intersection_degrees, out) }
    })
}

/// The default start of a net (Rust `net_start`): the first family's winner of the default start
/// search and the second family's among the candidates crossing it at 45° or more on average;
/// if that pair is not acceptable (a family scores above 3, or the families run within 10° of the
/// minimum angle over more than 1 % of the area), pairs of heights ±30° about each principal axis
/// in every orientation; each pair judged by a short net solve, and the fields are where the
/// winner's ended. Where every pair has a nearly straight family (a surface that bends little at
/// these angles across the model), the best of those is taken rather than none. Families by θ as
/// in `lml_net_new`. Writes `2 n`
/// doubles (the first field, then the second) to `fields` with the two-call pattern: `*needed`
/// receives `2 n`; with `capacity` below it nothing is computed or copied and
/// `LML_STATUS_BUFFER_TOO_SMALL` is returned (`fields` may be NULL then). Runs a few dozen short
/// solves: seconds on meshes of thousands of vertices.
///
/// Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL`, `LML_STATUS_INVALID_ARGUMENT` (NULL
/// mesh or `needed`, θ or the minimum angle out of range, named) or `LML_STATUS_SINGULAR_FIELD`
/// (no candidate leads to a family, not even a nearly straight one; the message gives every
/// candidate's reason).
#[no_mangle]
pub unsafe extern "C" fn lml_net_start(
    mesh: *const LmlMesh,
    theta_degrees_f: f64,
    theta_degrees_g: f64,
    min_intersection_degrees: f64,
    fields: *mut f64,
    capacity: usize,
    needed: *mut usize,
) -> LmlStatus {
    guarded(|| {
        // SAFETY (all blocks): live mesh handle; `fields` writable for `capacity` doubles; `needed` writable.
        let mesh = unsafe { handle(mesh, "mesh") }?;
        let params = params(&[("theta_degrees_f", theta_degrees_f), ("theta_degrees_g", theta_degrees_g)], min_intersection_degrees, f64::NAN)?;
        let n = mesh.mesh.vertex_count();
        if capacity < 2 * n || fields.is_null() {
            // Nothing to compute: report the size only.
            return unsafe { copy_out(&vec![0.0; 2 * n], fields, capacity, needed, "fields") };
        }
        let started = net_start(&mesh.mesh, &params, &SearchOptions::default()).map_err(|e| match e {
            SearchError::Field(error) => Failure::from(error),
            other => Failure::new(LmlStatus::SingularField, other.to_string()),
        })?;
        let flat: Vec<f64> = started.concat();
        unsafe { copy_out(&flat, fields, capacity, needed, "fields") }
    })
}

/// Releases a session. NULL is accepted and ignored. The handle must not be used again.
#[no_mangle]
pub unsafe extern "C" fn lml_net_free(net: *mut LmlNet) {
    guarded(|| {
        // SAFETY: `net` is NULL or a live handle from lml_net_new, lml_web_new or lml_net_load.
        unsafe { release(net) };
        Ok(LmlStatus::Ok)
    });
}

/// Serialises the whole session (mesh, every field with its auxiliary variables, parameters,
/// the intersection target's orientation, weight stage, solver damping) as bytes: the magic
/// `"LMLN"`, a little-endian `uint32_t` format version, then the state. Portable across
/// platforms; a restored session continues bit for bit as the original would have.
///
/// Two-call pattern: `*needed` is always set to the byte count; if `out` is NULL or `capacity`
/// (in bytes) is smaller, nothing is copied and `LML_STATUS_BUFFER_TOO_SMALL` is returned. The
/// buffer stays owned by the caller.
/// Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL` or `LML_STATUS_INVALID_ARGUMENT`.
#[no_mangle]
pub unsafe extern "C" fn lml_net_save(net: *const LmlNet, out: *mut u8, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `out` writable for `capacity` bytes; writable `needed`.
        let net = unsafe { handle(net, "net") }?;
        unsafe { copy_out(&net.solver.to_bytes(), out, capacity, needed, "out") }
    })
}

/// Restores a session from `length` bytes written by `lml_net_save` (copied; the caller keeps
/// them). `out` receives the new session, owned by the caller (release with `lml_net_free`); set
/// to NULL on failure.
///
/// Every restored quantity is checked: the mesh as in `lml_mesh_new`, parameters as in
/// `lml_net_new` (or `lml_web_new` for a 3-web: the restored session has the saved one's family
/// count), scale factors normal and positive, every value finite, the fields within ±1e100,
/// counters and damping in range.
///
/// Returns `LML_STATUS_OK`; `LML_STATUS_CORRUPT_DATA` (empty, truncated, damaged or inconsistent
/// bytes, another kind of session, or another format version: the message says which);
/// `LML_STATUS_INVALID_ARGUMENT` (NULL `out`, NULL `bytes` with a non-zero length).
#[no_mangle]
pub unsafe extern "C" fn lml_net_load(bytes: *const u8, length: usize, out: *mut *mut LmlNet) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): writable `out`; `bytes` readable for `length` bytes.
        let mut out = unsafe { Out::new(out, "out") }?;
        out.set(std::ptr::null_mut());
        let bytes = unsafe { input(bytes, length, "bytes") }?;
        let solver = NetSolver::from_bytes(bytes)?;
        out.set_owned(LmlNet { mesh: Arc::new(solver.mesh()), solver });
        Ok(LmlStatus::Ok)
    })
}

/// Runs at most `max_iterations` iterations and writes the state to `*report` (may be NULL).
///
/// Returns `LML_STATUS_MORE` (step again), `LML_STATUS_CONVERGED`, `LML_STATUS_INVALID_ARGUMENT`
/// (NULL or misaligned pointer) or `LML_STATUS_DID_NOT_CONVERGE` (an iteration failed
/// numerically; the fields keep their last good state).
#[no_mangle]
pub unsafe extern "C" fn lml_net_step(net: *mut LmlNet, max_iterations: u32, report: *mut LmlNetReport) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle used by this thread only; `report` NULL or writable.
        let net = unsafe { handle_mut(net, "net") }?;
        let report = unsafe { Out::optional(report, "report") }?;
        let step = net.solver.step(usize::try_from(max_iterations).unwrap_or(usize::MAX))?;
        if let Some(mut report) = report {
            report.set(LmlNetReport::from(&step));
        }
        Ok(if step.converged { LmlStatus::Converged } else { LmlStatus::More })
    })
}

/// Writes the state after the last step (or after creation) to `*report`.
/// Returns `LML_STATUS_OK` or `LML_STATUS_INVALID_ARGUMENT` (NULL argument).
#[no_mangle]
pub unsafe extern "C" fn lml_net_report(net: *const LmlNet, report: *mut LmlNetReport) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; writable `report`.
        let net = unsafe { handle(net, "net") }?;
        unsafe { Out::new(report, "report") }?.set(LmlNetReport::from(net.solver.report()));
        Ok(LmlStatus::Ok)
    })
}

/// Copies field `k` (below `lml_net_family_count`: 0 or 1 for a net, 0, 1 or 2 for a 3-web; one
/// value per vertex, in the scale of its start field, a 3-web's three in one common scale) into
/// `values` with the two-call pattern: `*needed` receives the vertex count; with `capacity`
/// below it nothing is copied and `LML_STATUS_BUFFER_TOO_SMALL` is returned (`values` may be
/// NULL then). Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL` or
/// `LML_STATUS_INVALID_ARGUMENT` (NULL net or `needed`, `k` not below the family count).
#[no_mangle]
pub unsafe extern "C" fn lml_net_field(net: *const LmlNet, k: u32, values: *mut f64, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `values` writable for `capacity` doubles; `needed` writable.
        let net = unsafe { handle(net, "net") }?;
        unsafe { copy_out(&net.field(k)?, values, capacity, needed, "values") }
    })
}

/// Writes the session's number of families to `*count`: 2 for a net (`lml_net_new`), 3 for a
/// 3-web (`lml_web_new`). Returns `LML_STATUS_OK` or `LML_STATUS_INVALID_ARGUMENT` (NULL argument).
#[no_mangle]
pub unsafe extern "C" fn lml_net_family_count(net: *const LmlNet, count: *mut u32) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; writable `count`.
        let net = unsafe { handle(net, "net") }?;
        // 2 or 3 (checked by the solver).
        unsafe { Out::new(count, "count") }?.set(net.family_count() as u32);
        Ok(LmlStatus::Ok)
    })
}
