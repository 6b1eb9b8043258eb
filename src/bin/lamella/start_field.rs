//! Where the field optimisation starts (paper Sec. 3.2.2): the coordinate along the longest
//! bounding-box axis, guide P-curves traced from the boundary or read from guides.json (Eq. 5–7),
//! or sketched strokes with the target angle estimated from them (Fig. 14).
use crate::config::{check_theta, Settings, Start};
use crate::error::{CliError, CliResult};
use crate::guides::{crossings, read_guides_json, require_no_crossings, trace_guides};
use crate::strokes_file::read_strokes;
use lamella::initialisation::{estimate_target_angle, field_from_guide_curves, field_from_strokes, GuideCurveOptions, InitialisationError, StrokeOptions};
use lamella::mesh::{EdgePoint, TriMesh};
use serde_json::{json, Value};

/// The initial field and what the optimisation should aim at.
pub struct StartField {
    pub values: Vec<f64>,
    /// Target angle θ in degrees (estimated from strokes unless given).
    pub theta: f64,
    /// Target ‖∇F‖ of `E_grad` suggested by guide curves (their spacing); `None` keeps the
    /// initial field's mean.
    pub gradient_target: Option<f64>,
    /// How the start was made, for report.json.
    pub description: Value,
}

/// The coordinate along the longest axis of the bounding box (on the hall roof, x: its level
/// sets are the arches across the hall).
pub fn axis_field(mesh: &TriMesh) -> Vec<f64> {
    let (low, high) = mesh.bounding_box();
    let axis = (high - low).iamax();
    mesh.positions().iter().map(|p| p[axis]).collect()
}

pub fn start_field(mesh: &TriMesh, settings: &Settings) -> CliResult<StartField> {
    match &settings.start {
        Start::Axis => Ok(StartField {
            values: axis_field(mesh),
            theta: settings.theta,
            gradient_target: None,
            description: json!({ "kind": "bounding-box axis" }),
        }),
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
            from_guides(mesh, &curves, settings.theta, description)
        }
        Start::GuidesFile(path) => {
            let (file_theta, curves) = read_guides_json(path)?;
            let theta = if settings.theta_given { settings.theta } else { file_theta };
            check_theta(theta)?;
            from_guides(mesh, &curves, theta, json!({ "kind": "guides file", "file": path.display().to_string(), "guides": curves.len() }))
        }
        Start::Strokes(path) => {
            let strokes = read_strokes(path)?;
            let fitted = field_from_strokes(mesh, &strokes, &StrokeOptions::default()).map_err(|e| start_error(mesh, "strokes", e))?;
            let estimate = estimate_target_angle(mesh, &fitted.field, &fitted.samples).map_err(|e| start_error(mesh, "strokes", e))?;
            let theta = if settings.theta_given { settings.theta } else { estimate };
            Ok(StartField {
                values: fitted.field,
                theta,
                gradient_target: None,
                description: json!({
                    "kind": "strokes",
                    "file": path.display().to_string(),
                    "strokes": strokes.len(),
                    "estimated_theta_degrees": estimate,
                    "fit_iterations": fitted.iterations,
                }),
            })
        }
    }
}

fn from_guides(mesh: &TriMesh, curves: &[Vec<EdgePoint>], theta: f64, description: Value) -> CliResult<StartField> {
    let guide = field_from_guide_curves(mesh, curves, &GuideCurveOptions::default()).map_err(|e| start_error(mesh, "guides", e))?;
    Ok(StartField { values: guide.field, theta, gradient_target: Some(guide.gradient_target), description })
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
