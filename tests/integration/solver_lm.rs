//! Levenberg–Marquardt on small classical problems: Rosenbrock, exponential-decay fitting, and a
//! start whose Gauss–Newton step must be rejected.
use crate::solver_support;

use lamella::solver::{Convergence, LeastSquaresProblem, LevenbergMarquardt, LmOptions};
use solver_support::OneBlock;

/// Rosenbrock as residuals r = (10(y − x²), 1 − x).
fn rosenbrock() -> impl LeastSquaresProblem {
    OneBlock {
        variable_count: 2,
        variables: vec![0, 1],
        residual_count: 2,
        evaluate: |x: &[f64], r: &mut [f64], jacobian: Option<&mut [f64]>| {
            r[0] = 10.0 * (x[1] - x[0] * x[0]);
            r[1] = 1.0 - x[0];
            if let Some(j) = jacobian {
                j.copy_from_slice(&[-20.0 * x[0], 10.0, -1.0, 0.0]);
            }
        },
    }
}

fn solve<P: LeastSquaresProblem>(problem: &P, x: &mut [f64], options: LmOptions, max_iterations: usize) -> Vec<f64> {
    let mut solver = LevenbergMarquardt::new(problem, options).unwrap();
    let mut energies = vec![LevenbergMarquardt::evaluate_energy(problem, x)];
    for _ in 0..max_iterations {
        let outcome = solver.iterate(problem, x).unwrap();
        assert!(outcome.energy_after <= outcome.energy_before);
        energies.push(outcome.energy_after);
        if outcome.converged.is_some() {
            return energies;
        }
    }
    panic!("no convergence in {max_iterations} iterations");
}

#[test]
fn rosenbrock_converges_to_one_one() {
    let mut x = [-1.2, 1.0];
    let energies = solve(&rosenbrock(), &mut x, LmOptions::default(), 200);
    assert!((x[0] - 1.0).abs() < 1e-8 && (x[1] - 1.0).abs() < 1e-8, "{x:?}");
    assert!(energies.windows(2).all(|w| w[1] <= w[0]));
}

/// Exponential decay y = A exp(−λ t), one block per sample, data with uniform noise of
/// half-width `NOISE` from a fixed-seed xorshift.
struct DecayFit {
    t: Vec<f64>,
    y: Vec<f64>,
}

const TRUE_AMPLITUDE: f64 = 2.5;
const TRUE_RATE: f64 = 1.3;
const NOISE: f64 = 0.01;

fn xorshift(state: &mut u64) -> f64 {
    *state ^= *state << 13;
    *state ^= *state >> 7;
    *state ^= *state << 17;
    (*state >> 11) as f64 / (1u64 << 53) as f64
}

impl DecayFit {
    fn generate(samples: usize) -> Self {
        let mut state = 0x9E37_79B9_7F4A_7C15u64;
        let t: Vec<f64> = (0..samples).map(|i| 4.0 * i as f64 / (samples - 1) as f64).collect();
        let y = t
            .iter()
            .map(|&t| TRUE_AMPLITUDE * (-TRUE_RATE * t).exp() + NOISE * (2.0 * xorshift(&mut state) - 1.0))
            .collect();
        Self { t, y }
    }

    /// ∂model/∂(A, λ) at sample i.
    fn model_gradient(&self, i: usize, p: &[f64]) -> [f64; 2] {
        let e = (-p[1] * self.t[i]).exp();
        [e, -p[0] * self.t[i] * e]
    }
}

impl LeastSquaresProblem for DecayFit {
    fn variable_count(&self) -> usize {
        2
    }
    fn block_count(&self) -> usize {
        self.t.len()
    }
    fn block_variables(&self, _b: usize) -> &[u32] {
        &[0, 1]
    }
    fn block_residual_count(&self, _b: usize) -> usize {
        1
    }
    fn evaluate_block(&self, b: usize, x: &[f64], r: &mut [f64], jacobian: Option<&mut [f64]>) {
        r[0] = x[0] * (-x[1] * self.t[b]).exp() - self.y[b];
        if let Some(j) = jacobian {
            j.copy_from_slice(&self.model_gradient(b, x));
        }
    }
}

#[test]
fn exponential_decay_fit_recovers_parameters_within_their_standard_errors() {
    let problem = DecayFit::generate(200);
    let mut p = [1.0, 0.5];
    solve(&problem, &mut p, LmOptions::default(), 100);
    // Standard errors from the covariance σ²(JᵀJ)⁻¹, σ² = NOISE²/3 for uniform noise.
    let mut jtj = [0.0; 3];
    for i in 0..problem.t.len() {
        let g = problem.model_gradient(i, &p);
        jtj[0] += g[0] * g[0];
        jtj[1] += g[0] * g[1];
        jtj[2] += g[1] * g[1];
    }
    let det = jtj[0] * jtj[2] - jtj[1] * jtj[1];
    let variance = NOISE * NOISE / 3.0;
    let se_amplitude = (variance * jtj[2] / det).sqrt();
    let se_rate = (variance * jtj[0] / det).sqrt();
    assert!((p[0] - TRUE_AMPLITUDE).abs() < 4.0 * se_amplitude, "A = {} ± {se_amplitude}", p[0]);
    assert!((p[1] - TRUE_RATE).abs() < 4.0 * se_rate, "λ = {} ± {se_rate}", p[1]);
    // The data do determine the parameters well: the errors are small in absolute terms.
    assert!(se_amplitude < 5e-3 && se_rate < 5e-3);
}

