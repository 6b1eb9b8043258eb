//! The fairness energy E_fair (paper Eq. 6, Stein et al. 2018) against independent expectations:
//! affine functions are in its null space up to the boundary, the energy of a quadratic converges
//! to ∫‖H‖², functions affine in the development of a cylinder have vanishing energy, and the
//! precomputed operators are consistent with the residuals and the energy.

use lamella::field::hessian_energy::HessianEnergy;
use lamella::mesh::{TriMesh, Vec3};
use lamella::surfaces::{cylinder_patch, planar_disk, CylinderPatch, PlanarPatch};

fn disk_mesh(target_vertices: usize, irregularity: f64, seed: u64) -> TriMesh {
    let patch = PlanarPatch { radius: 1.0, target_vertices, irregularity, seed };
    planar_disk(&patch).unwrap().into_mesh().unwrap()
}

fn cylinder_mesh(target_vertices: usize) -> TriMesh {
    let patch =
        CylinderPatch { radius: 10.0, span: 150f64.to_radians(), height: 15.0, target_vertices, irregularity: 0.3, seed: 2 };
    cylinder_patch(&patch).unwrap().into_mesh().unwrap()
}

fn sample(mesh: &TriMesh, f: impl Fn(&Vec3) -> f64) -> Vec<f64> {
    mesh.positions().iter().map(f).collect()
}

fn total_area(mesh: &TriMesh) -> f64 {
    mesh.face_areas().iter().sum()
}

fn residual_norm(energy: &HessianEnergy, v: usize, field: &[f64]) -> f64 {
    let mut r = [0.0; 3];
    energy.vertex_residuals(v, field, &mut r);
    r.iter().map(|x| x * x).sum::<f64>().sqrt()
}

/// Asserts that every vertex residual of the affine function `a + g·p` vanishes, boundary vertices
/// included, relative to the scale ‖g‖ · (diameter / mean edge length) of single residual terms.
fn assert_affine_null_space(mesh: &TriMesh, diameter: f64, gradient: Vec3) {
    let energy = HessianEnergy::new(mesh);
    let field = sample(mesh, |p| 2.5 + gradient.dot(p));
    let scale = gradient.norm() * diameter / mesh.mean_edge_length();
    let mut boundary_vertices = 0;
    for v in 0..mesh.vertex_count() {
        let r = residual_norm(&energy, v, &field);
        assert!(r < 1e-12 * scale, "vertex {v} (boundary: {}): residual {r:e}", mesh.is_boundary_vertex(v));
        boundary_vertices += usize::from(mesh.is_boundary_vertex(v));
    }
    assert!(boundary_vertices > 50);
}

#[test]
fn affine_functions_have_zero_residuals_on_an_irregular_planar_disk() {
    let mesh = disk_mesh(3000, 0.3, 17);
    assert_affine_null_space(&mesh, 2.0, Vec3::new(0.7, -1.3, 0.0));
}

#[test]
fn affine_functions_have_zero_residuals_on_a_tilted_planar_disk() {
    // The same disk rotated out of the xy plane and moved: the tangent projection must follow.
    let disk = planar_disk(&PlanarPatch { radius: 1.0, target_vertices: 3000, irregularity: 0.3, seed: 18 }).unwrap();
    let rotation = nalgebra::Rotation3::from_axis_angle(&nalgebra::Unit::new_normalize(Vec3::new(1.0, 2.0, 0.5)), 1.1);
    let positions = disk.positions.iter().map(|p| rotation * p + Vec3::new(3.0, -1.0, 2.0)).collect();
    let mesh = TriMesh::from_vertices_and_faces(positions, disk.faces).unwrap();
    assert_affine_null_space(&mesh, 2.0, Vec3::new(0.4, 1.1, -0.8));
}

#[test]
fn quadratic_energy_converges_to_the_integral_of_the_squared_hessian() {
    // F = x² + 3xy: H = [[2, 3], [3, 0]], ‖H‖_F² = 22, so E → 22 · area.
    let mut errors = Vec::new();
    for target in [300, 1200, 4800, 19200] {
        let mesh = disk_mesh(target, 0.0, 4);
        let energy = HessianEnergy::new(&mesh);
        let field = sample(&mesh, |p| p.x * p.x + 3.0 * p.x * p.y);
        let relative_error = (energy.energy(&field) / (22.0 * total_area(&mesh)) - 1.0).abs();
        eprintln!("{} vertices: relative error of E(x² + 3xy) {relative_error:.3e}", mesh.vertex_count());
        errors.push(relative_error);
    }
    assert!(errors.windows(2).all(|w| w[1] < w[0]), "errors decrease under refinement: {errors:?}");
    assert!(errors[3] < 5e-3);
}

