//! The node and strip diagnostics of Sec. 5.1 (Prop. 1–2) at every centre-line vertex of the
//! strips, through the C ABI.

use super::guard::guarded;
use super::raw::copy_out;
use super::status::LmlStatus;
use super::strips::{strips_of, LmlStrips};
use crate::strips::VertexDiagnostics;

/// `LmlVertexDiagnostics.defined` bit: `curvature` is defined.
pub const LML_DIAGNOSTIC_CURVATURE: u32 = 1;
/// `LmlVertexDiagnostics.defined` bit: `torsion` is defined.
pub const LML_DIAGNOSTIC_TORSION: u32 = 1 << 1;
/// `LmlVertexDiagnostics.defined` bit: `conical_curvature` is defined (the vertex bends).
pub const LML_DIAGNOSTIC_CONICAL_CURVATURE: u32 = 1 << 2;
/// `LmlVertexDiagnostics.defined` bit: `darboux_angle_degrees` is defined.
pub const LML_DIAGNOSTIC_DARBOUX_ANGLE: u32 = 1 << 3;
/// `LmlVertexDiagnostics.defined` bit: `binormal_ruling_degrees` is defined.
pub const LML_DIAGNOSTIC_BINORMAL_RULING: u32 = 1 << 4;
/// `LmlVertexDiagnostics.defined` bit: `binormal_offset` is defined.
pub const LML_DIAGNOSTIC_BINORMAL_OFFSET: u32 = 1 << 5;
/// `LmlVertexDiagnostics.defined` bit: `singular_point_distance` is defined (else the singular
/// point is at infinity, or the vertex is straight).
pub const LML_DIAGNOSTIC_SINGULAR_POINT_DISTANCE: u32 = 1 << 6;

/// The Sec. 5.1 quantities at one centre-line vertex of a strip (see `lml_strips_diagnostics`).
/// A quantity whose bit is not set in `defined` is 0 (end vertices, straight stretches, a torsion
/// or k′ that cannot be differenced): no NaN is ever written. Lengths in the mesh's units.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LmlVertexDiagnostics {
    /// `LML_DIAGNOSTIC_*` bits of the quantities that are defined.
    pub defined: u32,
    /// 1 when the singular point of the rectifying developable's ruling lies inside the strip or
    /// within one strip width of its boundary (Prop. 1), else 0.
    pub singular_point_near: u32,
    /// Curvature κ ≥ 0 (of the circle through the vertex and its neighbours).
    pub curvature: f64,
    /// Torsion τ (signed).
    pub torsion: f64,
    /// Conical curvature k = τ/κ.
    pub conical_curvature: f64,
    /// Angle atan |k| in degrees between the binormal and the Darboux vector (the ruling of the
    /// rectifying developable).
    pub darboux_angle_degrees: f64,
    /// Angle in degrees between the strip's binormal and its ruling at the vertex.
    pub binormal_ruling_degrees: f64,
    /// κ k² v² / 2 at v = half the strip width (Prop. 2): the distance of the binormal's point at
    /// the strip edge from the rectifying developable.
    pub binormal_offset: f64,
    /// Distance along the ruling from the curve to the ruling's singular point.
    pub singular_point_distance: f64,
}

impl From<&VertexDiagnostics> for LmlVertexDiagnostics {
    fn from(d: &VertexDiagnostics) -> LmlVertexDiagnostics {
        let mut defined = 0;
        let mut value = |bit: u32, v: Option<f64>| match v {
            Some(v) => {
                defined |= bit;
                v
            }
            None => 0.0,
        };
        let curvature = value(LML_DIAGNOSTIC_CURVATURE, d.curvature);
        let torsion = value(LML_DIAGNOSTIC_TORSION, d.torsion);
        let conical_curvature = value(LML_DIAGNOSTIC_CONICAL_CURVATURE, d.conical_curvature);
        let darboux_angle_degrees = value(LML_DIAGNOSTIC_DARBOUX_ANGLE, d.darboux_angle_degrees);
        let binormal_ruling_degrees = value(LML_DIAGNOSTIC_BINORMAL_RULING, d.binormal_ruling_degrees);
        let binormal_offset = value(LML_DIAGNOSTIC_BINORMAL_OFFSET, d.binormal_offset);
        let singular_point_distance = value(LML_DIAGNOSTIC_SINGULAR_POINT_DISTANCE, d.singular_point_distance);
        LmlVertexDiagnostics {
            defined,
            singular_point_near: u32::from(d.singular_point_near),
            curvature,
            torsion,
            conical_curvature,
            darboux_angle_degrees,
            binormal_ruling_degrees,
            binormal_offset,
            singular_point_distance,
        }
    }
}

/// Copies the Sec. 5.1 diagnostics of every centre-line point, laid out as `lml_strips_centres`
/// (one struct per point, strips one after another as `lml_strips_point_offsets` says): how far
/// each strip's binormals (the usual node axes) are from the rulings of its rectifying
/// developable, and where that developable's singular points lie.
///
/// Two-call pattern as `lml_strips_point_offsets` (`capacity` and `*needed` count structs).
/// Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL` or `LML_STATUS_INVALID_ARGUMENT`.
#[no_mangle]
pub unsafe extern "C" fn lml_strips_diagnostics(strips: *const LmlStrips, out: *mut LmlVertexDiagnostics, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `out` writable for `capacity` structs; writable `needed`.
        let strips = unsafe { strips_of(strips) }?;
        let diagnostics: Vec<LmlVertexDiagnostics> = strips.iter().flat_map(|s| s.diagnostics()).map(|d| LmlVertexDiagnostics::from(&d)).collect();
        unsafe { copy_out(&diagnostics, out, capacity, needed, "out") }
    })
}
