//! `lamella net`: a gridshell net of two curve families (paper Sec. 4.1) or a 3-web of three
//! (Sec. 4.2, optionally as a Kagome pattern): the fields optimised together from the default
//! start, their level curves and rectifying strips per family, the quad net (or the web's
//! triangles, or triangles and hexagons) of their crossings and the nodes where strips cross, and
//! with the fabrication flags the workshop files of every family (nodes marked, splices kept away
//! from them); exit 3 when a family's strips miss their angle (as `design`), two families cross
//! below the minimum, or a web's fields leave Eq. 18.
use crate::args::NetArgs;
use crate::config::DEFAULT_OUT;
use crate::console::err_line;
use crate::error::{CliError, CliResult};
use crate::fabrication_files::{self, cli_error, overstress_warning, report_section, summary_line};
use crate::mesh_input::{load_mesh, mesh_name, read_bytes};
use crate::net_obj::net_obj;
use crate::output_dir::OutputDir;
use crate::progress::{note, summary, Verbosity};
use crate::start_field::read_field_for;
use crate::strip_obj::{curves_obj, strips_obj};
use crate::strips_cmd::{build_strips, build_strips_at, StripRun};
use crate::svg::cut_sheet::{cut_sheet_svg, CutMark, CutPiece};
use crate::svg::preview::preview_svg;
use crate::view_cmd::write_view;
use lamella::fabrication::{plan_fabrication, FabricationStrip};
use lamella::field::Family;
use lamella::initialisation::SearchOptions;
use lamella::mesh::TriMesh;
use lamella::net::{flat_point, net_start_search, strip_net, strip_web, web_levels, NetParams, NetReport, NetSolver, NetStart, Node, QuadNet, StripNet, StripWeb, Web};
use lamella::strips::{PatternMetrics, StripPattern, VertexDiagnostics};
use serde_json::{json, Value};
use std::fmt::Write as _;
use std::path::PathBuf;
use std::time::Instant;

/// Iterations per `step` between progress notes.
const STEP: usize = 10;

/// Parses `--families`: two (a net) or three (a 3-web) comma-separated names, each as
/// [`parse_family`] reads it.
fn parse_families(text: &str) -> CliResult<Vec<Family>> {
    let families: Vec<Family> = text.split(',').map(|name| parse_family("--families", name.trim())).collect::<CliResult<_>>()?;
    if !(2..=3).contains(&families.len()) {
        return Err(CliError::bad_input(format!("--families: a net has two families and a 3-web three, got {} in '{}'", families.len(), lamella::input::clip(text))));
    }
    Ok(families)
}

/// Largest `|F + G + H|` (relative to the fields' range) of an acceptable 3-web: above it the
/// diagonals of the first two families' net are no longer the third family's curves.
const MAX_WEB_RESIDUAL: f64 = 1e-5;

/// What the strips were built on: a net's quads or a web's faces.
enum Built {
    Net(QuadNet),
    Web(Web),
}

/// Parses one family given to `flag` (`--families`, `--types`): `P<θ>` (pseudo-geodesics of
/// angle θ in degrees, in (0, 180)), `G` (geodesics) or `A` (asymptotic curves).
pub fn parse_family(flag: &str, name: &str) -> CliResult<Family> {
    let bad = || CliError::bad_input(format!("{flag}: '{}' is not P<θ>, G or A", lamella::input::clip(name)));
    match name {
        "A" | "a" => Ok(Family::Asymptotic),
        "G" | "g" => Ok(Family::Geodesic),
        _ => {
            let theta: f64 = name.strip_prefix(['P', 'p']).ok_or_else(bad)?.parse().map_err(|_| bad())?;
            if !(theta.is_finite() && theta > 0.0 && theta < 180.0) {
                return Err(CliError::bad_input(format!("{flag}: θ of '{}' must lie in (0°, 180°)", lamella::input::clip(name))));
            }
            Ok(Family::from_theta(theta))
        }
    }
}

/// A family's short name in file names and reports.
pub fn family_label(family: &Family) -> String {
    match family {
        Family::PseudoGeodesic { theta_degrees } => format!("P{theta_degrees}"),
        Family::Geodesic => "G".into(),
        Family::Asymptotic => "A".into(),
        Family::ConstantSlope { slope_degrees, .. } => format!("S{slope_degrees}"),
    }
}

