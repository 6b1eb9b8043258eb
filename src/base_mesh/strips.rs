//! The rectifying strips of a base mesh: on every row and column, the developable strip of planar
//! quads fitted to the common node rulings ([`super::node_torsion`]), given a width, unrolled and
//! measured against the reference like the strips of level curves (Table 4).

use super::net_mesh::NetMesh;
use super::report::Reference;
use crate::mesh::Vec3;
use crate::strips::{discrete_binormals, strip_with_rulings, PatternMetrics, SkippedCurve, StripLines, StripPattern, StripWarning, SurfaceProjector, Verdict};

/// The strips of a net's families: `width`, measured with `projector` (built on `reference`'s
/// mesh) and judged with `tolerance_degrees`.
pub(crate) struct FamilyStrips<'a> {
    pub net: &'a NetMesh,
    pub reference: &'a Reference,
    pub projector: &'a SurfaceProjector<'a>,
    pub width: f64,
    pub tolerance_degrees: f64,
}

impl FamilyStrips<'_> {
    /// Family `k`'s strips on the fitted `rulings` (one entry per polyline), judged at the angle
    /// `theta` (along the polylines' direction); without one (a constant slope prescribes no
    /// angle) each strip at its own mean angle. A strip's `curve` and `level` are its polyline's
    /// index.
    pub fn build(&self, k: usize, rulings: &[Option<Vec<Vec3>>], theta: Option<f64>) -> StripPattern {
        let (net, reference, width) = (self.net, self.reference, self.width);
        let (mut strips, mut skipped) = (Vec::new(), Vec::new());
        for (index, (line, lines)) in net.polylines(k).iter().zip(rulings).enumerate() {
            let centre: Vec<Vec3> = line.iter().map(|&v| net.positions()[v as usize]).collect();
            let Some(lines) = lines else {
                let warning = if centre.len() < 3 { StripWarning::TooFewPoints { points: centre.len() } } else { StripWarning::SolverFailed { message: "no developable strip of planar quads fits this polyline".into() } };
                skipped.push(SkippedCurve { curve: index, warnings: vec![warning] });
                continue;
            };
            let normals: Vec<Vec3> = centre.iter().map(|c| reference.closest(c).1).collect();
            let theta = theta.unwrap_or_else(|| mean_angle(&centre, &normals));
            let (sin, cos) = theta.to_radians().sin_cos();
            let targets: Vec<Vec3> = (0..centre.len())
                .map(|i| {
                    let tangent = (centre[(i + 1).min(centre.len() - 1)] - centre[i.saturating_sub(1)]).try_normalize(0.0).unwrap_or_else(Vec3::zeros);
                    normals[i] * cos + normals[i].cross(&tangent) * sin
                })
                .collect();
            let binormals: Vec<Vec3> = discrete_binormals(&centre)
                .iter()
                .zip(&targets)
                .map(|(b, target)| b.map_or(*target, |b| if b.dot(target) < 0.0 { -b } else { b }))
                .collect();
            let toward: f64 = lines.iter().zip(&targets).map(|(d, t)| d.dot(t)).sum();
            let rulings: Vec<Vec3> = lines.iter().map(|d| if toward < 0.0 { -d } else { *d }).collect();
            let strip_lines = StripLines { curve: index, level: index as f64, centre, binormals, rulings };
            let strip = strip_with_rulings(self.projector, strip_lines, width, theta, reference.diagonal, Vec::new());
            if strip.is_finite() {
                strips.push(strip);
            } else {
                skipped.push(SkippedCurve { curve: index, warnings: vec![StripWarning::NonFiniteInput] });
            }
        }
        let metrics = PatternMetrics::from_strips(strips.iter().map(|s| &s.metrics));
        let verdict = Verdict::judge(&strips, self.tolerance_degrees);
        StripPattern { strips, skipped, metrics, verdict }
    }
}

/// The mean signed angle (Sec. 3.1) between the discrete binormals of `centre` and `normals` at
/// its inner vertices, 90° where none is defined.
fn mean_angle(centre: &[Vec3], normals: &[Vec3]) -> f64 {
    let angles: Vec<f64> = discrete_binormals(centre)
        .iter()
        .enumerate()
        .filter_map(|(i, b)| {
            let b = (*b)?;
            let side = normals[i].cross(&(centre[i + 1] - centre[i - 1])).try_normalize(0.0)?;
            let sign = if b.dot(&side) < 0.0 { -1.0 } else { 1.0 };
            Some((sign * b.dot(&normals[i])).clamp(-1.0, 1.0).acos().to_degrees())
        })
        .collect();
    if angles.is_empty() { 90.0 } else { angles.iter().sum::<f64>() / angles.len() as f64 }
}
