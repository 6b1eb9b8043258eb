//! `lamella trace`: guide P-curves of angle θ (paper Sec. 3.2.1, Eq. 4) from evenly spaced points
//! of one side of the outer boundary, for `field --guides-file` / `design --guides-file`.
use crate::args::{StartFlags, TraceArgs};
use crate::config::{Flags, Settings, Start};
use crate::error::CliResult;
use crate::guides::{crossings, guides_json, guides_obj, stop_name, trace_guides};
use crate::mesh_input::{load_mesh, mesh_name};
use crate::output_dir::OutputDir;
use crate::progress::{note, summary, Verbosity};
use serde_json::json;

/// Guides traced when --guides is not given.
pub const DEFAULT_TRACE_GUIDES: usize = 4;

pub fn run(args: &TraceArgs) -> CliResult<()> {
    let verbosity = Verbosity::from(args.verbosity);
    let start_flags = StartFlags { guides: args.guides, seeding: args.seeding.clone(), ..StartFlags::default() };
    let settings = Settings::resolve(Flags {
        mesh: Some(&args.mesh),
        out: Some(&args.out),
        family: Some(&args.family),
        field: None,
        config: Some(&args.config),
        start: Some(&start_flags),
        strips: None,
    })?;
    let count = match settings.start {
        Start::Guides(count) => count,
        _ => DEFAULT_TRACE_GUIDES,
    };
    let mesh = load_mesh(settings.mesh.as_deref())?;
    let name = mesh_name(settings.mesh.as_deref());
    let out = OutputDir::create(&settings.out, settings.force)?;
    let guides = trace_guides(&mesh, count, settings.guide_side, settings.guide_angle, settings.theta)?;
    note(verbosity, &format!("{name}: {count} guides of θ = {}° from side {} at {}°", settings.theta, guides.side, settings.guide_angle));
    let report = crossings(&mesh, &guides);
    let position = |p: &lamella::mesh::Vec3| [p.x, p.y, p.z];
    let document = json!({
        "mesh": name,
        "theta_degrees": settings.theta,
        "side": guides.side,
        "start_angle_degrees": guides.start_angle,
        "guides": guides.curves.iter().map(|c| json!({
            "points": c.points().len(),
            "length_m": c.length(),
            "stop": stop_name(c.stop()),
        })).collect::<Vec<_>>(),
        "crossings": report.crossings.iter().map(|c| json!({ "guides": c.curves, "position": position(&c.position) })).collect::<Vec<_>>(),
        "self_intersections": report.self_intersections.iter().map(|c| json!({ "guide": c.curves[0], "position": position(&c.position) })).collect::<Vec<_>>(),
    });
    out.write("guides.json", guides_json(&guides))?;
    out.write("guides.obj", guides_obj(&guides))?;
    out.write("report.json", serde_json::to_string_pretty(&document).unwrap_or_default())?;
    let target = out.target().display().to_string();
    out.commit()?;
    let lengths: Vec<String> = guides.curves.iter().map(|c| format!("{:.2} m ({})", c.length(), stop_name(c.stop()))).collect();
    let warning = if report.is_intersection_free() {
        String::from("no crossings")
    } else {
        format!(
            "warning: {} crossing(s) and {} self-intersection(s): these guides cannot start a field; try another --guide-angle or --guide-side",
            report.crossings.len(),
            report.self_intersections.len()
        )
    };
    summary(verbosity, &format!("guides: {}\n{warning}\nwrote {target}/ (guides.json, guides.obj, report.json)", lengths.join(", ")))
}
