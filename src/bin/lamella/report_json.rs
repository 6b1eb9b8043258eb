//! report.json: parameters, per-iteration energies, Table 4 metrics per strip and overall, and
//! timings. Non-finite numbers become `null` (JSON has no NaN).
use crate::config::Settings;
use crate::field_files::HistoryRow;
use crate::strip_obj::strip_name;
use crate::strips_cmd::StripRun;
use lamella::field::FieldSolver;
use lamella::quality::FamilyAngles;
use serde_json::{json, Map, Value};

/// Wall-clock seconds per stage.
pub struct Timings {
    pub field: f64,
    pub strips: f64,
    pub total: f64,
}

/// The parameters in force, and how the field started (when a field was made).
pub fn parameters(settings: &Settings, theta: f64, mesh: &str, start: Option<&Value>) -> Value {
    json!({
        "mesh": mesh,
        "theta_degrees": theta,
        "max_iterations": settings.max_iterations,
        "strips": settings.strips,
        "width_m": settings.width,
        "tolerance_degrees": settings.tolerance,
        "start": start,
    })
}

fn field_section(solver: &FieldSolver, history: &[HistoryRow], measure: &FamilyAngles) -> Value {
    let r = solver.report();
    let rows: Vec<Value> = history
        .iter()
        .map(|h| {
            json!({
                "iteration": h.iteration,
                "stage": h.stage,
                "e_angle": h.energies.angle,
                "e_frame": h.energies.frame,
                "e_fair": h.energies.fair,
                "e_grad": h.energies.grad,
                "e_total": h.energies.total,
                "angle_error_max_degrees": h.angle_error_max_degrees,
            })
        })
        .collect();
    json!({
        "iterations": r.iterations,
        "converged": r.converged,
        "family": solver.params().family,
        "angle_error_max_degrees": r.angle_error_max_degrees,
        "angle_error_rms_degrees": r.angle_error_rms_degrees,
        "singular_vertices": r.singular_vertices.len(),
        "level_curves": {
            "measured_points": measure.measured,
            "spacing_m": measure.spacing,
            "angle_error_rms_degrees": measure.rms_error_degrees,
            "angle_error_max_degrees": measure.max_error_degrees,
            "straight_fraction": measure.straight_fraction(),
            "worst": measure.worst,
        },
        "history": rows,
    })
}

fn strips_section(run: &StripRun) -> Value {
    let strips: Vec<Value> = run
        .pattern
        .strips
        .iter()
        .enumerate()
        .map(|(id, s)| {
            let m = &s.metrics;
            json!({
                "id": id,
                "name": strip_name(id),
                "curve": s.curve,
                "level": s.level,
                "vertices": s.centre.len(),
                "length_m": m.length,
                "max_diff_theta_degrees": m.max_diff_theta_degrees,
                "e_straight": m.e_straight,
                "e_planar": m.e_planar,
                "max_planar": m.max_planar,
                "appro_percent": m.appro_percent,
                "flipped_quads": m.flipped_quads,
                "max_quad_angle_error_degrees": m.max_quad_angle_error_degrees,
                "max_ruling_over_width": m.max_ruling_over_width,
                "warnings": s.warnings.iter().map(ToString::to_string).collect::<Vec<_>>(),
            })
        })
        .collect();
    let skipped: Vec<Value> = run
        .pattern
        .skipped
        .iter()
        .map(|s| json!({ "curve": s.curve, "warnings": s.warnings.iter().map(ToString::to_string).collect::<Vec<_>>() }))
        .collect();
    let m = &run.pattern.metrics;
    json!({
        "width_m": run.width,
        "curve_spacing_m": run.spacing,
        "curves": run.curves.len(),
        "strips": strips,
        "skipped": skipped,
        "overall": {
            "strip_count": m.strip_count,
            "total_length_m": run.pattern.strips.iter().map(|s| s.metrics.length).sum::<f64>(),
            "max_diff_theta_degrees": m.max_diff_theta_degrees,
            "max_e_straight": m.max_e_straight,
            "e_planar": m.e_planar,
            "max_planar": m.max_planar,
            "appro_percent": m.appro_percent,
            "flipped_quads": m.flipped_quads,
            "max_quad_angle_error_degrees": m.max_quad_angle_error_degrees,
            "max_ruling_over_width": m.max_ruling_over_width,
        },
        "verdict": run.pattern.verdict,
        "acceptable": run.pattern.verdict.is_acceptable(),
        "verdict_message": run.pattern.verdict.message(),
    })
}

/// The whole report, pretty-printed.
pub fn document(parameters: &Value, field: Option<(&FieldSolver, &[HistoryRow], &FamilyAngles)>, strips: Option<&StripRun>, timings: &Timings) -> String {
    pretty(&document_value(parameters, field, strips, timings))
}

/// A report pretty-printed, with a final line break.
pub fn pretty(report: &Value) -> String {
    // Serialising a Value cannot fail; fall back to the empty string regardless.
    serde_json::to_string_pretty(report).unwrap_or_default() + "\n"
}

/// The whole report.
pub fn document_value(parameters: &Value, field: Option<(&FieldSolver, &[HistoryRow], &FamilyAngles)>, strips: Option<&StripRun>, timings: &Timings) -> Value {
    let mut root = Map::new();
    root.insert("lamella_version".into(), json!(env!("CARGO_PKG_VERSION")));
    root.insert("parameters".into(), parameters.clone());
    if let Some((solver, history, measure)) = field {
        root.insert("field".into(), field_section(solver, history, measure));
    }
    if let Some(run) = strips {
        root.insert("strips".into(), strips_section(run));
    }
    root.insert(
        "timings_s".into(),
        json!({ "field": timings.field, "strips": timings.strips, "total": timings.total }),
    );
    Value::Object(root)
}
