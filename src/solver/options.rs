//! Parameters of the Levenberg–Marquardt iteration (Madsen, Nielsen & Tingleff 2004, Alg. 3.16).

/// Options of [`super::LevenbergMarquardt`]. All fields are public; [`Default`] gives the values
/// documented on each field.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct LmOptions {
    /// Initial damping μ₀ = tau · max diag(JᵀJ). Default 1e-3 (MNT; use 1e-6 when the start is
    /// believed to be good, up to 1 when it is poor).
    pub tau: f64,
    /// ε1: converged when ‖Jᵀr‖∞ ≤ ε1. Default 1e-12.
    pub gradient_tolerance: f64,
    /// ε2: converged when the step satisfies ‖h‖ ≤ ε2 (‖x‖ + ε2). Default 1e-14.
    pub step_tolerance: f64,
    /// ε3: converged when E(x) ≤ ε3. Default 0 (only an exact zero residual).
    pub energy_tolerance: f64,
    /// Damped solves tried per iteration before giving up on it. Default 10.
    pub max_trials: usize,
    /// Lower bound on μ. Default 1e-20.
    pub min_damping: f64,
    /// Upper bound on μ. Default 1e20.
    pub max_damping: f64,
}

impl Default for LmOptions {
    fn default() -> Self {
        Self {
            tau: 1e-3,
            gradient_tolerance: 1e-12,
            step_tolerance: 1e-14,
            energy_tolerance: 0.0,
            max_trials: 10,
            min_damping: 1e-20,
            max_damping: 1e20,
        }
    }
}
