//! `lamella reshape`: the surface optimisation of paper Sec. 3.3 (Fig. 17). The field stays
//! fixed and the vertices move so that its level sets become P-curves of θ, within a bound on
//! the deviation from the original surface; then the level curves and strips on the moved
//! surface, judged as by `design` (exit 3 when they miss θ). With `--alternate`, field steps and
//! surface steps in turn (the alternating schedule of Sec. 3.3).
use crate::args::ReshapeArgs;
use crate::config::{out_of_range, DEFAULT_OUT, MAX_ITERATIONS_LIMIT, MAX_STRIPS};
use crate::error::{CliError, CliResult};
use crate::field_files::field_csv;
use crate::mesh_input::{load_mesh, mesh_name, read_bytes};
use crate::output_dir::OutputDir;
use crate::progress::{note, summary, Verbosity};
use crate::start_field::read_field_for;
use crate::strip_obj::{curves_obj, rulings_obj, strips_obj};
use crate::strips_cmd::{build_strips, strips_summary, StripRun};
use crate::svg::preview::displacement_preview_svg;
use lamella::field::FieldSolver;
use lamella::mesh::{TriMesh, Vec3};
use lamella::reshape::{AlternatingParams, AlternatingSolver, ReshapeParams, ReshapeReport, ReshapeSolver, ReshapeWeights, Tolerance};
use serde_json::{json, Value};
use std::fmt::Write as _;
use std::path::PathBuf;
use std::time::Instant;

/// Most rounds of `--alternate`.
const MAX_ROUNDS: usize = 1000;

/// Iterations per `step` between progress notes.
const STEP: usize = 10;

/// Parses `--tolerance`: `P%` of the bounding-box diagonal, or a length.
pub fn parse_tolerance(text: &str) -> CliResult<Tolerance> {
    match text.trim().strip_suffix('%') {
        Some(percent) => {
            let value: f64 = percent.trim().parse().map_err(|_| CliError::bad_input(format!("--tolerance: `{}` is not a percentage", lamella::input::clip(text))))?;
            if !(value.is_finite() && value > 0.0 && value <= 100.0) {
                return Err(out_of_range("tolerance", text, "a length > 0 or a percentage in (0 %, 100 %]"));
            }
            Ok(Tolerance::DiagonalFraction(value / 100.0))
        }
        None => Ok(Tolerance::Absolute(crate::units::length("--tolerance", text)?)),
    }
}

fn check(args: &ReshapeArgs) -> CliResult<()> {
    if let Some(theta) = args.theta {
        if !(theta.is_finite() && theta > 0.0 && theta < 180.0) {
            return Err(out_of_range("theta", theta, "between 0 and 180 degrees, exclusive"));
        }
    }
    if !(1..=MAX_ITERATIONS_LIMIT).contains(&args.max_iterations) {
        return Err(out_of_range("max-iterations", args.max_iterations, &format!("1 to {MAX_ITERATIONS_LIMIT}")));
    }
    if let Some(rounds) = args.alternate {
        if !(1..=MAX_ROUNDS).contains(&rounds) {
            return Err(out_of_range("alternate", rounds, &format!("1 to {MAX_ROUNDS} rounds")));
        }
    }
    if !(1..=MAX_STRIPS).contains(&args.strips) {
        return Err(out_of_range("strips", args.strips, &format!("1 to {MAX_STRIPS}")));
    }
    if !(args.angle_tolerance.is_finite() && args.angle_tolerance > 0.0 && args.angle_tolerance < 180.0) {
        return Err(out_of_range("angle-tolerance", args.angle_tolerance, "between 0 and 180 degrees, exclusive"));
    }
    Ok(())
}

