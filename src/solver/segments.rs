//! Deterministic parallel loop over the variable-length segments of a flat buffer.
//!
//! Each segment is written by exactly one task, so results do not depend on the number of
//! threads; the split into tasks uses fixed ranges (never work-stealing sizes).

/// Segments handled sequentially by one task.
const GRAIN: usize = 32;

/// Calls `f(i, segment_i)` for every segment `buffer[offsets[i]-offsets[0]..offsets[i+1]-offsets[0]]`
/// in parallel. Returns the lowest index for which `f` returned `false`, if any.
pub(crate) fn try_for_each_segment<F>(buffer: &mut [f64], offsets: &[usize], f: &F) -> Option<usize>
where
    F: Fn(usize, &mut [f64]) -> bool + Sync,
{
    split(buffer, offsets, 0, f)
}

fn split<F>(buffer: &mut [f64], offsets: &[usize], first: usize, f: &F) -> Option<usize>
where
    F: Fn(usize, &mut [f64]) -> bool + Sync,
{
    let count = offsets.len().saturating_sub(1);
    if count <= GRAIN {
        let mut failed = None;
        let mut rest = buffer;
        for i in 0..count {
            let (segment, tail) = std::mem::take(&mut rest).split_at_mut(offsets[i + 1] - offsets[i]);
            rest = tail;
            if !f(first + i, segment) && failed.is_none() {
                failed = Some(first + i);
            }
        }
        return failed;
    }
    let mid = count / 2;
    let (left, right) = buffer.split_at_mut(offsets[mid] - offsets[0]);
    let (a, b) = rayon::join(
        || split(left, &offsets[..=mid], first, f),
        || split(right, &offsets[mid..], first + mid, f),
    );
    a.or(b)
}
