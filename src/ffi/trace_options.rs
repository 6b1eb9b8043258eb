//! `LmlTraceOptions`: the stop limits and tolerances of guide-curve tracing (paper Sec. 3.2.1)
//! as a plain C struct, and `LmlTraceStop`, why a traced curve ended.

use super::failure::Failure;
use super::guard::guarded;
use super::raw::Out;
use super::status::LmlStatus;
use crate::tracing::{StopReason, TraceOptions};

/// Largest `LmlTraceOptions.max_points`. (A literal, so that the header can show it; equal to
/// the library's limit.)
pub const LML_MAX_TRACE_POINTS: u64 = 10_000_000;

/// Limits and tolerances of `lml_guides_trace`. Fill it with `lml_trace_options_default`, then
/// change fields as needed. Lengths are in the mesh's unit, angles in degrees.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LmlTraceOptions {
    /// Stop a curve once it is at least this long; `INFINITY` for no limit (default). > 0.
    pub max_length: f64,
    /// Stop a curve once it has this many points (2 to `LML_MAX_TRACE_POINTS` = 10000000;
    /// default 100000).
    pub max_points: u64,
    /// A root of the tracing equation (paper Eq. 4) is accepted if the angle it realises is
    /// within this many degrees of θ (0 < tolerance < 90; default 2).
    pub angle_tolerance_degrees: f64,
    /// Sharpest accepted turn between consecutive segments in degrees (0 < turn ≤ 90; default
    /// 45): a much sharper turn would jump onto another curve family.
    pub max_turn_degrees: f64,
}

impl From<&TraceOptions> for LmlTraceOptions {
    fn from(o: &TraceOptions) -> LmlTraceOptions {
        LmlTraceOptions {
            max_length: o.max_length,
            max_points: u64::try_from(o.max_points).unwrap_or(u64::MAX),
            angle_tolerance_degrees: o.angle_tolerance_degrees,
            max_turn_degrees: o.max_turn_degrees,
        }
    }
}

impl LmlTraceOptions {
    /// The library's options (the fields the C struct leaves out keep their defaults); range
    /// checks are left to the tracer, whose messages name the option.
    pub(crate) fn to_options(self) -> TraceOptions {
        TraceOptions {
            max_length: self.max_length,
            max_points: usize::try_from(self.max_points).unwrap_or(usize::MAX),
            angle_tolerance_degrees: self.angle_tolerance_degrees,
            max_turn_degrees: self.max_turn_degrees,
            ..TraceOptions::default()
        }
    }
}

/// Writes the default tracing options to `*out`: no length limit, 100000 points, 2° tolerance,
/// turns up to 45°.
/// Returns `LML_STATUS_OK` or `LML_STATUS_INVALID_ARGUMENT` (NULL `out`).
#[no_mangle]
pub unsafe extern "C" fn lml_trace_options_default(out: *mut LmlTraceOptions) -> LmlStatus {
    guarded(|| {
        // SAFETY: `out` is NULL or writable (caller's contract).
        unsafe { Out::new(out, "out") }?.set(LmlTraceOptions::from(&TraceOptions::default()));
        Ok(LmlStatus::Ok)
    })
}

/// Why the tracing of a guide curve stopped (one of the `LML_TRACE_STOP_*` constants).
pub type LmlTraceStop = u32;
/// The last point lies on the mesh boundary: the curve runs from boundary to boundary.
pub const LML_TRACE_STOP_BOUNDARY: LmlTraceStop = 0;
/// No next point satisfies the tracing equation: the curve family does not continue here
/// (a singular configuration).
pub const LML_TRACE_STOP_NO_CANDIDATE: LmlTraceStop = 1;
/// The curve reached `LmlTraceOptions.max_length`.
pub const LML_TRACE_STOP_LENGTH_LIMIT: LmlTraceStop = 2;
/// The curve reached `LmlTraceOptions.max_points`.
pub const LML_TRACE_STOP_POINT_LIMIT: LmlTraceStop = 3;

/// The C code of a stop reason.
pub(crate) fn stop_code(stop: StopReason) -> LmlTraceStop {
    match stop {
        StopReason::Boundary => LML_TRACE_STOP_BOUNDARY,
        StopReason::NoValidCandidate => LML_TRACE_STOP_NO_CANDIDATE,
        StopReason::LengthLimit => LML_TRACE_STOP_LENGTH_LIMIT,
        StopReason::PointLimit => LML_TRACE_STOP_POINT_LIMIT,
    }
}

/// Checks the options pointer: NULL means the defaults.
///
/// # Safety
/// A non-NULL `options` must point at an initialised `LmlTraceOptions`.
pub(crate) unsafe fn options_or_default(options: *const LmlTraceOptions) -> Result<TraceOptions, Failure> {
    if options.is_null() {
        return Ok(TraceOptions::default());
    }
    // SAFETY: forwarded contract.
    Ok(unsafe { super::raw::handle(options, "options") }?.to_options())
}

#[cfg(test)]
mod tests {
    #[test]
    fn the_point_limit_is_the_library_limit() {
        assert_eq!(usize::try_from(super::LML_MAX_TRACE_POINTS), Ok(crate::tracing::MAX_TRACE_POINTS));
    }
}
