//! `lamella shade`: a shading system (paper Sec. 6). The site's dates and hours give the light
//! region (Eq. 24); the field is optimised for E_block / E_light (Eq. 25–27) with per-vertex
//! labels; strips are built along its level curves; then the sun-path check casts the hourly
//! sun rays from points just behind the surface through the strips and reports the blocked
//! fraction of the direct-sun hours per region. Exit 3 when a region misses its fraction or when
//! a strip quad misses its curve's θ by more than `--tolerance` (the strips' verdict of `design`).
use crate::args::ShadeArgs;
use crate::config::{check_tolerance, out_of_range, parse_vector, DEFAULT_OUT, MAX_ITERATIONS_LIMIT, MAX_STRIPS};
use crate::error::{CliError, CliResult};
use crate::field_files::field_csv;
use crate::mesh_input::{load_mesh, mesh_name};
use crate::output_dir::OutputDir;
use crate::progress::{note, summary, Verbosity};
use crate::start_field::read_field_for;
use crate::strip_obj::{curves_obj, rulings_obj, strip_name, strips_obj};
use crate::strips_cmd::mean_gradient_norm;
use crate::svg::cut_sheet::{cut_sheet_svg, CutPiece};
use crate::svg::shading::shading_svg;
use crate::svg::sunpath::sunpath_svg;
use lamella::curves::uniform_levels;
use lamella::input::clip;
use lamella::mesh::TriMesh;
use lamella::shading::{
    default_start, most_common_slope, shading_strips, sun_path_check, with_transition_ring, Clock, DateRange, HourRange,
    LightRegion, MonthDay, ShadingParams, ShadingSolver, ShadingStrips, ShadingWeights, Site, StartKind, SunPathEvaluation, SunSample, VertexLabel,
};
use serde_json::{json, Value};
use std::path::PathBuf;
use std::time::Instant;

/// Iterations per `step` between progress notes.
const STEP: usize = 10;
/// Default sample offset behind the surface, as a fraction of the curve spacing.
const OFFSET_PER_SPACING: f64 = 0.05;

fn shading_error(e: lamella::shading::ShadingError) -> CliError {
    CliError::bad_input(format!("shade: {e}"))
}

/// `A..B` as two numbers; errors name the flag.
fn parse_pair(flag: &str, text: &str) -> CliResult<[f64; 2]> {
    let error = || CliError::bad_input(format!("--{flag}: `{}` is not MIN..MAX", clip(text)));
    let (a, b) = text.split_once("..").ok_or_else(error)?;
    let a: f64 = a.trim().parse().map_err(|_| error())?;
    let b: f64 = b.trim().parse().map_err(|_| error())?;
    Ok([a, b])
}

fn parse_hours(flag: &str, text: &str) -> CliResult<HourRange> {
    let [first, last] = parse_pair(flag, text)?;
    Ok(HourRange { first, last })
}

fn parse_dates(text: &str) -> CliResult<DateRange> {
    let error = || CliError::bad_input(format!("--dates: `{}` is not MM-DD..MM-DD", clip(text)));
    let day = |t: &str| -> CliResult<MonthDay> {
        let (m, d) = t.trim().split_once('-').ok_or_else(error)?;
        Ok(MonthDay { month: m.parse().map_err(|_| error())?, day: d.parse().map_err(|_| error())? })
    };
    let (a, b) = text.split_once("..").ok_or_else(error)?;
    Ok(DateRange { first: day(a)?, last: day(b)? })
}

fn check(args: &ShadeArgs) -> CliResult<()> {
    if !(1..=MAX_ITERATIONS_LIMIT).contains(&args.max_iterations) {
        return Err(out_of_range("max-iterations", args.max_iterations, &format!("1 to {MAX_ITERATIONS_LIMIT}")));
    }
    if !(1..=MAX_STRIPS).contains(&args.strips) {
        return Err(out_of_range("strips", args.strips, &format!("1 to {MAX_STRIPS}")));
    }
    for (name, value) in [("min-blocked", args.min_blocked), ("max-blocked-pass", args.max_blocked_pass)] {
        if !(value.is_finite() && (0.0..=1.0).contains(&value)) {
            return Err(out_of_range(name, value, "0 to 1"));
        }
    }
    if args.ring > 100 {
        return Err(out_of_range("ring", args.ring, "0 to 100"));
    }
    check_tolerance(args.tolerance)?;
    Ok(())
}

