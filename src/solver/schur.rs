//! Schur elimination of the local variable groups.
//!
//! For a group L with local Jacobian columns J_L and the group's global columns J_G, the damped
//! normal equations read
//! [H_GG+μI  C_Lᵀ; C_L  D_L+μI] [h_G; h_L] = −[g_G; g_L],  D_L = J_LᵀJ_L,  C_L = J_LᵀJ_G.
//! Eliminating h_L gives the reduced system
//! (H_GG + μI − Σ_L C_Lᵀ(D_L+μI)⁻¹C_L) h_G = −g_G + Σ_L C_Lᵀ(D_L+μI)⁻¹g_L
//! and the back-substitution h_L = −(D_L+μI)⁻¹(g_L + C_L h_G).
//!
//! With the Cholesky factor D_L + μI = L Lᵀ and [Z | z] = L⁻¹[C_L | g_L] (one forward
//! substitution), the Schur terms are W = ZᵀZ and v = Zᵀz, and h_L = −L⁻ᵀ(z + Z h_G).
//! The groups are small (a handful of variables), so everything is hand-rolled on row-major
//! slices of one buffer per group.
//!
//! The global Gram G_L = J_GᵀJ_G of the group's blocks is summed here too (from the same
//! Jacobian rows) rather than scattered into H_GG block by block: the group hands S the single
//! packed term W − G_L on its Schur targets, which cover every global pair of its blocks.
use super::structure::{triangle_len, BlockStructure, GroupStructure};

/// Dense per-group workspace (k local variables, q coupled global variables), sized once.
///
/// `buffer` holds, in this order: D_L (k×k, lower triangle used), [C_L | g_L] (k×(q+1)), the
/// Cholesky factor L (k×k, lower), [Z | z] (k×(q+1)), G_L and W − G_L (upper triangles of q×q
/// packed row by row, the order of the pattern's Schur targets), v (q) and h_L (k). All row-major.
pub(crate) struct GroupSystem {
    k: usize,
    q: usize,
    buffer: Vec<f64>,
    /// Nonzero local (offset, value) and global (coupling index, value) entries of one
    /// Jacobian row (capacities k and q, never exceeded).
    row_locals: Vec<(u32, f64)>,
    row_globals: Vec<(u32, f64)>,
}

/// Mutable views of a group's workspace sections.
struct Sections<'a> {
    normal: &'a mut [f64],
    coupling: &'a mut [f64],
    factor: &'a mut [f64],
    solved: &'a mut [f64],
    gram: &'a mut [f64],
    schur: &'a mut [f64],
    schur_rhs: &'a mut [f64],
    step: &'a mut [f64],
}

impl GroupSystem {
    pub fn new(k: usize, q: usize) -> Self {
        let w = q + 1;
        let len = 2 * k * k + 2 * k * w + 2 * triangle_len(q) + q + k;
        Self { k, q, buffer: vec![0.0; len], row_locals: Vec::with_capacity(k), row_globals: Vec::with_capacity(q) }
    }