/// The surface optimisation to run: continued from --resume, or new on the mesh and field of
/// --session or of --mesh and --field, with --theta and --tolerance.
fn start(args: &ReshapeArgs) -> CliResult<(ReshapeSolver, String)> {
    if let Some(path) = &args.resume {
        let bytes = read_bytes(path)?;
        let solver = ReshapeSolver::from_bytes(&bytes).map_err(|e| CliError::bad_input(format!("{}: not a usable surface session: {e}", path.display())))?;
        return Ok((solver, format!("surface session {}", path.display())));
    }
    let tolerance = parse_tolerance(args.tolerance.as_deref().unwrap_or(DEFAULT_TOLERANCE))?;
    let (mesh, field, source) = inputs(args)?;
    // Invariant: clap requires --theta unless --resume is given.
    let theta = args.theta.ok_or_else(|| CliError::bad_input("give --theta"))?;
    let params = ReshapeParams { tolerance, ..ReshapeParams::new(theta) };
    let solver = ReshapeSolver::new(&mesh, &field, params).map_err(|e| CliError::bad_input(format!("reshape: {e}")))?;
    Ok((solver, source))
}

/// `--tolerance` when not given: 1 % of the bounding-box diagonal.
const DEFAULT_TOLERANCE: &str = "1%";

/// The mesh and field to reshape: from a session, or from --mesh and --field.
fn inputs(args: &ReshapeArgs) -> CliResult<(TriMesh, Vec<f64>, String)> {
    if let Some(path) = &args.session {
        let bytes = read_bytes(path)?;
        let solver = FieldSolver::from_bytes(&bytes).map_err(|e| CliError::bad_input(format!("{}: not a usable field session: {e}", path.display())))?;
        return Ok((solver.mesh(), solver.field(), format!("session {}", path.display())));
    }
    let mesh = load_mesh(args.mesh.mesh.as_deref())?;
    // Invariant: clap requires --field unless --session is given.
    let field_path = args.field_csv.as_ref().ok_or_else(|| CliError::bad_input("give --field or --session"))?;
    let field = read_field_for(&mesh, field_path)?;
    Ok((mesh, field, mesh_name(args.mesh.mesh.as_deref())))
}

pub fn run(args: &ReshapeArgs) -> CliResult<()> {
    let started = Instant::now();
    let verbosity = Verbosity::from(args.verbosity);
    check(args)?;
    match args.alternate {
        Some(rounds) => run_alternating(args, rounds, started, verbosity),
        None => run_surface(args, started, verbosity),
    }
}

/// The surface optimisation with the field fixed.
fn run_surface(args: &ReshapeArgs, started: Instant, verbosity: Verbosity) -> CliResult<()> {
    let (mut solver, source) = start(args)?;
    let out = output_dir(args)?;
    let (mesh, field, theta) = (solver.original().clone(), solver.field().to_vec(), solver.params().theta_degrees);
    note(
        verbosity,
        &format!("reshape {source}: {} vertices, θ = {theta}°, tolerance {:.4} m, from iteration {}", mesh.vertex_count(), solver.report().tolerance, solver.iterations()),
    );
    while solver.iterations() < args.max_iterations && !solver.is_converged() {
        let report = solver.step(STEP.min(args.max_iterations - solver.iterations())).map_err(|e| CliError::internal(format!("reshape: {e}")))?;
        if verbosity == Verbosity::Verbose {
            note(verbosity, &progress_line(&report));
        }
    }
    let surface_seconds = started.elapsed().as_secs_f64();
    let moved = solver.mesh();
    let run = write_moved(&out, args, &mesh, &moved, &solver.deviations(), &field, theta)?;
    out.write("reshape.bin", solver.to_bytes())?;
    let r = solver.report();
    let mut report = report_json(&source, theta, &solver.params().weights, r, &run);
    report["timings_seconds"] = json!({ "surface": surface_seconds, "total": started.elapsed().as_secs_f64() });
    out.write("report.json", serde_json::to_string_pretty(&report).map_err(|e| CliError::internal(format!("report.json: {e}")))?)?;
    let iterations = format!("{} iterations{}", r.iterations, if r.converged { ", converged" } else { "" });
    finish(out, verbosity, &iterations, r, &run, started, "surface.obj, deviation.csv, reshape.bin, curves.obj, strips.obj, rulings.obj, preview.svg, report.json")
}

