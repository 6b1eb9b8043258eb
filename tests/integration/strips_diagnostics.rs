//! The node diagnostics of Sec. 5.1 on analytic curves: a helix (constant κ and τ, so constant
//! conical curvature k = τ/κ, vertical Darboux vector, singular points at infinity) and a helix
//! of growing pitch (k′ ≠ 0: singular points at a finite distance v_r = −1/(κ k′) along d).

use lamella::mesh::Vec3;
use lamella::strips::strip_diagnostics;

const R: f64 = 2.0;
const PITCH: f64 = 0.8;

fn helix(t: f64) -> Vec3 {
    Vec3::new(R * t.cos(), R * t.sin(), PITCH * t)
}

#[test]
fn a_helix_has_its_curvature_torsion_and_darboux_angle() {
    let a2 = R * R + PITCH * PITCH;
    let (kappa, tau) = (R / a2, PITCH / a2);
    let ts: Vec<f64> = (0..=120).map(|i| i as f64 * 0.05).collect();
    let centre: Vec<Vec3> = ts.iter().map(|&t| helix(t)).collect();
    // Exact binormals; the rectifying developable is the cylinder, its rulings vertical.
    let binormals: Vec<Vec3> = ts.iter().map(|&t| Vec3::new(PITCH * t.sin(), -PITCH * t.cos(), R) / a2.sqrt()).collect();
    let rulings = vec![Vec3::z(); centre.len()];
    let width = 0.6;
    let diagnostics = strip_diagnostics(&centre, &binormals, &rulings, width);
    let k = tau / kappa;
    let angle = k.atan().to_degrees();
    let mut measured = 0;
    for d in &diagnostics[2..diagnostics.len() - 2] {
        let rel = |got: Option<f64>, want: f64| (got.expect("defined") - want).abs() / want.abs();
        assert!(rel(d.curvature, kappa) < 1e-3, "κ {:?} vs {kappa}", d.curvature);
        assert!(rel(d.torsion, tau) < 1e-3, "τ {:?} vs {tau}", d.torsion);
        assert!(rel(d.conical_curvature, k) < 1e-3, "k {:?} vs {k}", d.conical_curvature);
        assert!((d.darboux_angle_degrees.unwrap() - angle).abs() < 0.05, "{:?} vs {angle}", d.darboux_angle_degrees);
        assert!((d.binormal_ruling_degrees.unwrap() - angle).abs() < 1e-9, "{:?} vs {angle}", d.binormal_ruling_degrees);
        // Prop. 2: κ k² v² / 2 at v = width / 2.
        assert!(rel(d.binormal_offset, kappa * k * k * (width / 2.0).powi(2) / 2.0) < 3e-3);
        // k is constant: the singular points are at infinity (or at least far beyond the strip).
        assert!(d.singular_point_distance.is_none_or(|s| s > 1e3), "{:?}", d.singular_point_distance);
        assert!(!d.singular_point_near);
        measured += 1;
    }
    assert!(measured > 100);
    // The ends have no curvature.
    assert!(diagnostics[0].curvature.is_none() && diagnostics[0].conical_curvature.is_none());
}

#[test]
fn a_growing_pitch_brings_the_singular_points_to_a_finite_distance() {
    let growth = 0.3;
    let curve = |t: f64| Vec3::new(R * t.cos(), R * t.sin(), PITCH * t + growth * t * t);
    // Frenet quantities from the exact derivatives.
    let frenet = |t: f64| {
        let d1 = Vec3::new(-R * t.sin(), R * t.cos(), PITCH + 2.0 * growth * t);
        let d2 = Vec3::new(-R * t.cos(), -R * t.sin(), 2.0 * growth);
        let d3 = Vec3::new(R * t.sin(), -R * t.cos(), 0.0);
        let cross = d1.cross(&d2);
        (cross.norm() / d1.norm().powi(3), cross.dot(&d3) / cross.norm_squared(), d1.norm())
    };
    let k = |t: f64| {
        let (kappa, tau, _) = frenet(t);
        tau / kappa
    };
    let ts: Vec<f64> = (0..=200).map(|i| i as f64 * 0.01).collect();
    let centre: Vec<Vec3> = ts.iter().map(|&t| curve(t)).collect();
    let binormals = vec![Vec3::z(); centre.len()];
    // The singular points stay 8.3 or more from the curve: clear of a 0.5 wide strip, near an 8 wide one.
    for (width, near_expected) in [(0.5, false), (8.0, true)] {
        let diagnostics = strip_diagnostics(&centre, &binormals, &binormals, width);
        let mut near = 0;
        for (i, d) in diagnostics.iter().enumerate().skip(5).take(190) {
            let t = ts[i];
            let (kappa, tau, speed) = frenet(t);
            let k_s = (k(t + 1e-5) - k(t - 1e-5)) / 2e-5 / speed;
            let expected = (tau * tau + kappa * kappa).sqrt() / (kappa * k_s).abs();
            let got = d.singular_point_distance.expect("finite");
            assert!((got - expected).abs() < 0.02 * expected, "t = {t}: singular point at {got}, expected {expected}");
            // Near: within one strip width of the strip, which reaches (width / 2) / sin α along the
            // vertical ruling (α its angle with the tangent).
            let tangent = (centre[i + 1] - centre[i - 1]).normalize();
            let extent = 0.5 * width / tangent.cross(&Vec3::z()).norm();
            assert_eq!(d.singular_point_near, got <= extent + width, "t = {t}: {got}");
            near += usize::from(d.singular_point_near);
        }
        assert_eq!(near > 0, near_expected, "width {width}: {near} near singular points");
    }
}
