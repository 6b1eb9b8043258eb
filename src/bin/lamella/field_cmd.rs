//! `lamella field`: optimise the scalar field whose level sets form the θ pseudo-geodesics
//! (paper Sec. 3.2, Eq. 12), or continue a saved session.
use crate::args::FieldArgs;
use crate::config::{Flags, Settings};
use crate::error::{CliError, CliResult};
use crate::field_files::{energies_csv, field_csv, read_energies_csv, HistoryRow};
use crate::mesh_input::{load_mesh, mesh_name, read_bytes};
use crate::output_dir::OutputDir;
use crate::progress::{note, summary, Progress, Verbosity};
use crate::report_json::{self, Timings};
use crate::start_field::{start_field, StartField};
use crate::svg::convergence::convergence_svg;
use lamella::field::{FieldError, FieldParams, FieldSolver};
use lamella::mesh::TriMesh;
use std::time::Instant;

/// A new pseudo-geodesic field optimisation from `start` with the default schedule.
pub fn new_solver(mesh: &TriMesh, start: &StartField) -> CliResult<FieldSolver> {
    let mut params = FieldParams::pseudo_geodesic(start.theta);
    params.gradient_target = start.gradient_target;
    FieldSolver::new(mesh, &start.values, params).map_err(field_error)
}

/// Runs iterations one at a time until convergence or `max_iterations` in total, appending
/// each state to `history`.
pub fn optimise(
    solver: &mut FieldSolver,
    max_iterations: usize,
    history: &mut Vec<HistoryRow>,
    verbosity: Verbosity,
) -> CliResult<()> {
    let mut progress = Progress::new(verbosity, solver.iterations(), max_iterations);
    while !solver.is_converged() && solver.iterations() < max_iterations {
        let report = solver.step(1).map_err(field_error)?;
        history.push(HistoryRow::of(&report));
        progress.iteration(&report);
    }
    progress.finish();
    Ok(())
}

/// Field errors caused by the input are bad input; the rest are internal failures.
pub fn field_error(error: FieldError) -> CliError {
    match error {
        FieldError::Solver(_) | FieldError::SolverFailedNear { .. } => CliError::internal(format!("field optimisation failed: {error}")),
        _ => CliError::bad_input(format!("field: {error}")),
    }
}

/// Largest measured angle error (degrees) a field may keep without a warning.
const ANGLE_ERROR_WARNING_DEGREES: f64 = 1.0;

/// Description of the field's state: one line, and a warning line when the level curves miss θ
/// somewhere by more than a degree.
pub fn field_summary(solver: &FieldSolver) -> String {
    let r = solver.report();
    let mut text = format!(
        "field {} after {} iterations: E_angle {:.2e}, angle error max {:.3}° (RMS {:.3}°), {} singular vertices",
        if r.converged { "converged" } else { "stopped" },
        r.iterations,
        r.energies.angle,
        r.angle_error_max_degrees,
        r.angle_error_rms_degrees,
        r.singular_vertices.len()
    );
    if r.angle_error_max_degrees > ANGLE_ERROR_WARNING_DEGREES {
        text.push_str(&format!(
            "\nwarning: the level curves miss θ by up to {:.1}° somewhere: no θ family covers the surface from this start; try another start (--guides with another --guide-angle or --guide-side, --strokes)",
            r.angle_error_max_degrees
        ));
    }
    text
}

/// Writes the field's files: field.csv, session.bin, energies.csv, convergence.svg.
pub fn write_field_files(out: &OutputDir, solver: &FieldSolver, history: &[HistoryRow]) -> CliResult<()> {
    out.write("field.csv", field_csv(&solver.field()))?;
    out.write("session.bin", solver.to_bytes())?;
    out.write("energies.csv", energies_csv(history))?;
    out.write("convergence.svg", convergence_svg(history))
}

pub fn run(args: &FieldArgs) -> CliResult<()> {
    let started = Instant::now();
    let verbosity = Verbosity::from(args.verbosity);
    let settings = Settings::resolve(Flags {
        mesh: Some(&args.mesh),
        out: Some(&args.out),
        field: Some(&args.field),
        config: Some(&args.config),
        strips: None,
        start: Some(&args.start),
    })?;
    let mut start_description = None;
    let (mut solver, mut history, source) = match &args.resume {
        Some(path) => {
            let bytes = read_bytes(path)?;
            let solver = FieldSolver::from_bytes(&bytes)
                .map_err(|e| CliError::bad_input(format!("{}: not a usable field session: {e}", path.display())))?;
            let beside = path.with_file_name("energies.csv");
            let mut history = if beside.is_file() { read_energies_csv(&beside)? } else { Vec::new() };
            history.retain(|row| row.iteration <= solver.iterations());
            (solver, history, format!("session {}", path.display()))
        }
        None => {
            let mesh = load_mesh(settings.mesh.as_deref())?;
            let start = start_field(&mesh, &settings)?;
            let solver = new_solver(&mesh, &start)?;
            start_description = Some(start.description);
            let history = vec![HistoryRow::of(solver.report())];
            (solver, history, mesh_name(settings.mesh.as_deref()))
        }
    };
    let out = OutputDir::create(&settings.out, settings.force)?;
    let theta = solver.params().family.theta_degrees();
    note(verbosity, &format!("field on {source}: θ = {theta}°, from iteration {}", solver.iterations()));
    let field_started = Instant::now();
    optimise(&mut solver, settings.max_iterations, &mut history, verbosity)?;
    let field_seconds = field_started.elapsed().as_secs_f64();
    write_field_files(&out, &solver, &history)?;
    let timings = Timings { field: field_seconds, strips: 0.0, total: started.elapsed().as_secs_f64() };
    let parameters = report_json::parameters(&settings, theta, &source, start_description.as_ref());
    let report = report_json::document(&parameters, Some((&solver, &history)), None, &timings);
    out.write("report.json", report)?;
    let target = out.target().display().to_string();
    out.commit()?;
    summary(verbosity, &format!("{}\nwrote {target}/ (field.csv, session.bin, energies.csv, convergence.svg, report.json)", field_summary(&solver)))
}
