//! The default design as `lamella design` runs it, without the files: the start search (short
//! solves from several starts), the winner's solve to convergence, 20 level curves and their
//! rectifying strips, on the hall roof at 3,000, 10,000 and 50,000 vertices (the larger two
//! searched on a 1,500-vertex coarsening). Each size is run `RUNS` times; the table gives the
//! median of each phase and of the whole.
//!
//! Run: `cargo bench --bench default_design`.

mod support;

use support::{default_design, roof};

const RUNS: usize = 5;

fn median(values: &mut [f64]) -> f64 {
    values.sort_by(f64::total_cmp);
    values[values.len() / 2]
}

fn main() {
    println!("| vertices | searched on | candidates | search (s) | solve (s) | iterations | strips (s) | total (s) | strip planes max error (°) |");
    println!("|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    for vertices in [3_000, 10_000, 50_000] {
        let mesh = roof(vertices);
        let (mut search, mut solve, mut strips, mut total) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
        let mut last = None;
        for _ in 0..RUNS {
            let run = default_design(&mesh, 60.0, Some(0.9));
            search.push(run.search);
            solve.push(run.solve);
            strips.push(run.strips);
            total.push(run.search + run.solve + run.strips);
            last = Some(run);
        }
        let run = last.expect("at least one run");
        println!(
            "| {} | {} | {} | {:.2} | {:.2} | {} | {:.2} | {:.2} | {:.2} |",
            mesh.vertex_count(),
            run.searched_on,
            run.candidates,
            median(&mut search),
            median(&mut solve),
            run.report.iterations,
            median(&mut strips),
            median(&mut total),
            run.pattern.metrics.max_quad_angle_error_degrees
        );
    }
}
