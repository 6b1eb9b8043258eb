//! `LmlStrips`: rectifying developable strips of planar quads along level curves (paper
//! Sec. 3.4, Fig. 20, Eq. 16–17), their flat unrollings and the measures of Table 4.

use super::curves::LmlCurves;
use super::failure::Failure;
use super::guard::guarded;
use super::layout::{flat_xy, flat_xyz, offsets};
use super::raw::{copy_out, handle, release, Out};
use super::status::LmlStatus;
use super::last_error::set_last_error;
use super::strip_metrics::{LmlPatternMetrics, LmlSkippedCurve, LmlStripMetrics, LmlVerdict};
use super::strip_params::LmlStripParams;
use crate::strips::{rectifying_strips, RectifyingStrip, StripPattern};

/// A strip pattern (opaque): one rectifying strip per level curve that could carry one, with
/// its flat unrolling and metrics, and the curves that were skipped. Create it with
/// `lml_strips_new`, release it with `lml_strips_free`. Immutable once created.
///
/// Layout of the arrays: the strips come one after another, in curve order. A strip with `n`
/// centre points has `n` entries in the per-point arrays (centres, rulings, unrolled centres),
/// `2n` vertices (first its boundary on the rulings' side, `left_0 … left_{n−1}`, then the
/// other, `right_0 … right_{n−1}`) in `lml_strips_vertices` and `lml_strips_unrolled_vertices`
/// alike, and `n − 1` quads `(left_j, left_{j+1}, right_{j+1}, right_j)` whose indices address
/// both vertex arrays. Three offset tables (points, vertices, quads) cut the arrays per strip.
pub struct LmlStrips {
    pub(crate) pattern: StripPattern,
    /// θ of the strips' family in degrees (from their parameters), for the bill of materials;
    /// `None` for shading strips (one θ per curve).
    pub(crate) theta_degrees: Option<f64>,
}

/// Builds a rectifying strip on every polyline of `curves` (in parallel; the result does not
/// depend on the thread count): each polyline is optimised into a θ-pseudo-geodesic near the
/// surface the curves were extracted from, rulings in its outer bisecting planes make planar
/// quads, and the strip is cut to `params->width` and unrolled.
///
/// - `curves`: from `lml_curves_new` / `lml_curves_new_uniform` (resample them to the quad
///   length the strips should have); the strips keep no reference to them.
/// - `params`: filled by `lml_strip_params_default` and possibly edited. Copied.
/// - `out`: receives the new strips, owned by the caller (release with `lml_strips_free`); set
///   to NULL on failure.
///
/// A polyline that cannot carry a strip (fewer than 3 points, a zero-length segment, a failed
/// optimisation) does not fail the call: it is listed by `lml_strips_skipped`.
///
/// Returns `LML_STATUS_OK` (every strip's plane within `params->tolerance_degrees` of θ, no
/// flipped quad); `LML_STATUS_NO_ACCEPTABLE_FAMILY` (the strips are built and `*out` is valid,
/// but some miss θ by more than the tolerance or have flipped quads, or no strip could be
/// built: `lml_last_error_message()` names the strips and the worst point and what to try,
/// `lml_strips_verdict` gives the numbers); `LML_STATUS_INVALID_ARGUMENT` (NULL pointer; width
/// not finite or ≤ 0, θ outside [0, 180], tolerance outside (0, 180), a weight negative or not
/// finite, an iteration count above `LML_MAX_STRIP_ROUNDS` / `LML_MAX_STRIP_ITERATIONS` (the
/// parameter is named)).
#[no_mangle]
pub unsafe extern "C" fn lml_strips_new(curves: *const LmlCurves, params: *const LmlStripParams, out: *mut *mut LmlStrips) -> LmlStatus {
    guarded(|| {
        // SAFETY (all blocks): writable `out`; live `curves` handle; readable `params`.
        let mut out = unsafe { Out::new(out, "out") }?;
        out.set(std::ptr::null_mut());
        let curves = unsafe { handle(curves, "curves") }?;
        let params = unsafe { handle(params, "params") }?.to_params();
        let pattern = rectifying_strips(&curves.mesh, &curves.curves, &params)?;
        let status = if pattern.verdict.is_acceptable() {
            LmlStatus::Ok
        } else {
            set_last_error(&pattern.verdict.message());
            LmlStatus::NoAcceptableFamily
        };
        out.set_owned(LmlStrips { pattern, theta_degrees: Some(params.theta_degrees) });
        Ok(status)
    })
}