    fn sections(&mut self) -> Sections<'_> {
        let (k, w) = (self.k, self.q + 1);
        let (normal, rest) = self.buffer.split_at_mut(k * k);
        let (coupling, rest) = rest.split_at_mut(k * w);
        let (factor, rest) = rest.split_at_mut(k * k);
        let (solved, rest) = rest.split_at_mut(k * w);
        let (gram, rest) = rest.split_at_mut(triangle_len(self.q));
        let (schur, rest) = rest.split_at_mut(triangle_len(self.q));
        let (schur_rhs, step) = rest.split_at_mut(self.q);
        Sections { normal, coupling, factor, solved, gram, schur, schur_rhs, step }
    }

    fn gram_offset(&self) -> usize {
        2 * self.k * self.k + 2 * self.k * (self.q + 1)
    }

    fn schur_offset(&self) -> usize {
        self.gram_offset() + triangle_len(self.q)
    }

    /// G_L = J_GᵀJ_G summed over the group's blocks, upper triangle packed row by row (valid
    /// after [`Self::accumulate`]).
    pub fn gram(&self) -> &[f64] {
        let start = self.gram_offset();
        &self.buffer[start..start + triangle_len(self.q)]
    }

    /// W − G_L with W = C_Lᵀ(D_L+μI)⁻¹C_L, upper triangle packed row by row (valid after
    /// [`Self::eliminate`]).
    pub fn schur(&self) -> &[f64] {
        let start = self.schur_offset();
        &self.buffer[start..start + triangle_len(self.q)]
    }

    /// v = C_Lᵀ(D_L+μI)⁻¹g_L (valid after [`Self::eliminate`]).
    pub fn schur_rhs(&self) -> &[f64] {
        let start = self.schur_offset() + triangle_len(self.q);
        &self.buffer[start..start + self.q]
    }

    /// h_L (valid after [`Self::back_substitute`]).
    pub fn step(&self) -> &[f64] {
        &self.buffer[self.buffer.len() - self.k..]
    }

    /// Accumulates D_L, C_L and G_L from the group's block Jacobians (in block order, rows in
    /// order) and copies g_L from the full gradient.
    pub fn accumulate(
        &mut self,
        l: usize,
        blocks: &BlockStructure,
        groups: &GroupStructure,
        slots: &[f64],
        gradient: &[f64],
    ) {
        let (k, q, w) = (self.k, self.q, self.q + 1);
        let (mut row_locals, mut row_globals) = (std::mem::take(&mut self.row_locals), std::mem::take(&mut self.row_globals));
        let s = self.sections();
        s.normal.fill(0.0);
        s.coupling.fill(0.0);
        s.gram.fill(0.0);
        for &b in groups.blocks(l) {
            let b = b as usize;
            let n = blocks.var_ptr[b + 1] - blocks.var_ptr[b];
            let jacobian = blocks.jacobian(b, slots);
            let (local_positions, local_offsets) = blocks.local_positions(b);
            let global_positions = blocks.global_positions(b);
            let coupling_index = blocks.coupling_index(b);
            // A block of a group has at least one (local) variable, so n > 0.
            for row in jacobian.chunks_exact(n) {
                // Structural zeros (e.g. auxiliaries absent from a residual row, field values of
                // uncrossed edges) add nothing: gather the row's nonzero entries first.
                row_locals.clear();
                row_locals.extend(local_positions.iter().zip(local_offsets).map(|(&p, &o)| (o, row[p as usize])).filter(|e| e.1 != 0.0));
                row_globals.clear();
                row_globals.extend(global_positions.iter().zip(coupling_index).map(|(&p, &i)| (i, row[p as usize])).filter(|e| e.1 != 0.0));
                for &(oa, va) in &row_locals {
                    let oa = oa as usize;
                    let normal_row = &mut s.normal[oa * k..(oa + 1) * k];
                    for &(oc, vc) in &row_locals {
                        if oc as usize <= oa {
                            normal_row[oc as usize] += va * vc;
                        }
                    }
                    let coupling_row = &mut s.coupling[oa * w..(oa + 1) * w];
                    for &(ig, vg) in &row_globals {
                        coupling_row[ig as usize] += va * vg;
                    }
                }
                for (a, &(ia, va)) in row_globals.iter().enumerate() {
                    for &(ib, vb) in &row_globals[a..] {
                        let (i, j) = if ia <= ib { (ia as usize, ib as usize) } else { (ib as usize, ia as usize) };
                        s.gram[packed_upper_index(i, j, q)] += va * vb;
                    }
                }
            }
        }
        let local_gradient = &gradient[groups.starts[l]..groups.starts[l + 1]];
        for (row, &g) in s.coupling.chunks_exact_mut(w).zip(local_gradient) {
            row[w - 1] = g;
        }
        self.row_locals = row_locals;
        self.row_globals = row_globals;
    }

    /// Largest diagonal entry of D_L.
    pub fn max_diagonal(&self) -> f64 {
        (0..self.k).fold(0.0, |m: f64, i| m.max(self.buffer[i * self.k + i]))
    }

    /// Factors D_L + μI = LLᵀ, solves [Z | z] = L⁻¹[C_L | g_L] and forms W = ZᵀZ, v = Zᵀz.
    /// Returns `false` if the dense factorisation fails (not numerically positive definite).
    pub fn eliminate(&mut self, mu: f64) -> bool {
        let (k, q) = (self.k, self.q);
        eliminate_kernel(k, q, &mut self.sections(), mu)
    }

    /// h_L = −L⁻ᵀ(z + Z h_G) from the reduced solution `global_step`.
    pub fn back_substitute(&mut self, globals: &[u32], global_step: &[f64]) {
        let (k, w) = (self.k, self.q + 1);
        let s = self.sections();
        for (h, z_row) in s.step.iter_mut().zip(s.solved.chunks_exact(w)) {
            *h = z_row[w - 1] + globals.iter().zip(z_row).map(|(&v, z)| z * global_step[v as usize]).sum::<f64>();
        }
        // Backward substitution with Lᵀ: h'_i = (s_i − Σ_{p>i} L_pi h'_p) / L_ii, then h_L = −h'.
        for i in (0..k).rev() {
            let mut value = s.step[i];
            for p in i + 1..k {
                value -= s.factor[p * k + i] * s.step[p];
            }
            s.step[i] = value / s.factor[i * k + i];
        }
        for h in s.step.iter_mut() {
            *h = -*h;
        }
    }
}

