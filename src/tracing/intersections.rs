//! Crossings between traced curves and self-intersections (the initialisation of Sec. 3.2.2
//! needs an ordered, intersection-free set of guide curves).
//!
//! Two segments are tested where they could meet: a uniform grid of cells (two mean edges or
//! the longest segment, whichever is wider) proposes the pairs. A pair is projected onto the plane normal to the mean surface normal at
//! its four end points and intersected there; the two segments must also come within half a
//! mean edge of each other in space, so sheets of a surface folding over itself do not meet.

use super::normal::point_normal;
use super::TracedCurve;
use crate::mesh::{TriMesh, Vec3};
use std::collections::HashMap;

/// Where two segments meet: curve indices, segment indices (segment `k` joins points `k` and
/// `k + 1`) and the meeting point. For a self-intersection both curves are the same.
#[derive(Clone, Debug, PartialEq)]
pub struct Crossing {
    pub curves: [usize; 2],
    pub segments: [usize; 2],
    pub position: Vec3,
}

/// Crossings between different curves and self-intersections, each sorted by (curves, segments).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct IntersectionReport {
    pub crossings: Vec<Crossing>,
    pub self_intersections: Vec<Crossing>,
}

impl IntersectionReport {
    pub fn is_intersection_free(&self) -> bool {
        self.crossings.is_empty() && self.self_intersections.is_empty()
    }
}

/// One segment of one curve.
struct Segment {
    curve: usize,
    index: usize,
    ends: [Vec3; 2],
    normal: Vec3,
}

/// All crossings and self-intersections of `curves` (traced on `mesh`). Segments that touch
/// count as meeting; consecutive segments of a curve (sharing a point) do not.
pub fn intersections(mesh: &TriMesh, curves: &[TracedCurve]) -> IntersectionReport {
    let segments: Vec<Segment> = curves
        .iter()
        .enumerate()
        .flat_map(|(c, curve)| {
            let (points, positions) = (curve.points(), curve.positions());
            (0..positions.len().saturating_sub(1)).map(move |k| {
                let normal = [&points[k], &points[k + 1]]
                    .iter()
                    .filter_map(|p| point_normal(mesh, p))
                    .fold(Vec3::zeros(), |sum, n| sum + n);
                Segment { curve: c, index: k, ends: [positions[k], positions[k + 1]], normal }
            })
        })
        .collect();
    let reach = 0.5 * mesh.mean_edge_length();
    let longest = segments.iter().map(|s| (s.ends[1] - s.ends[0]).norm()).fold(0.0, f64::max);
    let mut report = IntersectionReport::default();
    for (i, j) in candidate_pairs(&segments, (4.0 * reach).max(longest), reach) {
        let (a, b) = (&segments[i], &segments[j]);
        if a.curve == b.curve && a.index.abs_diff(b.index) <= 1 {
            continue;
        }
        if let Some(position) = meet(a, b, reach) {
            let crossing = Crossing { curves: [a.curve, b.curve], segments: [a.index, b.index], position };
            if a.curve == b.curve {
                report.self_intersections.push(crossing);
            } else {
                report.crossings.push(crossing);
            }
        }
    }
    report
}

/// Index pairs `(i, j)`, `i < j`, of segments whose bounding boxes (grown by `margin`) share a
/// grid cell of width `cell` (`cell ≥` every segment length and `≥ margin`, so each segment
/// covers at most 3 × 3 × 3 cells); sorted and without repeats.
fn candidate_pairs(segments: &[Segment], cell: f64, margin: f64) -> Vec<(usize, usize)> {
    let mut grid: HashMap<[i64; 3], Vec<usize>> = HashMap::new();
    let key = |x: f64| (x / cell).floor() as i64;
    for (s, segment) in segments.iter().enumerate() {
        let [p, q] = segment.ends;
        let (lo, hi) = (p.inf(&q).add_scalar(-margin), p.sup(&q).add_scalar(margin));
        for x in key(lo.x)..=key(hi.x) {
            for y in key(lo.y)..=key(hi.y) {
                for z in key(lo.z)..=key(hi.z) {
                    grid.entry([x, y, z]).or_default().push(s);
                }
            }
        }
    }
    let mut pairs: Vec<(usize, usize)> = grid
        .values()
        .flat_map(|members| {
            members.iter().enumerate().flat_map(move |(k, &i)| members[k + 1..].iter().map(move |&j| (i.min(j), i.max(j))))
        })
        .collect();
    pairs.sort_unstable();
    pairs.dedup();
    pairs
}

