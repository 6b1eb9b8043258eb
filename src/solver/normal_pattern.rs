//! Fixed sparsity pattern of the reduced normal matrix S over the global variables
//! (upper triangle, CSC), and the scatter maps from block and group products to its value array.
//!
//! S has an entry (i, j) when i and j are global variables of one block without a local group, or
//! global variables of one local group (the Schur-complement fill), plus the whole diagonal.
use super::structure::{BlockStructure, GroupStructure};
use super::SolverError;

pub(crate) struct NormalPattern {
    /// The upper triangle's columns; their rows are read only while the solver is set up
    /// ([`Self::free_rows`]).
    pub col_ptr: Vec<usize>,
    pub row_idx: Vec<usize>,
    /// Position of the diagonal entry of each column; after [`Self::assign_storage`], every
    /// stored copy of a diagonal entry as (variable, value position), by variable.
    pub diagonal: Vec<(u32, usize)>,
    /// Share of the damping μ on each value position: 1 on the diagonal, ½ on each of the two
    /// copies of a separator variable's diagonal, 0 elsewhere.
    pub damping_share: Vec<f64>,
    /// `gram_targets[gram_ptr[b]..]`: for each upper pair (i ≤ j) of the global positions of a block b
    /// without a local group (none for the others),
    /// in the order of its Gram slot, the value position in S.
    pub gram_ptr: Vec<usize>,
    pub gram_targets: Vec<u32>,
    /// `schur_targets[schur_ptr[l]..]`: for each upper pair (i ≤ j) of group l's sorted globals, the
    /// value position in S. Handed to [`super::assembly::ReducedGather`] by
    /// [`Self::take_schur_targets`], which is all that reads them.
    schur_ptr: Vec<usize>,
    schur_targets: Vec<u32>,
}

impl NormalPattern {
    /// Errors: `InvalidLayout` when the pattern has more entries than 32-bit positions reach.
    pub fn build(blocks: &BlockStructure, groups: &GroupStructure) -> Result<Self, SolverError> {
        let g = blocks.global_count;
        // Cliques: sorted global variable sets whose squares make up the pattern.
        let mut clique_ptr = vec![0];
        let mut clique_vars: Vec<u32> = Vec::new();
        for b in 0..blocks.block_count() {
            if blocks.group[b].is_none() && blocks.global_positions(b).len() > 1 {
                let vars = blocks.variables(b);
                let start = clique_vars.len();
                clique_vars.extend(blocks.global_positions(b).iter().map(|&p| vars[p as usize]));
                clique_vars[start..].sort_unstable();
                clique_ptr.push(clique_vars.len());
            }
        }
        for l in 0..groups.group_count() {
            if groups.globals(l).len() > 1 {
                clique_vars.extend_from_slice(groups.globals(l));
                clique_ptr.push(clique_vars.len());
            }
        }
        let (col_ptr, row_idx) = upper_pattern(g, &clique_ptr, &clique_vars);
        check_positions(row_idx.len())?;
        let mut pattern = Self {
            diagonal: Vec::new(),
            damping_share: Vec::new(),
            col_ptr,
            row_idx,
            gram_ptr: vec![0],
            gram_targets: Vec::new(),
            schur_ptr: vec![0],
            schur_targets: Vec::new(),
        };
        // Every (row, column) entry the scatter maps need, looked up at once: diagonal, then the
        // Gram pairs of the blocks without a group, then the Schur pairs of the groups.
        let mut entries: Vec<(u32, u32)> = (0..g as u32).map(|j| (j, j)).collect();
        for b in 0..blocks.block_count() {
            let vars = blocks.variables(b);
            let positions = if blocks.group[b].is_none() { blocks.global_positions(b) } else { &[] };
            for (i, &pi) in positions.iter().enumerate() {
                entries.extend(positions[i..].iter().map(|&pj| (vars[pi as usize], vars[pj as usize])));
            }
            pattern.gram_ptr.push(entries.len() - g);
        }
        let gram_end = entries.len();
        for l in 0..groups.group_count() {
            let set = groups.globals(l);
            for (i, &vi) in set.iter().enumerate() {
                entries.extend(set[i..].iter().map(|&vj| (vi, vj)));
            }
            pattern.schur_ptr.push(entries.len() - gram_end);
        }
        let mut targets = pattern.positions(&entries);
        // Positions are below the entry count, checked to fit 32 bits above.
        let narrow = |targets: Vec<usize>| targets.into_iter().map(|t| t as u32).collect();
        pattern.schur_targets = narrow(targets.split_off(gram_end));
        pattern.gram_targets = narrow(targets.split_off(g));
        pattern.diagonal = targets.into_iter().enumerate().map(|(v, t)| (v as u32, t)).collect();
        pattern.damping_share = vec![0.0; pattern.row_idx.len()];
        for &(_, t) in &pattern.diagonal {
            pattern.damping_share[t] = 1.0;
        }
        Ok(pattern)
    }