/// r(x) = atan(x): from x = 2 the Gauss–Newton step −r/r' = −5 atan 2 overshoots to x ≈ −3.5
/// where |atan| is larger, so the first, nearly undamped trial must be rejected.
fn arctangent() -> impl LeastSquaresProblem {
    OneBlock {
        variable_count: 1,
        variables: vec![0],
        residual_count: 1,
        evaluate: |x: &[f64], r: &mut [f64], jacobian: Option<&mut [f64]>| {
            r[0] = x[0].atan();
            if let Some(j) = jacobian {
                j[0] = 1.0 / (1.0 + x[0] * x[0]);
            }
        },
    }
}

#[test]
fn overshooting_step_is_rejected_and_damping_grows() {
    let options = LmOptions { tau: 1e-6, ..LmOptions::default() };
    let initial_damping = options.tau * (1.0f64 / 5.0).powi(2);
    let mut solver = LevenbergMarquardt::new(&arctangent(), options.clone()).unwrap();
    let mut x = [2.0];
    let outcome = solver.iterate(&arctangent(), &mut x).unwrap();
    assert!(outcome.trials >= 2, "{outcome:?}");
    assert!(outcome.accepted);
    assert!(outcome.energy_after < outcome.energy_before);
    assert!((outcome.energy_before - 2.0f64.atan().powi(2)).abs() < 1e-15);
    assert!(outcome.damping > initial_damping, "{outcome:?}");
    assert_eq!(outcome.damping, solver.damping());
    // Continue to the root x = 0.
    let mut converged = None;
    for _ in 0..100 {
        let o = solver.iterate(&arctangent(), &mut x).unwrap();
        assert!(o.energy_after <= o.energy_before);
        if o.converged.is_some() {
            converged = o.converged;
            break;
        }
    }
    assert!(converged.is_some());
    assert!(x[0].abs() < 1e-8, "{x:?}");
}

#[test]
fn zero_residual_reports_convergence_without_moving() {
    let mut x = [1.0, 1.0];
    let problem = rosenbrock();
    let mut solver = LevenbergMarquardt::new(&problem, LmOptions::default()).unwrap();
    let outcome = solver.iterate(&problem, &mut x).unwrap();
    assert_eq!(x, [1.0, 1.0]);
    assert!(!outcome.accepted);
    assert_eq!(outcome.trials, 0);
    assert_eq!(outcome.converged, Some(Convergence::SmallGradient));
}

/// r = x0 + x1 − 2: JᵀJ = [[1, 1], [1, 1]] is singular, so with μ = 1e-20 (below the rounding
/// of 1 + μ) the sparse Cholesky fails until the damping has grown.
fn rank_deficient() -> impl LeastSquaresProblem {
    OneBlock {
        variable_count: 2,
        variables: vec![0, 1],
        residual_count: 1,
        evaluate: |x: &[f64], r: &mut [f64], jacobian: Option<&mut [f64]>| {
            r[0] = x[0] + x[1] - 2.0;
            if let Some(j) = jacobian {
                j.copy_from_slice(&[1.0, 1.0]);
            }
        },
    }
}

#[test]
fn failed_factorisation_is_a_rejected_trial_with_more_damping() {
    let options = LmOptions { tau: 0.0, min_damping: 1e-20, ..LmOptions::default() };
    let mut solver = LevenbergMarquardt::new(&rank_deficient(), options.clone()).unwrap();
    let mut x = [0.0, 0.0];
    let outcome = solver.iterate(&rank_deficient(), &mut x).unwrap();
    assert!(outcome.trials > 1 && outcome.accepted, "{outcome:?}");
    assert!(outcome.energy_after < 1e-6 * outcome.energy_before);
    // The damping had to grow past the rounding of 1 + μ before a factorisation succeeded.
    assert!(outcome.damping > 1e-18, "{outcome:?}");
    assert!((x[0] + x[1] - 2.0).abs() < 1e-6, "{x:?}");

    let single = LmOptions { max_trials: 1, ..options };
    let mut solver = LevenbergMarquardt::new(&rank_deficient(), single).unwrap();
    let mut x = [0.0, 0.0];
    let e = solver.iterate(&rank_deficient(), &mut x).unwrap_err();
    assert_eq!(e, lamella::solver::SolverError::FactorizationFailed { trials: 1 });
    assert_eq!(x, [0.0, 0.0]);
}