/// [`GroupSystem::eliminate`] for k local and q global variables.
fn eliminate_kernel(k: usize, q: usize, s: &mut Sections<'_>, mu: f64) -> bool {
    let w = q + 1;
    if !cholesky_lower(s.normal, mu, s.factor, k) {
        return false;
    }
    // Forward substitution, row by row: Z_i = (B_i − Σ_{p<i} L_ip Z_p) / L_ii.
    s.solved.copy_from_slice(s.coupling);
    for i in 0..k {
        let (done, rest) = s.solved.split_at_mut(i * w);
        let current = &mut rest[..w];
        for (p, &lip) in s.factor[i * k..i * k + i].iter().enumerate() {
            for (c, &z) in current.iter_mut().zip(&done[p * w..(p + 1) * w]) {
                *c -= lip * z;
            }
        }
        let diagonal = s.factor[i * k + i];
        for c in current.iter_mut() {
            *c /= diagonal;
        }
    }
    // W − G_L = ZᵀZ − G_L (upper, packed) and v = Zᵀz, summed over the rows of Z in order.
    for (wij, &g) in s.schur.iter_mut().zip(s.gram.iter()) {
        *wij = -g;
    }
    s.schur_rhs.fill(0.0);
    for z_row in s.solved.chunks_exact(w) {
        let mut t = 0;
        for i in 0..q {
            let zi = z_row[i];
            for (wij, &zj) in s.schur[t..t + q - i].iter_mut().zip(&z_row[i..q]) {
                *wij += zi * zj;
            }
            t += q - i;
            s.schur_rhs[i] += zi * z_row[q];
        }
    }
    true
}

/// Cholesky factor (lower, row-major k×k, into `factor`) of `normal + μI`, reading only the lower
/// triangle of `normal`. Returns `false` on a non-positive or non-finite pivot.
fn cholesky_lower(normal: &[f64], mu: f64, factor: &mut [f64], k: usize) -> bool {
    for j in 0..k {
        let (above, rest) = factor.split_at_mut(j * k);
        let row_j = &mut rest[..k];
        for i in 0..j {
            let row_i = &above[i * k..i * k + i];
            let dot: f64 = row_i.iter().zip(&row_j[..i]).map(|(a, b)| a * b).sum();
            row_j[i] = (normal[j * k + i] - dot) / above[i * k + i];
        }
        let squares: f64 = row_j[..j].iter().map(|v| v * v).sum();
        let pivot = normal[j * k + j] + mu - squares;
        if !(pivot > 0.0 && pivot.is_finite()) {
            return false;
        }
        row_j[j] = pivot.sqrt();
    }
    true
}

/// Index of entry (i, j), i ≤ j, in the row-by-row packed upper triangle of a q×q matrix.
fn packed_upper_index(i: usize, j: usize, q: usize) -> usize {
    i * (2 * q - i + 1) / 2 + (j - i)
}
