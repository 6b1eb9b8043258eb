//! Malformed problems and non-finite evaluations give errors, never panics.
use lamella::solver::{LeastSquaresProblem, LevenbergMarquardt, LmOptions, SolverError, VariableLayout};

/// Linear residuals x_v − 1 per declared variable, optionally NaN in one block or its Jacobian.
struct Configurable {
    n: usize,
    blocks: Vec<Vec<u32>>,
    groups: Option<(usize, Vec<usize>)>,
    nan_residual_block: Option<usize>,
    nan_jacobian_block: Option<usize>,
}

impl Configurable {
    fn new(n: usize, blocks: Vec<Vec<u32>>) -> Self {
        Self { n, blocks, groups: None, nan_residual_block: None, nan_jacobian_block: None }
    }
}

impl LeastSquaresProblem for Configurable {
    fn variable_count(&self) -> usize {
        self.n
    }
    fn block_count(&self) -> usize {
        self.blocks.len()
    }
    fn block_variables(&self, b: usize) -> &[u32] {
        &self.blocks[b]
    }
    fn block_residual_count(&self, b: usize) -> usize {
        self.blocks[b].len()
    }
    fn evaluate_block(&self, b: usize, x: &[f64], r: &mut [f64], jacobian: Option<&mut [f64]>) {
        let k = self.blocks[b].len();
        for (i, &v) in self.blocks[b].iter().enumerate() {
            r[i] = if self.nan_residual_block == Some(b) { f64::NAN } else { x[v as usize] - 1.0 };
        }
        if let Some(j) = jacobian {
            for i in 0..k {
                j[i * k + i] = if self.nan_jacobian_block == Some(b) { f64::INFINITY } else { 1.0 };
            }
        }
    }
    fn variable_layout(&self) -> VariableLayout {
        match &self.groups {
            Some((g, sizes)) => VariableLayout::with_local_groups(*g, sizes).unwrap(),
            None => VariableLayout::all_global(self.n),
        }
    }
}

fn build_error(problem: &Configurable) -> SolverError {
    match LevenbergMarquardt::new(problem, LmOptions::default()) {
        Ok(_) => panic!("malformed problem accepted"),
        Err(e) => e,
    }
}

#[test]
fn variable_index_out_of_range_is_rejected() {
    let e = build_error(&Configurable::new(3, vec![vec![0, 1], vec![2, 3]]));
    assert!(matches!(e, SolverError::InvalidProblem { block: 1, .. }), "{e}");
}

#[test]
fn duplicate_variable_in_a_block_is_rejected() {
    let e = build_error(&Configurable::new(3, vec![vec![0, 2, 0]]));
    assert!(matches!(e, SolverError::InvalidProblem { block: 0, .. }), "{e}");
}

#[test]
fn block_touching_two_local_groups_is_rejected() {
    let mut problem = Configurable::new(6, vec![vec![0, 2], vec![1, 3, 5]]);
    problem.groups = Some((2, vec![2, 2]));
    let e = build_error(&problem);
    assert!(matches!(e, SolverError::InvalidProblem { block: 1, .. }), "{e}");
    assert!(!e.to_string().is_empty());
}

#[test]
fn layout_not_covering_the_variables_is_rejected() {
    let mut problem = Configurable::new(6, vec![vec![0, 2]]);
    problem.groups = Some((2, vec![2]));
    assert!(matches!(build_error(&problem), SolverError::InvalidLayout { .. }));
    assert!(matches!(VariableLayout::with_local_groups(2, &[3, 0]), Err(SolverError::InvalidLayout { .. })));
}

#[test]
fn non_finite_residual_and_jacobian_name_the_block() {
    let mut problem = Configurable::new(4, vec![vec![0], vec![1, 2], vec![3]]);
    problem.nan_residual_block = Some(1);
    let mut solver = LevenbergMarquardt::new(&problem, LmOptions::default()).unwrap();
    let mut x = vec![0.0; 4];
    let e = solver.iterate(&problem, &mut x).unwrap_err();
    assert_eq!(e, SolverError::NonFiniteResidual { block: 1 });
    assert_eq!(x, vec![0.0; 4]);
    problem.nan_residual_block = None;
    problem.nan_jacobian_block = Some(2);
    let e = solver.iterate(&problem, &mut x).unwrap_err();
    assert_eq!(e, SolverError::NonFiniteJacobian { block: 2 });
    assert_eq!(LevenbergMarquardt::evaluate_energy(&problem, &x), 4.0);
}

