//! `lamella design` (and `lamella` without arguments): the whole pipeline of the paper on one
//! surface: field (Sec. 3.2) → level curves → rectifying strips (Sec. 3.4) → cut sheet, plots and
//! report and the 3D viewer (view.html), into one output directory.
use crate::args::DesignArgs;
use crate::config::{Flags, Settings};
use crate::console::err_line;
use crate::error::{CliError, CliResult};
use crate::fabrication_files::{self, cli_error, overstress_warning, report_section, summary_line};
use crate::field_cmd::{family_measure, field_summary, optimise, write_field_files};
use crate::field_files::HistoryRow;
use crate::mesh_input::{load_mesh, mesh_name};
use crate::output_dir::OutputDir;
use crate::progress::{note, summary, Verbosity};
use crate::report_json::{self, Timings};
use crate::reshape_trial::reshape_trial;
use crate::start_field::start_solver;
use crate::strip_obj::strip_name;
use crate::strips_cmd::{build_strips, strips_summary, warning_lines, write_strip_files, StripRun};
use crate::svg::cut_sheet::{cut_sheet_svg, CutPiece};
use crate::view_cmd::write_view;
use lamella::view::family_name;
use lamella::fabrication::{plan_fabrication, FabricationStrip};
use std::time::Instant;

pub fn run(args: &DesignArgs) -> CliResult<()> {
    let started = Instant::now();
    let verbosity = Verbosity::from(args.verbosity);
    let settings = Settings::resolve(Flags {
        mesh: Some(&args.mesh),
        out: Some(&args.out),
        family: None,
        field: Some(&args.field),
        strips: Some(&args.strips),
        config: Some(&args.config),
        start: Some(&args.start),
    })?;
    // The workshop files' parameters are checked before the long computation.
    let fabrication = fabrication_files::requested(&args.fabrication).then(|| fabrication_files::params(&args.fabrication, Some(settings.theta))).transpose()?;
    let mesh = load_mesh(settings.mesh.as_deref())?;
    let name = mesh_name(settings.mesh.as_deref());
    let out = OutputDir::create(&settings.out, settings.force)?;
    note(
        verbosity,
        &format!("{name}: {} vertices, {} triangles; θ = {}°, {} strips", mesh.vertex_count(), mesh.face_count(), settings.theta, settings.strips),
    );
    let start = start_solver(&mesh, &settings, verbosity)?;
    let theta = start.theta;
    let mut solver = start.solver;
    let mut history = vec![HistoryRow::of(solver.report())];
    optimise(&mut solver, settings.max_iterations, &mut history, verbosity)?;
    let field_seconds = started.elapsed().as_secs_f64();

    let strips_started = Instant::now();
    let run = build_strips(&mesh, &solver.field(), theta, settings.strips, settings.width, settings.tolerance)?;
    let measure = family_measure(&mesh, &solver, &run.curves)?;
    let strips_seconds = strips_started.elapsed().as_secs_f64();
    if verbosity == Verbosity::Verbose {
        warning_lines(&run).iter().for_each(err_line);
    }
    // Only when the verdict fails, and for the angles `reshape` takes: how far the surface would
    // have to move (paper Sec. 3.3).
    let reshapable = theta > 0.0 && theta < 180.0;
    let trial = if run.pattern.verdict.is_acceptable() || !reshapable {
        None
    } else {
        note(verbosity, "the strips miss θ: trying how far the surface would have to move (a short reshape)");
        reshape_trial(&mesh, &solver.field(), theta, settings.strips, settings.width, settings.tolerance).ok()
    };

    let mut surface = Vec::new();
    mesh.write_obj(&mut surface).map_err(|e| CliError::internal(format!("surface.obj: {e}")))?;
    out.write("surface.obj", surface)?;
    write_field_files(&out, &solver, &history)?;
    write_strip_files(&out, &mesh, &run)?;
    let pieces: Vec<CutPiece> =
        run.pattern.strips.iter().enumerate().map(|(id, s)| CutPiece { name: strip_name(id), unrolling: &s.unrolling, marks: Vec::new() }).collect();
    out.write("unrolled.svg", cut_sheet_svg(&pieces))?;
    let plan = match fabrication {
        Some(mut params) => {
            params.theta_degrees = Some(theta);
            let strips: Vec<FabricationStrip> = run.pattern.strips.iter().enumerate().map(|(id, s)| FabricationStrip::from_rectifying(&strip_name(id), s)).collect();
            let plan = plan_fabrication(&strips, &params).map_err(cli_error)?;
            let boundaries: Vec<(&[_], &[_])> = run.pattern.strips.iter().map(|s| (s.left.as_slice(), s.right.as_slice())).collect();
            fabrication_files::write_files(&out, &plan, &boundaries, Some(&mesh))?;
            Some(plan)
        }
        None => None,
    };
    write_view(&out, &name, &mesh, &[(&family_name(theta), &run.curves, &run.pattern.strips)], plan.as_ref())?;
    let timings = Timings { field: field_seconds, strips: strips_seconds, total: started.elapsed().as_secs_f64() };
    let parameters = report_json::parameters(&settings, theta, &name, Some(&start.description));
    let mut report = report_json::document_value(&parameters, Some((&solver, &history, &measure)), Some(&run), &timings);
    if let (Some(plan), Some(root)) = (&plan, report.as_object_mut()) {
        root.insert("fabrication".into(), report_section(plan));
    }
    if let (Some(trial), Some(root)) = (&trial, report.as_object_mut()) {
        root.insert("reshape_trial".into(), trial.to_json());
    }
    out.write("report.json", report_json::pretty(&report))?;
    let target = out.target().display().to_string();
    out.commit()?;
    if let Some(warning) = plan.as_ref().and_then(overstress_warning) {
        if verbosity != Verbosity::Quiet {
            err_line(format!("lamella: warning: {warning}"));
        }
    }
    let workshop = plan.as_ref().map_or(String::new(), |p| format!("{}\n", summary_line(p)));
    let workshop_files = if plan.is_some() { format!(", {}", fabrication_files::FILES) } else { String::new() };
    summary(
        verbosity,
        &format!(
            "{}\n{}\n{workshop}done in {:.1} s (field {field_seconds:.1} s, strips {strips_seconds:.1} s); wrote {target}/ (surface.obj, field.csv, session.bin, energies.csv, curves.obj, strips.obj, rulings.obj, diagnostics.csv, report.json, unrolled.svg, convergence.svg, preview.svg, view.html{workshop_files})",
            field_summary(&solver, &measure),
            strips_summary(&run),
            started.elapsed().as_secs_f64()
        ),
    )?;
    let session = format!("{target}/session.bin");
    verdict(&run).map_err(|error| match error {
        CliError::NoAcceptableFamily(message) => CliError::NoAcceptableFamily(match &trial {
            Some(trial) => format!("{message}; {}", trial.advice(&session, theta)),
            None if reshapable => format!(
                "{message}; if no family of θ = {theta}° exists on this surface, move the surface a little: lamella reshape --session {session} --theta {theta} --tolerance 1%"
            ),
            None => message,
        }),
        other => other,
    })
}

/// Exit code 3 with the verdict's message when the strips miss θ or have flipped quads.
pub fn verdict(run: &StripRun) -> CliResult<()> {
    if run.pattern.verdict.is_acceptable() {
        Ok(())
    } else {
        Err(CliError::NoAcceptableFamily(run.pattern.verdict.message()))
    }
}
