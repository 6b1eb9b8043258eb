//! Adaptive Levenberg–Marquardt (Madsen, Nielsen & Tingleff 2004, Alg. 3.16, damping matrix
//! D = I) on the sparse normal equations, with Schur elimination of local variable groups.
//! Used for the level-set field optimisation of the paper (Sec. 3.2.2, Eq. 8–12).

use super::assembly::{reduce_blocks, ConstantHessian, ReducedGather, ReducedSystem};
use super::evaluation::{evaluate_energy_into, evaluate_energy_standalone, evaluate_slots};
use super::normal_pattern::NormalPattern;
use super::schur::{GroupSystems, KEPT_ACCUMULATION_LIMIT};
use super::substructured_cholesky::{SplitWork, SubstructuredCholesky};
use super::structure::{analyse, BlockStructure, GroupStructure};
use super::{Convergence, IterationOutcome, LeastSquaresProblem, LmOptions, SolverError};

/// Upper bound of the damping growth factor ν (it doubles on every rejection).
const MAX_GROWTH: f64 = 1e12;

/// The adaptive part of the damping: μ (`None` until the first iteration) and its growth factor ν.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct DampingState {
    pub mu: Option<f64>,
    pub nu: f64,
}

/// Solver state: fixed pattern, symbolic factorisation, workspaces, μ and ν.
pub struct LevenbergMarquardt {
    options: LmOptions,
    blocks: BlockStructure,
    groups: GroupStructure,
    pattern: NormalPattern,
    /// `None` when there are no global variables.
    cholesky: Option<SubstructuredCholesky>,
    systems: GroupSystems,
    gather: ReducedGather,
    slots: Vec<f64>,
    /// Residuals of the last trial point, segmented by block.
    trial_residuals: Vec<f64>,
    /// The last [`Self::iterate`] accepted its last trial point.
    accepted: bool,
    gradient: Vec<f64>,
    hessian: Vec<f64>,
    /// The constant blocks' share of `hessian`, summed at `constant_revision`.
    constant_hessian: ConstantHessian,
    /// diag(JᵀJ) over the global variables (scratch of [`Self::initial_damping`]).
    global_diagonal: Vec<f64>,
    step: Vec<f64>,
    trial_x: Vec<f64>,
    mu: Option<f64>,
    nu: f64,
    /// The problem's constant-Jacobian revision `constant_hessian` was summed at and the
    /// constant blocks' Jacobians were checked at (`None` before the first evaluation or after a
    /// failed one).
    constant_revision: Option<u64>,
}

impl LevenbergMarquardt {
    /// Validates the problem (variable indices in range, no duplicates, layout consistent: each
    /// block touches ≤ 1 local group), builds the fixed sparsity pattern of the (reduced) normal
    /// matrix, its bisection into two domains (where that shortens a factorisation on two cores)
    /// and their symbolic Cholesky analyses (AMD ordering) once.
    pub fn new<P: LeastSquaresProblem>(problem: &P, options: LmOptions) -> Result<Self, SolverError> {
        Self::with_split_work(problem, options, SplitWork::Span)
    }

    /// [`Self::new`] for a solve that splits its reduced matrix only where that lowers `work`.
    pub(crate) fn with_split_work<P: LeastSquaresProblem>(problem: &P, options: LmOptions, work: SplitWork) -> Result<Self, SolverError> {
        Self::build(problem, options, work, KEPT_ACCUMULATION_LIMIT)
    }

    /// [`Self::with_split_work`], keeping the groups' accumulated systems for retried trials if
    /// they hold at most `kept_limit` values (see [`GroupSystems`]).
    fn build<P: LeastSquaresProblem>(problem: &P, options: LmOptions, work: SplitWork, kept_limit: usize) -> Result<Self, SolverError> {
        let (blocks, groups) = analyse(problem)?;
        let mut pattern = NormalPattern::build(&blocks, &groups)?;
        let cholesky = if pattern.dimension() > 0 {
            let mut cholesky = SubstructuredCholesky::analyse(&pattern.col_ptr, &pattern.row_idx, work)?;
            // The reduced matrix is assembled directly in the factorisations' storage order.
            let storage = cholesky.storage_positions(pattern.row_idx.len());
            pattern.assign_storage(&blocks, &groups, &storage, &cholesky.domains_of_variables())?;
            Some(cholesky)
        } else {
            None
        };
        let systems = GroupSystems::new(&blocks, &groups, kept_limit);
        let constant_hessian = ConstantHessian::new(&pattern);
        let gather = ReducedGather::new(&mut pattern, &groups, &systems)?;
        pattern.free_rows();
        let n = blocks.variable_count;
        let nnz = pattern.storage_len();
        Ok(Self {
            options,
            systems,
            gather,
            slots: vec![0.0; blocks.slot_ptr[blocks.block_count()]],
            trial_residuals: vec![0.0; blocks.residual_ptr[blocks.block_count()]],
            accepted: false,
            gradient: vec![0.0; n],
            hessian: vec![0.0; nnz],
            constant_hessian,
            global_diagonal: vec![0.0; blocks.global_count],
            step: vec![0.0; n],
            trial_x: vec![0.0; n],
            mu: None,
            nu: 2.0,
            constant_revision: None,
            blocks,
            groups,
            pattern,
            cholesky,
        })
    }

