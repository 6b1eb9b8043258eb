//! One level of nested dissection of the reduced normal matrix's graph: vertex separators S
//! that split the global variables into two domains no block couples (George 1973). Each cut's
//! bisecting coordinate is the difference of the graph distances to two far-apart vertices: the
//! ends of a pseudo-diameter (found as in George & Liu 1979) or of a second path across it;
//! [`super::substructured_cholesky`] takes the cut whose factorisation costs least.
//!
//! Two vertices are adjacent when an entry of the pattern couples them, i.e. when some block or
//! local group involves both. Every pair adjacent across the split has its second vertex in S, so
//! no block touches both domains: each domain's blocks and groups assemble a matrix of their own,
//! and the two are factorised at the same time (see [`super::substructured_cholesky`]).

/// Smallest dimension worth splitting: below it the dense separator work outweighs the gain.
const MIN_DIMENSION: usize = 400;

/// Largest separator proposed: the dimension n over `MAX_SEPARATOR_DIVISOR`. The separator's
/// Schur complement is dense (s² memory, s³/3 work), so it must stay small next to the sparse
/// factorisations; long-range couplings (possible in a general least-squares problem) make
/// separators grow towards a fraction of n.
const MAX_SEPARATOR_DIVISOR: usize = 8;

/// Cuts are proposed with separators up to this factor above the smallest: the cheapest split
/// has had a separator within 10 % of the smallest (nets, webs and fields of 1,400 to 200,000
/// vertices), and each cut proposed costs its two domains' symbolic analyses.
const SEPARATOR_SLACK: f64 = 1.25;

/// The part of a variable in a bisection.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Part {
    /// Interior of domain 0 or 1.
    Domain(u8),
    Separator,
}

/// Cuts of the variables of the symmetric pattern given by its upper triangle (CSC, `col_ptr`,
/// `row_idx`) into two domains and a separator, each balanced and with a separator of at most
/// n / `MAX_SEPARATOR_DIVISOR` variables and at most [`SEPARATOR_SLACK`] times the smallest,
/// distinct, in a fixed order. Empty when splitting cannot pay: a small or disconnected graph, or
/// only separators above n / `MAX_SEPARATOR_DIVISOR`.
///
/// Each cut follows the coordinate d_p − d_q of the graph distances to two far-apart vertices p,
/// q: the ends a, b of a pseudo-diameter, and the ends c, d of a second path across it (c the
/// vertex farthest from both a and b, d the vertex farthest from c), in the pairs (a, b), (c, d),
/// (a, c), (a, d), (b, c), (b, d). On a rectangle a, b are opposite corners and c, d the other
/// two, so a pair along a side cuts across the short way, where the pseudo-diameter alone cuts
/// diagonally; on an irregular mesh the cuts' separators differ by up to half.
pub(crate) fn candidate_cuts(col_ptr: &[usize], row_idx: &[usize]) -> Vec<Vec<Part>> {
    let n = col_ptr.len() - 1;
    if n < MIN_DIMENSION {
        return Vec::new();
    }
    let graph = Adjacency::from_upper(col_ptr, row_idx);
    let from_first = graph.distances(0);
    if from_first.contains(&u32::MAX) {
        return Vec::new();
    }
    let a = farthest(&from_first);
    let from_a = graph.distances(a);
    let b = farthest(&from_a);
    let from_b = graph.distances(b);
    let c = (0..n).max_by_key(|&v| (from_a[v].min(from_b[v]), v)).unwrap_or(0);
    let from_c = graph.distances(c);
    let from_d = graph.distances(farthest(&from_c));
    let ends = [&from_a, &from_b, &from_c, &from_d];
    let mut cuts: Vec<(usize, Vec<Part>)> = Vec::new();
    for (p, q) in [(0, 1), (2, 3), (0, 2), (0, 3), (1, 2), (1, 3)] {
        let Some(parts) = graph.balanced_split(ends[p], ends[q]) else { continue };
        let separator = parts.iter().filter(|&&part| part == Part::Separator).count();
        if separator * MAX_SEPARATOR_DIVISOR <= n && cuts.iter().all(|(_, cut)| *cut != parts) {
            cuts.push((separator, parts));
        }
    }
    let smallest = cuts.iter().map(|&(separator, _)| separator).min().unwrap_or(0);
    cuts.into_iter().filter(|&(separator, _)| separator as f64 <= SEPARATOR_SLACK * smallest as f64).map(|(_, parts)| parts).collect()
}

/// The last vertex reached at the greatest distance (ties go to the larger index).
fn farthest(distance: &[u32]) -> usize {
    (0..distance.len()).max_by_key(|&v| (distance[v], v)).unwrap_or(0)
}

