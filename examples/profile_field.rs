use lamella::field::{FieldParams, FieldSolver};
fn main() {
    let mesh = lamella::surfaces::hall_roof(3000).into_mesh().unwrap();
    let initial: Vec<f64> = mesh.positions().iter().map(|p| p.x).collect();
    let mut s = FieldSolver::new(&mesh, &initial, FieldParams::pseudo_geodesic(60.0)).unwrap();
    s.step(30).unwrap();
    let snap = s.to_bytes();
    let t = std::time::Instant::now();
    let mut its = 0;
    for _ in 0..40 { let mut s = FieldSolver::from_bytes(&snap).unwrap(); s.step(5).unwrap(); its += 5; }
    eprintln!("{:.2} ms/it (incl. restore)", t.elapsed().as_secs_f64() * 1e3 / its as f64);
}
