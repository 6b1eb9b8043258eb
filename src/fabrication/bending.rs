//! The bending and twisting check of one strip: how far bending the flat strip along its centre
//! line and twisting it with its rectifying frame strains and stresses the material.
//!
//! A rectifying strip unrolls to a straight strip (Fig. 20, Eq. 16–17): its centre line is a
//! geodesic of the strip, so the whole curvature of the centre line bends the strip about its
//! weak axis (across its width), and the strip's normal turns about the tangent at the rate of
//! its rectifying frame. At point `i`, with thickness `t`:
//! - weak-axis curvature `κ_i = |k_i · N_i|`: `k_i` the curvature vector of the circle through
//!   `c_{i−2}, c_i, c_{i+2}` (the nearer neighbours next to the ends; exactly `1/R` for points on
//!   a circle of radius R; two points apart so that vertex-scale noise of a polyline does not read
//!   as bending), `N_i = t_i × d_i` the strip's unit normal (`t_i` the tangent, `d_i` the ruling);
//!   the end points take their neighbour's;
//! - bending strain `ε = t κ / 2` and stress `σ = E t κ / 2` at the faces;
//! - twist rate `τ_i`: the angle by which `N` turns about the tangent from one point to the next
//!   (after the minimal rotation that carries one tangent to the next, i.e. relative to parallel
//!   transport), divided by the segment's length, averaged over the two segments at a point (the
//!   end segments, whose one-sided tangents are half a segment off, take their neighbours'); for
//!   an exact rectifying developable it is the centre line's torsion (the rulings point along the
//!   Darboux vector `τ t + κ b`, Sec. 2.1);
//! - torsional shear stress of a thin rectangular section (Saint-Venant, width ≫ thickness)
//!   `τ_s = G t τ`;
//! - utilisation: the von Mises comparison stress `√(σ² + 3 τ_s²)` over the allowable stress.
//!
//! Strong-axis (in-plane) bending is zero for a strip that unrolls straight and is not checked.
use super::error::FabricationError;
use super::material::Material;
use super::strip_input::FabricationStrip;
use crate::mesh::Vec3;

/// The circle of the curvature at `c_i` passes through `c_{i−SPAN}` and `c_{i+SPAN}` (nearer
/// neighbours at the ends).
const SPAN: usize = 2;

/// The check of one strip, per centre point and at its worst point.
#[derive(Clone, Debug, PartialEq)]
pub struct StripCheck {
    /// Arc length of each centre point, metres.
    pub arc_length: Vec<f64>,
    /// Weak-axis curvature `κ_i` in 1/m.
    pub curvature: Vec<f64>,
    /// Twist rate `|τ_i|` of the rectifying frame in rad/m.
    pub twist_rate: Vec<f64>,
    /// Utilisation `√(σ² + 3 τ_s²) / f` per point (1 = the allowable stress).
    pub utilisation: Vec<f64>,
    /// Largest bending strain `t κ / 2` (dimensionless).
    pub max_strain: f64,
    /// Largest bending stress `E t κ / 2`, Pa.
    pub max_bending_stress: f64,
    /// Largest torsional shear stress `G t τ`, Pa.
    pub max_shear_stress: f64,
    /// Largest utilisation.
    pub max_utilisation: f64,
    /// The centre point of the largest utilisation (the first of equals).
    pub worst_point: usize,
    /// Its position in space.
    pub worst_position: Vec3,
}

impl StripCheck {
    /// Whether the strip is stressed beyond the allowable stress somewhere (utilisation > 1).
    pub fn is_overstressed(&self) -> bool {
        self.max_utilisation > 1.0
    }

    /// Smallest bending radius `1 / max κ`, metres; `None` for a straight strip.
    pub fn min_bending_radius(&self) -> Option<f64> {
        let most = self.curvature.iter().copied().fold(0.0, f64::max);
        (most > 0.0).then(|| 1.0 / most)
    }

    /// Largest twist rate, rad/m.
    pub fn max_twist_rate(&self) -> f64 {
        self.twist_rate.iter().copied().fold(0.0, f64::max)
    }
}

/// Checks that a thickness is finite and positive.
pub fn validate_thickness(thickness: f64) -> Result<(), FabricationError> {
    if thickness.is_finite() && thickness > 0.0 {
        Ok(())
    } else {
        Err(FabricationError::parameter("thickness", format!("must be finite and > 0 m, got {thickness}")))
    }
}

/// Curvature vector of the circle through `a, p, b` at `p` (pointing to its centre, length 1/R);
/// zero for collinear points.
fn curvature_vector(a: &Vec3, p: &Vec3, b: &Vec3) -> Vec3 {
    let (u, v) = (a - p, b - p);
    let normal = u.cross(&v);
    let area2 = normal.norm_squared();
    if area2 <= f64::EPSILON * u.norm_squared() * v.norm_squared() {
        return Vec3::zeros();
    }
    // Offset of the circumcentre from p.
    let centre = (v * u.norm_squared() - u * v.norm_squared()).cross(&normal) / (2.0 * area2);
    centre / centre.norm_squared()
}

/// Signed angle by which `n1` turns away from `n0` carried along (by the minimal rotation taking
/// `t0` to `t1`), measured about `t1`.
fn turn_about_tangent(t0: &Vec3, n0: &Vec3, t1: &Vec3, n1: &Vec3) -> f64 {
    let axis = t0.cross(t1);
    let (sin, cos) = (axis.norm(), t0.dot(t1));
    let carried = match axis.try_normalize(0.0) {
        // Rodrigues' rotation of n0 about `axis` by the angle between the tangents.
        Some(k) => n0 * cos + k.cross(n0) * sin + k * k.dot(n0) * (1.0 - cos),
        None => *n0,
    };
    carried.cross(n1).dot(t1).atan2(carried.dot(n1))
}

