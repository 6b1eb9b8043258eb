//! The slope vote of the constant-slope initialisation (Sec. 6, Fig. 34–35): with the light
//! region taken as an arc of a great circle (γ fixed at its middle, δ over its interval), every
//! face votes for the slopes of its tangent directions that are orthogonal to some light of the
//! arc; the most common slope picks the family of curves of constant slope (against the earth
//! axis) to start from.
//!
//! The slope of a tangent direction `t` is `asin(t_z)` in the earth-axis frame, with `t`
//! oriented along the face's horizontal direction `z × n_f` (so `t` and `−t` do not vote
//! twice). Faces whose normal lies within [`STEEP_FACE_DEGREES`] of the earth axis have no such
//! orientation and do not vote.

use super::earth_frame::{light_direction, EarthFrame};
use super::light_region::LightRegion;
use crate::mesh::{TriMesh, Vec3};

/// Width of a slope bin in degrees; the bins cover [−90°, 90°].
pub const SLOPE_BIN_DEGREES: f64 = 5.0;
/// Faces whose normal is within this angle (degrees) of the earth axis do not vote.
pub const STEEP_FACE_DEGREES: f64 = 5.0;
/// Lights sampled along the arc of the region.
const ARC_SAMPLES: usize = 17;

/// The outcome of the vote.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct SlopeVote {
    /// Centre of the winning bin, degrees (ties: the middle one of the tied bins).
    pub slope_degrees: f64,
    /// Votes per bin, from −90° upwards.
    pub histogram: Vec<usize>,
    /// Faces that voted.
    pub voting_faces: usize,
}

/// The vote of every face of `mesh` for the region's arc in the site's `frame`; `None` when no
/// face votes.
pub fn most_common_slope(mesh: &TriMesh, frame: &EarthFrame, region: &LightRegion) -> Option<SlopeVote> {
    let bins = (180.0 / SLOPE_BIN_DEGREES).round() as usize;
    let mut histogram = vec![0usize; bins];
    let gamma = 0.5 * (region.gamma_degrees[0] + region.gamma_degrees[1]);
    let [d0, d1] = region.delta_degrees;
    let lights: Vec<Vec3> = (0..ARC_SAMPLES).map(|k| light_direction(d0 + (d1 - d0) * k as f64 / (ARC_SAMPLES - 1) as f64, gamma)).collect();
    let min_horizontal = STEEP_FACE_DEGREES.to_radians().sin();
    let mut voting_faces = 0;
    for normal in mesh.face_normals() {
        let n = frame.to_earth(normal);
        let horizontal = Vec3::z().cross(&n);
        if horizontal.norm() < min_horizontal {
            continue;
        }
        let slopes = lights.iter().filter_map(|l| {
            let t = n.cross(l).try_normalize(1e-9)?;
            let t = if t.dot(&horizontal) < 0.0 { -t } else { t };
            Some(t.z.clamp(-1.0, 1.0).asin().to_degrees())
        });
        let (low, high) = slopes.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), s| (lo.min(s), hi.max(s)));
        if low > high {
            continue;
        }
        voting_faces += 1;
        let bin = |s: f64| (((s + 90.0) / SLOPE_BIN_DEGREES).floor().max(0.0) as usize).min(bins - 1);
        for count in &mut histogram[bin(low)..=bin(high)] {
            *count += 1;
        }
    }
    if voting_faces == 0 {
        return None;
    }
    // Ties (a planar region votes the same bins everywhere): the middle one of the tied bins.
    let most = histogram.iter().copied().max().unwrap_or(0);
    let tied: Vec<usize> = (0..bins).filter(|&k| histogram[k] == most).collect();
    let best = tied[tied.len() / 2];
    Some(SlopeVote { slope_degrees: -90.0 + (best as f64 + 0.5) * SLOPE_BIN_DEGREES, histogram, voting_faces })
}
