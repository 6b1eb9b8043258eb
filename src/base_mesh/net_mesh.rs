//! A base mesh with regular combinatorics (paper Sec. 3.5): vertices and two families of
//! polylines, the rows and the columns (a quad net), or three, with the diagonals (a 3-web or a
//! Kagome pattern), each vertex on at most one polyline of each family. A net's quads are the
//! 2 × 2 blocks the polylines close, a web's triangles the cycles of one segment of each family.

use super::error::BaseMeshError;
use crate::mesh::Vec3;
use crate::net::{QuadNet, Web};

/// Most vertices a net may have (far above any gridshell; keeps the variable count in `u32`).
pub const MAX_NET_VERTICES: usize = 10_000_000;

/// A net of rows (family 0) and columns (family 1), and for a 3-web diagonals (family 2).
#[derive(Clone, Debug, PartialEq)]
pub struct NetMesh {
    positions: Vec<Vec3>,
    /// `polylines[k]`: the polylines of family `k`, as vertex indices (two or three families).
    polylines: Vec<Vec<Vec<u32>>>,
    /// Per vertex and family: the previous and the next vertex along its polyline (none along a
    /// net's absent third family).
    neighbours: Vec<[[Option<u32>; 2]; 3]>,
}

/// The names of the families' polylines in messages.
const POLYLINE_NAMES: [&str; 3] = ["row", "column", "diagonal"];

/// The neighbours of a vertex along one family's polyline.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Along {
    pub back: Option<u32>,
    pub front: Option<u32>,
}

impl Along {
    /// Both neighbours, when the vertex is inside its polyline.
    pub fn inner(&self) -> Option<(u32, u32)> {
        self.back.zip(self.front)
    }

    /// Whether the vertex lies on a polyline of this family.
    pub fn on_polyline(&self) -> bool {
        self.back.is_some() || self.front.is_some()
    }
}

impl NetMesh {
    /// The net of `positions` with `rows` and `columns` (vertex indices, in order along each
    /// polyline).
    ///
    /// Errors ([`BaseMeshError::InvalidNet`], naming the offending element): no vertex or more
    /// than [`MAX_NET_VERTICES`], a non-finite position, a polyline of fewer than two vertices,
    /// an index out of range, a vertex on two polylines of one family (or twice on one), two
    /// consecutive vertices at the same point.
    pub fn new(positions: Vec<Vec3>, rows: Vec<Vec<u32>>, columns: Vec<Vec<u32>>) -> Result<NetMesh, BaseMeshError> {
        NetMesh::with_families(positions, vec![rows, columns])
    }

    /// The 3-web (or Kagome pattern) of `positions` with `rows`, `columns` and `diagonals`, the
    /// third family. Errors as [`Self::new`].
    pub fn web(positions: Vec<Vec3>, rows: Vec<Vec<u32>>, columns: Vec<Vec<u32>>, diagonals: Vec<Vec<u32>>) -> Result<NetMesh, BaseMeshError> {
        NetMesh::with_families(positions, vec![rows, columns, diagonals])
    }

    fn with_families(positions: Vec<Vec3>, families: Vec<Vec<Vec<u32>>>) -> Result<NetMesh, BaseMeshError> {
        let invalid = |message: String| Err(BaseMeshError::InvalidNet { message });
        let n = positions.len();
        if n == 0 || n > MAX_NET_VERTICES {
            return invalid(format!("{n} vertices; a net has 1 to {MAX_NET_VERTICES}"));
        }
        if let Some(v) = positions.iter().position(|p| !p.iter().all(|x| x.is_finite())) {
            return invalid(format!("vertex {v} has a non-finite coordinate"));
        }
        let mut neighbours = vec![[[None; 2]; 3]; n];
        for (k, (name, lines)) in POLYLINE_NAMES.into_iter().zip(&families).enumerate() {
            for (l, line) in lines.iter().enumerate() {
                if line.len() < 2 {
                    return invalid(format!("{name} {l} has {} vertices; a polyline needs at least 2", line.len()));
                }
                if let Some(&v) = line.iter().find(|&&v| v as usize >= n) {
                    return invalid(format!("{name} {l} refers to vertex {v}, but the net has {n}"));
                }
                for (s, pair) in line.windows(2).enumerate() {
                    if positions[pair[0] as usize] == positions[pair[1] as usize] {
                        return invalid(format!("{name} {l}: vertices {} and {} (segment {s}) are at the same point", pair[0], pair[1]));
                    }
                }
                for (s, &v) in line.iter().enumerate() {
                    let slot = &mut neighbours[v as usize][k];
                    if slot.iter().any(Option::is_some) {
                        return invalid(format!("vertex {v} lies on two {name}s (or twice on {name} {l}); each vertex is on at most one {name}"));
                    }
                    *slot = [s.checked_sub(1).map(|p| line[p]), line.get(s + 1).copied()];
                }
            }
        }
        Ok(NetMesh { positions, polylines: families, neighbours })
    }

