//! Fixed sparsity pattern of the reduced normal matrix S over the global variables
//! (upper triangle, CSC), and the scatter maps from block and group products to its value array.
//!
//! S has an entry (i, j) when i and j are global variables of one block without a local group, or
//! global variables of one local group (the Schur-complement fill), plus the whole diagonal.
use super::structure::{BlockStructure, GroupStructure};

pub(crate) struct NormalPattern {
    pub col_ptr: Vec<usize>,
    pub row_idx: Vec<usize>,
    /// Position of the diagonal entry of each column.
    pub diagonal: Vec<usize>,
    /// Whether each value position is on the diagonal.
    pub is_diagonal: Vec<bool>,
    /// `gram_targets[gram_ptr[b]..]`: for each upper pair (i ≤ j) of the global positions of a block b
    /// without a local group (none for the others),
    /// in the order of its Gram slot, the value position in S.
    pub gram_ptr: Vec<usize>,
    pub gram_targets: Vec<usize>,
    /// `schur_targets[schur_ptr[l]..]`: for each upper pair (i ≤ j) of group l's sorted globals, the
    /// value position in S.
    pub schur_ptr: Vec<usize>,
    pub schur_targets: Vec<usize>,
}

impl NormalPattern {
    pub fn build(blocks: &BlockStructure, groups: &GroupStructure) -> Self {
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
        let mut pattern = Self {
            diagonal: Vec::new(),
            is_diagonal: Vec::new(),
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
        pattern.schur_targets = targets.split_off(gram_end);
        pattern.gram_targets = targets.split_off(g);
        pattern.diagonal = targets;
        pattern.is_diagonal = vec![false; pattern.row_idx.len()];
        for &d in &pattern.diagonal {
            pattern.is_diagonal[d] = true;
        }
        pattern
    }

    /// Renumbers the value positions: the value at position t moves to `new_position[t]` (a
    /// permutation of the positions, e.g. the sparse Cholesky's storage order). Afterwards the
    /// scatter maps and diagonals refer to the new positions; `col_ptr`/`row_idx` keep the
    /// original upper pattern.
    pub fn renumber(&mut self, new_position: &[usize]) {
        for t in self.diagonal.iter_mut().chain(&mut self.gram_targets).chain(&mut self.schur_targets) {
            *t = new_position[*t];
        }
        let mut is_diagonal = vec![false; self.is_diagonal.len()];
        for (t, &d) in self.is_diagonal.iter().enumerate() {
            is_diagonal[new_position[t]] = d;
        }
        self.is_diagonal = is_diagonal;
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
