//! `lamella optimise`: the base-mesh optimisation of paper Sec. 3.5 on the net.obj of `net`: its
//! rows and columns made into the asked families exactly near the reference surface, with
//! `--torsion-free` also a ruling shared by both strips at every node (Sec. 5.2.1, Eq. 21); the
//! strips of the optimised net, its nodes, the session (optimise.bin, continued by `--resume`) and
//! a report measured against the reference; exit 3 when a family misses its angle or the nodes
//! are not torsion-free as asked.
use crate::args::OptimiseArgs;
use crate::config::DEFAULT_OUT;
use crate::error::{CliError, CliResult};
use crate::mesh_input::{load_mesh, mesh_name, read_bytes};
use crate::config::parse_vector;
use crate::net_cmd::{diagnostics_cells, diagnostics_header, family_label, parse_family};
use crate::net_obj::{net_obj, read_net_obj};
use crate::output_dir::OutputDir;
use crate::progress::{note, summary, Verbosity};
use crate::strip_obj::strips_obj;
use lamella::base_mesh::{BaseMeshParams, BaseMeshReport, BaseMeshSolver, BaseMeshWeights, NetMesh, NodeRuling, TORSION_FREE_DEGREES};
use lamella::field::Family;
use lamella::mesh::Vec3;
use lamella::strips::{StripPattern, VertexDiagnostics};
use serde_json::json;
use std::fmt::Write as _;
use std::path::PathBuf;
use std::time::Instant;

/// Iterations per `step` between progress notes.
const STEP: usize = 10;

/// The optimisation to run, and how the report names its net and its reference: continued from
/// --resume, or new from --net, --types and --torsion-free near --reference.
fn start(args: &OptimiseArgs) -> CliResult<(BaseMeshSolver, String, String)> {
    if let Some(path) = &args.resume {
        let bytes = read_bytes(path)?;
        let solver = BaseMeshSolver::from_bytes(&bytes).map_err(|e| CliError::bad_input(format!("{}: not a usable base-mesh session: {e}", path.display())))?;
        let name = format!("base-mesh session {}", path.display());
        return Ok((solver, name.clone(), name));
    }
    // Invariant: clap requires --net and --types unless --resume is given.
    let families = parse_types(args.types.as_deref().ok_or_else(|| CliError::bad_input("give --types"))?, args.axis.as_deref())?;
    let path = args.net.as_deref().ok_or_else(|| CliError::bad_input("give --net"))?;
    let net = read_net_obj(path)?;
    let reference = load_mesh(args.reference.as_deref())?;
    let mut params = match families[..] {
        [rows, columns, diagonals] => BaseMeshParams::web(rows, columns, diagonals),
        _ => BaseMeshParams::new(families[0], families[1]),
    };
    params.torsion_free = args.torsion_free;
    params.tolerance_degrees = args.tolerance;
    if let Some(weights) = &args.weights {
        params.weights = parse_weights(weights)?;
    }
    let solver = BaseMeshSolver::new(&net, &reference, params).map_err(|e| CliError::bad_input(format!("optimise: {e}")))?;
    Ok((solver, path.display().to_string(), mesh_name(args.reference.as_deref())))
}

/// The weights of `--weights`: `name=value` pairs over the defaults, each name once.
fn parse_weights(text: &str) -> CliResult<BaseMeshWeights> {
    let mut weights = BaseMeshWeights::default();
    let mut seen = Vec::new();
    for pair in text.split(',') {
        let bad = |message: String| CliError::bad_input(format!("--weights: {message}"));
        let (name, value) = pair.split_once('=').ok_or_else(|| bad(format!("`{pair}` is not name=value")))?;
        let name = name.trim();
        let value: f64 = value.trim().parse().map_err(|_| bad(format!("{name}: `{}` is not a number", value.trim())))?;
        let slot = match name {
            "curve" => &mut weights.curve,
            "fair" => &mut weights.fair,
            "close" => &mut weights.close,
            "pull" => &mut weights.pull,
            "torsion" => &mut weights.torsion,
            other => return Err(bad(format!("unknown weight `{other}` (curve, fair, close, pull, torsion)"))),
        };
        if seen.contains(&name) {
            return Err(bad(format!("{name} is given twice")));
        }
        seen.push(name);
        *slot = value;
    }
    Ok(weights)
}

