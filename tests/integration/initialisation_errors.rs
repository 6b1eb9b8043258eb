//! Every bad input to the initialisation gets its own error naming the offending curve, stroke or
//! point, and a design that runs but fails says so in its status.

use crate::initialisation_support;

use initialisation_support::{cylinder, Catenary, HEIGHT, RADIUS};
use lamella::initialisation::{
    auto_design, estimate_target_angle, field_from_guide_curves, field_from_strokes, AutoDesignOptions, DesignStatus, GuideCurveOptions,
    InitialisationError, StrokeOptions,
};
use lamella::mesh::{EdgePoint, TriMesh, Vec3};
use std::sync::OnceLock;

fn mesh() -> &'static TriMesh {
    static MESH: OnceLock<TriMesh> = OnceLock::new();
    MESH.get_or_init(|| cylinder(600, 1))
}

fn guides() -> Vec<Vec<EdgePoint>> {
    [3.0, 9.0].iter().map(|&z0| Catenary::new(60.0, z0).edge_points(mesh())).collect()
}

fn strokes() -> Vec<Vec<Vec3>> {
    [3.0, 9.0].iter().map(|&z0| Catenary::new(60.0, z0).stroke(4.0, 22.0, 40, 0.05)).collect()
}

fn guide_error(curves: &[Vec<EdgePoint>]) -> InitialisationError {
    field_from_guide_curves(mesh(), curves, &GuideCurveOptions::default()).expect_err("invalid guides")
}

fn stroke_error(strokes: &[Vec<Vec3>]) -> InitialisationError {
    field_from_strokes(mesh(), strokes, &StrokeOptions::default()).expect_err("invalid strokes")
}

/// The error's message mentions every fragment.
fn assert_names(error: &InitialisationError, fragments: &[&str]) {
    let message = error.to_string();
    for fragment in fragments {
        assert!(message.contains(fragment), "`{message}` does not mention `{fragment}`");
    }
}

#[test]
fn the_valid_inputs_are_accepted() {
    assert!(field_from_guide_curves(mesh(), &guides(), &GuideCurveOptions::default()).is_ok());
    assert!(field_from_strokes(mesh(), &strokes(), &StrokeOptions::default()).is_ok());
}

#[test]
fn guide_curve_errors_name_curve_and_point() {
    let one = &guides()[..1];
    assert_eq!(guide_error(one), InitialisationError::TooFewGuideCurves { count: 1 });
    assert_eq!(guide_error(&[]), InitialisationError::TooFewGuideCurves { count: 0 });

    let mut empty = guides();
    empty[1].clear();
    assert_eq!(guide_error(&empty), InitialisationError::EmptyGuideCurve { curve: 1 });

    let n = mesh().vertex_count() as u32;
    let mut out_of_range = guides();
    out_of_range[1][4].edge[1] = n + 7;
    let e = guide_error(&out_of_range);
    assert_eq!(e, InitialisationError::GuideVertexOutOfRange { curve: 1, point: 4, vertex: n + 7, vertex_count: n as usize });
    assert_names(&e, &["guide curve 1", "point 4", &format!("{}", n + 7)]);

    // Vertex 0 and the vertex farthest from it are not joined by an edge.
    let far = (0..n).max_by(|&a, &b| {
        let d = |v: u32| (mesh().positions()[v as usize] - mesh().positions()[0]).norm();
        d(a).total_cmp(&d(b))
    });
    let mut not_an_edge = guides();
    not_an_edge[0][2].edge = [0, far.expect("vertices")];
    let e = guide_error(&not_an_edge);
    assert_eq!(e, InitialisationError::GuideNotAnEdge { curve: 0, point: 2, edge: not_an_edge[0][2].edge });
    assert_names(&e, &["guide curve 0", "point 2", "not an edge"]);

    for t in [1.5, -0.1, f64::NAN, f64::INFINITY] {
        let mut bad_t = guides();
        bad_t[1][0].t = t;
        match guide_error(&bad_t) {
            InitialisationError::GuideParameterOutOfRange { curve: 1, point: 0, t: got } => {
                assert!(got.to_bits() == t.to_bits(), "t = {got}")
            }
            other => panic!("t = {t}: {other:?}"),
        }
    }

    let mut coincident = guides();
    coincident[1][0] = coincident[0][0];
    assert_eq!(guide_error(&coincident), InitialisationError::CoincidentGuideStarts);

    for (options, name) in [
        (GuideCurveOptions { trace_weight: 0.0, ..GuideCurveOptions::default() }, "trace_weight"),
        (GuideCurveOptions { fair_weight: f64::NAN, ..GuideCurveOptions::default() }, "fair_weight"),
    ] {
        let e = field_from_guide_curves(mesh(), &guides(), &options).expect_err("bad option");
        assert!(matches!(e, InitialisationError::InvalidOption { name: n, .. } if n == name), "{e:?}");
    }
}

