//! The quality measures of paper Table 4 per strip and per pattern, and the strip warnings as
//! bit flags, as plain C structs.

use crate::strips::{PatternMetrics, RectifyingStrip, SkippedCurve, StripWarning, Verdict, WorstQuad};

/// A set of `LML_STRIP_WARNING_*` bits.
pub type LmlStripWarnings = u64;
/// The polyline has fewer than 3 points (the curve was skipped).
pub const LML_STRIP_WARNING_TOO_FEW_POINTS: LmlStripWarnings = 1 << 0;
/// A point of the polyline is not finite (skipped).
pub const LML_STRIP_WARNING_NON_FINITE_INPUT: LmlStripWarnings = 1 << 1;
/// A segment of the polyline has (nearly) zero length (skipped; resample the curves).
pub const LML_STRIP_WARNING_ZERO_LENGTH_SEGMENT: LmlStripWarnings = 1 << 2;
/// The strip optimisation failed numerically (skipped).
pub const LML_STRIP_WARNING_SOLVER_FAILED: LmlStripWarnings = 1 << 3;
/// The level curve passes singular field vertices: it may follow a wrong branch or turn sharply.
pub const LML_STRIP_WARNING_SINGULAR_VERTICES: LmlStripWarnings = 1 << 4;
/// A closed level curve was cut open at its first point (strips are open).
pub const LML_STRIP_WARNING_CLOSED_CURVE_OPENED: LmlStripWarnings = 1 << 5;
/// The width is so large that neighbouring rulings cross inside the strip and quads fold over.
pub const LML_STRIP_WARNING_WIDTH_TOO_LARGE: LmlStripWarnings = 1 << 6;
/// Some quads flip their orientation against their neighbours or the target binormal side
/// (counted in `LmlStripMetrics::flipped_quads`).
pub const LML_STRIP_WARNING_FLIPPED_QUADS: LmlStripWarnings = 1 << 7;

fn warning_bit(warning: &StripWarning) -> LmlStripWarnings {
    match warning {
        StripWarning::TooFewPoints { .. } => LML_STRIP_WARNING_TOO_FEW_POINTS,
        StripWarning::NonFiniteInput => LML_STRIP_WARNING_NON_FINITE_INPUT,
        StripWarning::ZeroLengthSegment { .. } => LML_STRIP_WARNING_ZERO_LENGTH_SEGMENT,
        StripWarning::SolverFailed { .. } => LML_STRIP_WARNING_SOLVER_FAILED,
        StripWarning::SingularVertices { .. } => LML_STRIP_WARNING_SINGULAR_VERTICES,
        StripWarning::ClosedCurveOpened => LML_STRIP_WARNING_CLOSED_CURVE_OPENED,
        StripWarning::WidthTooLarge { .. } => LML_STRIP_WARNING_WIDTH_TOO_LARGE,
        StripWarning::FlippedQuads { .. } => LML_STRIP_WARNING_FLIPPED_QUADS,
    }
}

fn warning_bits(warnings: &[StripWarning]) -> LmlStripWarnings {
    warnings.iter().fold(0, |bits, w| bits | warning_bit(w))
}

fn count(n: usize) -> u64 {
    n as u64
}

/// One strip: which curve it was built on and its Table 4 measures. Lengths are in the mesh's
/// unit, angles in degrees. (All fields are 64 bits: no padding.)
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LmlStripMetrics {
    /// Index (into the `LmlCurves` the strips were built from) of the strip's level curve.
    pub curve: u64,
    /// Level value of that curve.
    pub level: f64,
    /// Length of the strip's centre line (the same in space and unrolled).
    pub length: f64,
    /// diff_θ: max over the inner centre points of |θ_measured − θ|, the angle between the
    /// discrete binormal (paper Eq. 1) and the surface normal at the closest surface point.
    pub max_diff_theta_degrees: f64,
    /// e_straight: max distance of the unrolled centre points from their least-squares line,
    /// divided by `length`.
    pub e_straight: f64,
    /// E_planar: Σ det(d̂_j, d̂_{j+1}, ê_j)² over the quads (unit rulings d, unit edges e).
    pub e_planar: f64,
    /// max |det(d̂_j, d̂_{j+1}, ê_j)|: the largest planarity residual of one quad.
    pub max_planar: f64,
    /// Appro: max distance of the centre points from the surface, in % of the surface's
    /// bounding-box diagonal.
    pub appro_percent: f64,
    /// Quads whose orientation flips.
    pub flipped_quads: u64,
    /// The strip's `LML_STRIP_WARNING_*` bits (0: none).
    pub warnings: LmlStripWarnings,
    /// Max over the quads of the error of the strip plane's angle: the in-plane direction across
    /// the centre line against the smooth surface normal (the quad normal should make 90° − θ
    /// with it); defined where the centre line is straight too. What the verdict judges.
    pub max_quad_angle_error_degrees: f64,
    /// The longest ruling segment from the centre line to a boundary, over the strip width.
    pub max_ruling_over_width: f64,
}