/// Symmetric adjacency lists without the diagonal (CSR).
struct Adjacency {
    ptr: Vec<usize>,
    neighbours: Vec<usize>,
}

impl Adjacency {
    fn from_upper(col_ptr: &[usize], row_idx: &[usize]) -> Self {
        let n = col_ptr.len() - 1;
        let off_diagonal = || (0..n).flat_map(|c| row_idx[col_ptr[c]..col_ptr[c + 1]].iter().map(move |&r| (r, c))).filter(|(r, c)| r != c);
        let mut ptr = vec![0usize; n + 1];
        for (r, c) in off_diagonal() {
            ptr[r + 1] += 1;
            ptr[c + 1] += 1;
        }
        for v in 0..n {
            ptr[v + 1] += ptr[v];
        }
        let mut fill = ptr.clone();
        let mut neighbours = vec![0usize; ptr[n]];
        for (r, c) in off_diagonal() {
            neighbours[fill[r]] = c;
            fill[r] += 1;
            neighbours[fill[c]] = r;
            fill[c] += 1;
        }
        Self { ptr, neighbours }
    }

    fn neighbours(&self, v: usize) -> &[usize] {
        &self.neighbours[self.ptr[v]..self.ptr[v + 1]]
    }

    /// Breadth-first distances from `source` (`u32::MAX` where unreachable).
    fn distances(&self, source: usize) -> Vec<u32> {
        let n = self.ptr.len() - 1;
        let mut distance = vec![u32::MAX; n];
        let mut queue = Vec::with_capacity(n);
        distance[source] = 0;
        queue.push(source);
        let mut head = 0;
        while head < queue.len() {
            let v = queue[head];
            head += 1;
            for &w in self.neighbours(v) {
                if distance[w] == u32::MAX {
                    distance[w] = distance[v] + 1;
                    queue.push(w);
                }
            }
        }
        distance
    }

    /// The split along the coordinate `from_p − from_q` (graph distances to two ends) whose two
    /// interiors balance: domain 0 takes the first k variables in that order, the separator is
    /// the boundary of the rest towards it, and a second pass sizes k so that the interiors hold
    /// about as many variables. `None` when a domain is empty.
    fn balanced_split(&self, from_p: &[u32], from_q: &[u32]) -> Option<Vec<Part>> {
        let n = from_p.len();
        let mut order: Vec<usize> = (0..n).collect();
        order.sort_unstable_by_key(|&v| (from_p[v] as i64 - from_q[v] as i64, v));
        let mut parts = self.split(&order, n / 2);
        let separator = parts.iter().filter(|&&p| p == Part::Separator).count();
        if separator > 0 && separator < n {
            parts = self.split(&order, (n - separator) / 2);
        }
        let count = |part: Part| parts.iter().filter(|&&p| p == part).count();
        (count(Part::Domain(0)) > 0 && count(Part::Domain(1)) > 0).then_some(parts)
    }

