//! Intersection report and order check of traced curve sets on the validation cylinder.

use crate::tracing_support;

use lamella::tracing::{
    boundary_segments, check_order, evenly_spaced_starts, intersections, OrderDefect, StopReason, TraceOptions, TracedCurve, Tracer,
    DEFAULT_CORNER_TURN_DEGREES,
};
use tracing_support::*;

#[test]
fn crossing_mirror_curves_are_reported_where_the_catenaries_meet() {
    let mesh = cylinder(3000, 23);
    let tracer = Tracer::new(&mesh);
    let options = TraceOptions::default();
    let rising = tracer.trace(&left_side_point(&mesh, 2.0), 60.0, 90.0, &options).expect("valid");
    let falling = tracer.trace(&left_side_point(&mesh, 13.0), 120.0, 90.0, &options).expect("valid");
    let report = intersections(&mesh, &[rising.clone(), falling.clone()]);
    assert!(report.self_intersections.is_empty());
    assert_eq!(report.crossings.len(), 1, "{:?}", report.crossings);
    let crossing = &report.crossings[0];
    assert_eq!(crossing.curves, [0, 1]);
    // The catenaries 2 + c(x) and 13 − c(x), c(x) = (cosh kx − 1)/k, meet where c(x) = 5.5.
    let k = 30f64.to_radians().tan() / RADIUS;
    let x = (1.0 + 5.5 * k).acosh() / k;
    let (cx, cy) = development(&crossing.position);
    eprintln!("crossing at ({cx}, {cy}), analytic ({x}, 7.5)");
    assert!((cx - x).abs() < 0.1 && (cy - 7.5).abs() < 0.1, "crossing at ({cx}, {cy}), expected ({x}, 7.5)");
    // The reported segments really contain the crossing point.
    for (curve, segment) in [(&rising, crossing.segments[0]), (&falling, crossing.segments[1])] {
        let p = curve.positions();
        let (a, b) = (p[segment], p[segment + 1]);
        let along = (crossing.position - a).dot(&(b - a)) / (b - a).norm_squared();
        let offset = (a + (b - a) * along.clamp(0.0, 1.0) - crossing.position).norm();
        assert!(offset < 0.05, "crossing is {offset} away from its segment");
    }
    assert_eq!(check_order(&mesh, &[rising, falling]), Err(OrderDefect::Crossing { first: 0, second: 1 }));
}

/// θ = 60° traces from `count` evenly spaced starts on the cylinder's left side (its points
/// all have y = 0, φ = 0), perpendicular to the side: vertically shifted copies of one catenary.
fn left_side_family(count: usize) -> (lamella::mesh::TriMesh, Vec<TracedCurve>) {
    let mesh = cylinder(3000, 29);
    let segments = boundary_segments(&mesh, 0, DEFAULT_CORNER_TURN_DEGREES).expect("valid loop");
    let left = segments
        .iter()
        .position(|s| s.vertices().iter().all(|&v| mesh.positions()[v as usize].y.abs() < 1e-9))
        .expect("a side at φ = 0");
    let starts = evenly_spaced_starts(&mesh, &segments, left, count).expect("valid request");
    let tracer = Tracer::new(&mesh);
    let curves = starts
        .iter()
        .map(|s| tracer.trace(s, 60.0, 90.0, &TraceOptions::default()).expect("valid"))
        .collect();
    (mesh, curves)
}

#[test]
fn parallel_family_is_intersection_free_and_ordered() {
    let (mesh, curves) = left_side_family(5);
    for curve in &curves {
        assert_eq!(curve.stop(), StopReason::Boundary);
    }
    let report = intersections(&mesh, &curves);
    assert!(report.is_intersection_free(), "{report:?}");
    assert_eq!(check_order(&mesh, &curves), Ok(()));
    // Swapping two neighbours breaks the order: curve 1 no longer lies between 0 and 2.
    let mut shuffled = curves.clone();
    shuffled.swap(1, 2);
    assert_eq!(check_order(&mesh, &shuffled), Err(OrderDefect::NotBetween { curve: 1 }));
}

#[test]
fn open_curves_in_the_middle_cannot_be_ordered() {
    let (mesh, curves) = left_side_family(3);
    let tracer = Tracer::new(&mesh);
    let options = TraceOptions { max_length: 3.0, ..TraceOptions::default() };
    let short = tracer.trace(&curves[1].points()[0], 60.0, 90.0, &options).expect("valid");
    assert_eq!(short.stop(), StopReason::LengthLimit);
    assert!(short.length() >= 3.0 && short.length() < 3.0 + 2.0 * mesh.mean_edge_length());
    let set = [curves[0].clone(), short, curves[2].clone()];
    assert!(intersections(&mesh, &set).is_intersection_free());
    assert_eq!(check_order(&mesh, &set), Err(OrderDefect::OpenEnd { curve: 1 }));
}
