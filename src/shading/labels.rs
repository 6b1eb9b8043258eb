//! Mixed regions on one model (Sec. 6, Fig. 38): each vertex blocks the light, lets it through,
//! or is free (a transition vertex with only the fairness terms), and a ring of free vertices
//! separates the blocking part from the letting-through part.

use super::error::ShadingError;
use crate::mesh::TriMesh;
use std::collections::VecDeque;

/// What a vertex's strips do with the light.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
pub enum VertexLabel {
    /// `E_block` (Eq. 26): rectifying planes orthogonal to a light direction of the block region.
    Block,
    /// `E_light` (Eq. 27): the light of the pass region lies in the rectifying planes.
    Pass,
    /// Transition: fairness and gradient terms only.
    Free,
}

/// `labels` (one per vertex) with every `Block` vertex within `ring` edges of a `Pass` vertex,
/// and every `Pass` vertex within `ring` edges of a `Block` one, made `Free`: a transition band
/// about `2 · ring` edges wide (none for `ring = 0`). Errors on a wrong label count.
pub fn with_transition_ring(mesh: &TriMesh, labels: &[VertexLabel], ring: usize) -> Result<Vec<VertexLabel>, ShadingError> {
    if labels.len() != mesh.vertex_count() {
        return Err(ShadingError::invalid("labels", format!("{} labels for {} vertices", labels.len(), mesh.vertex_count())));
    }
    let to_pass = hop_distances(mesh, labels, VertexLabel::Pass);
    let to_block = hop_distances(mesh, labels, VertexLabel::Block);
    Ok(labels
        .iter()
        .enumerate()
        .map(|(v, &label)| match label {
            VertexLabel::Block if to_pass[v] <= ring => VertexLabel::Free,
            VertexLabel::Pass if to_block[v] <= ring => VertexLabel::Free,
            other => other,
        })
        .collect())
}

/// Edge hops from every vertex to the nearest vertex labelled `source` (`usize::MAX` if none).
fn hop_distances(mesh: &TriMesh, labels: &[VertexLabel], source: VertexLabel) -> Vec<usize> {
    let mut distance = vec![usize::MAX; labels.len()];
    let mut queue: VecDeque<usize> = (0..labels.len()).filter(|&v| labels[v] == source).collect();
    queue.iter().for_each(|&v| distance[v] = 0);
    while let Some(v) = queue.pop_front() {
        for &w in mesh.star(v).neighbours {
            if distance[w as usize] == usize::MAX {
                distance[w as usize] = distance[v] + 1;
                queue.push_back(w as usize);
            }
        }
    }
    distance
}
