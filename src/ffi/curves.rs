//! `LmlCurves`: the level curves of a field session (paper Sec. 3.4, first paragraph), oriented
//! along `∇F × n` and optionally resampled: the base curves of the strips.

use super::failure::Failure;
use super::field::LmlField;
use super::guard::guarded;
use super::net::LmlNet;
use super::layout::{flat_xyz, offsets};
use super::raw::{copy_out, handle, input, release, Out};
use super::status::LmlStatus;
use crate::curves::{extract_level_curves, resample_all, uniform_levels, LevelCurve};
use crate::mesh::TriMesh;
use std::sync::Arc;

/// Most levels one `lml_curves_new` / `lml_curves_new_uniform` call accepts. (A literal, so
/// that the header can show it; equal to the library's limit.)
pub const LML_MAX_LEVELS: usize = 10_000;

/// Most points the polylines of one `lml_curves_new` / `lml_curves_new_uniform` call may get
/// by resampling (`spacing` > 0). (A literal, equal to the library's limit.)
pub const LML_MAX_CURVE_POINTS: usize = 4_000_000;

/// Level polylines of a field (opaque), each with its level value, per-point surface normals and
/// a closed flag, together with the surface they lie on. Create it with `lml_curves_new` or
/// `lml_curves_new_uniform`, release it with `lml_curves_free`. Immutable once created.
pub struct LmlCurves {
    /// The field's surface, in the caller's units.
    pub(crate) mesh: Arc<TriMesh>,
    pub(crate) curves: Vec<LevelCurve>,
}

/// The level curves of the current field at `levels`, resampled to `spacing` unless it is 0.
pub(super) fn extract(mesh: &Arc<TriMesh>, values: &[f64], levels: impl FnOnce(&[f64]) -> Result<Vec<f64>, Failure>, spacing: f64) -> Result<LmlCurves, Failure> {
    if !(spacing.is_finite() && spacing >= 0.0) {
        return Err(Failure::argument("spacing", format!("must be finite and ≥ 0 (0: no resampling), got {spacing}")));
    }
    let mut curves = extract_level_curves(mesh, values, &levels(values)?)?;
    if spacing > 0.0 {
        curves = resample_all(&curves, spacing)?;
    }
    Ok(LmlCurves { mesh: Arc::clone(mesh), curves })
}

/// Extracts the level curves of the current field at the given values.
///
/// - `field`: the session; its current field is used (converged or not). The curves keep their
///   own reference to the surface, so the session may be freed or stepped on afterwards.
/// - `levels`: `level_count` field values (in the scale of the initial field), each finite and
///   inside [min F, max F] of the current field; `level_count` at most `LML_MAX_LEVELS`
///   (10000). Copied. Each level may give several polylines
///   (open ones from boundary to boundary first, then closed loops), or none when it only
///   touches the surface in a point.
/// - `spacing`: 0 keeps the polylines' own vertices (one per crossed mesh edge); > 0 resamples
///   each polyline at equal arc-length steps as close to `spacing` (a length) as its length
///   allows, keeping the end points of open ones. Strips use these vertices, so `spacing`
///   sets their quad length. All polylines together may get at most `LML_MAX_CURVE_POINTS`
///   (4000000) points: a smaller spacing is refused before anything is allocated.
/// - `out`: receives the new curves, owned by the caller (release with `lml_curves_free`); set
///   to NULL on failure.
///
/// Returns `LML_STATUS_OK`; `LML_STATUS_INVALID_ARGUMENT` (NULL pointer, `level_count` 0 or
/// above `LML_MAX_LEVELS`, a non-finite level (its index is named) or one outside the field's
/// range (the range is given), `spacing` negative, not finite or so small that the polylines
/// would exceed `LML_MAX_CURVE_POINTS` points); `LML_STATUS_SINGULAR_FIELD` (the field is
/// constant).
#[no_mangle]
pub unsafe extern "C" fn lml_curves_new(
    field: *const LmlField,
    levels: *const f64,
    level_count: usize,
    spacing: f64,
    out: *mut *mut LmlCurves,
) -> LmlStatus {
    guarded(|| {
        // SAFETY (all blocks): the pointer contracts are those documented above.
        let mut out = unsafe { Out::new(out, "out") }?;
        out.set(std::ptr::null_mut());
        let field = unsafe { handle(field, "field") }?;
        let levels = unsafe { input(levels, level_count, "levels") }?;
        out.set_owned(extract(&field.mesh, &field.solver.field(), |_| Ok(levels.to_vec()), spacing)?);
        Ok(LmlStatus::Ok)
    })
}

