//! Parameters of the strip computation (Sec. 3.4).
use serde::{Deserialize, Serialize};

/// Weights λ of the strip energies; each residual is multiplied by `√λ`. Lengths are measured
/// in units of the polyline's mean edge length, so the defaults suit any scale.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct StripWeights {
    /// Eq. 8 on polyline vertices: `(b·n)² − cos²θ` and `(b·n)(b·u) − sinθ cosθ`; with the
    /// planarity weight (`√(λ_angle λ_planarity)`), Eq. 8 on the quad normals, which make the angle
    /// 90° − θ with the surface normal.
    pub angle: f64,
    /// Eq. 9 on polyline vertices: `b·ê_{i−1}`, `b·ê_i`, `b·b − 1`.
    pub binormal: f64,
    /// Distance to the surface along its normal, `(c − c*)·n*` (c* the closest surface point).
    /// Default 0.01: where the base curve is close to a straight line or turns through an
    /// inflection, keeping θ, planar quads and a straight unrolling at once needs it to leave the
    /// surface a little (Table 4: "can slightly change the base curve"); Appro reports by how
    /// much (0.02–0.13 % of the diagonal on the paper's Hall, Wave and quad meshes; on a surface
    /// with no family of θ the curves may stray further, and the verdict still fails them).
    pub surface: f64,
    /// Tangential drift `c − c*`: keeps the vertices from sliding along the surface.
    pub slide: f64,
    /// The fairness regulariser `c_{i−1} − 2c_i + c_{i+1}` (Sec. 3.4); used in the binormal-strip
    /// stage and the first rectifying-strip round, 0 in the final round.
    pub fair: f64,
    /// Eq. 16–17: `d_i·(ê_i − ê_{i−1})`, `d·d − 1` and `N·d_i`, `N·d_{i+1}`, `N·ê_i`, `N·N − 1`.
    pub planarity: f64,
    /// Proximity of the rulings to their initial guess (the version-1 model of Fig. 19); used in the
    /// first rectifying-strip round, 0 in the final round.
    pub ruling_anchor: f64,
}

impl Default for StripWeights {
    fn default() -> Self {
        StripWeights { angle: 1.0, binormal: 1.0, surface: 0.01, slide: 1e-4, fair: 1e-4, planarity: 1.0, ruling_anchor: 1e-3 }
    }
}

/// Most binormal-strip rounds ([`StripParams::binormal_rounds`]) a computation accepts.
pub const MAX_STRIP_ROUNDS: usize = 32;
/// Most Levenberg–Marquardt iterations of one strip stage ([`StripParams::iterations_per_round`],
/// [`StripParams::final_iterations`], [`StripParams::polish_iterations`]); with
/// [`MAX_STRIP_ROUNDS`] this bounds a strip to 17,500 iterations.
pub const MAX_STRIP_ITERATIONS: usize = 500;

/// What strips to build and how hard to optimise them.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct StripParams {
    /// Target angle θ between binormal and surface normal, in degrees (the field's θ).
    pub theta_degrees: f64,
    /// Strip width: the distance between the two straight boundaries of the flat strip.
    pub width: f64,
    pub weights: StripWeights,
    /// Binormal-strip stage: rounds of (project onto the surface, then Levenberg–Marquardt),
    /// at most [`MAX_STRIP_ROUNDS`].
    pub binormal_rounds: usize,
    /// Levenberg–Marquardt iterations per binormal-strip round and in the regularised
    /// rectifying-strip round.
    pub iterations_per_round: usize,
    /// Iterations of the final rectifying-strip round (fairness and ruling anchor at weight 0).
    pub final_iterations: usize,
    /// Iterations of the closing polish: positions held, rulings and quad normals solved for
    /// exact planarity (Eq. 16–17 only).
    pub polish_iterations: usize,
    /// Largest angle error (degrees, in (0, 180)) of a quad in an acceptable pattern (see
    /// [`super::Verdict`]). Default 2°.
    pub tolerance_degrees: f64,
}

impl StripParams {
    /// Defaults for a target angle and a strip width.
    pub fn new(theta_degrees: f64, width: f64) -> Self {
        StripParams {
            theta_degrees,
            width,
            weights: StripWeights::default(),
            binormal_rounds: 8,
            iterations_per_round: 15,
            final_iterations: 60,
            polish_iterations: 30,
            tolerance_degrees: super::verdict::DEFAULT_TOLERANCE_DEGREES,
        }
    }
}
