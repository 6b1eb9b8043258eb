//! One Levenberg–Marquardt iteration (evaluation, assembly, Schur elimination, sparse Cholesky,
//! trial energy) on a synthetic problem shaped like the paper's level-set optimisation
//! (Sec. 3.2.2): a scalar F per vertex of a grid (global) and six auxiliaries b, u per vertex
//! (one local group each), coupled through a 4-neighbour gradient stencil.
//!
//! Run: `cargo bench --bench lm_iteration`.
use std::time::{Duration, Instant};

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use lamella::solver::{check_block_jacobian, LeastSquaresProblem, LevenbergMarquardt, LmOptions, VariableLayout};

/// Grid sides: 10,000 and 50,176 global variables (plus six local variables per vertex).
const GRID_SIDES: [usize; 2] = [100, 224];

/// Per vertex v: an auxiliary block over (b, u, F_v, F_e, F_w, F_n, F_s) with residuals
/// ‖b‖² − 1, ‖u‖² − 1, b·u, u·∇F, b·∇F − ‖∇F‖ (∇F by central differences, clamped at the
/// border), and a global fairness block over the same F values: 4F_v − Σ neighbours, plus a weak
/// data term F_v − (x + y²) fixing the field.
struct SyntheticField {
    side: usize,
    variables: Vec<[u32; 11]>,
}

impl SyntheticField {
    fn new(side: usize) -> Self {
        let n = side * side;
        let clamp = |r: isize, c: isize| {
            let r = r.clamp(0, side as isize - 1) as usize;
            let c = c.clamp(0, side as isize - 1) as usize;
            (r * side + c) as u32
        };
        let variables = (0..n)
            .map(|v| {
                let (r, c) = ((v / side) as isize, (v % side) as isize);
                let l = (n + 6 * v) as u32;
                [l, l + 1, l + 2, l + 3, l + 4, l + 5, v as u32, clamp(r, c + 1), clamp(r, c - 1), clamp(r + 1, c), clamp(r - 1, c)]
            })
            .collect();
        Self { side, variables }
    }

    fn vertex_count(&self) -> usize {
        self.side * self.side
    }

    fn initial(&self) -> Vec<f64> {
        let n = self.vertex_count();
        let mut x = vec![0.0; 7 * n];
        for v in 0..n {
            let (y, z) = ((v / self.side) as f64 / self.side as f64, (v % self.side) as f64 / self.side as f64);
            x[v] = z + y * y + 0.05 * (7.0 * y).sin();
            x[n + 6 * v..n + 6 * v + 6].copy_from_slice(&[0.1, 0.2, 0.9, 0.8, -0.3, 0.1]);
        }
        x
    }

    /// The distinct global variables of vertex v's stencil (border vertices repeat neighbours).
    fn distinct(&self, v: usize) -> bool {
        let s = &self.variables[v][6..];
        (0..s.len()).all(|i| (i + 1..s.len()).all(|j| s[i] != s[j]))
    }
}

