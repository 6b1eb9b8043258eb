//! Partition of the variables into global variables and small local groups
//! (e.g. the six auxiliaries b, u of one vertex, paper Eq. 10–12) that are
//! eliminated by a Schur complement before the sparse solve.
use std::ops::Range;

use super::SolverError;

/// Variables `[0, global_count)` are global; `[global_count, variable_count)` are split into
/// contiguous local groups, in order.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct VariableLayout {
    global_count: usize,
    /// `group_starts[l]..group_starts[l + 1]` are the variables of group `l`; the first entry is
    /// `global_count`, the last is the variable count.
    group_starts: Vec<usize>,
}

impl VariableLayout {
    /// Every one of the `n` variables is global (no Schur elimination).
    pub fn all_global(n: usize) -> Self {
        Self { global_count: n, group_starts: vec![n] }
    }

    /// `group_sizes` cover `[global_count, global_count + Σ sizes)` contiguously, in order.
    /// Every group must be non-empty.
    pub fn with_local_groups(global_count: usize, group_sizes: &[usize]) -> Result<Self, SolverError> {
        let mut group_starts = Vec::with_capacity(group_sizes.len() + 1);
        group_starts.push(global_count);
        let mut end = global_count;
        for (l, &size) in group_sizes.iter().enumerate() {
            if size == 0 {
                return Err(SolverError::InvalidLayout { message: format!("local group {l} is empty") });
            }
            end = end.checked_add(size).ok_or_else(|| SolverError::InvalidLayout {
                message: "variable count overflows".to_string(),
            })?;
            group_starts.push(end);
        }
        Ok(Self { global_count, group_starts })
    }

    /// Number of global variables (the unknowns of the reduced sparse system).
    pub fn global_count(&self) -> usize {
        self.global_count
    }

    /// Total number of variables (global and local).
    pub fn variable_count(&self) -> usize {
        // The vector always holds at least `global_count`.
        self.group_starts[self.group_starts.len() - 1]
    }

    /// Number of local groups.
    pub fn group_count(&self) -> usize {
        self.group_starts.len() - 1
    }

    /// Variables of local group `group` (empty if out of range).
    pub fn group_range(&self, group: usize) -> Range<usize> {
        match (self.group_starts.get(group), self.group_starts.get(group + 1)) {
            (Some(&start), Some(&end)) => start..end,
            _ => 0..0,
        }
    }

    /// The local group containing `variable`, or `None` for global or out-of-range variables.
    pub fn group_of(&self, variable: usize) -> Option<usize> {
        if variable < self.global_count || variable >= self.variable_count() {
            return None;
        }
        // group_starts is increasing; the group is the last start <= variable.
        Some(self.group_starts.partition_point(|&s| s <= variable) - 1)
    }
}
