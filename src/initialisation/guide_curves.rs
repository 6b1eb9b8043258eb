//! The initial field from guide curves (paper Sec. 3.2.2, Fig. 12 b–c, Eq. 5–7).
//!
//! Guide curve `i` (in the order given) carries the value `F^i = i`. First, a linear function in
//! the conformal parameter domain (LSCM, see `conformal_map`) runs from the start of the first
//! curve (`F^1`) to the start of the last (`F^n`). Then
//! `E_init = λ0 E_trace + λ1 E_fair` (Eq. 7) is minimised, a linear least-squares problem solved
//! with one sparse Cholesky factorisation.
//!
//! `E_trace` (Eq. 5) is used in its linear form (reference notes §5.3): a guide point
//! `p = (1 − t) v0 + t v1` contributes `((1 − t) F0 + t F1 − F^i)²`. This is the paper's ratio
//! `(F^i − F0)/(F1 − F0) − t` multiplied by `F1 − F0`: the same zero set (the piecewise linear
//! field interpolates `F^i` at `p`), but linear in F and without the division by `F1 − F0`, which
//! blows up on edges running along a level set. We use it without the edge-length factor of the
//! authors' code, because the solve runs on the mesh scaled to mean edge length 1.
//!
//! With a direct solve the linear function is not needed as a starting point; it enters as a
//! very weak Tikhonov term `μ Σ_v A_v (F_v − F_lin(v))²` (μ = 1e-6 on the unit-scaled mesh) that
//! settles the few directions neither the guides nor the fairness energy fix.

use super::conformal_map::least_squares_conformal_map;
use super::error::{positive_option, InitialisationError};
use super::linear_least_squares::LinearRows;
use super::smoothness_rows::{mean_gradient_norm, push_fairness_rows};
use crate::mesh::{EdgePoint, TriMesh};

/// Weight of the Tikhonov pull towards the linear initial function (unit-scaled mesh).
const LINEAR_PULL: f64 = 1e-6;

/// The weights of Eq. 7.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct GuideCurveOptions {
    /// λ0, the weight of `E_trace` (Eq. 5). Default 3 (the paper's choice).
    pub trace_weight: f64,
    /// λ1, the weight of `E_fair` (Eq. 6). Default 1.
    pub fair_weight: f64,
}

impl Default for GuideCurveOptions {
    fn default() -> Self {
        GuideCurveOptions { trace_weight: 3.0, fair_weight: 1.0 }
    }
}

/// A smooth field whose level sets follow the guide curves.
#[derive(Clone, Debug, PartialEq)]
pub struct GuideField {
    /// One value per vertex; guide curve `i` lies near the level set `F = i`.
    pub field: Vec<f64>,
    /// Suggested `FieldParams::gradient_target` (field units per length unit of the mesh): the
    /// area-weighted mean `‖∇F‖` over the faces between the first and the last guide curve
    /// (`0 ≤ F ≤ n − 1` at all three corners), so that the pseudo-geodesic optimisation keeps the
    /// spacing of the guides (level sets `1/r` apart).
    pub gradient_target: f64,
}

/// Minimises Eq. 7 for the ordered guide curves `curves` on `mesh` (Sec. 3.2.2).
pub fn field_from_guide_curves(
    mesh: &TriMesh,
    curves: &[Vec<EdgePoint>],
    options: &GuideCurveOptions,
) -> Result<GuideField, InitialisationError> {
    let weights = validated(mesh, curves, options)?;
    GuideFieldBasis::new(mesh)?.fit(curves, weights)
}

/// What Eq. 7 needs of the mesh alone, whatever the guides: the mesh scaled to unit mean edge
/// length and its conformal map. The start search fits many guide sets on one mesh and builds
/// this once.
pub(crate) struct GuideFieldBasis<'a> {
    mesh: &'a TriMesh,
    unit_mesh: TriMesh,
    map: Vec<[f64; 2]>,
}

