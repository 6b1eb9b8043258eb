//! Sparse Cholesky backends on normal-equation-like matrices: numeric factorisation + solve per
//! iteration with the symbolic analysis reused, as in every Levenberg–Marquardt trial.
//!
//! Matrices: M = LᵀL + εI with L the graph Laplacian of the hall-roof benchmark meshes, which has
//! the 2-ring stencil of the field problem's Schur-reduced normal matrix (every curve block couples
//! the field values of a whole vertex star). Backends:
//! faer's supernodal/simplicial Cholesky (its own AMD ordering) and nalgebra-sparse's
//! `CscCholesky` on M permuted by AMD from the `amd` crate (nalgebra-sparse has no ordering).
//!
//! Run: `cargo bench --bench linear_backends`.
use std::time::Duration;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use faer::linalg::solvers::SolveCore;
use faer::sparse::linalg::solvers::{Llt, SymbolicLlt};
use faer::sparse::{SparseColMat, SymbolicSparseColMat};
use faer::{Conj, MatMut, Side};
use nalgebra::DMatrix;
use nalgebra_sparse::factorization::{CscCholesky, CscSymbolicCholesky};
use lamella::surfaces::hall_roof;
use nalgebra_sparse::{CooMatrix, CscMatrix};

/// Vertex counts of the hall-roof benchmark meshes.
const ROOF_VERTICES: [usize; 4] = [600, 3_000, 10_000, 50_000];

/// Graph Laplacian of the hall-roof mesh with about `vertices` vertices.
fn mesh_laplacian(vertices: usize) -> CscMatrix<f64> {
    let mesh = hall_roof(vertices).into_mesh().expect("the built-in roof is valid");
    let n = mesh.vertex_count();
    let mut degree = vec![0.0; n];
    let mut coo = CooMatrix::new(n, n);
    for &[i, j] in mesh.edges() {
        let (i, j) = (i as usize, j as usize);
        coo.push(i, j, -1.0);
        coo.push(j, i, -1.0);
        degree[i] += 1.0;
        degree[j] += 1.0;
    }
    for (i, &d) in degree.iter().enumerate() {
        coo.push(i, i, d);
    }
    CscMatrix::from(&coo)
}

/// M = LᵀL + εI (symmetric positive definite, full pattern, sorted rows).
fn bilaplacian(vertices: usize) -> CscMatrix<f64> {
    let l = mesh_laplacian(vertices);
    let mut m = &l.transpose() * &l;
    let n = m.nrows();
    for j in 0..n {
        let mut column = m.col_mut(j);
        let (rows, values) = column.rows_and_values_mut();
        if let Ok(k) = rows.binary_search(&j) {
            values[k] += 1e-3;
        }
    }
    m
}

/// Upper triangle of `m` as a faer matrix.
fn faer_upper(m: &CscMatrix<f64>) -> SparseColMat<usize, f64> {
    let n = m.nrows();
    let (mut col_ptr, mut row_idx, mut values) = (vec![0], Vec::new(), Vec::new());
    for j in 0..n {
        let column = m.col(j);
        for (&i, &v) in column.row_indices().iter().zip(column.values()) {
            if i <= j {
                row_idx.push(i);
                values.push(v);
            }
        }
        col_ptr.push(row_idx.len());
    }
    SparseColMat::new(SymbolicSparseColMat::new_checked(n, n, col_ptr, None, row_idx), values)
}

/// P M Pᵀ with P the AMD permutation of `m`'s pattern.
fn amd_permuted(m: &CscMatrix<f64>) -> CscMatrix<f64> {
    let n = m.nrows();
    let (_, inverse, _) = amd::order::<usize>(n, m.col_offsets(), m.row_indices(), &amd::Control::default())
        .expect("valid symmetric pattern");
    let mut coo = CooMatrix::new(n, n);
    for (i, j, &v) in m.triplet_iter() {
        coo.push(inverse[i], inverse[j], v);
    }
    CscMatrix::from(&coo)
}

fn rhs(n: usize) -> Vec<f64> {
    (0..n).map(|i| ((i % 17) as f64 - 8.0) / 8.0).collect()
}

/// max |M x − b| for a solution x of the unpermuted system.
fn residual(m: &CscMatrix<f64>, x: &[f64], b: &[f64]) -> f64 {
    let mut worst: f64 = 0.0;
    let mut mx = vec![0.0; b.len()];
    for (i, j, &v) in m.triplet_iter() {
        mx[i] += v * x[j];
    }
    for (a, c) in mx.iter().zip(b) {
        worst = worst.max((a - c).abs());
    }
    worst
}

fn linear_backends(c: &mut Criterion) {
    let mut group = c.benchmark_group("numeric_factor_and_solve");
    group.sample_size(10).warm_up_time(Duration::from_millis(500)).measurement_time(Duration::from_secs(2));
    for vertices in ROOF_VERTICES {
        let m = bilaplacian(vertices);
        let n = m.nrows();
        let b = rhs(n);

        let upper = faer_upper(&m);
        let symbolic = SymbolicLlt::try_new(upper.symbolic(), Side::Upper).expect("symbolic analysis");
        let faer_solve = |x: &mut [f64]| {
            let llt = Llt::try_new_with_symbolic(symbolic.clone(), upper.as_ref(), Side::Upper).expect("SPD");
            x.copy_from_slice(&b);
            llt.solve_in_place_with_conj(Conj::No, MatMut::from_column_major_slice_mut(x, n, 1));
        };
        let mut x = vec![0.0; n];
        faer_solve(&mut x);
        assert!(residual(&m, &x, &b) < 1e-6, "faer solve inaccurate");
        group.bench_with_input(BenchmarkId::new("faer", n), &n, |bench, _| bench.iter(|| faer_solve(&mut x)));

        let permuted = amd_permuted(&m);
        let symbolic = CscSymbolicCholesky::factor(permuted.pattern().clone());
        let mut cholesky = CscCholesky::factor_numerical(symbolic, permuted.values()).expect("SPD");
        let mut x = DMatrix::zeros(n, 1);
        let mut nalgebra_solve = |x: &mut DMatrix<f64>| {
            cholesky.refactor(permuted.values()).expect("SPD");
            x.copy_from_slice(&b);
            cholesky.solve_mut(&mut *x);
        };
        // Check against the permuted matrix (the right-hand side is a test vector either way).
        nalgebra_solve(&mut x);
        assert!(residual(&permuted, x.as_slice(), &b) < 1e-6, "nalgebra-sparse solve inaccurate");
        group.bench_with_input(BenchmarkId::new("nalgebra_sparse_amd", n), &n, |bench, _| {
            bench.iter(|| nalgebra_solve(&mut x))
        });
        eprintln!("n = {n}: nnz(M) = {}, nnz(L) with AMD = {}", m.nnz(), cholesky.l().nnz());
    }
    group.finish();
}

criterion_group!(benches, linear_backends);
criterion_main!(benches);
