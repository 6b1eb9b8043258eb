//! Start points for guide curves on the mesh boundary (reference notes §4.1): boundary loops
//! split at corners, evenly spaced starts, a start by arc length, the start nearest a point.

use super::edge_point::LmlEdgePoint;
use super::failure::Failure;
use super::guard::guarded;
use super::mesh::LmlMesh;
use super::raw::{copy_out, handle, input, Out};
use super::status::LmlStatus;
use crate::mesh::Vec3;
use crate::tracing::{boundary_segments, boundary_start, evenly_spaced_starts, nearest_boundary_point};

/// The default corner threshold in degrees: a boundary vertex where the boundary turns by at
/// least this much splits a loop into segments. (A literal, so that the header can show it;
/// equal to the library's default.)
pub const LML_DEFAULT_CORNER_TURN_DEGREES: f64 = 30.0;

/// Most start points one `lml_boundary_starts` call returns. (A literal, so that the header can
/// show it; equal to the library's limit.)
pub const LML_MAX_STARTS: u32 = 10_000;

/// Writes to `*count` the number of segments of boundary loop `loop_index` (loops numbered from
/// 0, the loops of a disk with holes in the library's order) when split at its corners:
/// vertices where the boundary turns by at least `corner_turn_degrees` (in [0, 180], e.g.
/// `LML_DEFAULT_CORNER_TURN_DEGREES`). A loop without corners is one closed segment; a
/// rectangular patch has 4.
///
/// Returns `LML_STATUS_OK` or `LML_STATUS_INVALID_ARGUMENT` (NULL pointer, `loop_index` not a
/// loop of the mesh (the loop count is given), `corner_turn_degrees` not finite or outside
/// [0, 180]).
#[no_mangle]
pub unsafe extern "C" fn lml_boundary_segment_count(
    mesh: *const LmlMesh,
    loop_index: u32,
    corner_turn_degrees: f64,
    count: *mut usize,
) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle, writable `count`.
        let mesh = unsafe { handle(mesh, "mesh") }?;
        let mut count = unsafe { Out::new(count, "count") }?;
        count.set(boundary_segments(&mesh.mesh, loop_index as usize, corner_turn_degrees)?.len());
        Ok(LmlStatus::Ok)
    })
}

/// Copies `count` start points on segment `segment_index` of boundary loop `loop_index` (split
/// at corners as in `lml_boundary_segment_count`), evenly spaced by arc length: at
/// `(i + 1/2)·L / count` from the segment's first corner, so neighbours are `L / count` apart
/// and the corners are avoided. Each point lies on a boundary edge given in loop order (the
/// interior on the left, seen from the side the normals point to); pass them to
/// `lml_guides_trace`.
///
/// `count` is 1 to `LML_MAX_STARTS` (10000), checked before anything is allocated.
///
/// Two-call pattern: `*needed` is always set to `count` (when the arguments are valid); if
/// `out` is NULL or `capacity` (in points) is smaller, nothing is copied and
/// `LML_STATUS_BUFFER_TOO_SMALL` is returned. The buffer stays owned by the caller.
///
/// Returns `LML_STATUS_OK`; `LML_STATUS_BUFFER_TOO_SMALL`; `LML_STATUS_INVALID_ARGUMENT` (NULL
/// pointer, `loop_index` or `segment_index` out of range (the count is given),
/// `corner_turn_degrees` not in [0, 180], `count` 0 or above `LML_MAX_STARTS`).
#[no_mangle]
pub unsafe extern "C" fn lml_boundary_starts(
    mesh: *const LmlMesh,
    loop_index: u32,
    corner_turn_degrees: f64,
    segment_index: u32,
    count: u32,
    out: *mut LmlEdgePoint,
    capacity: usize,
    needed: *mut usize,
) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `out` writable for `capacity` points; writable `needed`.
        let mesh = unsafe { handle(mesh, "mesh") }?;
        let segments = boundary_segments(&mesh.mesh, loop_index as usize, corner_turn_degrees)?;
        let starts = evenly_spaced_starts(&mesh.mesh, &segments, segment_index as usize, count as usize)?;
        let starts: Vec<LmlEdgePoint> = starts.iter().map(LmlEdgePoint::from).collect();
        unsafe { copy_out(&starts, out, capacity, needed, "out") }
    })
}

/// Writes to `*out` the start point at arc-length parameter `s` ∈ [0, 1] along boundary loop
/// `loop_index`, measured from the loop's first vertex in loop order (`s = 1` is back at the
/// first vertex); its edge is given in loop order.
///
/// Returns `LML_STATUS_OK` or `LML_STATUS_INVALID_ARGUMENT` (NULL pointer, `loop_index` out of
/// range (the loop count is given), `s` not finite or outside [0, 1]).
#[no_mangle]
pub unsafe extern "C" fn lml_boundary_start_at(mesh: *const LmlMesh, loop_index: u32, s: f64, out: *mut LmlEdgePoint) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle, writable `out`.
        let mesh = unsafe { handle(mesh, "mesh") }?;
        let mut out = unsafe { Out::new(out, "out") }?;
        out.set(LmlEdgePoint::from(&boundary_start(&mesh.mesh, loop_index as usize, s)?));
        Ok(LmlStatus::Ok)
    })
}

/// Writes to `*out` the point of the mesh boundary (any loop) closest in space to `point`
/// (3 doubles x, y, z, e.g. where a designer clicked); its edge is a boundary edge given in
/// loop order. Ties go to the first boundary edge in loop order.
///
/// Returns `LML_STATUS_OK` or `LML_STATUS_INVALID_ARGUMENT` (NULL pointer, a NaN or infinite
/// coordinate).
#[no_mangle]
pub unsafe extern "C" fn lml_boundary_start_nearest(mesh: *const LmlMesh, point: *const f64, out: *mut LmlEdgePoint) -> LmlStatus {
    guarded(|| {
        // SAFETY (all blocks): live handle; `point` readable for 3 doubles; writable `out`.
        let mesh = unsafe { handle(mesh, "mesh") }?;
        let xyz = unsafe { input(point, 3, "point") }?;
        let mut out = unsafe { Out::new(out, "out") }?;
        let nearest = nearest_boundary_point(&mesh.mesh, Vec3::new(xyz[0], xyz[1], xyz[2]))
            .map_err(|e| Failure::argument("point", e))?;
        out.set(LmlEdgePoint::from(&nearest));
        Ok(LmlStatus::Ok)
    })
}

#[cfg(test)]
mod tests {
    #[test]
    fn the_corner_default_is_the_library_default() {
        assert_eq!(super::LML_DEFAULT_CORNER_TURN_DEGREES, crate::tracing::DEFAULT_CORNER_TURN_DEGREES);
    }

    #[test]
    fn the_start_limit_is_the_library_limit() {
        assert_eq!(usize::try_from(super::LML_MAX_STARTS), Ok(crate::tracing::MAX_STARTS));
    }
}