/// Like `lml_curves_new` at `count` levels spread uniformly over the current field's range
/// [min F, max F], the extremes left out: `min F + k (max F − min F) / (count + 1)`,
/// k = 1 … `count`, `count` at most `LML_MAX_LEVELS` (10000). Read the values back with
/// `lml_curves_levels`.
///
/// Returns `LML_STATUS_OK`; `LML_STATUS_INVALID_ARGUMENT` (NULL pointer, `count` 0 or above
/// `LML_MAX_LEVELS`, `spacing` negative, not finite or too small as in `lml_curves_new`);
/// `LML_STATUS_SINGULAR_FIELD` (the field is constant).
#[no_mangle]
pub unsafe extern "C" fn lml_curves_new_uniform(field: *const LmlField, count: usize, spacing: f64, out: *mut *mut LmlCurves) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): writable `out`; live `field` handle.
        let mut out = unsafe { Out::new(out, "out") }?;
        out.set(std::ptr::null_mut());
        let field = unsafe { handle(field, "field") }?;
        out.set_owned(extract(&field.mesh, &field.solver.field(), |values| Ok(uniform_levels(&field.mesh, values, count)?), spacing)?);
        Ok(LmlStatus::Ok)
    })
}

/// Like `lml_curves_new_uniform` on field `k` of a net session (below `lml_net_family_count`):
/// the base curves of that family's strips (build them with `lml_strips_new` at the family's θ,
/// then the net's nodes with `lml_strip_net_new`). A 3-web's strips take the curves at its
/// even-pace levels instead (`lml_curves_new_from_web`).
///
/// Returns as `lml_curves_new_uniform`, and `LML_STATUS_INVALID_ARGUMENT` for `k` not below the
/// family count.
#[no_mangle]
pub unsafe extern "C" fn lml_curves_new_from_net(net: *const LmlNet, k: u32, count: usize, spacing: f64, out: *mut *mut LmlCurves) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): writable `out`; live `net` handle.
        let mut out = unsafe { Out::new(out, "out") }?;
        out.set(std::ptr::null_mut());
        let net = unsafe { handle(net, "net") }?;
        let values = net.field(k)?;
        out.set_owned(extract(&net.mesh, &values, |values| Ok(uniform_levels(&net.mesh, values, count)?), spacing)?);
        Ok(LmlStatus::Ok)
    })
}

/// Releases curves. NULL is accepted and ignored. Strips built from them keep working. The handle
/// must not be used (or freed) again.
#[no_mangle]
pub unsafe extern "C" fn lml_curves_free(curves: *mut LmlCurves) {
    guarded(|| {
        // SAFETY: `curves` is NULL or a live handle from lml_curves_new / lml_curves_new_uniform.
        unsafe { release(curves) };
        Ok(LmlStatus::Ok)
    });
}

/// Writes the number of polylines `c` to `*count` (may be 0: no level crossed the surface in
/// more than a point).
/// Returns `LML_STATUS_OK` or `LML_STATUS_INVALID_ARGUMENT` (NULL argument).
#[no_mangle]
pub unsafe extern "C" fn lml_curves_count(curves: *const LmlCurves, count: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle, writable `count`.
        let curves = unsafe { handle(curves, "curves") }?;
        unsafe { Out::new(count, "count") }?.set(curves.curves.len());
        Ok(LmlStatus::Ok)
    })
}