    /// Current damping μ (0 before the first iteration or after [`Self::reset_damping`]).
    pub fn damping(&self) -> f64 {
        self.mu.unwrap_or(0.0)
    }

    /// μ and ν, to be saved with a session and handed back to [`Self::restore_damping`], so that
    /// a restored solve continues exactly as the original would have.
    pub fn damping_state(&self) -> DampingState {
        DampingState { mu: self.mu, nu: self.nu }
    }

    /// Restores μ and ν saved by [`Self::damping_state`].
    pub fn restore_damping(&mut self, state: DampingState) {
        self.mu = state.mu;
        self.nu = state.nu;
    }

    /// The next [`Self::iterate`] re-initialises μ from `tau` (call after weights change).
    pub fn reset_damping(&mut self) {
        self.mu = None;
        self.nu = 2.0;
    }

    /// Residuals of block `b` at the point the last [`Self::iterate`] moved x to, as evaluated
    /// for its gain ratio; `None` if that iteration accepted no step.
    pub(crate) fn accepted_residuals(&self, b: usize) -> Option<&[f64]> {
        let ptr = &self.blocks.residual_ptr;
        self.accepted.then(|| &self.trial_residuals[ptr[b]..ptr[b + 1]])
    }

    /// Energy E(x) = Σ_b ‖r_b(x)‖² without Jacobians (parallel, deterministic: per-block squared
    /// norms summed in block order). Non-finite residuals or a wrong length of `x` give +∞.
    pub fn evaluate_energy<P: LeastSquaresProblem>(problem: &P, x: &[f64]) -> f64 {
        evaluate_energy_standalone(problem, x)
    }

    /// One Levenberg–Marquardt iteration at x (x updated in place only if a step is accepted).
    ///
    /// Evaluates residuals and Jacobians at x (the Gram products of constant blocks once per
    /// revision of the problem, see [`LeastSquaresProblem::block_jacobian_is_constant`]), solves
    /// (JᵀJ + μI) h = −Jᵀr (Schur-reduced), and
    /// accepts h when the gain ratio ρ = (E(x) − E(x+h)) / (L(0) − L(h)) is positive, with
    /// L(0) − L(h) = hᵀ(μh − Jᵀr) for E = ‖r‖². Accepted: μ ← μ·max(1/3, 1 − (2ρ − 1)³), ν ← 2;
    /// rejected (including failed factorisations and non-finite trial energies): μ ← μν, ν ← 2ν,
    /// and the damped system is re-solved, up to `max_trials`, without evaluating Jacobians again
    /// (except those of the local groups in a solve too large to keep their accumulated systems,
    /// see [`GroupSystems`]).
    /// Never accepts a step that raises E.
    ///
    /// Runs on a thread of the rayon pool (the calling thread if it is one), so that its short
    /// parallel passes fork from a worker rather than each waking the pool from outside.
    pub fn iterate<P: LeastSquaresProblem>(&mut self, problem: &P, x: &mut [f64]) -> Result<IterationOutcome, SolverError> {
        rayon::scope(|_| self.iterate_here(problem, x))
    }

