//! Seeding start points on the boundary: corners split the loop, starts are evenly spaced by
//! arc length, and a single start lies where its arc-length parameter says.

use crate::tracing_support;

use lamella::mesh::{EdgePoint, TriMesh, Vec3};
use lamella::tracing::{
    boundary_segments, boundary_start, evenly_spaced_starts, nearest_boundary_point, TraceError, DEFAULT_CORNER_TURN_DEGREES,
};
use tracing_support::{cylinder, saddle};

fn position(mesh: &TriMesh, p: &EdgePoint) -> Vec3 {
    p.position(mesh).expect("point on the mesh")
}

/// Arc length along the polyline `vertices` from its first vertex to `p` (on one of its edges).
fn arc_length_to(mesh: &TriMesh, vertices: &[u32], p: &EdgePoint) -> f64 {
    let pos = mesh.positions();
    let mut arc = 0.0;
    for w in vertices.windows(2) {
        let (a, b) = (pos[w[0] as usize], pos[w[1] as usize]);
        if p.edge == [w[0], w[1]] {
            return arc + p.t * (b - a).norm();
        }
        arc += (b - a).norm();
    }
    panic!("{p:?} is not on the polyline");
}

#[test]
fn corners_split_rectangular_patches_into_four_sides() {
    for mesh in [cylinder(3000, 5), saddle(8.0, 5.0, 2000)] {
        let segments = boundary_segments(&mesh, 0, DEFAULT_CORNER_TURN_DEGREES).expect("valid loop");
        assert_eq!(segments.len(), 4);
        let (lo, hi) = mesh.bounding_box();
        let corner_count = |p: &Vec3| {
            // The patch corners are extreme in two coordinates of the bounding box.
            [(p.x, lo.x, hi.x), (p.y, lo.y, hi.y), (p.z, lo.z, hi.z)]
                .iter()
                .filter(|(v, l, h)| (v - l).abs() < 1e-9 || (v - h).abs() < 1e-9)
                .count()
        };
        let boundary_loop = &mesh.boundary_loops()[0];
        let mut total = 0;
        for segment in &segments {
            let v = segment.vertices();
            assert!(v.len() >= 3);
            for end in [v[0], v[v.len() - 1]] {
                assert!(corner_count(&mesh.positions()[end as usize]) >= 2, "segment end {end} is not a corner");
            }
            total += v.len() - 1;
        }
        assert_eq!(total, boundary_loop.len(), "the segments cover the loop once");
    }
}

#[test]
fn no_corners_leave_one_closed_segment() {
    let mesh = cylinder(1000, 5);
    let segments = boundary_segments(&mesh, 0, 180.0).expect("valid loop");
    assert_eq!(segments.len(), 1);
    let v = segments[0].vertices();
    assert_eq!(v.len(), mesh.boundary_loops()[0].len() + 1);
    assert_eq!(v[0], v[v.len() - 1]);
}

#[test]
fn starts_are_evenly_spaced_by_arc_length() {
    let mesh = cylinder(3000, 9);
    let segments = boundary_segments(&mesh, 0, DEFAULT_CORNER_TURN_DEGREES).expect("valid loop");
    for (index, segment) in segments.iter().enumerate() {
        let starts = evenly_spaced_starts(&mesh, &segments, index, 7).expect("valid request");
        assert_eq!(starts.len(), 7);
        let v = segment.vertices();
        let length: f64 = v.windows(2).map(|w| (mesh.positions()[w[1] as usize] - mesh.positions()[w[0] as usize]).norm()).sum();
        let arcs: Vec<f64> = starts.iter().map(|p| arc_length_to(&mesh, v, p)).collect();
        for (i, arc) in arcs.iter().enumerate() {
            let expected = (i as f64 + 0.5) * length / 7.0;
            assert!((arc - expected).abs() < 1e-9 * length, "start {i}: arc {arc} vs {expected}");
            assert!(starts[i].t >= 0.0 && starts[i].t <= 1.0);
        }
    }
}

#[test]
fn one_start_by_loop_parameter() {
    let mesh = cylinder(3000, 9);
    let boundary_loop = &mesh.boundary_loops()[0];
    let mut closed = boundary_loop.clone();
    closed.push(boundary_loop[0]);
    let length: f64 = closed.windows(2).map(|w| (mesh.positions()[w[1] as usize] - mesh.positions()[w[0] as usize]).norm()).sum();
    for s in [0.0, 0.1, 0.37, 0.5, 0.99] {
        let p = boundary_start(&mesh, 0, s).expect("valid parameter");
        let arc = arc_length_to(&mesh, &closed, &p);
        assert!((arc - s * length).abs() < 1e-9 * length, "s = {s}: arc {arc}");
    }
    let end = boundary_start(&mesh, 0, 1.0).expect("valid parameter");
    assert!((position(&mesh, &end) - mesh.positions()[boundary_loop[0] as usize]).norm() < 1e-9);
}

