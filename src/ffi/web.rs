//! 3-webs (paper Sec. 4.2) on `LmlNet` sessions: three families whose fields hold
//! `F + G + H = 0` (Eq. 18), created with `lml_web_new` and stepped, saved and read like a net;
//! the even-pace levels of the web and the level curves at them (the base curves of each family's
//! strips).

use super::curves::{extract, LmlCurves, LML_MAX_LEVELS};
use super::failure::Failure;
use super::guard::guarded;
use super::mesh::LmlMesh;
use super::net::{create, LmlNet};
use super::raw::{copy_out, handle, input, Out};
use super::status::LmlStatus;
use crate::field::StepReport;
use crate::net::{web_levels, WebLevels, WebReport};

/// The state of a 3-web after `lml_net_step` beyond what `LmlNetReport` says of its first two
/// families (written by the library; the caller owns the struct). Angles in degrees.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LmlWebReport {
    /// RMS and maximum of the third family's |θ_measured − θ| over its measured vertices.
    pub angle_error_rms_degrees: f64,
    pub angle_error_max_degrees: f64,
    /// Singular vertices of the third field.
    pub singular_vertex_count: u64,
    /// Largest and RMS |F + G + H| over the vertices (Eq. 18), relative to the largest of the
    /// three fields' ranges.
    pub residual_max: f64,
    pub residual_rms: f64,
    /// The factor on the third field's terms in the weight stage in force (it grows to 1 at the
    /// final stage: the third family joins gradually).
    pub third_family_factor: f64,
    /// Index 0: how the third family crosses the first; 1: how it crosses the second. Smallest and
    /// area-weighted mean unsigned intersection angle over the faces.
    pub min_intersection_degrees: [f64; 2],
    pub mean_intersection_degrees: [f64; 2],
    /// Faces where the third family crosses the first (0) or the second (1) below the minimum angle.
    pub faces_below_min: [u64; 2],
}

impl LmlWebReport {
    fn new(web: &WebReport, third: &StepReport) -> LmlWebReport {
        LmlWebReport {
            angle_error_rms_degrees: third.angle_error_rms_degrees,
            angle_error_max_degrees: third.angle_error_max_degrees,
            singular_vertex_count: third.singular_vertices.len() as u64,
            residual_max: web.residual_max,
            residual_rms: web.residual_rms,
            third_family_factor: web.third_family_factor,
            min_intersection_degrees: web.intersections.map(|i| i.min_degrees),
            mean_intersection_degrees: web.intersections.map(|i| i.mean_degrees),
            faces_below_min: web.intersections.map(|i| i.faces_below_min as u64),
        }
    }
}

/// Family `k` of a 3-web (the argument `name`) as an index, or the failure naming it.
pub(super) fn web_family(k: u32, name: &str) -> Result<usize, Failure> {
    if k > 2 {
        return Err(Failure::argument(name, format!("a 3-web has families 0, 1 and 2, got {k}")));
    }
    Ok(k as usize)
}

/// The even-pace levels of the 3-web `net` (`lml_web_levels`) with its three fields, every
/// argument checked and named.
pub(super) fn levels_of(net: &LmlNet, count_f: usize, count_h: usize, kagome: u32) -> Result<(WebLevels, [Vec<f64>; 3]), Failure> {
    let fields = net.web_fields()?;
    for (name, count) in [("count_f", count_f), ("count_h", count_h)] {
        if !(1..=LML_MAX_LEVELS).contains(&count) {
            return Err(Failure::argument(name, format!("must lie in [1, {LML_MAX_LEVELS}] (LML_MAX_LEVELS), got {count}")));
        }
    }
    if kagome > 1 {
        return Err(Failure::argument("kagome", format!("must be 0 (a 3-web of triangles) or 1 (a Kagome pattern), got {kagome}")));
    }
    let levels = web_levels(&net.mesh, &fields[0], &fields[1], &fields[2], [count_f, count_h], kagome == 1)?;
    Ok((levels, fields))
}

/// Starts a 3-web optimisation (paper Sec. 4.2) with the default weights: fields F and H of the
/// first two families and G of the third, the diagonal one, held to F + G + H = 0 (Eq. 18) at
/// every vertex. The result is an `LmlNet` session: step it with `lml_net_step`, read it with
/// `lml_net_report` (the first two families), `lml_net_web_report` (Eq. 18 and the third family)
/// and `lml_net_field` (k = 0, 1, 2), save it with `lml_net_save`, release it with `lml_net_free`.
///
/// - `mesh`: the surface (copied).
/// - `thetas`: 3 doubles, the families of F, H and G by their angles θ in [0°, 180°] as in
///   `lml_net_new` (0° and 180° asymptotic curves, 90° geodesics, others pseudo-geodesics).
///   E.g. {0, 0, 90}: an AAG web. Copied.
/// - `initial_fields`: `2 n` doubles, F's `n` values (one per vertex) then H's, as in
///   `lml_net_new` (e.g. from `lml_net_start` at the first two θ); G starts as −F − H, all three
///   in one common scale. Copied.
/// - `min_intersection_degrees`: minimum intersection angle of every pair of families, in
///   [0°, 90°).
/// - `intersection_degrees`: target intersection angle of F and H in (0°, 180°) held as a weak
///   term, or NaN for none.
/// - `out`: receives the new session (release with `lml_net_free`); NULL on failure.
///
/// Returns `LML_STATUS_OK`; `LML_STATUS_INVALID_ARGUMENT` (NULL pointer, `n` ≠ vertex count, a
/// value out of range, naming it: `thetas[i]` for a θ); `LML_STATUS_SINGULAR_FIELD` (a constant
/// field).
#[no_mangle]
pub unsafe extern "C" fn lml_web_new(
    mesh: *const LmlMesh,
    thetas: *const f64,
    initial_fields: *const f64,
    n: usize,
    min_intersection_degrees: f64,
    intersection_degrees: f64,
    out: *mut *mut LmlNet,
) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): the pointer contracts are those documented above.
        let thetas = || {
            let t = unsafe { input(thetas, 3, "thetas") }?;
            Ok(vec![("thetas[0]", t[0]), ("thetas[1]", t[1]), ("thetas[2]", t[2])])
        };
        unsafe { create(mesh, thetas, initial_fields, n, min_intersection_degrees, intersection_degrees, out) }
    })
}

