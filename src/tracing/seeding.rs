//! Start points for traced guide curves on the mesh boundary (reference notes §4.1): the
//! boundary loops split at corners into segments, evenly spaced start points along a segment,
//! a single start point by arc-length parameter along a loop, and the boundary point nearest to
//! a given point in space (where a designer clicks).

use super::TraceError;
use crate::mesh::{EdgePoint, TriMesh, Vec3};

/// The default corner threshold: a boundary vertex where the boundary turns by at least 30°
/// (the authors' corner angle of 150°, reference notes §4.1).
pub const DEFAULT_CORNER_TURN_DEGREES: f64 = 30.0;

/// A run of consecutive boundary vertices of one loop, in loop order (interior on the left),
/// from corner to corner; a loop without corners is one closed segment whose last vertex
/// repeats its first.
#[derive(Clone, Debug, PartialEq)]
pub struct BoundarySegment {
    loop_index: usize,
    vertices: Vec<u32>,
}

impl BoundarySegment {
    /// Index of the loop in [`TriMesh::boundary_loops`].
    pub fn loop_index(&self) -> usize {
        self.loop_index
    }

    /// The vertices, consecutive ones joined by boundary edges (at least two).
    pub fn vertices(&self) -> &[u32] {
        &self.vertices
    }
}

/// Splits boundary loop `loop_index` at its corners: vertices where the boundary direction
/// turns by at least `corner_turn_degrees` (∈ [0°, 180°], e.g.
/// [`DEFAULT_CORNER_TURN_DEGREES`]). The segments follow the loop, starting at its first corner.
pub fn boundary_segments(mesh: &TriMesh, loop_index: usize, corner_turn_degrees: f64) -> Result<Vec<BoundarySegment>, TraceError> {
    if !(0.0..=180.0).contains(&corner_turn_degrees) {
        return Err(TraceError::CornerAngleOutOfRange { degrees: corner_turn_degrees });
    }
    let boundary_loop = boundary_loop(mesh, loop_index)?;
    let positions = mesh.positions();
    let n = boundary_loop.len();
    // Internal invariant: loop vertices are mesh vertices.
    let at = |k: usize| positions[boundary_loop[k % n] as usize];
    let corners: Vec<usize> = (0..n)
        .filter(|&k| {
            let incoming = at(k + n) - at(k + n - 1);
            let outgoing = at(k + 1) - at(k);
            incoming.angle(&outgoing).to_degrees() >= corner_turn_degrees
        })
        .collect();
    let run = |from: usize, edges: usize| BoundarySegment {
        loop_index,
        vertices: (from..=from + edges).map(|k| boundary_loop[k % n]).collect(),
    };
    if corners.is_empty() {
        return Ok(vec![run(0, n)]);
    }
    Ok((0..corners.len())
        .map(|j| {
            let (from, to) = (corners[j], corners[(j + 1) % corners.len()]);
            let edges = if to > from { to - from } else { to + n - from };
            run(from, edges)
        })
        .collect())
}

/// Most start points one [`evenly_spaced_starts`] call returns.
pub const MAX_STARTS: usize = 10_000;

/// `count` start points on segment `segment_index` of `segments`, evenly spaced by arc length:
/// at arc lengths `(i + ½)·L / count` from the segment's first vertex, so neighbours are `L / count`
/// apart and the corners are avoided. Each is an [`EdgePoint`] on a boundary edge, its edge
/// given in loop order. `count` is 1 to [`MAX_STARTS`] ([`TraceError::ZeroCurves`],
/// [`TraceError::TooManyStarts`]).
pub fn evenly_spaced_starts(
    mesh: &TriMesh,
    segments: &[BoundarySegment],
    segment_index: usize,
    count: usize,
) -> Result<Vec<EdgePoint>, TraceError> {
    let segment = segments
        .get(segment_index)
        .ok_or(TraceError::SegmentOutOfRange { index: segment_index, count: segments.len() })?;
    if count == 0 {
        return Err(TraceError::ZeroCurves);
    }
    if count > MAX_STARTS {
        return Err(TraceError::TooManyStarts { count });
    }
    let polyline = BoundaryPolyline::new(mesh, &segment.vertices)?;
    Ok((0..count)
        .map(|i| polyline.point_at((i as f64 + 0.5) / count as f64 * polyline.length))
        .collect())
}

