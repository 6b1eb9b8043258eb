//! The intersection angle of two families per triangle (paper Sec. 4.1): with the normalised
//! gradients `g_F = ∇F/‖∇F‖`, `g_G = ∇G/‖∇G‖` and `g_G^⊥ = n_f × g_G` (rotation by 90° in the
//! face), the level sets of `F` and `G` cross at the oriented angle `γ` with
//! `g_F · g_G = cos γ` and `g_F · g_G^⊥ = sin γ`.
//!
//! Rows per face, each scaled by the square root of its weight times the face area (as `E_grad`):
//!
//! | row | residual | use |
//! |---|---|---|
//! | 0 | `g_F · g_G − cos γ` | target angle, weak (weight 0 without a target) |
//! | 1 | `g_F · g_G^⊥ − sin γ` | target angle, weak |
//! | 2 | `max(0, sin² γ_min − (g_F · g_G^⊥)²)` | minimum intersection angle: the families never become tangent (squared sines: smooth where they are tangent) |
//!
//! The unsigned intersection angle of the two curve families is `asin |g_F · g_G^⊥|` in
//! `[0°, 90°]`. The derivatives are exact (the norms are not frozen):
//! `∂g_F/∂F_j = (I − g_F g_Fᵀ) ∇φ_j / ‖∇F‖`.

use crate::mesh::{TriMesh, Vec3};

/// Rows per face.
pub(crate) const ROWS: usize = 3;

/// Below this gradient norm (on the normalised problem, mean 1) a face's rows are zero: the
/// direction of a vanishing gradient is undefined (`E_grad` keeps gradients away from it).
const MIN_GRADIENT: f64 = 1e-9;

/// The weights and targets of the intersection rows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct IntersectionTerm {
    /// `(cos γ, sin γ)` of the oriented target angle.
    pub target: (f64, f64),
    /// Weight of rows 0 and 1 (0: no target angle).
    pub target_weight: f64,
    /// `sin γ_min`.
    pub min_sine: f64,
    /// Weight of row 2.
    pub min_weight: f64,
}

/// `∇F` on face `f`.
pub(crate) fn face_gradient(mesh: &TriMesh, field: &[f64], f: usize) -> Vec3 {
    let gradients = mesh.face_gradients(f);
    let corners = mesh.faces()[f];
    (0..3).map(|k| gradients[k] * field[corners[k] as usize]).sum()
}

/// `(g_F · g_G, g_F · g_G^⊥)` on face `f`, or `None` where a gradient vanishes.
pub(crate) fn cos_sin(mesh: &TriMesh, f_field: &[f64], g_field: &[f64], f: usize) -> Option<(f64, f64)> {
    let (a, b) = (face_gradient(mesh, f_field, f), face_gradient(mesh, g_field, f));
    let (na, nb) = (a.norm(), b.norm());
    if !(na > 0.0 && nb > 0.0 && na.is_finite() && nb.is_finite()) {
        return None;
    }
    let (ga, gb) = (a / na, b / nb);
    Some((ga.dot(&gb), ga.dot(&mesh.face_normals()[f].cross(&gb))))
}

/// The unsigned angle in degrees (in `[0°, 90°]`) at which the level sets of the two fields
/// cross on each face; `None` where a gradient vanishes.
pub fn intersection_angles(mesh: &TriMesh, f_field: &[f64], g_field: &[f64]) -> Vec<Option<f64>> {
    (0..mesh.face_count()).map(|f| cos_sin(mesh, f_field, g_field, f).map(|(_, s)| s.abs().min(1.0).asin().to_degrees())).collect()
}

/// The area-weighted mean of the oriented angle's `(cos γ, sin γ)` over the faces, normalised
/// (`None` if it vanishes): the orientation a target angle is read against.
pub(crate) fn mean_orientation(mesh: &TriMesh, f_field: &[f64], g_field: &[f64]) -> Option<(f64, f64)> {
    let (mut c, mut s) = (0.0, 0.0);
    for f in 0..mesh.face_count() {
        if let Some((cf, sf)) = cos_sin(mesh, f_field, g_field, f) {
            c += cf * mesh.face_areas()[f];
            s += sf * mesh.face_areas()[f];
        }
    }
    let norm = c.hypot(s);
    (norm > 0.0 && norm.is_finite()).then(|| (c / norm, s / norm))
}

