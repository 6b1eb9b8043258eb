//! A smooth field whose level sets follow sketched strokes (Sec. 3.2.2, "Interactive steering",
//! Fig. 14 b).
//!
//! The initial field is a linear ramp in the conformal parameter domain between the two
//! farthest-apart stroke start points, increasing from the earlier to the later stroke of that
//! pair (so the order of the strokes orients the family), scaled to mean `‖∇F‖ = 1` on the mesh
//! scaled to mean edge length 1. Then, on that unit-scaled mesh, each iteration solves the linear
//! least-squares problem
//!
//! ```text
//! w_s Σ_c Σ_{p ∈ c} (F0 u + F1 v + F2 t − c_c)²  +  λ_fair E_fair  +  λ_grad Σ_f A_f ‖∇F_f − d_f‖²
//! ```
//!
//! where `c_c` is the mean of the current field over the samples of stroke c (the paper's update)
//! and `d_f = ∇F_f/‖∇F_f‖` is the current unit gradient direction. The last term is a
//! linearisation of the strip-width term `(‖∇F‖ − 1)²` of Eq. 11 around the current direction:
//! at a fixed point it equals `(‖∇F‖ − 1)²` on every face, so it keeps the field from collapsing
//! to a constant (which would satisfy the stroke term trivially) and sets the spacing of the level
//! sets to one mean edge length, while the per-iteration update of `d_f` lets the level sets turn
//! towards the strokes. The matrix of this problem does not change between iterations (only the
//! targets `c_c` and `d_f` do), so it is factorised once.

use super::conformal_map::least_squares_conformal_map;
use super::error::{positive_option, InitialisationError};
use super::linear_least_squares::LinearRows;
use super::smoothness_rows::{face_frame, face_gradient, mean_gradient_norm, push_fairness_rows};
use super::strokes::{project_strokes, StrokeSample};
use crate::mesh::{TriMesh, Vec3};

/// Weights and stopping rule of the stroke fit (on the mesh scaled to mean edge length 1).
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct StrokeOptions {
    /// Largest accepted distance of a stroke point from the surface, in mean edge lengths. Default 1.
    pub max_distance: f64,
    /// `w_s`, the weight of the stroke term. Default 10.
    pub stroke_weight: f64,
    /// `λ_fair`, the weight of `E_fair` (Eq. 6). Default 1.
    pub fair_weight: f64,
    /// `λ_grad`, the weight of the linearised gradient-norm term. Default 0.1.
    pub gradient_weight: f64,
    /// Most iterations. Default 100.
    pub max_iterations: usize,
    /// Stop when no vertex value moves by more than this fraction of the field's range in one
    /// iteration. Default 1e-4: the level sets have then turned onto the strokes (within about
    /// 20 iterations on the test surfaces); what remains is a slow drift of the spacing far from
    /// the strokes, which the pseudo-geodesic optimisation redistributes anyway.
    pub tolerance: f64,
}

impl Default for StrokeOptions {
    fn default() -> Self {
        StrokeOptions { max_distance: 1.0, stroke_weight: 10.0, fair_weight: 1.0, gradient_weight: 0.1, max_iterations: 100, tolerance: 1e-4 }
    }
}

/// The smoothed field of the strokes.
#[derive(Clone, Debug, PartialEq)]
pub struct StrokeField {
    /// One value per vertex; level sets about one mean edge length apart.
    pub field: Vec<f64>,
    /// The filtered stroke samples (see [`project_strokes`]).
    pub samples: Vec<Vec<StrokeSample>>,
    /// Iterations run.
    pub iterations: usize,
    /// Whether the last iteration moved the field by less than the tolerance.
    pub converged: bool,
}

