//! `lamella surface KIND`: a built-in surface as surface.obj, with the Brauner surface's exact
//! asymptotic u-lines (paper Sec. 5.2.4, Eq. 23, Fig. 32) as asymptotic.obj.
use crate::args::SurfaceArgs;
use crate::config::DEFAULT_OUT;
use crate::error::{CliError, CliResult};
use crate::mesh_input::ROOF_VERTICES;
use crate::output_dir::OutputDir;
use crate::progress::{summary, Verbosity};
use crate::report_json::pretty;
use crate::strip_obj::curves_obj;
use lamella::curves::LevelCurve;
use lamella::mesh::TriMesh;
use lamella::surfaces::{brauner_point, brauner_slope_degrees, brauner_surface, hall_roof, BraunerSurface, PaperHeatSolution};
use serde_json::{json, Value};
use std::path::PathBuf;

/// Most vertices a built-in surface is generated with.
const MAX_VERTICES: usize = 1_000_000;
/// Default number of u-lines in asymptotic.obj.
const DEFAULT_LINES: usize = 11;
/// Most u-lines in asymptotic.obj.
const MAX_LINES: usize = 1000;
/// Points per u-line.
const LINE_POINTS: usize = 200;

pub fn run(args: &SurfaceArgs) -> CliResult<()> {
    let verbosity = Verbosity::from(args.verbosity);
    let vertices = args.vertices.unwrap_or(ROOF_VERTICES);
    if !(100..=MAX_VERTICES).contains(&vertices) {
        return Err(CliError::bad_input(format!("--vertices must lie in 100..={MAX_VERTICES}, got {vertices}")));
    }
    if args.kind != "brauner" && (args.mu.is_some() || args.lines.is_some()) {
        return Err(CliError::bad_input(format!("--mu and --lines belong to the brauner surface, not {}", args.kind)));
    }
    let target = args.out.out.clone().unwrap_or_else(|| PathBuf::from(DEFAULT_OUT));
    let (mesh, lines, mut report) = match args.kind.as_str() {
        "brauner" => brauner(args, vertices)?,
        _ => {
            let mesh = hall_roof(vertices).into_mesh().map_err(|e| CliError::internal(format!("hall roof: {e}")))?;
            (mesh, Vec::new(), json!({ "kind": "hall-roof" }))
        }
    };
    let (low, high) = mesh.bounding_box();
    report["vertices"] = json!(mesh.vertex_count());
    report["faces"] = json!(mesh.faces().len());
    report["bounding_box"] = json!({ "min": [low.x, low.y, low.z], "max": [high.x, high.y, high.z] });
    let out = OutputDir::create(&target, args.out.force)?;
    let mut surface = Vec::new();
    mesh.write_obj(&mut surface).map_err(|e| CliError::internal(format!("surface.obj: {e}")))?;
    out.write("surface.obj", surface)?;
    if !lines.is_empty() {
        out.write("asymptotic.obj", curves_obj(&lines))?;
    }
    out.write("report.json", pretty(&report))?;
    out.commit()?;
    let extra = if lines.is_empty() { String::new() } else { format!(", asymptotic.obj ({} u-lines)", lines.len()) };
    summary(verbosity, &format!("{}: {} vertices, {} triangles; wrote {}/ (surface.obj{extra}, report.json)", args.kind, mesh.vertex_count(), mesh.faces().len(), target.display()))
}

/// The paper's Brauner surface with μ from the flags, its u-lines `v = const` at `--lines` evenly
/// spaced values of v (exact points and normals of Eq. 23; each is an asymptotic curve of slope
/// `atan(μ e^{−v})`), and its part of report.json.
fn brauner(args: &SurfaceArgs, vertices: usize) -> CliResult<(TriMesh, Vec<LevelCurve>, Value)> {
    let mut surface = BraunerSurface::paper(vertices);
    if let Some(mu) = args.mu {
        surface.mu = mu;
    }
    let count = args.lines.unwrap_or(DEFAULT_LINES);
    if !(2..=MAX_LINES).contains(&count) {
        return Err(CliError::bad_input(format!("--lines must lie in 2..={MAX_LINES}, got {count}")));
    }
    // brauner_surface checks μ (finite, > 0) and names it.
    let mesh = brauner_surface(&surface).map_err(|e| CliError::bad_input(format!("brauner surface: {e}")))?.into_mesh().map_err(|e| CliError::internal(format!("brauner surface: {e}")))?;
    let ([u0, u1], [v0, v1]) = (surface.u_range, surface.v_range);
    let lines: Vec<LevelCurve> = (0..count)
        .map(|k| {
            let v = v0 + (v1 - v0) * k as f64 / (count - 1) as f64;
            let us = (0..LINE_POINTS).map(|i| u0 + (u1 - u0) * i as f64 / (LINE_POINTS - 1) as f64);
            LevelCurve {
                level: v,
                points: us.clone().map(|u| brauner_point(&PaperHeatSolution, surface.mu, u, v)).collect(),
                normals: us.map(|u| surface.normal(u, v)).collect(),
                closed: false,
                singular_vertices: Vec::new(),
            }
        })
        .collect();
    let slopes: Vec<Value> = lines.iter().map(|l| json!({ "v": l.level, "slope_degrees": brauner_slope_degrees(surface.mu, l.level) })).collect();
    let report = json!({
        "kind": "brauner",
        "mu": surface.mu,
        "u_range": surface.u_range,
        "v_range": surface.v_range,
        "asymptotic_u_lines": slopes,
    });
    Ok((mesh, lines, report))
}