/// Evaluates the rows of face `f`. `f_field`, `g_field`: the two fields' values per vertex.
/// `jacobian` has the columns `F` at the face's three corners, then `G` at them.
pub(crate) fn evaluate(mesh: &TriMesh, term: &IntersectionTerm, f_field: &[f64], g_field: &[f64], f: usize, residuals: &mut [f64], jacobian: Option<&mut [f64]>) {
    let (a, b) = (face_gradient(mesh, f_field, f), face_gradient(mesh, g_field, f));
    let (na, nb) = (a.norm(), b.norm());
    if !(na > MIN_GRADIENT && nb > MIN_GRADIENT) {
        return;
    }
    let n = mesh.face_normals()[f];
    let (ga, gb) = (a / na, b / nb);
    let gb_perp = n.cross(&gb);
    let (cos, sin) = (ga.dot(&gb), ga.dot(&gb_perp));
    let area = mesh.face_areas()[f];
    let target_scale = (term.target_weight * area).sqrt();
    let min_scale = (term.min_weight * area).sqrt();
    let hinge = term.min_sine * term.min_sine - sin * sin;
    residuals[0] = target_scale * (cos - term.target.0);
    residuals[1] = target_scale * (sin - term.target.1);
    residuals[2] = if hinge > 0.0 { min_scale * hinge } else { 0.0 };
    let Some(jac) = jacobian else { return };
    // d(g·c)/dF_j = (P c)·∇φ_j / ‖∇F‖ with P = I − g gᵀ.
    let project = |g: &Vec3, c: &Vec3, norm: f64| (c - g * g.dot(c)) / norm;
    // cos = g_F·g_G; sin = g_F·(n × g_G) = g_G·(g_F × n).
    let rows: [(Vec3, Vec3, f64); 3] = [
        (project(&ga, &gb, na), project(&gb, &ga, nb), target_scale),
        (project(&ga, &gb_perp, na), project(&gb, &ga.cross(&n), nb), target_scale),
        (project(&ga, &gb_perp, na), project(&gb, &ga.cross(&n), nb), if hinge > 0.0 { -2.0 * min_scale * sin } else { 0.0 }),
    ];
    let gradients = mesh.face_gradients(f);
    for (row, (df, dg, scale)) in rows.iter().enumerate() {
        for k in 0..3 {
            jac[row * 6 + k] = scale * df.dot(&gradients[k]);
            jac[row * 6 + 3 + k] = scale * dg.dot(&gradients[k]);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::surfaces::{hyperbolic_paraboloid, HyperbolicParaboloid};

    #[test]
    fn the_rows_and_their_jacobian_match_the_angle_and_central_differences() {
        let surface = HyperbolicParaboloid { c: 3.0, half_width: 2.0, target_vertices: 100, irregularity: 0.3, seed: 3 };
        let mesh = hyperbolic_paraboloid(&surface).expect("surface").into_mesh().expect("mesh");
        let f: Vec<f64> = mesh.positions().iter().map(|p| p.x + 0.3 * p.y * p.y).collect();
        let g: Vec<f64> = mesh.positions().iter().map(|p| 0.2 * p.x + p.y - 0.1 * p.x * p.y).collect();
        // A minimum above every face's angle keeps the hinge row active everywhere.
        let term = IntersectionTerm { target: (0.5, 0.75f64.sqrt()), target_weight: 2.0, min_sine: 1.0, min_weight: 3.0 };
        for face in 0..mesh.face_count() {
            let mut r = [0.0; ROWS];
            let mut jac = [0.0; ROWS * 6];
            evaluate(&mesh, &term, &f, &g, face, &mut r, Some(&mut jac));
            let (c, s) = cos_sin(&mesh, &f, &g, face).expect("gradients");
            assert!((c * c + s * s - 1.0).abs() < 1e-12);
            let area = mesh.face_areas()[face];
            assert!((r[0] - (2.0 * area).sqrt() * (c - 0.5)).abs() < 1e-12);
            assert!((r[2] - (3.0 * area).sqrt() * (1.0 - s * s)).abs() < 1e-12);
            let corners = mesh.faces()[face];
            for column in 0..6 {
                let h = 1e-6;
                let shifted = |delta: f64| {
                    let (mut f, mut g) = (f.clone(), g.clone());
                    let v = corners[column % 3] as usize;
                    if column < 3 { f[v] += delta } else { g[v] += delta }
                    let mut r = [0.0; ROWS];
                    evaluate(&mesh, &term, &f, &g, face, &mut r, None);
                    r
                };
                let (plus, minus) = (shifted(h), shifted(-h));
                for row in 0..ROWS {
                    let numeric = (plus[row] - minus[row]) / (2.0 * h);
                    assert!((numeric - jac[row * 6 + column]).abs() < 1e-5 * (1.0 + numeric.abs()), "face {face} row {row} column {column}: {numeric} vs {}", jac[row * 6 + column]);
                }
            }
        }
    }
}
