//! `lamella field --family slope`: a field whose level curves have constant slope about an axis
//! (paper Sec. 5.2.3, Eq. 22), started from the slope directions, optimised, and judged along its
//! level curves; exits 3 when they miss the slope by more than [`SLOPE_TOLERANCE_DEGREES`]
//! anywhere the slope is reachable. Besides the field's files it writes isophote.obj, the
//! boundary of the reachable region.
use crate::args::FieldArgs;
use crate::config::{parse_vector, Flags, Settings, Start};
use crate::error::{CliError, CliResult};
use crate::field_cmd::{field_error, measured_curves, optimise, write_field_files};
use crate::field_files::HistoryRow;
use crate::mesh_input::{load_mesh, mesh_name};
use crate::output_dir::OutputDir;
use crate::progress::{note, summary, Verbosity};
use crate::report_json::pretty;
use crate::start_field::read_field_for;
use crate::strip_obj::curves_obj;
use lamella::field::{reachable_boundary, Family, FieldParams, FieldSolver};
use lamella::initialisation::slope_start_field;
use lamella::mesh::{TriMesh, Vec3};
use lamella::quality::{slope_angles, SlopeAngles, DEFAULT_SPACING_EDGES};
use serde_json::json;
use std::time::Instant;

/// Largest slope error (degrees, along the level curves, where reachable) of an acceptable field.
pub const SLOPE_TOLERANCE_DEGREES: f64 = 0.5;
/// Default slope β in degrees.
const DEFAULT_SLOPE: f64 = 30.0;
/// Level curves the slope is measured on.
const MEASURED_LEVELS: usize = 20;

/// Whether the flags ask for a constant-slope family.
pub fn requested(args: &FieldArgs) -> bool {
    args.field.family.family.as_deref() == Some("slope")
}

pub fn run(args: &FieldArgs) -> CliResult<()> {
    let started = Instant::now();
    let verbosity = Verbosity::from(args.verbosity);
    if args.field.family.theta.is_some() {
        return Err(CliError::bad_input("--family slope has no θ: give --slope (and --axis) instead of --theta"));
    }
    let mut field_flags = args.field.clone();
    field_flags.family.family = None;
    let settings = Settings::resolve(Flags { mesh: Some(&args.mesh), out: Some(&args.out), field: Some(&field_flags), config: Some(&args.config), start: Some(&args.start), ..Flags::default() })?;
    let axis = match &args.slope.axis {
        Some(text) => parse_vector("--axis", text)?,
        None => Vec3::z(),
    };
    let slope = args.slope.slope.unwrap_or(DEFAULT_SLOPE);
    let family = Family::ConstantSlope { axis: [axis.x, axis.y, axis.z], slope_degrees: slope, free_slope: args.slope.free_slope };
    let mesh = load_mesh(settings.mesh.as_deref())?;
    let out = OutputDir::create(&settings.out, settings.force)?;
    let (start, description) = match &settings.start {
        Start::Search => (slope_start_field(&mesh, family_axis(&family), slope).map_err(|e| CliError::bad_input(format!("constant-slope start: {e}")))?, "slope directions"),
        Start::Direction(d) => (mesh.positions().iter().map(|p| p.dot(d)).collect(), "height along a direction"),
        Start::FieldFile(path) => (read_field_for(&mesh, path)?, "field file"),
        _ => return Err(CliError::bad_input("--family slope starts from the slope directions, --direction or --start-field (not guides or strokes)")),
    };
    let mut solver = FieldSolver::new(&mesh, &start, FieldParams::new(family)).map_err(field_error)?;
    note(verbosity, &format!("constant-slope field on {}: axis {:.3},{:.3},{:.3}, slope {slope}°{}", mesh_name(settings.mesh.as_deref()), axis.x, axis.y, axis.z, if args.slope.free_slope { " (free)" } else { "" }));
    let mut history = vec![HistoryRow::of(solver.report())];
    optimise(&mut solver, settings.max_iterations, &mut history, verbosity)?;
    finish(out, &mesh, &solver, &history, &json!({ "mesh": mesh_name(settings.mesh.as_deref()), "start": description }), started, verbosity)
}

