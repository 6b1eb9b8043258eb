//! The conformal parameterisation of the initialisation (LSCM, Sec. 3.2.2): a similarity on a
//! planar mesh, an isometry up to scale on a developable one.

use crate::initialisation_support;

use initialisation_support::{cylinder, development};
use lamella::initialisation::conformal_map;
use lamella::surfaces::{planar_disk, PlanarPatch};

#[test]
fn planar_mesh_is_reproduced_up_to_a_similarity() {
    let patch = PlanarPatch { radius: 5.0, target_vertices: 900, irregularity: 0.4, seed: 2 };
    let mesh = planar_disk(&patch).expect("valid disk").into_mesh().expect("valid mesh");
    let map = conformal_map(&mesh).expect("LSCM");
    // Least-squares fit of w = a z + b (complex numbers z = x + i y, w = u + i v), then the residual.
    let n = mesh.vertex_count() as f64;
    let z: Vec<(f64, f64)> = mesh.positions().iter().map(|p| (p.x, p.y)).collect();
    let w: Vec<(f64, f64)> = map.iter().map(|m| (m[0], m[1])).collect();
    let mean = |v: &[(f64, f64)]| v.iter().fold((0.0, 0.0), |s, p| (s.0 + p.0 / n, s.1 + p.1 / n));
    let (zm, wm) = (mean(&z), mean(&w));
    // a = Σ conj(z − z̄)(w − w̄) / Σ |z − z̄|².
    let (mut num, mut den) = ((0.0, 0.0), 0.0);
    for (p, q) in z.iter().zip(&w) {
        let (dz, dw) = ((p.0 - zm.0, p.1 - zm.1), (q.0 - wm.0, q.1 - wm.1));
        num.0 += dz.0 * dw.0 + dz.1 * dw.1;
        num.1 += dz.0 * dw.1 - dz.1 * dw.0;
        den += dz.0 * dz.0 + dz.1 * dz.1;
    }
    let a = (num.0 / den, num.1 / den);
    let scale = (a.0 * a.0 + a.1 * a.1).sqrt();
    let worst = z
        .iter()
        .zip(&w)
        .map(|(p, q)| {
            let (dz, dw) = ((p.0 - zm.0, p.1 - zm.1), (q.0 - wm.0, q.1 - wm.1));
            let predicted = (a.0 * dz.0 - a.1 * dz.1, a.0 * dz.1 + a.1 * dz.0);
            ((predicted.0 - dw.0).powi(2) + (predicted.1 - dw.1).powi(2)).sqrt()
        })
        .fold(0.0, f64::max);
    // Relative to the image of the radius; an orientation-reversing map would not fit at all.
    assert!(worst <= 1e-9 * scale * patch.radius, "off a similarity by {worst} (scale {scale})");
}

#[test]
fn cylinder_patch_maps_isometrically_up_to_scale() {
    let mesh = cylinder(1500, 3);
    let map = conformal_map(&mesh).expect("LSCM");
    let ratios: Vec<f64> = mesh
        .edges()
        .iter()
        .map(|&[a, b]| {
            let (ma, mb) = (map[a as usize], map[b as usize]);
            let planar = ((mb[0] - ma[0]).powi(2) + (mb[1] - ma[1]).powi(2)).sqrt();
            // Against the developed length, which the chord of the mesh matches to ~1e-4.
            let (da, db) = (development(&mesh.positions()[a as usize]), development(&mesh.positions()[b as usize]));
            planar / ((db.0 - da.0).powi(2) + (db.1 - da.1).powi(2)).sqrt()
        })
        .collect();
    let mean = ratios.iter().sum::<f64>() / ratios.len() as f64;
    let spread = ratios.iter().map(|r| (r / mean - 1.0).abs()).fold(0.0, f64::max);
    eprintln!("edge length ratio: mean {mean:.6}, largest relative deviation {spread:.2e}");
    assert!(spread <= 1e-3, "edge length ratios vary by {spread}");
}
