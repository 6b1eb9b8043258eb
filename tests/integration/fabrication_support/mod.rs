//! Analytic strips for the fabrication tests: rectifying strips of helices (their rulings along
//! the Darboux vector `τ t + κ b`, so they unroll straight), with known curvature and torsion.
#![allow(dead_code)]

use lamella::fabrication::{FabricationParams, FabricationStrip, Material, Stock};
use lamella::mesh::Vec3;

/// The helix `(r cos u, r sin u, h u)` for `u ∈ [0, turn]` sampled at `samples + 1` points, as a
/// strip of width `width` named `name`.
pub fn helix_strip(name: &str, r: f64, h: f64, turn: f64, samples: usize, width: f64) -> FabricationStrip {
    let q = r * r + h * h;
    let u = |i: usize| turn * i as f64 / samples as f64;
    let centre = (0..=samples).map(|i| Vec3::new(r * u(i).cos(), r * u(i).sin(), h * u(i))).collect();
    let offsets = (0..=samples)
        .map(|i| {
            let t = Vec3::new(-r * u(i).sin(), r * u(i).cos(), h) / q.sqrt();
            let b = Vec3::new(h * u(i).sin(), -h * u(i).cos(), r) / q.sqrt();
            let darboux = (t * h + b * r).normalize();
            // Half-ruling whose component across the centre line is width / 2.
            darboux * (0.5 * width / t.cross(&darboux).norm())
        })
        .collect();
    FabricationStrip { name: name.to_string(), centre, offsets, nodes: vec![], theta_degrees: None }
}

/// The helix's centre-line length `turn √(r² + h²)`.
pub fn helix_length(r: f64, h: f64, turn: f64) -> f64 {
    turn * (r * r + h * h).sqrt()
}

/// Four strips, 3 m to 13 m long, of widths 0.12 m to 0.2 m.
pub fn helix_pattern() -> Vec<FabricationStrip> {
    vec![
        helix_strip("strip_0", 6.0, 0.4, 0.5, 60, 0.12),
        helix_strip("strip_1", 8.0, 0.3, 1.6, 200, 0.15),
        helix_strip("strip_2", 12.0, 0.5, 0.9, 150, 0.2),
        helix_strip("strip_3", 5.0, 1.0, 1.2, 120, 0.16),
    ]
}

/// Timber 6 mm, 4.8 m boards with 0.3 m splices and 10 mm gaps.
pub fn timber_params() -> FabricationParams {
    FabricationParams { material: Material::preset("timber").expect("preset"), thickness: 0.006, stock: Stock::boards(4.8), theta_degrees: Some(90.0) }
}
