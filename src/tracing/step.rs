//! One propagation step (Sec. 3.2.1, Fig. 13): from the segment `p_{i−1} p_i`, the next point
//! `p_{i+1}` on a candidate edge solves Eq. 4,
//! `[(g_i × g_{i+1})·n_i]² − ‖g_i × g_{i+1}‖²·cos²θ = 0`, with `g_i = p_i − p_{i−1}`,
//! `g_{i+1} = p_{i+1} − p_i`; of its two roots (the osculating planes σ1, σ2 of Fig. 8) the
//! signed Darboux-frame angle of Sec. 3.1 keeps the one of the traced family. At the start
//! point the incoming direction `g_0` is the prescribed start tangent instead of a segment.
//! For θ within the angle tolerance of 0° or 180° (asymptotic curves) Eq. 4 degenerates and its
//! limit [`AsymptoticLimit`] takes its place.

use super::asymptotic::AsymptoticLimit;
use super::edge_search::{cone_coefficients, nearest_solution, Found};
use super::neighbourhood::{candidate_edges, Reach};
use super::normal::point_normal;
use super::TraceOptions;
use crate::field::LevelFrame;
use crate::mesh::{EdgeFaces, EdgePoint, TriMesh, Vec3};

/// Below this `‖ê_i × ê_{i+1}‖` (a turn of 10⁻⁵ rad) two segments count as collinear: their
/// osculating plane is undefined, and a straight continuation is the zero-curvature limit of
/// every P-curve. Eq. 4 has such a (double) root where the curve crosses into a coplanar or
/// nearly coplanar face: there both osculating planes of Fig. 8 meet the edge where the
/// straight continuation does, and the measured angle is rounding noise.
const STRAIGHT: f64 = 1e-5;

/// Where a step starts: the current point, its position, and the face the curve arrived
/// through (`None` at the start point).
#[derive(Clone, Copy, Debug)]
pub(crate) struct StepFrom<'a> {
    pub point: &'a EdgePoint,
    pub position: &'a Vec3,
    pub arrived: Option<u32>,
}

/// The next point after `from`, entered along `incoming` (`g_i`); `None` if no candidate edge
/// point is forward (turn below [`TraceOptions::max_turn_degrees`]), farther than `d0` and of
/// the traced family within tolerance, neither in the near search nor in the widened second round.
pub(crate) fn next_point(
    mesh: &TriMesh,
    adjacency: &EdgeFaces,
    from: StepFrom<'_>,
    incoming: &Vec3,
    theta_degrees: f64,
    options: &TraceOptions,
) -> Option<Found> {
    let normal = point_normal(mesh, from.point)?;
    let g = *incoming;
    let min_step = options.min_step_ratio * mesh.mean_edge_length();
    let cos = theta_degrees.to_radians().cos();
    let min_turn_cos = options.max_turn_degrees.to_radians().cos();
    let tolerance = options.angle_tolerance_degrees;
    let asymptotic = theta_degrees <= tolerance || theta_degrees >= 180.0 - tolerance;
    let forward = |step: &Vec3| {
        let along = step.dot(&g);
        along > 0.0 && along >= min_turn_cos * step.norm() * g.norm()
    };
    let search = |reach: Reach| {
        let candidates = candidate_edges(mesh, adjacency, from.point, from.arrived, reach);
        if asymptotic {
            let limit = AsymptoticLimit { mesh, normal: &normal, tolerance };
            let accept = |step: &Vec3, t: f64, edge: [u32; 2]| forward(step) && limit.accepts(step, t, edge);
            nearest_solution(mesh, from.position, &candidates, min_step, |x0, x1, edge| limit.coefficients(x0, x1, edge), accept)
        } else {
            let coefficients = |x0: &Vec3, x1: &Vec3, _: [u32; 2]| cone_coefficients(&g.cross(x0), &g.cross(x1), &normal, cos);
            let accept = |step: &Vec3, _: f64, _: [u32; 2]| forward(step) && angle_within(&g, step, &normal, theta_degrees, tolerance);
            nearest_solution(mesh, from.position, &candidates, min_step, coefficients, accept)
        }
    };
    search(Reach::Near { vertex_ratio: options.vertex_ratio }).or_else(|| search(Reach::Wide))
}

/// Whether the turn `incoming → outgoing` at a point with unit `normal` realises the signed
/// binormal angle θ (Sec. 3.1, measured as [`LevelFrame::signed_angle_degrees`] with the tangent
/// of Eq. 1 and the side vector `u = n × t`) within `tolerance` degrees. The angle is defined
/// modulo 180° (`b ~ −b`), so θ = 0 and θ = 180 both mean asymptotic.
fn angle_within(incoming: &Vec3, outgoing: &Vec3, normal: &Vec3, theta_degrees: f64, tolerance: f64) -> bool {
    let (e_in, e_out) = (incoming.normalize(), outgoing.normalize());
    let cross = e_in.cross(&e_out);
    if cross.norm() < STRAIGHT {
        return true;
    }
    let Some(tangent) = (e_in + e_out).try_normalize(0.0) else { return false };
    let Some(side) = normal.cross(&tangent).try_normalize(0.0) else { return false };
    let frame = LevelFrame { tangent, normal: *normal, side, binormal: Some(cross.normalize()) };
    frame.signed_angle_degrees().is_some_and(|angle| {
        let difference = (angle - theta_degrees).abs();
        difference.min(180.0 - difference) <= tolerance
    })
}