#[test]
fn bad_seeding_requests_are_named() {
    let mesh = cylinder(500, 9);
    let segments = boundary_segments(&mesh, 0, DEFAULT_CORNER_TURN_DEGREES).expect("valid loop");
    assert_eq!(boundary_segments(&mesh, 1, 30.0), Err(TraceError::LoopOutOfRange { index: 1, count: 1 }));
    assert!(matches!(boundary_segments(&mesh, 0, f64::NAN), Err(TraceError::CornerAngleOutOfRange { .. })));
    assert_eq!(boundary_segments(&mesh, 0, 181.0), Err(TraceError::CornerAngleOutOfRange { degrees: 181.0 }));
    assert_eq!(evenly_spaced_starts(&mesh, &segments, 0, 0), Err(TraceError::ZeroCurves));
    assert_eq!(evenly_spaced_starts(&mesh, &segments, 4, 3), Err(TraceError::SegmentOutOfRange { index: 4, count: 4 }));
    assert_eq!(boundary_start(&mesh, 2, 0.5), Err(TraceError::LoopOutOfRange { index: 2, count: 1 }));
    assert_eq!(boundary_start(&mesh, 0, 1.5), Err(TraceError::ArcParameterOutOfRange { s: 1.5 }));
    assert!(matches!(boundary_start(&mesh, 0, f64::NAN), Err(TraceError::ArcParameterOutOfRange { .. })));
    // Segments of a larger mesh name the vertex this mesh lacks.
    let big = cylinder(3000, 9);
    let foreign = boundary_segments(&big, 0, DEFAULT_CORNER_TURN_DEGREES).expect("valid loop");
    let result = (0..foreign.len()).map(|i| evenly_spaced_starts(&mesh, &foreign, i, 3)).find(|r| r.is_err());
    assert!(matches!(result, Some(Err(TraceError::VertexOutOfRange { .. }))));
    for error in [TraceError::ZeroCurves, TraceError::SegmentOutOfRange { index: 4, count: 4 }] {
        assert!(!error.to_string().is_empty());
    }
}

/// The distance from `q` to the boundary, by brute force: every boundary edge sampled at 2001 points.
fn sampled_boundary_distance(mesh: &TriMesh, q: &Vec3) -> f64 {
    let pos = mesh.positions();
    let mut best = f64::INFINITY;
    for boundary_loop in mesh.boundary_loops() {
        for (k, &a) in boundary_loop.iter().enumerate() {
            let b = boundary_loop[(k + 1) % boundary_loop.len()];
            for i in 0..=2000 {
                let p = pos[a as usize].lerp(&pos[b as usize], i as f64 / 2000.0);
                best = best.min((p - q).norm());
            }
        }
    }
    best
}

#[test]
fn nearest_boundary_point_finds_the_clicked_boundary_point() {
    let mesh = cylinder(1000, 5);
    let boundary_edges: Vec<[u32; 2]> = mesh
        .boundary_loops()
        .iter()
        .flat_map(|l| (0..l.len()).map(move |k| [l[k], l[(k + 1) % l.len()]]))
        .collect();
    // A boundary point moved off the surface along the radial direction made perpendicular to
    // its boundary edge has itself as nearest boundary point.
    for s in [0.03, 0.2, 0.37, 0.61, 0.88] {
        let on = boundary_start(&mesh, 0, s).expect("valid parameter");
        let p = position(&mesh, &on);
        let [a, b] = on.edge.map(|v| mesh.positions()[v as usize]);
        let along = (b - a).normalize();
        let radial = Vec3::new(p.x, p.y, 0.0);
        let off = (radial - radial.dot(&along) * along).normalize();
        let nearest = nearest_boundary_point(&mesh, p + 0.3 * off).expect("finite point");
        assert!(boundary_edges.contains(&nearest.edge), "{nearest:?} is not on a boundary edge in loop order");
        assert!((0.0..=1.0).contains(&nearest.t));
        assert!((position(&mesh, &nearest) - p).norm() < 1e-9, "s = {s}");
    }
    // Points inside and around the patch: no sampled boundary point is closer.
    for q in [Vec3::new(9.0, 3.0, 7.0), Vec3::new(0.0, 12.0, -2.0), Vec3::new(-20.0, 5.0, 30.0), Vec3::new(0.0, 0.0, 7.5)] {
        let nearest = nearest_boundary_point(&mesh, q).expect("finite point");
        let d = (position(&mesh, &nearest) - q).norm();
        let sampled = sampled_boundary_distance(&mesh, &q);
        assert!(d <= sampled + 1e-12 && d > sampled - 1e-2, "{q:?}: {d} vs sampled {sampled}");
    }
    assert_eq!(nearest_boundary_point(&mesh, Vec3::new(f64::NAN, 0.0, 0.0)), Err(TraceError::NonFinitePoint));
    assert_eq!(nearest_boundary_point(&mesh, Vec3::new(0.0, f64::INFINITY, 0.0)), Err(TraceError::NonFinitePoint));
}
