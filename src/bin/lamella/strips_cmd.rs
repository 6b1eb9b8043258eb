//! `lamella strips`: level curves of the field at equally spaced values, resampled to the mesh's
//! edge length, and the rectifying strips along them (paper Sec. 3.4).
use crate::args::StripsArgs;
use crate::config::{Flags, Settings};
use crate::console::err_line;
use crate::diagnostics_csv::diagnostics_csv;
use crate::error::{CliError, CliResult};
use crate::start_field::read_field_for;
use crate::mesh_input::{load_mesh, mesh_name};
use crate::output_dir::OutputDir;
use crate::progress::{note, summary, Verbosity};
use crate::report_json::{self, Timings};
use crate::strip_obj::{curves_obj, rulings_obj, strips_obj};
use crate::svg::preview::preview_svg;
use lamella::curves::{extract_level_curves, resample_all, uniform_levels, LevelCurve};
use lamella::mesh::{TriMesh, Vec3};
use lamella::strips::{rectifying_strips, StripParams, StripPattern};
use std::time::Instant;

/// Default strip width as a fraction of the mean spacing of neighbouring level curves.
const WIDTH_PER_SPACING: f64 = 0.5;

/// The strips of a design with the curves they were built on.
pub struct StripRun {
    /// The resampled level curves, one per level that the level set crosses (possibly several).
    pub curves: Vec<LevelCurve>,
    pub pattern: StripPattern,
    /// The strip width used, in mesh units.
    pub width: f64,
    /// Mean distance between neighbouring level curves, in mesh units.
    pub spacing: f64,
}

/// Area-weighted mean `‖∇F‖` over the faces (`∇F` piecewise constant).
pub fn mean_gradient_norm(mesh: &TriMesh, field: &[f64]) -> f64 {
    let mut weighted = 0.0;
    let mut area = 0.0;
    for (f, face) in mesh.faces().iter().enumerate() {
        let gradients = mesh.face_gradients(f);
        let gradient: Vec3 = (0..3).map(|k| gradients[k] * field[face[k] as usize]).sum();
        weighted += gradient.norm() * mesh.face_areas()[f];
        area += mesh.face_areas()[f];
    }
    if area > 0.0 {
        weighted / area
    } else {
        0.0
    }
}

/// Builds `count` strips on `field` (one value per vertex, checked by the caller), judged with
/// `tolerance` degrees.
pub fn build_strips(mesh: &TriMesh, field: &[f64], theta: f64, count: usize, width: Option<f64>, tolerance: f64) -> CliResult<StripRun> {
    let levels = uniform_levels(mesh, field, count).map_err(|e| CliError::bad_input(format!("level curves: {e}")))?;
    build_strips_at(mesh, field, theta, &levels, width, tolerance)
}

/// As [`build_strips`] on the given increasing `levels` of `field`.
pub fn build_strips_at(mesh: &TriMesh, field: &[f64], theta: f64, levels: &[f64], width: Option<f64>, tolerance: f64) -> CliResult<StripRun> {
    let step = match levels {
        [a, b, ..] => b - a,
        // A single level: its distance to the field's minimum.
        [a] => a - field.iter().copied().fold(f64::INFINITY, f64::min),
        [] => 0.0,
    };
    let gradient = mean_gradient_norm(mesh, field);
    let spacing = if gradient > 0.0 { step / gradient } else { 0.0 };
    let width = match width {
        Some(w) => w,
        None if spacing.is_finite() && spacing > 0.0 => WIDTH_PER_SPACING * spacing,
        None => return Err(CliError::bad_input("the field is constant: no level curves, give --width")),
    };
    let curves = extract_level_curves(mesh, field, levels).map_err(|e| CliError::bad_input(format!("level curves: {e}")))?;
    let curves = resample_all(&curves, mesh.mean_edge_length()).map_err(|e| CliError::internal(format!("resampling level curves: {e}")))?;
    let params = StripParams { tolerance_degrees: tolerance, ..StripParams::new(theta, width) };
    let pattern = rectifying_strips(mesh, &curves, &params).map_err(|e| CliError::bad_input(format!("strips: {e}")))?;
    Ok(StripRun { curves, pattern, width, spacing })
}

