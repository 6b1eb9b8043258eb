//! Schur elimination of the local variable groups.
//!
//! For a group L with local Jacobian columns J_L and the group's global columns J_G, the damped
//! normal equations read
//! [H_GG+μI  C_Lᵀ; C_L  D_L+μI] [h_G; h_L] = −[g_G; g_L],  D_L = J_LᵀJ_L,  C_L = J_LᵀJ_G.
//! Eliminating h_L gives the reduced system
//! (H_GG + μI − Σ_L C_Lᵀ(D_L+μI)⁻¹C_L) h_G = −g_G + Σ_L C_Lᵀ(D_L+μI)⁻¹g_L
//! and the back-substitution h_L = −(D_L+μI)⁻¹(g_L + C_L h_G).
use nalgebra::{Cholesky, DMatrix, DVector, Dyn};

use super::evaluation::column_dot;
use super::structure::{BlockStructure, GroupStructure};

/// Dense per-group workspace (k local variables, q coupled global variables), sized once.
pub(crate) struct GroupSystem {
    /// D_L = J_LᵀJ_L (k×k).
    normal: DMatrix<f64>,
    /// C_L = J_LᵀJ_G (k×q).
    coupling: DMatrix<f64>,
    /// g_L (k).
    gradient: DVector<f64>,
    /// Storage of the Cholesky factor of D_L + μI (k×k).
    factor: DMatrix<f64>,
    /// Y = (D_L+μI)⁻¹C_L (k×q).
    solved_coupling: DMatrix<f64>,
    /// y = (D_L+μI)⁻¹g_L (k).
    solved_gradient: DVector<f64>,
    /// W = C_LᵀY (q×q), subtracted from S.
    pub schur: DMatrix<f64>,
    /// v = C_Lᵀy (q), added to the reduced right-hand side.
    pub schur_rhs: DVector<f64>,
    /// h_G gathered at the group's globals (q).
    gathered: DVector<f64>,
    /// h_L (k).
    pub step: DVector<f64>,
}

impl GroupSystem {
    pub fn new(k: usize, q: usize) -> Self {
        Self {
            normal: DMatrix::zeros(k, k),
            coupling: DMatrix::zeros(k, q),
            gradient: DVector::zeros(k),
            factor: DMatrix::zeros(k, k),
            solved_coupling: DMatrix::zeros(k, q),
            solved_gradient: DVector::zeros(k),
            schur: DMatrix::zeros(q, q),
            schur_rhs: DVector::zeros(q),
            gathered: DVector::zeros(q),
            step: DVector::zeros(k),
        }
    }

    /// Accumulates D_L, C_L from the group's block Jacobians (in block order) and copies g_L
    /// from the full gradient.
    pub fn accumulate(
        &mut self,
        l: usize,
        blocks: &BlockStructure,
        groups: &GroupStructure,
        slots: &[f64],
        gradient: &[f64],
    ) {
        self.normal.fill(0.0);
        self.coupling.fill(0.0);
        for &b in groups.blocks(l) {
            let b = b as usize;
            let n = blocks.var_ptr[b + 1] - blocks.var_ptr[b];
            let jacobian = blocks.jacobian(b, slots);
            let (local_positions, local_offsets) = blocks.local_positions(b);
            for (&pa, &oa) in local_positions.iter().zip(local_offsets) {
                for (&pc, &oc) in local_positions.iter().zip(local_offsets) {
                    self.normal[(oa as usize, oc as usize)] += column_dot(jacobian, n, pa as usize, pc as usize);
                }
                for (&pg, &ig) in blocks.global_positions(b).iter().zip(blocks.coupling_index(b)) {
                    self.coupling[(oa as usize, ig as usize)] += column_dot(jacobian, n, pa as usize, pg as usize);
                }
            }
        }
        self.gradient.copy_from_slice(&gradient[groups.starts[l]..groups.starts[l + 1]]);
    }

    /// Largest diagonal entry of D_L.
    pub fn max_diagonal(&self) -> f64 {
        self.normal.diagonal().iter().fold(0.0, |m: f64, &d| m.max(d))
    }

    /// Factors D_L + μI and forms W = C_Lᵀ(D_L+μI)⁻¹C_L and v = C_Lᵀ(D_L+μI)⁻¹g_L.
    /// Returns `false` if the dense factorisation fails.
    pub fn eliminate(&mut self, mu: f64) -> bool {
        let mut damped = std::mem::replace(&mut self.factor, DMatrix::zeros(0, 0));
        damped.copy_from(&self.normal);
        for i in 0..damped.nrows() {
            damped[(i, i)] += mu;
        }
        let cholesky = Cholesky::<f64, Dyn>::new_unchecked(damped);
        let l = cholesky.l_dirty();
        let positive = (0..l.nrows()).all(|i| l[(i, i)].is_finite() && l[(i, i)] > 0.0);
        if positive {
            self.solved_coupling.copy_from(&self.coupling);
            cholesky.solve_mut(&mut self.solved_coupling);
            self.solved_gradient.copy_from(&self.gradient);
            cholesky.solve_mut(&mut self.solved_gradient);
            self.schur.gemm_tr(1.0, &self.coupling, &self.solved_coupling, 0.0);
            self.schur_rhs.gemv_tr(1.0, &self.coupling, &self.solved_gradient, 0.0);
        }
        self.factor = cholesky.unpack_dirty();
        positive
    }

    /// h_L = −(y + Y h_G) from the reduced solution `global_step`.
    pub fn back_substitute(&mut self, globals: &[u32], global_step: &[f64]) {
        for (gathered, &v) in self.gathered.iter_mut().zip(globals) {
            *gathered = global_step[v as usize];
        }
        self.step.copy_from(&self.solved_gradient);
        self.step.gemv(1.0, &self.solved_coupling, &self.gathered, 1.0);
        self.step.neg_mut();
    }
}
