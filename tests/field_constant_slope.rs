//! Constant-slope families (paper Sec. 5.2.3, Eq. 22) on the vault z = h(1 − (x/a)²)(1 − (y/b)²):
//! the level curves' tangents keep the slope β against the planes orthogonal to the axis d
//! wherever the tangent planes are steep enough, measured on the extracted level curves against
//! the vault's exact normal.

use lamella::curves::{extract_level_curves, uniform_levels, LevelCurve};
use lamella::field::{slope_reachable, Family, FieldError, FieldParams, FieldSolver};
use lamella::initialisation::slope_start_field;
use lamella::mesh::{TriMesh, Vec3};
use lamella::surfaces::{vault, Vault};

const SURFACE: Vault = Vault { half_length: 5.0, half_width: 4.0, rise: 3.0, target_vertices: 1200, irregularity: 0.25, seed: 7 };

fn vault_mesh() -> TriMesh {
    let n: usize = std::env::var("NV").map(|v| v.parse().unwrap()).unwrap_or(1200);
    vault(&Vault { target_vertices: n, ..SURFACE }).expect("valid vault").into_mesh().expect("valid mesh")
}

/// The exact upward unit normal of the vault at (x, y).
fn vault_normal(p: &Vec3) -> Vec3 {
    let (a, b, h) = (SURFACE.half_length, SURFACE.half_width, SURFACE.rise);
    let (u, v) = (1.0 - (p.x / a).powi(2), 1.0 - (p.y / b).powi(2));
    Vec3::new(2.0 * h * p.x / (a * a) * v, 2.0 * h * p.y / (b * b) * u, 1.0).normalize()
}

/// Slope errors |asin|t·d| − |β|| in degrees at the inner points of the curves resampled every
/// `spacing` (tangent: the chord of the two neighbours), where the exact normal reaches β;
/// and the number of inner points that do not.
fn slope_errors(curves: &[LevelCurve], axis: &Vec3, slope: f64, spacing: f64) -> (Vec<f64>, usize) {
    let (mut errors, mut unreachable) = (Vec::new(), 0);
    let mut worst = (0.0, Vec3::zeros());
    for curve in curves {
        let points = curve.resampled(spacing).expect("valid spacing").points;
        for w in points.windows(3) {
            if !slope_reachable(&vault_normal(&w[1]), axis, slope) {
                unreachable += 1;
                continue;
            }
            let t = (w[2] - w[0]).normalize();
            errors.push((t.dot(axis).abs().asin().to_degrees() - slope.abs()).abs());
            if *errors.last().unwrap() > worst.0 { worst = (*errors.last().unwrap(), w[1]); }
        }
    }
    eprintln!("worst {worst:?}");
    (errors, unreachable)
}

fn max(values: &[f64]) -> f64 {
    values.iter().copied().fold(0.0, f64::max)
}

fn run(axis: [f64; 3], slope: f64, free: bool) -> (TriMesh, Vec<f64>, Vec<f64>, FieldSolver) {
    let mesh = vault_mesh();
    let start = slope_start_field(&mesh, axis, slope).expect("start");
    let family = Family::ConstantSlope { axis, slope_degrees: slope, free_slope: free };
    let mut solver = FieldSolver::new(&mesh, &start, FieldParams::new(family)).expect("valid input");
    let report = solver.step(300).expect("solver runs");
    eprintln!("{report:?}");
    let field = solver.field();
    (mesh, start, field, solver)
}

#[test]
fn explore() {
    for (axis, slope) in [([0.8f64, 0.0, 0.6], 30.0), ([1.0, 0.0, 0.0], 30.0)] {
        let (mesh, start, field, solver) = run(axis, slope, false);
        let d = Vec3::from(axis).normalize();
        let spacing = 3.0 * mesh.mean_edge_length();
        for (name, f) in [("start", &start), ("final", &field)] {
            let levels = uniform_levels(&mesh, f, 15).unwrap();
            let curves = extract_level_curves(&mesh, f, &levels).unwrap();
            let (errors, unreachable) = slope_errors(&curves, &d, slope, spacing);
            let rms = (errors.iter().map(|e| e * e).sum::<f64>() / errors.len() as f64).sqrt();
            eprintln!("{axis:?} {slope} {name}: curves {} measured {} unreachable {unreachable} max {:.3} rms {:.3}", curves.len(), errors.len(), max(&errors), rms);
        }
        eprintln!("slope {:?}", solver.slope_degrees());
    }
}
