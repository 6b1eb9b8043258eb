//! Cholesky solve of the reduced normal matrix A by substructuring (one level of nested
//! dissection): the global variables are split into two domains and a separator S that no block
//! couples across ([`super::bisection`]), so A is the sum of two domain matrices
//!
//! ```text
//! A⁽ᵈ⁾ = [ A_II⁽ᵈ⁾  A_IS⁽ᵈ⁾ ]  =  L⁽ᵈ⁾ L⁽ᵈ⁾ᵀ,   L⁽ᵈ⁾ = [ L_II⁽ᵈ⁾   0   ]
//!        [ A_SI⁽ᵈ⁾  A_SS⁽ᵈ⁾ ]                        [ C⁽ᵈ⁾    R⁽ᵈ⁾ ]
//! ```
//!
//! each assembled from the blocks and groups of its domain (the separator's diagonal damping
//! split in halves). Both are positive definite and are factorised at the same time, one per
//! thread. Eliminating the interiors leaves the separator's Schur complement
//! `Ã = A_SS − Σ_d C⁽ᵈ⁾C⁽ᵈ⁾ᵀ = Σ_d R⁽ᵈ⁾R⁽ᵈ⁾ᵀ`, a small dense matrix factorised last.
//!
//! Every step runs sequentially inside its domain and the dense work is sequential, so the
//! results do not depend on the number of threads. Small or poorly separable patterns use one
//! domain and no separator: a plain sparse Cholesky.
use faer::dyn_stack::{MemBuffer, MemStack, StackReq};
use faer::linalg::cholesky::llt;
use faer::linalg::matmul::triangular::{self, BlockStructure};
use faer::{Accum, Conj, Mat, MatMut, Par};
use std::sync::atomic::{AtomicBool, Ordering};

use super::bisection::{candidate_cuts, Part};
use super::sparse_cholesky::SparseCholesky;
use super::SolverError;

/// What splitting the matrix into two domains, factorised at the same time with a dense
/// separator last, must lower to be taken (counted in floating-point operations from the
/// symbolic analyses, once, when the solver is built).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum SplitWork {
    /// The time on two cores: the larger domain's factorisation, then the separator's dense work.
    Span,
    /// The work on both cores together: for a solve that shares the cores with another one
    /// running beside it (the start search's probes), where a split that shortens each solve's
    /// span but adds operations slows the pair down.
    Total,
}

pub(crate) struct SubstructuredCholesky {
    dimension: usize,
    /// One or two domains; their matrices are stored one after the other in `values`.
    domains: Vec<Domain>,
    values: Vec<f64>,
    /// The caller's variable of each separator index.
    separator: Vec<usize>,
    /// Ã, then its Cholesky factor (lower triangle; rows padded, see [`padded_square`]).
    schur: Mat<f64>,
    dense_scratch: MemBuffer,
    /// Separator right-hand side, then solution.
    separator_rhs: Vec<f64>,
}

struct Domain {
    cholesky: SparseCholesky,
    /// The domain's values start at this offset of the shared storage.
    offset: usize,
    /// Right-hand side and solution in the factor's order.
    work: Vec<f64>,
    /// R⁽ᵈ⁾, the factor's trailing separator block (lower triangle; rows padded).
    separator_factor: Mat<f64>,
    /// R⁽ᵈ⁾R⁽ᵈ⁾ᵀ (lower triangle; rows padded), the domain's share of Ã.
    separator_product: Mat<f64>,
    /// C⁽ᵈ⁾ L_II⁽ᵈ⁾⁻¹ b_I, the domain's reduction of the separator's right-hand side.
    separator_reduction: Vec<f64>,
}

