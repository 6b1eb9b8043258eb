//! Bad input to the strip computation: typed errors for impossible parameters, per-strip warnings
//! (or skips) for bad curves, never a panic or a NaN; and bit-identical results for any thread count.

use crate::strips_support;

use lamella::curves::{extract_level_curves, uniform_levels, CurveError, LevelCurve};
use lamella::mesh::{TriMesh, Vec3};
use lamella::strips::{rectifying_strips, RectifyingStrip, StripError, StripParams, StripPattern, StripWarning};
use lamella::surfaces::{planar_disk, PlanarPatch};
use strips_support::sixty_degree_cylinder;

fn disk() -> TriMesh {
    let patch = PlanarPatch { radius: 5.0, target_vertices: 800, irregularity: 0.3, seed: 2 };
    planar_disk(&patch).expect("valid patch").into_mesh().expect("valid mesh")
}

fn curve(points: Vec<Vec3>) -> LevelCurve {
    let normals = vec![Vec3::z(); points.len()];
    LevelCurve { level: 0.0, points, normals, closed: false, singular_vertices: Vec::new() }
}

/// A gently bent planar arc on the disk (θ = 0 there: the binormal is the plane's normal).
fn arc() -> Vec<Vec3> {
    (0..15).map(|k| Vec3::new(-3.0 + 0.4 * k as f64, 0.02 * (k as f64 - 7.0).powi(2), 0.0)).collect()
}

fn finite(strip: &RectifyingStrip) -> bool {
    let vectors = [&strip.centre, &strip.binormals, &strip.rulings, &strip.left, &strip.right];
    let flat = [&strip.unrolling.centre, &strip.unrolling.left, &strip.unrolling.right];
    let m = strip.metrics;
    vectors.iter().all(|v| v.iter().all(|p| p.iter().all(|x| x.is_finite())))
        && flat.iter().all(|v| v.iter().all(|p| p.iter().all(|x| x.is_finite())))
        && [m.max_diff_theta_degrees, m.e_straight, m.e_planar, m.max_planar, m.appro_percent, m.length].iter().all(|x| x.is_finite())
}

#[test]
fn impossible_parameters_are_errors() {
    let mesh = disk();
    let curves = [curve(arc())];
    for width in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        let result = rectifying_strips(&mesh, &curves, &StripParams::new(0.0, width));
        assert!(matches!(result, Err(StripError::InvalidWidth { .. })), "width {width}: {result:?}");
    }
    for theta in [-1.0, 180.5, f64::NAN] {
        let result = rectifying_strips(&mesh, &curves, &StripParams::new(theta, 0.3));
        assert!(matches!(result, Err(StripError::InvalidTheta { .. })), "θ {theta}: {result:?}");
    }
    let mut params = StripParams::new(0.0, 0.3);
    params.weights.slide = -1.0;
    assert!(matches!(rectifying_strips(&mesh, &curves, &params), Err(StripError::InvalidParameter { name: "weights.slide", .. })));
    let mut params = StripParams::new(0.0, 0.3);
    params.weights.planarity = 0.0;
    assert!(matches!(rectifying_strips(&mesh, &curves, &params), Err(StripError::InvalidParameter { name: "weights.planarity", .. })));
}

