//! The first segment of a traced curve. The start angle α fixes the curve's tangent at the
//! boundary start point `s`: the unit tangent `t_0` at angle α against the boundary direction,
//! in the tangent plane at `s` (the reference notes §4.2 measure α the same way, inside the
//! surface from the boundary direction that has the interior on its left).
//!
//! The first segment is then found like every other, by Eq. 4 with `t_0` as incoming
//! direction, so the start point already obeys the P-curve condition. Shooting the first
//! segment straight along `t_0` instead (the authors' code) leaves its chord tilted out of the
//! tangent plane, and that tilt turns into a persistent error of the curve's direction; for the
//! same reason the tangent plane at the start comes from a quadratic fit ([`start_normal`])
//! rather than from the one-sided boundary vertex normals.

use super::edge_search::Found;
use super::start_normal::start_normal;
use super::step::{next_point, StepFrom};
use super::TraceOptions;
use crate::mesh::{EdgeFaces, EdgePoint, TriMesh, Vec3};

/// The first point after `start` (position `s`) for the start angle α against the boundary
/// direction `r` (unit, interior on its left), or `None` if no candidate qualifies.
#[allow(clippy::too_many_arguments)]
pub(crate) fn first_segment(
    mesh: &TriMesh,
    adjacency: &EdgeFaces,
    start: &EdgePoint,
    s: &Vec3,
    r: &Vec3,
    alpha_degrees: f64,
    theta_degrees: f64,
    options: &TraceOptions,
) -> Option<Found> {
    let normal = start_normal(mesh, start, s)?;
    let along = (r - normal * r.dot(&normal)).try_normalize(0.0)?;
    let inward = normal.cross(&along);
    let (sin, cos) = alpha_degrees.to_radians().sin_cos();
    let tangent = along * cos + inward * sin;
    let from = StepFrom { point: start, position: s, arrived: None };
    next_point(mesh, adjacency, from, &tangent, theta_degrees, options)
}
