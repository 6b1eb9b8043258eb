//! The output of the strip computation: rectifying strips of planar quads with their flat
//! unrollings, metrics and warnings.
use super::error::StripWarning;
use super::metrics::{PatternMetrics, StripMetrics};
use super::unrolling::Unrolling;
use super::verdict::Verdict;
use crate::mesh::Vec3;

/// One rectifying developable strip (Fig. 20): planar quads
/// `(left_j, left_{j+1}, right_{j+1}, right_j)` split by the medial polyline `centre`.
#[derive(Clone, Debug, PartialEq)]
pub struct RectifyingStrip {
    /// Index of the level curve it was built on.
    pub curve: usize,
    /// Level value of that curve.
    pub level: f64,
    /// The optimised base polyline `c_i` (the strip's medial line).
    pub centre: Vec<Vec3>,
    /// Unit binormals `b_i` of the binormal-strip stage (Eq. 8–9), oriented by the target angle.
    pub binormals: Vec<Vec3>,
    /// Unit rulings `d_i` in the outer bisecting planes (Eq. 16), on the binormals' side.
    pub rulings: Vec<Vec3>,
    /// Boundary `c_i + s_i d_i`, with `s_i` chosen so that the flat strip has the requested width
    /// (`s_i = width / (2 sin α_i)`, `α_i` the angle between ruling and polyline).
    pub left: Vec<Vec3>,
    /// Boundary `c_i − s_i d_i`.
    pub right: Vec<Vec3>,
    /// The strip laid flat.
    pub unrolling: Unrolling,
    pub metrics: StripMetrics,
    pub warnings: Vec<StripWarning>,
}

impl RectifyingStrip {
    /// The strip's width across its centre line: at the first vertex, the part of
    /// `left − right` orthogonal to the first edge (there `s_0 = width / (2 sin α_0)` exactly);
    /// 0 for a strip of fewer than two points.
    pub fn width(&self) -> f64 {
        let (Some(a), Some(b)) = (self.centre.first(), self.centre.get(1)) else { return 0.0 };
        let Some(edge) = (b - a).try_normalize(0.0) else { return 0.0 };
        (self.left[0] - self.right[0]).cross(&edge).norm()
    }

    /// The Sec. 5.1 diagnostics at every vertex of the centre line ([`super::strip_diagnostics`]).
    pub fn diagnostics(&self) -> Vec<super::VertexDiagnostics> {
        super::strip_diagnostics(&self.centre, &self.binormals, &self.rulings, self.width())
    }
}

/// A level curve no strip could be built on, and why.
#[derive(Clone, Debug, PartialEq)]
pub struct SkippedCurve {
    pub curve: usize,
    pub warnings: Vec<StripWarning>,
}

/// All strips of a pattern with the Table 4 summary and the verdict.
#[derive(Clone, Debug, PartialEq)]
pub struct StripPattern {
    pub strips: Vec<RectifyingStrip>,
    pub skipped: Vec<SkippedCurve>,
    pub metrics: PatternMetrics,
    /// Whether the strips meet θ within [`super::StripParams::tolerance_degrees`] without flipped quads.
    pub verdict: Verdict,
}
