//! Blocks with constant Jacobians (`LeastSquaresProblem::block_jacobian_is_constant`): the solver
//! sums their Gram products once per revision of the problem and then forms only their residuals
//! and Jᵀr, with the same iterates as when it forms everything every time: bit for bit where no
//! other global block shares their entries of the normal matrix, and up to rounding where one
//! does (the constant blocks' share of an entry is then summed first).
use lamella::solver::{new_revision, LeastSquaresProblem, LevenbergMarquardt, LmOptions, SolverError, VariableLayout};

/// Points p_i ∈ R² (local groups of 2) on the unit circle, coupled to a chain of global scalars
/// a_i by the nonlinear rows (‖p_i‖² − 1, p_i.x − a_i a_{i+1}); two kinds of linear rows
/// scaled by `weight`: `weight (a_{i+1} − a_i − 0.1)` (global) and `weight (p_i.y − 0.05 i)`
/// (in p_i's group); and, with `bend`, the nonlinear global rows `a_i a_{i+1} − 0.1`, which
/// share the linear global rows' entries.
struct Chain {
    points: usize,
    blocks: Vec<(Row, Vec<u32>)>,
    weight: f64,
    /// Declares the linear blocks constant.
    declared: bool,
    revision: u64,
}

#[derive(Clone, Copy, PartialEq)]
enum Row {
    Circle,
    Step,
    Height(f64),
    Bend,
}

impl Chain {
    fn new(points: usize, declared: bool, bend: bool) -> Self {
        let g = (points + 1) as u32;
        let mut blocks = Vec::new();
        for i in 0..points as u32 {
            blocks.push((Row::Circle, vec![g + 2 * i, g + 2 * i + 1, i, i + 1]));
            blocks.push((Row::Step, vec![i, i + 1]));
            blocks.push((Row::Height(0.05 * i as f64), vec![g + 2 * i + 1]));
            if bend {
                blocks.push((Row::Bend, vec![i, i + 1]));
            }
        }
        Chain { points, blocks, weight: 0.5, declared, revision: new_revision() }
    }

    fn start(&self) -> Vec<f64> {
        (0..self.variable_count()).map(|v| 0.3 + 0.01 * v as f64).collect()
    }
}

impl LeastSquaresProblem for Chain {
    fn variable_count(&self) -> usize {
        3 * self.points + 1
    }
    fn block_count(&self) -> usize {
        self.blocks.len()
    }
    fn block_variables(&self, b: usize) -> &[u32] {
        &self.blocks[b].1
    }
    fn block_residual_count(&self, b: usize) -> usize {
        if self.blocks[b].0 == Row::Circle {
            2
        } else {
            1
        }
    }
    fn evaluate_block(&self, b: usize, x: &[f64], r: &mut [f64], jacobian: Option<&mut [f64]>) {
        let (row, variables) = &self.blocks[b];
        let value = |k: usize| x[variables[k] as usize];
        match *row {
            Row::Circle => {
                let (px, py, a, c) = (value(0), value(1), value(2), value(3));
                r[0] = px * px + py * py - 1.0;
                r[1] = px - a * c;
                if let Some(j) = jacobian {
                    j.copy_from_slice(&[2.0 * px, 2.0 * py, 0.0, 0.0, 1.0, 0.0, -c, -a]);
                }
            }
            Row::Step => {
                r[0] = self.weight * (value(1) - value(0) - 0.1);
                if let Some(j) = jacobian {
                    j.copy_from_slice(&[-self.weight, self.weight]);
                }
            }
            Row::Height(target) => {
                r[0] = self.weight * (value(0) - target);
                if let Some(j) = jacobian {
                    j[0] = self.weight;
                }
            }
            Row::Bend => {
                let (a, c) = (value(0), value(1));
                r[0] = a * c - 0.1;
                if let Some(j) = jacobian {
                    j.copy_from_slice(&[c, a]);
                }
            }
        }
    }
    fn block_jacobian_is_constant(&self, b: usize) -> bool {
        self.declared && matches!(self.blocks[b].0, Row::Step | Row::Height(_))
    }
    fn constant_jacobian_revision(&self) -> u64 {
        self.revision
    }
    fn variable_layout(&self) -> VariableLayout {
        VariableLayout::with_local_groups(self.points + 1, &vec![2; self.points]).unwrap()
    }
}

/// The bits of x after each of `iterations` iterations, with the linear rows' weight set to
/// `new_weight` after the fifth (a new revision when `bump`).
fn run(mut problem: Chain, iterations: usize, new_weight: f64, bump: bool) -> Vec<Vec<u64>> {
    let mut x = problem.start();
    let mut solver = LevenbergMarquardt::new(&problem, LmOptions::default()).unwrap();
    let mut trace = Vec::new();
    for i in 0..iterations {
        if i == 5 {
            problem.weight = new_weight;
            if bump {
                problem.revision = new_revision();
            }
        }
        solver.iterate(&problem, &mut x).unwrap();
        trace.push(x.iter().map(|v| v.to_bits()).collect());
    }
    trace
}

#[test]
fn constant_jacobians_give_the_same_iterates_bit_for_bit() {
    let declared = run(Chain::new(40, true, false), 12, 2.0, true);
    let evaluated = run(Chain::new(40, false, false), 12, 2.0, true);
    assert_eq!(declared, evaluated);
    // The iterates moved: the comparison is not between two idle runs.
    assert_ne!(declared[0], declared[11]);
}

#[test]
fn constant_jacobians_sharing_entries_with_varying_blocks_give_the_same_iterates_up_to_rounding() {
    let declared = run(Chain::new(40, true, true), 12, 2.0, true);
    let evaluated = run(Chain::new(40, false, true), 12, 2.0, true);
    let value = |bits: &u64| f64::from_bits(*bits);
    for (i, (d, e)) in declared.iter().zip(&evaluated).enumerate() {
        for (v, (a, b)) in d.iter().map(value).zip(e.iter().map(value)).enumerate() {
            assert!((a - b).abs() <= 1e-12 * (1.0 + b.abs()), "iteration {i}, variable {v}: {a} against {b}");
        }
    }
    assert_ne!(declared[0], declared[11]);
}

#[test]
fn constant_jacobians_are_reused_until_the_revision_changes() {
    // Without a new revision the solver keeps the Gram products of weight 0.5 after the change
    // to 2.0: from then on its steps differ from those of fresh ones.
    let stale = run(Chain::new(40, true, false), 8, 2.0, false);
    let evaluated = run(Chain::new(40, false, false), 8, 2.0, false);
    assert_eq!(stale[..5], evaluated[..5]);
    assert_ne!(stale[5], evaluated[5]);
}

#[test]
fn a_block_whose_constness_changes_is_refused_by_name() {
    // Constness decides how a block is stored: the solver refuses a problem that changed its
    // answer instead of reusing a Gram product it no longer holds.
    let mut problem = Chain::new(6, true, false);
    let mut x = problem.start();
    let mut solver = LevenbergMarquardt::new(&problem, LmOptions::default()).unwrap();
    solver.iterate(&problem, &mut x).unwrap();
    let before = x.clone();
    problem.declared = false;
    let error = solver.iterate(&problem, &mut x).expect_err("refused");
    assert!(matches!(error, SolverError::ProblemChanged { .. }), "{error}");
    assert!(error.to_string().contains("block 1"), "{error}");
    // Nothing was lost: x is where the last accepted iteration left it.
    assert_eq!(x, before);
}