/// How far below `--min-angle` the smallest crossing may fall before the net is refused (exit 3):
/// the minimum angle is held by a penalty (Sec. 4.1), which lets a face sit just under it.
const MIN_ANGLE_SLACK_DEGREES: f64 = 1.0;

/// The net optimisation to run, its surface, the surface's name and the default start it came
/// from (with the seconds its search took): continued from --resume, or new from the default
/// start of --families on --mesh.
fn start(args: &NetArgs) -> CliResult<(NetSolver, TriMesh, String, Option<(NetStart, f64)>)> {
    if let Some(path) = &args.resume {
        let bytes = read_bytes(path)?;
        let solver = NetSolver::from_bytes(&bytes).map_err(|e| CliError::bad_input(format!("{}: not a usable net session: {e}", path.display())))?;
        let mesh = solver.mesh();
        return Ok((solver, mesh, format!("net session {}", path.display()), None));
    }
    // Invariant: clap requires --families unless --resume is given.
    let families = parse_families(args.families.as_deref().ok_or_else(|| CliError::bad_input("give --families"))?)?;
    let mut params = match families[..] {
        [f, h, g] => NetParams::web(f, h, g),
        _ => NetParams::new(families[0], families[1]),
    };
    params.intersection_degrees = args.angle;
    params.min_intersection_degrees = args.min_angle;
    params.validate().map_err(|e| CliError::bad_input(format!("net: {e}")))?;
    let mesh = load_mesh(args.mesh.mesh.as_deref())?;
    let name = mesh_name(args.mesh.mesh.as_deref());
    if !args.start_field.is_empty() {
        let given = if params.is_web() { 2 } else { params.families.len() };
        if args.start_field.len() != given {
            return Err(CliError::bad_input(format!("--start-field: give one per family ({given} for these --families), got {}", args.start_field.len())));
        }
        let fields = args.start_field.iter().map(|path| read_field_for(&mesh, path)).collect::<CliResult<Vec<_>>>()?;
        let solver = NetSolver::new(&mesh, &fields, params).map_err(|e| CliError::bad_input(format!("--start-field: {e}")))?;
        return Ok((solver, mesh, name, None));
    }
    let searched = Instant::now();
    let start = net_start_search(&mesh, &params, &SearchOptions::default()).map_err(|e| CliError::bad_input(format!("start: {e}")))?;
    let solver = NetSolver::new(&mesh, &start.fields, params).map_err(|e| CliError::bad_input(format!("net: {e}")))?;
    Ok((solver, mesh, name, Some((start, searched.elapsed().as_secs_f64()))))
}

/// One line on the default start: the pairs probed and the one continued from.
fn start_line(start: &NetStart, seconds: f64) -> String {
    let on = start.proxy_vertices.map_or(String::new(), |n| format!(" on a {n}-vertex coarsening"));
    let winner = &start.candidates[start.winner];
    let line = format!("start: {} candidate pairs in {seconds:.1} s{on}; continuing from {}", start.candidates.len(), winner.kind.describe());
    match &winner.rejected {
        // A rejected winner is the fallback on nearly straight families.
        Some(reason) => format!(
            "{line}\nwarning: every start pair has a nearly straight family (the best: {reason}); the surface bends little at these angles across the model, so the curves' binormals are weakly defined and the strips' verdict decides; other families or --start-field may do better"
        ),
        None => line,
    }
}

/// report.json's `start`: every candidate pair with its scores, the winner and the time.
fn start_json(start: &NetStart, seconds: f64) -> Value {
    let candidates: Vec<Value> = start
        .candidates
        .iter()
        .map(|c| {
            json!({
                "start": c.kind.describe(),
                "score": c.score.map_or(Value::Null, number),
                "family_scores": c.family_scores.iter().map(|s| s.map_or(Value::Null, number)).collect::<Vec<_>>(),
                "area_below_min_angle": number(c.tangent_area_fraction),
                "rejected": c.rejected,
            })
        })
        .collect();
    let fallback = start.candidates[start.winner].rejected.is_some();
    json!({ "candidates": candidates, "winner": start.winner, "fallback": fallback, "proxy_vertices": start.proxy_vertices, "seconds": number(seconds) })
}

