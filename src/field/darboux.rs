//! The discrete Darboux frame of the level curve through a vertex (Sec. 2.2, 3.1), measured
//! from the field itself rather than from the solver's auxiliary variables: the independent
//! yardstick for how well a field meets its target angle at the scale of the mesh. The frame is
//! that of the level jet ([`super::level_jet`]): the level curve of the field's local quadratic
//! fit on the surface's osculating quadric.

use super::level_jet::{JetStencils, LevelJet};
use super::problem::level_jet_at;
use crate::mesh::{TriMesh, Vec3};


/// Frame of the level curve at a regular vertex.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LevelFrame {
    /// Unit tangent, along `∇F × n`.
    pub tangent: Vec3,
    /// Unit surface normal at the vertex.
    pub normal: Vec3,
    /// Unit side vector `n × t`, which points along `+∇F` (Sec. 3.2.2).
    pub side: Vec3,
    /// Unit discrete binormal `ê_p × ê_q` normalised (Sec. 3.1), `None` where the curve is
    /// straight: where its radius of curvature exceeds the model's size (the bounding-box
    /// diagonal), as the curve-level measure of [`crate::quality`] has it.
    pub binormal: Option<Vec3>,
}

impl LevelFrame {
    /// Signed angle between binormal and normal in degrees, `θ = acos(sign(b·u)·(b·n))`,
    /// in `[0°, 180°]`: `θ` and `180° − θ` are the two mirror families of Fig. 8, and the value
    /// does not depend on the orientation of `b`. `None` where the binormal is undefined.
    pub fn signed_angle_degrees(&self) -> Option<f64> {
        let b = self.binormal?;
        let sign = if b.dot(&self.side) < 0.0 { -1.0 } else { 1.0 };
        Some((sign * b.dot(&self.normal)).clamp(-1.0, 1.0).acos().to_degrees())
    }
}

/// The frame of a level jet on a model of size `model_size` (lengths in the jet's units).
pub(crate) fn frame_of_jet(jet: &LevelJet, model_size: f64) -> LevelFrame {
    let binormal = (jet.curvature() * model_size > 1.0).then(|| jet.to_p.unit().cross(&jet.to_q.unit()).try_normalize(0.0)).flatten();
    LevelFrame { tangent: jet.tangent.value, normal: jet.normal, side: jet.side.value, binormal }
}

/// The bounding-box diagonal of `mesh`.
pub(crate) fn model_size(mesh: &TriMesh) -> f64 {
    let (low, high) = mesh.bounding_box();
    (high - low).norm()
}

/// The level frame at vertex `v` (panics if `v` is out of range or `field` shorter than the
/// vertex count); `None` at singular vertices and where the local fits are not well posed.
/// Fits the field around `v` on each call (the surface's fits are the mesh's own, made once).
pub fn level_frame(mesh: &TriMesh, field: &[f64], v: usize) -> Option<LevelFrame> {
    let stencils = JetStencils::new(mesh, &[v as u32], &mesh.local_quadrics()[v..=v]);
    Some(frame_of_jet(&level_jet_at(mesh, &stencils.get(0), v, field)?, model_size(mesh)))
}