#[test]
fn quadratic_energy_on_jittered_disks_stays_within_the_consistency_floor() {
    // Jitter makes the lumped weak Hessian of a quadratic vary from vertex to vertex; the energy
    // then carries an O(irregularity²) excess that refinement does not remove.
    for target in [1200, 4800] {
        let mesh = disk_mesh(target, 0.3, 4);
        let energy = HessianEnergy::new(&mesh);
        let field = sample(&mesh, |p| p.x * p.x + 3.0 * p.x * p.y);
        let relative_error = (energy.energy(&field) / (22.0 * total_area(&mesh)) - 1.0).abs();
        eprintln!("irregularity 0.3, {} vertices: relative error {relative_error:.3e}", mesh.vertex_count());
        assert!(relative_error < 0.06);
    }
}

#[test]
fn natural_boundary_condition_unlike_the_laplacian() {
    // On boundary vertices an affine F has zero Hessian residual, while the uniform and the
    // cotangent Laplacian of the same F do not vanish there (their one-sided stars are unbalanced).
    let mesh = disk_mesh(1200, 0.2, 9);
    let energy = HessianEnergy::new(&mesh);
    let field = sample(&mesh, |p| 1.0 + 0.6 * p.x + 0.8 * p.y);
    let p = mesh.positions();
    let mut cotan = vec![0.0; mesh.vertex_count()];
    for f in mesh.faces() {
        for k in 0..3 {
            // The angle at corner k weighs the opposite edge (i, j).
            let (o, i, j) = (f[k] as usize, f[(k + 1) % 3] as usize, f[(k + 2) % 3] as usize);
            let (a, b) = (p[i] - p[o], p[j] - p[o]);
            let cot = a.dot(&b) / a.cross(&b).norm();
            cotan[i] += 0.5 * cot * (field[j] - field[i]);
            cotan[j] += 0.5 * cot * (field[i] - field[j]);
        }
    }
    let boundary: Vec<usize> = (0..mesh.vertex_count()).filter(|&v| mesh.is_boundary_vertex(v)).collect();
    let uniform: Vec<f64> = boundary
        .iter()
        .map(|&v| {
            let neighbours = mesh.star(v).neighbours;
            neighbours.iter().map(|&j| field[j as usize] - field[v]).sum::<f64>() / neighbours.len() as f64
        })
        .collect();
    let largest_hessian = boundary.iter().map(|&v| residual_norm(&energy, v, &field)).fold(0.0, f64::max);
    // A Laplacian of an affine F at a boundary vertex is about ∇F · (inward offset ~ h); it only
    // vanishes where ∇F happens to be tangent to the boundary.
    let boundary_cotan: Vec<f64> = boundary.iter().map(|&v| cotan[v]).collect();
    let mean_abs = |values: &[f64]| values.iter().map(|x| x.abs()).sum::<f64>() / values.len() as f64;
    let (mean_uniform, mean_cotan) = (mean_abs(&uniform), mean_abs(&boundary_cotan));
    let nonzero = uniform.iter().zip(&boundary_cotan).filter(|(u, c)| u.abs() > 1e-9 && c.abs() > 1e-9).count();
    eprintln!(
        "{} boundary vertices: mean |uniform Laplacian| {mean_uniform:.3e}, mean |cotan Laplacian| {mean_cotan:.3e}, \
         both nonzero at {nonzero}; max Hessian residual {largest_hessian:.3e}",
        boundary.len()
    );
    let h = mesh.mean_edge_length();
    assert!(mean_uniform > 0.05 * h && mean_cotan > 0.05 * h);
    assert!(nonzero as f64 > 0.9 * boundary.len() as f64);
    assert!(largest_hessian < 1e-12);
    // Interior vertices: both Laplacians vanish for affine F too (sanity check of the comparison).
    let interior_cotan = (0..mesh.vertex_count()).filter(|&v| !mesh.is_boundary_vertex(v)).map(|v| cotan[v].abs()).fold(0.0, f64::max);
    assert!(interior_cotan < 1e-12);
}

#[test]
fn functions_affine_in_the_cylinder_development_have_vanishing_energy() {
    // Arc length R·φ and height z are affine in the development of the cylinder (R = 10, 150°,
    // height 15); z² has Hessian 2 e_z ⊗ e_z, ‖H‖² = 4, so E(z²) → 4 · area.
    let mut previous = (f64::INFINITY, f64::INFINITY);
    for target in [500, 2000, 8000] {
        let mesh = cylinder_mesh(target);
        let energy = HessianEnergy::new(&mesh);
        let arc = energy.energy(&sample(&mesh, |p| 10.0 * p.y.atan2(p.x)));
        let height = energy.energy(&sample(&mesh, |p| p.z));
        let curved = energy.energy(&sample(&mesh, |p| p.z * p.z)) / (4.0 * total_area(&mesh));
        eprintln!("{} vertices: E(Rφ) {arc:.3e}, E(z) {height:.3e}, E(z²) / (4 area) {curved:.4}", mesh.vertex_count());
        assert!(arc < 0.5 * previous.0 && height < 0.5 * previous.1, "energies decrease like h²");
        assert!((curved - 1.0).abs() < 0.06);
        // Compared with the curved function the affine ones are negligible.
        assert!(arc.max(height) < 1e-5 * curved * 4.0 * total_area(&mesh));
        previous = (arc, height);
    }
}