/// Labels from --mask and --pass (non-zero values select), with the transition ring.
fn labels(mesh: &TriMesh, args: &ShadeArgs) -> CliResult<Vec<VertexLabel>> {
    let read = |path: &PathBuf| read_field_for(mesh, path);
    let block = args.mask.as_ref().map(read).transpose()?;
    let pass = args.pass.as_ref().map(read).transpose()?;
    let labels: Vec<VertexLabel> = (0..mesh.vertex_count())
        .map(|v| match (&block, &pass) {
            (_, Some(pass)) if pass[v] != 0.0 => VertexLabel::Pass,
            (Some(block), _) if block[v] == 0.0 => VertexLabel::Free,
            _ => VertexLabel::Block,
        })
        .collect();
    if labels.iter().all(|&l| l == VertexLabel::Free) {
        return Err(CliError::bad_input("--mask selects no vertex and --pass none either: nothing to shade"));
    }
    with_transition_ring(mesh, &labels, args.ring).map_err(shading_error)
}

pub fn run(args: &ShadeArgs) -> CliResult<()> {
    let started = Instant::now();
    let verbosity = Verbosity::from(args.verbosity);
    check(args)?;
    let clock = Clock { longitude_degrees: args.longitude, time_zone_hours: args.time_zone };
    let site = Site {
        latitude_degrees: args.latitude,
        clock,
        north: parse_vector("--north", &args.north)?,
        up: parse_vector("--up", &args.up)?,
        dates: parse_dates(&args.dates)?,
        hours: parse_hours("hours", &args.hours)?,
    };
    let pass_site = Site { hours: args.pass_hours.as_deref().map(|h| parse_hours("pass-hours", h)).transpose()?.unwrap_or(site.hours), ..site };
    let frame = site.frame().map_err(shading_error)?;
    pass_site.frame().map_err(shading_error)?;
    let width = args.width.as_deref().map(|w| crate::units::length("--width", w)).transpose()?;
    let offset = args.offset.as_deref().map(|w| crate::units::length("--offset", w)).transpose()?;
    let mesh = load_mesh(args.mesh.mesh.as_deref())?;
    let name = mesh_name(args.mesh.mesh.as_deref());
    let labels = labels(&mesh, args)?;
    let block_region = match (&args.delta, &args.gamma) {
        (Some(d), Some(g)) => LightRegion::new(parse_pair("delta", d)?, parse_pair("gamma", g)?),
        _ => LightRegion::of_site(&site),
    }
    .map_err(shading_error)?;
    let pass_region = LightRegion::of_site(&pass_site).map_err(shading_error)?;
    let target: PathBuf = args.out.out.clone().unwrap_or_else(|| PathBuf::from(DEFAULT_OUT));
    let out = OutputDir::create(&target, args.out.force)?;

    let weights = ShadingWeights::for_labels(&labels);
    let params = ShadingParams { pass_region, weights, ..ShadingParams::new(frame, block_region) };
    let (start, start_description) = start_field(&mesh, args, &params, &labels)?;
    let vote = most_common_slope(&mesh, &frame, &block_region);
    let mut solver = ShadingSolver::new(&mesh, &start, &labels, params).map_err(shading_error)?;
    note(
        verbosity,
        &format!(
            "{name}: {} vertices; block region δ {:.1}..{:.1}°, γ {:.1}..{:.1}°; {} block, {} pass vertices",
            mesh.vertex_count(),
            block_region.delta_degrees[0],
            block_region.delta_degrees[1],
            block_region.gamma_degrees[0],
            block_region.gamma_degrees[1],
            labels.iter().filter(|&&l| l == VertexLabel::Block).count(),
            labels.iter().filter(|&&l| l == VertexLabel::Pass).count()
        ),
    );
    while solver.iterations() < args.max_iterations && !solver.is_converged() {
        let report = solver.step(STEP.min(args.max_iterations - solver.iterations())).map_err(|e| CliError::internal(format!("shade: {e}")))?;
        if verbosity == Verbosity::Verbose {
            let e = report.energies;
            note(verbosity, &format!("iteration {}: E_block {:.3e}, E_light {:.3e}, E_fair {:.3e}, E_grad {:.3e}, constraints {:.3e}", report.iterations, e.block, e.light, e.fair, e.grad, e.constraints));
        }
    }
    let field_seconds = started.elapsed().as_secs_f64();
    let field = solver.field();
    let spacing = curve_spacing(&mesh, &field, args.strips)?;
    let width = width.unwrap_or(spacing);
    let strips = shading_strips(&mesh, &field, &solver.binormals(), args.strips, width, args.tolerance).map_err(shading_error)?;
    let offset = offset.unwrap_or(OFFSET_PER_SPACING * spacing);
    let evaluation_started = Instant::now();
    let check = sun_path_check(&mesh, &labels, &strips.pattern.strips, &site, &pass_site, offset).map_err(shading_error)?;
    let evaluation_seconds = evaluation_started.elapsed().as_secs_f64();
    let (block_suns, fractions, block_eval) = (&check.block_suns, &check.vertex_fractions, &check.block);
    let (block_fraction, pass_fraction) = (check.block_fraction(), check.pass_fraction());

    out.write("field.csv", field_csv(&field))?;
    out.write("curves.obj", curves_obj(&strips.curves))?;
    out.write("strips.obj", strips_obj(&strips.pattern))?;
    out.write("rulings.obj", rulings_obj(&strips.pattern))?;
    let pieces: Vec<CutPiece> = strips.pattern.strips.iter().enumerate().map(|(id, s)| CutPiece { name: strip_name(id), unrolling: &s.unrolling, marks: Vec::new() }).collect();
    out.write("unrolled.svg", cut_sheet_svg(&pieces))?;
    out.write("shading.svg", shading_svg(&mesh, fractions, &strips.pattern, &frame, block_suns))?;
    out.write("sunpath.svg", sunpath_svg(&frame, block_suns, &block_eval.sun_fractions, &block_region))?;
    let verdict = verdict(args, block_fraction, pass_fraction, &strips);
    let report = json!({
        "input": name,
        "site": {
            "latitude_degrees": args.latitude, "longitude_degrees": args.longitude, "time_zone_hours": args.time_zone,
            "north": [frame.north().x, frame.north().y, frame.north().z], "dates": args.dates, "hours": args.hours,
            "pass_hours": args.pass_hours.clone().unwrap_or_else(|| args.hours.clone()),
        },
        "light_region": { "block": region_json(&block_region), "pass": region_json(&pass_region) },
        "start": start_description,
        "constant_slope_vote": vote.map(|v| json!({ "slope_degrees": v.slope_degrees, "voting_faces": v.voting_faces, "histogram": v.histogram, "used": start_description["kind"] == "constant slope about the earth axis" })),
        "labels": { "block": count(&labels, VertexLabel::Block), "pass": count(&labels, VertexLabel::Pass), "free": count(&labels, VertexLabel::Free), "ring": args.ring },
        "weights": serde_json::to_value(solver.params().weights).unwrap_or(Value::Null),
        "optimisation": serde_json::to_value(solver.report()).unwrap_or(Value::Null),
        "strips": {
            "count": strips.pattern.strips.len(), "curves": strips.curves.len(), "width_m": number(width), "spacing_m": number(spacing),
            "theta_degrees": strips.thetas.iter().map(|t| t.map_or(Value::Null, number)).collect::<Vec<_>>(),
            "max_strip_plane_angle_error_degrees": number(strips.pattern.metrics.max_quad_angle_error_degrees),
            "verdict": strips_verdict_json(&strips),
        },
        "sun_path": {
            "sample_offset_m": number(offset),
            "block_suns": block_suns.len(), "pass_suns": check.pass_suns.len(), "rays": check.rays(),
            "blocked_fraction": { "block_region": option(block_fraction), "pass_region": option(pass_fraction), "free_block_hours": option(block_eval.regions.free) },
            "per_sun": suns_json(block_suns, block_eval),
            "per_vertex": fractions.iter().map(|f| option(*f)).collect::<Vec<_>>(),
        },
        "verdict": { "min_blocked": args.min_blocked, "max_blocked_pass": args.max_blocked_pass, "tolerance_degrees": args.tolerance, "acceptable": verdict.is_ok(), "message": verdict.as_ref().err().cloned() },
        "timings_seconds": { "field": field_seconds, "evaluation": evaluation_seconds, "total": started.elapsed().as_secs_f64() },
    });
    out.write("report.json", serde_json::to_string_pretty(&report).map_err(|e| CliError::internal(format!("report.json: {e}")))?)?;
    let target = out.target().display().to_string();
    out.commit()?;
    let shown = |f: Option<f64>| f.map_or("–".to_string(), |f| format!("{:.1} %", 100.0 * f));
    summary(
        verbosity,
        &format!(
            "{} iterations{}; {} strips; blocked share of the direct-sun hours: block region {}, pass region {}\ndone in {:.1} s; wrote {target}/ (field.csv, curves.obj, strips.obj, rulings.obj, unrolled.svg, shading.svg, sunpath.svg, report.json)",
            solver.iterations(),
            if solver.is_converged() { ", converged" } else { "" },
            strips.pattern.strips.len(),
            shown(block_fraction),
            shown(pass_fraction),
            started.elapsed().as_secs_f64()
        ),
    )?;
    verdict.map_err(CliError::NoAcceptableFamily)
}