pub fn run(args: &NetArgs) -> CliResult<()> {
    let started = Instant::now();
    let verbosity = Verbosity::from(args.verbosity);
    let fabrication = fabrication_files::requested(&args.fabrication).then(|| fabrication_files::params(&args.fabrication, None)).transpose()?;
    let (mut solver, mesh, name, searched) = start(args)?;
    if args.kagome && !solver.params().is_web() {
        return Err(CliError::bad_input("--kagome: a Kagome pattern needs three --families (a 3-web)"));
    }
    let families = solver.params().families.clone();
    let target: PathBuf = args.out.out.clone().unwrap_or_else(|| PathBuf::from(DEFAULT_OUT));
    let out = OutputDir::create(&target, args.out.force)?;
    let labels: Vec<String> = families.iter().map(family_label).collect();
    note(verbosity, &format!("{name}: {} vertices; net {}, from iteration {}", mesh.vertex_count(), labels.join(", "), solver.iterations()));
    if let Some((start, seconds)) = &searched {
        note(verbosity, &start_line(start, *seconds));
    }
    while solver.iterations() < args.max_iterations && !solver.is_converged() {
        let report = solver.step(STEP.min(args.max_iterations - solver.iterations())).map_err(|e| CliError::internal(format!("net solve: {e}")))?;
        if verbosity == Verbosity::Verbose {
            note(verbosity, &progress_line(&report));
        }
    }
    let field_seconds = started.elapsed().as_secs_f64();

    let strips_started = Instant::now();
    let fields = solver.fields();
    let (runs, built, nodes) = if solver.params().is_web() {
        let levels = web_levels(&mesh, &fields[0], &fields[1], &fields[2], [args.lines, args.lines], args.kagome).map_err(|e| CliError::bad_input(format!("web levels: {e}")))?;
        let runs: Vec<StripRun> = families
            .iter()
            .zip(&fields)
            .zip(&levels.levels)
            .map(|((family, field), levels)| build_strips_at(&mesh, field, family.theta_degrees(), levels, args.width, args.tolerance))
            .collect::<CliResult<_>>()?;
        let patterns = [&runs[0].pattern, &runs[1].pattern, &runs[2].pattern];
        let StripWeb { web, nodes } = strip_web(&mesh, [&fields[0], &fields[1], &fields[2]], levels, patterns).map_err(|e| CliError::internal(format!("web: {e}")))?;
        (runs, Built::Web(web), nodes)
    } else {
        let runs: Vec<StripRun> = families
            .iter()
            .zip(&fields)
            .map(|(family, field)| build_strips(&mesh, field, family.theta_degrees(), args.lines, args.width, args.tolerance))
            .collect::<CliResult<_>>()?;
        // The same net and nodes as the C ABI's and C#'s: at the levels that carry strips.
        let StripNet { net, nodes } = strip_net(&mesh, &fields[0], &fields[1], [&runs[0].pattern, &runs[1].pattern]).map_err(|e| CliError::internal(format!("net: {e}")))?;
        (runs, Built::Net(net), nodes)
    };
    let strips_seconds = strips_started.elapsed().as_secs_f64();

    for (k, run) in runs.iter().enumerate() {
        out.write(&format!("curves_{k}.obj"), curves_obj(&run.curves))?;
        out.write(&format!("strips_{k}.obj"), strips_obj(&run.pattern))?;
    }
    out.write("net.obj", crossings_obj(&built))?;
    out.write("net.bin", solver.to_bytes())?;
    out.write("nodes.csv", nodes_csv(&nodes))?;
    out.write("unrolled.svg", cut_sheet_svg(&cut_pieces(&runs, &nodes)))?;
    out.write("preview.svg", preview_svg(&mesh, &merged(&runs)))?;
    let plan = match fabrication {
        Some(params) => {
            let plan = plan_fabrication(&fabrication_strips(&families, &runs, &nodes), &params).map_err(cli_error)?;
            let boundaries: Vec<(&[_], &[_])> = runs.iter().flat_map(|r| r.pattern.strips.iter().map(|s| (s.left.as_slice(), s.right.as_slice()))).collect();
            fabrication_files::write_files(&out, &plan, &boundaries, Some(&mesh))?;
            Some(plan)
        }
        None => None,
    };
    let view_families: Vec<(&str, &[_], &[_])> = labels.iter().zip(&runs).map(|(label, run)| (label.as_str(), run.curves.as_slice(), run.pattern.strips.as_slice())).collect();
    write_view(&out, &name, &mesh, &view_families, plan.as_ref())?;
    let mut report = report_json(&name, &labels, &solver, &runs, &built, &nodes, [field_seconds, strips_seconds, started.elapsed().as_secs_f64()]);
    if let (Some(plan), Some(root)) = (&plan, report.as_object_mut()) {
        root.insert("fabrication".into(), report_section(plan));
    }
    if let (Some((start, seconds)), Some(root)) = (&searched, report.as_object_mut()) {
        root.insert("start".into(), start_json(start, *seconds));
    }
    out.write("report.json", serde_json::to_string_pretty(&report).map_err(|e| CliError::internal(format!("report.json: {e}")))?)?;
    let target = out.target().display().to_string();
    out.commit()?;
    if let Some(warning) = plan.as_ref().and_then(overstress_warning) {
        if verbosity != Verbosity::Quiet {
            err_line(format!("lamella: warning: {warning}"));
        }
    }
    let r = solver.report();
    let family_lines: Vec<String> = runs
        .iter()
        .zip(&labels)
        .map(|(run, label)| format!("{label}: {} strips, strip planes max angle error {:.3}°", run.pattern.strips.len(), run.pattern.metrics.max_quad_angle_error_degrees))
        .collect();
    summary(
        verbosity,
        &format!(
            "{} iterations{}; intersection angle min {:.1}°, mean {:.1}°\n{}\n{}; {} nodes\n{}done in {:.1} s; wrote {target}/ (curves_<k>.obj, strips_<k>.obj, net.obj, nodes.csv, unrolled.svg, preview.svg, view.html, report.json{})",
            r.iterations,
            if r.converged { ", converged" } else { "" },
            r.intersection.min_degrees,
            r.intersection.mean_degrees,
            family_lines.join("\n"),
            built_line(&built),
            nodes.len(),
            plan.as_ref().map_or(String::new(), |p| format!("{}\n", summary_line(p))),
            started.elapsed().as_secs_f64(),
            if plan.is_some() { format!(", {}", fabrication_files::FILES) } else { String::new() }
        ),
    )?;
    let mut missed: Vec<String> =
        runs.iter().zip(&labels).filter(|(run, _)| !run.pattern.verdict.is_acceptable()).map(|(run, label)| format!("family {label}: {}", run.pattern.verdict.message())).collect();
    let min_angle = solver.params().min_intersection_degrees;
    let pairs = std::iter::once(("the first two families", &r.intersection))
        .chain(r.web.iter().flat_map(|w| [("the third family and the first", &w.intersections[0]), ("the third family and the second", &w.intersections[1])]));
    for (pair, crossing) in pairs {
        if crossing.min_degrees < min_angle - MIN_ANGLE_SLACK_DEGREES {
            missed.push(format!(
                "{pair} cross at {:.1}° (below the minimum {min_angle:.1}° on {} faces); try a smaller --min-angle, other families or another start",
                crossing.min_degrees, crossing.faces_below_min
            ));
        }
    }
    if let Some(web) = r.web.filter(|w| w.residual_max > MAX_WEB_RESIDUAL) {
        missed.push(format!("the fields leave F + G + H = 0 by {:.1e} of their range (above {MAX_WEB_RESIDUAL:e}): the third family is not the diagonals", web.residual_max));
    }
    if missed.is_empty() {
        Ok(())
    } else {
        Err(CliError::NoAcceptableFamily(missed.join("; ")))
    }
}

