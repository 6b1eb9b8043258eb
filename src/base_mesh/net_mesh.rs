//! A base mesh with regular combinatorics (paper Sec. 3.5): vertices and two families of
//! polylines, the rows and the columns, each vertex on at most one polyline of each family. Its
//! quads are the 2 × 2 blocks the polylines close.

use super::error::BaseMeshError;
use crate::mesh::Vec3;
use crate::net::QuadNet;

/// Most vertices a net may have (far above any gridshell; keeps the variable count in `u32`).
pub const MAX_NET_VERTICES: usize = 10_000_000;

/// A net of rows (family 0) and columns (family 1).
#[derive(Clone, Debug, PartialEq)]
pub struct NetMesh {
    positions: Vec<Vec3>,
    /// `polylines[k]`: the polylines of family `k`, as vertex indices.
    polylines: [Vec<Vec<u32>>; 2],
    /// Per vertex and family: the previous and the next vertex along its polyline.
    neighbours: Vec<[[Option<u32>; 2]; 2]>,
}

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
        let invalid = |message: String| Err(BaseMeshError::InvalidNet { message });
        let n = positions.len();
        if n == 0 || n > MAX_NET_VERTICES {
            return invalid(format!("{n} vertices; a net has 1 to {MAX_NET_VERTICES}"));
        }
        if let Some(v) = positions.iter().position(|p| !p.iter().all(|x| x.is_finite())) {
            return invalid(format!("vertex {v} has a non-finite coordinate"));
        }
        let mut neighbours = vec![[[None; 2]; 2]; n];
        for (k, (name, lines)) in [("row", &rows), ("column", &columns)].into_iter().enumerate() {
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
        Ok(NetMesh { positions, polylines: [rows, columns], neighbours })
    }

    /// The net of crossings of two fields' level sets (as extracted by [`crate::net::extract_quad_net`]).
    /// Errors as [`Self::new`] (a net extracted from a valid field pair has none).
    pub fn from_quad_net(net: &QuadNet) -> Result<NetMesh, BaseMeshError> {
        NetMesh::new(net.vertices.iter().map(|v| v.position).collect(), net.rows.clone(), net.columns.clone())
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

    /// The polylines of family `k` (0: rows, 1: columns).
    pub fn polylines(&self, k: usize) -> &[Vec<u32>] {
        &self.polylines[k]
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

    /// The vertices on a polyline of each family: the nodes of the strip structure.
    pub fn nodes(&self) -> impl Iterator<Item = usize> + '_ {
        (0..self.vertex_count()).filter(|&v| self.along(v, 0).on_polyline() && self.along(v, 1).on_polyline())
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
        assert!(message(NetMesh::new(same, r, c)).contains("vertices 0 and 1"));
    }
}
