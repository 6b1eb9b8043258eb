//! Local variable groups: unit vectors p_i ∈ S² (one local group each) coupled through a chain of
//! global scalars a_i. Schur elimination must reproduce the all-global solve, E must decrease
//! monotonically, and results must be bit-identical for 1 and 2 rayon threads.
use std::sync::atomic::{AtomicUsize, Ordering};

use lamella::solver::{LeastSquaresProblem, LevenbergMarquardt, LmOptions, VariableLayout};

/// Globals a_0..a_N, locals p_i (3 each) for i < N.
/// Group blocks: [‖p_i‖² − 1, p_i.z − (a_i + a_{i+1})/2, p_i.x − c_i, p_i.y − s_i] over
/// (p_i, a_i, a_{i+1}) and p_i.x p_i.y − e_i over (p_i.y, p_i.x); global blocks: chain
/// smoothness a_{i+1} − a_i − 0.01 and the anchor a_0 − 0.2.
struct UnitVectorChain {
    n: usize,
    schur: bool,
    variables: Vec<Vec<u32>>,
    /// Jacobian evaluations of the group blocks (b < 2n) so far.
    group_jacobians: AtomicUsize,
}

impl UnitVectorChain {
    fn new(n: usize, schur: bool) -> Self {
        let g = (n + 1) as u32;
        let mut variables = Vec::new();
        for i in 0..n as u32 {
            let p = g + 3 * i;
            variables.push(vec![p, p + 1, p + 2, i, i + 1]);
            variables.push(vec![p + 1, p]);
        }
        for i in 0..n as u32 {
            variables.push(vec![i + 1, i]);
        }
        variables.push(vec![0]);
        Self { n, schur, variables, group_jacobians: AtomicUsize::new(0) }
    }

    fn initial(&self) -> Vec<f64> {
        let mut x = vec![0.0; self.variable_count()];
        for i in 0..self.n {
            let p = self.n + 1 + 3 * i;
            x[p..p + 3].copy_from_slice(&[0.5, 0.5, 0.5]);
        }
        x
    }

    fn targets(i: usize) -> (f64, f64, f64) {
        let t = i as f64;
        (0.6 * (0.7 * t).cos(), 0.5 * (0.3 * t).sin(), 0.1 * (1.1 * t).cos())
    }
}

impl LeastSquaresProblem for UnitVectorChain {
    fn variable_count(&self) -> usize {
        self.n + 1 + 3 * self.n
    }
    fn block_count(&self) -> usize {
        self.variables.len()
    }
    fn block_variables(&self, b: usize) -> &[u32] {
        &self.variables[b]
    }
    fn block_residual_count(&self, b: usize) -> usize {
        if b < 2 * self.n && b % 2 == 0 {
            4
        } else {
            1
        }
    }
    fn evaluate_block(&self, b: usize, x: &[f64], r: &mut [f64], jacobian: Option<&mut [f64]>) {
        let v = |k: usize| x[self.variables[b][k] as usize];
        if b < 2 * self.n {
            if jacobian.is_some() {
                self.group_jacobians.fetch_add(1, Ordering::Relaxed);
            }
            let (c, s, e) = Self::targets(b / 2);
            if b % 2 == 0 {
                let (px, py, pz, a0, a1) = (v(0), v(1), v(2), v(3), v(4));
                r.copy_from_slice(&[px * px + py * py + pz * pz - 1.0, pz - 0.5 * (a0 + a1), px - c, py - s]);
                if let Some(j) = jacobian {
                    #[rustfmt::skip]
                    j.copy_from_slice(&[
                        2.0 * px, 2.0 * py, 2.0 * pz, 0.0, 0.0,
                        0.0, 0.0, 1.0, -0.5, -0.5,
                        1.0, 0.0, 0.0, 0.0, 0.0,
                        0.0, 1.0, 0.0, 0.0, 0.0,
                    ]);
                }
            } else {
                let (py, px) = (v(0), v(1));
                r[0] = px * py - e;
                if let Some(j) = jacobian {
                    j.copy_from_slice(&[px, py]);
                }
            }
        } else if b < 3 * self.n {
            r[0] = v(0) - v(1) - 0.01;
            if let Some(j) = jacobian {
                j.copy_from_slice(&[1.0, -1.0]);
            }
        } else {
            r[0] = v(0) - 0.2;
            if let Some(j) = jacobian {
                j[0] = 1.0;
            }
        }
    }
    fn variable_layout(&self) -> VariableLayout {
        if self.schur {
            VariableLayout::with_local_groups(self.n + 1, &vec![3; self.n]).unwrap()
        } else {
            VariableLayout::all_global(self.variable_count())
        }
    }
}

fn options() -> LmOptions {
    LmOptions { gradient_tolerance: 1e-13, ..LmOptions::default() }
}

