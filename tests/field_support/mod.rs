//! Shared helpers of the field tests: test surfaces, their developments and level-set samples.
#![allow(dead_code)]

use lamella::mesh::{TriMesh, Vec3};
use lamella::surfaces::{cylinder_patch, hyperbolic_paraboloid, CylinderPatch, HyperbolicParaboloid};

pub const RADIUS: f64 = 10.0;

/// The paper's validation cylinder: R = 10, 150° span, height 15, irregular triangulation.
pub fn cylinder(target_vertices: usize, seed: u64) -> TriMesh {
    let patch = CylinderPatch { radius: RADIUS, span: 150f64.to_radians(), height: 15.0, target_vertices, irregularity: 0.25, seed };
    cylinder_patch(&patch).expect("valid patch").into_mesh().expect("valid mesh")
}

/// z = xy/c over [−a, a]², irregularly triangulated.
pub fn saddle(c: f64, half_width: f64, target_vertices: usize) -> TriMesh {
    let surface = HyperbolicParaboloid { c, half_width, target_vertices, irregularity: 0.25, seed: 3 };
    hyperbolic_paraboloid(&surface).expect("valid surface").into_mesh().expect("valid mesh")
}

/// Arc length along the circumference and height: the isometric development of the cylinder.
pub fn development(p: &Vec3) -> (f64, f64) {
    (RADIUS * p.y.atan2(p.x), p.z)
}

/// Height plus a low-frequency perturbation: smooth, but its level sets are not P-curves.
pub fn perturbed_height(mesh: &TriMesh) -> Vec<f64> {
    mesh.positions()
        .iter()
        .map(|p| {
            let (s, z) = development(p);
            z + 0.8 * (s / 9.0).sin() + 0.3 * (z / 5.0).cos()
        })
        .collect()
}

/// Points where the piecewise-linear field crosses `level` on the mesh edges.
pub fn level_points(mesh: &TriMesh, field: &[f64], level: f64) -> Vec<Vec3> {
    let mut points = Vec::new();
    for &[a, b] in mesh.edges() {
        let (fa, fb) = (field[a as usize], field[b as usize]);
        if (fa - level) * (fb - level) < 0.0 {
            let t = (level - fa) / (fb - fa);
            let (pa, pb) = (mesh.positions()[a as usize], mesh.positions()[b as usize]);
            points.push(pa + (pb - pa) * t);
        }
    }
    points
}

/// `count` levels spread evenly inside the field's range (the extreme ones left out).
pub fn levels(field: &[f64], count: usize) -> Vec<f64> {
    let min = field.iter().cloned().fold(f64::INFINITY, f64::min);
    let max = field.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
    (1..=count).map(|i| min + (max - min) * i as f64 / (count + 1) as f64).collect()
}

/// Largest distance of 2D points from their best-fitting straight line (principal axis),
/// and the extent of the points along that line.
pub fn line_fit(points: &[(f64, f64)]) -> (f64, f64) {
    let n = points.len() as f64;
    let (mx, my) = points.iter().fold((0.0, 0.0), |(x, y), p| (x + p.0 / n, y + p.1 / n));
    let (mut sxx, mut sxy, mut syy) = (0.0, 0.0, 0.0);
    for &(x, y) in points {
        sxx += (x - mx) * (x - mx);
        sxy += (x - mx) * (y - my);
        syy += (y - my) * (y - my);
    }
    let angle = 0.5 * (2.0 * sxy).atan2(sxx - syy);
    let (dx, dy) = (angle.cos(), angle.sin());
    let mut deviation: f64 = 0.0;
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for &(x, y) in points {
        let along = (x - mx) * dx + (y - my) * dy;
        deviation = deviation.max(((x - mx) * dy - (y - my) * dx).abs());
        lo = lo.min(along);
        hi = hi.max(along);
    }
    (deviation, hi - lo)
}
