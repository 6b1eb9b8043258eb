//! The verdict on a strip pattern: do the strips a fabricator would get meet the asked angle,
//! without flipped quads, on the surface? Judged on the strips themselves (each quad's plane
//! against the smooth surface normal, [`super::StripMetrics::max_quad_angle_error_degrees`], and
//! the centre line's distance from the surface, [`super::StripMetrics::appro_percent`]), not on
//! any energy.

use serde::{Deserialize, Serialize};

use super::metrics::StripMetrics;
use super::strip::RectifyingStrip;

/// Default largest angle error of an acceptable strip, in degrees.
pub const DEFAULT_TOLERANCE_DEGREES: f64 = 2.0;

/// Largest distance of an acceptable strip's centre line from the surface, in per cent of the
/// surface's bounding-box diagonal (Table 4's Appro, which the paper's results keep below 0.1 %).
/// The strip optimisation lets the centre line leave the surface a little to meet θ; where no
/// family of θ exists it strays further (a sphere cap at θ = 10°: 2.3 %).
pub const MAX_APPRO_PERCENT: f64 = 1.0;

/// The quad that misses θ most.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct WorstQuad {
    /// Index of the strip in the pattern.
    pub strip: usize,
    /// Index of the quad along the strip.
    pub quad: usize,
    pub point: [f64; 3],
    pub error_degrees: f64,
}

/// Whether a pattern is acceptable, and where it is not.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Verdict {
    pub tolerance_degrees: f64,
    /// Strips (indices into the pattern) with a quad more than the tolerance off θ.
    pub strips_missing_theta: Vec<usize>,
    /// Strips with flipped quads.
    pub strips_with_flipped_quads: Vec<usize>,
    /// Strips whose centre line leaves the surface by more than [`MAX_APPRO_PERCENT`].
    #[serde(default)]
    pub strips_off_surface: Vec<usize>,
    pub worst: Option<WorstQuad>,
    /// No strip could be built.
    pub empty: bool,
}

impl Verdict {
    /// The verdict on `strips` with `tolerance_degrees`.
    pub fn judge(strips: &[RectifyingStrip], tolerance_degrees: f64) -> Verdict {
        let metrics: Vec<StripMetrics> = strips.iter().map(|s| s.metrics).collect();
        Verdict::of_metrics(&metrics, tolerance_degrees)
    }

    /// The verdict on strips with these measures (one per strip, in order).
    pub fn of_metrics(metrics: &[StripMetrics], tolerance_degrees: f64) -> Verdict {
        let mut verdict = Verdict { tolerance_degrees, empty: metrics.is_empty(), ..Verdict::default() };
        for (index, m) in metrics.iter().enumerate() {
            if m.max_quad_angle_error_degrees > tolerance_degrees {
                verdict.strips_missing_theta.push(index);
            }
            if m.flipped_quads > 0 {
                verdict.strips_with_flipped_quads.push(index);
            }
            if m.appro_percent > MAX_APPRO_PERCENT {
                verdict.strips_off_surface.push(index);
            }
            if verdict.worst.is_none_or(|w| m.max_quad_angle_error_degrees > w.error_degrees) {
                verdict.worst =
                    Some(WorstQuad { strip: index, quad: m.worst_quad, point: m.worst_quad_point, error_degrees: m.max_quad_angle_error_degrees });
            }
        }
        verdict
    }

    /// Strips within the tolerance, none flipped, none off the surface, at least one strip.
    pub fn is_acceptable(&self) -> bool {
        !self.empty && self.strips_missing_theta.is_empty() && self.strips_with_flipped_quads.is_empty() && self.strips_off_surface.is_empty()
    }

    /// One line saying where θ is missed and what to try; "acceptable: …" when it is not.
    pub fn message(&self) -> String {
        if self.empty {
            return "no acceptable family: no strip could be built; try another start (guides, strokes) or θ".into();
        }
        let worst = self.worst.map_or(String::new(), |w| {
            format!(
                "worst: strip {} quad {} at ({:.3}, {:.3}, {:.3}), {:.2}° off",
                w.strip, w.quad, w.point[0], w.point[1], w.point[2], w.error_degrees
            )
        });
        if self.is_acceptable() {
            return format!("acceptable: every strip within {}° of θ and {MAX_APPRO_PERCENT} % of the surface, no flipped quad ({worst})", self.tolerance_degrees);
        }
        let mut parts = Vec::new();
        if !self.strips_missing_theta.is_empty() {
            let verb = if self.strips_missing_theta.len() == 1 { "misses" } else { "miss" };
            parts.push(format!("{} {verb} θ by more than {}°", strip_list(&self.strips_missing_theta), self.tolerance_degrees));
        }
        if !self.strips_with_flipped_quads.is_empty() {
            let verb = if self.strips_with_flipped_quads.len() == 1 { "has" } else { "have" };
            parts.push(format!("{} {verb} flipped quads", strip_list(&self.strips_with_flipped_quads)));
        }
        if !self.strips_off_surface.is_empty() {
            let verb = if self.strips_off_surface.len() == 1 { "leaves" } else { "leave" };
            parts.push(format!("{} {verb} the surface by more than {MAX_APPRO_PERCENT} % of its diagonal", strip_list(&self.strips_off_surface)));
        }
        format!(
            "no acceptable family: {}; {worst}; try a varying angle, another θ, or another start (guides from another side or angle, strokes)",
            parts.join(", ")
        )
    }
}

/// "strips 1, 4, 7" (at most eight named, then "and N more").
fn strip_list(strips: &[usize]) -> String {
    const NAMED: usize = 8;
    let named: Vec<String> = strips.iter().take(NAMED).map(|s| s.to_string()).collect();
    let more = strips.len().saturating_sub(NAMED);
    let word = if strips.len() == 1 { "strip" } else { "strips" };
    if more > 0 {
        format!("{word} {} and {more} more", named.join(", "))
    } else {
        format!("{word} {}", named.join(", "))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A strip within 1° of θ, without flipped quads, whose centre line is `appro_percent` of the
    /// diagonal away from the surface at its farthest.
    fn strip(appro_percent: f64) -> StripMetrics {
        StripMetrics { max_quad_angle_error_degrees: 1.0, appro_percent, ..StripMetrics::default() }
    }

    #[test]
    fn strips_that_leave_the_surface_are_not_acceptable() {
        let near = Verdict::of_metrics(&[strip(0.2), strip(MAX_APPRO_PERCENT)], DEFAULT_TOLERANCE_DEGREES);
        assert!(near.is_acceptable(), "{}", near.message());
        let far = Verdict::of_metrics(&[strip(0.2), strip(2.3), strip(1.2)], DEFAULT_TOLERANCE_DEGREES);
        assert!(!far.is_acceptable());
        assert_eq!(far.strips_off_surface, vec![1, 2]);
        assert!(far.strips_missing_theta.is_empty() && far.strips_with_flipped_quads.is_empty());
        let message = far.message();
        assert!(message.starts_with("no acceptable family: strips 1, 2 leave the surface by more than 1 % of its diagonal"), "{message}");
    }
}
