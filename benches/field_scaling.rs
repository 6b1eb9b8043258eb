//! Whole solves of the pseudo-geodesic field on the hall roof at every benchmark size: wall time
//! from `FieldSolver::new` to convergence, iterations, mean time per iteration, the final accuracy
//! (the vertex-star measure the solver reports, and the angle error along 20 level curves against
//! the smooth surface normal, `quality::family_angles`) and the process's peak resident memory (sizes run in increasing order, so the peak after each
//! line belongs to that size). Every size is solved `RUNS` times (a fresh solver each time; the
//! median and the range are reported), the 50k one once: it takes seconds.
//!
//! Run: `cargo bench --bench field_scaling`.

mod support;

use lamella::curves::{extract_level_curves, uniform_levels};
use lamella::field::{FieldParams, FieldSolver};
use lamella::mesh::TriMesh;
use lamella::quality::family_angles;
use std::time::Instant;
use support::{roof, solver, ROOF_VERTICES};

/// RMS and max angle error (degrees) along 20 level curves of the solver's field, resampled every
/// 3 mean edge lengths, against the smooth surface normal.
fn curve_errors(mesh: &TriMesh, solver: &FieldSolver) -> (f64, f64) {
    let field = solver.field();
    let levels = uniform_levels(mesh, &field, 20).expect("levels");
    let curves = extract_level_curves(mesh, &field, &levels).expect("curves");
    let (low, high) = mesh.bounding_box();
    let family = FieldParams::pseudo_geodesic(60.0).family;
    let measure = family_angles(&curves, family, 3.0 * mesh.mean_edge_length(), (high - low).norm()).expect("measurable curves");
    (measure.rms_error_degrees, measure.max_error_degrees)
}

/// Peak resident set size of this process in MiB (Linux `VmHWM`), if known.
fn peak_memory_mib() -> Option<f64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    let kib: f64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kib / 1024.0)
}

/// Solves per size below 20,000 vertices.
const RUNS: usize = 7;

fn main() {
    // `cargo bench` passes `--bench`; a filter argument (as for criterion) is not supported.
    println!("| vertices | iterations | full solve (s) | per iteration (ms) | range (ms) | E_angle | star max error (°) | curves RMS / max error (°) | singular | peak RSS (MiB) |");
    println!("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    for vertices in ROOF_VERTICES {
        let mesh = roof(vertices);
        let runs = if vertices < 20_000 { RUNS } else { 1 };
        let mut timings = Vec::with_capacity(runs);
        let mut report = None;
        let mut curves = (f64::NAN, f64::NAN);
        for _ in 0..runs {
            let started = Instant::now();
            let mut s = solver(&mesh);
            let prepared = started.elapsed();
            let last = s.step(500).expect("solver runs");
            let total = started.elapsed();
            let per_iteration = (total - prepared).as_secs_f64() / last.iterations.max(1) as f64;
            timings.push((per_iteration, total.as_secs_f64()));
            report = Some(last);
            curves = curve_errors(&mesh, &s);
        }
        let report = report.expect("at least one run");
        timings.sort_by(|a, b| a.0.total_cmp(&b.0));
        let (per_iteration, total) = timings[timings.len() / 2];
        println!(
            "| {} | {} | {:.2} | {:.1} | {:.1}–{:.1} | {:.1e} | {:.3} | {:.2} / {:.2} | {} | {:.0} |",
            mesh.vertex_count(),
            report.iterations,
            total,
            per_iteration * 1e3,
            timings[0].0 * 1e3,
            timings[timings.len() - 1].0 * 1e3,
            report.energies.angle,
            report.angle_error_max_degrees,
            curves.0,
            curves.1,
            report.singular_vertices.len(),
            peak_memory_mib().unwrap_or(f64::NAN)
        );
    }
}