impl SubstructuredCholesky {
    /// Bisection, orderings and symbolic analyses of the matrix with the upper-triangular CSC
    /// pattern `col_ptr`, `row_idx` (sorted rows, diagonal present).
    /// A split is taken where it lowers `work` ([`split_or_whole`]).
    pub fn analyse(col_ptr: &[usize], row_idx: &[usize], work: SplitWork) -> Result<Self, SolverError> {
        let n = col_ptr.len() - 1;
        let (mut domains, separator) = split_or_whole(col_ptr, row_idx, work)?;
        let mut offset = 0;
        for domain in &mut domains {
            domain.offset = offset;
            offset += domain.cholesky.value_count();
        }
        let s = separator.len();
        let dense_scratch = MemBuffer::try_new(StackReq::or(
            llt::factor::cholesky_in_place_scratch::<f64>(s, Par::Seq, Default::default()),
            llt::solve::solve_in_place_scratch::<f64>(s, 1, Par::Seq),
        ))
        .map_err(|e| SolverError::SymbolicAnalysisFailed { message: format!("{e:?}") })?;
        Ok(Self {
            dimension: n,
            domains,
            values: vec![0.0; offset],
            schur: padded_square(s),
            dense_scratch,
            separator_rhs: vec![0.0; s],
            separator,
        })
    }

    /// For each domain, the storage position of every entry of the caller's pattern that
    /// belongs to it (`usize::MAX` for the others): `original_count` is the pattern's length.
    /// Asked once, when the caller sets up its assembly (the maps it is made from are freed).
    pub fn storage_positions(&mut self, original_count: usize) -> Vec<Vec<usize>> {
        self.domains
            .iter_mut()
            .map(|domain| {
                let mut position = vec![usize::MAX; original_count];
                for (p, &t) in domain.cholesky.take_original_positions().iter().enumerate() {
                    position[t] = domain.offset + p;
                }
                position
            })
            .collect()
    }

    /// The domain whose interior holds each variable (`None` for separator variables).
    pub fn domains_of_variables(&self) -> Vec<Option<usize>> {
        let mut domain_of = vec![None; self.dimension];
        for (d, domain) in self.domains.iter().enumerate() {
            let variables = domain.cholesky.variables();
            for &v in &variables[..variables.len() - self.separator.len()] {
                domain_of[v] = Some(d);
            }
        }
        domain_of
    }

    /// Numeric factorisation. `fill(values)` writes the domain matrices into the shared storage
    /// (see [`Self::storage_positions`]). Returns `false` if A is not numerically positive
    /// definite.
    pub fn factorize_with(&mut self, fill: impl FnOnce(&mut [f64])) -> bool {
        fill(&mut self.values);
        let values = &self.values;
        let factorised = AtomicBool::new(true);
        for_each_domain(&mut self.domains, |domain| {
            if !domain.factorize(values) {
                factorised.store(false, Ordering::Relaxed);
            }
        });
        factorised.into_inner() && self.factorize_separator()
    }

    /// Ã = Σ_d R⁽ᵈ⁾R⁽ᵈ⁾ᵀ and its dense Cholesky factor.
    fn factorize_separator(&mut self) -> bool {
        let s = self.separator.len();
        if s == 0 {
            return true;
        }
        let mut schur = self.schur.as_mut().subrows_mut(0, s);
        for j in 0..s {
            for i in j..s {
                schur[(i, j)] = self.domains.iter().map(|d| d.separator_product[(i, j)]).sum();
            }
        }
        llt::factor::cholesky_in_place(schur, Default::default(), Par::Seq, MemStack::new(&mut self.dense_scratch), Default::default()).is_ok()
    }

    /// Solves A x = b in place (`rhs` indexed by the caller's variables) with the last
    /// successful factorisation.
    pub fn solve_in_place(&mut self, rhs: &mut [f64]) {
        let s = self.separator.len();
        // Forward: y = L_II⁻¹ b_I per domain, and its reduction c = C y of the separator's
        // right-hand side (the factor's trailing rows give R⁻¹(0 − c), so c = −R·(that)).
        let input: &[f64] = rhs;
        for_each_domain(&mut self.domains, |domain| domain.forward(input));
        for (i, &v) in self.separator.iter().enumerate() {
            let mut value = rhs[v];
            for domain in &self.domains {
                value -= domain.separator_reduction[i];
            }
            self.separator_rhs[i] = value;
        }
        if s > 0 {
            llt::solve::solve_in_place_with_conj(
                self.schur.as_ref().subrows(0, s),
                Conj::No,
                MatMut::from_column_major_slice_mut(&mut self.separator_rhs, s, 1),
                Par::Seq,
                MemStack::new(&mut self.dense_scratch),
            );
        }
        // Backward: x_I = L_II⁻ᵀ(y − Cᵀ x_S), through Lᵀ with the trailing rows set to Rᵀ x_S.
        let x_separator = &self.separator_rhs;
        for_each_domain(&mut self.domains, |domain| domain.backward(x_separator));
        for domain in &self.domains {
            let variables = domain.cholesky.variables();
            let interior = variables.len() - s;
            for (&v, &x) in variables[..interior].iter().zip(&domain.work) {
                rhs[v] = x;
            }
        }
        for (&v, &x) in self.separator.iter().zip(&self.separator_rhs) {
            rhs[v] = x;
        }
    }
}