impl LeastSquaresProblem for SyntheticField {
    fn variable_count(&self) -> usize {
        7 * self.vertex_count()
    }
    fn block_count(&self) -> usize {
        2 * self.vertex_count()
    }
    fn block_variables(&self, b: usize) -> &[u32] {
        let v = b / 2;
        match (b % 2, self.distinct(v)) {
            (0, true) => &self.variables[v],
            (0, false) => &self.variables[v][..6],
            (_, true) => &self.variables[v][6..],
            (_, false) => &self.variables[v][6..7],
        }
    }
    fn block_residual_count(&self, b: usize) -> usize {
        if b % 2 == 0 {
            5
        } else {
            2
        }
    }
    fn evaluate_block(&self, b: usize, x: &[f64], r: &mut [f64], jacobian: Option<&mut [f64]>) {
        let v = b / 2;
        let vars = self.block_variables(b);
        let h = 1.0 / self.side as f64;
        let interior = self.distinct(v);
        if b % 2 == 0 {
            let mut p = [0.0; 11];
            for (k, &i) in vars.iter().enumerate() {
                p[k] = x[i as usize];
            }
            let (bv, u) = ([p[0], p[1], p[2]], [p[3], p[4], p[5]]);
            let g = if interior { [(p[7] - p[8]) / (2.0 * h), (p[9] - p[10]) / (2.0 * h), 0.0] } else { [0.0; 3] };
            let dot = |a: [f64; 3], c: [f64; 3]| a[0] * c[0] + a[1] * c[1] + a[2] * c[2];
            let gn = dot(g, g).sqrt().max(1e-12);
            r.copy_from_slice(&[dot(bv, bv) - 1.0, dot(u, u) - 1.0, dot(bv, u), dot(u, g), dot(bv, g) - gn]);
            if let Some(j) = jacobian {
                let n = vars.len();
                for k in 0..3 {
                    j[k] = 2.0 * bv[k];
                    j[n + 3 + k] = 2.0 * u[k];
                    j[2 * n + k] = u[k];
                    j[2 * n + 3 + k] = bv[k];
                    j[3 * n + 3 + k] = g[k];
                    j[4 * n + k] = g[k];
                }
                if interior {
                    // ∂g/∂(F_e, F_w, F_n, F_s) = (±1/2h in x, ±1/2h in y).
                    let d = 1.0 / (2.0 * h);
                    let rows = [(3, u), (4, [bv[0] - g[0] / gn, bv[1] - g[1] / gn, 0.0])];
                    for (row, a) in rows {
                        j[row * n + 7] = a[0] * d;
                        j[row * n + 8] = -a[0] * d;
                        j[row * n + 9] = a[1] * d;
                        j[row * n + 10] = -a[1] * d;
                    }
                }
            }
        } else {
            let (y, z) = ((v / self.side) as f64 * h, (v % self.side) as f64 * h);
            let f = |k: usize| x[vars[k] as usize];
            let (w_fair, w_data) = (0.1, 0.01);
            r[0] = if interior { w_fair * (4.0 * f(0) - f(1) - f(2) - f(3) - f(4)) } else { 0.0 };
            r[1] = w_data * (f(0) - (z + y * y));
            if let Some(j) = jacobian {
                let n = vars.len();
                if interior {
                    j[..5].copy_from_slice(&[4.0 * w_fair, -w_fair, -w_fair, -w_fair, -w_fair]);
                }
                j[n] = w_data;
            }
        }
    }
    fn variable_layout(&self) -> VariableLayout {
        let n = self.vertex_count();
        VariableLayout::with_local_groups(n, &vec![6; n]).expect("non-empty groups")
    }
}

fn peak_resident_mib() -> f64 {
    std::fs::read_to_string("/proc/self/status")
        .ok()
        .and_then(|s| s.lines().find(|l| l.starts_with("VmHWM:")).map(str::to_string))
        .and_then(|l| l.split_whitespace().nth(1).and_then(|k| k.parse::<f64>().ok()))
        .map_or(0.0, |kib| kib / 1024.0)
}

fn lm_iteration(c: &mut Criterion) {
    let mut group = c.benchmark_group("lm_iteration");
    group.sample_size(10).warm_up_time(Duration::from_millis(500)).measurement_time(Duration::from_secs(3));
    for side in GRID_SIDES {
        let problem = SyntheticField::new(side);
        let start = Instant::now();
        let mut solver = LevenbergMarquardt::new(&problem, LmOptions::default()).expect("valid problem");
        let setup = start.elapsed();
        let x0 = problem.initial();
        for b in [0, 1, 2 * side + 2, 2 * side + 3, problem.block_count() / 2, problem.block_count() / 2 + 1] {
            assert!(check_block_jacobian(&problem, &x0, b, 1e-6) < 1e-5, "Jacobian of block {b}");
        }
        let mut x = x0.clone();
        let outcome = solver.iterate(&problem, &mut x).expect("iteration");
        eprintln!(
            "globals {}, locals {}: new() {:.0} ms, first iteration {:?}, peak RSS {:.0} MiB",
            problem.vertex_count(),
            6 * problem.vertex_count(),
            setup.as_secs_f64() * 1e3,
            (outcome.energy_before, outcome.energy_after, outcome.trials),
            peak_resident_mib()
        );
        group.bench_with_input(BenchmarkId::new("schur", problem.vertex_count()), &side, |bench, _| {
            bench.iter(|| {
                solver.reset_damping();
                x.copy_from_slice(&x0);
                solver.iterate(&problem, &mut x).expect("iteration")
            })
        });
    }
    group.finish();
}

criterion_group!(benches, lm_iteration);
criterion_main!(benches);