/// The start field and its description: --start-field, --start-direction, or the default.
fn start_field(mesh: &TriMesh, args: &ShadeArgs, params: &ShadingParams, labels: &[VertexLabel]) -> CliResult<(Vec<f64>, Value)> {
    if let Some(path) = &args.start_field {
        return Ok((read_field_for(mesh, path)?, json!({ "kind": "field file", "file": path.display().to_string() })));
    }
    if let Some(text) = &args.start_direction {
        let direction = parse_vector("--start-direction", text)?;
        let values = mesh.positions().iter().map(|p| p.dot(&direction)).collect();
        return Ok((values, json!({ "kind": "height along a direction", "direction": [direction.x, direction.y, direction.z] })));
    }
    let start = default_start(mesh, params, labels);
    let d = start.direction;
    let description = match start.kind {
        StartKind::ConstantSlope { slope_degrees } => json!({ "kind": "constant slope about the earth axis", "slope_degrees": slope_degrees, "axis": [d.x, d.y, d.z] }),
        StartKind::EarthAxisHeight => json!({ "kind": "height along the earth axis", "direction": [d.x, d.y, d.z] }),
        StartKind::AcrossCentralLight => json!({ "kind": "height across the central light", "direction": [d.x, d.y, d.z] }),
    };
    Ok((start.field, description))
}

