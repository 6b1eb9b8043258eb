//! One iteration of the surface optimisation (Sec. 3.3) as `ReshapeSolver::step(1)` runs it,
//! report included (the mesh rebuilt, normals, fairness operator and closest points recomputed),
//! on the hall roof at the size of the paper's Fig. 17 (1,073 vertices, 0.24 s per iteration on
//! the authors' Xeon, Table 3, weights 0.02 / 2e-3 / 3e-4 / 30) and at 3,000 vertices. Field:
//! the height along the hall (the time of an iteration hardly depends on it); θ = 45°, tolerance
//! 10 % of the diagonal; 10 warm-up iterations, then the median of `SAMPLES` single steps.
//!
//! Run: `cargo bench --bench reshape_iteration`.

mod support;

use lamella::reshape::{ReshapeParams, ReshapeSolver, Tolerance};
use support::{median_seconds, roof};

const SAMPLES: usize = 21;

fn main() {
    println!("| vertices | time per `step(1)` (median of {SAMPLES}) | paper (Table 3) |");
    println!("|---:|---:|---:|");
    for (vertices, paper) in [(1_073, "0.24 s (Fig. 17(b), 1,073 vertices)"), (3_000, "")] {
        let mesh = roof(vertices);
        let field: Vec<f64> = mesh.positions().iter().map(|p| p.x + 0.3 * p.y).collect();
        let mut params = ReshapeParams::new(45.0);
        params.tolerance = Tolerance::DiagonalFraction(0.1);
        // No convergence test: every sample runs one iteration.
        params.relative_tolerance = 0.0;
        params.lm.gradient_tolerance = 0.0;
        params.lm.step_tolerance = 0.0;
        let mut solver = ReshapeSolver::new(&mesh, &field, params).expect("valid input");
        solver.step(10).expect("solver runs");
        let before = solver.iterations();
        let median = median_seconds(SAMPLES, || {
            solver.step(1).expect("solver runs");
        });
        assert_eq!(solver.iterations(), before + SAMPLES, "every sample ran an iteration");
        println!("| {} | {:.1} ms | {paper} |", mesh.vertex_count(), 1e3 * median);
    }
}