    /// The groups' Schur targets (see the field), moved out: `(schur_ptr, schur_targets)`.
    pub fn take_schur_targets(&mut self) -> (Vec<usize>, Vec<u32>) {
        (std::mem::take(&mut self.schur_ptr), std::mem::take(&mut self.schur_targets))
    }

    /// Moves the values into the storage of the domain matrices (see
    /// [`super::substructured_cholesky`]): `storage[d][t]` is the position of entry `t` of the
    /// pattern in domain `d`'s matrix (`usize::MAX` if absent), `domain_of[v]` the domain whose
    /// interior holds variable `v` (`None` on the separator). Each block and group scatters into
    /// the domain of its variables; `col_ptr`/`row_idx` keep the original upper pattern.
    pub fn assign_storage(
        &mut self,
        blocks: &BlockStructure,
        groups: &GroupStructure,
        storage: &[Vec<usize>],
        domain_of: &[Option<usize>],
    ) -> Result<(), SolverError> {
        // Local variables (beyond `domain_of`) have no domain.
        let domain = |vars: &[u32]| vars.iter().find_map(|&v| domain_of.get(v as usize).copied().flatten()).unwrap_or(0);
        let storage_len = storage.iter().flatten().filter(|&&p| p != usize::MAX).count();
        check_positions(storage_len)?;
        let relocate = |targets: &mut [u32], d: usize| -> Result<(), SolverError> {
            for t in targets {
                let position = storage[d][*t as usize];
                if position == usize::MAX {
                    return Err(SolverError::SymbolicAnalysisFailed { message: "a block couples two domains".to_string() });
                }
                // Below `storage_len`, checked above.
                *t = position as u32;
            }
            Ok(())
        };
        for b in 0..blocks.block_count() {
            let d = domain(blocks.variables(b));
            relocate(&mut self.gram_targets[self.gram_ptr[b]..self.gram_ptr[b + 1]], d)?;
        }
        for l in 0..groups.group_count() {
            let d = domain(groups.globals(l));
            relocate(&mut self.schur_targets[self.schur_ptr[l]..self.schur_ptr[l + 1]], d)?;
        }
        self.damping_share = vec![0.0; storage_len];
        let mut diagonal = Vec::with_capacity(self.diagonal.len());
        for &(v, t) in &self.diagonal {
            let copies: Vec<usize> = storage.iter().map(|positions| positions[t]).filter(|&p| p != usize::MAX).collect();
            for &p in &copies {
                self.damping_share[p] = 1.0 / copies.len() as f64;
                diagonal.push((v, p));
            }
        }
        self.diagonal = diagonal;
        Ok(())
    }

    /// Frees the upper triangle's rows once the factorisation's analysis, the storage and the
    /// gather are set up (nothing reads them later; [`Self::dimension`] stays).
    pub fn free_rows(&mut self) {
        self.row_idx = Vec::new();
    }

