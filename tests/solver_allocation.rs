//! After the first call, `iterate` does not allocate (all workspaces are sized by `new`).
//!
//! Measured in a one-thread rayon pool: with more threads, rayon's work-stealing deques grow and
//! shrink their buffers depending on how the OS schedules the workers, which allocates inside
//! rayon (seen as rare failures on a loaded machine) and says nothing about Lamella's code. The
//! parallel code paths are the same ones, run by one worker.
use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

use lamella::solver::{LeastSquaresProblem, LevenbergMarquardt, LmOptions, VariableLayout};

struct Counting;

static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::Relaxed);
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

/// Points p_i ∈ R² (local groups of 2) pulled to the unit circle and towards offsets of a
/// chain of global scalars a_i: r = (‖p_i‖² − 1, p_i.x − a_i − a_{i+1}, p_i.y − 0.1 i), plus
/// chain smoothness a_{i+1} − a_i.
struct CircleChain {
    n: usize,
    variables: Vec<Vec<u32>>,
}

impl CircleChain {
    fn new(n: usize) -> Self {
        let g = (n + 1) as u32;
        let mut variables: Vec<Vec<u32>> = (0..n as u32).map(|i| vec![g + 2 * i, g + 2 * i + 1, i, i + 1]).collect();
        variables.extend((0..n as u32).map(|i| vec![i, i + 1]));
        Self { n, variables }
    }
}

impl LeastSquaresProblem for CircleChain {
    fn variable_count(&self) -> usize {
        3 * self.n + 1
    }
    fn block_count(&self) -> usize {
        2 * self.n
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
            let (px, py) = (v(0), v(1));
            r.copy_from_slice(&[px * px + py * py - 1.0, px - v(2) - v(3), py - 0.1 * b as f64]);
            if let Some(j) = jacobian {
                j.copy_from_slice(&[2.0 * px, 2.0 * py, 0.0, 0.0, 1.0, 0.0, -1.0, -1.0, 0.0, 1.0, 0.0, 0.0]);
            }
        } else {
            r[0] = v(1) - v(0);
            if let Some(j) = jacobian {
                j.copy_from_slice(&[-1.0, 1.0]);
            }
        }
    }
    fn variable_layout(&self) -> VariableLayout {
        VariableLayout::with_local_groups(self.n + 1, &vec![2; self.n]).unwrap()
    }
}

#[test]
fn iterate_does_not_allocate_after_the_first_call() {
    let problem = CircleChain::new(400);
    let pool = rayon::ThreadPoolBuilder::new().num_threads(1).build().unwrap();
    pool.install(|| {
        let mut x = vec![0.3; problem.variable_count()];
        let mut solver = LevenbergMarquardt::new(&problem, LmOptions::default()).unwrap();
        solver.iterate(&problem, &mut x).unwrap();
        let before = ALLOCATIONS.load(Ordering::Relaxed);
        let mut accepted = 0;
        for _ in 0..5 {
            accepted += usize::from(solver.iterate(&problem, &mut x).unwrap().accepted);
        }
        let allocations = ALLOCATIONS.load(Ordering::Relaxed) - before;
        assert!(accepted > 0);
        assert_eq!(allocations, 0, "iterate allocated {allocations} times");
    });
}