/// Releases strips. NULL is accepted and ignored. The handle must not be used (or freed) again.
#[no_mangle]
pub unsafe extern "C" fn lml_strips_free(strips: *mut LmlStrips) {
    guarded(|| {
        // SAFETY: `strips` is NULL or a live handle from lml_strips_new.
        unsafe { release(strips) };
        Ok(LmlStatus::Ok)
    });
}

/// Writes the verdict on the strips to `*verdict`: whether they meet θ within the tolerance they
/// were built with, without flipped quads, and where they miss most.
/// Returns `LML_STATUS_OK` or `LML_STATUS_INVALID_ARGUMENT` (NULL argument).
#[no_mangle]
pub unsafe extern "C" fn lml_strips_verdict(strips: *const LmlStrips, verdict: *mut LmlVerdict) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle, writable `verdict`.
        let strips = unsafe { handle(strips, "strips") }?;
        unsafe { Out::new(verdict, "verdict") }?.set(LmlVerdict::from(&strips.pattern.verdict));
        Ok(LmlStatus::Ok)
    })
}

/// Writes the number of strips `s` to `*count`.
/// Returns `LML_STATUS_OK` or `LML_STATUS_INVALID_ARGUMENT` (NULL argument).
#[no_mangle]
pub unsafe extern "C" fn lml_strips_count(strips: *const LmlStrips, count: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle, writable `count`.
        let strips = unsafe { handle(strips, "strips") }?;
        unsafe { Out::new(count, "count") }?.set(strips.pattern.strips.len());
        Ok(LmlStatus::Ok)
    })
}

/// The strips of a live handle.
///
/// # Safety
/// As [`handle`].
pub(super) unsafe fn strips_of<'a>(strips: *const LmlStrips) -> Result<&'a [RectifyingStrip], Failure> {
    // SAFETY: forwarded contract.
    Ok(&unsafe { handle(strips, "strips") }?.pattern.strips)
}

/// Copies the offset table of the centre points: `s + 1` values starting at 0; strip `i` has the
/// points `offsets[i] .. offsets[i + 1]` of `lml_strips_centres`, `lml_strips_rulings` and
/// `lml_strips_unrolled_centres` (counted in points, not doubles).
///
/// Two-call pattern: `*needed` is always set to `s + 1`; if `out` is NULL or `capacity` is
/// smaller, nothing is copied and `LML_STATUS_BUFFER_TOO_SMALL` is returned. The buffer stays
/// owned by the caller.
/// Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL` or `LML_STATUS_INVALID_ARGUMENT`.
#[no_mangle]
pub unsafe extern "C" fn lml_strips_point_offsets(strips: *const LmlStrips, out: *mut usize, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `out` writable for `capacity` values; writable `needed`.
        let strips = unsafe { strips_of(strips) }?;
        unsafe { copy_out(&offsets(strips.iter().map(|s| s.centre.len())), out, capacity, needed, "out") }
    })
}

/// Copies the offset table of the strip vertices (`2n` per strip of `n` points): `s + 1` values
/// starting at 0, indexing the vertices of `lml_strips_vertices` and
/// `lml_strips_unrolled_vertices`. Two-call pattern as `lml_strips_point_offsets`.
/// Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL` or `LML_STATUS_INVALID_ARGUMENT`.
#[no_mangle]
pub unsafe extern "C" fn lml_strips_vertex_offsets(strips: *const LmlStrips, out: *mut usize, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): as lml_strips_point_offsets.
        let strips = unsafe { strips_of(strips) }?;
        unsafe { copy_out(&offsets(strips.iter().map(|s| 2 * s.centre.len())), out, capacity, needed, "out") }
    })
}

/// Copies the offset table of the quads (`n − 1` per strip of `n` points): `s + 1` values
/// starting at 0, indexing the quads of `lml_strips_quads`. Two-call pattern as
/// `lml_strips_point_offsets`.
/// Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL` or `LML_STATUS_INVALID_ARGUMENT`.
#[no_mangle]
pub unsafe extern "C" fn lml_strips_quad_offsets(strips: *const LmlStrips, out: *mut usize, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): as lml_strips_point_offsets.
        let strips = unsafe { strips_of(strips) }?;
        unsafe { copy_out(&offsets(strips.iter().map(quad_count)), out, capacity, needed, "out") }
    })
}