impl From<&RectifyingStrip> for LmlStripMetrics {
    fn from(s: &RectifyingStrip) -> LmlStripMetrics {
        let m = &s.metrics;
        LmlStripMetrics {
            curve: count(s.curve),
            level: s.level,
            length: m.length,
            max_diff_theta_degrees: m.max_diff_theta_degrees,
            e_straight: m.e_straight,
            e_planar: m.e_planar,
            max_planar: m.max_planar,
            appro_percent: m.appro_percent,
            flipped_quads: count(m.flipped_quads),
            warnings: warning_bits(&s.warnings),
            max_quad_angle_error_degrees: m.max_quad_angle_error_degrees,
            max_ruling_over_width: m.max_ruling_over_width,
        }
    }
}

/// Table 4 over a whole pattern: maxima over its strips, and the sum of E_planar.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LmlPatternMetrics {
    /// |Strip|: the number of strips built.
    pub strip_count: u64,
    /// Curves no strip could be built on (listed by `lml_strips_skipped`).
    pub skipped_count: u64,
    pub max_diff_theta_degrees: f64,
    pub max_e_straight: f64,
    /// Σ E_planar over all strips.
    pub e_planar: f64,
    pub max_planar: f64,
    pub appro_percent: f64,
    pub flipped_quads: u64,
    /// Max over all strips of `LmlStripMetrics::max_quad_angle_error_degrees`.
    pub max_quad_angle_error_degrees: f64,
    /// Max over all strips of `LmlStripMetrics::max_ruling_over_width`.
    pub max_ruling_over_width: f64,
}

impl LmlPatternMetrics {
    pub(crate) fn new(m: &PatternMetrics, skipped: usize) -> LmlPatternMetrics {
        LmlPatternMetrics {
            strip_count: count(m.strip_count),
            skipped_count: count(skipped),
            max_diff_theta_degrees: m.max_diff_theta_degrees,
            max_e_straight: m.max_e_straight,
            e_planar: m.e_planar,
            max_planar: m.max_planar,
            appro_percent: m.appro_percent,
            flipped_quads: count(m.flipped_quads),
            max_quad_angle_error_degrees: m.max_quad_angle_error_degrees,
            max_ruling_over_width: m.max_ruling_over_width,
        }
    }
}

/// The verdict on a strip pattern (see `lml_strips_verdict`). Angles in degrees.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LmlVerdict {
    /// 1 when every strip is within the tolerance of θ, no quad is flipped and no centre line
    /// leaves the surface by more than 1 % of its bounding-box diagonal (and at least one strip
    /// was built), 0 otherwise.
    pub acceptable: u64,
    pub tolerance_degrees: f64,
    /// Strips with a quad more than the tolerance off θ.
    pub strips_missing_theta: u64,
    /// Strips with flipped quads.
    pub strips_with_flipped_quads: u64,
    /// The quad that misses θ most: its strip, its index along the strip, its centre and error.
    pub worst_strip: u64,
    pub worst_quad: u64,
    pub worst_point: [f64; 3],
    pub worst_error_degrees: f64,
    /// Strips whose centre line leaves the surface by more than 1 % of the surface's
    /// bounding-box diagonal (`appro_percent` of their metrics; added in ABI version 3).
    pub strips_off_surface: u64,
}

impl From<&Verdict> for LmlVerdict {
    fn from(v: &Verdict) -> LmlVerdict {
        let worst = v.worst.unwrap_or(WorstQuad { strip: 0, quad: 0, point: [0.0; 3], error_degrees: 0.0 });
        LmlVerdict {
            acceptable: u64::from(v.is_acceptable()),
            tolerance_degrees: v.tolerance_degrees,
            strips_missing_theta: count(v.strips_missing_theta.len()),
            strips_with_flipped_quads: count(v.strips_with_flipped_quads.len()),
            worst_strip: count(worst.strip),
            worst_quad: count(worst.quad),
            worst_point: worst.point,
            worst_error_degrees: worst.error_degrees,
            strips_off_surface: count(v.strips_off_surface.len()),
        }
    }
}

/// A level curve no strip could be built on, and why.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LmlSkippedCurve {
    /// Index of the curve in the `LmlCurves` the strips were built from.
    pub curve: u64,
    /// `LML_STRIP_WARNING_*` bits; at least one of TOO_FEW_POINTS, NON_FINITE_INPUT,
    /// ZERO_LENGTH_SEGMENT, SOLVER_FAILED says why it was skipped.
    pub warnings: LmlStripWarnings,
}

impl From<&SkippedCurve> for LmlSkippedCurve {
    fn from(s: &SkippedCurve) -> LmlSkippedCurve {
        LmlSkippedCurve { curve: count(s.curve), warnings: warning_bits(&s.warnings) }
    }
}
