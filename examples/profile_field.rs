use lamella::field::{FieldParams, FieldSolver};
use std::time::{Duration, Instant};

/// Milliseconds per iteration on the 2,970-vertex hall roof from the state after 30 iterations,
/// restored from a saved session before every 5 iterations (the restore is included, amortised
/// over the 5), then the same split into restore and iterations.
fn main() {
    let mesh = lamella::surfaces::hall_roof(3000).into_mesh().unwrap();
    let initial: Vec<f64> = mesh.positions().iter().map(|p| p.x).collect();
    let mut s = FieldSolver::new(&mesh, &initial, FieldParams::pseudo_geodesic(60.0)).unwrap();
    s.step(30).unwrap();
    let snap = s.to_bytes();
    let (mut restoring, mut stepping) = (Duration::ZERO, Duration::ZERO);
    let t = Instant::now();
    let mut its = 0;
    for _ in 0..40 {
        let r = Instant::now();
        let mut s = FieldSolver::from_bytes(&snap).unwrap();
        restoring += r.elapsed();
        let r = Instant::now();
        s.step(5).unwrap();
        stepping += r.elapsed();
        its += 5;
    }
    eprintln!("{:.2} ms/it (incl. restore)", t.elapsed().as_secs_f64() * 1e3 / its as f64);
    eprintln!(
        "  restore {:.2} ms each, step {:.2} ms/it",
        restoring.as_secs_f64() * 1e3 / 40.0,
        stepping.as_secs_f64() * 1e3 / its as f64
    );
}