fn quad_count(strip: &RectifyingStrip) -> usize {
    strip.centre.len().saturating_sub(1)
}

/// Copies the strip vertices in space: `3v` doubles (`v` = total vertex count), each strip's
/// `2n` vertices in the order described at `LmlStrips` (`left_i` = centre_i + s_i ruling_i,
/// `right_i` = centre_i − s_i ruling_i, with s_i chosen so that the flat strip has the
/// requested width).
///
/// Two-call pattern as `lml_strips_point_offsets` (`capacity` and `*needed` count doubles).
/// Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL` or `LML_STATUS_INVALID_ARGUMENT`.
#[no_mangle]
pub unsafe extern "C" fn lml_strips_vertices(strips: *const LmlStrips, out: *mut f64, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `out` writable for `capacity` doubles; writable `needed`.
        let strips = unsafe { strips_of(strips) }?;
        let vertices: Vec<f64> = strips.iter().flat_map(|s| [flat_xyz(&s.left), flat_xyz(&s.right)]).flatten().collect();
        unsafe { copy_out(&vertices, out, capacity, needed, "out") }
    })
}

/// Copies the quads: `4q` zero-based vertex indices into the whole `lml_strips_vertices` array
/// (not per strip), quad `j` of a strip with `n` points and first vertex `o` being
/// `(o + j, o + j + 1, o + n + j + 1, o + n + j)`. The quads of a strip are planar up to
/// `max_planar` of its metrics, and consistently oriented.
///
/// Two-call pattern as `lml_strips_point_offsets` (`capacity` and `*needed` count indices).
/// Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL`, `LML_STATUS_INVALID_ARGUMENT`, or
/// `LML_STATUS_INTERNAL_ERROR` (more vertices than `uint32_t` indices reach).
#[no_mangle]
pub unsafe extern "C" fn lml_strips_quads(strips: *const LmlStrips, out: *mut u32, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `out` writable for `capacity` indices; writable `needed`.
        let strips = unsafe { strips_of(strips) }?;
        unsafe { copy_out(&quad_indices(strips)?, out, capacity, needed, "out") }
    })
}

fn quad_indices(strips: &[RectifyingStrip]) -> Result<Vec<u32>, Failure> {
    let mut quads = Vec::new();
    let mut first = 0;
    for strip in strips {
        let n = strip.centre.len();
        for j in 0..quad_count(strip) {
            for corner in [first + j, first + j + 1, first + n + j + 1, first + n + j] {
                let index = u32::try_from(corner)
                    .map_err(|_| Failure::new(LmlStatus::InternalError, format!("strip vertex {corner} exceeds uint32_t quad indices")))?;
                quads.push(index);
            }
        }
        first += 2 * n;
    }
    Ok(quads)
}

/// Copies the centre lines (the optimised base polylines, the strips' medial lines): `3k`
/// doubles, `k` the total point count, strips one after another as `lml_strips_point_offsets`
/// says.
///
/// Two-call pattern as `lml_strips_point_offsets` (`capacity` and `*needed` count doubles).
/// Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL` or `LML_STATUS_INVALID_ARGUMENT`.
#[no_mangle]
pub unsafe extern "C" fn lml_strips_centres(strips: *const LmlStrips, out: *mut f64, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): as lml_strips_vertices.
        let strips = unsafe { strips_of(strips) }?;
        let centres: Vec<f64> = strips.iter().flat_map(|s| flat_xyz(&s.centre)).collect();
        unsafe { copy_out(&centres, out, capacity, needed, "out") }
    })
}

/// Copies the unit rulings `d_i` at the centre points (in the outer bisecting planes, Eq. 16,
/// on the binormals' side), laid out as `lml_strips_centres`.
///
/// Two-call pattern as `lml_strips_point_offsets` (`capacity` and `*needed` count doubles).
/// Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL` or `LML_STATUS_INVALID_ARGUMENT`.
#[no_mangle]
pub unsafe extern "C" fn lml_strips_rulings(strips: *const LmlStrips, out: *mut f64, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): as lml_strips_vertices.
        let strips = unsafe { strips_of(strips) }?;
        let rulings: Vec<f64> = strips.iter().flat_map(|s| flat_xyz(&s.rulings)).collect();
        unsafe { copy_out(&rulings, out, capacity, needed, "out") }
    })
}

