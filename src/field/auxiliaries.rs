//! The auxiliary binormal `b` and side vector `u` of each curve vertex of a pseudo-geodesic
//! field (Eq. 9–10): their start and the orientation test of Sec. 3.2.2. Shared by the
//! single-field solver and the multi-field one ([`crate::net`]); `x` is the problem's own view of
//! the variables (its field first, its auxiliaries at [`FieldProblem::auxiliary_start`]).

use super::darboux::LevelFrame;
use super::params::Family;
use super::problem::FieldProblem;
use crate::mesh::Vec3;

/// The auxiliary vector at `offset` (0: `b`, 3: `u`) of the `k`-th curve vertex.
pub(crate) fn auxiliary(problem: &FieldProblem, x: &[f64], k: usize, offset: usize) -> Vec3 {
    let start = problem.auxiliary_start(k) + offset;
    Vec3::new(x[start], x[start + 1], x[start + 2])
}

fn set_auxiliary(problem: &FieldProblem, x: &mut [f64], k: usize, offset: usize, value: &Vec3) {
    let start = problem.auxiliary_start(k) + offset;
    x[start..start + 3].copy_from_slice(value.as_slice());
}

/// Starts `b` at the discrete binormal of the level polyline (or at `cos θ n + sin θ u` where it
/// is straight) and `u` at `n × t` (Sec. 3.2.2). Nothing to do for other families.
pub(crate) fn initialize_auxiliaries(problem: &FieldProblem, x: &mut [f64]) {
    let Family::PseudoGeodesic { theta_degrees } = problem.family() else { return };
    let (sin, cos) = theta_degrees.to_radians().sin_cos();
    for k in 0..problem.curve_vertices().len() {
        let v = problem.curve_vertices()[k] as usize;
        let normal = problem.mesh().smooth_normals()[v];
        let (b, u) = match problem.level_frame(k, x) {
            Some(frame) => (frame.binormal.unwrap_or(normal * cos + frame.side * sin), frame.side),
            None => (normal, any_tangent(&normal)),
        };
        set_auxiliary(problem, x, k, 0, &b);
        set_auxiliary(problem, x, k, 3, &u);
    }
}

/// The orientation test of Sec. 3.2.2 on the level `frames` of the current field: where
/// `det(q − p, u, n) ≤ 0`, re-initialise `u = n × (q − p)` normalised. Returns how many side
/// vectors were flipped (none for other families).
pub(crate) fn reorient_side_vectors(problem: &FieldProblem, x: &mut [f64], frames: &[Option<LevelFrame>]) -> usize {
    if !matches!(problem.family(), Family::PseudoGeodesic { .. }) {
        return 0;
    }
    let mut flips = 0;
    for (k, frame) in frames.iter().enumerate() {
        if let Some(frame) = frame {
            if auxiliary(problem, x, k, 3).dot(&frame.side) <= 0.0 {
                set_auxiliary(problem, x, k, 3, &frame.side);
                flips += 1;
            }
        }
    }
    flips
}

fn any_tangent(normal: &Vec3) -> Vec3 {
    let helper = if normal.x.abs() < 0.9 { Vec3::x() } else { Vec3::y() };
    normal.cross(&helper).normalize()
}