/// The start point at arc-length parameter `s ∈ [0, 1]` along boundary loop `loop_index`,
/// measured from the loop's first vertex in loop order (`s = 1` is back at the first vertex).
pub fn boundary_start(mesh: &TriMesh, loop_index: usize, s: f64) -> Result<EdgePoint, TraceError> {
    let boundary_loop = boundary_loop(mesh, loop_index)?;
    if !(0.0..=1.0).contains(&s) {
        return Err(TraceError::ArcParameterOutOfRange { s });
    }
    let mut closed = boundary_loop.to_vec();
    closed.push(boundary_loop[0]);
    let polyline = BoundaryPolyline::new(mesh, &closed)?;
    Ok(polyline.point_at(s * polyline.length))
}

/// The point of the mesh boundary (any loop) closest to `point` in space, on its boundary edge
/// given in loop order. Ties go to the first edge in loop order (loops in the order of
/// [`TriMesh::boundary_loops`]), so the answer is deterministic.
pub fn nearest_boundary_point(mesh: &TriMesh, point: Vec3) -> Result<EdgePoint, TraceError> {
    if !point.iter().all(|c| c.is_finite()) {
        return Err(TraceError::NonFinitePoint);
    }
    let positions = mesh.positions();
    let mut best: Option<(f64, EdgePoint)> = None;
    for boundary_loop in mesh.boundary_loops() {
        for (k, &a) in boundary_loop.iter().enumerate() {
            let b = boundary_loop[(k + 1) % boundary_loop.len()];
            // Internal invariant: loop vertices are mesh vertices.
            let (pa, pb) = (positions[a as usize], positions[b as usize]);
            let edge = pb - pa;
            let length2 = edge.norm_squared();
            let t = if length2 > 0.0 { ((point - pa).dot(&edge) / length2).clamp(0.0, 1.0) } else { 0.0 };
            let distance2 = (pa + t * edge - point).norm_squared();
            if best.as_ref().is_none_or(|(d, _)| distance2 < *d) {
                best = Some((distance2, EdgePoint { edge: [a, b], t }));
            }
        }
    }
    best.map(|(_, p)| p).ok_or(TraceError::LoopOutOfRange { index: 0, count: 0 })
}

/// Boundary loop `index` of `mesh`.
fn boundary_loop(mesh: &TriMesh, index: usize) -> Result<&[u32], TraceError> {
    let loops = mesh.boundary_loops();
    loops
        .get(index)
        .map(Vec::as_slice)
        .ok_or(TraceError::LoopOutOfRange { index, count: loops.len() })
}

/// A boundary polyline with its vertex positions and total length.
struct BoundaryPolyline<'a> {
    vertices: &'a [u32],
    points: Vec<Vec3>,
    length: f64,
}

impl<'a> BoundaryPolyline<'a> {
    /// Fails if a vertex is not a vertex of `mesh` (a segment of another mesh).
    fn new(mesh: &TriMesh, vertices: &'a [u32]) -> Result<BoundaryPolyline<'a>, TraceError> {
        let positions = mesh.positions();
        let points = vertices
            .iter()
            .map(|&v| {
                positions.get(v as usize).copied().ok_or(TraceError::VertexOutOfRange { vertex: v, vertex_count: positions.len() })
            })
            .collect::<Result<Vec<Vec3>, TraceError>>()?;
        let length = points.windows(2).map(|w| (w[1] - w[0]).norm()).sum();
        Ok(BoundaryPolyline { vertices, points, length })
    }

    /// The point at arc length `arc` (clamped to the polyline) on its edge, in polyline order.
    fn point_at(&self, arc: f64) -> EdgePoint {
        // Internal invariant: boundary polylines have at least two vertices (one edge).
        let lengths: Vec<f64> = self.points.windows(2).map(|w| (w[1] - w[0]).norm()).collect();
        let mut remaining = arc.max(0.0);
        let mut k = 0;
        while k + 1 < lengths.len() && remaining > lengths[k] {
            remaining -= lengths[k];
            k += 1;
        }
        let t = if lengths[k] > 0.0 { (remaining / lengths[k]).clamp(0.0, 1.0) } else { 0.0 };
        EdgePoint { edge: [self.vertices[k], self.vertices[k + 1]], t }
    }
}