impl<'a> GuideFieldBasis<'a> {
    /// Errors: `SingularSystem` when the conformal map cannot be computed.
    pub(crate) fn new(mesh: &'a TriMesh) -> Result<GuideFieldBasis<'a>, InitialisationError> {
        let (unit_mesh, _) = mesh.unit_scaled();
        let map = least_squares_conformal_map(&unit_mesh).ok_or(InitialisationError::SingularSystem { stage: "conformal map" })?;
        Ok(GuideFieldBasis { mesh, unit_mesh, map })
    }

    /// [`field_from_guide_curves`] on the basis's mesh.
    pub(crate) fn field(&self, curves: &[Vec<EdgePoint>], options: &GuideCurveOptions) -> Result<GuideField, InitialisationError> {
        let weights = validated(self.mesh, curves, options)?;
        self.fit(curves, weights)
    }

    /// Eq. 7 for validated curves with the weights (λ0, λ1).
    fn fit(&self, curves: &[Vec<EdgePoint>], (trace_weight, fair_weight): (f64, f64)) -> Result<GuideField, InitialisationError> {
        let (mesh, unit_mesh) = (self.mesh, &self.unit_mesh);
        let linear = linear_initial_function(&self.map, curves)?;

        let n = mesh.vertex_count();
        let mut rows = LinearRows::new();
        push_fairness_rows(&mut rows, unit_mesh, fair_weight);
        for (i, curve) in curves.iter().enumerate() {
            for point in curve {
                let [a, b] = point.edge.map(|v| v as usize);
                rows.push([(a, 1.0 - point.t), (b, point.t)], i as f64, trace_weight);
            }
        }
        for (v, &value) in linear.iter().enumerate() {
            rows.push([(v, 1.0)], value, LINEAR_PULL * unit_mesh.vertex_areas()[v]);
        }
        let singular = InitialisationError::SingularSystem { stage: "guide-curve fit (Eq. 7)" };
        let field = rows.factorise(n).ok_or(singular.clone())?.solve(rows.targets()).ok_or(singular.clone())?;

        let last = (curves.len() - 1) as f64;
        let between = |f: usize| mesh.faces()[f].iter().all(|&c| (0.0..=last).contains(&field[c as usize]));
        let gradient_target = mean_gradient_norm(mesh, &field, between)
            .or_else(|| mean_gradient_norm(mesh, &field, |_| true))
            .filter(|r| r.is_finite() && *r > 0.0)
            .ok_or(singular)?;
        Ok(GuideField { field, gradient_target })
    }
}

/// The weights (λ0, λ1) of `options` once they and `curves` are checked.
fn validated(mesh: &TriMesh, curves: &[Vec<EdgePoint>], options: &GuideCurveOptions) -> Result<(f64, f64), InitialisationError> {
    let trace_weight = positive_option("trace_weight", options.trace_weight)?;
    let fair_weight = positive_option("fair_weight", options.fair_weight)?;
    validate_guide_curves(mesh, curves)?;
    Ok((trace_weight, fair_weight))
}

/// The linear function of Sec. 3.2.2 in the parameter domain:
/// `F(p) = F^1 + (F^n − F^1) (m(p) − m(c^1_0))·(m(c^n_0) − m(c^1_0)) / ‖m(c^n_0) − m(c^1_0)‖²`.
fn linear_initial_function(map: &[[f64; 2]], curves: &[Vec<EdgePoint>]) -> Result<Vec<f64>, InitialisationError> {
    let image = |p: &EdgePoint| {
        let [a, b] = p.edge.map(|v| map[v as usize]);
        [a[0] + p.t * (b[0] - a[0]), a[1] + p.t * (b[1] - a[1])]
    };
    // Validated: at least two curves, none empty.
    let m0 = image(&curves[0][0]);
    let m1 = image(&curves[curves.len() - 1][0]);
    let d = [m1[0] - m0[0], m1[1] - m0[1]];
    let length2 = d[0] * d[0] + d[1] * d[1];
    if !(length2 > 0.0 && length2.is_finite()) {
        return Err(InitialisationError::CoincidentGuideStarts);
    }
    let span = (curves.len() - 1) as f64;
    Ok(map.iter().map(|m| span * ((m[0] - m0[0]) * d[0] + (m[1] - m0[1]) * d[1]) / length2).collect())
}

/// Checks the curves: at least two, none empty, every point on an edge of `mesh` with `t ∈ [0, 1]`.
fn validate_guide_curves(mesh: &TriMesh, curves: &[Vec<EdgePoint>]) -> Result<(), InitialisationError> {
    if curves.len() < 2 {
        return Err(InitialisationError::TooFewGuideCurves { count: curves.len() });
    }
    for (curve, points) in curves.iter().enumerate() {
        if points.is_empty() {
            return Err(InitialisationError::EmptyGuideCurve { curve });
        }
        for (point, p) in points.iter().enumerate() {
            if let Some(&vertex) = p.edge.iter().find(|&&v| v as usize >= mesh.vertex_count()) {
                return Err(InitialisationError::GuideVertexOutOfRange { curve, point, vertex, vertex_count: mesh.vertex_count() });
            }
            let key = [p.edge[0].min(p.edge[1]), p.edge[0].max(p.edge[1])];
            if mesh.edges().binary_search(&key).is_err() {
                return Err(InitialisationError::GuideNotAnEdge { curve, point, edge: p.edge });
            }
            if !(0.0..=1.0).contains(&p.t) {
                return Err(InitialisationError::GuideParameterOutOfRange { curve, point, t: p.t });
            }
        }
    }
    Ok(())
}
