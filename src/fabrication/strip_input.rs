//! A strip as fabrication sees it: its centre line `c_i`, the half-rulings `s_i d_i` to the
//! boundary on the rulings' side, optional node positions along it, and its flat unrolling.
use super::error::FabricationError;
use crate::mesh::Vec3;
use crate::strips::{unroll, RectifyingStrip, Unrolling};

/// Relative length below which a segment counts as zero, and a ruling as parallel to the centre
/// line (`‖t × d‖ / ‖d‖`).
const DEGENERATE: f64 = 1e-9;

/// One strip to check and cut.
#[derive(Clone, Debug, PartialEq)]
pub struct FabricationStrip {
    /// Its name in every output (`strip_<id>`); piece ids are `<name>-<k>`.
    pub name: String,
    /// The medial polyline `c_i`, in metres.
    pub centre: Vec<Vec3>,
    /// The half-rulings `s_i d_i` from `c_i` to the boundary on the rulings' side.
    pub offsets: Vec<Vec3>,
    /// Arc-length positions (from the centre line's start, metres) of nodes that splices must
    /// avoid (crossings with another family, holes); empty when the strips are not part of a net.
    pub nodes: Vec<f64>,
    /// θ of the strip's own family in degrees, for a plan of several families (a net's);
    /// `None`: the plan's [`super::FabricationParams::theta_degrees`].
    pub theta_degrees: Option<f64>,
}

impl FabricationStrip {
    /// The strip between the boundaries `left_i = c_i + s_i d_i` and `right_i = c_i − s_i d_i`
    /// (as stored in strips.obj).
    pub fn from_boundaries(name: &str, left: &[Vec3], right: &[Vec3]) -> FabricationStrip {
        let centre = left.iter().zip(right).map(|(l, r)| (l + r) * 0.5).collect();
        let offsets = left.iter().zip(right).map(|(l, r)| (l - r) * 0.5).collect();
        FabricationStrip { name: name.to_string(), centre, offsets, nodes: Vec::new(), theta_degrees: None }
    }

    /// A strip of a computed pattern, by its boundaries (so that it matches strips.obj bit for bit).
    pub fn from_rectifying(name: &str, strip: &RectifyingStrip) -> FabricationStrip {
        FabricationStrip::from_boundaries(name, &strip.left, &strip.right)
    }

    /// Checks the strip (index `index` in its list): at least 2 points, as many offsets as points,
    /// finite values, no zero-length segment, no ruling along the centre line, nodes finite.
    pub fn validate(&self, index: usize) -> Result<(), FabricationError> {
        let bad = |message: String| FabricationError::InvalidStrip { strip: index, name: self.name.clone(), message };
        if self.centre.len() < 2 {
            return Err(bad(format!("{} points, at least 2 are needed", self.centre.len())));
        }
        if self.offsets.len() != self.centre.len() {
            return Err(bad(format!("{} rulings for {} points", self.offsets.len(), self.centre.len())));
        }
        if let Some(i) = self.centre.iter().zip(&self.offsets).position(|(c, d)| !(c.iter().chain(d.iter()).all(|x| x.is_finite()))) {
            return Err(bad(format!("point {i} is not finite")));
        }
        let scale = self.centre.iter().map(|c| c.amax()).fold(1.0, f64::max);
        if let Some(j) = self.centre.windows(2).position(|w| (w[1] - w[0]).norm() <= DEGENERATE * scale) {
            return Err(bad(format!("segment {j} has zero length")));
        }
        let tangents = self.tangents();
        if let Some(i) = tangents.iter().zip(&self.offsets).position(|(t, d)| t.cross(d).norm() <= DEGENERATE * d.norm().max(f64::MIN_POSITIVE)) {
            return Err(bad(format!("the ruling at point {i} is zero or along the centre line")));
        }
        if let Some(k) = self.nodes.iter().position(|s| !s.is_finite()) {
            return Err(bad(format!("node {k} is not finite")));
        }
        if let Some(theta) = self.theta_degrees.filter(|t| !(0.0..=180.0).contains(t)) {
            return Err(bad(format!("θ must lie in [0°, 180°], got {theta}")));
        }
        Ok(())
    }

    /// Unit tangents: the central difference `c_{i+1} − c_{i−1}` inside, the end segments at the ends.
    pub fn tangents(&self) -> Vec<Vec3> {
        let n = self.centre.len();
        (0..n)
            .map(|i| {
                let (a, b) = (i.saturating_sub(1), (i + 1).min(n.saturating_sub(1)));
                (self.centre[b] - self.centre[a]).try_normalize(0.0).unwrap_or_else(Vec3::zeros)
            })
            .collect()
    }

    /// Arc length of the centre line at each point, from 0.
    pub fn arc_lengths(&self) -> Vec<f64> {
        let mut total = 0.0;
        std::iter::once(0.0)
            .chain(self.centre.windows(2).map(|w| {
                total += (w[1] - w[0]).norm();
                total
            }))
            .collect()
    }

    /// The strip laid flat (Fig. 20), one point per centre point.
    pub fn unrolling(&self) -> Unrolling {
        unroll(&self.centre, &self.offsets)
    }

    /// Width of the strip: twice the mean length of the half-rulings' component across the centre line.
    pub fn width(&self) -> f64 {
        let tangents = self.tangents();
        let across: f64 = tangents.iter().zip(&self.offsets).map(|(t, d)| t.cross(d).norm()).sum();
        2.0 * across / self.offsets.len().max(1) as f64
    }
}
