//! The default design as `lamella design` runs it, without the files: the start search (short
//! solves from several starts), the winner's solve to convergence, 20 level curves and their
//! rectifying strips, on the hall roof at 3,000, 10,000 and 50,000 vertices (the larger two
//! searched on a 3,000-vertex coarsening). Each size is run `RUNS` times; the table gives the
//! median of each phase and of the whole.
//!
//! Run: `cargo bench --bench default_design`.

mod support;

use lamella::curves::{extract_level_curves, uniform_levels, LevelCurve};
use lamella::field::FieldParams;
use lamella::initialisation::{search_start, SearchOptions};
use lamella::strips::{rectifying_strips, StripParams};
use std::time::Instant;
use support::roof;

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
        let (mut candidates, mut iterations, mut error, mut searched_on) = (0, 0, 0.0, 0);
        for _ in 0..RUNS {
            let started = Instant::now();
            let outcome = search_start(&mesh, FieldParams::pseudo_geodesic(60.0), SearchOptions::default()).expect("a start");
            let searched = started.elapsed().as_secs_f64();
            let mut solver = outcome.solver;
            let report = solver.step(400).expect("solver runs");
            let solved = started.elapsed().as_secs_f64();
            let field = solver.field();
            let levels = uniform_levels(&mesh, &field, 20).expect("levels");
            let curves: Vec<LevelCurve> = extract_level_curves(&mesh, &field, &levels)
                .expect("curves")
                .iter()
                .map(|c| c.resampled(mesh.mean_edge_length()).expect("resampled"))
                .collect();
            let pattern = rectifying_strips(&mesh, &curves, &StripParams::new(60.0, 0.9)).expect("strips");
            let finished = started.elapsed().as_secs_f64();
            search.push(searched);
            solve.push(solved - searched);
            strips.push(finished - solved);
            total.push(finished);
            candidates = outcome.candidates.len();
            searched_on = outcome.proxy_vertices.unwrap_or(mesh.vertex_count());
            iterations = report.iterations;
            error = pattern.metrics.max_quad_angle_error_degrees;
        }
        println!(
            "| {} | {searched_on} | {candidates} | {:.2} | {:.2} | {iterations} | {:.2} | {:.2} | {error:.2} |",
            mesh.vertex_count(),
            median(&mut search),
            median(&mut solve),
            median(&mut strips),
            median(&mut total)
        );
    }
}
