//! The workshop files of `fabricate` and `design --thickness`: the parameters from the flags,
//! cut.dxf, cut.svg, bom.csv, utilisation.svg, the report section and the warning about strips
//! over 100 % utilisation.
use crate::args::FabricationFlags;
use crate::error::{CliError, CliResult};
use crate::output_dir::OutputDir;
use crate::svg::preview::{strips_view_svg, ColouredStrip};
use crate::units::{length, length_or_zero, stress};
use lamella::fabrication::{bom_csv, bom_rows, cut_dxf, cut_svg, utilisation_rgb, FabricationError, FabricationParams, FabricationPlan, Material, Stock};
use serde_json::{json, Value};

/// Files written by [`write_files`].
pub const FILES: &str = "cut.dxf, cut.svg, bom.csv, utilisation.svg";

/// The flag that sets a fabrication parameter, for messages.
fn flag(parameter: &str) -> &'static str {
    match parameter {
        "thickness" => "--thickness",
        "stock_length" => "--stock",
        "stock_width" => "--stock-width",
        "overlap" => "--overlap",
        "youngs_modulus" => "--youngs-modulus",
        "shear_modulus" => "--shear-modulus",
        "allowable_stress" => "--allowable-stress",
        "theta" => "--theta",
        _ => "a fabrication parameter",
    }
}

/// A fabrication error as a command-line error: bad input (exit 2), naming the flag.
pub fn cli_error(error: FabricationError) -> CliError {
    match &error {
        FabricationError::InvalidParameter { name, message } => CliError::bad_input(format!("{}: {message}", flag(name))),
        _ => CliError::bad_input(error.to_string()),
    }
}

/// The material from --material and the moduli flags.
fn material(flags: &FabricationFlags) -> CliResult<Material> {
    let name = flags.material.as_deref().unwrap_or("timber");
    let custom = name.eq_ignore_ascii_case("custom");
    let mut material = match Material::preset(name) {
        Some(m) => m,
        None if custom => Material { name: "custom".into(), youngs_modulus: 0.0, shear_modulus: 0.0, allowable_stress: 0.0 },
        None => {
            return Err(CliError::bad_input(format!(
                "--material: unknown material `{}` (timber, plywood, steel, aluminium or custom)",
                lamella::input::clip(name)
            )))
        }
    };
    let values = [
        ("--youngs-modulus", &flags.youngs_modulus, &mut material.youngs_modulus),
        ("--shear-modulus", &flags.shear_modulus, &mut material.shear_modulus),
        ("--allowable-stress", &flags.allowable_stress, &mut material.allowable_stress),
    ];
    for (option, text, value) in values {
        match text {
            Some(text) => *value = stress(option, text)?,
            None if custom => return Err(CliError::bad_input(format!("--material custom needs {option}"))),
            None => {}
        }
    }
    Ok(material)
}

/// The fabrication parameters of the flags (--thickness is required).
pub fn params(flags: &FabricationFlags, theta_degrees: Option<f64>) -> CliResult<FabricationParams> {
    let thickness = flags.thickness.as_deref().ok_or_else(|| CliError::bad_input("--thickness is needed (e.g. --thickness 6mm)"))?;
    let mut stock = Stock::boards(flags.stock.as_deref().map(|s| length("--stock", s)).transpose()?.unwrap_or(4.8));
    stock.width = flags.stock_width.as_deref().map(|s| length("--stock-width", s)).transpose()?;
    if let Some(overlap) = flags.overlap.as_deref() {
        stock.overlap = length_or_zero("--overlap", overlap)?;
    }
    let params = FabricationParams { material: material(flags)?, thickness: length("--thickness", thickness)?, stock, theta_degrees };
    params.validate().map_err(cli_error)?;
    Ok(params)
}

/// Whether `design` should write the workshop files: any fabrication flag given.
pub fn requested(flags: &FabricationFlags) -> bool {
    [&flags.material, &flags.thickness, &flags.stock, &flags.stock_width, &flags.overlap, &flags.youngs_modulus, &flags.shear_modulus, &flags.allowable_stress]
        .iter()
        .any(|f| f.is_some())
}

/// Writes cut.dxf, cut.svg, bom.csv and utilisation.svg (the strips coloured by utilisation,
/// over `mesh` when given).
pub fn write_files(out: &OutputDir, plan: &FabricationPlan, strips: &[(&[lamella::mesh::Vec3], &[lamella::mesh::Vec3])], mesh: Option<&lamella::mesh::TriMesh>) -> CliResult<()> {
    out.write("cut.dxf", cut_dxf(plan))?;
    out.write("cut.svg", cut_svg(plan))?;
    out.write("bom.csv", bom_csv(plan))?;
    let coloured: Vec<ColouredStrip> = strips
        .iter()
        .zip(&plan.checks)
        .map(|((left, right), check)| ColouredStrip {
            left,
            right,
            quad_rgb: check.utilisation.windows(2).map(|u| utilisation_rgb(0.5 * (u[0] + u[1])).map(|c| f64::from(c) / 255.0)).collect(),
        })
        .collect();
    out.write("utilisation.svg", strips_view_svg(mesh, &coloured, "lamella: strips coloured by utilisation (green 0, yellow 50 %, orange 100 %, red over)"))
}

