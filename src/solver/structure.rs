//! Validated, flattened structure of a problem: each block's variables split into global and
//! local ones, its slot in the evaluation buffer, and the blocks and global variables of every
//! local group. Built once by [`super::LevenbergMarquardt::new`].
use super::{LeastSquaresProblem, SolverError, VariableLayout};

/// Block structure (CSR-like flat arrays indexed by block).
pub(crate) struct BlockStructure {
    pub variable_count: usize,
    pub global_count: usize,
    /// `variables[var_ptr[b]..var_ptr[b+1]]`: a copy of `block_variables(b)`.
    pub var_ptr: Vec<usize>,
    pub variables: Vec<u32>,
    pub residual_ptr: Vec<usize>,
    /// `slot_ptr[b]..slot_ptr[b+1]`: block `b`'s evaluation slot, laid out as
    /// [residuals m | Jᵀr n | upper-triangular Gram of global columns].
    /// Blocks of a local group have an empty slot: they are evaluated into their group's system
    /// (see [`super::schur::GroupSystems`]). Blocks with a constant Jacobian have no Gram part:
    /// their share of H_GG is summed once per revision (see [`super::assembly::ConstantHessian`]).
    pub slot_ptr: Vec<usize>,
    /// Positions (within the block's variable list) of its global variables.
    pub global_ptr: Vec<usize>,
    pub global_positions: Vec<u32>,
    /// For each entry of `global_positions` of a block with a local group: the index of that
    /// variable in the group's sorted global set (`GroupStructure::globals`); 0 otherwise.
    pub coupling_index: Vec<u32>,
    /// Positions (within the block's variable list) of its local variables and their offsets
    /// inside the group.
    pub local_ptr: Vec<usize>,
    pub local_positions: Vec<u32>,
    pub local_offsets: Vec<u32>,
    /// The local group touched by each block.
    pub group: Vec<Option<u32>>,
    /// Whether each block's Jacobian is constant
    /// ([`LeastSquaresProblem::block_jacobian_is_constant`], recorded when the solver is built).
    pub constant_jacobian: Vec<bool>,
}

/// Local-group structure (CSR-like flat arrays indexed by group).
pub(crate) struct GroupStructure {
    /// First variable of each group, plus the end: group `l` owns `starts[l]..starts[l+1]`.
    pub starts: Vec<usize>,
    pub block_ptr: Vec<usize>,
    pub blocks: Vec<u32>,
    /// Sorted union of the global variables of the group's blocks.
    pub global_ptr: Vec<usize>,
    pub globals: Vec<u32>,
}

/// Views of one block's evaluation slot.
pub(crate) struct BlockSlot<'a> {
    pub residuals: &'a mut [f64],
    pub gradient: &'a mut [f64],
    pub gram: &'a mut [f64],
}

/// Read-only views of the parts of one block's evaluation slot that the reduction reads.
pub(crate) struct BlockSlotRef<'a> {
    pub residuals: &'a [f64],
    pub gradient: &'a [f64],
    pub gram: &'a [f64],
}

impl BlockStructure {
    pub fn block_count(&self) -> usize {
        self.group.len()
    }

    pub fn variables(&self, b: usize) -> &[u32] {
        &self.variables[self.var_ptr[b]..self.var_ptr[b + 1]]
    }

    pub fn residual_count(&self, b: usize) -> usize {
        self.residual_ptr[b + 1] - self.residual_ptr[b]
    }

    pub fn global_positions(&self, b: usize) -> &[u32] {
        &self.global_positions[self.global_ptr[b]..self.global_ptr[b + 1]]
    }

    pub fn coupling_index(&self, b: usize) -> &[u32] {
        &self.coupling_index[self.global_ptr[b]..self.global_ptr[b + 1]]
    }

    pub fn local_positions(&self, b: usize) -> (&[u32], &[u32]) {
        let range = self.local_ptr[b]..self.local_ptr[b + 1];
        (&self.local_positions[range.clone()], &self.local_offsets[range])
    }

    /// Splits block `b`'s slot (`slot` must be exactly that segment; `b` without a local group)
    /// into its parts.
    pub fn split_slot<'a>(&self, b: usize, slot: &'a mut [f64]) -> BlockSlot<'a> {
        let m = self.residual_count(b);
        let n = self.var_ptr[b + 1] - self.var_ptr[b];
        let (residuals, rest) = slot.split_at_mut(m);
        let (gradient, gram) = rest.split_at_mut(n);
        BlockSlot { residuals, gradient, gram }
    }

    /// Read-only views of block `b`'s slot within the whole slot buffer (`b` without a local
    /// group).
    pub fn slot<'a>(&self, b: usize, slots: &'a [f64]) -> BlockSlotRef<'a> {
        let m = self.residual_count(b);
        let n = self.var_ptr[b + 1] - self.var_ptr[b];
        let slot = &slots[self.slot_ptr[b]..self.slot_ptr[b + 1]];
        let (residuals, rest) = slot.split_at(m);
        let (gradient, gram) = rest.split_at(n);
        BlockSlotRef { residuals, gradient, gram }
    }
}

impl GroupStructure {
    pub fn group_count(&self) -> usize {
        self.starts.len() - 1
    }

    pub fn blocks(&self, l: usize) -> &[u32] {
        &self.blocks[self.block_ptr[l]..self.block_ptr[l + 1]]
    }

    pub fn globals(&self, l: usize) -> &[u32] {
        &self.globals[self.global_ptr[l]..self.global_ptr[l + 1]]
    }

