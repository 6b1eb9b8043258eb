//! Where the field optimisation starts (paper Sec. 3.2.2): by default a search over several
//! starts that keeps the one whose level curves come nearest the asked family
//! ([`StartSearch`]); or a start the user chose: the height along a direction, a field from a
//! file, guide P-curves traced from the boundary or read from guides.json (Eq. 5–7), or sketched
//! strokes with the target angle estimated from them (Fig. 14).
use crate::config::{check_theta, Settings, Start};
use crate::console::err_line;
use crate::error::{CliError, CliResult};
use crate::field_cmd::field_error;
use crate::field_files::read_field_csv;
use crate::guides::{crossings, read_guides_json, require_no_crossings, trace_guides};
use crate::progress::{note, Verbosity};
use crate::strokes_file::read_strokes;
use lamella::field::{FieldParams, FieldSolver};
use lamella::initialisation::{
    estimate_target_angle, field_from_guide_curves, field_from_strokes, GuideCurveOptions, InitialisationError, SearchError, SearchOptions, StartSearch,
    StrokeOptions,
};
use lamella::mesh::{EdgePoint, TriMesh};
use serde_json::{json, Value};
use std::path::Path;
use std::time::Instant;

/// A field optimisation ready to be stepped, and how it was started.
pub struct Started {
    pub solver: FieldSolver,
    /// Target angle θ in degrees (estimated from strokes unless given).
    pub theta: f64,
    /// How the start was made (for a search: every candidate with its score), for report.json.
    pub description: Value,
}

/// The solver for the settings' start on `mesh`.
pub fn start_solver(mesh: &TriMesh, settings: &Settings, verbosity: Verbosity) -> CliResult<Started> {
    let chosen = |values: Vec<f64>, theta: f64, gradient_target: Option<f64>, description: Value| {
        let mut params = FieldParams::pseudo_geodesic(theta);
        params.gradient_target = gradient_target;
        let solver = FieldSolver::new(mesh, &values, params).map_err(field_error)?;
        Ok(Started { solver, theta, description })
    };
    match &settings.start {
        Start::Search => search(mesh, settings.theta, verbosity),
        Start::Direction(d) => {
            let values = mesh.positions().iter().map(|p| p.dot(d)).collect();
            chosen(values, settings.theta, None, json!({ "kind": "height along a direction", "direction": [d.x, d.y, d.z] }))
        }
        Start::FieldFile(path) => {
            let values = read_field_for(mesh, path)?;
            chosen(values, settings.theta, None, json!({ "kind": "field file", "file": path.display().to_string() }))
        }
        Start::Guides(count) => {
            let guides = trace_guides(mesh, *count, settings.guide_side, settings.guide_angle, settings.theta)?;
            require_no_crossings(&crossings(mesh, &guides))?;
            let curves: Vec<Vec<EdgePoint>> = guides.curves.iter().map(|c| c.points().to_vec()).collect();
            let description = json!({
                "kind": "traced guides",
                "guides": count,
                "side": guides.side,
                "start_angle_degrees": guides.start_angle,
                "lengths_m": guides.curves.iter().map(|c| c.length()).collect::<Vec<_>>(),
            });
            let (values, target) = from_guides(mesh, &curves)?;
            chosen(values, settings.theta, Some(target), description)
        }
        Start::GuidesFile(path) => {
            let (file_theta, curves) = read_guides_json(path)?;
            let theta = if settings.theta_given { settings.theta } else { file_theta };
            check_theta(theta)?;
            let (values, target) = from_guides(mesh, &curves)?;
            chosen(values, theta, Some(target), json!({ "kind": "guides file", "file": path.display().to_string(), "guides": curves.len() }))
        }
        Start::Strokes(path) => {
            let strokes = read_strokes(path)?;
            let fitted = field_from_strokes(mesh, &strokes, &StrokeOptions::default()).map_err(|e| start_error(mesh, "strokes", e))?;
            let estimate = estimate_target_angle(mesh, &fitted.field, &fitted.samples).map_err(|e| start_error(mesh, "strokes", e))?;
            let theta = if settings.theta_given { settings.theta } else { estimate };
            let description = json!({
                "kind": "strokes",
                "file": path.display().to_string(),
                "strokes": strokes.len(),
                "estimated_theta_degrees": estimate,
                "fit_iterations": fitted.iterations,
            });
            chosen(fitted.field, theta, None, description)
        }
    }
}

