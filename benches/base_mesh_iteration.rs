//! One iteration of the base-mesh optimisation (Sec. 3.5), on the cases of the paper's Table 3
//! ("quad/triangle mesh optimization statistics"; authors' Xeon), each at its size and with its
//! families:
//!
//! | Table 3 | net | vertices | T / iter |
//! |---|---|---:|---:|
//! | Fig. 1 | PPG web (θ 45°, 60°, geodesic diagonals) | 933 | 0.14 s |
//! | Fig. 23 | PP net (θ 30°, 60°) | 584 | 0.063 s |
//! | Fig. 28 | AAG web | 616 | 0.053 s |
//! | Fig. 30(a₁) | GGA web | 394 | 0.053 s |
//!
//! The nets are made from level sets as `lamella net` makes them: the P and G families on the
//! hall roof, from the heights `x + y`, `x − y` (and `−(x + y) − (x − y)` for a web's third field);
//! the AAG web on the hyperbolic paraboloid `z = xy/5`, whose asymptotic curves are the heights
//! `x` and `y` (the time of an iteration does not depend on how good the net is). Then the PP net
//! with torsion-free nodes (Eq. 21), which Table 3 does not have, at the sizes of Fig. 23 and
//! Fig. 1. Each sample is a fresh solver (its construction not timed) stepped `step(0)` once (the
//! report each `step` ends with: each family's angles, the deviation, the strips fitted at every
//! node) and then `step(1)` ten times (an iteration with its closest points on the reference, and
//! the report), every call timed on its own; the table gives the medians over all samples of both,
//! and an iteration alone as their difference. From a fresh start each sample: the iterations of a
//! real solve (near a minimum, with no convergence test, the damping would reject step after
//! step). With torsion-free nodes their rows are on from the first iteration (`families_first`
//! off).
//!
//! Run: `cargo bench --bench base_mesh_iteration`.

mod support;

use lamella::base_mesh::{BaseMeshParams, BaseMeshSolver, NetMesh};
use lamella::field::Family;
use lamella::mesh::TriMesh;
use lamella::net::{extract_quad_net, extract_web, web_levels};
use lamella::surfaces::{hyperbolic_paraboloid, HyperbolicParaboloid};
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

/// The quad net of the level sets of `f` and `g` with `levels` levels each.
fn quad_net(mesh: &TriMesh, f: &[f64], g: &[f64], levels: usize) -> NetMesh {
    NetMesh::from_quad_net(&extract_quad_net(mesh, f, g, [levels, levels]).expect("a net")).expect("a valid net")
}

/// The 3-web of the level sets of `f`, `g` and `−f − g` with `levels` levels of `f` and `g`.
fn web(mesh: &TriMesh, f: &[f64], g: &[f64], levels: usize) -> NetMesh {
    let h: Vec<f64> = f.iter().zip(g).map(|(a, b)| -a - b).collect();
    let levels = web_levels(mesh, f, g, &h, [levels, levels], false).expect("levels");
    NetMesh::from_web(&extract_web(mesh, f, g, levels)).expect("a valid web")
}

/// One row of the table: `net` on `surface` with `params`.
fn row(kind: &str, net: &NetMesh, surface: &TriMesh, params: &BaseMeshParams, paper: &str) {
    let (mut reports, mut steps) = (Vec::new(), Vec::new());
    for _ in 0..SAMPLES {
        let mut solver = BaseMeshSolver::new(net, surface, params.clone()).expect("valid input");
        reports.push(timed(|| solver.step(0).expect("solver runs")).0);
        for _ in 0..STEPS {
            let (seconds, report) = timed(|| solver.step(1).expect("solver runs"));
            assert_eq!(report.step_iterations, 1, "a sample converged early");
            steps.push(seconds);
        }
    }
    let (report, step) = (median(reports), median(steps));
    let alone = (step - report).max(0.0);
    println!("| {kind} | {} | {:.2} ms | {:.2} ms | {:.2} ms | {paper} |", net.vertex_count(), 1e3 * step, 1e3 * report, 1e3 * alone);
}

fn main() {
    let p = |theta_degrees| Family::PseudoGeodesic { theta_degrees };
    let (a, g) = (Family::Asymptotic, Family::Geodesic);
    let roof = roof(3_000);
    let diagonal: Vec<f64> = roof.positions().iter().map(|q| q.x + q.y).collect();
    let anti: Vec<f64> = roof.positions().iter().map(|q| q.x - q.y).collect();
    let hypar = hyperbolic_paraboloid(&HyperbolicParaboloid { c: 5.0, half_width: 5.0, target_vertices: 3_000, irregularity: 0.3, seed: 7 })
        .expect("a surface")
        .into_mesh()
        .expect("a valid mesh");
    let x: Vec<f64> = hypar.positions().iter().map(|q| q.x).collect();
    let y: Vec<f64> = hypar.positions().iter().map(|q| q.y).collect();

    println!("| net | vertices | one step(1) | its report (step(0)) | the iteration alone | paper (Table 3) |");
    println!("|---|---:|---:|---:|---:|---:|");
    let fig_1 = web(&roof, &diagonal, &anti, 45);
    row("PPG web (45°, 60°, G)", &fig_1, &roof, &BaseMeshParams::web(p(45.0), p(60.0), g), "0.14 s (Fig. 1, PPG, 933 v)");
    let fig_23 = quad_net(&roof, &diagonal, &anti, 35);
    row("PP net (30°, 60°)", &fig_23, &roof, &BaseMeshParams::new(p(30.0), p(60.0)), "0.063 s (Fig. 23, PP, 584 v)");
    let fig_28 = web(&hypar, &x, &y, 25);
    row("AAG web", &fig_28, &hypar, &BaseMeshParams::web(a, a, g), "0.053 s (Fig. 28, AAG, 616 v)");
    let fig_30 = web(&roof, &diagonal, &anti, 29);
    row("GGA web", &fig_30, &roof, &BaseMeshParams::web(g, g, a), "0.053 s (Fig. 30(a₁), GGA, 394 v)");
    for net in [&fig_23, &quad_net(&roof, &diagonal, &anti, 44)] {
        let mut params = BaseMeshParams::new(p(60.0), p(60.0));
        params.torsion_free = true;
        // With torsion-free nodes, their rows from the first iteration on.
        params.families_first = false;
        row("PP net (60°, 60°), torsion-free", net, &roof, &params, "(no torsion-free row in Table 3)");
    }
}