    /// [`Self::iterate`] on the calling thread.
    fn iterate_here<P: LeastSquaresProblem>(&mut self, problem: &P, x: &mut [f64]) -> Result<IterationOutcome, SolverError> {
        self.check_unchanged(problem, x)?;
        self.accepted = false;
        // The constant blocks' share of H_GG is summed once per revision.
        let revision = problem.constant_jacobian_revision();
        let reuse_constant = self.constant_revision == Some(revision);
        self.constant_revision = None;
        // The blocks without a group are evaluated into their slots while the groups' blocks are
        // evaluated into their group systems and accumulated there. With μ already known, each
        // group is eliminated for the first trial right after its accumulation, while its
        // workspace is still in cache.
        let known_mu = self.mu;
        let (evaluated, eliminated) = {
            let (blocks, groups, slots, systems) = (&self.blocks, &self.groups, &mut self.slots, &mut self.systems);
            let x = &*x;
            rayon::join(
                || evaluate_slots(problem, blocks, x, slots, reuse_constant),
                || systems.accumulate(problem, x, blocks, groups, known_mu),
            )
        };
        let eliminated = lowest_block_error(evaluated, eliminated)?;
        if !reuse_constant {
            self.constant_hessian.refresh(problem, &self.blocks, &self.pattern, x);
        }
        self.constant_revision = Some(revision);
        let energy = reduce_blocks(
            &self.blocks,
            &self.pattern,
            &self.slots,
            &self.systems,
            &self.constant_hessian,
            &mut self.gradient,
            &mut self.hessian,
        );
        let mut first_elimination = known_mu.map(|mu| (mu, eliminated));
        let gradient_norm_inf = self.gradient.iter().fold(0.0, |m: f64, g| m.max(g.abs()));
        let mu = match self.mu {
            Some(mu) => mu,
            None => self.initial_damping(),
        };
        self.mu = Some(mu);
        let mut outcome = IterationOutcome {
            energy_before: energy,
            energy_after: energy,
            accepted: false,
            trials: 0,
            damping: mu,
            gradient_norm_inf,
            step_norm: 0.0,
            converged: None,
        };
        if gradient_norm_inf <= self.options.gradient_tolerance {
            outcome.converged = Some(Convergence::SmallGradient);
            return Ok(outcome);
        }
        if energy <= self.options.energy_tolerance {
            outcome.converged = Some(Convergence::SmallEnergy);
            return Ok(outcome);
        }
        let x_norm = x.iter().map(|v| v * v).sum::<f64>().sqrt();
        let mut factorised_once = false;
        while outcome.trials < self.options.max_trials {
            outcome.trials += 1;
            let mu = self.damping();
            let eliminated = first_elimination.take().filter(|&(known, _)| known == mu).map(|(_, ok)| ok);
            if self.solve_damped(problem, x, mu, eliminated) {
                factorised_once = true;
                outcome.step_norm = self.step.iter().map(|h| h * h).sum::<f64>().sqrt();
                let eps2 = self.options.step_tolerance;
                if outcome.step_norm <= eps2 * (x_norm + eps2) {
                    outcome.converged = Some(Convergence::SmallStep);
                    return Ok(outcome);
                }
                // L(0) − L(h) = hᵀ(μh − g) for E = ‖r‖² and (JᵀJ + μI)h = −g.
                let predicted: f64 = self.step.iter().zip(&self.gradient).map(|(h, g)| h * (mu * h - g)).sum();
                for ((t, xi), h) in self.trial_x.iter_mut().zip(x.iter()).zip(&self.step) {
                    *t = xi + h;
                }
                let trial = evaluate_energy_into(problem, &self.blocks, &self.trial_x, &mut self.trial_residuals);
                if let Some(trial_energy) = trial.filter(|&e| e < energy && predicted > 0.0) {
                    let rho = (energy - trial_energy) / predicted;
                    let factor = (1.0 - (2.0 * rho - 1.0).powi(3)).max(1.0 / 3.0);
                    self.set_damping(mu * factor);
                    self.nu = 2.0;
                    x.copy_from_slice(&self.trial_x);
                    self.accepted = true;
                    outcome.accepted = true;
                    outcome.energy_after = trial_energy;
                    outcome.damping = self.damping();
                    if trial_energy <= self.options.energy_tolerance {
                        outcome.converged = Some(Convergence::SmallEnergy);
                    }
                    return Ok(outcome);
                }
            }
            self.set_damping(mu * self.nu);
            self.nu = (2.0 * self.nu).min(MAX_GROWTH);
            outcome.damping = self.damping();
        }
        if factorised_once || self.options.max_trials == 0 {
            Ok(outcome)
        } else {
            Err(SolverError::FactorizationFailed { trials: outcome.trials })
        }
    }