/// The default start search, reported on stderr (one line, every candidate under `--verbose`).
fn search(mesh: &TriMesh, theta: f64, verbosity: Verbosity) -> CliResult<Started> {
    let started = Instant::now();
    let mut search = StartSearch::new(mesh, FieldParams::pseudo_geodesic(theta), SearchOptions::default()).map_err(field_error)?;
    loop {
        let more = search.step().map_err(field_error)?;
        if verbosity == Verbosity::Verbose {
            if let Some(c) = search.candidates().last() {
                let outcome = match (&c.rejected, c.score) {
                    (Some(reason), _) => format!("rejected: {reason}"),
                    (None, Some(score)) => format!("score {score:.2} (RMS {:.2}°, max {:.2}°)", c.rms_error_degrees, c.max_error_degrees),
                    (None, None) => "not scored".into(),
                };
                err_line(format_args!("start candidate {}: {}: {outcome}", search.candidates().len() - 1, c.kind.describe()));
            }
        }
        if !more {
            break;
        }
    }
    let candidates: Vec<Value> = search.candidates().iter().map(|c| json!({
        "start": c.kind.describe(),
        "kind": c.kind,
        "score": c.score,
        "rms_error_degrees": c.rms_error_degrees,
        "max_error_degrees": c.max_error_degrees,
        "straight_fraction": c.straight_fraction,
        "singular_vertices": c.singular_vertices,
        "rejected": c.rejected,
    })).collect();
    let winner = search.winner();
    let chosen = winner.map(|w| search.candidates()[w].kind.describe());
    let proxy_vertices = search.proxy_vertex_count();
    note(
        verbosity,
        &format!(
            "start search{}: {} candidates in {:.1} s; {}",
            proxy_vertices.map_or(String::new(), |n| format!(" on a {n}-vertex coarsening")),
            candidates.len(),
            started.elapsed().as_secs_f64(),
            chosen.as_deref().map_or("none acceptable".to_string(), |c| format!("continuing from {c}"))
        ),
    );
    // A winner that is itself rejected is the fallback on nearly straight level curves.
    let fallback = winner.and_then(|w| search.candidates()[w].rejected.clone());
    if let (Some(reason), Some(chosen)) = (&fallback, &chosen) {
        note(
            verbosity,
            &format!(
                "warning: every start leads to nearly straight level curves ({chosen} is the best: {reason}); the surface bends little at this θ across the model, so the curves' binormals are weakly defined and the strips' verdict decides; another θ or a start of your own (--guides, --direction, --strokes, --start-field) may do better"
            ),
        );
    }
    let description = json!({ "kind": "search", "proxy_vertices": proxy_vertices, "winner": winner, "fallback": fallback.is_some(), "candidates": candidates });
    let solver = search.into_solver().map_err(|e| match e {
        SearchError::NoStart { .. } => CliError::bad_input(format!("{e}; give a start (--guides, --direction, --strokes, --start-field)")),
        SearchError::Field(error) => field_error(error),
    })?;
    Ok(Started { solver, theta, description })
}

fn from_guides(mesh: &TriMesh, curves: &[Vec<EdgePoint>]) -> CliResult<(Vec<f64>, f64)> {
    let guide = field_from_guide_curves(mesh, curves, &GuideCurveOptions::default()).map_err(|e| start_error(mesh, "guides", e))?;
    Ok((guide.field, guide.gradient_target))
}

/// The field of `path`, checked against the mesh.
pub fn read_field_for(mesh: &TriMesh, path: &Path) -> CliResult<Vec<f64>> {
    let field = read_field_csv(path)?;
    if field.len() != mesh.vertex_count() {
        return Err(CliError::bad_input(format!(
            "{}: {} values for a mesh of {} vertices",
            path.display(),
            field.len(),
            mesh.vertex_count()
        )));
    }
    Ok(field)
}

/// Initialisation errors are bad input. A singular linear system comes from the mesh (the
/// systems are regular on any non-degenerate mesh): the message names its sharpest corner.
fn start_error(mesh: &TriMesh, what: &str, error: InitialisationError) -> CliError {
    match error {
        InitialisationError::SingularSystem { .. } => {
            let (face, degrees) = mesh.sharpest_corner();
            CliError::bad_input(format!(
                "{what}: {error}; the mesh is likely numerically degenerate: its sharpest corner is {degrees:.2e}° in face {face}"
            ))
        }
        _ => CliError::bad_input(format!("{what}: {error}")),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::CliError;
    use lamella::surfaces::hall_roof;

    #[test]
    fn a_singular_initial_system_is_bad_input_naming_the_sharpest_corner() {
        let mesh = hall_roof(60).into_mesh().expect("valid roof");
        let (face, _) = mesh.sharpest_corner();
        let error = start_error(&mesh, "guides", InitialisationError::SingularSystem { stage: "conformal map" });
        assert!(matches!(error, CliError::BadInput(_)), "{error}");
        assert_eq!(error.exit_code(), 2);
        let message = error.to_string();
        assert!(message.contains("conformal map") && message.contains(&format!("in face {face}")), "{message}");
    }
}