#[test]
fn non_finite_blocks_of_local_groups_are_named_and_the_lowest_block_wins() {
    // Blocks 1 and 3 belong to the local groups {4} and {5}; blocks 0 and 2 are global. The
    // groups' blocks are evaluated in their own pass: the error still names the lowest block.
    let mut problem = Configurable::new(6, vec![vec![0], vec![1, 4], vec![2], vec![3, 5]]);
    problem.groups = Some((4, vec![1, 1]));
    let mut solver = LevenbergMarquardt::new(&problem, LmOptions::default()).unwrap();
    let mut x = vec![0.0; 6];
    let mut error = |residual: Option<usize>, jacobian: Option<usize>| {
        problem.nan_residual_block = residual;
        problem.nan_jacobian_block = jacobian;
        solver.iterate(&problem, &mut x).unwrap_err()
    };
    assert_eq!(error(Some(1), None), SolverError::NonFiniteResidual { block: 1 });
    assert_eq!(error(None, Some(3)), SolverError::NonFiniteJacobian { block: 3 });
    assert_eq!(error(Some(2), Some(3)), SolverError::NonFiniteResidual { block: 2 });
    assert_eq!(error(Some(3), Some(1)), SolverError::NonFiniteJacobian { block: 1 });
    assert_eq!(error(Some(0), Some(1)), SolverError::NonFiniteResidual { block: 0 });
    assert_eq!(x, vec![0.0; 6]);
    // Finite again: the solver steps (to x = 1 everywhere).
    problem.nan_residual_block = None;
    problem.nan_jacobian_block = None;
    let outcome = solver.iterate(&problem, &mut x).unwrap();
    assert!(outcome.accepted && outcome.energy_after < 0.5 * outcome.energy_before, "{outcome:?}");
}

#[test]
fn wrong_variable_vector_length_is_an_error() {
    let problem = Configurable::new(3, vec![vec![0, 1, 2]]);
    let mut solver = LevenbergMarquardt::new(&problem, LmOptions::default()).unwrap();
    let e = solver.iterate(&problem, &mut [0.0; 2]).unwrap_err();
    assert_eq!(e, SolverError::WrongVariableCount { expected: 3, found: 2 });
    assert_eq!(LevenbergMarquardt::evaluate_energy(&problem, &[0.0; 2]), f64::INFINITY);
}

#[test]
fn changed_problem_structure_is_an_error() {
    let problem = Configurable::new(3, vec![vec![0, 1, 2]]);
    let other = Configurable::new(3, vec![vec![0, 1], vec![2]]);
    let mut solver = LevenbergMarquardt::new(&problem, LmOptions::default()).unwrap();
    let e = solver.iterate(&other, &mut [0.0; 3]).unwrap_err();
    assert!(matches!(e, SolverError::ProblemChanged { .. }), "{e}");
}

#[test]
fn linear_problem_with_groups_and_unused_variables_is_solved_in_one_step() {
    // Variable 1 appears in no block; its step must be exactly zero, not NaN.
    let mut problem = Configurable::new(6, vec![vec![0, 3], vec![2, 4, 5]]);
    problem.groups = Some((3, vec![1, 2]));
    let mut solver = LevenbergMarquardt::new(&problem, LmOptions { tau: 1e-12, ..LmOptions::default() }).unwrap();
    let mut x = vec![0.0; 6];
    let outcome = solver.iterate(&problem, &mut x).unwrap();
    assert!(outcome.accepted);
    assert_eq!(x[1], 0.0);
    for &v in &[0, 2, 3, 4, 5] {
        assert!((x[v] - 1.0).abs() < 1e-9, "{x:?}");
    }
}
