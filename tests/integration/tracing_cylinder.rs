//! Traced P-curves on the paper's validation cylinder (Sec. 3.1, Fig. 10) against the analytic
//! curves in the cylinder's development.

use crate::tracing_support;

use lamella::tracing::{StopReason, TraceOptions, TracedCurve, Tracer};
use tracing_support::*;

/// The catenary of the θ family through the apex `(0, apex)` in the development, opening
/// upwards (`up`) or downwards: `y = apex ± (cosh(kx) − 1)/k`, `k = tan(90° − θ)/R`.
///
/// Derivation (Wunderlich; Sec. 2.2): with ψ the developed tangent's angle against the
/// circumference, `κ_g = dψ/ds` and `|κ_n| = cos²ψ / R`; `κ_g/κ_n = tan α = cot θ` integrates to
/// `y' = sinh(kx)`. Sign: travelling in +x at the apex on the outward-normal cylinder,
/// `u = n × t` points up; a curve bending up has `κ n^p = k u − n / R`, so its binormal
/// `b ∝ t × n^p = k n + u / R` has `b·u > 0` and `acos(b·n) = atan(1/(kR)) = θ`. Bending down
/// gives `b·n < 0 < b·u`, i.e. the signed angle 180° − θ.
fn catenary(theta: f64, apex: f64, up: bool, x_end: f64) -> Vec<(f64, f64)> {
    let k = (90.0 - theta).to_radians().tan() / RADIUS;
    let sign = if up { 1.0 } else { -1.0 };
    (0..=2000)
        .map(|i| {
            let x = x_end * i as f64 / 2000.0;
            (x, apex + sign * ((k * x).cosh() - 1.0) / k)
        })
        .collect()
}

fn trace_from_left(theta: f64, height: f64, alpha: f64) -> (lamella::mesh::TriMesh, TracedCurve) {
    let mesh = cylinder(3000, 17);
    let tracer = Tracer::new(&mesh);
    let start = left_side_point(&mesh, height);
    let curve = tracer.trace(&start, theta, alpha, &TraceOptions::default()).expect("valid input");
    (mesh, curve)
}

/// Traces θ from the left side at `apex` perpendicular to it (α = 90°: the start is the apex)
/// and compares with the catenary of `family_theta` opening `up` or down.
fn check_catenary(theta: f64, family_theta: f64, apex: f64, up: bool) {
    let (mesh, curve) = trace_from_left(theta, apex, 90.0);
    assert_eq!(curve.stop(), StopReason::Boundary);
    let developed: Vec<(f64, f64)> = curve.positions().iter().map(development).collect();
    let last = developed[developed.len() - 1];
    let expected_end = if up { HEIGHT } else { 0.0 };
    assert!((last.1 - expected_end).abs() < 1e-9, "curve should end at height {expected_end}, ends at {last:?}");
    let angles = binormal_angles(&mesh, curve.points(), curve.positions());
    let measured: Vec<f64> = angles.iter().flatten().copied().collect();
    assert!(measured.len() + 2 >= angles.len(), "too many straight turns");
    let worst = measured.iter().map(|a| (a - theta).abs()).fold(0.0, f64::max);
    eprintln!("theta {theta}: {} points, worst binormal angle error {worst:e}°", curve.points().len());
    assert!(worst <= 1.0, "binormal angle off by {worst}°");
    let analytic = catenary(family_theta, apex, up, last.0);
    let length = length_2d(&developed);
    let distance = hausdorff(&developed, &analytic);
    eprintln!("theta {theta}: length {length}, Hausdorff {distance} ({} % of the length)", 100.0 * distance / length);
    // The brief asks for 1 %; the fitted start normal brings it to a few hundredths of a percent
    // (with the one-sided boundary vertex normals instead it is about 1.1 %).
    assert!(distance <= 0.002 * length, "Hausdorff {distance} vs length {length}");
}

#[test]
fn sixty_degrees_traces_the_upward_catenary() {
    check_catenary(60.0, 60.0, 2.0, true);
}

#[test]
fn mirror_family_traces_the_downward_catenary() {
    check_catenary(120.0, 60.0, 13.0, false);
}

#[test]
fn geodesic_is_a_helix() {
    // α = 60° against the boundary direction (downwards on the left side) points 30° below the
    // circumference: the helix develops into the line y = 13 − x·tan 30°.
    let (_, curve) = trace_from_left(90.0, 13.0, 60.0);
    assert_eq!(curve.stop(), StopReason::Boundary);
    let developed: Vec<(f64, f64)> = curve.positions().iter().map(development).collect();
    let last = developed[developed.len() - 1];
    assert!(last.1.abs() < 1e-9, "the helix should end at the bottom, ends at {last:?}");
    let slope = -30f64.to_radians().tan();
    let line = [(0.0, 13.0), (last.0, 13.0 + slope * last.0)];
    let length = length_2d(&developed);
    let distance = hausdorff(&developed, &line);
    eprintln!("helix: length {length}, Hausdorff {distance} ({} %)", 100.0 * distance / length);
    assert!(distance <= 0.005 * length, "Hausdorff {distance} vs length {length}");
}

#[test]
fn tracing_is_deterministic() {
    let (_, a) = trace_from_left(60.0, 2.0, 90.0);
    let (_, b) = trace_from_left(60.0, 2.0, 90.0);
    assert_eq!(a, b);
}

