//! Edge → face adjacency: the one or two faces of every undirected edge, for walking across an
//! edge from one triangle to its neighbour (the triangle pair of the tracing step, Fig. 13).

use super::TriMesh;

/// Marks the missing second face of a boundary edge.
const NO_FACE: u32 = u32::MAX;

/// The faces of each edge of a mesh, indexed like [`TriMesh::edges`].
#[derive(Clone, Debug, PartialEq)]
pub struct EdgeFaces {
    edges: Vec<[u32; 2]>,
    faces: Vec<[u32; 2]>,
}

impl EdgeFaces {
    /// Builds the adjacency of `mesh` (validated, so every edge has one or two faces).
    pub fn new(mesh: &TriMesh) -> EdgeFaces {
        let edges = mesh.edges().to_vec();
        let mut faces = vec![[NO_FACE; 2]; edges.len()];
        for (f, face) in mesh.faces().iter().enumerate() {
            for c in 0..3 {
                let (a, b) = (face[c], face[(c + 1) % 3]);
                // Internal invariant: every face edge is one of the mesh's edges, used by at
                // most two faces (the mesh is validated manifold).
                let e = edges.binary_search(&[a.min(b), a.max(b)]).expect("face edge is a mesh edge");
                let slot = if faces[e][0] == NO_FACE { 0 } else { 1 };
                faces[e][slot] = f as u32;
            }
        }
        EdgeFaces { edges, faces }
    }

    /// Index of the undirected edge `{a, b}` in [`TriMesh::edges`], if it is an edge.
    pub fn edge_index(&self, a: u32, b: u32) -> Option<usize> {
        self.edges.binary_search(&[a.min(b), a.max(b)]).ok()
    }

    /// The faces of edge `{a, b}`: the first, and the second unless it is a boundary edge.
    /// `None` if `{a, b}` is not an edge.
    pub fn faces(&self, a: u32, b: u32) -> Option<(u32, Option<u32>)> {
        let [first, second] = self.faces[self.edge_index(a, b)?];
        Some((first, (second != NO_FACE).then_some(second)))
    }

    /// Whether `{a, b}` is an edge with a single face.
    pub fn is_boundary_edge(&self, a: u32, b: u32) -> bool {
        matches!(self.faces(a, b), Some((_, None)))
    }

    /// The face across edge `{a, b}` from `face`: `None` at the boundary, or if `{a, b}` is not
    /// an edge of `face`.
    pub fn across(&self, a: u32, b: u32, face: u32) -> Option<u32> {
        match self.faces(a, b)? {
            (first, Some(second)) if first == face => Some(second),
            (first, Some(second)) if second == face => Some(first),
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::Vec3;

    #[test]
    fn two_triangles_share_their_diagonal() {
        let positions = vec![
            Vec3::new(0.0, 0.0, 0.0),
            Vec3::new(1.0, 0.0, 0.0),
            Vec3::new(1.0, 1.0, 0.0),
            Vec3::new(0.0, 1.0, 0.0),
        ];
        let mesh = TriMesh::from_vertices_and_faces(positions, vec![[0, 1, 2], [0, 2, 3]]).expect("valid");
        let adjacency = EdgeFaces::new(&mesh);
        assert_eq!(adjacency.faces(2, 0), Some((0, Some(1))));
        assert_eq!(adjacency.across(0, 2, 0), Some(1));
        assert_eq!(adjacency.across(0, 2, 1), Some(0));
        assert_eq!(adjacency.across(0, 1, 0), None);
        assert!(adjacency.is_boundary_edge(1, 0));
        assert!(!adjacency.is_boundary_edge(0, 2));
        assert_eq!(adjacency.faces(1, 3), None);
        assert_eq!(adjacency.faces(7, 9), None);
    }
}