    /// Domain 0 = the first `k` variables of `order`; the others adjacent to it form the
    /// separator; the rest is domain 1.
    fn split(&self, order: &[usize], k: usize) -> Vec<Part> {
        let mut parts = vec![Part::Domain(1); order.len()];
        for &v in &order[..k] {
            parts[v] = Part::Domain(0);
        }
        for &v in &order[k..] {
            if self.neighbours(v).iter().any(|&w| parts[w] == Part::Domain(0)) {
                parts[v] = Part::Separator;
            }
        }
        parts
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Upper CSC pattern of the 5-point stencil on a w × h grid (vertex x + w·y).
    fn grid(w: usize, h: usize) -> (Vec<usize>, Vec<usize>) {
        let (mut col_ptr, mut row_idx) = (vec![0], Vec::new());
        for c in 0..w * h {
            let (x, y) = (c % w, c / w);
            if y > 0 {
                row_idx.push(c - w);
            }
            if x > 0 {
                row_idx.push(c - 1);
            }
            row_idx.push(c);
            col_ptr.push(row_idx.len());
        }
        (col_ptr, row_idx)
    }

    fn separator_len(parts: &[Part]) -> usize {
        parts.iter().filter(|&&p| p == Part::Separator).count()
    }

    /// Every cut of the pattern splits it into balanced domains that no entry couples; returns
    /// the smallest separator.
    fn smallest_valid_separator(col_ptr: &[usize], row_idx: &[usize]) -> usize {
        let cuts = candidate_cuts(col_ptr, row_idx);
        assert!(!cuts.is_empty(), "no cut");
        for parts in &cuts {
            for c in 0..col_ptr.len() - 1 {
                for &r in &row_idx[col_ptr[c]..col_ptr[c + 1]] {
                    let crossing = matches!((parts[r], parts[c]), (Part::Domain(a), Part::Domain(b)) if a != b);
                    assert!(!crossing, "entry ({r}, {c}) couples the two domains");
                }
            }
            let count = |p| parts.iter().filter(|&&q| q == p).count();
            let (first, second, separator) = (count(Part::Domain(0)), count(Part::Domain(1)), count(Part::Separator));
            assert!(first.abs_diff(second) <= separator, "domains of {first} and {second} vertices");
        }
        cuts.iter().map(|parts| separator_len(parts)).min().unwrap_or(0)
    }

    #[test]
    fn every_cut_separates_the_domains() {
        let (w, h) = (60, 25);
        let (col_ptr, row_idx) = grid(w, h);
        // The cut across the short side: one column.
        assert_eq!(smallest_valid_separator(&col_ptr, &row_idx), h);
    }

    /// Upper CSC pattern of a w × h grid triangulated with each square's diagonal in one of two
    /// directions, chosen by a fixed irregular rule (vertex x + w·y): the graph distances of an
    /// irregular surface mesh, whose level sets are not straight.
    fn irregular_triangulation(w: usize, h: usize) -> (Vec<usize>, Vec<usize>) {
        let (mut col_ptr, mut row_idx) = (vec![0], Vec::new());
        for c in 0..w * h {
            let (x, y) = (c % w, c / w);
            let rising = (x * 7 + y * 13 + (x * y) % 5) % 3 != 0;
            if y > 0 && x > 0 && rising {
                row_idx.push(c - w - 1);
            }
            if y > 0 {
                row_idx.push(c - w);
            }
            if y > 0 && x + 1 < w && !rising {
                row_idx.push(c - w + 1);
            }
            if x > 0 {
                row_idx.push(c - 1);
            }
            row_idx.push(c);
            col_ptr.push(row_idx.len());
        }
        (col_ptr, row_idx)
    }

    #[test]
    fn a_square_is_cut_across_a_side_not_along_its_diagonal() {
        // The pseudo-diameter of a 55 × 55 square runs corner to corner, and the cut along the
        // difference of the distances to its ends alone took 97 vertices; a side is 55.
        let (col_ptr, row_idx) = irregular_triangulation(55, 55);
        let smallest = smallest_valid_separator(&col_ptr, &row_idx);
        assert!(smallest <= 60, "separator of {smallest} vertices");
    }

    #[test]
    fn long_range_couplings_swell_the_separator() {
        // A 100 × 100 grid splits with a separator of one row.
        let (col_ptr, row_idx) = grid(100, 100);
        assert_eq!(smallest_valid_separator(&col_ptr, &row_idx), 100);
        // 100 couplings between far-apart vertices: every cut crosses many of them (several
        // hundred variables, still below n/8 = 1,250), so splits are proposed
        // (`substructured_cholesky` then keeps one domain: the dense part would dominate).
        let n = 100 * 100;
        let mut columns: Vec<Vec<usize>> = (0..n).map(|c| row_idx[col_ptr[c]..col_ptr[c + 1]].to_vec()).collect();
        for k in 0..100 {
            let (a, b) = ((k * 7919) % n, (k * 104_729 + 5000) % n);
            columns[a.max(b)].push(a.min(b));
        }
        let (mut col_ptr, mut row_idx) = (vec![0], Vec::new());
        for mut column in columns {
            column.sort_unstable();
            column.dedup();
            row_idx.extend(column);
            col_ptr.push(row_idx.len());
        }
        let smallest = smallest_valid_separator(&col_ptr, &row_idx);
        assert!(smallest > 4 * 100, "separator of {smallest}");
    }

    #[test]
    fn small_or_disconnected_patterns_are_not_split() {
        let (col_ptr, row_idx) = grid(10, 10);
        assert!(candidate_cuts(&col_ptr, &row_idx).is_empty());
        // Two 30 × 10 grids side by side, no coupling between them.
        let (mut col_ptr, mut row_idx) = grid(30, 10);
        let (second_ptr, second_rows) = grid(30, 10);
        let offset = 300;
        for c in 0..300 {
            row_idx.extend(second_rows[second_ptr[c]..second_ptr[c + 1]].iter().map(|r| r + offset));
            col_ptr.push(row_idx.len());
        }
        assert!(candidate_cuts(&col_ptr, &row_idx).is_empty());
    }
}
