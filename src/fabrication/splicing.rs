//! Splitting a strip longer than the stock into pieces that overlap at splices, with the splices
//! where the strip bends least and away from nodes.
//!
//! Pieces of at most `S` cover a centre line of length `L` with overlaps `o`: piece `k` spans
//! `[a_k, b_k]` with `a_0 = 0`, `a_{k+1} = b_k − o`, `b_{n−1} = L`, so the piece lengths sum to
//! `L + (n − 1) o`; each piece is at least `2 o` long (a middle piece holds an overlap at each end).
//! The splice ends `b_k` are chosen on a grid of step at most `o/8` by dynamic programming over
//! the whole strip, minimising, in this order: `2 n + 5 h`, with `h` the splices that have a node
//! within a quarter overlap of their overlap `[b_k − o, b_k]` (so one more piece is worth less than
//! a node kept clear, three more are not); the sum over the splices of the largest utilisation in
//! their overlap; the sum of the squared piece lengths (pieces of even length).

/// Weights of the pieces and of the splices at a node in the first criterion.
const PIECE_COST: u32 = 2;
const NODE_COST: u32 = 5;
/// Grid steps per overlap (and at least this many per usable length).
const STEPS: f64 = 8.0;

/// The cost of a chain of pieces, compared lexicographically (see the module docs).
#[derive(Clone, Copy, Debug, PartialEq, PartialOrd)]
struct Cost {
    count: u32,
    utilisation: f64,
    evenness: f64,
}

impl Cost {
    fn then(self, piece: f64, splice: Option<(bool, f64)>) -> Cost {
        let (node, utilisation) = splice.unwrap_or((false, 0.0));
        Cost { count: self.count + PIECE_COST + if node { NODE_COST } else { 0 }, utilisation: self.utilisation + utilisation, evenness: self.evenness + piece * piece }
    }
}

/// Where the pieces of one strip start and end, arc lengths from the centre line's start (see the
/// module docs); `usable` must exceed `2 overlap`.
pub fn splice_intervals(arc_length: &[f64], utilisation: &[f64], nodes: &[f64], usable: f64, overlap: f64) -> Vec<[f64; 2]> {
    let total = arc_length.last().copied().unwrap_or(0.0);
    if total <= usable {
        return vec![[0.0, total]];
    }
    let step = if overlap > 0.0 { overlap / STEPS } else { f64::INFINITY }.min(usable / STEPS);
    let count = (total / step).ceil() as usize;
    let ends: Vec<f64> = (1..count).map(|j| total * j as f64 / count as f64).collect();
    let fits = |length: f64| length >= 2.0 * overlap && length <= usable;
    let splice = |end: f64| (nodes.iter().any(|s| *s >= end - 1.25 * overlap && *s <= end + 0.25 * overlap), peak(arc_length, utilisation, end - overlap, end));
    // best[j]: the cheapest chain of pieces whose last one ends at ends[j], and where the one
    // before it ended (None: it starts the strip).
    let mut best: Vec<Option<(Cost, Option<usize>)>> = vec![None; ends.len()];
    for j in 0..ends.len() {
        let here = splice(ends[j]);
        let mut choice = fits(ends[j]).then(|| (Cost { count: 0, utilisation: 0.0, evenness: 0.0 }.then(ends[j], Some(here)), None));
        let earliest = ends.partition_point(|e| *e < ends[j] + overlap - usable);
        for i in earliest..j {
            let piece = ends[j] - (ends[i] - overlap);
            if let (true, Some((cost, _))) = (fits(piece), best[i]) {
                let cost = cost.then(piece, Some(here));
                if choice.is_none_or(|(c, _)| cost < c) {
                    choice = Some((cost, Some(i)));
                }
            }
        }
        best[j] = choice;
    }
    let last = (0..ends.len())
        .filter_map(|j| {
            let piece = total - (ends[j] - overlap);
            best[j].filter(|_| fits(piece)).map(|(cost, _)| (cost.then(piece, None), j))
        })
        .fold(None, |chosen: Option<(Cost, usize)>, (cost, j)| if chosen.is_none_or(|(c, _)| cost < c) { Some((cost, j)) } else { chosen });
    let Some((_, mut j)) = last else { return even_intervals(total, usable, overlap) };
    let mut splices = vec![ends[j]];
    while let Some((_, Some(i))) = best[j] {
        splices.push(ends[i]);
        j = i;
    }
    splices.reverse();
    let mut intervals = Vec::with_capacity(splices.len() + 1);
    let mut start = 0.0;
    for end in splices {
        intervals.push([start, end]);
        start = end - overlap;
    }
    intervals.push([start, total]);
    intervals
}

/// The fewest pieces of equal length (when the grid leaves no chain, which a strip barely longer
/// than a board may).
fn even_intervals(total: f64, usable: f64, overlap: f64) -> Vec<[f64; 2]> {
    let count = ((total - overlap) / (usable - overlap)).ceil().max(1.0) as usize;
    let length = (total + (count - 1) as f64 * overlap) / count as f64;
    (0..count).map(|k| [k as f64 * (length - overlap), if k + 1 == count { total } else { k as f64 * (length - overlap) + length }]).collect()
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
    fn a_piece_more_keeps_the_splices_clear_of_nodes_the_fewest_cannot_avoid() {
        let s: Vec<f64> = (0..=100).map(|i| 0.1 * i as f64).collect(); // 10 m
        let flat = vec![0.5; s.len()];
        // Three pieces of 3.6 m with 0.3 m overlaps leave the first splice 0.2 m of freedom
        // (ending within [3.4, 3.6] m); a node at 3.45 m is within a quarter overlap of every such
        // splice, so a fourth piece is used.
        let fewest = splice_intervals(&s, &flat, &[], 3.6, 0.3);
        assert_eq!(fewest.len(), 3);
        let nodes = [3.45];
        let intervals = splice_intervals(&s, &flat, &nodes, 3.6, 0.3);
        assert_eq!(intervals.len(), 4, "{intervals:?}");
        check(&intervals, 10.0, 3.6, 0.3);
        for [_, b] in &intervals[..3] {
            assert!(nodes.iter().all(|n| *n < b - 1.25 * 0.3 || *n > b + 0.25 * 0.3), "splice at {b}");
        }
    }

    #[test]
    fn a_short_strip_is_one_piece() {
        assert_eq!(splice_intervals(&[0.0, 1.0, 2.0], &[0.0; 3], &[], 4.8, 0.3), vec![[0.0, 2.0]]);
    }
}