/// Mean distance between neighbouring level curves of `count` uniform levels.
fn curve_spacing(mesh: &TriMesh, field: &[f64], count: usize) -> CliResult<f64> {
    let levels = uniform_levels(mesh, field, count).map_err(|e| CliError::bad_input(format!("level curves: {e}")))?;
    let step = match levels.as_slice() {
        [a, b, ..] => b - a,
        [a] => a - field.iter().copied().fold(f64::INFINITY, f64::min),
        [] => 0.0,
    };
    let spacing = step / mean_gradient_norm(mesh, field);
    if spacing.is_finite() && spacing > 0.0 {
        Ok(spacing)
    } else {
        Err(CliError::bad_input("the optimised field is constant: no level curves, give --width"))
    }
}

/// The verdict of the sun-path check and of the strips (each quad against its own curve's θ).
fn verdict(args: &ShadeArgs, block: Option<f64>, pass: Option<f64>, strips: &ShadingStrips) -> Result<(), String> {
    let mut misses = Vec::new();
    if let Some(miss) = strips.miss() {
        misses.push(miss);
    }
    if let Some(b) = block.filter(|&b| b < args.min_blocked) {
        misses.push(format!("the block region has {:.1} % of its direct-sun hours blocked, asked at least {:.1} %", 100.0 * b, 100.0 * args.min_blocked));
    }
    if let Some(p) = pass.filter(|&p| p > args.max_blocked_pass) {
        misses.push(format!("the pass region has {:.1} % of its direct-sun hours blocked, asked at most {:.1} %", 100.0 * p, 100.0 * args.max_blocked_pass));
    }
    if misses.is_empty() { Ok(()) } else { Err(format!("no acceptable shading: {}", misses.join("; "))) }
}

/// The strips' verdict in report.json.
fn strips_verdict_json(strips: &ShadingStrips) -> Value {
    let verdict = &strips.pattern.verdict;
    let mut value = serde_json::to_value(verdict).unwrap_or(Value::Null);
    if let Some(object) = value.as_object_mut() {
        object.insert("acceptable".into(), json!(verdict.is_acceptable()));
        object.insert("message".into(), strips.miss().map_or(Value::Null, Value::String));
    }
    value
}

fn count(labels: &[VertexLabel], label: VertexLabel) -> usize {
    labels.iter().filter(|&&l| l == label).count()
}

fn region_json(r: &LightRegion) -> Value {
    json!({ "delta_degrees": r.delta_degrees, "gamma_degrees": r.gamma_degrees })
}

fn suns_json(suns: &[SunSample], evaluation: &SunPathEvaluation) -> Vec<Value> {
    suns.iter()
        .zip(&evaluation.sun_fractions)
        .map(|(s, f)| json!({ "day": s.day, "hour": s.hour, "elevation_degrees": number(s.elevation_degrees), "azimuth_degrees": number(s.azimuth_degrees), "blocked_fraction": option(*f) }))
        .collect()
}

/// JSON has no NaN: non-finite numbers become null.
fn number(x: f64) -> Value {
    if x.is_finite() { json!(x) } else { Value::Null }
}

fn option(x: Option<f64>) -> Value {
    x.map_or(Value::Null, number)
}
