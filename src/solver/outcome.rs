//! What one Levenberg–Marquardt iteration did.

/// The stopping rules of Madsen, Nielsen & Tingleff (2004).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Convergence {
    /// ‖Jᵀr‖∞ ≤ ε1.
    SmallGradient,
    /// ‖h‖ ≤ ε2 (‖x‖ + ε2).
    SmallStep,
    /// E(x) ≤ ε3.
    SmallEnergy,
}

/// Result of [`super::LevenbergMarquardt::iterate`].
#[derive(Clone, Debug, PartialEq)]
pub struct IterationOutcome {
    /// E(x) at the start of the iteration.
    pub energy_before: f64,
    /// E at the returned x (equal to `energy_before` when no step was accepted).
    pub energy_after: f64,
    /// Whether x was moved.
    pub accepted: bool,
    /// Damped solves attempted (0 when converged before solving).
    pub trials: usize,
    /// μ after the iteration's updates.
    pub damping: f64,
    /// ‖Jᵀr‖∞ at the start of the iteration.
    pub gradient_norm_inf: f64,
    /// ‖h‖₂ of the last computed step (0 if none).
    pub step_norm: f64,
    /// Set when a stopping rule holds.
    pub converged: Option<Convergence>,
}