#[test]
fn stroke_errors_name_stroke_and_point() {
    assert_eq!(stroke_error(&[]), InitialisationError::TooFewStrokes { count: 0 });
    assert_eq!(stroke_error(&strokes()[..1]), InitialisationError::TooFewStrokes { count: 1 });

    let mut short = strokes();
    short[1].truncate(1);
    assert_eq!(stroke_error(&short), InitialisationError::StrokeTooShort { stroke: 1, points: 1 });
    // Two points in one triangle leave one sample after the one-per-triangle filter.
    let p = Catenary::new(60.0, 9.0).point(13.0, 0.0);
    let mut one_triangle = strokes();
    one_triangle[1] = vec![p, p + Vec3::new(0.0, 0.0, 1e-6)];
    assert_eq!(stroke_error(&one_triangle), InitialisationError::StrokeTooShort { stroke: 1, points: 1 });

    let mut non_finite = strokes();
    non_finite[0][7].y = f64::NAN;
    let e = stroke_error(&non_finite);
    assert_eq!(e, InitialisationError::NonFiniteStrokePoint { stroke: 0, point: 7 });
    assert_names(&e, &["stroke 0", "point 7"]);

    let mut off = strokes();
    off[1][12] *= 1.5; // 5 units outside the cylinder of radius 10
    let e = stroke_error(&off);
    assert!(matches!(e, InitialisationError::StrokePointOffSurface { stroke: 1, point: 12, .. }), "{e:?}");
    assert_names(&e, &["stroke 1", "point 12", "from the surface"]);
    let mut inside = strokes();
    inside[0][3] = Vec3::new(0.0, 0.0, 5.0); // on the axis, R = 10 from the surface
    assert!(matches!(stroke_error(&inside), InitialisationError::StrokePointOffSurface { stroke: 0, point: 3, .. }));

    // A third stroke running up the patch crosses both catenaries.
    let mut crossing = strokes();
    crossing.push((0..40).map(|i| Vec3::new(RADIUS * 0.8f64.cos(), RADIUS * 0.8f64.sin(), 0.5 + 14.0 * i as f64 / 39.0)).collect());
    let e = stroke_error(&crossing);
    assert!(matches!(e, InitialisationError::CrossingStrokes { first: 0, second: 2, .. }), "{e:?}");
    assert_names(&e, &["strokes 0 and 2", "cross"]);

    let e = field_from_strokes(mesh(), &strokes(), &StrokeOptions { max_distance: 0.0, ..StrokeOptions::default() }).expect_err("bad option");
    assert!(matches!(e, InitialisationError::InvalidOption { name: "max_distance", .. }), "{e:?}");
    let e = field_from_strokes(mesh(), &strokes(), &StrokeOptions { tolerance: -1.0, ..StrokeOptions::default() }).expect_err("bad option");
    assert!(matches!(e, InitialisationError::InvalidOption { name: "tolerance", .. }), "{e:?}");
}

#[test]
fn strokes_on_the_boundary_give_no_measurable_angle() {
    // Along the bottom and top edges every sample's nearest vertex is a boundary vertex.
    let along = |z: f64| -> Vec<Vec3> {
        (0..30)
            .map(|i| {
                let phi = 0.2 + 2.2 * i as f64 / 29.0;
                Vec3::new(RADIUS * phi.cos(), RADIUS * phi.sin(), z)
            })
            .collect()
    };
    let boundary: Vec<Vec<Vec3>> = vec![along(0.0), along(HEIGHT)];
    let fitted = field_from_strokes(mesh(), &boundary, &StrokeOptions::default()).expect("valid strokes");
    assert_eq!(estimate_target_angle(mesh(), &fitted.field, &fitted.samples), Err(InitialisationError::NoMeasurableAngle));
    let e = auto_design(mesh(), &boundary, &AutoDesignOptions::default()).expect_err("no angle");
    assert_eq!(e, InitialisationError::NoMeasurableAngle);
}

#[test]
fn an_unfinished_design_says_so() {
    let capped = AutoDesignOptions { max_iterations: 3, ..AutoDesignOptions::default() };
    let design = auto_design(mesh(), &strokes(), &capped).expect("valid strokes");
    assert_eq!(design.status, DesignStatus::NotConverged { iterations: 3 });
    assert!(!design.status.is_success());
    let strict = AutoDesignOptions { angle_energy_tolerance: 0.0, ..AutoDesignOptions::default() };
    let design = auto_design(mesh(), &strokes(), &strict).expect("valid strokes");
    assert!(matches!(design.status, DesignStatus::AngleNotReached { energy } if energy > 0.0), "{:?}", design.status);
    let e = auto_design(mesh(), &strokes(), &AutoDesignOptions { angle_energy_tolerance: f64::NAN, ..AutoDesignOptions::default() });
    assert!(matches!(e, Err(InitialisationError::InvalidOption { name: "angle_energy_tolerance", .. })), "{e:?}");
}
