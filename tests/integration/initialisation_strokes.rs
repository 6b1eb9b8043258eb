//! Interactive design from sketched strokes (Sec. 3.2.2, Fig. 14): strokes drawn along known
//! 60° P-curves of the cylinder, slightly off the surface, give the target angle 60° and a
//! converged pseudo-geodesic family.

use crate::initialisation_support;

use initialisation_support::{cylinder, Catenary};
use lamella::initialisation::{
    auto_design, estimate_target_angle, field_from_strokes, project_strokes, AutoDesignOptions, DesignStatus, StrokeOptions,
};
use lamella::mesh::{TriMesh, Vec3};

/// Distance of the stroke points from the cylinder surface.
const LIFT: f64 = 0.05;

/// Three strokes along the θ catenaries z0 = 3, 6, 9, over the middle of the patch, bottom to top.
fn strokes_at(theta: f64) -> Vec<Vec<Vec3>> {
    [3.0, 6.0, 9.0].iter().map(|&z0| Catenary::new(theta, z0).stroke(4.0, 22.0, 60, LIFT)).collect()
}

fn strokes() -> Vec<Vec<Vec3>> {
    strokes_at(60.0)
}

fn estimated_angle(mesh: &TriMesh, strokes: &[Vec<Vec3>]) -> f64 {
    let fitted = field_from_strokes(mesh, strokes, &StrokeOptions::default()).expect("valid strokes");
    eprintln!("stroke fit: {} iterations, converged {}", fitted.iterations, fitted.converged);
    assert!(fitted.converged, "stroke fit did not settle in {} iterations", fitted.iterations);
    estimate_target_angle(mesh, &fitted.field, &fitted.samples).expect("angle measurable")
}

#[test]
fn stroke_points_are_projected_one_per_triangle() {
    let mesh = cylinder(1500, 7);
    let strokes = strokes();
    let samples = project_strokes(&mesh, &strokes, 1.0).expect("valid strokes");
    for (stroke, samples) in strokes.iter().zip(&samples) {
        let mut faces: Vec<u32> = samples.iter().map(|s| s.face).collect();
        faces.sort_unstable();
        faces.dedup();
        assert_eq!(faces.len(), samples.len(), "one sample per triangle");
        assert!(samples.len() >= 20, "{} samples", samples.len());
        for s in samples {
            let corners = mesh.faces()[s.face as usize].map(|c| mesh.positions()[c as usize]);
            assert!(s.barycentric.iter().all(|&w| w >= -1e-12) && (s.barycentric.iter().sum::<f64>() - 1.0).abs() < 1e-12);
            let on_mesh = corners[0] * s.barycentric[0] + corners[1] * s.barycentric[1] + corners[2] * s.barycentric[2];
            // The stroke point is LIFT outside the cylinder; the chords of the mesh lie up to
            // e²/(8R) ≈ 0.01 inside it.
            let distance = (stroke[s.point] - on_mesh).norm();
            assert!((LIFT - 1e-9..=LIFT + 0.02).contains(&distance), "distance {distance}");
        }
    }
}

#[test]
fn strokes_along_sixty_degree_curves_give_sixty_degrees() {
    let mesh = cylinder(1500, 7);
    let theta = estimated_angle(&mesh, &strokes());
    eprintln!("estimated θ = {theta:.3}°");
    assert!((theta - 60.0).abs() <= 1.0, "θ = {theta}");
    // Drawn in the opposite order, the family is oriented the other way: the mirror angle.
    let reversed: Vec<Vec<Vec3>> = strokes().into_iter().rev().collect();
    let mirrored = estimated_angle(&mesh, &reversed);
    eprintln!("reversed order: θ = {mirrored:.3}°");
    assert!((mirrored - 120.0).abs() <= 1.0, "θ = {mirrored}");
    // Flatter curves of a steeper angle are told apart.
    let seventy = estimated_angle(&mesh, &strokes_at(70.0));
    eprintln!("70° strokes: θ = {seventy:.3}°");
    assert!((seventy - 70.0).abs() <= 1.0, "θ = {seventy}");
}

#[test]
fn auto_design_converges_to_the_sixty_degree_family() {
    let mesh = cylinder(1500, 11);
    let design = auto_design(&mesh, &strokes(), &AutoDesignOptions::default()).expect("valid strokes");
    let report = &design.report;
    eprintln!(
        "auto_design: θ = {:.3}°, {:?}, {} iterations, E_angle {:.2e}, max error {:.3}°",
        design.theta_degrees, design.status, report.iterations, report.energies.angle, report.angle_error_max_degrees
    );
    assert_eq!(design.status, DesignStatus::Succeeded);
    assert!((design.theta_degrees - 60.0).abs() <= 1.0);
    assert!(report.energies.angle <= 1e-5, "E_angle = {}", report.energies.angle);
    assert!(report.angle_error_max_degrees <= 1.0, "max angle error {}°", report.angle_error_max_degrees);
    assert!(report.singular_vertices.is_empty());
    assert!(design.field.iter().all(|f| f.is_finite()) && design.field.len() == mesh.vertex_count());
}

#[test]
fn the_design_does_not_depend_on_the_thread_count() {
    let mesh = cylinder(800, 2);
    let run = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().expect("thread pool");
        pool.install(|| {
            let options = AutoDesignOptions { max_iterations: 20, ..AutoDesignOptions::default() };
            let design = auto_design(&mesh, &strokes(), &options).expect("valid strokes");
            let bits = |v: &[f64]| v.iter().map(|f| f.to_bits()).collect::<Vec<u64>>();
            (bits(&design.stroke_field), bits(&design.field), design.theta_degrees.to_bits())
        })
    };
    assert!(run(1) == run(2), "one and two threads give different bits");
}