/// Iterates to convergence, asserting E never increases; returns the final x.
fn converge(problem: &UnitVectorChain) -> Vec<f64> {
    let mut x = problem.initial();
    let mut solver = LevenbergMarquardt::new(problem, options()).unwrap();
    let mut previous = f64::INFINITY;
    for _ in 0..200 {
        let outcome = solver.iterate(problem, &mut x).unwrap();
        assert!(outcome.energy_before <= previous);
        assert!(outcome.energy_after <= outcome.energy_before);
        previous = outcome.energy_after;
        if outcome.converged.is_some() {
            return x;
        }
    }
    panic!("no convergence");
}

#[test]
fn first_schur_step_equals_the_full_normal_equations_step() {
    let schur = UnitVectorChain::new(30, true);
    let global = UnitVectorChain::new(30, false);
    let (mut xs, mut xg) = (schur.initial(), global.initial());
    let os = LevenbergMarquardt::new(&schur, options()).unwrap().iterate(&schur, &mut xs).unwrap();
    let og = LevenbergMarquardt::new(&global, options()).unwrap().iterate(&global, &mut xg).unwrap();
    assert!(os.accepted && og.accepted);
    assert!((os.damping - og.damping).abs() <= 1e-12 * og.damping);
    for (a, b) in xs.iter().zip(&xg) {
        assert!((a - b).abs() < 1e-12, "{a} vs {b}");
    }
}

/// With almost no damping the first steps overshoot, so iterations take several trials. Each
/// re-eliminates the groups for the larger μ from the systems accumulated once at x (a solve this
/// small keeps them): every group block's Jacobian is evaluated once per iteration however many
/// trials it takes, and the step taken still matches the all-global solve's (which keeps its
/// Jacobian across trials).
#[test]
fn rejected_trials_re_eliminate_without_evaluating_again() {
    let options = LmOptions { tau: 1e-12, ..options() };
    let schur = UnitVectorChain::new(30, true);
    let global = UnitVectorChain::new(30, false);
    let (mut xs, mut xg) = (schur.initial(), global.initial());
    let mut solver_s = LevenbergMarquardt::new(&schur, options.clone()).unwrap();
    let mut solver_g = LevenbergMarquardt::new(&global, options).unwrap();
    let mut retried = 0;
    for _ in 0..6 {
        let before = schur.group_jacobians.load(Ordering::Relaxed);
        let os = solver_s.iterate(&schur, &mut xs).unwrap();
        let og = solver_g.iterate(&global, &mut xg).unwrap();
        assert_eq!(schur.group_jacobians.load(Ordering::Relaxed) - before, 2 * schur.n, "{os:?}");
        assert_eq!((os.trials, os.accepted), (og.trials, og.accepted));
        assert!((os.damping - og.damping).abs() <= 1e-9 * og.damping, "{os:?} vs {og:?}");
        if os.trials > 1 && os.accepted {
            retried += 1;
        }
        for (a, b) in xs.iter().zip(&xg) {
            assert!((a - b).abs() < 1e-9, "{a} vs {b} after {os:?}");
        }
    }
    assert!(retried > 0, "no iteration rejected a trial and then accepted one");
}

#[test]
fn schur_elimination_matches_all_global_solution() {
    let xs = converge(&UnitVectorChain::new(30, true));
    let xg = converge(&UnitVectorChain::new(30, false));
    let worst = xs.iter().zip(&xg).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
    assert!(worst < 1e-9, "max difference {worst}");
    // The solution is a genuine compromise: unit vectors only approximately (residuals conflict).
    let p = &xs[31..34];
    let norm = (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt();
    assert!((norm - 1.0).abs() < 0.2);
}

fn run_in_pool(threads: usize, problem: &UnitVectorChain) -> (Vec<u64>, Vec<u64>) {
    let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
    pool.install(|| {
        let mut x = problem.initial();
        let mut solver = LevenbergMarquardt::new(problem, options()).unwrap();
        let mut energies = Vec::new();
        for _ in 0..4 {
            let outcome = solver.iterate(problem, &mut x).unwrap();
            energies.push(outcome.energy_after.to_bits());
            energies.push(outcome.damping.to_bits());
        }
        energies.push(LevenbergMarquardt::evaluate_energy(problem, &x).to_bits());
        (x.iter().map(|v| v.to_bits()).collect(), energies)
    })
}

#[test]
fn results_are_bit_identical_for_one_and_two_threads() {
    for schur in [true, false] {
        let problem = UnitVectorChain::new(1500, schur);
        let one = run_in_pool(1, &problem);
        let two = run_in_pool(2, &problem);
        assert!(one == two, "thread count changed the result (schur = {schur})");
    }
}
