//! Where the next point is searched (Fig. 13): the edges of the triangle across the current
//! edge and, near a vertex or when that triangle holds no solution, the edges opposite the
//! current edge's end vertices in their whole one-rings.

use crate::mesh::{EdgeFaces, EdgePoint, TriMesh};

/// An edge `[a, b]` (`a < b`) on which the next point may lie, with the face whose interior the
/// segment to it crosses, and whether it is a boundary edge (where the curve will end).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct CandidateEdge {
    pub edge: [u32; 2],
    pub face: u32,
    pub on_boundary: bool,
}

/// How widely to search around the current point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Reach {
    /// The triangle across the edge, plus the one-ring of an end vertex within this fraction
    /// of the edge (the authors' 1 % vertex merge: a curve passing close to a vertex does not
    /// stall in its thin wedges).
    Near { vertex_ratio: f64 },
    /// The triangle across the edge and the one-rings of both end vertices (the widened
    /// second round, for a curve that leaves the triangle pair just past a vertex).
    Wide,
}

/// The candidate edges around `point` (canonical, on a mesh edge), excluding the face the
/// curve arrived through (`None` at the start point):
/// * the other two edges of each face of the current edge except `arrived`, i.e. the triangle
///   across the edge (at the start point its boundary face);
/// * the edge opposite `v` in every face of the one-ring of each end vertex `v` that `reach`
///   includes, except `arrived`.
///
/// Each edge appears once, with the first face that reached it, in a deterministic order.
pub(crate) fn candidate_edges(
    mesh: &TriMesh,
    adjacency: &EdgeFaces,
    point: &EdgePoint,
    arrived: Option<u32>,
    reach: Reach,
) -> Vec<CandidateEdge> {
    let [a, b] = point.edge;
    let mut candidates: Vec<CandidateEdge> = Vec::new();
    let mut push = |edge: [u32; 2], face: u32| {
        let edge = [edge[0].min(edge[1]), edge[0].max(edge[1])];
        if edge != point.edge && !candidates.iter().any(|c| c.edge == edge) {
            let on_boundary = adjacency.is_boundary_edge(edge[0], edge[1]);
            candidates.push(CandidateEdge { edge, face, on_boundary });
        }
    };
    let faces = mesh.faces();
    if let Some((first, second)) = adjacency.faces(a, b) {
        for f in [Some(first), second].into_iter().flatten().filter(|&f| Some(f) != arrived) {
            // Internal invariant: adjacency faces index the mesh's faces.
            let corners = faces[f as usize];
            for c in 0..3 {
                push([corners[c], corners[(c + 1) % 3]], f);
            }
        }
    }
    let rings: &[u32] = match reach {
        Reach::Near { vertex_ratio } if point.t <= vertex_ratio => &[a],
        Reach::Near { vertex_ratio } if point.t >= 1.0 - vertex_ratio => &[b],
        Reach::Near { .. } => &[],
        Reach::Wide => &[a, b],
    };
    for &v in rings {
        // Internal invariant: `v` is a validated vertex index.
        for &f in mesh.star(v as usize).faces.iter().filter(|&&f| Some(f) != arrived) {
            let corners = faces[f as usize];
            // The corner order within the face is irrelevant: take the two corners that are not v.
            let others: Vec<u32> = corners.iter().copied().filter(|&c| c != v).collect();
            if let [x, y] = others[..] {
                push([x, y], f);
            }
        }
    }
    candidates
}