/// Calls `f` on every domain, the two of a split at the same time.
fn for_each_domain(domains: &mut [Domain], f: impl Fn(&mut Domain) + Sync) {
    match domains {
        [only] => f(only),
        [first, second] => {
            rayon::join(|| f(first), || f(second));
        }
        _ => {}
    }
}

/// The domains and the separator: of the bisection's cuts ([`candidate_cuts`]) the one whose
/// split costs the least `work`, if that is below the whole matrix's factorisation; else one
/// domain and no separator. A split costs each domain's sparse factorisation (its trailing
/// separator block included), R⁽ᵈ⁾R⁽ᵈ⁾ᵀ (s³/3 per domain) and the Cholesky of Ã (s³/3), counted
/// from the supernodal structures ([`SparseCholesky::flops`]). A cut with a smaller separator
/// can still cost more (domains of unequal density), and a cut across a chain-like pattern (a
/// strip's problem) can cost each domain more than the whole matrix. The choice depends on the
/// pattern and `work` only, not on the threads.
fn split_or_whole(col_ptr: &[usize], row_idx: &[usize], work: SplitWork) -> Result<(Vec<Domain>, Vec<usize>), SolverError> {
    let n = col_ptr.len() - 1;
    // The whole matrix's analysis is kept until a cut beats it; the cuts' analyses are only
    // counted and dropped, so that no more than three are held at a time (a design's peak
    // memory), and the winner's are made again at the end.
    enum Choice {
        Whole(SparseCholesky),
        Cut(Vec<Part>, Vec<usize>),
    }
    let whole = Domain::analyse(col_ptr, row_idx, &vec![Part::Domain(0); n], 0, &[])?;
    let mut least = whole.flops();
    let mut choice = Choice::Whole(whole);
    for parts in candidate_cuts(col_ptr, row_idx) {
        let separator: Vec<usize> = (0..n).filter(|&v| parts[v] == Part::Separator).collect();
        let [first, second] = analyse_split(col_ptr, row_idx, &parts, &separator)?.map(|domain| domain.flops());
        let dense = (separator.len() as f64).powi(3) / 3.0;
        let cost = match work {
            SplitWork::Span => first.max(second) + 2.0 * dense,
            SplitWork::Total => first + second + 3.0 * dense,
        };
        if cost < least {
            (least, choice) = (cost, Choice::Cut(parts, separator));
        }
    }
    Ok(match choice {
        Choice::Whole(whole) => (vec![Domain::new(whole, 0)], Vec::new()),
        Choice::Cut(parts, separator) => {
            let s = separator.len();
            (analyse_split(col_ptr, row_idx, &parts, &separator)?.map(|domain| Domain::new(domain, s)).into(), separator)
        }
    })
}

/// The orderings and symbolic analyses of the two domains of the split `parts`, made at once.
fn analyse_split(col_ptr: &[usize], row_idx: &[usize], parts: &[Part], separator: &[usize]) -> Result<[SparseCholesky; 2], SolverError> {
    let analyse = |d: u8| Domain::analyse(col_ptr, row_idx, parts, d, separator);
    let (first, second) = rayon::join(|| analyse(0), || analyse(1));
    Ok([first?, second?])
}

/// An s × s dense matrix stored with its row count rounded up to a multiple of 8, the zero rows
/// beyond s included, so that its column stride has no padding of its own (use the view of the
/// first s rows). faer's SIMD kernels read the padding of a column; `Mat::zeros` leaves it as
/// the allocator hands it out, and stale integers there read as subnormal floats, which made one
/// 119 × 119 Cholesky 7× slower.
fn padded_square(s: usize) -> Mat<f64> {
    Mat::zeros(s.next_multiple_of(8), s)
}