fn progress_line(r: &NetReport) -> String {
    let errors: Vec<String> = r.families.iter().map(|f| format!("{:.3}° RMS", f.angle_error_rms_degrees)).collect();
    let web = r.web.map_or(String::new(), |w| format!(", F + G + H {:.1e}", w.residual_max));
    format!("iteration {}: energy {:.3e}, angle errors {}, intersection min {:.1}°{web}", r.iterations, r.total_energy, errors.join(" / "), r.intersection.min_degrees)
}

/// The summary line of what the strips were built on.
fn built_line(built: &Built) -> String {
    match built {
        Built::Net(net) => format!("net: {} vertices, {} quads", net.vertices.len(), net.quads.len()),
        Built::Web(web) => {
            let hexagons = web.faces.iter().filter(|f| f.len() == 6).count();
            let kind = if web.levels.kagome { "Kagome pattern" } else { "3-web" };
            format!("{kind}: {} vertices, {} triangles, {hexagons} hexagons", web.vertices.len(), web.faces.len() - hexagons)
        }
    }
}

/// The Sec. 5.1 columns of a nodes.csv, for the strips of both families.
pub fn diagnostics_header() -> String {
    (0..2).map(|k| format!(",conical_curvature_{k},darboux_angle_degrees_{k},binormal_offset_{k},singular_point_near_{k}")).collect()
}