    /// The net of crossings of two fields' level sets (as extracted by [`crate::net::extract_quad_net`]).
    /// Errors as [`Self::new`] (a net extracted from a valid field pair has none).
    pub fn from_quad_net(net: &QuadNet) -> Result<NetMesh, BaseMeshError> {
        NetMesh::new(net.vertices.iter().map(|v| v.position).collect(), net.rows.clone(), net.columns.clone())
    }

    /// The web extracted from three fields' level sets ([`crate::net::extract_web`]): its
    /// polylines of each family as rows, columns and diagonals. Errors as [`Self::new`].
    pub fn from_web(web: &Web) -> Result<NetMesh, BaseMeshError> {
        let [rows, columns, diagonals] = web.polylines.each_ref().map(|family| family.iter().map(|(_, line)| line.clone()).collect());
        NetMesh::web(web.vertices.iter().map(|v| v.position).collect(), rows, columns, diagonals)
    }

    /// The same net at other positions (one per vertex, finite, checked by the caller).
    pub(crate) fn with_positions(&self, positions: Vec<Vec3>) -> NetMesh {
        NetMesh { positions, ..self.clone() }
    }

    pub fn positions(&self) -> &[Vec3] {
        &self.positions
    }

    pub fn vertex_count(&self) -> usize {
        self.positions.len()
    }

    /// The rows (family 0).
    pub fn rows(&self) -> &[Vec<u32>] {
        &self.polylines[0]
    }

    /// The columns (family 1).
    pub fn columns(&self) -> &[Vec<u32>] {
        &self.polylines[1]
    }

    /// The diagonals (family 2 of a web; none in a net).
    pub fn diagonals(&self) -> &[Vec<u32>] {
        self.polylines.get(2).map_or(&[], Vec::as_slice)
    }

    /// The polylines of family `k` (0: rows, 1: columns, 2: diagonals).
    pub fn polylines(&self, k: usize) -> &[Vec<u32>] {
        &self.polylines[k]
    }

    /// Two for a net, three for a web.
    pub fn family_count(&self) -> usize {
        self.polylines.len()
    }

    /// Where vertex `v` sits on the polyline of family `k`.
    pub(crate) fn along(&self, v: usize, k: usize) -> Along {
        let [back, front] = self.neighbours[v][k];
        Along { back, front }
    }