/// Copies the strips laid flat: `2v` doubles, `(x, y)` of each vertex of `lml_strips_vertices`
/// in the same order, so `lml_strips_quads` indexes them too. Each strip is unrolled quad by
/// quad, isometrically, starting at the origin with its first centre edge along +x; strips are
/// not arranged against each other.
///
/// Two-call pattern as `lml_strips_point_offsets` (`capacity` and `*needed` count doubles).
/// Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL` or `LML_STATUS_INVALID_ARGUMENT`.
#[no_mangle]
pub unsafe extern "C" fn lml_strips_unrolled_vertices(strips: *const LmlStrips, out: *mut f64, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): as lml_strips_vertices.
        let strips = unsafe { strips_of(strips) }?;
        let flat: Vec<f64> = strips.iter().flat_map(|s| [flat_xy(&s.unrolling.left), flat_xy(&s.unrolling.right)]).flatten().collect();
        unsafe { copy_out(&flat, out, capacity, needed, "out") }
    })
}

/// Copies the unrolled centre lines: `2k` doubles, `(x, y)` of each point of
/// `lml_strips_centres` in the same order (straight up to `e_straight` of the metrics).
///
/// Two-call pattern as `lml_strips_point_offsets` (`capacity` and `*needed` count doubles).
/// Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL` or `LML_STATUS_INVALID_ARGUMENT`.
#[no_mangle]
pub unsafe extern "C" fn lml_strips_unrolled_centres(strips: *const LmlStrips, out: *mut f64, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): as lml_strips_vertices.
        let strips = unsafe { strips_of(strips) }?;
        let flat: Vec<f64> = strips.iter().flat_map(|s| flat_xy(&s.unrolling.centre)).collect();
        unsafe { copy_out(&flat, out, capacity, needed, "out") }
    })
}

/// Copies one `LmlStripMetrics` per strip, in strip order.
///
/// Two-call pattern as `lml_strips_point_offsets` (`capacity` and `*needed` count structs;
/// when `*needed` is 0, `out` may be NULL and the call succeeds).
/// Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL` or `LML_STATUS_INVALID_ARGUMENT`.
#[no_mangle]
pub unsafe extern "C" fn lml_strips_metrics(strips: *const LmlStrips, out: *mut LmlStripMetrics, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `out` writable for `capacity` structs; writable `needed`.
        let strips = unsafe { strips_of(strips) }?;
        let metrics: Vec<LmlStripMetrics> = strips.iter().map(LmlStripMetrics::from).collect();
        unsafe { copy_out(&metrics, out, capacity, needed, "out") }
    })
}

/// Writes the measures of the whole pattern to `*metrics`.
/// Returns `LML_STATUS_OK` or `LML_STATUS_INVALID_ARGUMENT` (NULL argument).
#[no_mangle]
pub unsafe extern "C" fn lml_strips_pattern_metrics(strips: *const LmlStrips, metrics: *mut LmlPatternMetrics) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle, writable `metrics`.
        let pattern = &unsafe { handle(strips, "strips") }?.pattern;
        unsafe { Out::new(metrics, "metrics") }?.set(LmlPatternMetrics::new(&pattern.metrics, pattern.skipped.len()));
        Ok(LmlStatus::Ok)
    })
}

/// Copies the curves no strip could be built on, one `LmlSkippedCurve` each, in curve order.
///
/// Two-call pattern as `lml_strips_metrics` (`*needed` is often 0).
/// Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL` or `LML_STATUS_INVALID_ARGUMENT`.
#[no_mangle]
pub unsafe extern "C" fn lml_strips_skipped(strips: *const LmlStrips, out: *mut LmlSkippedCurve, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `out` writable for `capacity` structs; writable `needed`.
        let pattern = &unsafe { handle(strips, "strips") }?.pattern;
        let skipped: Vec<LmlSkippedCurve> = pattern.skipped.iter().map(LmlSkippedCurve::from).collect();
        unsafe { copy_out(&skipped, out, capacity, needed, "out") }
    })
}
