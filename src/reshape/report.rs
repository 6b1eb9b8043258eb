//! What a surface optimisation reports after each call to `step`.

use super::problem::SurfaceProblem;
use crate::field::Family;
use crate::mesh::Vec3;
use serde::{Deserialize, Serialize};

/// The unweighted terms of `E^M_pg` (Sec. 3.3) on the normalised problem (mean edge length 1).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct ReshapeEnergies {
    /// `E^S_fair = E^S_H + E^S_uni + E^S_c`.
    pub fair: f64,
    /// `E^S_close`, Eq. 14 (without the tolerance guard).
    pub close: f64,
    /// `E^S_angle` with its auxiliary constraints (Eq. 8–10).
    pub angle: f64,
    /// `E^S_edge`, Eq. 15.
    pub edge: f64,
}

/// State of a surface optimisation after a `step`. Lengths are in the caller's units.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct ReshapeReport {
    /// Iterations run since the solver was created.
    pub iterations: usize,
    /// Iterations run by this call.
    pub iterations_this_step: usize,
    pub energies: ReshapeEnergies,
    /// RMS and maximum of `|θ_measured − θ|` in degrees over the curve vertices whose level
    /// polyline `p⁺, v0, q⁺` is not straight, measured against the mesh's smooth normals (the
    /// optimiser's own diagnostic; judge curves with [`crate::quality::family_angles`]).
    pub angle_error_rms_degrees: f64,
    pub angle_error_max_degrees: f64,
    /// Curve vertices where the angle was measured.
    pub measured_vertices: usize,
    /// Largest and RMS distance of a vertex from the original surface (its closest point there).
    pub max_deviation: f64,
    pub rms_deviation: f64,
    /// The bound on `max_deviation`.
    pub tolerance: f64,
    /// Largest relative change of an edge length, `|l_e − l*_e| / l*_e`.
    pub max_edge_change: f64,
    /// Factor on the normal part of `E^S_close` (1 until a step left the tolerance).
    pub guard: f64,
    /// Steps undone during this call because they left the tolerance or broke the mesh.
    pub undone_steps: usize,
    /// Side vectors re-oriented during this call.
    pub flips: usize,
    /// Levenberg–Marquardt damping μ after the last iteration.
    pub damping: f64,
    pub converged: bool,
}

/// The star measure of the signed angle at every curve vertex of `problem` at positions `x`
/// (unit scale): `(sum of squared errors, max error, measured count)`.
pub(crate) fn star_angle_errors(problem: &SurfaceProblem, x: &[f64], theta: f64, model_size: f64) -> (f64, f64, usize) {
    let family = Family::PseudoGeodesic { theta_degrees: theta };
    let position = |v: u32| Vec3::new(x[3 * v as usize], x[3 * v as usize + 1], x[3 * v as usize + 2]);
    let mut result = (0.0, 0.0f64, 0);
    for curve in problem.curves() {
        let [p, q] = [curve.far_p, curve.far_q].map(|e| position(e.a) + (position(e.b) - position(e.a)) * e.t);
        let v0 = position(curve.vertex);
        let (incoming, outgoing, chord) = (v0 - p, q - v0, q - p);
        let cross = incoming.cross(&outgoing);
        // Straight at the model's scale (circumradius above the model size): no binormal.
        if cross.norm() * 2.0 * model_size <= incoming.norm() * outgoing.norm() * chord.norm() {
            continue;
        }
        let normal = problem.lin.normals[curve.vertex as usize];
        let Some(side) = normal.cross(&chord).try_normalize(0.0) else { continue };
        let binormal = cross.normalize();
        let sign = if binormal.dot(&side) < 0.0 { -1.0 } else { 1.0 };
        let measured = (sign * binormal.dot(&normal)).clamp(-1.0, 1.0).acos().to_degrees();
        let error = family.angle_error_degrees(measured, theta);
        result.0 += error * error;
        result.1 = result.1.max(error);
        result.2 += 1;
    }
    result
}
