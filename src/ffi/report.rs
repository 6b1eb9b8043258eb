//! `LmlReport`: the state of a field optimisation after a step, as a plain C struct.

use crate::field::StepReport;

/// The state of a field optimisation after `lml_field_step` (written by the library; the caller
/// owns the struct). Energies are those of the normalised problem (mean edge length 1, initial
/// mean ‖∇F‖ 1), unweighted; angles are in degrees.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LmlReport {
    /// Iterations run since the session was created.
    pub iterations: u64,
    /// Iterations run by the last call.
    pub iterations_this_step: u64,
    /// Index of the weight stage in force (the number of warm-up stages for the final weights).
    pub stage: u64,
    /// `E_fair`, paper Eq. 6.
    pub energy_fair: f64,
    /// `E_grad`, paper Eq. 11.
    pub energy_grad: f64,
    /// The curve term: `E_angle` (Eq. 8) for pseudo-geodesics, `E_geo` or `E_asy` (Eq. 13).
    pub energy_angle: f64,
    /// The auxiliary-variable constraints of Eq. 9–10 (pseudo-geodesics only, else 0).
    pub energy_frame: f64,
    /// The weighted total λ_fair E_fair + λ_grad E_grad + λ_angle (E_angle + E_frame) being minimised.
    pub energy_total: f64,
    /// RMS of |θ_measured − θ| in degrees over the measured vertices, from the field's own level polylines.
    pub angle_error_rms_degrees: f64,
    /// Maximum of |θ_measured − θ| in degrees over the measured vertices.
    pub angle_error_max_degrees: f64,
    /// Interior vertices where the angle was measured.
    pub measured_vertices: u64,
    /// Interior vertices whose level curve does not cross exactly two star edges (list them
    /// with `lml_field_singular_vertices`).
    pub singular_vertex_count: u64,
    /// Side vectors re-oriented by the orientation test during the last call.
    pub flips: u64,
    /// Levenberg–Marquardt damping μ after the last iteration.
    pub damping: f64,
    /// 1 when the final stage has converged (further steps do nothing), else 0. (64 bits, like
    /// every field, so that the struct has no padding.)
    pub converged: u64,
}

impl From<&StepReport> for LmlReport {
    fn from(r: &StepReport) -> LmlReport {
        let count = |n: usize| n as u64;
        LmlReport {
            iterations: count(r.iterations),
            iterations_this_step: count(r.iterations_this_step),
            stage: count(r.stage),
            energy_fair: r.energies.fair,
            energy_grad: r.energies.grad,
            energy_angle: r.energies.angle,
            energy_frame: r.energies.frame,
            energy_total: r.energies.total,
            angle_error_rms_degrees: r.angle_error_rms_degrees,
            angle_error_max_degrees: r.angle_error_max_degrees,
            measured_vertices: count(r.measured_vertices),
            singular_vertex_count: count(r.singular_vertices.len()),
            flips: count(r.flips),
            damping: r.damping,
            converged: u64::from(r.converged),
        }
    }
}
