//! `LmlGuides`: guide curves traced on a mesh (paper Sec. 3.2.1, Eq. 4): discrete
//! pseudo-geodesics from boundary start points, with their crossings and the order check that
//! the initialisation from guide curves (Sec. 3.2.2) needs.

use super::edge_point::LmlEdgePoint;
use super::failure::Failure;
use super::guard::guarded;
use super::layout::{flat_xyz, offsets};
use super::mesh::LmlMesh;
use super::raw::{copy_out, handle, input, release, Out};
use super::status::LmlStatus;
use super::trace_options::{options_or_default, stop_code, LmlTraceOptions, LmlTraceStop};
use crate::mesh::{EdgePoint, TriMesh};
use crate::tracing::{check_order, intersections, Crossing, OrderDefect, TraceError, TracedCurve, Tracer};
use std::sync::Arc;

/// Guide curves (opaque): traced polylines on mesh edges (edge points and positions), why
/// each stopped, and the mesh they were traced on. Create it with `lml_guides_trace`, release
/// it with `lml_guides_free`. Immutable once created.
pub struct LmlGuides {
    /// The surface traced on, in the caller's units.
    pub(crate) mesh: Arc<TriMesh>,
    pub(crate) curves: Vec<TracedCurve>,
}

/// Where two traced segments meet. Segment `k` of a curve joins its points `k` and `k + 1`; a
/// self-intersection has `first_curve == second_curve`.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LmlCrossing {
    pub first_curve: u32,
    pub second_curve: u32,
    pub first_segment: u32,
    pub second_segment: u32,
    /// The meeting point (x, y, z).
    pub position: [f64; 3],
}

/// An index as `u32`; the counts behind it are bounded when the guides are traced.
fn index(value: usize) -> Result<u32, Failure> {
    u32::try_from(value).map_err(|_| Failure::new(LmlStatus::InternalError, format!("index {value} does not fit 32 bits")))
}

impl LmlCrossing {
    fn new(c: &Crossing) -> Result<LmlCrossing, Failure> {
        Ok(LmlCrossing {
            first_curve: index(c.curves[0])?,
            second_curve: index(c.curves[1])?,
            first_segment: index(c.segments[0])?,
            second_segment: index(c.segments[1])?,
            position: [c.position.x, c.position.y, c.position.z],
        })
    }
}

/// A tracing error of start `i`, naming the argument it comes from.
fn trace_failure(i: usize, e: TraceError) -> Failure {
    match e {
        TraceError::InvalidOption { .. } => Failure::argument("options", e),
        TraceError::ThetaOutOfRange { .. } => Failure::argument("theta_degrees", e),
        TraceError::StartAngleOutOfRange { .. } => Failure::argument("start_angle_degrees", e),
        _ => Failure::argument(&format!("starts[{i}]"), e),
    }
}

/// Traces one discrete P-curve (pseudo-geodesic) per start point, in order: curve `i` starts at
/// `starts[i]`, so it becomes the level `F = i` of `lml_field_values_from_guides`.
///
/// - `mesh`: the surface; the guides keep their own copy of it, so it may be freed afterwards.
/// - `starts`: `count` (≥ 1) points on boundary edges (either orientation of the edge), e.g.
///   from `lml_boundary_starts`. Copied.
/// - `theta_degrees`: θ ∈ [0, 180], the angle between the curve's binormal and the surface
///   normal (paper Eq. 2): 90 gives geodesics, 0 or 180 asymptotic curves; θ and 180 − θ are
///   the two mirror families. θ is measured with the side vector `n × t` pointing to the left of
///   the travel direction (seen from the side the normals point to).
/// - `start_angle_degrees`: α ∈ (0, 180), the tangent at the start against the boundary
///   direction that has the interior on its left, turned into the surface (90: perpendicular).
/// - `options`: limits and tolerances; NULL for the defaults of `lml_trace_options_default`.
///   Copied.
/// - `out`: receives the new guides, owned by the caller (release with `lml_guides_free`); set
///   to NULL on failure.
///
/// Each curve runs until it reaches the boundary, no next point exists, or a limit of
/// `options` (see `lml_guides_stops`); it has at least two points.
///
/// Returns `LML_STATUS_OK`; `LML_STATUS_INVALID_ARGUMENT` (NULL pointer, `count` 0, an option
/// out of range (named; e.g. `max_points` above `LML_MAX_TRACE_POINTS`), θ or α out of range, or start `i` invalid: a vertex out of range, not a
/// boundary edge, `t` outside [0, 1], or no first segment leaves it at α into the surface; the
/// message names `starts[i]`).
#[no_mangle]
pub unsafe extern "C" fn lml_guides_trace(
    mesh: *const LmlMesh,
    starts: *const LmlEdgePoint,
    count: usize,
    theta_degrees: f64,
    start_angle_degrees: f64,
    options: *const LmlTraceOptions,
    out: *mut *mut LmlGuides,
) -> LmlStatus {
    guarded(|| {
        // SAFETY (all blocks): the pointer contracts are those documented above.
        let mut out = unsafe { Out::new(out, "out") }?;
        out.set(std::ptr::null_mut());
        let mesh = unsafe { handle(mesh, "mesh") }?;
        let starts = unsafe { input(starts, count, "starts") }?;
        let options = unsafe { options_or_default(options) }?;
        if starts.is_empty() {
            return Err(Failure::argument("count", "at least one start point is needed"));
        }
        index(starts.len()).map_err(|_| Failure::argument("count", format!("{count} start points are too many")))?;
        let tracer = Tracer::new(&mesh.mesh);
        let curves = starts
            .iter()
            .enumerate()
            .map(|(i, start)| tracer.trace(&EdgePoint::from(start), theta_degrees, start_angle_degrees, &options).map_err(|e| trace_failure(i, e)))
            .collect::<Result<Vec<_>, _>>()?;
        out.set_owned(LmlGuides { mesh: Arc::new(mesh.mesh.clone()), curves });
        Ok(LmlStatus::Ok)
    })
}