impl Domain {
    /// Ordering and symbolic analysis of domain `d` of the split `parts` (its interior, then the
    /// separator).
    fn analyse(col_ptr: &[usize], row_idx: &[usize], parts: &[Part], d: u8, separator: &[usize]) -> Result<SparseCholesky, SolverError> {
        let n = col_ptr.len() - 1;
        let interior: Vec<usize> = (0..n).filter(|&v| parts[v] == Part::Domain(d)).collect();
        let mut local = vec![usize::MAX; n];
        for (i, &v) in interior.iter().chain(separator).enumerate() {
            local[v] = i;
        }
        SparseCholesky::analyse(col_ptr, row_idx, &interior, separator, &local)
    }

    /// The domain of an analysis whose trailing `s` variables are the separator, with its
    /// workspaces; its storage offset is set by the caller.
    fn new(cholesky: SparseCholesky, s: usize) -> Self {
        Domain {
            work: vec![0.0; cholesky.variables().len()],
            cholesky,
            offset: 0,
            separator_factor: padded_square(s),
            separator_product: padded_square(s),
            separator_reduction: vec![0.0; s],
        }
    }

    /// Numeric factorisation of the domain matrix, then R⁽ᵈ⁾ and R⁽ᵈ⁾R⁽ᵈ⁾ᵀ.
    fn factorize(&mut self, values: &[f64]) -> bool {
        let len = self.cholesky.value_count();
        if !self.cholesky.factorize(&values[self.offset..self.offset + len]) {
            return false;
        }
        let s = self.separator_reduction.len();
        if s == 0 {
            return true;
        }
        self.cholesky.separator_block(self.separator_factor.as_mut().subrows_mut(0, s));
        let r = self.separator_factor.as_ref().subrows(0, s);
        triangular::matmul(
            self.separator_product.as_mut().subrows_mut(0, s),
            BlockStructure::TriangularLower,
            Accum::Replace,
            r,
            BlockStructure::TriangularLower,
            r.transpose(),
            BlockStructure::TriangularUpper,
            1.0,
            Par::Seq,
        );
        true
    }

    /// y = L_II⁻¹ b_I, and the separator reduction C y.
    fn forward(&mut self, rhs: &[f64]) {
        let s = self.separator_reduction.len();
        let r = self.separator_factor.as_ref();
        let variables = self.cholesky.variables();
        let interior = variables.len() - s;
        for (w, &v) in self.work.iter_mut().zip(&variables[..interior]) {
            *w = rhs[v];
        }
        self.work[interior..].fill(0.0);
        self.cholesky.forward_solve(&mut self.work);
        let trailing = &self.work[interior..];
        for (i, c) in self.separator_reduction.iter_mut().enumerate() {
            *c = -(0..=i).map(|j| r[(i, j)] * trailing[j]).sum::<f64>();
        }
    }

