//! diagnostics.csv: the node and strip diagnostics of Sec. 5.1 (Prop. 1–2) at every vertex of
//! every strip's central polyline ([`lamella::strips::strip_diagnostics`]). Undefined values
//! (end vertices, straight pieces, a singular point at infinity) are empty cells.
use lamella::strips::{strip_diagnostics, StripPattern};
use std::fmt::Write as _;

const HEADER: &str = "strip,vertex,x,y,z,curvature,torsion,conical_curvature,darboux_angle_degrees,binormal_ruling_degrees,binormal_offset,singular_point_distance,singular_point_near";

/// The CSV text for the strips of `pattern`, built with strip width `width`.
pub fn diagnostics_csv(pattern: &StripPattern, width: f64) -> String {
    let mut text = format!("# Sec. 5.1 diagnostics per strip vertex: k = torsion/curvature; binormal_offset = |curvature| k^2 (width/2)^2 / 2, the distance of the binormal point at the strip edge from the rectifying developable; singular_point_distance along the ruling, near = within {} strip width(s) of the strip or inside it\n{HEADER}\n", lamella::strips::SINGULAR_POINT_CLEARANCE_WIDTHS);
    let cell = |v: Option<f64>| v.filter(|v| v.is_finite()).map_or(String::new(), |v| format!("{v:.6e}"));
    for (id, strip) in pattern.strips.iter().enumerate() {
        for (i, (d, p)) in strip_diagnostics(&strip.centre, &strip.binormals, &strip.rulings, width).iter().zip(&strip.centre).enumerate() {
            let _ = writeln!(
                text,
                "{id},{i},{:.6},{:.6},{:.6},{},{},{},{},{},{},{},{}",
                p.x,
                p.y,
                p.z,
                cell(d.curvature),
                cell(d.torsion),
                cell(d.conical_curvature),
                cell(d.darboux_angle_degrees),
                cell(d.binormal_ruling_degrees),
                cell(d.binormal_offset),
                cell(d.singular_point_distance),
                u8::from(d.singular_point_near)
            );
        }
    }
    text
}