fn family_axis(family: &Family) -> [f64; 3] {
    match *family {
        Family::ConstantSlope { axis, .. } => axis,
        _ => [0.0, 0.0, 1.0],
    }
}

/// Writes the files of a constant-slope field (`field`'s files, isophote.obj, report.json),
/// prints the summary and exits 3 when the level curves miss the slope.
pub fn finish(out: OutputDir, mesh: &TriMesh, solver: &FieldSolver, history: &[HistoryRow], parameters: &serde_json::Value, started: Instant, verbosity: Verbosity) -> CliResult<()> {
    let axis = solver.params().family.slope_axis().ok_or_else(|| CliError::internal("not a constant-slope family"))?;
    let slope = solver.slope_degrees().ok_or_else(|| CliError::internal("not a constant-slope family"))?;
    write_field_files(&out, solver, history)?;
    let curves = measured_curves(mesh, &solver.field(), MEASURED_LEVELS)?;
    let measure = slope_angles(&curves, &axis, slope, DEFAULT_SPACING_EDGES * mesh.mean_edge_length()).map_err(|e| CliError::internal(format!("measuring the level curves: {e}")))?;
    let boundary = reachable_boundary(mesh, &axis, slope).map_err(|e| CliError::internal(format!("isophote: {e}")))?;
    out.write("isophote.obj", curves_obj(&boundary))?;
    let r = solver.report();
    let report = json!({
        "lamella_version": env!("CARGO_PKG_VERSION"),
        "parameters": parameters,
        "field": {
            "family": solver.params().family,
            "slope_degrees": slope,
            "iterations": r.iterations,
            "converged": r.converged,
            "singular_vertices": r.singular_vertices.len(),
            "slope_error_rms_degrees_at_vertices": r.angle_error_rms_degrees,
            "slope_error_max_degrees_at_vertices": r.angle_error_max_degrees,
            "level_curves": measure,
            "isophote_curves": boundary.len(),
            "acceptable": measure.max_error_degrees <= SLOPE_TOLERANCE_DEGREES && measure.measured > 0,
        },
        "timings_s": { "total": started.elapsed().as_secs_f64() },
    });
    out.write("report.json", pretty(&report))?;
    let target = out.target().display().to_string();
    out.commit()?;
    summary(verbosity, &format!("{}\nwrote {target}/ (field.csv, session.bin, energies.csv, convergence.svg, isophote.obj, report.json)", slope_summary(solver, slope, &measure, boundary.len())))?;
    if measure.measured == 0 {
        return Err(CliError::NoAcceptableFamily("no acceptable family: no level-curve point lies where the slope is reachable".into()));
    }
    if measure.max_error_degrees > SLOPE_TOLERANCE_DEGREES {
        let at = measure.worst.map_or(String::new(), |w| format!(" (at {:.3}, {:.3}, {:.3})", w[0], w[1], w[2]));
        return Err(CliError::NoAcceptableFamily(format!(
            "no acceptable family: the level curves miss the slope {slope:.3}° by up to {:.3}°{at}, more than {SLOPE_TOLERANCE_DEGREES}°",
            measure.max_error_degrees
        )));
    }
    Ok(())
}

fn slope_summary(solver: &FieldSolver, slope: f64, measure: &SlopeAngles, boundary: usize) -> String {
    let r = solver.report();
    format!(
        "constant-slope field {} after {} iterations (slope {slope:.3}°): {} singular vertices; along the level curves where reachable: slope error RMS {:.3}°, max {:.3}° ({} points measured, {} beyond the isophote; {boundary} isophote curve(s))",
        if r.converged { "converged" } else { "stopped" },
        r.iterations,
        r.singular_vertices.len(),
        measure.rms_error_degrees,
        measure.max_error_degrees,
        measure.measured,
        measure.unreachable
    )
}
