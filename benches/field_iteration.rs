//! One Levenberg–Marquardt iteration of the pseudo-geodesic field optimisation (Eq. 12):
//! block evaluation, Schur elimination of the binormal/side-vector auxiliaries, sparse Cholesky,
//! trial energy, plus the report `FieldSolver::step` produces. Measured as a front end meets it: a
//! live session in the final stage (weights of Table 2), restored from a saved session after 20
//! iterations for every sample and stepped once untimed (so its workspaces are in memory, as in
//! a session that has been stepping), then the timed `step(1)`.
//!
//! Run: `cargo bench --bench field_iteration`.

mod support;

use criterion::{criterion_group, criterion_main, BatchSize, BenchmarkId, Criterion};
use lamella::field::FieldSolver;
use std::time::Duration;
use support::{roof, solver, ROOF_VERTICES};

fn field_iteration(c: &mut Criterion) {
    let mut group = c.benchmark_group("field_iteration");
    group.sample_size(10).warm_up_time(Duration::from_millis(500)).measurement_time(Duration::from_secs(3));
    for vertices in ROOF_VERTICES {
        let mesh = roof(vertices);
        let mut warm = solver(&mesh);
        warm.step(20).expect("solver runs");
        let snapshot = warm.to_bytes();
        group.bench_with_input(BenchmarkId::new("step_1", mesh.vertex_count()), &snapshot, |bench, snapshot| {
            bench.iter_batched(
                || {
                    let mut live = FieldSolver::from_bytes(snapshot).expect("restores");
                    live.step(1).expect("iterates");
                    live
                },
                |mut s| s.step(1).expect("iterates"),
                BatchSize::LargeInput,
            )
        });
    }
    group.finish();
}

criterion_group!(benches, field_iteration);
criterion_main!(benches);
