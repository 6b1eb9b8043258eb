//! One iteration of the base-mesh optimisation (Sec. 3.5) of a PP net, plain and with
//! torsion-free nodes (Eq. 21), at the sizes of the paper's Table 3 (Fig. 1: 933 vertices,
//! 0.14 s per iteration; Fig. 23: 584 vertices, 0.063 s; on the authors' Xeon). The net: the
//! crossings of the heights `x + y` and `x − y` on the hall roof (the time of an iteration does
//! not depend on how good the net is), θ = 60° for both families. Two figures per size: an
//! iteration alone (the Levenberg–Marquardt iteration with the reference's closest points), and the report each `step` ends with (each family's angles, the deviation, the
//! strips fitted at every node). From fresh solvers: medians of `step(10)`, `step(0)` (the report
//! alone) and the construction, each from a fresh solver: an iteration is
//! `(step(10) − step(0)) / 10`, the report `step(0) − construction`.
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
use support::{median_seconds, roof};

const SAMPLES: usize = 11;

fn main() {
    let mesh = roof(3_000);
    let f: Vec<f64> = mesh.positions().iter().map(|p| p.x + p.y).collect();
    let g: Vec<f64> = mesh.positions().iter().map(|p| p.x - p.y).collect();
    let theta = Family::PseudoGeodesic { theta_degrees: 60.0 };
    println!("| net | vertices | one iteration | the report of a step | paper (Table 3) |");
    println!("|---|---:|---:|---:|---:|");
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
            // From a fresh start each sample: the iterations of a real solve (near a minimum,
            // with no convergence test, the damping would reject step after step).
            // With torsion-free nodes, their rows from the first iteration on.
            params.families_first = false;
            let fresh = || BaseMeshSolver::new(&net, &mesh, params.clone()).expect("valid input");
            let report = median_seconds(SAMPLES, || {
                fresh().step(0).expect("solver runs");
            });
            let mut ran = usize::MAX;
            let ten = median_seconds(SAMPLES, || {
                ran = ran.min(fresh().step(10).expect("solver runs").step_iterations);
            });
            assert_eq!(ran, 10, "a sample converged early");
            let construction = median_seconds(SAMPLES, || {
                fresh();
            });
            // Each timing includes the construction; `step(10)` and `step(0)` end with one report.
            let alone = (ten - report).max(0.0) / 10.0;
            let report = (report - construction).max(0.0);
            let kind = if web { "PPG web" } else if torsion_free { "PP net, torsion-free" } else { "PP net" };
            println!("| {kind} | {} | {:.2} ms | {:.2} ms | {paper} |", net.vertex_count(), 1e3 * alone, 1e3 * report);
        }
    }
}