/// Projects and filters `strokes` and fits a smooth field whose level sets follow them.
pub fn field_from_strokes(mesh: &TriMesh, strokes: &[Vec<Vec3>], options: &StrokeOptions) -> Result<StrokeField, InitialisationError> {
    let stroke_weight = positive_option("stroke_weight", options.stroke_weight)?;
    let fair_weight = positive_option("fair_weight", options.fair_weight)?;
    let gradient_weight = positive_option("gradient_weight", options.gradient_weight)?;
    if !(options.tolerance.is_finite() && options.tolerance >= 0.0) {
        return Err(InitialisationError::InvalidOption { name: "tolerance", message: format!("must be finite and ≥ 0, got {}", options.tolerance) });
    }
    let samples = project_strokes(mesh, strokes, options.max_distance)?;
    let (unit_mesh, _) = mesh.unit_scaled();
    let mut field = initial_ramp(&unit_mesh, &samples)?;

    let n = mesh.vertex_count();
    let mut rows = LinearRows::new();
    push_fairness_rows(&mut rows, &unit_mesh, fair_weight);
    let first_stroke_row = rows.len();
    for stroke in &samples {
        for s in stroke {
            let corners = unit_mesh.faces()[s.face as usize];
            rows.push(corners.iter().zip(s.barycentric).map(|(&c, w)| (c as usize, w)), 0.0, stroke_weight);
        }
    }
    let first_gradient_row = rows.len();
    let frames: Vec<[Vec3; 2]> = (0..unit_mesh.face_count()).map(|f| face_frame(&unit_mesh, f)).collect();
    for (f, frame) in frames.iter().enumerate() {
        let corners = unit_mesh.faces()[f];
        for axis in frame {
            let entries = corners.iter().zip(unit_mesh.face_gradients(f)).map(|(&c, g)| (c as usize, axis.dot(g)));
            rows.push(entries, 0.0, gradient_weight * unit_mesh.face_areas()[f]);
        }
    }
    let singular = InitialisationError::SingularSystem { stage: "stroke fit" };
    let system = rows.factorise(n).ok_or(singular.clone())?;

    let mut targets = rows.targets().to_vec();
    let (mut iterations, mut converged) = (0, false);
    while iterations < options.max_iterations && !converged {
        let mut r = first_stroke_row;
        for stroke in &samples {
            let mean = stroke.iter().map(|s| s.value(&unit_mesh, &field)).sum::<f64>() / stroke.len() as f64;
            targets[r..r + stroke.len()].fill(mean);
            r += stroke.len();
        }
        for (f, frame) in frames.iter().enumerate() {
            let direction = face_gradient(&unit_mesh, &field, f).try_normalize(0.0).unwrap_or_else(Vec3::zeros);
            for (a, axis) in frame.iter().enumerate() {
                targets[first_gradient_row + 2 * f + a] = axis.dot(&direction);
            }
        }
        let next = system.solve(&targets).ok_or(singular.clone())?;
        let range = value_range(&next);
        let change = next.iter().zip(&field).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
        field = next;
        iterations += 1;
        converged = change <= options.tolerance * range;
    }
    Ok(StrokeField { field, samples, iterations, converged })
}

/// The linear ramp between the two farthest-apart stroke starts in the conformal domain,
/// increasing towards the later stroke, scaled to mean `‖∇F‖ = 1` on `unit_mesh`.
fn initial_ramp(unit_mesh: &TriMesh, samples: &[Vec<StrokeSample>]) -> Result<Vec<f64>, InitialisationError> {
    let singular = InitialisationError::SingularSystem { stage: "initial stroke ramp" };
    let map = least_squares_conformal_map(unit_mesh).ok_or(InitialisationError::SingularSystem { stage: "conformal map" })?;
    let image = |s: &StrokeSample| {
        let corners = unit_mesh.faces()[s.face as usize];
        let mut m = [0.0; 2];
        for (&c, w) in corners.iter().zip(s.barycentric) {
            m[0] += w * map[c as usize][0];
            m[1] += w * map[c as usize][1];
        }
        m
    };
    // Validated: every stroke has at least two samples.
    let starts: Vec<[f64; 2]> = samples.iter().map(|stroke| image(&stroke[0])).collect();
    let distance2 = |a: [f64; 2], b: [f64; 2]| (b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2);
    let mut pair = (0, 1, -1.0);
    for i in 0..starts.len() {
        for j in i + 1..starts.len() {
            let d = distance2(starts[i], starts[j]);
            if d > pair.2 {
                pair = (i, j, d);
            }
        }
    }
    let (m0, m1, length2) = (starts[pair.0], starts[pair.1], pair.2);
    if !(length2 > 0.0 && length2.is_finite()) {
        return Err(singular);
    }
    let d = [m1[0] - m0[0], m1[1] - m0[1]];
    let ramp: Vec<f64> = map.iter().map(|m| ((m[0] - m0[0]) * d[0] + (m[1] - m0[1]) * d[1]) / length2).collect();
    let gradient = mean_gradient_norm(unit_mesh, &ramp, |_| true).filter(|g| g.is_finite() && *g > 0.0).ok_or(singular)?;
    Ok(ramp.iter().map(|f| f / gradient).collect())
}

fn value_range(field: &[f64]) -> f64 {
    let (lo, hi) = field.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &f| (lo.min(f), hi.max(f)));
    hi - lo
}