/// Releases guides. NULL is accepted and ignored. The handle must not be used (or freed) again.
#[no_mangle]
pub unsafe extern "C" fn lml_guides_free(guides: *mut LmlGuides) {
    guarded(|| {
        // SAFETY: `guides` is NULL or a live handle from lml_guides_trace.
        unsafe { release(guides) };
        Ok(LmlStatus::Ok)
    });
}

/// Writes the number of curves `c` (the number of start points) to `*count`.
/// Returns `LML_STATUS_OK` or `LML_STATUS_INVALID_ARGUMENT` (NULL argument).
#[no_mangle]
pub unsafe extern "C" fn lml_guides_count(guides: *const LmlGuides, count: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle, writable `count`.
        let guides = unsafe { handle(guides, "guides") }?;
        unsafe { Out::new(count, "count") }?.set(guides.curves.len());
        Ok(LmlStatus::Ok)
    })
}

/// Copies the offset table of the curves: `c + 1` values starting at 0; curve `i` has the points
/// `offsets[i] .. offsets[i + 1]` (counted in points) of `lml_guides_points` and
/// `lml_guides_edge_points`, so `offsets[c]` is the total point count `k`.
///
/// Two-call pattern: `*needed` is always set to `c + 1`; if `out` is NULL or `capacity` is
/// smaller, nothing is copied and `LML_STATUS_BUFFER_TOO_SMALL` is returned. The buffer stays
/// owned by the caller.
/// Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL` or `LML_STATUS_INVALID_ARGUMENT`.
#[no_mangle]
pub unsafe extern "C" fn lml_guides_offsets(guides: *const LmlGuides, out: *mut usize, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `out` writable for `capacity` values; writable `needed`.
        let guides = unsafe { handle(guides, "guides") }?;
        unsafe { copy_out(&offsets(guides.curves.iter().map(|c| c.points().len())), out, capacity, needed, "out") }
    })
}

/// Copies the points of all curves, one after another in travel direction (from the start
/// point): `3k` doubles in the mesh's units, point `p` at `out[3p..3p+3]`.
///
/// Two-call pattern as `lml_guides_offsets` (`capacity` and `*needed` count doubles).
/// Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL` or `LML_STATUS_INVALID_ARGUMENT`.
#[no_mangle]
pub unsafe extern "C" fn lml_guides_points(guides: *const LmlGuides, out: *mut f64, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `out` writable for `capacity` doubles; writable `needed`.
        let guides = unsafe { handle(guides, "guides") }?;
        let points: Vec<f64> = guides.curves.iter().flat_map(|c| flat_xyz(c.positions())).collect();
        unsafe { copy_out(&points, out, capacity, needed, "out") }
    })
}

/// Copies the points of all curves as edge points (`k` of them, laid out as
/// `lml_guides_points`), each edge given as `[a, b]` with `a < b` and `t` measured from `a`.
///
/// Two-call pattern as `lml_guides_offsets` (`capacity` and `*needed` count points).
/// Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL` or `LML_STATUS_INVALID_ARGUMENT`.
#[no_mangle]
pub unsafe extern "C" fn lml_guides_edge_points(
    guides: *const LmlGuides,
    out: *mut LmlEdgePoint,
    capacity: usize,
    needed: *mut usize,
) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `out` writable for `capacity` points; writable `needed`.
        let guides = unsafe { handle(guides, "guides") }?;
        let points: Vec<LmlEdgePoint> = guides.curves.iter().flat_map(|c| c.points().iter().map(LmlEdgePoint::from)).collect();
        unsafe { copy_out(&points, out, capacity, needed, "out") }
    })
}