/// One strip's Sec. 5.1 cells at a node ([`diagnostics_header`]), empty where undefined or
/// where no strip passes.
pub fn diagnostics_cells(d: Option<&VertexDiagnostics>) -> String {
    let cell = |value: Option<f64>| value.map_or(String::new(), |v| v.to_string());
    match d {
        Some(d) => format!(",{},{},{},{}", cell(d.conical_curvature), cell(d.darboux_angle_degrees), cell(d.binormal_offset), u8::from(d.singular_point_near)),
        None => ",,,,".into(),
    }
}

/// The name of strip `id` of family `k` in every output.
fn net_strip_name(k: usize, id: usize) -> String {
    format!("f{k}_strip_{id}")
}

/// Both families' strips in one pattern (for the preview).
fn merged(runs: &[StripRun]) -> StripPattern {
    let strips: Vec<_> = runs.iter().flat_map(|r| r.pattern.strips.iter().cloned()).collect();
    let metrics = PatternMetrics::from_strips(strips.iter().map(|s| &s.metrics));
    StripPattern { strips, skipped: Vec::new(), metrics, verdict: runs[0].pattern.verdict.clone() }
}

/// The nodes on strip `id` of family `k`, each with the side (0 or 1) the strip takes in it.
fn nodes_on(nodes: &[Node], k: usize, id: usize) -> impl Iterator<Item = (&Node, usize)> {
    nodes.iter().filter_map(move |n| (0..2).find(|&side| n.families[side] == k && n.strips[side] == id).map(|side| (n, side)))
}

/// Every family's strips for the workshop, named as in every output, each with its family's θ
/// and the arc lengths of its nodes (which splices avoid and the cut files mark).
fn fabrication_strips(families: &[Family], runs: &[StripRun], nodes: &[Node]) -> Vec<FabricationStrip> {
    let mut strips = Vec::new();
    for (k, (family, run)) in families.iter().zip(runs).enumerate() {
        for (id, strip) in run.pattern.strips.iter().enumerate() {
            let mut input = FabricationStrip::from_rectifying(&net_strip_name(k, id), strip);
            input.nodes = nodes_on(nodes, k, id).map(|(n, side)| n.arc_lengths[side]).collect();
            input.theta_degrees = Some(family.theta_degrees());
            strips.push(input);
        }
    }
    strips
}

/// Every flat strip with a mark at each of its nodes, labelled with the crossing strip's name.
fn cut_pieces<'a>(runs: &'a [StripRun], nodes: &[Node]) -> Vec<CutPiece<'a>> {
    let mut pieces = Vec::new();
    for (k, run) in runs.iter().enumerate() {
        for (id, strip) in run.pattern.strips.iter().enumerate() {
            let marks = nodes_on(nodes, k, id)
                .filter_map(|(n, side)| flat_point(&strip.unrolling.centre, n.arc_lengths[side]).map(|at| CutMark { at, label: net_strip_name(n.families[1 - side], n.strips[1 - side]) }))
                .collect();
            pieces.push(CutPiece { name: net_strip_name(k, id), unrolling: &strip.unrolling, marks });
        }
    }
    pieces
}

/// net.obj: the crossings as vertices, the quads (a web's triangles and hexagons) as faces, each
/// family's polylines as `l` polylines.
fn crossings_obj(built: &Built) -> String {
    match built {
        Built::Net(net) => {
            let positions: Vec<_> = net.vertices.iter().map(|v| v.position).collect();
            net_obj("lamella net: vertex (i, j) = crossing of level i of field 0 with level j of field 1", &positions, &net.quads, &[("rows", &net.rows), ("columns", &net.columns)])
        }
        Built::Web(web) => {
            let positions: Vec<_> = web.vertices.iter().map(|v| v.position).collect();
            let [rows, columns, diagonals] = web.polylines.each_ref().map(|family| family.iter().map(|(_, line)| line.clone()).collect::<Vec<_>>());
            let title = if web.levels.kagome {
                "lamella net: Kagome pattern; rows, columns and diagonals are the three families' curves, crossing in pairs"
            } else {
                "lamella net: 3-web; rows = levels of field 0, columns = levels of field 1, diagonals = levels of field 2 (i + j = const)"
            };
            net_obj(title, &positions, &web.faces, &[("rows", &rows), ("columns", &columns), ("diagonals", &diagonals)])
        }
    }
}