/// Field and surface steps in turn (`--alternate ROUNDS`).
fn run_alternating(args: &ReshapeArgs, rounds: usize, started: Instant, verbosity: Verbosity) -> CliResult<()> {
    let tolerance = parse_tolerance(args.tolerance.as_deref().unwrap_or(DEFAULT_TOLERANCE))?;
    let (mesh, field, source) = inputs(args)?;
    // Invariant: clap requires --theta unless --resume is given, and --alternate excludes it.
    let theta = args.theta.ok_or_else(|| CliError::bad_input("give --theta"))?;
    let params = AlternatingParams {
        reshape: ReshapeParams { tolerance, ..ReshapeParams::new(theta) },
        iterations_per_step: args.max_iterations,
        ..AlternatingParams::new(theta)
    };
    let mut solver = AlternatingSolver::new(&mesh, &field, params).map_err(|e| CliError::bad_input(format!("reshape: {e}")))?;
    let out = output_dir(args)?;
    note(
        verbosity,
        &format!("reshape {source}, field and surface in turn: {} vertices, θ = {theta}°, tolerance {:.4} m, at most {rounds} rounds", mesh.vertex_count(), solver.report().surface.tolerance),
    );
    while solver.report().rounds < rounds && !solver.is_converged() {
        let report = solver.step(1).map_err(|e| CliError::internal(format!("reshape: {e}")))?;
        if verbosity == Verbosity::Verbose {
            let f = &report.field;
            note(verbosity, &format!("round {}: field {} iterations, E_angle {:.3e}, angle error {:.3}° RMS; surface {}", report.rounds, f.iterations, f.energies.angle, f.angle_error_rms_degrees, progress_line(&report.surface)));
        }
    }
    let steps_seconds = started.elapsed().as_secs_f64();
    let report = solver.report().clone();
    let run = write_moved(&out, args, &mesh, solver.mesh(), solver.deviations(), solver.field(), theta)?;
    out.write("field.csv", field_csv(solver.field()))?;
    let mut json = report_json(&source, theta, &ReshapeParams::new(theta).weights, &report.surface, &run);
    json["alternating"] = json!({
        "rounds": report.rounds,
        "max_rounds": rounds,
        "converged": report.converged,
        "field": {
            "iterations": report.field.iterations,
            "converged": report.field.converged,
            "energy_angle": number(report.field.energies.angle),
            "vertex_angle_error_rms_degrees": number(report.field.angle_error_rms_degrees),
            "vertex_angle_error_max_degrees": number(report.field.angle_error_max_degrees),
        },
    });
    json["timings_seconds"] = json!({ "rounds": steps_seconds, "total": started.elapsed().as_secs_f64() });
    out.write("report.json", serde_json::to_string_pretty(&json).map_err(|e| CliError::internal(format!("report.json: {e}")))?)?;
    let rounds_text = format!("{} rounds{}", report.rounds, if report.converged { ", converged" } else { "" });
    finish(out, verbosity, &rounds_text, &report.surface, &run, started, "surface.obj, field.csv, deviation.csv, curves.obj, strips.obj, rulings.obj, preview.svg, report.json")
}

fn output_dir(args: &ReshapeArgs) -> CliResult<OutputDir> {
    let target: PathBuf = args.out.out.clone().unwrap_or_else(|| PathBuf::from(DEFAULT_OUT));
    OutputDir::create(&target, args.out.force)
}

