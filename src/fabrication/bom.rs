//! The bill of materials: one row per piece, as CSV (bom.csv) and as rows for reports.
use super::plan::{family_name, FabricationPlan};
use std::fmt::Write as _;

/// One row of the bill of materials.
#[derive(Clone, Debug, PartialEq)]
pub struct BomRow {
    /// `<strip>-<piece>`.
    pub id: String,
    /// The strip's name.
    pub strip: String,
    /// The family's name (`asymptotic`, `geodesic`, `pseudo-geodesic`), when θ is known.
    pub family: Option<&'static str>,
    /// θ in degrees, when known.
    pub theta_degrees: Option<f64>,
    /// Centre-line length, metres.
    pub length: f64,
    /// Width, metres.
    pub width: f64,
    /// Smallest bending radius, metres (`None`: straight).
    pub min_bending_radius: Option<f64>,
    /// Largest twist rate, rad/m.
    pub max_twist_rate: f64,
    /// Largest utilisation.
    pub max_utilisation: f64,
    /// Ids of the pieces spliced to it, previous first.
    pub splice_partners: Vec<String>,
    /// Board or sheet number, from 1.
    pub board: usize,
}

/// The rows of `plan`'s bill of materials, in piece order (strip by strip, along each strip).
pub fn bom_rows(plan: &FabricationPlan) -> Vec<BomRow> {
    plan.pieces
        .iter()
        .map(|p| BomRow {
            id: p.id.clone(),
            strip: plan.strip_names[p.strip].clone(),
            family: family_name(plan.strip_thetas[p.strip]),
            theta_degrees: plan.strip_thetas[p.strip],
            length: p.length(),
            width: p.width,
            min_bending_radius: p.min_bending_radius,
            max_twist_rate: p.max_twist_rate,
            max_utilisation: p.max_utilisation,
            splice_partners: plan.splice_partners(p).into_iter().map(str::to_string).collect(),
            board: p.placement.board + 1,
        })
        .collect()
}

/// A CSV field: quoted when it holds a comma, quote or line break.
fn field(text: &str) -> String {
    if text.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_string()
    }
}

/// A number with 6 decimals, or an empty field.
fn optional(value: Option<f64>) -> String {
    value.filter(|v| v.is_finite()).map_or(String::new(), |v| format!("{v:.6}"))
}

/// bom.csv: a header line, then one line per piece; lengths in metres, twist in rad/m, empty
/// fields for unknown θ and family and for straight pieces' radius; splice partners separated by
/// spaces.
pub fn bom_csv(plan: &FabricationPlan) -> String {
    let mut text = String::from("id,strip,family,theta_deg,length_m,width_m,min_bending_radius_m,max_twist_rate_rad_per_m,max_utilisation,splice_partners,board\n");
    for row in bom_rows(plan) {
        let _ = writeln!(
            text,
            "{},{},{},{},{:.6},{:.6},{},{:.6},{:.6},{},{}",
            field(&row.id),
            field(&row.strip),
            row.family.unwrap_or(""),
            optional(row.theta_degrees),
            row.length,
            row.width,
            optional(row.min_bending_radius),
            row.max_twist_rate,
            row.max_utilisation,
            field(&row.splice_partners.join(" ")),
            row.board
        );
    }
    text
}
