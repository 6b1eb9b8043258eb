//! The default start field of a shading design (Sec. 6): the height along the earth axis when
//! some vertex blocks (the paper's planar start: level curves in planes orthogonal to the earth
//! axis), else the height across the central light of the pass region and the mean normal
//! (level planes that contain the central light).

use super::labels::VertexLabel;
use super::params::ShadingParams;
use crate::mesh::{TriMesh, Vec3};

/// Which default start [`default_start`] took.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
pub enum StartKind {
    /// Height along the earth axis (some vertex blocks).
    EarthAxisHeight,
    /// Height across the central light of the pass region (every labelled vertex lets through).
    AcrossCentralLight,
}

/// The start field (one value per vertex: the height along the returned unit model direction)
/// for `labels` (one per vertex) under `params`.
pub fn default_start(mesh: &TriMesh, params: &ShadingParams, labels: &[VertexLabel]) -> (Vec<f64>, Vec3, StartKind) {
    let frame = &params.frame;
    let (direction, kind) = if labels.contains(&VertexLabel::Block) {
        (frame.axes[2], StartKind::EarthAxisHeight)
    } else {
        let normal: Vec3 = mesh.vertex_normals().iter().sum();
        let across = frame.to_model(&params.pass_region.central_direction()).cross(&normal);
        (across.try_normalize(1e-12).unwrap_or(frame.axes[2]), StartKind::AcrossCentralLight)
    };
    (mesh.positions().iter().map(|p| p.dot(&direction)).collect(), direction, kind)
}
