//! The field from guide curves (Sec. 3.2.2, Eq. 5–7): it interpolates the guides, is free of
//! singular vertices, and the pseudo-geodesic optimisation started from it reaches the paper's
//! accuracy, on the cylinder (guides: analytic 60° P-curves) and on the vault (guides: plane
//! sections, until traced curves are available).

use crate::initialisation_support;

use initialisation_support::{cylinder, plane_section, value_at, vault_mesh, Catenary};
use lamella::field::{find_level_crossing, FieldParams, FieldSolver};
use lamella::initialisation::{field_from_guide_curves, GuideCurveOptions, GuideField};
use lamella::mesh::{EdgePoint, TriMesh};

/// Interior vertices where the level curve does not cross exactly two star edges.
fn singular_vertices(mesh: &TriMesh, field: &[f64]) -> usize {
    (0..mesh.vertex_count()).filter(|&v| !mesh.is_boundary_vertex(v) && find_level_crossing(mesh, field, v).is_none()).count()
}

/// Largest |F(p) − i| over the points p of guide i.
fn interpolation_error(field: &[f64], guides: &[Vec<EdgePoint>]) -> f64 {
    guides
        .iter()
        .enumerate()
        .flat_map(|(i, g)| g.iter().map(move |p| (value_at(field, p) - i as f64).abs()))
        .fold(0.0, f64::max)
}

/// Runs the default 60° optimisation from the guide field and checks the paper's accuracy.
fn assert_sixty_degree_family(mesh: &TriMesh, guide: &GuideField, name: &str) {
    let mut params = FieldParams::pseudo_geodesic(60.0);
    params.gradient_target = Some(guide.gradient_target);
    let mut solver = FieldSolver::new(mesh, &guide.field, params).expect("valid input");
    let start = solver.report().angle_error_max_degrees;
    let report = solver.step(300).expect("solver runs");
    eprintln!(
        "{name}: start max error {start:.2}°, {} iterations, E_angle {:.2e}, max error {:.3}°, singular {}",
        report.iterations,
        report.energies.angle,
        report.angle_error_max_degrees,
        report.singular_vertices.len()
    );
    assert!(report.converged, "{name}: not converged after {} iterations", report.iterations);
    assert!(report.energies.angle <= 1e-5, "{name}: E_angle = {}", report.energies.angle);
    assert!(report.singular_vertices.is_empty(), "{name}: singular vertices {:?}", report.singular_vertices);
}

#[test]
fn cylinder_guides_are_interpolated_and_lead_to_the_sixty_degree_family() {
    let mesh = cylinder(1500, 7);
    let guides: Vec<Vec<EdgePoint>> = [2.0, 5.0, 8.0].iter().map(|&z0| Catenary::new(60.0, z0).edge_points(&mesh)).collect();
    assert!(guides.iter().all(|g| g.len() > 20), "each guide crosses many edges");
    let guide = field_from_guide_curves(&mesh, &guides, &GuideCurveOptions::default()).expect("valid guides");
    let error = interpolation_error(&guide.field, &guides);
    eprintln!("cylinder: interpolation error {error:.2e}, r = {:.4}", guide.gradient_target);
    assert!(error <= 0.02, "guide values missed by {error}");
    assert_eq!(singular_vertices(&mesh, &guide.field), 0);
    // The guides are 3 apart along the axis: the spacing of the family is about 1/3 per unit length
    // (the gradient of F = (z − catenary)/3 is 1/3 · √(1 + sinh²(k(s − s0))) ≥ 1/3).
    assert!((guide.gradient_target - 1.0 / 3.0).abs() < 0.15 / 3.0, "r = {}", guide.gradient_target);
    // Already close to the 60° family: the analytic guides span the whole patch.
    assert_sixty_degree_family(&mesh, &guide, "cylinder");
}

#[test]
fn vault_guides_are_interpolated_and_lead_to_a_sixty_degree_family() {
    let mesh = vault_mesh(1500, 5);
    let guides: Vec<Vec<EdgePoint>> = [-6.0, -2.0, 2.0, 6.0].iter().map(|&c| plane_section(&mesh, c)).collect();
    let guide = field_from_guide_curves(&mesh, &guides, &GuideCurveOptions::default()).expect("valid guides");
    let error = interpolation_error(&guide.field, &guides);
    eprintln!("vault: interpolation error {error:.2e}, r = {:.4}", guide.gradient_target);
    assert!(error <= 0.02, "guide values missed by {error}");
    assert_eq!(singular_vertices(&mesh, &guide.field), 0);
    // Sections 4 apart in x: F ≈ (x + 6)/4, whose surface gradient is (x̂ projected to the tangent
    // plane)/4, of norm at most 1/4 and close to it where the vault is gently sloped.
    assert!(guide.gradient_target > 0.21 && guide.gradient_target < 0.2505, "r = {}", guide.gradient_target);
    assert_sixty_degree_family(&mesh, &guide, "vault");
}
