//! The default design (issue 12: under 2 s at about 3,000 vertices) on eight analytic surfaces at
//! four angles: what `lamella design --mesh M.obj --theta T` does without a start option, minus
//! the files and minus the reshape trial a failing design adds (the start search, the winner's
//! solve to convergence, 20 level curves resampled at the mean edge and their rectifying strips of
//! half the curves' spacing). The surfaces are none of the library's generators: a saddle
//! `z = (x² − y²)/10`, an elliptic paraboloid, a wave `z = 0.8 sin(x/2) cos(y/3)`, a patch of a
//! torus (radii 6 and 2) on its outer side, a cylinder of radius 5, a monkey saddle
//! `z = (x³ − 3xy²)/25`, a helicoid and a patch of a sphere of radius 8, each meshed by a
//! 55 × 55 grid (3,025 vertices) jittered by up to 22 % of a cell in each parameter, cells split
//! along the shorter diagonal. θ = 30°, 45°, 60°, 80°; one run each.
//!
//! Columns: the verdict (acceptable: every strip plane within 2° of θ, no flipped quad), the
//! phases' wall times, the field's iterations on the mesh after the search, the level curves'
//! angle error from outside (RMS and max, `quality::family_angles`, every three mean edges) and
//! the strip planes' largest error.
//!
//! Run: `cargo bench --bench unseen_surfaces`.

mod support;

use lamella::field::Family;
use lamella::mesh::{TriMesh, Vec3};
use lamella::quality::family_angles;
use lamella::surfaces::SplitMix64;
use support::default_design;

/// Grid points per side.
const GRID: usize = 55;
/// Jitter of the inner grid points, as a fraction of a cell on either side.
const JITTER: f64 = 0.22;

type Surface = fn(f64, f64) -> Vec3;

/// The surfaces: name, map of the parameter rectangle, and the rectangle `[u0, u1] × [v0, v1]`.
const SURFACES: [(&str, Surface, [f64; 4]); 8] = [
    ("saddle", |u, v| Vec3::new(u, v, (u * u - v * v) / 10.0), [-5.0, 5.0, -5.0, 5.0]),
    ("paraboloid", |u, v| Vec3::new(u, v, -(u * u + v * v) / 12.0), [-5.0, 5.0, -5.0, 5.0]),
    ("wave", |u, v| Vec3::new(u, v, 0.8 * (u / 2.0).sin() * (v / 3.0).cos()), [-6.0, 6.0, -5.0, 5.0]),
    ("torus", |u, v| Vec3::new((6.0 + 2.0 * v.cos()) * u.cos(), (6.0 + 2.0 * v.cos()) * u.sin(), 2.0 * v.sin()), [-0.8, 0.8, -1.2, 1.2]),
    ("cylinder", |u, v| Vec3::new(5.0 * u.cos(), 5.0 * u.sin(), v), [-1.0, 1.0, 0.0, 8.0]),
    ("monkey saddle", |u, v| Vec3::new(u, v, (u * u * u - 3.0 * u * v * v) / 25.0), [-4.0, 4.0, -4.0, 4.0]),
    ("helicoid", |u, v| Vec3::new(u * v.cos(), u * v.sin(), 1.5 * v), [1.0, 5.0, -1.2, 1.2]),
    ("sphere", |u, v| Vec3::new(8.0 * v.cos() * u.cos(), 8.0 * v.cos() * u.sin(), 8.0 * v.sin()), [-0.6, 0.6, -0.5, 0.5]),
];

/// The jittered grid of `surface` over `[u0, u1] × [v0, v1]`.
fn mesh(surface: Surface, [u0, u1, v0, v1]: [f64; 4], seed: u64) -> TriMesh {
    let mut rng = SplitMix64::new(seed);
    let (du, dv) = ((u1 - u0) / (GRID - 1) as f64, (v1 - v0) / (GRID - 1) as f64);
    let mut positions = Vec::with_capacity(GRID * GRID);
    for j in 0..GRID {
        for i in 0..GRID {
            let inner = |k: usize| k > 0 && k < GRID - 1;
            let u = u0 + i as f64 * du + if inner(i) { rng.symmetric(JITTER * du) } else { 0.0 };
            let v = v0 + j as f64 * dv + if inner(j) { rng.symmetric(JITTER * dv) } else { 0.0 };
            positions.push(surface(u, v));
        }
    }
    let mut faces = Vec::with_capacity(2 * (GRID - 1) * (GRID - 1));
    for j in 0..GRID - 1 {
        for i in 0..GRID - 1 {
            let (a, b) = ((j * GRID + i) as u32, (j * GRID + i + 1) as u32);
            let (d, c) = (a + GRID as u32, b + GRID as u32);
            let length = |p: u32, q: u32| (positions[p as usize] - positions[q as usize]).norm();
            if length(a, c) <= length(b, d) {
                faces.extend([[a, b, c], [a, c, d]]);
            } else {
                faces.extend([[a, b, d], [b, c, d]]);
            }
        }
    }
    TriMesh::from_vertices_and_faces(positions, faces).expect("a valid grid mesh")
}

fn main() {
    println!("| surface | θ | verdict | search (s) | solve (s) | iterations | strips (s) | total (s) | curves RMS / max (°) | strip planes max (°) |");
    println!("|---|---:|---|---:|---:|---:|---:|---:|---:|---:|");
    let mut totals = Vec::new();
    for (seed, &(name, surface, rectangle)) in SURFACES.iter().enumerate() {
        let mesh = mesh(surface, rectangle, seed as u64 + 1);
        let (low, high) = mesh.bounding_box();
        for theta in [30.0, 45.0, 60.0, 80.0] {
            let run = default_design(&mesh, theta, None);
            let angles = family_angles(&run.curves, Family::PseudoGeodesic { theta_degrees: theta }, 3.0 * mesh.mean_edge_length(), (high - low).norm()).expect("measured");
            let total = run.search + run.solve + run.strips;
            let acceptable = run.pattern.verdict.is_acceptable();
            println!(
                "| {name} | {theta:.0}° | {} | {:.2} | {:.2} | {} | {:.2} | {total:.2} | {:.2} / {:.2} | {:.2} |",
                if acceptable { "acceptable" } else { "misses θ" },
                run.search,
                run.solve,
                run.report.iterations,
                run.strips,
                angles.rms_error_degrees,
                angles.max_error_degrees,
                run.pattern.metrics.max_quad_angle_error_degrees,
            );
            totals.push((acceptable, total));
        }
    }
    let acceptable: Vec<f64> = totals.iter().filter(|t| t.0).map(|t| t.1).collect();
    let over = acceptable.iter().filter(|&&t| t > 2.0).count();
    println!(
        "\n{} of {} designs acceptable; of those, {over} over 2 s (longest {:.2} s, summed {:.1} s)",
        acceptable.len(),
        totals.len(),
        acceptable.iter().fold(0.0f64, |m, &t| m.max(t)),
        acceptable.iter().sum::<f64>()
    );
}
