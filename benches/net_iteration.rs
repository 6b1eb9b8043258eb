//! One iteration of a PP net (two θ = 60° fields, Sec. 4.1) as `NetSolver::step(1)` runs it,
//! report included, on the hall roof at the size of the paper's Fig. 23 (1,394 vertices, 0.088 s
//! per iteration on the authors' Xeon, Table 2) and at 3,000 vertices. Starts: the heights along
//! and across the hall (the time of an iteration does not depend on the start); 10 warm-up
//! iterations, then the median of `SAMPLES` single steps.
//!
//! Run: `cargo bench --bench net_iteration`.

mod support;

use lamella::field::Family;
use lamella::net::{NetParams, NetSolver};
use support::{median_seconds, roof};

const SAMPLES: usize = 21;

fn main() {
    println!("| vertices | time per `step(1)` (median of {SAMPLES}) | paper (Table 2) |");
    println!("|---:|---:|---:|");
    for (vertices, paper) in [(1_394, "0.088 s (Fig. 23)"), (3_000, "")] {
        let mesh = roof(vertices);
        let f: Vec<f64> = mesh.positions().iter().map(|p| p.x + p.y).collect();
        let g: Vec<f64> = mesh.positions().iter().map(|p| p.x - p.y).collect();
        let theta = Family::PseudoGeodesic { theta_degrees: 60.0 };
        let mut params = NetParams::new(theta, theta);
        // No convergence test: every sample runs one iteration.
        params.field.relative_tolerance = 0.0;
        params.field.schedule.clear();
        let mut solver = NetSolver::new(&mesh, &[f, g], params).expect("valid input");
        solver.step(10).expect("solver runs");
        let median = median_seconds(SAMPLES, || {
            solver.step(1).expect("solver runs");
        });
        println!("| {} | {:.1} ms | {paper} |", mesh.vertex_count(), 1e3 * median);
    }
}
