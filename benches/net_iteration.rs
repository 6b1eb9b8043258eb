//! One iteration of a PP net (two θ = 60° fields, Sec. 4.1) and of a PPG 3-web (θ = 60°, 60°
//! and geodesics, Sec. 4.2) as `NetSolver::step(1)` runs it, report included, on the hall roof at
//! the sizes of the paper's Fig. 23 (1,394 vertices, PP, 0.088 s per iteration on the authors'
//! Xeon, Table 2) and Fig. 1 (3,021 vertices, three fields, 0.54 s). Starts: the heights along
//! the two diagonals of the hall (the time of an iteration does not depend on the start; a web's
//! third field is −F − H); 10 warm-up iterations, then the median of `SAMPLES` single steps.
//!
//! Run: `cargo bench --bench net_iteration`.

mod support;

use lamella::field::Family;
use lamella::net::{NetParams, NetSolver};
use support::{median_seconds, roof};

const SAMPLES: usize = 21;

fn main() {
    println!("| fields | vertices | time per `step(1)` (median of {SAMPLES}) | paper (Table 2) |");
    println!("|---|---:|---:|---:|");
    let theta = Family::PseudoGeodesic { theta_degrees: 60.0 };
    let cases = [
        (1_394, NetParams::new(theta, theta), "0.088 s (Fig. 23, PP)"),
        (3_000, NetParams::new(theta, theta), ""),
        (1_394, NetParams::web(theta, theta, Family::Geodesic), ""),
        (3_021, NetParams::web(theta, theta, Family::Geodesic), "0.54 s (Fig. 1, three fields)"),
    ];
    for (vertices, mut params, paper) in cases {
        let mesh = roof(vertices);
        let f: Vec<f64> = mesh.positions().iter().map(|p| p.x + p.y).collect();
        let g: Vec<f64> = mesh.positions().iter().map(|p| p.x - p.y).collect();
        // No convergence test: every sample runs one iteration.
        params.field.relative_tolerance = 0.0;
        params.field.schedule.clear();
        let mut solver = NetSolver::new(&mesh, &[f, g], params.clone()).expect("valid input");
        solver.step(10).expect("solver runs");
        let median = median_seconds(SAMPLES, || {
            solver.step(1).expect("solver runs");
        });
        let kind = if params.is_web() { "PPG web" } else { "PP net" };
        println!("| {kind} | {} | {:.1} ms | {paper} |", mesh.vertex_count(), 1e3 * median);
    }
}