/// Copies the offset table of the polylines: `c + 1` values starting at 0; polyline `i` has the
/// points `offsets[i] .. offsets[i + 1]` (counted in points, not doubles) of `lml_curves_points`
/// and `lml_curves_normals`, so `offsets[c]` is the total point count `k`.
///
/// Two-call pattern: `*needed` is always set to `c + 1`; if `out` is NULL or `capacity` is
/// smaller, nothing is copied and `LML_STATUS_BUFFER_TOO_SMALL` is returned. The buffer stays
/// owned by the caller.
/// Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL` or `LML_STATUS_INVALID_ARGUMENT`.
#[no_mangle]
pub unsafe extern "C" fn lml_curves_offsets(curves: *const LmlCurves, out: *mut usize, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `out` writable for `capacity` values; writable `needed`.
        let curves = unsafe { handle(curves, "curves") }?;
        unsafe { copy_out(&offsets(curves.curves.iter().map(|c| c.points.len())), out, capacity, needed, "out") }
    })
}

/// Copies the points of all polylines, one after another: `3k` doubles, point `p` at
/// `out[3p..3p+3]`. Each polyline runs along `∇F × n` (so its side vector `n × t` points
/// towards growing F); a closed one does not repeat its first point.
///
/// Two-call pattern as `lml_curves_offsets` (`capacity` and `*needed` count doubles).
/// Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL` or `LML_STATUS_INVALID_ARGUMENT`.
#[no_mangle]
pub unsafe extern "C" fn lml_curves_points(curves: *const LmlCurves, out: *mut f64, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `out` writable for `capacity` doubles; writable `needed`.
        let curves = unsafe { handle(curves, "curves") }?;
        let points: Vec<f64> = curves.curves.iter().flat_map(|c| flat_xyz(&c.points)).collect();
        unsafe { copy_out(&points, out, capacity, needed, "out") }
    })
}

/// Copies the unit surface normal at each point (interpolated from the mesh's vertex normals),
/// laid out as `lml_curves_points`.
///
/// Two-call pattern as `lml_curves_offsets` (`capacity` and `*needed` count doubles).
/// Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL` or `LML_STATUS_INVALID_ARGUMENT`.
#[no_mangle]
pub unsafe extern "C" fn lml_curves_normals(curves: *const LmlCurves, out: *mut f64, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): as lml_curves_points.
        let curves = unsafe { handle(curves, "curves") }?;
        let normals: Vec<f64> = curves.curves.iter().flat_map(|c| flat_xyz(&c.normals)).collect();
        unsafe { copy_out(&normals, out, capacity, needed, "out") }
    })
}

/// Copies the level value of each polyline: `c` doubles.
///
/// Two-call pattern as `lml_curves_offsets` (`*needed` is `c`; when it is 0, `out` may be NULL
/// and the call succeeds).
/// Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL` or `LML_STATUS_INVALID_ARGUMENT`.
#[no_mangle]
pub unsafe extern "C" fn lml_curves_levels(curves: *const LmlCurves, out: *mut f64, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `out` writable for `capacity` doubles; writable `needed`.
        let curves = unsafe { handle(curves, "curves") }?;
        let levels: Vec<f64> = curves.curves.iter().map(|c| c.level).collect();
        unsafe { copy_out(&levels, out, capacity, needed, "out") }
    })
}

/// Copies one flag per polyline: 1 when it closes on itself (a level set that never meets the
/// boundary; its last point joins its first), 0 when it runs from boundary to boundary.
///
/// Two-call pattern as `lml_curves_levels` (`capacity` and `*needed` count bytes).
/// Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL` or `LML_STATUS_INVALID_ARGUMENT`.
#[no_mangle]
pub unsafe extern "C" fn lml_curves_closed(curves: *const LmlCurves, out: *mut u8, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `out` writable for `capacity` bytes; writable `needed`.
        let curves = unsafe { handle(curves, "curves") }?;
        let closed: Vec<u8> = curves.curves.iter().map(|c| u8::from(c.closed)).collect();
        unsafe { copy_out(&closed, out, capacity, needed, "out") }
    })
}

#[cfg(test)]
mod tests {
    #[test]
    fn the_limits_are_the_library_limits() {
        assert_eq!(super::LML_MAX_LEVELS, crate::curves::MAX_LEVELS);
        assert_eq!(super::LML_MAX_CURVE_POINTS, crate::curves::MAX_CURVE_POINTS);
    }
}
