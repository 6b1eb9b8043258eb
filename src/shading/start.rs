//! The default start field of a shading design (Sec. 6, Fig. 34–35). When some vertex blocks:
//! the constant-slope family (about the earth axis) of the slope most faces vote for
//! ([`most_common_slope`]), or, when no face votes or no face is steep enough for that slope,
//! the height along the earth axis (the paper's planar start: curves in planes orthogonal to the
//! earth axis, slope 0). When every labelled vertex lets the light through: the height across
//! the central light of the pass region and the mean normal (level planes that contain the
//! central light).

use super::common_slope::{most_common_slope, SlopeVote};
use super::labels::VertexLabel;
use super::params::ShadingParams;
use crate::initialisation::slope_start_field;
use crate::mesh::{TriMesh, Vec3};

/// Which default start [`default_start`] took.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub enum StartKind {
    /// The constant-slope family of the voted slope about the earth axis (`direction`).
    ConstantSlope { slope_degrees: f64 },
    /// Height along the earth axis (some vertex blocks, but the vote gave no usable slope).
    EarthAxisHeight,
    /// Height across the central light of the pass region (every labelled vertex lets through).
    AcrossCentralLight,
}

/// A start field and how it was made.
#[derive(Clone, Debug, PartialEq)]
pub struct ShadingStart {
    /// One value per vertex.
    pub field: Vec<f64>,
    pub kind: StartKind,
    /// The earth axis of a constant-slope start, else the direction the field is the height along
    /// (unit model vector).
    pub direction: Vec3,
    /// The slope vote over the block region (when some vertex blocks and some face votes).
    pub vote: Option<SlopeVote>,
}

/// The start field for `labels` (one per vertex) under `params`.
pub fn default_start(mesh: &TriMesh, params: &ShadingParams, labels: &[VertexLabel]) -> ShadingStart {
    let frame = &params.frame;
    let height = |direction: Vec3| mesh.positions().iter().map(|p| p.dot(&direction)).collect();
    if !labels.contains(&VertexLabel::Block) {
        let normal: Vec3 = mesh.vertex_normals().iter().sum();
        let across = frame.to_model(&params.pass_region.central_direction()).cross(&normal);
        let direction = across.try_normalize(1e-12).unwrap_or(frame.axes[2]);
        return ShadingStart { field: height(direction), kind: StartKind::AcrossCentralLight, direction, vote: None };
    }
    let axis = frame.axes[2];
    let vote = most_common_slope(mesh, frame, &params.block_region);
    // The vote orients tangents along `axis × n` (slope = their rise); `slope_start_field` along
    // `n × axis`: the same lines have the opposite slope there.
    let sloped = vote.as_ref().and_then(|v| slope_start_field(mesh, axis.into(), -v.slope_degrees).ok().map(|field| (field, v.slope_degrees)));
    match sloped {
        Some((field, slope_degrees)) => ShadingStart { field, kind: StartKind::ConstantSlope { slope_degrees }, direction: axis, vote },
        None => ShadingStart { field: height(axis), kind: StartKind::EarthAxisHeight, direction: axis, vote },
    }
}