pub fn run(args: &OptimiseArgs) -> CliResult<()> {
    let started = Instant::now();
    let verbosity = Verbosity::from(args.verbosity);
    if !(args.tolerance.is_finite() && args.tolerance > 0.0 && args.tolerance < 90.0) {
        return Err(CliError::bad_input(format!("--tolerance: must lie in (0°, 90°), got {}", args.tolerance)));
    }
    if let Some(width) = args.width.filter(|w| !(w.is_finite() && *w > 0.0)) {
        return Err(CliError::bad_input(format!("--width: must be finite and > 0, got {width}")));
    }
    let (mut solver, net_name, name) = start(args)?;
    let params = solver.params().clone();
    let (tolerance, torsion_free) = (params.tolerance_degrees, params.torsion_free);
    let given = solver.given_net();
    let width = args.width.unwrap_or_else(|| 0.5 * mean_segment(given));
    let target: PathBuf = args.out.out.clone().unwrap_or_else(|| PathBuf::from(DEFAULT_OUT));
    let out = OutputDir::create(&target, args.out.force)?;
    let labels: Vec<String> = params.families.iter().map(family_label).collect();
    let diagonals = if given.family_count() == 3 { format!(", {} diagonals", given.diagonals().len()) } else { String::new() };
    note(verbosity, &format!("{net_name}: {} vertices, {} rows, {} columns{diagonals}; {} near {name}{}", given.vertex_count(), given.rows().len(), given.columns().len(), labels.join(", "), if torsion_free { ", torsion-free nodes" } else { "" }));
    note(verbosity, &progress_line(solver.report()));
    while solver.iterations() < args.max_iterations && !solver.is_converged() {
        let report = solver.step(STEP.min(args.max_iterations - solver.iterations())).map_err(|e| CliError::internal(format!("optimise: {e}")))?;
        if verbosity == Verbosity::Verbose {
            note(verbosity, &progress_line(&report));
        }
    }
    let strips = solver.strips(width, tolerance).map_err(|e| CliError::internal(format!("strips: {e}")))?;
    let optimised = solver.net();
    let net_text = if optimised.family_count() == 3 {
        let families = [("rows", optimised.rows()), ("columns", optimised.columns()), ("diagonals", optimised.diagonals())];
        net_obj("lamella optimise: the optimised web (its triangles; a Kagome pattern's hexagons are not written)", optimised.positions(), &optimised.triangles(), &families)
    } else {
        net_obj("lamella optimise: the optimised net", optimised.positions(), &optimised.quads(), &[("rows", optimised.rows()), ("columns", optimised.columns())])
    };
    out.write("net.obj", net_text)?;
    for (k, pattern) in strips.iter().enumerate() {
        out.write(&format!("strips_{k}.obj"), strips_obj(pattern))?;
    }
    out.write("optimise.bin", solver.to_bytes())?;
    out.write("nodes.csv", nodes_csv(&optimised, solver.nodes(), &strips))?;
    let report = solver.report().clone();
    let json = json!({
        "net": net_name,
        "reference": name,
        "families": labels,
        "torsion_free_asked": torsion_free,
        "tolerance_degrees": tolerance,
        "weights": params.weights,
        "width": width,
        "initial": solver.initial_report(),
        "final": &report,
        "strips": strips.iter().map(|p| json!({ "count": p.strips.len(), "skipped": p.skipped.len(), "metrics": p.metrics, "verdict": p.verdict.message() })).collect::<Vec<_>>(),
        "seconds": started.elapsed().as_secs_f64(),
    });
    out.write("report.json", serde_json::to_string_pretty(&json).map_err(|e| CliError::internal(format!("report.json: {e}")))?)?;
    let target = out.target().display().to_string();
    out.commit()?;
    summary(
        verbosity,
        &format!(
            "{} iterations{}\n{}\n{}done in {:.1} s; wrote {target}/ (net.obj, optimise.bin, strips_<k>.obj, nodes.csv, report.json)",
            report.iterations,
            if report.converged { ", converged" } else { "" },
            outcome_lines(&labels, solver.initial_report(), &report, &strips),
            if torsion_free { "" } else { "(node torsion as it stands; --torsion-free asks for 0)\n" },
            started.elapsed().as_secs_f64()
        ),
    )?;
    let mut missed = Vec::new();
    for (k, family) in report.families.iter().enumerate() {
        if family.max_error_degrees > tolerance || family.straight > 0 {
            let at = family.worst.map_or(String::new(), |w| format!(" (worst at ({:.3}, {:.3}, {:.3}))", w.point[0], w.point[1], w.point[2]));
            missed.push(format!("family {} misses {:.1}° by up to {:.2}°{at}, {} straight vertices", labels[k], report.targets_degrees[k], family.max_error_degrees, family.straight));
        }
    }
    if torsion_free && !report.torsion_free_stage {
        missed.push("the families did not settle, so the torsion-free nodes were not started".into());
    } else if torsion_free && !report.torsion_free {
        missed.push(format!("nodes are not torsion-free: rulings up to {:.2}° apart (at vertex {}; {TORSION_FREE_DEGREES}° allowed)", report.node_torsion.max_degrees, report.node_torsion.worst_vertex.map_or("-".into(), |v| v.to_string())));
    }
    if missed.is_empty() {
        Ok(())
    } else {
        Err(CliError::NoAcceptableFamily(format!("{}; try more --max-iterations, a larger --tolerance, other families or a finer net", missed.join("; "))))
    }
}

