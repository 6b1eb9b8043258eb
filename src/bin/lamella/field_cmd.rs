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
use crate::start_field::start_solver;
use crate::svg::convergence::convergence_svg;
use lamella::curves::{extract_level_curves, uniform_levels, LevelCurve};
use lamella::field::{Family, FieldError, FieldSolver};
use lamella::mesh::TriMesh;
use lamella::quality::{family_angles, FamilyAngles, DEFAULT_SPACING_EDGES};
use std::time::Instant;

/// Level curves the `field` command measures the family on.
const MEASURED_LEVELS: usize = 20;

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

/// Largest angle error (degrees, along the level curves) a field may keep without a warning.
const ANGLE_ERROR_WARNING_DEGREES: f64 = 2.0;

/// The family measure of `curves` (level curves of `mesh`) for the solver's family: along the
/// curves, resampled every three mean edges, against the smooth surface normal.
pub fn family_measure(mesh: &TriMesh, solver: &FieldSolver, curves: &[LevelCurve]) -> CliResult<FamilyAngles> {
    let (low, high) = mesh.bounding_box();
    family_angles(curves, solver.params().family, DEFAULT_SPACING_EDGES * mesh.mean_edge_length(), (high - low).norm())
        .map_err(|e| CliError::internal(format!("measuring the level curves: {e}")))
}

/// Description of the field's state: the optimiser's own figures, then the family as measured
/// along its level curves, and a warning line when the curves miss θ somewhere by more than 2°.
pub fn field_summary(solver: &FieldSolver, measure: &FamilyAngles) -> String {
    let r = solver.report();
    let mut text = format!(
        "field {} after {} iterations: E_angle {:.2e}, {} singular vertices; along the level curves: angle error RMS {:.3}°, max {:.3}°, {:.1} % nearly straight",
        if r.converged { "converged" } else { "stopped" },
        r.iterations,
        r.energies.angle,
        r.singular_vertices.len(),
        measure.rms_error_degrees,
        measure.max_error_degrees,
        100.0 * measure.straight_fraction()
    );
    if measure.max_error_degrees > ANGLE_ERROR_WARNING_DEGREES {
        let at = measure.worst.map_or(String::new(), |w| format!(" (at {:.3}, {:.3}, {:.3})", w.point[0], w.point[1], w.point[2]));
        text.push_str(&format!(
            "\nwarning: the level curves miss θ by up to {:.1}°{at}: no θ family covers the surface there from this start; the strips may still meet θ (they are optimised on their own), otherwise try another start (--guides with another --guide-angle or --guide-side, --strokes) or θ",
            measure.max_error_degrees
        ));
    }
    text
}

/// The level curves of the solver's field at `count` uniform levels.
pub fn measured_curves(mesh: &TriMesh, field: &[f64], count: usize) -> CliResult<Vec<LevelCurve>> {
    let levels = uniform_levels(mesh, field, count).map_err(|e| CliError::internal(format!("level curves: {e}")))?;
    extract_level_curves(mesh, field, &levels).map_err(|e| CliError::internal(format!("level curves: {e}")))
}

/// Writes the field's files: field.csv, session.bin, energies.csv, convergence.svg.
pub fn write_field_files(out: &OutputDir, solver: &FieldSolver, history: &[HistoryRow]) -> CliResult<()> {
    out.write("field.csv", field_csv(&solver.field()))?;
    out.write("session.bin", solver.to_bytes())?;
    out.write("energies.csv", energies_csv(history))?;
    out.write("convergence.svg", convergence_svg(history))
}

pub fn run(args: &FieldArgs) -> CliResult<()> {
    if crate::slope_field::requested(args) {
        return crate::slope_field::run(args);
    }
    let started = Instant::now();
    let verbosity = Verbosity::from(args.verbosity);
    let settings = Settings::resolve(Flags {
        mesh: Some(&args.mesh),
        out: Some(&args.out),
        family: None,
        field: Some(&args.field),
        config: Some(&args.config),
        strips: None,
        start: Some(&args.start),
    })?;
    let out = OutputDir::create(&settings.out, settings.force)?;
    let mut start_description = None;
    let (mut solver, mut history, source, mesh) = match &args.resume {
        Some(path) => {
            let bytes = read_bytes(path)?;
            let solver = FieldSolver::from_bytes(&bytes)
                .map_err(|e| CliError::bad_input(format!("{}: not a usable field session: {e}", path.display())))?;
            let beside = path.with_file_name("energies.csv");
            let mut history = if beside.is_file() { read_energies_csv(&beside)? } else { Vec::new() };
            history.retain(|row| row.iteration <= solver.iterations());
            let mesh = solver.mesh();
            (solver, history, format!("session {}", path.display()), mesh)
        }
        None => {
            let mesh = load_mesh(settings.mesh.as_deref())?;
            let started = start_solver(&mesh, &settings, verbosity)?;
            start_description = Some(started.description);
            let history = vec![HistoryRow::of(started.solver.report())];
            (started.solver, history, mesh_name(settings.mesh.as_deref()), mesh)
        }
    };
    if let Family::ConstantSlope { .. } = solver.params().family {
        optimise(&mut solver, settings.max_iterations, &mut history, verbosity)?;
        return crate::slope_field::finish(out, &mesh, &solver, &history, &serde_json::json!({ "mesh": source }), started, verbosity);
    }
    let theta = solver.params().family.theta_degrees();
    note(verbosity, &format!("field on {source}: θ = {theta}°, from iteration {}", solver.iterations()));
    let field_started = Instant::now();
    optimise(&mut solver, settings.max_iterations, &mut history, verbosity)?;
    let field_seconds = field_started.elapsed().as_secs_f64();
    write_field_files(&out, &solver, &history)?;
    let measure = family_measure(&mesh, &solver, &measured_curves(&mesh, &solver.field(), MEASURED_LEVELS)?)?;
    let timings = Timings { field: field_seconds, strips: 0.0, total: started.elapsed().as_secs_f64() };
    let parameters = report_json::parameters(&settings, theta, &source, start_description.as_ref());
    let report = report_json::document(&parameters, Some((&solver, &history, &measure)), None, &timings);
    out.write("report.json", report)?;
    let target = out.target().display().to_string();
    out.commit()?;
    summary(verbosity, &format!("{}\nwrote {target}/ (field.csv, session.bin, energies.csv, convergence.svg, report.json)", field_summary(&solver, &measure)))
}
