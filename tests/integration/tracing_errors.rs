//! Every bad tracing input gets its own error, whose message names the offending value.

use crate::tracing_support;

use lamella::mesh::EdgePoint;
use lamella::tracing::{TraceError, TraceOptions, Tracer};
use tracing_support::{cylinder, left_side_point};

fn expect_error(result: Result<lamella::tracing::TracedCurve, TraceError>, expected: TraceError, needle: &str) {
    let error = result.expect_err("bad input must be rejected");
    assert_eq!(error, expected);
    let message = error.to_string();
    assert!(message.contains(needle), "`{message}` should name `{needle}`");
}

#[test]
fn bad_start_points_are_rejected() {
    let mesh = cylinder(800, 3);
    let tracer = Tracer::new(&mesh);
    let options = TraceOptions::default();
    let n = mesh.vertex_count() as u32;
    let boundary = mesh.boundary_edges()[0];
    let on = |t: f64| EdgePoint { edge: [boundary.from, boundary.to], t };
    expect_error(
        tracer.trace(&EdgePoint { edge: [boundary.from, n + 5], t: 0.5 }, 60.0, 90.0, &options),
        TraceError::VertexOutOfRange { vertex: n + 5, vertex_count: n as usize },
        &format!("{}", n + 5),
    );
    let interior = *mesh.edges().iter().find(|e| !mesh.is_boundary_vertex(e[0] as usize)).expect("an interior edge");
    expect_error(
        tracer.trace(&EdgePoint { edge: interior, t: 0.5 }, 60.0, 90.0, &options),
        TraceError::NotBoundaryEdge { a: interior[0], b: interior[1] },
        &format!("({}, {})", interior[0], interior[1]),
    );
    // Two boundary vertices that share no edge.
    let far = mesh.boundary_loops()[0][5];
    expect_error(
        tracer.trace(&EdgePoint { edge: [boundary.from, far], t: 0.5 }, 60.0, 90.0, &options),
        TraceError::NotBoundaryEdge { a: boundary.from, b: far },
        "not a boundary edge",
    );
    expect_error(tracer.trace(&on(1.5), 60.0, 90.0, &options), TraceError::EdgeParameterOutOfRange { t: 1.5 }, "1.5");
    expect_error(tracer.trace(&on(-0.1), 60.0, 90.0, &options), TraceError::EdgeParameterOutOfRange { t: -0.1 }, "-0.1");
    let nan = tracer.trace(&on(f64::NAN), 60.0, 90.0, &options);
    assert!(matches!(nan, Err(TraceError::EdgeParameterOutOfRange { t }) if t.is_nan()));
    assert!(nan.expect_err("rejected").to_string().contains("NaN"));
}

#[test]
fn bad_angles_are_rejected() {
    let mesh = cylinder(800, 3);
    let tracer = Tracer::new(&mesh);
    let options = TraceOptions::default();
    let start = left_side_point(&mesh, 7.0);
    for theta in [-1.0, 180.5, f64::INFINITY] {
        expect_error(tracer.trace(&start, theta, 90.0, &options), TraceError::ThetaOutOfRange { degrees: theta }, &format!("{theta}"));
    }
    assert!(matches!(tracer.trace(&start, f64::NAN, 90.0, &options), Err(TraceError::ThetaOutOfRange { .. })));
    for alpha in [0.0, 180.0, -30.0, 200.0] {
        expect_error(tracer.trace(&start, 60.0, alpha, &options), TraceError::StartAngleOutOfRange { degrees: alpha }, &format!("{alpha}"));
    }
    assert!(matches!(tracer.trace(&start, 60.0, f64::NAN, &options), Err(TraceError::StartAngleOutOfRange { .. })));
    // The boundary values of θ are valid.
    for theta in [0.0, 180.0] {
        assert!(!matches!(tracer.trace(&start, theta, 90.0, &options), Err(TraceError::ThetaOutOfRange { .. })));
    }
}

#[test]
fn bad_options_are_rejected() {
    let mesh = cylinder(800, 3);
    let tracer = Tracer::new(&mesh);
    let start = left_side_point(&mesh, 7.0);
    let base = TraceOptions::default();
    let cases = [
        (TraceOptions { max_length: 0.0, ..base.clone() }, "max_length", 0.0),
        (TraceOptions { max_length: -2.0, ..base.clone() }, "max_length", -2.0),
        (TraceOptions { max_points: 1, ..base.clone() }, "max_points", 1.0),
        (TraceOptions { min_step_ratio: -1.0, ..base.clone() }, "min_step_ratio", -1.0),
        (TraceOptions { min_step_ratio: f64::INFINITY, ..base.clone() }, "min_step_ratio", f64::INFINITY),
        (TraceOptions { angle_tolerance_degrees: 0.0, ..base.clone() }, "angle_tolerance_degrees", 0.0),
        (TraceOptions { angle_tolerance_degrees: 95.0, ..base.clone() }, "angle_tolerance_degrees", 95.0),
        (TraceOptions { vertex_ratio: 0.5, ..base.clone() }, "vertex_ratio", 0.5),
        (TraceOptions { max_turn_degrees: 0.0, ..base.clone() }, "max_turn_degrees", 0.0),
        (TraceOptions { max_turn_degrees: 91.0, ..base.clone() }, "max_turn_degrees", 91.0),
    ];
    for (options, name, value) in cases {
        expect_error(tracer.trace(&start, 60.0, 90.0, &options), TraceError::InvalidOption { name, value }, name);
    }
    let nan = TraceOptions { max_length: f64::NAN, ..base };
    assert!(matches!(tracer.trace(&start, 60.0, 90.0, &nan), Err(TraceError::InvalidOption { name: "max_length", .. })));
}

#[test]
fn a_start_without_first_segment_is_reported() {
    let mesh = cylinder(800, 3);
    let tracer = Tracer::new(&mesh);
    let start = left_side_point(&mesh, 7.0);
    // d0 of a hundred mean edges leaves no admissible point in the start triangle or its rings.
    let options = TraceOptions { min_step_ratio: 100.0, ..TraceOptions::default() };
    let error = tracer.trace(&start, 60.0, 90.0, &options).expect_err("no first segment");
    assert!(matches!(error, TraceError::NoFirstSegment { start_angle_degrees, .. } if start_angle_degrees == 90.0));
    assert!(error.to_string().contains("alpha = 90"));
}

#[test]
fn limits_stop_the_curve() {
    let mesh = cylinder(3000, 3);
    let tracer = Tracer::new(&mesh);
    let start = left_side_point(&mesh, 2.0);
    let options = TraceOptions { max_points: 10, ..TraceOptions::default() };
    let curve = tracer.trace(&start, 60.0, 90.0, &options).expect("valid");
    assert_eq!(curve.stop(), lamella::tracing::StopReason::PointLimit);
    assert_eq!(curve.points().len(), 10);
    assert_eq!(curve.positions().len(), 10);
    for (p, x) in curve.points().iter().zip(curve.positions()) {
        assert!(p.edge[0] < p.edge[1] && (0.0..=1.0).contains(&p.t));
        assert!((p.position(&mesh).expect("on the mesh") - x).norm() < 1e-12);
    }
}
