//! `lamella metrics`: the Table 4 measures of the strips in a strips.obj, measured against the
//! surface (closest-point normals and distances).
use crate::args::MetricsArgs;
use crate::config::{check_theta, check_tolerance, resolve_family, DEFAULT_THETA};
use crate::console::out_line;
use crate::error::{CliError, CliResult};
use crate::mesh_input::load_mesh;
use crate::strip_obj::{read_strips_obj, StripShape};
use lamella::mesh::{TriMesh, Vec3};
use lamella::strips::{unroll, PatternMetrics, StripMetrics, SurfaceProjector, Verdict, DEFAULT_TOLERANCE_DEGREES};
use serde_json::json;
use std::fmt::Write as _;

/// Table 4 of one stored strip (at least 2 rulings, as read).
fn measure(projector: &SurfaceProjector, shape: &StripShape, theta: f64, diagonal: f64) -> CliResult<StripMetrics> {
    let centre = shape.centre();
    let offsets = shape.offsets();
    let rulings: Vec<Vec3> = offsets
        .iter()
        .map(|d| d.try_normalize(0.0))
        .collect::<Option<_>>()
        .ok_or_else(|| CliError::bad_input(format!("{}: a ruling of zero length", shape.name)))?;
    if !centre.iter().all(|c| c.iter().all(|x| x.is_finite())) {
        return Err(CliError::bad_input(format!("{}: a non-finite vertex", shape.name)));
    }
    let unrolling = unroll(&centre, &offsets);
    let strip = lamella::strips::StripShape { centre: &centre, rulings: &rulings, offsets: &offsets, unrolling: &unrolling, width: unrolling.width() };
    Ok(StripMetrics::on_surface(projector, &strip, theta, diagonal))
}

fn diagonal(mesh: &TriMesh) -> f64 {
    let (low, high) = mesh.bounding_box();
    (high - low).norm().max(f64::MIN_POSITIVE)
}

pub fn run(args: &MetricsArgs) -> CliResult<()> {
    let theta = resolve_family(args.family.theta, args.family.family.as_deref())?.unwrap_or(DEFAULT_THETA);
    check_theta(theta)?;
    let tolerance = args.tolerance.unwrap_or(DEFAULT_TOLERANCE_DEGREES);
    check_tolerance(tolerance)?;
    let mesh = load_mesh(args.mesh.mesh.as_deref())?;
    let shapes = read_strips_obj(&args.strips_obj)?;
    let projector = SurfaceProjector::new(&mesh);
    let diagonal = diagonal(&mesh);
    let metrics: Vec<StripMetrics> = shapes.iter().map(|s| measure(&projector, s, theta, diagonal)).collect::<CliResult<_>>()?;
    let overall = PatternMetrics::from_strips(metrics.iter());
    let verdict = Verdict::of_metrics(&metrics, tolerance);
    if args.json {
        let strips: Vec<_> = shapes.iter().zip(&metrics).map(|(s, m)| json!({ "name": s.name, "metrics": m })).collect();
        let document = json!({ "theta_degrees": theta, "strips": strips, "overall": overall, "verdict": verdict, "acceptable": verdict.is_acceptable() });
        return out_line(serde_json::to_string_pretty(&document).unwrap_or_default());
    }
    let mut table = format!("{:<12} {:>10} {:>12} {:>11} {:>11} {:>11} {:>9} {:>7}\n", "strip", "length m", "max diff θ°", "e_straight", "E_planar", "max planar", "Appro %", "flipped");
    for (s, m) in shapes.iter().zip(&metrics) {
        let _ = writeln!(
            table,
            "{:<12} {:>10.3} {:>12.4} {:>11.2e} {:>11.2e} {:>11.2e} {:>9.4} {:>7}",
            s.name, m.length, m.max_diff_theta_degrees, m.e_straight, m.e_planar, m.max_planar, m.appro_percent, m.flipped_quads
        );
    }
    let _ = write!(
        table,
        "{:<12} {:>10} {:>12.4} {:>11.2e} {:>11.2e} {:>11.2e} {:>9.4} {:>7}",
        "overall", "", overall.max_diff_theta_degrees, overall.max_e_straight, overall.e_planar, overall.max_planar, overall.appro_percent, overall.flipped_quads
    );
    let _ = write!(table, "\nstrip planes: max angle error {:.3}°; {}", overall.max_quad_angle_error_degrees, verdict.message());
    out_line(table)
}