/// A finite number or null.
fn finite(value: Option<f64>) -> Value {
    value.filter(|v| v.is_finite()).map_or(Value::Null, |v| json!(v))
}

/// The report section of a plan: parameters, per-strip checks, pieces (the bill of materials),
/// boards and yield, the strips over 100 %.
pub fn report_section(plan: &FabricationPlan) -> Value {
    let p = &plan.params;
    let strips: Vec<Value> = plan
        .checks
        .iter()
        .zip(&plan.strip_names)
        .map(|(c, name)| {
            json!({
                "name": name,
                "max_strain": c.max_strain,
                "max_bending_stress_mpa": c.max_bending_stress / 1e6,
                "max_shear_stress_mpa": c.max_shear_stress / 1e6,
                "max_utilisation": c.max_utilisation,
                "worst_point": c.worst_point,
                "worst_position": [c.worst_position.x, c.worst_position.y, c.worst_position.z],
                "worst_arc_length_m": c.arc_length[c.worst_point],
                "min_bending_radius_m": finite(c.min_bending_radius()),
                "max_twist_rate_rad_per_m": c.max_twist_rate(),
                "overstressed": c.is_overstressed(),
            })
        })
        .collect();
    let pieces: Vec<Value> = bom_rows(plan)
        .into_iter()
        .map(|r| {
            json!({
                "id": r.id, "strip": r.strip, "family": r.family, "theta_deg": finite(r.theta_degrees), "length_m": r.length,
                "width_m": r.width, "min_bending_radius_m": finite(r.min_bending_radius), "max_twist_rate_rad_per_m": r.max_twist_rate,
                "max_utilisation": r.max_utilisation, "splice_partners": r.splice_partners, "board": r.board,
            })
        })
        .collect();
    json!({
        "material": { "name": p.material.name, "youngs_modulus_gpa": p.material.youngs_modulus / 1e9, "shear_modulus_gpa": p.material.shear_modulus / 1e9,
                      "allowable_stress_mpa": p.material.allowable_stress / 1e6 },
        "thickness_m": p.thickness,
        "stock": { "length_m": p.stock.length, "width_m": plan.board_size[1], "width_given": p.stock.width.is_some(), "overlap_m": p.stock.overlap, "gap_m": p.stock.gap },
        "method": "weak-axis bending stress E t kappa / 2 from the centre line's curvature; torsional shear G t tau from the twist rate of the strip's rectifying frame; utilisation = sqrt(sigma^2 + 3 tau_s^2) / allowable stress",
        "strips": strips,
        "pieces": pieces,
        "boards": plan.boards,
        "material_yield": plan.material_yield(),
        "overstressed": plan.overstressed_strips().iter().map(|&i| plan.strip_names[i].clone()).collect::<Vec<_>>(),
    })
}

/// One line naming the strips over 100 % utilisation (with their worst point), if any.
pub fn overstress_warning(plan: &FabricationPlan) -> Option<String> {
    let over = plan.overstressed_strips();
    if over.is_empty() {
        return None;
    }
    let named: Vec<String> = over
        .iter()
        .take(lamella::input::MAX_LISTED_ITEMS)
        .map(|&i| {
            let c = &plan.checks[i];
            let p = c.worst_position;
            format!("{} ({:.0} % at {:.2} m, point ({:.2}, {:.2}, {:.2}))", plan.strip_names[i], 100.0 * c.max_utilisation, c.arc_length[c.worst_point], p.x, p.y, p.z)
        })
        .collect();
    let more = over.len().saturating_sub(named.len());
    let tail = if more > 0 { format!(" and {more} more") } else { String::new() };
    Some(format!(
        "{} of {} strips over 100 % utilisation for {} {:.1} mm: {}{tail}; use thinner or more flexible stock (flagged red in cut.svg, cut.dxf, utilisation.svg)",
        over.len(),
        plan.checks.len(),
        plan.params.material.name,
        1000.0 * plan.params.thickness,
        named.join(", ")
    ))
}

/// The summary line of a plan.
pub fn summary_line(plan: &FabricationPlan) -> String {
    let worst = plan.checks.iter().map(|c| c.max_utilisation).fold(0.0, f64::max);
    format!(
        "fabrication: {} pieces on {} boards of {:.2} m × {:.3} m, yield {:.0} %, largest utilisation {:.0} %",
        plan.pieces.len(),
        plan.boards,
        plan.board_size[0],
        plan.board_size[1],
        100.0 * plan.material_yield(),
        100.0 * worst
    )
}