/// The bending and twisting check of `strip` (validated by the caller) for `material` and
/// `thickness` (metres).
pub fn check_strip(strip: &FabricationStrip, material: &Material, thickness: f64) -> StripCheck {
    let n = strip.centre.len();
    let c = &strip.centre;
    let tangents = strip.tangents();
    let normals: Vec<Vec3> = tangents.iter().zip(&strip.offsets).map(|(t, d)| t.cross(d).try_normalize(0.0).unwrap_or_else(Vec3::zeros)).collect();
    let mut curvature: Vec<f64> = (0..n)
        .map(|i| {
            let reach = SPAN.min(i).min(n - 1 - i);
            if reach == 0 { 0.0 } else { curvature_vector(&c[i - reach], &c[i], &c[i + reach]).dot(&normals[i]).abs() }
        })
        .collect();
    // The ends have no circle of their own: they take their neighbour's.
    if n >= 3 {
        curvature[0] = curvature[1];
        curvature[n - 1] = curvature[n - 2];
    }
    let mut segment_twist: Vec<f64> =
        (0..n - 1).map(|j| turn_about_tangent(&tangents[j], &normals[j], &tangents[j + 1], &normals[j + 1]) / (c[j + 1] - c[j]).norm()).collect();
    // The end tangents are one-sided (half a segment off): the end segments take their neighbour's twist.
    if n >= 4 {
        segment_twist[0] = segment_twist[1];
        segment_twist[n - 2] = segment_twist[n - 3];
    }
    let twist_rate: Vec<f64> = (0..n)
        .map(|i| {
            let around: Vec<f64> = [i.checked_sub(1), (i < n - 1).then_some(i)].into_iter().flatten().map(|j| segment_twist[j]).collect();
            (around.iter().sum::<f64>() / around.len() as f64).abs()
        })
        .collect();
    let half = 0.5 * thickness;
    let utilisation: Vec<f64> = curvature
        .iter()
        .zip(&twist_rate)
        .map(|(k, tw)| {
            let sigma = material.youngs_modulus * half * k;
            let shear = material.shear_modulus * thickness * tw;
            (sigma * sigma + 3.0 * shear * shear).sqrt() / material.allowable_stress
        })
        .collect();
    let max_curvature = curvature.iter().copied().fold(0.0, f64::max);
    let worst_point = utilisation.iter().enumerate().fold(0, |best, (i, u)| if *u > utilisation[best] { i } else { best });
    StripCheck {
        arc_length: strip.arc_lengths(),
        max_strain: half * max_curvature,
        max_bending_stress: material.youngs_modulus * half * max_curvature,
        max_shear_stress: material.shear_modulus * thickness * twist_rate.iter().copied().fold(0.0, f64::max),
        max_utilisation: utilisation[worst_point],
        worst_point,
        worst_position: c[worst_point],
        curvature,
        twist_rate,
        utilisation,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn curvature_of_three_points_on_a_circle_is_the_inverse_radius() {
        let r = 2.5;
        let on = |a: f64| Vec3::new(r * a.cos(), r * a.sin(), 0.3);
        let k = curvature_vector(&on(0.1), &on(0.4), &on(0.55));
        assert!((k.norm() - 1.0 / r).abs() < 1e-12 / r);
        // Towards the centre.
        assert!(k.dot(&-on(0.4)) > 0.0);
        assert_eq!(curvature_vector(&Vec3::zeros(), &Vec3::x(), &(Vec3::x() * 2.0)), Vec3::zeros());
    }

    #[test]
    fn a_helix_strip_twists_at_its_torsion() {
        // Helix (r cos s', r sin s', h s'), curvature r/(r²+h²), torsion h/(r²+h²); its rectifying
        // strip has the principal normal as its normal, the Darboux vector as its ruling.
        let (r, h) = (2.0, 0.5);
        let q = r * r + h * h;
        let samples = 400;
        let point = |u: f64| Vec3::new(r * u.cos(), r * u.sin(), h * u);
        let centre: Vec<Vec3> = (0..=samples).map(|i| point(i as f64 * 0.01)).collect();
        let offsets: Vec<Vec3> = (0..=samples)
            .map(|i| {
                let u = i as f64 * 0.01;
                let t = Vec3::new(-r * u.sin(), r * u.cos(), h) / q.sqrt();
                let b = Vec3::new(h * u.sin(), -h * u.cos(), r) / q.sqrt();
                (t * (h / q) + b * (r / q)).normalize() * 0.05
            })
            .collect();
        let strip = FabricationStrip { name: "helix".into(), centre, offsets, nodes: vec![], theta_degrees: None };
        strip.validate(0).expect("valid strip");
        let steel = Material::preset("steel").expect("preset");
        let check = check_strip(&strip, &steel, 0.002);
        for i in 1..samples {
            assert!((check.curvature[i] * q / r - 1.0).abs() < 1e-3, "κ {} at {i}", check.curvature[i]);
            assert!((check.twist_rate[i] * q / h - 1.0).abs() < 1e-3, "τ {} at {i}", check.twist_rate[i]);
        }
        let sigma = steel.youngs_modulus * 0.001 * r / q;
        let shear = steel.shear_modulus * 0.002 * h / q;
        let expected = (sigma * sigma + 3.0 * shear * shear).sqrt() / steel.allowable_stress;
        assert!((check.max_utilisation / expected - 1.0).abs() < 1e-3);
    }
}