    pub fn size(&self, l: usize) -> usize {
        self.starts[l + 1] - self.starts[l]
    }
}

fn invalid(block: usize, message: String) -> SolverError {
    SolverError::InvalidProblem { block, message }
}

/// Number of entries of the upper triangle (with diagonal) of a k×k matrix.
pub(crate) fn triangle_len(k: usize) -> usize {
    k * (k + 1) / 2
}

/// Validates `problem` against its layout and flattens its structure.
pub(crate) fn analyse<P: LeastSquaresProblem>(problem: &P) -> Result<(BlockStructure, GroupStructure), SolverError> {
    let n = problem.variable_count();
    let layout: VariableLayout = problem.variable_layout();
    if layout.variable_count() != n {
        return Err(SolverError::InvalidLayout {
            message: format!("layout covers {} variables, problem has {n}", layout.variable_count()),
        });
    }
    if n > u32::MAX as usize {
        return Err(SolverError::InvalidLayout { message: format!("{n} variables exceed the u32 index range") });
    }
    let block_count = problem.block_count();
    let group_count = layout.group_count();
    let mut s = BlockStructure {
        variable_count: n,
        global_count: layout.global_count(),
        var_ptr: vec![0],
        variables: Vec::new(),
        residual_ptr: vec![0],
        slot_ptr: vec![0],
        global_ptr: vec![0],
        global_positions: Vec::new(),
        coupling_index: Vec::new(),
        local_ptr: vec![0],
        local_positions: Vec::new(),
        local_offsets: Vec::new(),
        group: Vec::with_capacity(block_count),
        constant_jacobian: Vec::with_capacity(block_count),
    };
    let mut seen = vec![usize::MAX; n];
    let mut group_block_count = vec![0usize; group_count];
    for b in 0..block_count {
        let vars = problem.block_variables(b);
        let m = problem.block_residual_count(b);
        let mut group = None;
        let mut global_count = 0usize;
        for (p, &v) in vars.iter().enumerate() {
            let v = v as usize;
            if v >= n {
                return Err(invalid(b, format!("variable {v} out of range (variable count {n})")));
            }
            if seen[v] == b {
                return Err(invalid(b, format!("variable {v} listed twice")));
            }
            seen[v] = b;
            match layout.group_of(v) {
                None => {
                    global_count += 1;
                    s.global_positions.push(p as u32);
                }
                Some(l) => {
                    if group.is_some_and(|g| g != l) {
                        return Err(invalid(b, "block touches more than one local group".to_string()));
                    }
                    group = Some(l);
                    s.local_positions.push(p as u32);
                    s.local_offsets.push((v - layout.group_range(l).start) as u32);
                }
            }
        }
        let too_large = || invalid(b, "block too large".to_string());
        let constant = problem.block_jacobian_is_constant(b);
        let slot_len = match group {
            Some(_) => 0,
            None if constant => m + vars.len(),
            None => (m + vars.len()).checked_add(triangle_len(global_count)).ok_or_else(too_large)?,
        };
        let last_slot = s.slot_ptr[b];
        s.slot_ptr.push(last_slot.checked_add(slot_len).ok_or_else(too_large)?);
        s.variables.extend_from_slice(vars);
        s.var_ptr.push(s.variables.len());
        s.residual_ptr.push(s.residual_ptr[b] + m);
        s.global_ptr.push(s.global_positions.len());
        s.local_ptr.push(s.local_positions.len());
        if let Some(l) = group {
            group_block_count[l] += 1;
        }
        s.group.push(group.map(|l| l as u32));
        s.constant_jacobian.push(constant);
    }
    s.coupling_index = vec![0; s.global_positions.len()];

    // Blocks of each group, in block order.
    let mut block_ptr = Vec::with_capacity(group_count + 1);
    block_ptr.push(0);
    for &c in &group_block_count {
        block_ptr.push(block_ptr[block_ptr.len() - 1] + c);
    }
    let mut fill = block_ptr.clone();
    let mut blocks = vec![0u32; block_ptr[group_count]];
    for (b, group) in s.group.iter().enumerate() {
        if let Some(l) = *group {
            blocks[fill[l as usize]] = b as u32;
            fill[l as usize] += 1;
        }
    }

    // Global variables of each group (sorted union) and each block's coupling indices into it.
    let mut global_ptr = vec![0];
    let mut globals = Vec::new();
    for l in 0..group_count {
        let start = globals.len();
        for &b in &blocks[block_ptr[l]..block_ptr[l + 1]] {
            let vars = s.variables(b as usize);
            globals.extend(s.global_positions(b as usize).iter().map(|&p| vars[p as usize]));
        }
        globals[start..].sort_unstable();
        let mut unique = start;
        for i in start..globals.len() {
            if i == start || globals[i] != globals[unique - 1] {
                globals[unique] = globals[i];
                unique += 1;
            }
        }
        globals.truncate(unique);
        let set = &globals[start..];
        for &b in &blocks[block_ptr[l]..block_ptr[l + 1]] {
            let b = b as usize;
            for i in s.global_ptr[b]..s.global_ptr[b + 1] {
                let v = s.variables[s.var_ptr[b] + s.global_positions[i] as usize];
                // Every global variable of the group's blocks is in the sorted set built above.
                s.coupling_index[i] = set.binary_search(&v).unwrap_or(0) as u32;
            }
        }
        global_ptr.push(globals.len());
    }
    let starts = (0..=group_count)
        .map(|l| if l < group_count { layout.group_range(l).start } else { n })
        .collect();
    Ok((s, GroupStructure { starts, block_ptr, blocks, global_ptr, globals }))
}