/// nodes.csv: one row per node.
fn nodes_csv(nodes: &[Node]) -> String {
    let mut text = String::from("strip_0,strip_1,arc_length_0,arc_length_1,x,y,z,axis_x,axis_y,axis_z,ruling_angle_degrees");
    text.push_str(&diagnostics_header());
    text.push('\n');
    for n in nodes {
        let (p, a) = (n.position, n.axis);
        let _ = write!(
            text,
            "{},{},{},{},{},{},{},{},{},{},{}",
            net_strip_name(n.families[0], n.strips[0]),
            net_strip_name(n.families[1], n.strips[1]),
            n.arc_lengths[0],
            n.arc_lengths[1],
            p.x,
            p.y,
            p.z,
            a.x,
            a.y,
            a.z,
            n.ruling_angle_degrees
        );
        for d in &n.diagnostics {
            text.push_str(&diagnostics_cells(Some(d)));
        }
        text.push('\n');
    }
    text
}

/// JSON has no NaN: non-finite numbers become null.
fn number(x: f64) -> Value {
    if x.is_finite() { json!(x) } else { Value::Null }
}

fn report_json(mesh: &str, labels: &[String], solver: &NetSolver, runs: &[StripRun], built: &Built, nodes: &[Node], seconds: [f64; 3]) -> Value {
    let r = solver.report();
    let families: Vec<Value> = labels
        .iter()
        .zip(runs)
        .zip(&r.families)
        .map(|((label, run), f)| {
            let m = &run.pattern.metrics;
            json!({
                "family": label,
                "e_angle": number(f.energies.angle),
                "e_fair": number(f.energies.fair),
                "e_grad": number(f.energies.grad),
                "angle_error_rms_degrees": number(f.angle_error_rms_degrees),
                "angle_error_max_degrees": number(f.angle_error_max_degrees),
                "singular_vertices": f.singular_vertices.len(),
                "strips": run.pattern.strips.len(),
                "strip_width_m": number(run.width),
                "max_strip_plane_angle_error_degrees": number(m.max_quad_angle_error_degrees),
                "acceptable": run.pattern.verdict.is_acceptable(),
            })
        })
        .collect();
    let ruling_angles: Vec<f64> = nodes.iter().map(|n| n.ruling_angle_degrees).collect();
    let max_ruling = ruling_angles.iter().copied().fold(0.0, f64::max);
    let mean_ruling = if ruling_angles.is_empty() { 0.0 } else { ruling_angles.iter().sum::<f64>() / ruling_angles.len() as f64 };
    let crossing = |c: &lamella::net::IntersectionReport| json!({ "min_degrees": number(c.min_degrees), "mean_degrees": number(c.mean_degrees), "faces_below_min": c.faces_below_min });
    let (net, web) = match built {
        Built::Net(net) => (json!({ "vertices": net.vertices.len(), "quads": net.quads.len(), "rows": net.rows.len(), "columns": net.columns.len() }), Value::Null),
        Built::Web(web) => {
            let w = r.web.unwrap_or_default();
            let hexagons = web.faces.iter().filter(|f| f.len() == 6).count();
            let value = json!({
                "kagome": web.levels.kagome,
                "pace": number(web.levels.pace),
                "vertices": web.vertices.len(),
                "triangles": web.faces.len() - hexagons,
                "hexagons": hexagons,
                "polylines": web.polylines.iter().map(Vec::len).collect::<Vec<_>>(),
                "residual_max": number(w.residual_max),
                "residual_rms": number(w.residual_rms),
                "third_family_factor": number(w.third_family_factor),
                "third_with_first": crossing(&w.intersections[0]),
                "third_with_second": crossing(&w.intersections[1]),
            });
            (Value::Null, value)
        }
    };
    json!({
        "mesh": mesh,
        "iterations": r.iterations,
        "converged": r.converged,
        "families": families,
        "intersection": {
            "target_degrees": solver.params().intersection_degrees,
            "min_asked_degrees": solver.params().min_intersection_degrees,
            "min_degrees": number(r.intersection.min_degrees),
            "mean_degrees": number(r.intersection.mean_degrees),
            "faces_below_min": r.intersection.faces_below_min,
        },
        "net": net,
        "web": web,
        "nodes": { "count": nodes.len(), "mean_ruling_angle_degrees": number(mean_ruling), "max_ruling_angle_degrees": number(max_ruling) },
        "timings_seconds": { "field": seconds[0], "strips": seconds[1], "total": seconds[2] },
    })
}