    /// x_I = L_II⁻ᵀ(y − Cᵀ x_S).
    fn backward(&mut self, x_separator: &[f64]) {
        let s = x_separator.len();
        let r = self.separator_factor.as_ref();
        let interior = self.work.len() - s;
        for j in 0..s {
            self.work[interior + j] = (j..s).map(|i| r[(i, j)] * x_separator[i]).sum();
        }
        self.cholesky.backward_solve(&mut self.work);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Element cliques of a w × h grid of quads (vertex x + w·y), each with a positive
    /// semidefinite element matrix v vᵀ, plus a diagonal `shift`: A = Σ_e v_e v_eᵀ + shift·I.
    struct QuadProblem {
        n: usize,
        cliques: Vec<[usize; 4]>,
        vectors: Vec<[f64; 4]>,
        shift: f64,
    }

    impl QuadProblem {
        fn new(w: usize, h: usize, shift: f64) -> Self {
            let mut cliques = Vec::new();
            let mut vectors = Vec::new();
            for y in 0..h - 1 {
                for x in 0..w - 1 {
                    let v = x + w * y;
                    cliques.push([v, v + 1, v + w, v + w + 1]);
                    // Deterministic, varied entries (a difference stencil plus a twist).
                    let k = (v % 7) as f64;
                    vectors.push([1.0 + 0.1 * k, -1.0, 0.5 - 0.05 * k, -0.4]);
                }
            }
            Self { n: w * h, cliques, vectors, shift }
        }

        /// Adds `count` cliques that each couple two pairs of far-apart variables.
        fn with_long_range_couplings(mut self, count: usize) -> Self {
            for k in 0..count {
                let (a, b) = ((k * 7919) % (self.n - 1), (k * 104_729 + self.n / 2) % (self.n - 1));
                if a.abs_diff(b) > 1 {
                    self.cliques.push([a, a + 1, b, b + 1]);
                    self.vectors.push([0.3, -0.2, 0.25, -0.1]);
                }
            }
            self
        }

        /// Upper CSC pattern (sorted rows, diagonal present).
        fn pattern(&self) -> (Vec<usize>, Vec<usize>) {
            let mut rows: Vec<Vec<usize>> = (0..self.n).map(|c| vec![c]).collect();
            for clique in &self.cliques {
                for &r in clique {
                    for &c in clique {
                        if r < c {
                            rows[c].push(r);
                        }
                    }
                }
            }
            let (mut col_ptr, mut row_idx) = (vec![0], Vec::new());
            for mut column in rows {
                column.sort_unstable();
                column.dedup();
                row_idx.extend(column);
                col_ptr.push(row_idx.len());
            }
            (col_ptr, row_idx)
        }

        /// Writes the domain matrices as the solver's assembly does: each clique into the domain
        /// of its variables, the shift shared between the copies of a separator diagonal.
        fn fill(&self, layout: &Layout, col_ptr: &[usize], row_idx: &[usize], values: &mut [f64]) {
            let (storage, domain_of) = layout;
            let position = |r: usize, c: usize| col_ptr[c] + row_idx[col_ptr[c]..col_ptr[c + 1]].binary_search(&r).unwrap();
            values.fill(0.0);
            for (clique, v) in self.cliques.iter().zip(&self.vectors) {
                let d = clique.iter().find_map(|&i| domain_of[i]).unwrap_or(0);
                for a in 0..4 {
                    for b in 0..4 {
                        if clique[a] <= clique[b] {
                            values[storage[d][position(clique[a], clique[b])]] += v[a] * v[b];
                        }
                    }
                }
            }
            for i in 0..self.n {
                let copies: Vec<usize> = storage.iter().map(|s| s[position(i, i)]).filter(|&p| p != usize::MAX).collect();
                for &p in &copies {
                    values[p] += self.shift / copies.len() as f64;
                }
            }
        }

        fn multiply(&self, x: &[f64]) -> Vec<f64> {
            let mut y: Vec<f64> = x.iter().map(|xi| self.shift * xi).collect();
            for (clique, v) in self.cliques.iter().zip(&self.vectors) {
                let dot: f64 = (0..4).map(|a| v[a] * x[clique[a]]).sum();
                for a in 0..4 {
                    y[clique[a]] += v[a] * dot;
                }
            }
            y
        }
    }

    /// Storage positions and domains of the variables, as the solver's assembly uses them.
    type Layout = (Vec<Vec<usize>>, Vec<Option<usize>>);

    fn layout(cholesky: &mut SubstructuredCholesky, nnz: usize) -> Layout {
        (cholesky.storage_positions(nnz), cholesky.domains_of_variables())
    }

    fn solve(problem: &QuadProblem) -> (SubstructuredCholesky, Vec<f64>, Vec<f64>) {
        solve_with_work(problem, SplitWork::Span)
    }

    /// max |A x − b|.
    fn worst_residual(problem: &QuadProblem, x: &[f64], b: &[f64]) -> f64 {
        problem.multiply(x).iter().zip(b).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max)
    }

