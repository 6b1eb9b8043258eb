//! Automatic interactive design of P-curves from sketched strokes (Sec. 3.2.2, Fig. 14; the
//! authors' AutoRunSmooth + AutoRunPG): fit a smooth field to the strokes, measure the target
//! angle θ along them, then optimise the field towards pseudo-geodesics of that angle with the
//! default parameters of `FieldParams::pseudo_geodesic`.

use super::error::InitialisationError;
use super::stroke_field::{field_from_strokes, StrokeOptions};
use super::target_angle::estimate_target_angle;
use crate::field::{FieldParams, FieldSolver, StepReport, PAPER_ANGLE_ENERGY};
use crate::mesh::{TriMesh, Vec3};

/// Iterations per `FieldSolver::step` call; side-vector flips are judged on the last call.
const STEP_CHUNK: usize = 10;

/// Options of [`auto_design`].
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct AutoDesignOptions {
    /// The stroke fit.
    pub strokes: StrokeOptions,
    /// Most pseudo-geodesic iterations. Default 400.
    pub max_iterations: usize,
    /// Largest `E_angle` (the report's unweighted energy) that counts as success. Default
    /// [`PAPER_ANGLE_ENERGY`] (the accuracy of the paper's Table 2).
    pub angle_energy_tolerance: f64,
}

impl Default for AutoDesignOptions {
    fn default() -> Self {
        AutoDesignOptions { strokes: StrokeOptions::default(), max_iterations: 400, angle_energy_tolerance: PAPER_ANGLE_ENERGY }
    }
}

/// How an automatic design ended.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub enum DesignStatus {
    /// Converged, no singular vertex, side vectors settled, `E_angle` within the tolerance.
    Succeeded,
    /// The field has singular vertices (level curves that branch or close around a vertex).
    SingularVertices { vertices: Vec<u32> },
    /// Side vectors were still being re-oriented in the last `FieldSolver::step` call (at most
    /// 10 iterations): the family is unstable.
    UnsettledFlips { flips: usize },
    /// The iteration cap was reached before the optimisation settled.
    NotConverged { iterations: usize },
    /// The optimisation settled with `E_angle` above the tolerance: no P-curve family of this
    /// angle was found near the strokes.
    AngleNotReached { energy: f64 },
}

impl DesignStatus {
    pub fn is_success(&self) -> bool {
        matches!(self, DesignStatus::Succeeded)
    }
}

/// The result of [`auto_design`].
#[derive(Clone, Debug, PartialEq)]
pub struct AutoDesign {
    /// The optimised field, one value per vertex.
    pub field: Vec<f64>,
    /// The smooth field fitted to the strokes (the start of the optimisation).
    pub stroke_field: Vec<f64>,
    /// The target angle θ estimated from the strokes, in degrees.
    pub theta_degrees: f64,
    /// The last report of the pseudo-geodesic optimisation.
    pub report: StepReport,
    /// Whether the design succeeded, and if not, why.
    pub status: DesignStatus,
}

/// Designs a P-curve family from sketched `strokes` (ordered polylines of 3D points near `mesh`).
///
/// Fails with an error on bad input (see [`InitialisationError`]); a design that runs but does not
/// reach a valid family is returned with a [`DesignStatus`] other than `Succeeded`.
pub fn auto_design(mesh: &TriMesh, strokes: &[Vec<Vec3>], options: &AutoDesignOptions) -> Result<AutoDesign, InitialisationError> {
    if !(options.angle_energy_tolerance.is_finite() && options.angle_energy_tolerance >= 0.0) {
        return Err(InitialisationError::InvalidOption {
            name: "angle_energy_tolerance",
            message: format!("must be finite and ≥ 0, got {}", options.angle_energy_tolerance),
        });
    }
    let smoothed = field_from_strokes(mesh, strokes, &options.strokes)?;
    let theta_degrees = estimate_target_angle(mesh, &smoothed.field, &smoothed.samples)?;
    let mut solver = FieldSolver::new(mesh, &smoothed.field, FieldParams::pseudo_geodesic(theta_degrees))?;
    let mut report = solver.report().clone();
    while !report.converged && report.iterations < options.max_iterations {
        report = solver.step(STEP_CHUNK.min(options.max_iterations - report.iterations))?;
    }
    let status = if !report.singular_vertices.is_empty() {
        DesignStatus::SingularVertices { vertices: report.singular_vertices.clone() }
    } else if report.flips > 0 {
        DesignStatus::UnsettledFlips { flips: report.flips }
    } else if !report.converged {
        DesignStatus::NotConverged { iterations: report.iterations }
    } else if report.energies.angle.is_nan() || report.energies.angle > options.angle_energy_tolerance {
        DesignStatus::AngleNotReached { energy: report.energies.angle }
    } else {
        DesignStatus::Succeeded
    };
    Ok(AutoDesign { field: solver.field(), stroke_field: smoothed.field, theta_degrees, report, status })
}