/// Two-line summary of a pattern: strips, lengths and warnings, then Table 4.
pub fn strips_summary(run: &StripRun) -> String {
    let m = &run.pattern.metrics;
    let lengths = run.pattern.strips.iter().map(|s| s.metrics.length);
    let total: f64 = lengths.clone().sum();
    let shortest = lengths.clone().fold(f64::INFINITY, f64::min);
    let longest = lengths.fold(0.0, f64::max);
    let warned = run.pattern.strips.iter().filter(|s| !s.warnings.is_empty()).count();
    let range = if m.strip_count > 0 { format!(" ({shortest:.2} m to {longest:.2} m)") } else { String::new() };
    format!(
        "{} strips, {} curves skipped, {warned} with warnings (--verbose lists them); width {:.3} m; total length {total:.2} m{range}\n\
         Table 4: max diff θ {:.3}°, max e_straight {:.2e}, max planarity {:.2e}, Appro {:.3} %, flipped quads {}; \
         strip planes: max angle error {:.3}°, longest ruling {:.2} strip widths",
        m.strip_count,
        run.pattern.skipped.len(),
        run.width,
        m.max_diff_theta_degrees,
        m.max_e_straight,
        m.max_planar,
        m.appro_percent,
        m.flipped_quads,
        m.max_quad_angle_error_degrees,
        m.max_ruling_over_width
    )
}

/// Strip warnings, one line each (shown under `--verbose`).
pub fn warning_lines(run: &StripRun) -> Vec<String> {
    let strips = run.pattern.strips.iter().enumerate().flat_map(|(id, s)| s.warnings.iter().map(move |w| format!("strip {id}: {w}")));
    let skipped = run.pattern.skipped.iter().flat_map(|s| s.warnings.iter().map(move |w| format!("curve {} skipped: {w}", s.curve)));
    strips.chain(skipped).collect()
}

/// Writes curves.obj, strips.obj, rulings.obj, diagnostics.csv and preview.svg.
pub fn write_strip_files(out: &OutputDir, mesh: &TriMesh, run: &StripRun) -> CliResult<()> {
    out.write("curves.obj", curves_obj(&run.curves))?;
    out.write("strips.obj", strips_obj(&run.pattern))?;
    out.write("rulings.obj", rulings_obj(&run.pattern))?;
    out.write("diagnostics.csv", diagnostics_csv(&run.pattern, run.width))?;
    out.write("preview.svg", preview_svg(mesh, &run.pattern))
}

pub fn run(args: &StripsArgs) -> CliResult<()> {
    let started = Instant::now();
    let verbosity = Verbosity::from(args.verbosity);
    let settings = Settings::resolve(Flags {
        mesh: Some(&args.mesh),
        out: Some(&args.out),
        family: Some(&args.family),
        field: None,
        strips: Some(&args.strips),
        config: Some(&args.config),
        start: None,
    })?;
    let mesh = load_mesh(settings.mesh.as_deref())?;
    let field = read_field_for(&mesh, &args.field_csv)?;
    let out = OutputDir::create(&settings.out, settings.force)?;
    note(verbosity, &format!("strips: {} level curves at θ = {}°", settings.strips, settings.theta));
    let run = build_strips(&mesh, &field, settings.theta, settings.strips, settings.width, settings.tolerance)?;
    if verbosity == Verbosity::Verbose {
        warning_lines(&run).iter().for_each(err_line);
    }
    let strips_seconds = started.elapsed().as_secs_f64();
    write_strip_files(&out, &mesh, &run)?;
    let timings = Timings { field: 0.0, strips: strips_seconds, total: started.elapsed().as_secs_f64() };
    let parameters = report_json::parameters(&settings, settings.theta, &mesh_name(settings.mesh.as_deref()), None);
    out.write("report.json", report_json::document(&parameters, None, Some(&run), &timings))?;
    let target = out.target().display().to_string();
    out.commit()?;
    summary(verbosity, &format!("{}\nwrote {target}/ (curves.obj, strips.obj, rulings.obj, diagnostics.csv, preview.svg, report.json)", strips_summary(&run)))?;
    crate::design::verdict(&run)
}
