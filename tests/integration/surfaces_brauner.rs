//! Brauner's surface of the paper (Eq. 23, Fig. 32): its u-lines v = const are asymptotic curves
//! of constant slope, checked on the analytic curves against the exact normal, on the generated
//! mesh, and as what the asymptotic field optimisation finds on that mesh.

use lamella::curves::{extract_level_curves, uniform_levels};
use lamella::field::{Family, FieldParams, FieldSolver};
use lamella::mesh::{TriMesh, Vec3};
use lamella::surfaces::{brauner_normal, brauner_point, brauner_slope_degrees, brauner_surface, BraunerSurface, HeatSolution, PaperHeatSolution};

#[test]
fn the_paper_function_solves_the_heat_equation() {
    let f = PaperHeatSolution;
    let h = 1e-4;
    for &(u, v) in &[(0.3, -0.7), (1.2, 0.1), (2.5, 0.9), (-1.0, 2.0)] {
        let value = |u: f64, v: f64| f.jet(u, v).f;
        let j = f.jet(u, v);
        let f_uu = (value(u + h, v) - 2.0 * value(u, v) + value(u - h, v)) / (h * h);
        let f_v = (value(u, v + h) - value(u, v - h)) / (2.0 * h);
        assert!((f_uu - f_v).abs() < 1e-5, "f_uu {f_uu} vs f_v {f_v} at ({u}, {v})");
        // The jet's partials against central differences.
        let d_u = |g: &dyn Fn(f64, f64) -> f64| (g(u + h, v) - g(u - h, v)) / (2.0 * h);
        let d_v = |g: &dyn Fn(f64, f64) -> f64| (g(u, v + h) - g(u, v - h)) / (2.0 * h);
        assert!((d_u(&value) - j.f_u).abs() < 1e-6);
        assert!((d_v(&value) - j.f_v).abs() < 1e-6);
        assert!((d_v(&|u, v| f.jet(u, v).f_u) - j.f_uv).abs() < 1e-6);
        assert!((d_v(&|u, v| f.jet(u, v).f_v) - j.f_vv).abs() < 1e-6);
    }
}

#[test]
fn eq_23_gives_the_closed_form_of_the_paper_surface() {
    // x = cos²u − 2v, y = sin u cos u − u, z = 2μ e^{−v} cos u (worked out by hand from Eq. 23).
    for &(u, v, mu) in &[(0.7, -0.3, 1.0), (1.9, 0.4, 2.5), (2.8, 1.1, 0.5)] {
        let p = brauner_point(&PaperHeatSolution, mu, u, v);
        let expected = Vec3::new(u.cos().powi(2) - 2.0 * v, u.sin() * u.cos() - u, 2.0 * mu * (-v).exp() * u.cos());
        assert!((p - expected).norm() < 1e-12, "{p:?} vs {expected:?}");
        assert_eq!(BraunerSurface::parameters_of(p.x, p.y).map(|(a, b)| ((a - u).abs() < 1e-9, (b - v).abs() < 1e-9)), Some((true, true)));
    }
}

#[test]
fn u_lines_are_asymptotic_curves_of_constant_slope() {
    let surface = BraunerSurface::paper(100);
    let h = 1e-4;
    for &v in &[-0.5, -0.2, 0.0, 0.3, 0.5] {
        let beta = brauner_slope_degrees(surface.mu, v);
        for i in 0..=40 {
            let u = surface.u_range[0] + (surface.u_range[1] - surface.u_range[0]) * i as f64 / 40.0;
            let c = |u: f64| brauner_point(&PaperHeatSolution, surface.mu, u, v);
            // Tangent and acceleration of the curve by differences of its points only.
            let (d1, d2) = ((c(u + h) - c(u - h)) / (2.0 * h), (c(u + h) - c(u) * 2.0 + c(u - h)) / (h * h));
            let slope = (d1.normalize().z.abs()).asin().to_degrees();
            assert!((slope - beta).abs() < 1e-6, "v = {v}, u = {u}: slope {slope}° vs {beta}°");
            // Normal curvature against the exact normal, relative to the curve's curvature.
            let n = surface.normal(u, v);
            let generic = brauner_normal(&PaperHeatSolution, surface.mu, u, v).expect("regular");
            assert!(n.cross(&generic).norm() < 1e-12, "the two exact normals disagree");
            assert!(n.dot(&d1.normalize()).abs() < 1e-9, "the curve leaves the tangent plane");
            let curvature = d1.cross(&d2).norm() / d1.norm().powi(3);
            let normal_curvature = n.dot(&d2) / d1.norm_squared();
            assert!(curvature > 0.05, "v = {v}, u = {u}: curvature {curvature}");
            assert!(normal_curvature.abs() < 1e-5 * curvature, "v = {v}, u = {u}: κ_n {normal_curvature} against κ {curvature}");
        }
    }
}