#[test]
fn energy_is_invariant_to_adding_a_constant() {
    let mesh = cylinder_mesh(1000);
    let energy = HessianEnergy::new(&mesh);
    let field = sample(&mesh, |p| (0.3 * p.x).sin() + p.z * p.y * 0.01);
    let shifted: Vec<f64> = field.iter().map(|f| f + 123.0).collect();
    let (e, e_shifted) = (energy.energy(&field), energy.energy(&shifted));
    assert!(e > 0.0);
    assert!((e - e_shifted).abs() < 1e-10 * e, "{e} vs {e_shifted}");
}

#[test]
fn operators_match_residuals_linearity_and_finite_differences() {
    let mesh = cylinder_mesh(600);
    let energy = HessianEnergy::new(&mesh);
    let n = mesh.vertex_count();
    let f = sample(&mesh, |p| (0.2 * p.x).cos() * p.z + 0.1 * p.y * p.y);
    let g = sample(&mesh, |p| (0.05 * p.z * p.x).sin());
    let (a, b) = (1.7, -0.4);
    let combined: Vec<f64> = f.iter().zip(&g).map(|(x, y)| a * x + b * y).collect();
    let mut total = 0.0;
    for v in 0..n {
        let variables = energy.vertex_variables(v);
        let operator = energy.vertex_operator(v);
        assert_eq!(variables[0] as usize, v);
        assert_eq!(variables.len(), mesh.star(v).neighbours.len() + 1);
        assert_eq!(operator.len(), HessianEnergy::ROWS_PER_VERTEX * variables.len());
        let (mut rf, mut rg, mut rc) = ([0.0; 3], [0.0; 3], [0.0; 3]);
        energy.vertex_residuals(v, &f, &mut rf);
        energy.vertex_residuals(v, &g, &mut rg);
        energy.vertex_residuals(v, &combined, &mut rc);
        let magnitude = rf.iter().chain(&rg).map(|x| x.abs()).fold(1e-3, f64::max);
        for row in 0..3 {
            assert!((rc[row] - (a * rf[row] + b * rg[row])).abs() < 1e-10 * magnitude, "linearity");
            // Residual = operator row · field restricted to the variables.
            let by_operator: f64 =
                (0..variables.len()).map(|k| operator[row * variables.len() + k] * f[variables[k] as usize]).sum();
            assert!((rf[row] - by_operator).abs() < 1e-12 * magnitude);
        }
        total += rf.iter().map(|r| r * r).sum::<f64>();
        // Central differences of the residuals with respect to each variable give the columns.
        let step = 1e-3;
        for (k, &j) in variables.iter().enumerate() {
            let (mut plus, mut minus) = (f.clone(), f.clone());
            plus[j as usize] += step;
            minus[j as usize] -= step;
            let (mut rp, mut rm) = ([0.0; 3], [0.0; 3]);
            energy.vertex_residuals(v, &plus, &mut rp);
            energy.vertex_residuals(v, &minus, &mut rm);
            for row in 0..3 {
                let column = operator[row * variables.len() + k];
                let difference = (rp[row] - rm[row]) / (2.0 * step);
                assert!((difference - column).abs() < 1e-8 * (1.0 + column.abs()));
            }
        }
    }
    assert!((energy.energy(&f) - total).abs() < 1e-12 * total);
    // Directional derivative of the quadratic energy: dE/dt (f + t g) at 0 = 2 Σ_v r_v(f) · r_v(g).
    let mut directional = 0.0;
    for v in 0..n {
        let (mut rf, mut rg) = ([0.0; 3], [0.0; 3]);
        energy.vertex_residuals(v, &f, &mut rf);
        energy.vertex_residuals(v, &g, &mut rg);
        directional += 2.0 * rf.iter().zip(&rg).map(|(x, y)| x * y).sum::<f64>();
    }
    let t = 1e-4;
    let along = |s: f64| energy.energy(&f.iter().zip(&g).map(|(x, y)| x + s * y).collect::<Vec<_>>());
    let difference = (along(t) - along(-t)) / (2.0 * t);
    assert!((difference - directional).abs() < 1e-6 * (1.0 + directional.abs()));
}

#[test]
fn same_mesh_gives_the_same_operator_bits() {
    let (a, b) = (HessianEnergy::new(&cylinder_mesh(800)), HessianEnergy::new(&cylinder_mesh(800)));
    assert_eq!(a, b);
    assert_eq!(a.vertex_count(), cylinder_mesh(800).vertex_count());
}
