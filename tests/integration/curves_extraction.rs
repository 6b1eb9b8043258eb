//! Level curves of analytic fields on a flat disk: positions, normals, orientation, open and
//! closed pieces kept apart, resampling, and the error cases.

use lamella::curves::{extract_level_curves, uniform_levels, CurveError, LevelCurve};
use lamella::mesh::{TriMesh, Vec3};
use lamella::surfaces::{planar_disk, PlanarPatch};

const RADIUS: f64 = 5.0;

fn disk() -> TriMesh {
    let patch = PlanarPatch { radius: RADIUS, target_vertices: 1200, irregularity: 0.3, seed: 9 };
    planar_disk(&patch).expect("valid patch").into_mesh().expect("valid mesh")
}

fn field(mesh: &TriMesh, f: impl Fn(&Vec3) -> f64) -> Vec<f64> {
    mesh.positions().iter().map(f).collect()
}

fn spacings(curve: &LevelCurve) -> Vec<f64> {
    let n = curve.points.len();
    let segments = if curve.closed { n } else { n - 1 };
    (0..segments).map(|k| (curve.points[(k + 1) % n] - curve.points[k]).norm()).collect()
}

fn segment_distance(p: &Vec3, a: &Vec3, b: &Vec3) -> f64 {
    let t = ((p - a).dot(&(b - a)) / (b - a).norm_squared()).clamp(0.0, 1.0);
    (p - (a + (b - a) * t)).norm()
}

#[test]
fn straight_levels_of_a_linear_field() {
    let mesh = disk();
    let f = field(&mesh, |p| 2.0 * p.x + 1.0);
    let levels = uniform_levels(&mesh, &f, 7).expect("valid field");
    // Uniform in [min, max] with the extremes left out.
    let min = f.iter().cloned().fold(f64::INFINITY, f64::min);
    let max = f.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
    assert!(min < -8.9 && max > 10.9);
    for (k, level) in levels.iter().enumerate() {
        let expected = min + (max - min) * (k + 1) as f64 / 8.0;
        assert!((level - expected).abs() < 1e-9, "level {k}: {level} vs {expected}");
    }
    let curves = extract_level_curves(&mesh, &f, &levels).expect("levels in range");
    assert_eq!(curves.len(), 7, "one piece per level on a disk");
    for curve in &curves {
        let x = (curve.level - 1.0) / 2.0;
        assert!(!curve.closed && curve.singular_vertices.is_empty());
        for (p, n) in curve.points.iter().zip(&curve.normals) {
            assert!((p.x - x).abs() < 1e-12 && p.z.abs() < 1e-12, "point {p:?} off the line x = {x}");
            assert!((n - Vec3::z()).norm() < 1e-12);
        }
        // Runs along ∇F × n = x̂ × ẑ = −ŷ, from boundary to boundary.
        let (first, last) = (curve.points[0], curve.points[curve.points.len() - 1]);
        assert!(first.y > 0.0 && last.y < 0.0);
        // The boundary is a polygon inscribed in the circle: the chord is a little shorter.
        let chord = (RADIUS * RADIUS - x * x).sqrt() * 2.0;
        assert!(curve.length() <= chord + 1e-9 && curve.length() > 0.99 * chord, "length {} vs {chord}", curve.length());
        assert!(curve.points.windows(2).all(|w| w[1].y < w[0].y), "monotone along −y");
    }
}

#[test]
fn two_pieces_per_level_are_kept_apart() {
    let mesh = disk();
    let f = field(&mesh, |p| p.x * p.x);
    let curves = extract_level_curves(&mesh, &f, &[1.0, 4.0]).expect("levels in range");
    assert_eq!(curves.len(), 4);
    for curve in &curves {
        let xs: Vec<f64> = curve.points.iter().map(|p| p.x).collect();
        let side = xs[0].signum();
        assert!(xs.iter().all(|x| x.signum() == side), "a piece crosses x = 0");
        let root = curve.level.sqrt();
        // Linear interpolation of x² along an edge: within the squared edge extent along x.
        assert!(xs.iter().all(|x| (x.abs() - root).abs() < 0.05), "level {}: {xs:?}", curve.level);
        // ∇F × n: on x > 0 towards −y, on x < 0 towards +y.
        let (first, last) = (curve.points[0], curve.points[curve.points.len() - 1]);
        assert!((last.y - first.y) * side < 0.0);
    }
}

