//! view.html, the interactive 3D viewer of a design ([`lamella::view`]): written by `design` and
//! `net` with their other files, and by `lamella view DIR` from the files of an existing output
//! directory (surface.obj, curves.obj, strips.obj, report.json) when it has none yet.
use crate::args::ViewArgs;
use crate::console::out_line;
use crate::error::{CliError, CliResult};
use crate::mesh_input::{read_mesh, read_text};
use crate::output_dir::{record_in_marker, OutputDir};
use crate::strip_obj::{read_curves_obj, read_strips_obj, StripShape};
use lamella::curves::LevelCurve;
use lamella::fabrication::FabricationPlan;
use lamella::mesh::TriMesh;
use lamella::strips::{unroll, RectifyingStrip, StripMetrics};
use lamella::view::{family_name, view_html, ViewScene, ViewStrip, ViewSurface};
use serde_json::Value;
use std::path::Path;

/// The viewer's file name in an output directory.
pub const VIEW_FILE: &str = "view.html";

/// Writes view.html of the strip families `families` (name, level curves, strips) on `mesh`
/// into `out`, with the bending utilisation of each strip when `plan` checked them (one check
/// per strip, in order).
pub fn write_view(out: &OutputDir, title: &str, mesh: &TriMesh, families: &[(&str, &[LevelCurve], &[RectifyingStrip])], plan: Option<&FabricationPlan>) -> CliResult<()> {
    let mut scene = ViewScene::of_families(title, Some(mesh), families);
    if let Some(plan) = plan {
        scene.strips.iter_mut().zip(&plan.checks).for_each(|(s, c)| s.utilisation = Some(c.max_utilisation));
    }
    out.write(VIEW_FILE, page(&scene)?)
}


fn page(scene: &ViewScene) -> CliResult<String> {
    view_html(scene).map_err(|e| CliError::internal(format!("{VIEW_FILE}: {e}")))
}

/// `lamella view DIR`: prints the path of DIR/view.html, writing it first from the files in DIR
/// if it is missing.
pub fn run(args: &ViewArgs) -> CliResult<()> {
    let dir = &args.dir;
    if !dir.is_dir() {
        return Err(CliError::bad_input(format!("{} is not a directory (give the output directory of `lamella design`)", dir.display())));
    }
    let target = dir.join(VIEW_FILE);
    if !target.exists() {
        let html = page(&scene_of_directory(dir)?)?;
        let staging = dir.join(format!(".{VIEW_FILE}.{}.tmp", std::process::id()));
        let unwritable = |e: std::io::Error| CliError::bad_input(format!("cannot write {}: {e}", target.display()));
        std::fs::write(&staging, html).map_err(unwritable)?;
        std::fs::rename(&staging, &target).map_err(|e| {
            let _ = std::fs::remove_file(&staging);
            unwritable(e)
        })?;
        record_in_marker(dir, VIEW_FILE)?;
    }
    out_line(target.display())
}

/// The scene of a `design` (or `strips`) output directory: strips.obj and report.json are
/// needed, surface.obj and curves.obj are shown when present.
fn scene_of_directory(dir: &Path) -> CliResult<ViewScene> {
    let strips_path = dir.join("strips.obj");
    if !strips_path.is_file() {
        return Err(CliError::bad_input(format!("{} has no strips.obj: not the output directory of `lamella design` or `lamella strips`", dir.display())));
    }
    let shapes = read_strips_obj(&strips_path)?;
    let report_path = dir.join("report.json");
    let report: Value = serde_json::from_str(&read_text(&report_path)?).map_err(|e| CliError::bad_input(format!("{}: {e}", report_path.display())))?;
    let surface_path = dir.join("surface.obj");
    let surface = if surface_path.is_file() { Some(ViewSurface::from_mesh(&read_mesh(&surface_path)?)) } else { None };
    let curves_path = dir.join("curves.obj");
    let curves = if curves_path.is_file() { read_curves_obj(&curves_path)? } else { Vec::new() };
    let theta = report.pointer("/parameters/theta_degrees").and_then(Value::as_f64);
    let family = theta.map_or_else(|| "strips".to_string(), family_name);
    let strips = shapes.iter().map(|s| view_strip(s, &report)).collect();
    let title = report.pointer("/parameters/mesh").and_then(Value::as_str).unwrap_or("design").to_string();
    Ok(ViewScene { title, surface, curves, families: vec![family], strips })
}

/// A strip of strips.obj with its measures and utilisation from report.json (looked up by name;
/// measures the report lacks are NaN, shown as n/a).
fn view_strip(shape: &StripShape, report: &Value) -> ViewStrip {
    let named = |section: &str| {
        report.pointer(section).and_then(Value::as_array).and_then(|list| list.iter().find(|s| s.get("name").and_then(Value::as_str) == Some(&shape.name)))
    };
    let number = |entry: Option<&Value>, key: &str| entry.and_then(|e| e.get(key)).and_then(Value::as_f64);
    let entry = named("/strips/strips");
    let field = |key: &str| number(entry, key).unwrap_or(f64::NAN);
    let metrics = StripMetrics {
        max_diff_theta_degrees: field("max_diff_theta_degrees"),
        e_straight: field("e_straight"),
        e_planar: field("e_planar"),
        max_planar: field("max_planar"),
        appro_percent: field("appro_percent"),
        flipped_quads: number(entry, "flipped_quads").unwrap_or(0.0) as usize,
        length: field("length_m"),
        max_quad_angle_error_degrees: field("max_quad_angle_error_degrees"),
        max_ruling_over_width: field("max_ruling_over_width"),
        ..StripMetrics::default()
    };
    ViewStrip {
        name: shape.name.clone(),
        family: 0,
        left: shape.left.clone(),
        right: shape.right.clone(),
        unrolling: unroll(&shape.centre(), &shape.offsets()),
        metrics,
        utilisation: number(named("/fabrication/strips"), "max_utilisation"),
    }
}