    /// μ₀ = tau · max diag(JᵀJ) over global and local variables (tau itself for a zero Jacobian).
    /// The global diagonal adds the diagonals of the groups' G_L to that of H_GG.
    fn initial_damping(&mut self) -> f64 {
        self.global_diagonal.fill(0.0);
        for &(v, position) in &self.pattern.diagonal {
            self.global_diagonal[v as usize] += self.hessian[position];
        }
        for l in 0..self.groups.group_count() {
            for (&v, g) in self.groups.globals(l).iter().zip(self.systems.gram_diagonal(&self.groups, l)) {
                self.global_diagonal[v as usize] += g;
            }
        }
        let global_max = self.global_diagonal.iter().fold(0.0, |m: f64, &d| m.max(d));
        let max_diagonal = global_max.max(self.systems.max_diagonal(&self.groups));
        let scale = if max_diagonal > 0.0 { max_diagonal } else { 1.0 };
        self.clamp_damping(self.options.tau * scale)
    }

    fn clamp_damping(&self, mu: f64) -> f64 {
        if mu.is_nan() {
            return self.options.max_damping;
        }
        mu.clamp(self.options.min_damping, self.options.max_damping.max(self.options.min_damping))
    }

    fn set_damping(&mut self, mu: f64) {
        self.mu = Some(self.clamp_damping(mu));
    }

    /// Solves the damped normal equations for the step h (into `self.step`). `eliminated` is the
    /// outcome of the group eliminations if they were already done for this μ. Returns `false` if
    /// a factorisation fails or the step is not finite.
    fn solve_damped<P: LeastSquaresProblem>(&mut self, problem: &P, x: &[f64], mu: f64, eliminated: Option<bool>) -> bool {
        let eliminated = match eliminated {
            Some(ok) => ok,
            None => self.systems.eliminate(problem, x, &self.blocks, &self.groups, mu),
        };
        if !eliminated {
            return false;
        }
        let g = self.blocks.global_count;
        let (global_step, local_step) = self.step.split_at_mut(g);
        let reduced = ReducedSystem {
            pattern: &self.pattern,
            gather: &self.gather,
            systems: &self.systems,
            hessian: &self.hessian,
            gradient: &self.gradient[..g],
            mu,
        };
        if let Some(cholesky) = self.cholesky.as_mut() {
            if !cholesky.factorize_with(|values| reduced.fill_values(values)) {
                return false;
            }
            reduced.fill_rhs(global_step);
            cholesky.solve_in_place(global_step);
        }
        self.systems.back_substitute(&self.groups, global_step, local_step);
        self.step.iter().all(|h| h.is_finite())
    }

    /// The counts the workspaces were sized for must still hold.
    fn check_unchanged<P: LeastSquaresProblem>(&self, problem: &P, x: &[f64]) -> Result<(), SolverError> {
        let n = self.blocks.variable_count;
        if x.len() != n {
            return Err(SolverError::WrongVariableCount { expected: n, found: x.len() });
        }
        let changed = |message: String| Err(SolverError::ProblemChanged { message });
        if problem.variable_count() != n {
            return changed(format!("variable count {} != {n}", problem.variable_count()));
        }
        if problem.block_count() != self.blocks.block_count() {
            return changed(format!("block count {} != {}", problem.block_count(), self.blocks.block_count()));
        }
        for b in 0..self.blocks.block_count() {
            if problem.block_residual_count(b) != self.blocks.residual_count(b)
                || problem.block_variables(b) != self.blocks.variables(b)
                || problem.block_jacobian_is_constant(b) != self.blocks.constant_jacobian[b]
            {
                return changed(format!("structure of block {b} changed"));
            }
        }
        Ok(())
    }
}