#[test]
fn bad_curves_are_skipped_with_a_reason() {
    let mesh = disk();
    let mut nan = arc();
    nan[4].y = f64::NAN;
    let mut repeated = arc();
    repeated[5] = repeated[4];
    let straight: Vec<Vec3> = (0..10).map(|k| Vec3::new(-2.0 + 0.4 * k as f64, 1.0, 0.0)).collect();
    let curves = [
        curve(arc()),
        curve(vec![Vec3::zeros(), Vec3::x()]),
        curve(Vec::new()),
        curve(nan),
        curve(repeated),
        curve(straight),
    ];
    let pattern = rectifying_strips(&mesh, &curves, &StripParams::new(0.0, 0.3)).expect("valid parameters");
    assert_eq!(pattern.strips.len(), 2);
    assert_eq!((pattern.strips[0].curve, pattern.strips[1].curve), (0, 5));
    assert!(pattern.strips.iter().all(finite));
    // A straight polyline has no principal normals (Eq. 1): its strip keeps the binormal rulings
    // and is planar and straight all the same.
    let line = &pattern.strips[1];
    assert!(line.metrics.max_planar <= 1e-9 && line.metrics.e_straight <= 1e-9, "{:?}", line.metrics);
    let reasons: Vec<(usize, &[StripWarning])> = pattern.skipped.iter().map(|s| (s.curve, s.warnings.as_slice())).collect();
    assert_eq!(reasons[0], (1, &[StripWarning::TooFewPoints { points: 2 }][..]));
    assert_eq!(reasons[1], (2, &[StripWarning::TooFewPoints { points: 0 }][..]));
    assert_eq!(reasons[2], (3, &[StripWarning::NonFiniteInput][..]));
    assert_eq!(reasons[3], (4, &[StripWarning::ZeroLengthSegment { segment: 4 }][..]));
    assert_eq!(pattern.metrics.strip_count, 2);
}

#[test]
fn singular_vertices_and_closed_curves_are_reported() {
    let mesh = disk();
    let field: Vec<f64> = mesh.positions().iter().map(|p| p.x * p.x + p.y * p.y).collect();
    // The small circle passes the star of the minimum at the centre vertex.
    let curves = extract_level_curves(&mesh, &field, &[0.01, 4.0]).expect("levels in range");
    assert_eq!(curves[0].singular_vertices, vec![0]);
    let resampled: Vec<LevelCurve> = curves.iter().map(|c| c.resampled(0.05).expect("valid spacing")).collect();
    let pattern = rectifying_strips(&mesh, &resampled, &StripParams::new(0.0, 0.02)).expect("valid parameters");
    let warnings_of = |curve: usize| -> Vec<StripWarning> {
        let built = pattern.strips.iter().find(|s| s.curve == curve).map(|s| s.warnings.clone());
        let skipped = pattern.skipped.iter().find(|s| s.curve == curve).map(|s| s.warnings.clone());
        built.or(skipped).expect("every curve is either built or skipped")
    };
    assert!(warnings_of(0).contains(&StripWarning::SingularVertices { vertices: vec![0] }), "{:?}", warnings_of(0));
    assert!(warnings_of(0).contains(&StripWarning::ClosedCurveOpened));
    assert!(warnings_of(1).contains(&StripWarning::ClosedCurveOpened));
    assert!(!warnings_of(1).iter().any(|w| matches!(w, StripWarning::SingularVertices { .. })));
    assert!(pattern.strips.iter().all(finite));
}

#[test]
fn levels_outside_the_range_are_errors() {
    let (mesh, field) = sixty_degree_cylinder();
    let levels = uniform_levels(mesh, field, 3).expect("valid field");
    let above = levels[2] + 1e3;
    assert!(matches!(extract_level_curves(mesh, field, &[levels[0], above]), Err(CurveError::LevelOutOfRange { .. })));
}

#[test]
fn results_do_not_depend_on_the_thread_count() {
    let (mesh, field) = sixty_degree_cylinder();
    let levels = uniform_levels(mesh, field, 4).expect("valid field");
    let curves: Vec<LevelCurve> = extract_level_curves(mesh, field, &levels)
        .expect("levels in range")
        .iter()
        .map(|c| c.resampled(0.6).expect("valid spacing"))
        .collect();
    let run = |threads: usize| -> StripPattern {
        let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().expect("thread pool");
        pool.install(|| rectifying_strips(mesh, &curves, &StripParams::new(60.0, 0.5)).expect("valid parameters"))
    };
    let (one, two) = (run(1), run(2));
    assert!(!one.strips.is_empty());
    assert_eq!(one, two);
}
