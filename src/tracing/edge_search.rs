//! The search of every step (the first segment included): on each candidate edge
//! `P(t) = (1 − t)·v_s + t·v_e`, solve the step's equation (quadratic in `t`: the cone of Eq. 4
//! or its asymptotic limit), keep the roots that lie on the edge, are farther than `d0` and pass
//! the caller's test, and take the nearest (Sec. 3.2.1).

use super::neighbourhood::CandidateEdge;
use super::quadratic::candidate_parameters;
use crate::mesh::{EdgePoint, TriMesh, Vec3};

/// Roots this far outside `[0, 1]` (rounding at the edge ends) are clamped onto the edge.
const END_SLACK: f64 = 1e-9;

/// A point found on a candidate edge, with the face the segment to it crosses.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Found {
    pub point: EdgePoint,
    pub position: Vec3,
    pub face: u32,
}

/// Coefficients `(a, b, c)` of `(X(t)·m)² − cos²·‖X(t)‖² = a t² + b t + c` for the linear
/// `X(t) = x0 + t·x1`: `X(t)` lies on the double cone with unit axis `m` and half-angle `acos(cos)`.
/// Eq. 4 is this with `X = g_i × g_{i+1}` and `m = n_i`.
pub(crate) fn cone_coefficients(x0: &Vec3, x1: &Vec3, axis: &Vec3, cos: f64) -> (f64, f64, f64) {
    let cos2 = cos * cos;
    let (m0, m1) = (x0.dot(axis), x1.dot(axis));
    (
        m1 * m1 - cos2 * x1.norm_squared(),
        2.0 * (m0 * m1 - cos2 * x0.dot(x1)),
        m0 * m0 - cos2 * x0.norm_squared(),
    )
}

/// The point on the `candidates` that solves the equation whose coefficients
/// `coefficients(v_s − from, v_e − v_s, [s, e])` gives, lies farther than `min_step` (`d0`) from `from`,
/// and passes `accept(P − from, t, [s, e])`: the nearest such point, ties keeping the earlier
/// candidate. On a boundary edge any positive distance will do: `d0` protects the osculating
/// plane of the *next* step, and the curve ends there.
pub(crate) fn nearest_solution(
    mesh: &TriMesh,
    from: &Vec3,
    candidates: &[CandidateEdge],
    min_step: f64,
    coefficients: impl Fn(&Vec3, &Vec3, [u32; 2]) -> (f64, f64, f64),
    accept: impl Fn(&Vec3, f64, [u32; 2]) -> bool,
) -> Option<Found> {
    let positions = mesh.positions();
    let mut best: Option<(f64, Found)> = None;
    for candidate in candidates {
        let [s, e] = candidate.edge;
        // Internal invariant: candidate edges come from the mesh's faces.
        let (ps, pe) = (positions[s as usize], positions[e as usize]);
        let (a, b, c) = coefficients(&(ps - from), &(pe - ps), candidate.edge);
        for t in candidate_parameters(a, b, c) {
            if !(-END_SLACK..=1.0 + END_SLACK).contains(&t) {
                continue;
            }
            let t = t.clamp(0.0, 1.0);
            let position = ps.lerp(&pe, t);
            let step = position - from;
            let floor = if candidate.on_boundary { 0.0 } else { min_step };
            if !(step.norm() > floor && accept(&step, t, candidate.edge)) {
                continue;
            }
            let distance = step.norm();
            if best.as_ref().is_none_or(|(nearest, _)| distance < *nearest) {
                let point = EdgePoint { edge: candidate.edge, t };
                best = Some((distance, Found { point, position, face: candidate.face }));
            }
        }
    }
    best.map(|(_, found)| found)
}