    fn solve_with_work(problem: &QuadProblem, work: SplitWork) -> (SubstructuredCholesky, Vec<f64>, Vec<f64>) {
        let (col_ptr, row_idx) = problem.pattern();
        let mut cholesky = SubstructuredCholesky::analyse(&col_ptr, &row_idx, work).unwrap();
        let layout = layout(&mut cholesky, row_idx.len());
        assert!(cholesky.factorize_with(|values| problem.fill(&layout, &col_ptr, &row_idx, values)));
        let b: Vec<f64> = (0..problem.n).map(|i| ((i * 37 % 23) as f64 - 11.0) / 7.0).collect();
        let mut x = b.clone();
        cholesky.solve_in_place(&mut x);
        (cholesky, x, b)
    }

    #[test]
    fn split_solve_matches_the_whole_matrix() {
        // 40 × 25 = 1,000 variables: bisected (a separator across the short side).
        let problem = QuadProblem::new(40, 25, 1e-3);
        let (cholesky, x, b) = solve(&problem);
        assert_eq!(cholesky.domains.len(), 2, "the grid is split");
        let separator = cholesky.separator.len();
        assert!((25..=60).contains(&separator), "separator of {separator} variables");
        let worst = worst_residual(&problem, &x, &b);
        assert!(worst < 1e-9, "max |Ax − b| = {worst:e}");
    }

    #[test]
    fn small_matrices_use_one_domain() {
        let problem = QuadProblem::new(12, 10, 1e-2);
        let (cholesky, x, b) = solve(&problem);
        assert_eq!(cholesky.domains.len(), 1);
        assert!(cholesky.separator.is_empty());
        let worst = worst_residual(&problem, &x, &b);
        assert!(worst < 1e-9, "max |Ax − b| = {worst:e}");
    }

    #[test]
    fn a_separator_swollen_by_long_range_couplings_keeps_one_domain() {
        // The bisection proposes a separator of several hundred variables: its dense Schur
        // complement would cost more than factorising the whole.
        let problem = QuadProblem::new(100, 100, 1e-3).with_long_range_couplings(100);
        let (col_ptr, row_idx) = problem.pattern();
        let cuts = candidate_cuts(&col_ptr, &row_idx);
        assert!(!cuts.is_empty(), "splits are proposed");
        for parts in &cuts {
            let proposed = parts.iter().filter(|&&p| p == Part::Separator).count();
            assert!(proposed > 400, "separator of {proposed}");
        }
        let (cholesky, x, b) = solve(&problem);
        assert_eq!(cholesky.domains.len(), 1);
        assert!(cholesky.separator.is_empty());
        let worst = worst_residual(&problem, &x, &b);
        assert!(worst < 1e-9, "max |Ax − b| = {worst:e}");
    }

    #[test]
    fn a_split_that_adds_work_is_taken_for_its_span_only() {
        // A 40 × 25 grid: the larger domain plus the separator cost less than the whole matrix
        // (so a solve with two cores to itself splits), both domains together more (so one that
        // shares the cores with another does not). Both solve A x = b.
        let problem = QuadProblem::new(40, 25, 1e-3);
        for (work, domains) in [(SplitWork::Span, 2), (SplitWork::Total, 1)] {
            let (cholesky, x, b) = solve_with_work(&problem, work);
            assert_eq!(cholesky.domains.len(), domains, "{work:?}");
            let worst = worst_residual(&problem, &x, &b);
            assert!(worst < 1e-9, "{work:?}: max |Ax − b| = {worst:e}");
        }
    }

    #[test]
    fn indefinite_matrix_is_reported() {
        let problem = QuadProblem::new(40, 25, -0.5);
        let (col_ptr, row_idx) = problem.pattern();
        let mut cholesky = SubstructuredCholesky::analyse(&col_ptr, &row_idx, SplitWork::Span).unwrap();
        let layout = layout(&mut cholesky, row_idx.len());
        assert!(!cholesky.factorize_with(|values| problem.fill(&layout, &col_ptr, &row_idx, values)));
    }

    #[test]
    fn same_bits_with_one_or_two_threads() {
        let problem = QuadProblem::new(40, 25, 1e-3);
        let run = |threads: usize| {
            let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
            pool.install(|| solve(&problem).1)
        };
        let (one, two) = (run(1), run(2));
        assert!(one.iter().zip(&two).all(|(a, b)| a.to_bits() == b.to_bits()));
    }
}
