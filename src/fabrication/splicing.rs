//! Splitting a strip longer than the stock into pieces that overlap at splices, with the splices
//! where the strip bends least and away from nodes.
//!
//! `n = ⌈(L − o)/(S − o)⌉` pieces of at most `S` each cover a centre line of length `L` with
//! overlaps `o`; piece `k` spans `[a_k, b_k]` with `a_0 = 0`, `a_{k+1} = b_k − o`, `b_{n−1} = L`, so
//! the piece lengths sum to `L + (n − 1) o`. Each end `b_k` is chosen in the range that keeps the
//! remaining pieces within `S` (`b_k ≥ L − (n − k − 1)(S − o)`, `b_k ≤ a_k + S`), among 200 evenly
//! spaced candidates, for the smallest utilisation over its overlap `[b_k − o, b_k]`, plus 10 for a
//! node within a quarter overlap of it (ties: the candidate nearest the middle of the range).

/// Candidate splice positions tried per splice.
const CANDIDATES: usize = 200;
/// Added to a candidate's cost when a node lies in its overlap (utilisations are O(1)).
const NODE_PENALTY: f64 = 10.0;

/// Where the pieces of one strip start and end, arc lengths from the centre line's start.
pub fn splice_intervals(arc_length: &[f64], utilisation: &[f64], nodes: &[f64], usable: f64, overlap: f64) -> Vec<[f64; 2]> {
    let total = arc_length.last().copied().unwrap_or(0.0);
    if total <= usable {
        return vec![[0.0, total]];
    }
    let count = ((total - overlap) / (usable - overlap)).ceil() as usize;
    let mut intervals = Vec::with_capacity(count);
    let mut start = 0.0;
    for k in 0..count - 1 {
        let remaining = (count - k - 1) as f64;
        let high = (start + usable).min(total);
        let low = (total - remaining * (usable - overlap)).max(start + 2.0 * overlap).min(high);
        let middle = 0.5 * (low + high);
        let cost = |end: f64| {
            let node = nodes.iter().any(|s| *s >= end - 1.25 * overlap && *s <= end + 0.25 * overlap);
            peak(arc_length, utilisation, end - overlap, end) + if node { NODE_PENALTY } else { 0.0 }
        };
        let end = (0..=CANDIDATES)
            .map(|i| low + (high - low) * i as f64 / CANDIDATES as f64)
            .map(|end| (cost(end), (end - middle).abs(), end))
            .fold((f64::INFINITY, f64::INFINITY, high), |best, c| if (c.0, c.1) < (best.0, best.1) { c } else { best })
            .2;
        intervals.push([start, end]);
        start = end - overlap;
    }
    intervals.push([start, total]);
    intervals
}

/// Largest value of the piecewise-linear profile `values(arc_length)` over `[from, to]`.
pub fn peak(arc_length: &[f64], values: &[f64], from: f64, to: f64) -> f64 {
    let inside = arc_length.iter().zip(values).filter(|(s, _)| **s >= from && **s <= to).map(|(_, v)| *v);
    inside.chain([interpolate(arc_length, values, from), interpolate(arc_length, values, to)]).fold(0.0, f64::max)
}

/// The piecewise-linear profile at `s` (clamped to its ends).
fn interpolate(arc_length: &[f64], values: &[f64], s: f64) -> f64 {
    let (index, fraction) = locate(arc_length, s);
    match values.get(index + 1) {
        Some(next) => values[index] + fraction * (next - values[index]),
        None => values.get(index).copied().unwrap_or(0.0),
    }
}

/// The segment `[i, i + 1]` of `arc_length` holding `s` and the fraction along it (clamped).
pub fn locate(arc_length: &[f64], s: f64) -> (usize, f64) {
    let n = arc_length.len();
    if n < 2 {
        return (0, 0.0);
    }
    let i = arc_length.partition_point(|x| *x <= s).clamp(1, n - 1) - 1;
    let span = arc_length[i + 1] - arc_length[i];
    let fraction = if span > 0.0 { ((s - arc_length[i]) / span).clamp(0.0, 1.0) } else { 0.0 };
    (i, fraction)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn check(intervals: &[[f64; 2]], total: f64, usable: f64, overlap: f64) {
        assert_eq!(intervals[0][0], 0.0);
        assert_eq!(intervals.last().expect("a piece")[1], total);
        for w in intervals.windows(2) {
            assert!((w[1][0] - (w[0][1] - overlap)).abs() < 1e-12);
        }
        for [a, b] in intervals {
            assert!(b - a <= usable + 1e-12 && b - a >= overlap, "{a}..{b}");
        }
        let sum: f64 = intervals.iter().map(|[a, b]| b - a).sum();
        assert!((sum - (total + overlap * (intervals.len() - 1) as f64)).abs() < 1e-9);
    }

    #[test]
    fn splices_avoid_the_curved_stretch_and_the_nodes() {
        let s: Vec<f64> = (0..=100).map(|i| 0.1 * i as f64).collect(); // 10 m
        // Highly stressed between 3.5 m and 4.5 m: a splice there is avoided.
        let u: Vec<f64> = s.iter().map(|x| if (3.5..=4.5).contains(x) { 1.5 } else { 0.2 }).collect();
        let intervals = splice_intervals(&s, &u, &[], 4.8, 0.3);
        assert_eq!(intervals.len(), 3);
        check(&intervals, 10.0, 4.8, 0.3);
        for [_, b] in &intervals[..2] {
            assert!(peak(&s, &u, b - 0.3, *b) < 1.0, "splice at {b}");
        }
        // A node at the middle-of-range splice moves it.
        let flat = vec![0.5; s.len()];
        let free = splice_intervals(&s, &flat, &[], 6.0, 0.3);
        let end = free[0][1];
        let moved = splice_intervals(&s, &flat, &[end - 0.1], 6.0, 0.3);
        check(&moved, 10.0, 6.0, 0.3);
        assert!(moved[0][1] - 1.25 * 0.3 > end - 0.1 || moved[0][1] + 0.25 * 0.3 < end - 0.1);
    }

    #[test]
    fn a_short_strip_is_one_piece() {
        assert_eq!(splice_intervals(&[0.0, 1.0, 2.0], &[0.0; 3], &[], 4.8, 0.3), vec![[0.0, 2.0]]);
    }
}