/// `--types`: two names (a net) or three (a web: rows, columns, diagonals), each as
/// `net --families` takes them or `S<β>`, a constant slope β about
/// `axis` (`--axis`, default the z axis).
fn parse_types(text: &str, axis: Option<&str>) -> CliResult<Vec<Family>> {
    let axis = match axis {
        Some(text) => parse_vector("--axis", text)?,
        None => Vec3::z(),
    };
    if axis.norm() == 0.0 {
        return Err(CliError::bad_input("--axis: must not be zero"));
    }
    let names: Vec<&str> = text.split(',').map(str::trim).collect();
    if !(2..=3).contains(&names.len()) {
        return Err(CliError::bad_input(format!("--types: a net has two families and a web three, got {} in '{}'", names.len(), lamella::input::clip(text))));
    }
    names
        .into_iter()
        .map(|name| match name.strip_prefix(['S', 's']) {
            Some(slope) => {
                let bad = || CliError::bad_input(format!("--types: the slope of '{}' must be a number in (−90°, 90°)", lamella::input::clip(name)));
                let slope_degrees: f64 = slope.parse().map_err(|_| bad())?;
                if !(slope_degrees.is_finite() && slope_degrees.abs() < 90.0) {
                    return Err(bad());
                }
                Ok(Family::ConstantSlope { axis: [axis.x, axis.y, axis.z], slope_degrees, free_slope: false })
            }
            None => parse_family("--types", name),
        })
        .collect()
}

fn mean_segment(net: &NetMesh) -> f64 {
    let lengths: Vec<f64> = (0..net.family_count()).flat_map(|k| net.segments(k).map(|[a, b]| (net.positions()[b as usize] - net.positions()[a as usize]).norm()).collect::<Vec<_>>()).collect();
    lengths.iter().sum::<f64>() / lengths.len().max(1) as f64
}

fn progress_line(r: &BaseMeshReport) -> String {
    let errors: Vec<String> = r.families.iter().map(|f| format!("{:.3}° max", f.max_error_degrees)).collect();
    format!(
        "iteration {}: energy {:.3e}, angle errors {}, node rulings up to {:.2}° apart, {:.3} % of the diagonal from the reference",
        r.iterations,
        r.energy,
        errors.join(" / "),
        r.node_torsion.max_degrees,
        r.deviation.max_percent
    )
}

/// Per family: the angle error before and after and its strips; then the nodes and the deviation.
fn outcome_lines(labels: &[String], initial: &BaseMeshReport, last: &BaseMeshReport, strips: &[StripPattern]) -> String {
    let mut text = String::new();
    for (k, label) in labels.iter().enumerate() {
        let _ = writeln!(
            text,
            "{label} (held at {:.2}°): angle error max {:.3}° → {:.3}°, RMS {:.3}° → {:.3}°; {} strips, strip planes max angle error {:.3}°",
            last.targets_degrees[k],
            initial.families[k].max_error_degrees,
            last.families[k].max_error_degrees,
            initial.families[k].rms_error_degrees,
            last.families[k].rms_error_degrees,
            strips[k].strips.len(),
            strips[k].metrics.max_quad_angle_error_degrees
        );
    }
    let _ = write!(
        text,
        "{} nodes: rulings apart max {:.2}° → {:.2}°, RMS {:.2}° → {:.2}°; farthest vertex {:.4} % of the diagonal from the reference",
        last.node_torsion.nodes,
        initial.node_torsion.max_degrees,
        last.node_torsion.max_degrees,
        initial.node_torsion.rms_degrees,
        last.node_torsion.rms_degrees,
        last.deviation.max_percent
    );
    text
}

/// nodes.csv: one row per vertex inside a row and a column, with the row's and the column's
/// strip's Sec. 5.1 diagnostics there (the node is a vertex of both strips' centre lines).
fn nodes_csv(net: &NetMesh, nodes: &[NodeRuling], strips: &[StripPattern]) -> String {
    let mut text = String::from("vertex,x,y,z,ruling_angle_degrees,axis_x,axis_y,axis_z");
    text.push_str(&diagnostics_header());
    text.push('\n');
    let cell = |value: Option<f64>| value.map_or(String::new(), |v| v.to_string());
    // Per family and vertex: its strip's diagnostics there.
    let diagnostics: [Vec<Option<VertexDiagnostics>>; 2] = [0, 1].map(|k| {
        let mut at = vec![None; net.vertex_count()];
        for strip in &strips[k].strips {
            for (&v, d) in net.polylines(k)[strip.curve].iter().zip(strip.diagnostics()) {
                at[v as usize] = Some(d);
            }
        }
        at
    });
    for node in nodes {
        let p = net.positions()[node.vertex];
        let axis = node.axis.map(|a| [a.x, a.y, a.z]);
        let _ = write!(
            text,
            "{},{},{},{},{},{},{},{}",
            node.vertex,
            p.x,
            p.y,
            p.z,
            cell(node.angle_degrees),
            cell(axis.map(|a| a[0])),
            cell(axis.map(|a| a[1])),
            cell(axis.map(|a| a[2]))
        );
        for family in &diagnostics {
            text.push_str(&diagnostics_cells(family[node.vertex].as_ref()));
        }
        text.push('\n');
    }
    text
}