/// Builds the strips of `field` on the moved surface and writes what both kinds of run write:
/// surface.obj, deviation.csv, curves.obj, strips.obj, rulings.obj, preview.svg.
fn write_moved(out: &OutputDir, args: &ReshapeArgs, original: &TriMesh, moved: &TriMesh, deviations: &[f64], field: &[f64], theta: f64) -> CliResult<StripRun> {
    let run = build_strips(moved, field, theta, args.strips, None, args.angle_tolerance)?;
    let mut surface = Vec::new();
    moved.write_obj(&mut surface).map_err(|e| CliError::internal(format!("surface.obj: {e}")))?;
    out.write("surface.obj", surface)?;
    out.write("deviation.csv", deviation_csv(original, moved, deviations))?;
    out.write("curves.obj", curves_obj(&run.curves))?;
    out.write("strips.obj", strips_obj(&run.pattern))?;
    out.write("rulings.obj", rulings_obj(&run.pattern))?;
    out.write("preview.svg", displacement_preview_svg(moved, &run.pattern, deviations))?;
    Ok(run)
}

/// Commits the output, prints the summary and gives the strips' verdict as the exit status.
fn finish(out: OutputDir, verbosity: Verbosity, steps: &str, r: &ReshapeReport, run: &StripRun, started: Instant, files: &str) -> CliResult<()> {
    let target = out.target().display().to_string();
    out.commit()?;
    summary(
        verbosity,
        &format!(
            "{steps}; deviation max {:.4} m, RMS {:.4} m (tolerance {:.4} m); edge lengths change by up to {:.1} %\n{}\ndone in {:.1} s; wrote {target}/ ({files})",
            r.max_deviation,
            r.rms_deviation,
            r.tolerance,
            100.0 * r.max_edge_change,
            strips_summary(run),
            started.elapsed().as_secs_f64()
        ),
    )?;
    crate::design::verdict(run)
}

fn progress_line(r: &ReshapeReport) -> String {
    format!(
        "iteration {}: E_angle {:.3e}, E_fair {:.3e}, E_close {:.3e}, E_edge {:.3e}; angle error {:.3}° RMS; deviation {:.4} m",
        r.iterations, r.energies.angle, r.energies.fair, r.energies.close, r.energies.edge, r.angle_error_rms_degrees, r.max_deviation
    )
}

/// deviation.csv: per vertex its displacement and its distance from the original surface.
fn deviation_csv(original: &TriMesh, moved: &TriMesh, deviations: &[f64]) -> String {
    let mut text = String::from("vertex,x,y,z,dx,dy,dz,deviation\n");
    for (v, ((p, o), d)) in moved.positions().iter().zip(original.positions()).zip(deviations).enumerate() {
        let shift: Vec3 = p - o;
        let _ = writeln!(text, "{v},{},{},{},{},{},{},{d}", p.x, p.y, p.z, shift.x, shift.y, shift.z);
    }
    text
}

/// JSON has no NaN: non-finite numbers become null.
fn number(x: f64) -> Value {
    if x.is_finite() { json!(x) } else { Value::Null }
}

/// report.json without its timings.
fn report_json(source: &str, theta: f64, w: &ReshapeWeights, r: &ReshapeReport, run: &StripRun) -> Value {
    let m = &run.pattern.metrics;
    json!({
        "input": source,
        "theta_degrees": theta,
        "weights": { "fair": w.fair, "close": w.close, "angle": w.angle, "edge": w.edge },
        "iterations": r.iterations,
        "converged": r.converged,
        "energies": { "angle": number(r.energies.angle), "fair": number(r.energies.fair), "close": number(r.energies.close), "edge": number(r.energies.edge) },
        "vertex_angle_error_rms_degrees": number(r.angle_error_rms_degrees),
        "vertex_angle_error_max_degrees": number(r.angle_error_max_degrees),
        "deviation": {
            "tolerance_m": number(r.tolerance),
            "max_m": number(r.max_deviation),
            "rms_m": number(r.rms_deviation),
            "guard": number(r.guard),
        },
        "max_edge_length_change": number(r.max_edge_change),
        "strips": {
            "count": run.pattern.strips.len(),
            "width_m": number(run.width),
            "max_strip_plane_angle_error_degrees": number(m.max_quad_angle_error_degrees),
            "acceptable": run.pattern.verdict.is_acceptable(),
            "verdict": run.pattern.verdict.message(),
        },
    })
}
