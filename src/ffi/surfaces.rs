//! Built-in surfaces: the Brauner surface of the paper's Fig. 32 (Sec. 5.2.4, Eq. 23), a
//! validation case with known asymptotic curves of constant slope.

use super::failure::Failure;
use super::guard::guarded;
use super::layout::flat_xyz;
use super::mesh::LmlMesh;
use super::raw::{copy_out, Out};
use super::status::LmlStatus;
use crate::surfaces::{brauner_surface, BraunerSurface};

/// Most vertices of a built-in surface.
pub const LML_MAX_SURFACE_VERTICES: usize = 1_000_000;
/// Most points of the u-lines of `lml_brauner_u_lines`, all lines together.
pub const LML_MAX_U_LINE_POINTS: usize = 1_000_000;

/// The paper's surface with `mu`, checked.
fn brauner(target_vertices: usize, mu: f64) -> Result<BraunerSurface, Failure> {
    if !(mu.is_finite() && mu > 0.0) {
        return Err(Failure::argument("mu", format!("must be finite and > 0, got {mu}")));
    }
    Ok(BraunerSurface { mu, ..BraunerSurface::paper(target_vertices) })
}

/// Creates the Brauner surface of the paper's Fig. 32 (Eq. 23 with `f = e^{−v}(cos u + u sin u
/// + 2v cos u)`): `x = cos²u − 2v`, `y = sin u cos u − u`, `z = 2μ e^{−v} cos u` over
/// u ∈ [0.6, π − 0.6], v ∈ [−0.5, 0.5], triangulated by a jittered grid of about
/// `target_vertices` vertices (deterministic), faces oriented upwards. Its u-lines `v = const`
/// are asymptotic curves rising at the constant slope `atan(μ e^{−v})` (`lml_brauner_u_lines`).
///
/// Returns `LML_STATUS_OK` or `LML_STATUS_INVALID_ARGUMENT` (NULL `out`, `target_vertices` below
/// 100 or above `LML_MAX_SURFACE_VERTICES`, `mu` not finite or ≤ 0, named); `*out` is NULL on
/// failure. Release the mesh with `lml_mesh_free`.
#[no_mangle]
pub unsafe extern "C" fn lml_mesh_new_brauner(target_vertices: usize, mu: f64, out: *mut *mut LmlMesh) -> LmlStatus {
    guarded(|| {
        // SAFETY: `out` is writable by contract.
        let mut out = unsafe { Out::new(out, "out") }?;
        out.set(std::ptr::null_mut());
        if !(100..=LML_MAX_SURFACE_VERTICES).contains(&target_vertices) {
            return Err(Failure::argument("target_vertices", format!("must lie in 100..={LML_MAX_SURFACE_VERTICES}, got {target_vertices}")));
        }
        let surface = brauner(target_vertices, mu)?;
        let generated = brauner_surface(&surface).map_err(|e| Failure::argument("mu", e))?;
        out.set_owned(LmlMesh { mesh: generated.into_mesh()? });
        Ok(LmlStatus::Ok)
    })
}

/// The u-lines of the surface of `lml_mesh_new_brauner` with `mu`, computed exactly: `lines`
/// curves `v = v_k`, v_k spread evenly over [−0.5, 0.5] (ends included), each of `points` points
/// evenly spaced in u. Line k rises at the slope `atan(μ e^{−v_k})` against the horizontal.
///
/// `out`: `lines × points` points, 3 doubles each, line after line. Two-call pattern: `*needed` is
/// set to `3 × lines × points`; a NULL `out` or a smaller `capacity` copies nothing and returns
/// `LML_STATUS_BUFFER_TOO_SMALL`.
///
/// Returns `LML_STATUS_OK`; `LML_STATUS_BUFFER_TOO_SMALL`; `LML_STATUS_INVALID_ARGUMENT` (NULL
/// `needed`, `lines` or `points` below 2, more than `LML_MAX_U_LINE_POINTS` points, `mu` not
/// finite or ≤ 0, named).
#[no_mangle]
pub unsafe extern "C" fn lml_brauner_u_lines(mu: f64, lines: usize, points: usize, out: *mut f64, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        for (name, count) in [("lines", lines), ("points", points)] {
            if count < 2 {
                return Err(Failure::argument(name, format!("must be at least 2, got {count}")));
            }
        }
        if lines.checked_mul(points).is_none_or(|total| total > LML_MAX_U_LINE_POINTS) {
            return Err(Failure::argument("points", format!("lines × points must be at most {LML_MAX_U_LINE_POINTS}")));
        }
        let surface = brauner(100, mu)?;
        let xyz: Vec<f64> = surface.u_line_levels(lines).into_iter().flat_map(|v| flat_xyz(&surface.u_line(v, points))).collect();
        // SAFETY: the two-call contract documented above.
        unsafe { copy_out(&xyz, out, capacity, needed, "out") }
    })
}
