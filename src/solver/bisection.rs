//! One level of nested dissection of the reduced normal matrix's graph: a vertex separator S
//! that splits the global variables into two domains no block couples (George 1973; the
//! bisecting coordinate is the difference of the graph distances to the two ends of a
//! pseudo-diameter, found as in George & Liu 1979).
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
/// Separators up to `MAX_SEPARATOR_PER_ROOT`·√n are small without weighing them: a surface
/// mesh's pattern with one variable per vertex splits with s ≈ 2.2√n (the hall roof at 600 to
/// 50,000 vertices, before the level jets; 3.4√n with them). With several variables per vertex
/// (the fields of a net, a vertex's position) s grows with their number, and whether the split
/// pays is weighed against the factorisation of the whole ([`separator_needs_weighing`]).
const MAX_SEPARATOR_PER_ROOT: f64 = 4.0;

/// The part of a variable in a bisection.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Part {
    /// Interior of domain 0 or 1.
    Domain(u8),
    Separator,
}

/// Whether a separator of `separator` variables splitting `n` is above `MAX_SEPARATOR_PER_ROOT`·√n,
/// so that the split must be weighed against the factorisation of the whole.
pub(crate) fn separator_needs_weighing(n: usize, separator: usize) -> bool {
    separator as f64 > MAX_SEPARATOR_PER_ROOT * (n as f64).sqrt()
}

/// Splits the variables of the symmetric pattern given by its upper triangle (CSC, `col_ptr`,
/// `row_idx`) into two domains and a separator. `None` when splitting cannot pay: a small or
/// disconnected graph, or a separator above n / `MAX_SEPARATOR_DIVISOR`.
pub(crate) fn bisect(col_ptr: &[usize], row_idx: &[usize]) -> Option<Vec<Part>> {
    let n = col_ptr.len() - 1;
    if n < MIN_DIMENSION {
        return None;
    }
    let graph = Adjacency::from_upper(col_ptr, row_idx);
    let from_first = graph.distances(0);
    if from_first.contains(&u32::MAX) {
        return None;
    }
    // Ends a, b of a pseudo-diameter; the bisecting coordinate d_a − d_b runs from a to b.
    let a = farthest(&from_first);
    let from_a = graph.distances(a);
    let from_b = graph.distances(farthest(&from_a));
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_unstable_by_key(|&v| (from_a[v] as i64 - from_b[v] as i64, v));

    // Domain 0 takes the first k variables in that order; the separator is the boundary of the
    // rest towards it. A second pass sizes k so that the two interiors balance.
    let mut parts = graph.split(&order, n / 2);
    let separator = parts.iter().filter(|&&p| p == Part::Separator).count();
    if separator > 0 && separator < n {
        parts = graph.split(&order, (n - separator) / 2);
    }
    let count = |part: Part| parts.iter().filter(|&&p| p == part).count();
    let separator = count(Part::Separator);
    let balanced = count(Part::Domain(0)) > 0 && count(Part::Domain(1)) > 0;
    (balanced && separator * MAX_SEPARATOR_DIVISOR <= n).then_some(parts)
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

    #[test]
    fn separator_cuts_every_coupling_between_the_domains() {
        let (w, h) = (60, 25);
        let (col_ptr, row_idx) = grid(w, h);
        let parts = bisect(&col_ptr, &row_idx).expect("a 1,500-vertex grid is split");
        for c in 0..w * h {
            for &r in &row_idx[col_ptr[c]..col_ptr[c + 1]] {
                let crossing = matches!((parts[r], parts[c]), (Part::Domain(a), Part::Domain(b)) if a != b);
                assert!(!crossing, "entry ({r}, {c}) couples the two domains");
            }
        }
        let count = |p| parts.iter().filter(|&&q| q == p).count();
        let (first, second, separator) = (count(Part::Domain(0)), count(Part::Domain(1)), count(Part::Separator));
        // A cut across the grid: at most the diagonal of the grid's extent, far below w·h / 8.
        assert!(separator <= w + h, "separator of {separator} vertices");
        assert!(first.abs_diff(second) <= separator, "domains of {first} and {second} vertices");
    }

    #[test]
    fn long_range_couplings_swell_the_separator_beyond_the_unweighed_size() {
        let separator = |parts: &[Part]| parts.iter().filter(|&&p| p == Part::Separator).count();
        // A 100 × 100 grid splits with a separator of about 100 (≤ 4√n = 400).
        let (col_ptr, row_idx) = grid(100, 100);
        let parts = bisect(&col_ptr, &row_idx).expect("a split");
        assert!(!separator_needs_weighing(col_ptr.len() - 1, separator(&parts)));
        // 100 couplings between far-apart vertices: the cut crosses them all (about 630
        // variables, still below n/8 = 1,250), so the split is proposed but must be weighed
        // (`substructured_cholesky` keeps one domain for it: the dense part would dominate).
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
        let parts = bisect(&col_ptr, &row_idx).expect("a split below n/8");
        assert!(separator_needs_weighing(n, separator(&parts)), "separator of {}", separator(&parts));
    }

    #[test]
    fn small_or_disconnected_patterns_are_not_split() {
        let (col_ptr, row_idx) = grid(10, 10);
        assert!(bisect(&col_ptr, &row_idx).is_none());
        // Two 30 × 10 grids side by side, no coupling between them.
        let (mut col_ptr, mut row_idx) = grid(30, 10);
        let (second_ptr, second_rows) = grid(30, 10);
        let offset = 300;
        for c in 0..300 {
            row_idx.extend(second_rows[second_ptr[c]..second_ptr[c + 1]].iter().map(|r| r + offset));
            col_ptr.push(row_idx.len());
        }
        assert!(bisect(&col_ptr, &row_idx).is_none());
    }
}
