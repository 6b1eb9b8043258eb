//! One iteration of the base-mesh optimisation (Sec. 3.5) of a PP net, plain and with
//! torsion-free nodes (Eq. 21), at the sizes of the paper's Table 3 (Fig. 1: 933 vertices,
//! 0.14 s per iteration; Fig. 23: 584 vertices, 0.063 s; on the authors' Xeon). The net: the
//! crossings of the heights `x + y` and `x − y` on the hall roof (the time of an iteration does
//! not depend on how good the net is), θ = 60° for both families. Each sample is a fresh solver
//! (its construction not timed) stepped `step(0)` once (the report each `step` ends with: each
//! family's angles, the deviation, the strips fitted at every node) and then `step(1)` ten times
//! (an iteration with its closest points on the reference, and the report), every call timed on
//! its own; the table gives the medians over all samples of both, and an iteration alone as
//! their difference. From a fresh start each sample: the iterations of a real solve (near a
//! minimum, with no convergence test, the damping would reject step after step).
//! With torsion-free nodes their rows are on from the first iteration (`families_first` off).
//! Then 3-webs (PPG: θ = 60°, 60°, geodesic diagonals) of the same heights and their diagonals
//! (`web_levels`, `extract_web`; the third field `−(x + y) − (x − y)`), at about the sizes of
//! Table 3's webs (Fig. 28, AAG: 616 vertices, 0.053 s; Fig. 1: 933, 0.14 s).
//!
//! Run: `cargo bench --bench base_mesh_iteration`.

mod support;

use lamella::base_mesh::{BaseMeshParams, BaseMeshSolver, NetMesh};
use lamella::field::Family;
use lamella::net::{extract_quad_net, extract_web, web_levels};
use std::time::Instant;
use support::roof;

/// Fresh solvers per row.
const SAMPLES: usize = 11;
/// `step(1)` calls timed per solver.
const STEPS: usize = 10;

/// The median of `times` (seconds).
fn median(mut times: Vec<f64>) -> f64 {
    times.sort_by(f64::total_cmp);
    times[times.len() / 2]
}

/// The wall time of `f` in seconds, and its result.
fn timed<T>(f: impl FnOnce() -> T) -> (f64, T) {
    let started = Instant::now();
    let value = f();
    (started.elapsed().as_secs_f64(), value)
}

fn main() {
    let mesh = roof(3_000);
    let f: Vec<f64> = mesh.positions().iter().map(|p| p.x + p.y).collect();
    let g: Vec<f64> = mesh.positions().iter().map(|p| p.x - p.y).collect();
    let theta = Family::PseudoGeodesic { theta_degrees: 60.0 };
    println!("| net | vertices | one step(1) | its report (step(0)) | the iteration alone | paper (Table 3) |");
    println!("|---|---:|---:|---:|---:|---:|");
    let h: Vec<f64> = f.iter().zip(&g).map(|(a, b)| -a - b).collect();
    let nets = [(35, "0.063 s (Fig. 23, 584 v)"), (44, "0.14 s (Fig. 1, 933 v)")].map(|(levels, paper)| {
        (NetMesh::from_quad_net(&extract_quad_net(&mesh, &f, &g, [levels, levels]).expect("a net")).expect("a valid net"), paper)
    });
    let webs = [(34, "0.053 s (Fig. 28, AAG, 616 v)"), (43, "0.14 s (Fig. 1, PPG, 933 v)")].map(|(levels, paper)| {
        let levels = web_levels(&mesh, &f, &g, &h, [levels, levels], false).expect("levels");
        (NetMesh::from_web(&extract_web(&mesh, &f, &g, levels)).expect("a valid web"), paper)
    });
    for (net, paper) in nets.iter().chain(&webs) {
        let web = net.family_count() == 3;
        for torsion_free in [false, true].into_iter().filter(|&t| !(t && web)) {
            let mut params = if web { BaseMeshParams::web(theta, theta, Family::Geodesic) } else { BaseMeshParams::new(theta, theta) };
            params.torsion_free = torsion_free;
            // With torsion-free nodes, their rows from the first iteration on.
            params.families_first = false;
            let (mut reports, mut steps) = (Vec::new(), Vec::new());
            for _ in 0..SAMPLES {
                let mut solver = BaseMeshSolver::new(net, &mesh, params.clone()).expect("valid input");
                reports.push(timed(|| solver.step(0).expect("solver runs")).0);
                for _ in 0..STEPS {
                    let (seconds, report) = timed(|| solver.step(1).expect("solver runs"));
                    assert_eq!(report.step_iterations, 1, "a sample converged early");
                    steps.push(seconds);
                }
            }
            let (report, step) = (median(reports), median(steps));
            let alone = (step - report).max(0.0);
            let kind = if web { "PPG web" } else if torsion_free { "PP net, torsion-free" } else { "PP net" };
            println!("| {kind} | {} | {:.2} ms | {:.2} ms | {:.2} ms | {paper} |", net.vertex_count(), 1e3 * step, 1e3 * report, 1e3 * alone);
        }
    }
}