/// The evaluation's outcome from its two parts (the blocks without a group, and the groups'
/// blocks with their accumulation): the error of the lower block if both fail, so that errors
/// name the lowest non-finite block.
fn lowest_block_error(slots: Result<(), SolverError>, groups: Result<bool, SolverError>) -> Result<bool, SolverError> {
    let block = |error: &SolverError| match error {
        SolverError::NonFiniteResidual { block } | SolverError::NonFiniteJacobian { block } => *block,
        _ => usize::MAX,
    };
    match (slots, groups) {
        (Ok(()), groups) => groups,
        (Err(error), Ok(_)) => Err(error),
        (Err(a), Err(b)) => Err(if block(&b) < block(&a) { b } else { a }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::solver::VariableLayout;
    use std::sync::atomic::{AtomicUsize, Ordering};

    /// Points p_i ∈ R² (a local group each) pulled onto circles of radius a_i (globals, tied
    /// along a chain): group blocks [‖p_i‖² − a_i², p_i − c_i] over (p_i, a_i); global blocks
    /// a_{i+1} − a_i − 0.05 and a_0 − 1.
    struct PointsOnCircles {
        n: usize,
        variables: Vec<Vec<u32>>,
        group_jacobians: AtomicUsize,
    }

    impl PointsOnCircles {
        fn new(n: usize) -> Self {
            let g = n as u32;
            let mut variables: Vec<Vec<u32>> = (0..g).map(|i| vec![g + 2 * i, g + 2 * i + 1, i]).collect();
            variables.extend((1..g).map(|i| vec![i, i - 1]));
            variables.push(vec![0]);
            Self { n, variables, group_jacobians: AtomicUsize::new(0) }
        }

        fn target(i: usize) -> [f64; 2] {
            let t = i as f64;
            [3.0 * (0.4 * t).cos(), 2.0 * (0.9 * t).sin()]
        }
    }

    impl LeastSquaresProblem for PointsOnCircles {
        fn variable_count(&self) -> usize {
            3 * self.n
        }
        fn block_count(&self) -> usize {
            self.variables.len()
        }
        fn block_variables(&self, b: usize) -> &[u32] {
            &self.variables[b]
        }
        fn block_residual_count(&self, b: usize) -> usize {
            if b < self.n {
                3
            } else {
                1
            }
        }
        fn evaluate_block(&self, b: usize, x: &[f64], r: &mut [f64], jacobian: Option<&mut [f64]>) {
            let v = |k: usize| x[self.variables[b][k] as usize];
            if b < self.n {
                let [cx, cy] = Self::target(b);
                let (px, py, a) = (v(0), v(1), v(2));
                r.copy_from_slice(&[px * px + py * py - a * a, px - cx, py - cy]);
                if let Some(j) = jacobian {
                    self.group_jacobians.fetch_add(1, Ordering::Relaxed);
                    j.copy_from_slice(&[2.0 * px, 2.0 * py, -2.0 * a, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0]);
                }
            } else if b < 2 * self.n - 1 {
                r[0] = v(0) - v(1) - 0.05;
                if let Some(j) = jacobian {
                    j.copy_from_slice(&[1.0, -1.0]);
                }
            } else {
                r[0] = v(0) - 1.0;
                if let Some(j) = jacobian {
                    j[0] = 1.0;
                }
            }
        }
        fn variable_layout(&self) -> VariableLayout {
            VariableLayout::with_local_groups(self.n, &vec![2; self.n]).unwrap()
        }
    }

    /// Solves from x = 0.5 with almost no initial damping (so that early steps overshoot and are
    /// retried); the bits of x, E and μ after each iteration, the trials, and the group Jacobians
    /// evaluated per iteration.
    fn run(kept_limit: usize) -> (bool, Vec<u64>, Vec<usize>, Vec<usize>) {
        let problem = PointsOnCircles::new(40);
        let options = LmOptions { tau: 1e-12, ..LmOptions::default() };
        let mut solver = LevenbergMarquardt::build(&problem, options, SplitWork::Span, kept_limit).unwrap();
        let mut x = vec![0.5; problem.variable_count()];
        let (mut bits, mut trials, mut evaluations) = (Vec::new(), Vec::new(), Vec::new());
        for _ in 0..8 {
            let before = problem.group_jacobians.load(Ordering::Relaxed);
            let outcome = solver.iterate(&problem, &mut x).unwrap();
            evaluations.push(problem.group_jacobians.load(Ordering::Relaxed) - before);
            trials.push(outcome.trials);
            bits.extend([outcome.energy_after.to_bits(), outcome.damping.to_bits()]);
            bits.extend(x.iter().map(|v| v.to_bits()));
        }
        (solver.systems.keeps_accumulation(), bits, trials, evaluations)
    }

    #[test]
    fn kept_accumulations_spare_the_evaluation_of_a_retry_and_change_no_bit() {
        let (kept, kept_bits, kept_trials, kept_evaluations) = run(usize::MAX);
        let (evaluated, bits, trials, evaluations) = run(0);
        assert!(kept && !evaluated);
        assert!(kept_bits == bits, "keeping the accumulations changed the result");
        assert_eq!(kept_trials, trials);
        assert!(trials.iter().any(|&t| t > 1), "no trial was retried: {trials:?}");
        // One evaluation of the 40 group blocks per iteration when kept, one per trial when not.
        assert!(kept_evaluations.iter().all(|&e| e == 40), "{kept_evaluations:?}");
        for (e, t) in evaluations.iter().zip(&trials) {
            assert_eq!(*e, 40 * t, "{evaluations:?} for trials {trials:?}");
        }
    }
}
