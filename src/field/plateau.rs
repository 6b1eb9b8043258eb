//! When the level curves have stopped improving: the final stage's convergence test as an
//! outside reviewer would judge it.
//!
//! Once the curve term is met (Eq. 8–10 or 13 within [`super::params::FAMILY_MET_CURVE_ENERGY`]
//! per curve vertex, and `E_angle` within the paper's [`super::params::PAPER_ANGLE_ENERGY`]),
//! what the iterations still lower is mostly the regularisers and the auxiliaries' constraints,
//! often by a few per cent per iteration for a hundred iterations and more, while the level
//! curves measured from outside ([`crate::quality::family_angles`]) no longer improve beyond the
//! noise of where the levels fall, or drift to straighter, worse families. So every
//! [`CHECK_ITERATIONS`] final-stage iterations the solver measures [`LEVELS`] level curves; when
//! [`PATIENCE`] such measures in a row fail to lower the best score so far by [`GAIN`], the stage
//! has converged. Not in the start search's probes, which run a fixed number of iterations so
//! that every start is judged after the same solve.

use serde::{Deserialize, Serialize};

use crate::field::Family;
use crate::mesh::TriMesh;
use crate::quality::{level_set_angles, DEFAULT_SPACING_EDGES};

/// Final-stage iterations between two measures of the level curves.
pub const CHECK_ITERATIONS: usize = 5;
/// Measures in a row without a gain after which the level curves count as settled.
pub const PATIENCE: usize = 2;
/// Relative decrease of the best score that counts as a gain.
pub const GAIN: f64 = 0.02;
/// Level curves measured, as the start search measures a probe.
pub const LEVELS: usize = 12;
/// Fewest vertices of a mesh whose level curves are judged this way. On coarser meshes the
/// measure has too few points (about 40 to 70 on a 400-vertex roof, against 80 to 180 at 3,000
/// vertices) and moves by more than [`GAIN`] with where the levels fall: on that roof it stopped
/// one solve at a better family than the energy's tests reach and another at a worse one.
pub const MIN_VERTICES: usize = 1_000;

/// The best score of the level curves in the current stage and the measures since it.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub(crate) struct Plateau {
    /// Lowest [`crate::quality::FamilyAngles::score`] measured in the stage (∞ before the first).
    best: f64,
    /// Measures since the best one.
    measures_since_best: usize,
}

impl Default for Plateau {
    fn default() -> Self {
        Plateau { best: f64::INFINITY, measures_since_best: 0 }
    }
}

impl Plateau {
    /// Whether the level curves are measured after final-stage iteration `stage_iterations` of a
    /// family of `family` on a mesh of `vertices`: every [`CHECK_ITERATIONS`] from
    /// [`MIN_VERTICES`] on; never for constant slope, whose measure is another
    /// ([`crate::quality::slope_angles`]).
    pub fn due(stage_iterations: usize, family: Family, vertices: usize) -> bool {
        vertices >= MIN_VERTICES && stage_iterations % CHECK_ITERATIONS == 0 && !matches!(family, Family::ConstantSlope { .. })
    }

    /// Measures the level curves of `field` on `mesh`; true once they have stopped improving.
    /// A field whose level curves cannot be measured does not settle this way.
    pub fn settled(&mut self, mesh: &TriMesh, field: &[f64], family: Family) -> bool {
        let Ok(measure) = level_set_angles(mesh, field, family, LEVELS, DEFAULT_SPACING_EDGES) else {
            return false;
        };
        self.record(measure.score())
    }

    /// Takes a measure's `score`; true once [`PATIENCE`] measures in a row have not lowered the
    /// best by [`GAIN`].
    fn record(&mut self, score: f64) -> bool {
        if score < (1.0 - GAIN) * self.best {
            self.best = score;
            self.measures_since_best = 0;
        } else {
            self.measures_since_best += 1;
        }
        self.measures_since_best >= PATIENCE
    }

    /// The state is one this type can be in: a best score that is ∞ or finite and ≥ 0, and no
    /// more measures since it than settle the stage.
    pub fn is_valid(&self) -> bool {
        (self.best == f64::INFINITY || (self.best.is_finite() && self.best >= 0.0)) && self.measures_since_best <= PATIENCE
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn settles_after(scores: &[f64]) -> Option<usize> {
        let mut plateau = Plateau::default();
        scores.iter().position(|&score| plateau.record(score)).map(|i| i + 1)
    }

    #[test]
    fn settles_once_two_measures_in_a_row_do_not_gain_two_percent() {
        // 8.9 and 8.85 are within 2 % of 9: the second of them settles.
        assert_eq!(settles_after(&[10.0, 9.0, 8.9, 8.85]), Some(4));
        // A worse measure counts as no gain; a gain in between starts the count again.
        assert_eq!(settles_after(&[10.0, 11.0, 9.0, 9.5, 8.0, 8.0, 8.0]), Some(7));
        // Steady gains of 5 % never settle.
        let falling: Vec<f64> = (0..20).map(|k| 10.0 * 0.95f64.powi(k)).collect();
        assert_eq!(settles_after(&falling), None);
    }

    #[test]
    fn only_meshes_of_enough_vertices_and_every_few_iterations_are_measured() {
        let family = Family::PseudoGeodesic { theta_degrees: 45.0 };
        assert!(Plateau::due(CHECK_ITERATIONS, family, MIN_VERTICES));
        assert!(!Plateau::due(CHECK_ITERATIONS + 1, family, MIN_VERTICES));
        assert!(!Plateau::due(CHECK_ITERATIONS, family, MIN_VERTICES - 1));
        assert!(!Plateau::due(CHECK_ITERATIONS, Family::ConstantSlope { axis: [0.0, 0.0, 1.0], slope_degrees: 30.0, free_slope: false }, MIN_VERTICES));
    }

    #[test]
    fn a_saved_state_out_of_range_is_invalid() {
        assert!(Plateau::default().is_valid());
        assert!(Plateau { best: 3.0, measures_since_best: PATIENCE }.is_valid());
        assert!(!Plateau { best: f64::NAN, measures_since_best: 0 }.is_valid());
        assert!(!Plateau { best: -1.0, measures_since_best: 0 }.is_valid());
        assert!(!Plateau { best: 3.0, measures_since_best: PATIENCE + 1 }.is_valid());
    }
}