#[test]
fn closed_circles_and_the_singular_centre() {
    let mesh = disk();
    let f = field(&mesh, |p| p.x * p.x + p.y * p.y);
    let curves = extract_level_curves(&mesh, &f, &[1e-4, 4.0, 9.0]).expect("levels in range");
    assert_eq!(curves.len(), 3);
    // The tiny circle passes the star of the minimum at the centre vertex (index 0).
    assert!(curves[0].closed && curves[0].singular_vertices == vec![0], "{:?}", curves[0].singular_vertices);
    for curve in &curves[1..] {
        assert!(curve.closed && curve.singular_vertices.is_empty());
        let r = curve.level.sqrt();
        assert!(curve.points.iter().all(|p| (p.norm() - r).abs() < 0.05 * r));
        // Closed curves do not repeat their first point.
        assert!((curve.points[0] - curve.points[curve.points.len() - 1]).norm() > 1e-6);
        // Along ∇F × n = (x, y) × ẑ: clockwise seen from +z, so the signed area is negative.
        let area: f64 = (0..curve.points.len())
            .map(|k| {
                let (a, b) = (curve.points[k], curve.points[(k + 1) % curve.points.len()]);
                0.5 * (a.x * b.y - a.y * b.x)
            })
            .sum();
        assert!(area < 0.0 && (area.abs() - std::f64::consts::PI * r * r).abs() < 0.02 * area.abs());
    }
}

#[test]
fn resampling_gives_equal_spacing_on_the_same_polyline() {
    let mesh = disk();
    let f = field(&mesh, |p| p.x * p.x + 0.5 * p.y);
    let curves = extract_level_curves(&mesh, &f, &[3.0, 6.0]).expect("levels in range");
    assert!(!curves.is_empty());
    for curve in &curves {
        let resampled = curve.resampled(0.3).expect("valid spacing");
        let steps = spacings(&resampled);
        let mean = steps.iter().sum::<f64>() / steps.len() as f64;
        assert!((mean - 0.3).abs() < 0.3 * 0.3 / 2.0 + 0.3 / steps.len() as f64, "mean spacing {mean}");
        // Chords of a curved polyline are slightly shorter than the arc steps.
        assert!(steps.iter().all(|s| (s - mean).abs() < 0.02 * mean), "uneven steps {steps:?}");
        if !curve.closed {
            assert_eq!(resampled.points[0], curve.points[0]);
            assert!((resampled.points[resampled.points.len() - 1] - curve.points[curve.points.len() - 1]).norm() < 1e-12);
        }
        // New points lie on the old polyline.
        for (p, n) in resampled.points.iter().zip(&resampled.normals) {
            let distance = (0..spacings(curve).len())
                .map(|k| segment_distance(p, &curve.points[k], &curve.points[(k + 1) % curve.points.len()]))
                .fold(f64::INFINITY, f64::min);
            assert!(distance < 1e-12, "point {p:?} is {distance} off the polyline");
            assert!((n.norm() - 1.0).abs() < 1e-12);
        }
    }
}

#[test]
fn bad_input_gets_typed_errors() {
    let mesh = disk();
    let f = field(&mesh, |p| p.x);
    assert!(matches!(extract_level_curves(&mesh, &f, &[6.0]), Err(CurveError::LevelOutOfRange { .. })));
    assert!(matches!(extract_level_curves(&mesh, &f, &[f64::NAN]), Err(CurveError::NonFiniteLevel { index: 0 })));
    assert_eq!(extract_level_curves(&mesh, &f, &[]), Err(CurveError::NoLevels));
    assert_eq!(uniform_levels(&mesh, &f, 0), Err(CurveError::NoLevels));
    assert!(matches!(uniform_levels(&mesh, &f[1..], 3), Err(CurveError::FieldLength { .. })));
    let mut broken = f.clone();
    broken[17] = f64::INFINITY;
    assert_eq!(uniform_levels(&mesh, &broken, 3), Err(CurveError::NonFiniteField { vertex: 17 }));
    assert_eq!(uniform_levels(&mesh, &vec![2.0; f.len()], 3), Err(CurveError::ConstantField));
    let curves = extract_level_curves(&mesh, &f, &[0.5]).expect("in range");
    for spacing in [0.0, -1.0, f64::NAN] {
        assert!(matches!(curves[0].resampled(spacing), Err(CurveError::InvalidSpacing { .. })));
    }
    let mut inconsistent = curves[0].clone();
    inconsistent.normals.pop();
    let (points, normals) = (inconsistent.points.len(), inconsistent.normals.len());
    assert_eq!(inconsistent.resampled(0.1), Err(CurveError::NormalCount { points, normals }));
}

#[test]
fn levels_through_vertices_give_no_duplicate_points() {
    let mesh = disk();
    let f = field(&mesh, |p| p.y);
    // Levels exactly at vertex values.
    let levels: Vec<f64> = [100, 400, 700].iter().map(|&v| f[v]).collect();
    for curve in extract_level_curves(&mesh, &f, &levels).expect("in range") {
        assert!(spacings(&curve).iter().all(|&s| s > 1e-9), "duplicate points at level {}", curve.level);
        assert!(curve.points.iter().all(|p| (p.y - curve.level).abs() < 1e-12));
    }
}