    /// The segments of family `k`'s polylines, each as its two vertices in polyline order.
    pub fn segments(&self, k: usize) -> impl Iterator<Item = [u32; 2]> + '_ {
        self.polylines[k].iter().flat_map(|line| line.windows(2).map(|w| [w[0], w[1]]))
    }

    /// The quads the polylines close: `[a, b, d, c]` for a row segment `a → b` whose vertices
    /// continue along their columns to `c`, `d` with `c → d` a row segment (for a net extracted
    /// by [`crate::net::extract_quad_net`], the quads of [`QuadNet::quads`]).
    pub fn quads(&self) -> Vec<[u32; 4]> {
        self.segments(0)
            .filter_map(|[a, b]| {
                let (c, d) = (self.neighbours[a as usize][1][1]?, self.neighbours[b as usize][1][1]?);
                (self.neighbours[c as usize][0][1] == Some(d)).then_some([a, b, d, c])
            })
            .collect()
    }

    /// A web's triangles: three vertices joined by a segment of each family, as
    /// `[a, b, c]` with `a → b` a row segment (in a 3-web, the halves of the rows' and columns'
    /// quads; in a Kagome pattern, its triangles). None in a net.
    pub fn triangles(&self) -> Vec<[u32; 3]> {
        if self.family_count() < 3 {
            return Vec::new();
        }
        let joined = |a: u32, b: u32, k: usize| self.neighbours[a as usize][k].contains(&Some(b));
        let mut triangles = Vec::new();
        for [a, b] in self.segments(0) {
            // A triangle has one row segment: it can only repeat among this segment's candidates.
            let first = triangles.len();
            for c in self.neighbours[a as usize][1].into_iter().chain(self.neighbours[b as usize][1]).flatten() {
                let closed = (joined(a, c, 1) && joined(b, c, 2)) || (joined(b, c, 1) && joined(a, c, 2));
                if closed && !triangles[first..].contains(&[a, b, c]) {
                    triangles.push([a, b, c]);
                }
            }
        }
        triangles
    }

    /// The vertices where polylines of two or more families cross: the nodes of the strip
    /// structure.
    pub fn nodes(&self) -> impl Iterator<Item = usize> + '_ {
        (0..self.vertex_count()).filter(|&v| (0..self.family_count()).filter(|&k| self.along(v, k).on_polyline()).count() >= 2)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid(rows: usize, columns: usize) -> (Vec<Vec3>, Vec<Vec<u32>>, Vec<Vec<u32>>) {
        let positions = (0..rows).flat_map(|i| (0..columns).map(move |j| Vec3::new(j as f64, i as f64, 0.0))).collect();
        let r = (0..rows).map(|i| (0..columns).map(|j| (i * columns + j) as u32).collect()).collect();
        let c = (0..columns).map(|j| (0..rows).map(|i| (i * columns + j) as u32).collect()).collect();
        (positions, r, c)
    }

    #[test]
    fn a_grid_has_its_quads_and_neighbours() {
        let (p, r, c) = grid(3, 4);
        let net = NetMesh::new(p, r, c).unwrap();
        assert_eq!(net.quads().len(), 2 * 3);
        assert_eq!(net.quads()[0], [0, 1, 5, 4]);
        assert_eq!(net.along(5, 0).inner(), Some((4, 6)));
        assert_eq!(net.along(5, 1).inner(), Some((1, 9)));
        assert_eq!(net.along(0, 1).inner(), None);
        assert_eq!(net.nodes().count(), 12);
    }

    #[test]
    fn bad_nets_are_refused_naming_the_element() {
        let (p, r, c) = grid(2, 3);
        let message = |result: Result<NetMesh, BaseMeshError>| result.unwrap_err().to_string();
        assert!(message(NetMesh::new(p.clone(), vec![vec![0, 1, 9]], c.clone())).contains("row 0 refers to vertex 9"));
        assert!(message(NetMesh::new(p.clone(), vec![vec![0]], c.clone())).contains("row 0 has 1 vertices"));
        assert!(message(NetMesh::new(p.clone(), vec![vec![0, 1], vec![1, 2]], c.clone())).contains("vertex 1 lies on two rows"));
        let mut nan = p.clone();
        nan[4].y = f64::NAN;
        assert!(message(NetMesh::new(nan, r.clone(), c.clone())).contains("vertex 4"));
        let mut same = p;
        same[1] = same[0];
        assert!(message(NetMesh::new(same, r.clone(), c.clone())).contains("vertices 0 and 1"));
        let p = grid(2, 3).0;
        assert!(message(NetMesh::web(p, r, c, vec![vec![1, 3], vec![1, 4]])).contains("vertex 1 lies on two diagonals"));
    }

    #[test]
    fn a_triangulated_grid_has_its_triangles() {
        // Diagonals (i, j + 1) → (i + 1, j): the 3-web of a 3 × 4 grid.
        let (p, r, c) = grid(3, 4);
        let diagonals: Vec<Vec<u32>> = (1..5)
            .map(|sum| (0..3usize).filter(|&i| sum >= i && sum - i < 4).map(|i| (i * 4 + sum - i) as u32).collect::<Vec<u32>>())
            .filter(|line| line.len() >= 2)
            .collect();
        let net = NetMesh::web(p, r, c, diagonals).unwrap();
        assert_eq!(net.family_count(), 3);
        let triangles = net.triangles();
        assert_eq!(triangles.len(), 2 * 2 * 3, "{triangles:?}");
        assert!(triangles.contains(&[0, 1, 4]) && triangles.contains(&[4, 5, 1]), "{triangles:?}");
        assert_eq!(net.nodes().count(), 12);
        assert!(net.quads().len() == 6);
    }
}
