//! The tracer (Sec. 3.2.1): a discrete pseudo-geodesic of angle θ from a boundary start point,
//! point by point until the boundary, a singular configuration, or a limit.

use super::first_segment::first_segment;
use super::step::{next_point, StepFrom};
use super::{StopReason, TraceError, TraceOptions, TracedCurve};
use crate::mesh::{EdgeFaces, EdgePoint, TriMesh, Vec3};

/// Traces guide curves on one mesh; holds the edge → face adjacency, built once.
#[derive(Clone, Debug)]
pub struct Tracer<'a> {
    mesh: &'a TriMesh,
    adjacency: EdgeFaces,
}

/// A validated start: canonical edge point, its position and the unit boundary tangent.
struct Start {
    point: EdgePoint,
    position: Vec3,
    tangent: Vec3,
}

impl<'a> Tracer<'a> {
    pub fn new(mesh: &'a TriMesh) -> Tracer<'a> {
        Tracer { mesh, adjacency: EdgeFaces::new(mesh) }
    }

    /// The mesh traced on.
    pub fn mesh(&self) -> &'a TriMesh {
        self.mesh
    }

    /// Traces the discrete P-curve of angle `theta_degrees` (θ ∈ [0°, 180°] between binormal
    /// and surface normal, Eq. 2; θ and 180° − θ are the mirror families, 90° gives geodesics
    /// and 0° or 180° asymptotic curves) from `start`, a point on a boundary edge (either
    /// orientation of the edge).
    ///
    /// `start_angle_degrees` (α ∈ (0°, 180°)) fixes the curve's tangent at `start`: the angle
    /// against the boundary direction that has the interior on its left, turned towards the
    /// interior in the tangent plane (α = 90°: perpendicular into the surface). Every point,
    /// the first included, solves Eq. 4 on the edges of the triangle across the current edge
    /// (near a vertex also its one-ring; if nothing qualifies, the one-rings of both edge ends),
    /// with the root of the family's signed angle, turning by less than
    /// [`TraceOptions::max_turn_degrees`], farther than `d0`, nearest. For θ within the angle
    /// tolerance of 0° or 180° the degenerate Eq. 4 is replaced by its limit, zero normal
    /// curvature per step.
    ///
    /// Before each step the first stop rule that applies ends the curve, in this order: the
    /// point is on the boundary, the length limit, the point limit; a step without a valid
    /// candidate ends it as [`StopReason::NoValidCandidate`]. The curve has at least two points.
    pub fn trace(
        &self,
        start: &EdgePoint,
        theta_degrees: f64,
        start_angle_degrees: f64,
        options: &TraceOptions,
    ) -> Result<TracedCurve, TraceError> {
        options.validate()?;
        let start = self.validate_start(start)?;
        if !(0.0..=180.0).contains(&theta_degrees) {
            return Err(TraceError::ThetaOutOfRange { degrees: theta_degrees });
        }
        if !(start_angle_degrees > 0.0 && start_angle_degrees < 180.0) {
            return Err(TraceError::StartAngleOutOfRange { degrees: start_angle_degrees });
        }
        let mesh = self.mesh;
        let first = first_segment(
            mesh,
            &self.adjacency,
            &start.point,
            &start.position,
            &start.tangent,
            start_angle_degrees,
            theta_degrees,
            options,
        )
        .ok_or(TraceError::NoFirstSegment {
            a: start.point.edge[0],
            b: start.point.edge[1],
            t: start.point.t,
            start_angle_degrees,
        })?;
        let mut points = vec![start.point, first.point];
        let mut positions = vec![start.position, first.position];
        let mut length = (first.position - start.position).norm();
        let mut current = first;
        let stop = loop {
            if self.on_boundary(&current.point) {
                break StopReason::Boundary;
            }
            if length >= options.max_length {
                break StopReason::LengthLimit;
            }
            if points.len() >= options.max_points {
                break StopReason::PointLimit;
            }
            let incoming = current.position - positions[positions.len() - 2];
            let from = StepFrom { point: &current.point, position: &current.position, arrived: Some(current.face) };
            let Some(next) = next_point(mesh, &self.adjacency, from, &incoming, theta_degrees, options) else {
                break StopReason::NoValidCandidate;
            };
            length += (next.position - current.position).norm();
            points.push(next.point);
            positions.push(next.position);
            current = next;
        };
        Ok(TracedCurve::new(points, positions, stop))
    }

    /// Checks that `start` is a point on a boundary edge and returns it with `a < b`, its
    /// position and the boundary tangent (oriented as in the edge's face).
    fn validate_start(&self, start: &EdgePoint) -> Result<Start, TraceError> {
        let vertex_count = self.mesh.vertex_count();
        for &vertex in &start.edge {
            if vertex as usize >= vertex_count {
                return Err(TraceError::VertexOutOfRange { vertex, vertex_count });
            }
        }
        if !(0.0..=1.0).contains(&start.t) {
            return Err(TraceError::EdgeParameterOutOfRange { t: start.t });
        }
        let [a, b] = start.edge;
        let Some((face, None)) = self.adjacency.faces(a, b) else {
            return Err(TraceError::NotBoundaryEdge { a, b });
        };
        let point = if a < b { *start } else { EdgePoint { edge: [b, a], t: 1.0 - start.t } };
        let [lo, hi] = point.edge;
        // Internal invariant: indices validated above; the face is the edge's face.
        let positions = self.mesh.positions();
        let corners = self.mesh.faces()[face as usize];
        let lo_corner = corners.iter().position(|&c| c == lo).unwrap_or(0);
        let (from, to) = if corners[(lo_corner + 1) % 3] == hi { (lo, hi) } else { (hi, lo) };
        let tangent = (positions[to as usize] - positions[from as usize]).normalize();
        let position = positions[lo as usize].lerp(&positions[hi as usize], point.t);
        Ok(Start { point, position, tangent })
    }

    /// Whether `point` lies on the boundary: on a boundary edge, or exactly at a boundary vertex.
    fn on_boundary(&self, point: &EdgePoint) -> bool {
        let [a, b] = point.edge;
        let at_vertex = if point.t == 0.0 {
            Some(a)
        } else if point.t == 1.0 {
            Some(b)
        } else {
            None
        };
        self.adjacency.is_boundary_edge(a, b) || at_vertex.is_some_and(|v| self.mesh.is_boundary_vertex(v as usize))
    }
}
