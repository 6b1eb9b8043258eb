//! The discrete Darboux frame of the level curve through a vertex (Sec. 2.2, 3.1), measured
//! from the field itself rather than from the solver's auxiliary variables: the independent
//! yardstick for how well a field meets its target angle.

use super::star_chords::StarChords;
use crate::mesh::{TriMesh, Vec3};

/// Below this `‖ê_p × ê_q‖` the level polyline is straight at the vertex and its binormal undefined.
const STRAIGHT: f64 = 1e-12;

/// Frame of the level polyline `p → v0 → q` at a regular interior vertex.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LevelFrame {
    /// Unit tangent `(q − p)/‖q − p‖`.
    pub tangent: Vec3,
    /// Unit surface normal at the vertex.
    pub normal: Vec3,
    /// Unit side vector `n × t`, which points along `+∇F` (Sec. 3.2.2).
    pub side: Vec3,
    /// Unit discrete binormal `ê_p × ê_q` normalised (Sec. 3.1), `None` where the polyline is straight.
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

/// The level frame at vertex `v`; `None` at boundary and singular vertices.
pub fn level_frame(mesh: &TriMesh, field: &[f64], v: usize) -> Option<LevelFrame> {
    let chords = StarChords::at_vertex(mesh, field, v)?;
    let normal = mesh.vertex_normals()[v];
    let tangent = chords.tangent.unit();
    let side = normal.cross(&tangent).try_normalize(0.0)?;
    let binormal = chords.to_p.unit().cross(&chords.to_q.unit()).try_normalize(STRAIGHT);
    Some(LevelFrame { tangent, normal, side, binormal })
}