fn paper_mesh(vertices: usize) -> TriMesh {
    brauner_surface(&BraunerSurface::paper(vertices)).expect("valid surface").into_mesh().expect("valid mesh")
}

#[test]
fn the_mesh_lies_on_the_surface_with_upward_faces() {
    let surface = BraunerSurface::paper(800);
    let mesh = paper_mesh(800);
    for p in mesh.positions() {
        let (u, v) = BraunerSurface::parameters_of(p.x, p.y).expect("inside the plan");
        assert!((brauner_point(&PaperHeatSolution, surface.mu, u, v) - p).norm() < 1e-9);
    }
    for (f, face) in mesh.faces().iter().enumerate() {
        let centre = face.iter().map(|&v| mesh.positions()[v as usize]).sum::<Vec3>() / 3.0;
        let (u, v) = BraunerSurface::parameters_of(centre.x, centre.y).expect("inside the plan");
        assert!(mesh.face_normals()[f].dot(&surface.normal(u, v)) > 0.9, "face {f}");
    }
    for bad in [
        BraunerSurface { mu: 0.0, ..surface.clone() },
        BraunerSurface { u_range: [0.0, 1.0], ..surface.clone() },
        BraunerSurface { u_range: [1.0, 3.2], ..surface.clone() },
        BraunerSurface { v_range: [0.5, 0.5], ..surface.clone() },
        BraunerSurface { v_range: [f64::NAN, 0.5], ..surface.clone() },
    ] {
        assert!(brauner_surface(&bad).is_err(), "{bad:?} accepted");
    }
}

/// Largest spread of v along the level curves of `field`, and the largest slope error (degrees)
/// of their chords every three edges against the analytic slope of the u-line through the point.
fn against_u_lines(mesh: &TriMesh, field: &[f64]) -> (f64, f64) {
    let mu = BraunerSurface::paper(0).mu;
    let levels = uniform_levels(mesh, field, 9).expect("levels");
    let curves = extract_level_curves(mesh, field, &levels).expect("curves");
    let (mut spread, mut slope_error) = (0.0f64, 0.0f64);
    for curve in &curves {
        let points = curve.resampled(3.0 * mesh.mean_edge_length()).expect("spacing").points;
        let vs: Vec<f64> = points.iter().map(|p| BraunerSurface::parameters_of(p.x, p.y).expect("inside").1).collect();
        let (lo, hi) = vs.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| (a.min(v), b.max(v)));
        spread = spread.max(hi - lo);
        for (w, v) in points.windows(3).zip(&vs[1..]) {
            let slope = (w[2] - w[0]).normalize().z.abs().asin().to_degrees();
            slope_error = slope_error.max((slope - brauner_slope_degrees(mu, *v)).abs());
        }
    }
    (spread, slope_error)
}

#[test]
fn the_asymptotic_field_finds_the_u_lines() {
    let mesh = paper_mesh(1500);
    // Start: v plus a smooth perturbation that bends the level sets off the u-lines.
    let start: Vec<f64> = mesh
        .positions()
        .iter()
        .map(|p| {
            let (u, v) = BraunerSurface::parameters_of(p.x, p.y).expect("inside");
            v + 0.08 * (2.0 * u).sin()
        })
        .collect();
    let (spread_before, slope_before) = against_u_lines(&mesh, &start);
    let mut solver = FieldSolver::new(&mesh, &start, FieldParams::new(Family::Asymptotic)).expect("valid input");
    let report = solver.step(200).expect("solver runs");
    let (spread_after, slope_after) = against_u_lines(&mesh, &solver.field());
    eprintln!("{report:?}\nv spread {spread_before} -> {spread_after}, slope error {slope_before}° -> {slope_after}°");
    assert!(spread_before > 0.1, "the start is already on the u-lines ({spread_before})");
    assert!(spread_after < 0.02, "v spread along the level curves {spread_before} -> {spread_after}");
    assert!(slope_after < 1.0, "slope error {slope_before}° -> {slope_after}°");
}