    /// Number of value positions (after [`Self::assign_storage`]: of the domain storage).
    pub fn storage_len(&self) -> usize {
        self.damping_share.len()
    }

    pub fn dimension(&self) -> usize {
        self.col_ptr.len() - 1
    }

    /// Value positions of the entries (a, b) of the symmetric matrix (stored as (min, max)), in
    /// order: the entries are bucketed by column, and each column's rows are spread over a dense
    /// row → position map once (no searching).
    fn positions(&self, entries: &[(u32, u32)]) -> Vec<usize> {
        let n = self.dimension();
        let key = |&(a, b): &(u32, u32)| (a.min(b) as usize, a.max(b) as usize);
        let mut bucket_ptr = vec![0usize; n + 1];
        for entry in entries {
            bucket_ptr[key(entry).1 + 1] += 1;
        }
        for c in 0..n {
            bucket_ptr[c + 1] += bucket_ptr[c];
        }
        let mut fill = bucket_ptr.clone();
        let mut bucket = vec![0usize; entries.len()];
        for (e, entry) in entries.iter().enumerate() {
            let c = key(entry).1;
            bucket[fill[c]] = e;
            fill[c] += 1;
        }
        let mut position_of_row = vec![0usize; n];
        let mut positions = vec![0usize; entries.len()];
        for c in 0..n {
            for p in self.col_ptr[c]..self.col_ptr[c + 1] {
                position_of_row[self.row_idx[p]] = p;
            }
            // Invariant: the pattern was built from the very cliques and diagonal queried here, so
            // every queried row of column c was just written.
            for &e in &bucket[bucket_ptr[c]..bucket_ptr[c + 1]] {
                positions[e] = position_of_row[key(&entries[e]).0];
            }
        }
        positions
    }
}

/// Value positions are stored as 32 bits (half the memory of the scatter maps): `count` of them
/// must fit.
pub(crate) fn check_positions(count: usize) -> Result<(), SolverError> {
    if count > u32::MAX as usize {
        return Err(SolverError::InvalidLayout { message: format!("{count} normal-matrix entries exceed the u32 index range") });
    }
    Ok(())
}

/// Upper-triangular CSC pattern (sorted rows) of the union of the squared cliques and the diagonal.
fn upper_pattern(n: usize, clique_ptr: &[usize], clique_vars: &[u32]) -> (Vec<usize>, Vec<usize>) {
    let clique_count = clique_ptr.len() - 1;
    // Transpose: the cliques containing each variable.
    let mut member_ptr = vec![0usize; n + 1];
    for &v in clique_vars {
        member_ptr[v as usize + 1] += 1;
    }
    for j in 0..n {
        member_ptr[j + 1] += member_ptr[j];
    }
    let mut fill = member_ptr.clone();
    let mut members = vec![0u32; clique_vars.len()];
    for c in 0..clique_count {
        for &v in &clique_vars[clique_ptr[c]..clique_ptr[c + 1]] {
            members[fill[v as usize]] = c as u32;
            fill[v as usize] += 1;
        }
    }
    let mut marker = vec![usize::MAX; n];
    let mut col_ptr = Vec::with_capacity(n + 1);
    col_ptr.push(0);
    let mut row_idx = Vec::new();
    for j in 0..n {
        let start = row_idx.len();
        marker[j] = j;
        row_idx.push(j);
        for &c in &members[member_ptr[j]..member_ptr[j + 1]] {
            let c = c as usize;
            for &i in &clique_vars[clique_ptr[c]..clique_ptr[c + 1]] {
                let i = i as usize;
                if i >= j {
                    break;
                }
                if marker[i] != j {
                    marker[i] = j;
                    row_idx.push(i);
                }
            }
        }
        row_idx[start..].sort_unstable();
        col_ptr.push(row_idx.len());
    }
    (col_ptr, row_idx)
}