/// Copies why the tracing of each curve stopped: `c` `LML_TRACE_STOP_*` codes.
///
/// Two-call pattern as `lml_guides_offsets` (`*needed` is `c`).
/// Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL` or `LML_STATUS_INVALID_ARGUMENT`.
#[no_mangle]
pub unsafe extern "C" fn lml_guides_stops(guides: *const LmlGuides, out: *mut LmlTraceStop, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `out` writable for `capacity` codes; writable `needed`.
        let guides = unsafe { handle(guides, "guides") }?;
        let stops: Vec<LmlTraceStop> = guides.curves.iter().map(|c| stop_code(c.stop())).collect();
        unsafe { copy_out(&stops, out, capacity, needed, "out") }
    })
}

/// Copies the length of each curve (its polyline, in the mesh's units): `c` doubles.
///
/// Two-call pattern as `lml_guides_offsets` (`*needed` is `c`).
/// Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL` or `LML_STATUS_INVALID_ARGUMENT`.
#[no_mangle]
pub unsafe extern "C" fn lml_guides_lengths(guides: *const LmlGuides, out: *mut f64, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `out` writable for `capacity` doubles; writable `needed`.
        let guides = unsafe { handle(guides, "guides") }?;
        let lengths: Vec<f64> = guides.curves.iter().map(TracedCurve::length).collect();
        unsafe { copy_out(&lengths, out, capacity, needed, "out") }
    })
}

/// Copies where the curves meet: first the crossings between different curves
/// (`first_curve < second_curve`), then the self-intersections (`first_curve == second_curve`,
/// `first_segment < second_segment`), each sorted by curves, then segments. Segments that touch
/// count as meeting; consecutive segments of one curve do not.
///
/// Two-call pattern as `lml_guides_offsets` (`capacity` and `*needed` count crossings;
/// `*needed` may be 0, and then `out` may be NULL and the call succeeds).
/// Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL` or `LML_STATUS_INVALID_ARGUMENT`.
#[no_mangle]
pub unsafe extern "C" fn lml_guides_crossings(guides: *const LmlGuides, out: *mut LmlCrossing, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `out` writable for `capacity` crossings; writable `needed`.
        let guides = unsafe { handle(guides, "guides") }?;
        let report = intersections(&guides.mesh, &guides.curves);
        let crossings = report.crossings.iter().chain(&report.self_intersections).map(LmlCrossing::new).collect::<Result<Vec<_>, _>>()?;
        unsafe { copy_out(&crossings, out, capacity, needed, "out") }
    })
}

/// Checks that the curves are ordered like the level sets `F = 0, 1, …, c − 1` of one function,
/// as `lml_field_values_from_guides` requires: no curve intersects itself, no two cross or
/// touch, and each inner curve runs from the boundary loop of its start back to that loop and
/// separates its two neighbours (curve `i` lies between curves `i − 1` and `i + 1`).
///
/// Returns `LML_STATUS_OK` (ordered); `LML_STATUS_INVALID_GUIDES` (the message names the first
/// defect found and the curve indices, checked in the order above); `LML_STATUS_INVALID_ARGUMENT`
/// (NULL `guides`).
#[no_mangle]
pub unsafe extern "C" fn lml_guides_check_order(guides: *const LmlGuides) -> LmlStatus {
    guarded(|| {
        // SAFETY: live handle.
        let guides = unsafe { handle(guides, "guides") }?;
        check_order(&guides.mesh, &guides.curves).map_err(|defect| {
            let message = match defect {
                OrderDefect::SelfIntersection { curve } => format!("guide curve {curve} intersects itself"),
                OrderDefect::Crossing { first, second } => format!("guide curves {first} and {second} cross"),
                OrderDefect::OpenEnd { curve } => {
                    format!("guide curve {curve} does not run from its boundary loop back to it, so it does not separate its neighbours")
                }
                OrderDefect::NotBetween { curve } => {
                    format!("guide curve {curve} does not lie between guide curves {} and {}", curve.saturating_sub(1), curve + 1)
                }
            };
            Failure::new(LmlStatus::InvalidGuides, message)
        })?;
        Ok(LmlStatus::Ok)
    })
}
