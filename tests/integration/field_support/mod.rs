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
    develop(p, RADIUS)
}

/// The development of a point of the cylinder of radius `radius` about the z axis.
pub fn develop(p: &Vec3, radius: f64) -> (f64, f64) {
    (radius * p.y.atan2(p.x), p.z)
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

/// Symmetric Hausdorff distance, in the cylinder's development, between a polyline and the best
/// catenary `z = ±cosh(k (s − s0))/k + c` over the polyline's `s` range (k = cot θ / R).
pub fn catenary_hausdorff(points: &[(f64, f64)], k: f64) -> f64 {
    let vertical = |s0: f64, sign: f64| {
        let residual: Vec<f64> = points.iter().map(|&(s, z)| z - sign * (k * (s - s0)).cosh() / k).collect();
        let (lo, hi) = residual.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &r| (a.min(r), b.max(r)));
        (0.5 * (hi - lo), 0.5 * (hi + lo))
    };
    let s_min = points.iter().map(|p| p.0).fold(f64::INFINITY, f64::min);
    let s_max = points.iter().map(|p| p.0).fold(f64::NEG_INFINITY, f64::max);
    let mut best = f64::INFINITY;
    for sign in [-1.0, 1.0] {
        let (mut lo, mut hi) = (-80.0, 110.0);
        let mut s_best = lo;
        for i in 0..=380 {
            let s0 = lo + (hi - lo) * i as f64 / 380.0;
            if vertical(s0, sign).0 < vertical(s_best, sign).0 {
                s_best = s0;
            }
        }
        lo = s_best - 0.5;
        hi = s_best + 0.5;
        let golden = 0.5 * (5f64.sqrt() - 1.0);
        for _ in 0..60 {
            let (a, b) = (hi - golden * (hi - lo), lo + golden * (hi - lo));
            if vertical(a, sign).0 < vertical(b, sign).0 {
                hi = b;
            } else {
                lo = a;
            }
        }
        let s0 = 0.5 * (lo + hi);
        let offset = vertical(s0, sign).1;
        let curve: Vec<(f64, f64)> = (0..=2000)
            .map(|i| {
                let s = s_min + (s_max - s_min) * i as f64 / 2000.0;
                (s, sign * (k * (s - s0)).cosh() / k + offset)
            })
            .collect();
        best = best.min(hausdorff_2d(points, &curve));
    }
    best
}

fn segment_distance(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let length2 = dx * dx + dy * dy;
    let t = if length2 > 0.0 { (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / length2).clamp(0.0, 1.0) } else { 0.0 };
    ((p.0 - a.0 - t * dx).powi(2) + (p.1 - a.1 - t * dy).powi(2)).sqrt()
}

/// Symmetric Hausdorff distance between two 2D polylines (vertices to the other polyline).
pub fn hausdorff_2d(a: &[(f64, f64)], b: &[(f64, f64)]) -> f64 {
    let one_sided = |from: &[(f64, f64)], to: &[(f64, f64)]| {
        from.iter()
            .map(|&p| to.windows(2).map(|w| segment_distance(p, w[0], w[1])).fold(f64::INFINITY, f64::min))
            .fold(0.0, f64::max)
    };
    one_sided(a, b).max(one_sided(b, a))
}