/// Writes a 3-web's state after the last `lml_net_step` (or after creation) to `*report`.
/// Returns `LML_STATUS_OK` or `LML_STATUS_INVALID_ARGUMENT` (NULL argument, or `net` a net of two
/// families, which has no third family).
#[no_mangle]
pub unsafe extern "C" fn lml_net_web_report(net: *const LmlNet, report: *mut LmlWebReport) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; writable `report`.
        let net = unsafe { handle(net, "net") }?;
        let mut report = unsafe { Out::new(report, "report") }?;
        let (web, third) = net.web_report()?;
        report.set(LmlWebReport::new(web, third));
        Ok(LmlStatus::Ok)
    })
}

/// Copies the even-pace levels of family `k` (0: F, 1: H, 2: G) of a 3-web's current fields into
/// `levels`, increasing. F's and H's levels share one pace, the smaller of `range / (count + 1)`
/// for `count_f` levels of F and `count_h` of H, each spread centred over its field's range, so
/// that the diagonals of their net are G's levels (with `kagome` = 1 the diagonals shifted by half
/// a pace: a Kagome pattern, whose three families never meet at one point). The same arguments
/// give the same levels in `lml_curves_new_from_web` and `lml_strip_web_new` while the session is
/// not stepped.
///
/// - `count_f`, `count_h`: in [1, `LML_MAX_LEVELS`]; the family with the wider range at that
///   pace gets more levels than asked.
/// - `kagome`: 0 (a 3-web of triangles) or 1 (a Kagome pattern of triangles and hexagons).
/// - `k`: the family, 0, 1 or 2.
///
/// Two-call pattern: `*needed` receives the level count; with `capacity` below it nothing is
/// copied and `LML_STATUS_BUFFER_TOO_SMALL` is returned (`levels` may be NULL then).
/// Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL`, `LML_STATUS_INVALID_ARGUMENT` (NULL
/// `net` or `needed`, `net` a net of two families, a count, `kagome` or `k` out of range: named)
/// or `LML_STATUS_SINGULAR_FIELD` (a field has become constant).
#[no_mangle]
pub unsafe extern "C" fn lml_web_levels(
    net: *const LmlNet,
    count_f: usize,
    count_h: usize,
    kagome: u32,
    k: u32,
    levels: *mut f64,
    capacity: usize,
    needed: *mut usize,
) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `levels` writable for `capacity` doubles; `needed` writable.
        let net = unsafe { handle(net, "net") }?;
        let (web, _) = levels_of(net, count_f, count_h, kagome)?;
        unsafe { copy_out(&web.levels[web_family(k, "k")?], levels, capacity, needed, "levels") }
    })
}

/// Extracts the level curves of field `k` (0: F, 1: H, 2: G) of a 3-web at its even-pace levels
/// (`lml_web_levels` with the same `count_f`, `count_h` and `kagome`): the base curves of that
/// family's strips (build them with `lml_strips_new` at the family's θ, then the web with
/// `lml_strip_web_new`). `spacing` as in `lml_curves_new`: 0 keeps the polylines' own vertices, a
/// positive spacing resamples them at about that arc length. `out` receives the new curves
/// (release with `lml_curves_free`); NULL on failure.
///
/// Returns `LML_STATUS_OK`; `LML_STATUS_INVALID_ARGUMENT` (NULL pointer, `net` a net of two
/// families, a count, `kagome` or `k` out of range, `spacing` as in `lml_curves_new`: named);
/// `LML_STATUS_SINGULAR_FIELD` (a field has become constant).
#[no_mangle]
pub unsafe extern "C" fn lml_curves_new_from_web(
    net: *const LmlNet,
    k: u32,
    count_f: usize,
    count_h: usize,
    kagome: u32,
    spacing: f64,
    out: *mut *mut LmlCurves,
) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): writable `out`; live `net` handle.
        let mut out = unsafe { Out::new(out, "out") }?;
        out.set(std::ptr::null_mut());
        let net = unsafe { handle(net, "net") }?;
        let (web, fields) = levels_of(net, count_f, count_h, kagome)?;
        let k = web_family(k, "k")?;
        out.set_owned(extract(&net.mesh, &fields[k], |_| Ok(web.levels[k].clone()), spacing)?);
        Ok(LmlStatus::Ok)
    })
}