/// The point where segments `a` and `b` meet in the projection along their mean normal, if
/// they also come within `reach` of each other in space there.
fn meet(a: &Segment, b: &Segment, reach: f64) -> Option<Vec3> {
    let normal = (a.normal + b.normal).try_normalize(0.0)?;
    let e1 = normal.cross(&Vec3::x()).try_normalize(1e-6).or_else(|| normal.cross(&Vec3::y()).try_normalize(0.0))?;
    let e2 = normal.cross(&e1);
    let origin = a.ends[0];
    let flat = |p: &Vec3| ((p - origin).dot(&e1), (p - origin).dot(&e2));
    let (p0, p1, q0, q1) = (flat(&a.ends[0]), flat(&a.ends[1]), flat(&b.ends[0]), flat(&b.ends[1]));
    let (s, t) = segment_parameters(p0, p1, q0, q1)?;
    let on_a = a.ends[0].lerp(&a.ends[1], s);
    let on_b = b.ends[0].lerp(&b.ends[1], t);
    ((on_a - on_b).norm() <= reach).then(|| on_a.lerp(&on_b, 0.5))
}

/// Parameters `(s, t) ∈ [0, 1]²` where the plane segments `p0 p1` and `q0 q1` meet (touching
/// included; for overlapping collinear segments, the first point of the overlap on `p`).
fn segment_parameters(p0: (f64, f64), p1: (f64, f64), q0: (f64, f64), q1: (f64, f64)) -> Option<(f64, f64)> {
    let cross = |u: (f64, f64), v: (f64, f64)| u.0 * v.1 - u.1 * v.0;
    let sub = |u: (f64, f64), v: (f64, f64)| (u.0 - v.0, u.1 - v.1);
    let (r, d) = (sub(p1, p0), sub(q1, q0));
    let denominator = cross(r, d);
    let w = sub(q0, p0);
    if denominator != 0.0 {
        let s = cross(w, d) / denominator;
        let t = cross(w, r) / denominator;
        return ((0.0..=1.0).contains(&s) && (0.0..=1.0).contains(&t)).then_some((s, t));
    }
    if cross(w, r) != 0.0 {
        return None; // parallel, not collinear
    }
    // Collinear: overlap of the parameter ranges of q0, q1 along p.
    let rr = r.0 * r.0 + r.1 * r.1;
    if rr == 0.0 {
        return None;
    }
    let along = |q: (f64, f64)| (sub(q, p0).0 * r.0 + sub(q, p0).1 * r.1) / rr;
    let (u0, u1) = (along(q0), along(q1));
    let (lo, hi) = (u0.min(u1).max(0.0), u0.max(u1).min(1.0));
    if lo > hi {
        return None;
    }
    let dd = d.0 * d.0 + d.1 * d.1;
    let point = (p0.0 + lo * r.0, p0.1 + lo * r.1);
    let t = if dd > 0.0 { (sub(point, q0).0 * d.0 + sub(point, q0).1 * d.1) / dd } else { 0.0 };
    Some((lo, t.clamp(0.0, 1.0)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::EdgePoint;
    use crate::tracing::StopReason;

    #[test]
    fn a_looping_curve_intersects_itself() {
        // The unit square in z = 0 (normals +z) and a hand-made bow tie: segments 0 and 2 cross.
        let positions = vec![Vec3::new(0.0, 0.0, 0.0), Vec3::new(1.0, 0.0, 0.0), Vec3::new(1.0, 1.0, 0.0), Vec3::new(0.0, 1.0, 0.0)];
        let mesh = TriMesh::from_vertices_and_faces(positions, vec![[0, 1, 2], [0, 2, 3]]).expect("valid");
        let corners = [(0.1, 0.1), (0.9, 0.9), (0.9, 0.1), (0.1, 0.9)];
        let points = vec![EdgePoint { edge: [0, 1], t: 0.0 }; 4];
        let curve = TracedCurve::new(points, corners.iter().map(|&(x, y)| Vec3::new(x, y, 0.0)).collect(), StopReason::Boundary);
        let report = intersections(&mesh, &[curve]);
        assert!(report.crossings.is_empty());
        assert_eq!(report.self_intersections.len(), 1);
        let hit = &report.self_intersections[0];
        assert_eq!((hit.curves, hit.segments), ([0, 0], [0, 2]));
        assert!((hit.position - Vec3::new(0.5, 0.5, 0.0)).norm() < 1e-12);
    }

    #[test]
    fn plane_segments_meet_touch_or_miss() {
        let (s, t) = segment_parameters((0.0, 0.0), (2.0, 0.0), (1.0, -1.0), (1.0, 1.0)).expect("crossing");
        assert!((s - 0.5).abs() < 1e-15 && (t - 0.5).abs() < 1e-15);
        assert!(segment_parameters((0.0, 0.0), (2.0, 0.0), (2.0, 0.0), (3.0, 1.0)).is_some());
        assert!(segment_parameters((0.0, 0.0), (2.0, 0.0), (0.0, 1.0), (2.0, 1.0)).is_none());
        assert!(segment_parameters((0.0, 0.0), (2.0, 0.0), (1.0, 0.0), (3.0, 0.0)).is_some());
        assert!(segment_parameters((0.0, 0.0), (1.0, 0.0), (2.0, 0.0), (3.0, 0.0)).is_none());
        assert!(segment_parameters((0.0, 0.0), (1.0, 1.0), (1.1, 1.1), (0.0, 3.0)).is_none());
    }
}
