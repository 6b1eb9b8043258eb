//! The sun-path check of a shading design (not in the paper): the sun every hour of every day
//! of the site's dates, rays from samples behind every vertex through the strips, each vertex
//! judged with the suns of its own region (the pass region's hours for `Pass` vertices).

use super::error::ShadingError;
use super::evaluation::{evaluate_sun_path, samples_behind, strip_triangles, SunPathEvaluation};
use super::labels::VertexLabel;
use super::site::Site;
use super::sun_path::{sun_samples, SunSample};
use crate::mesh::TriMesh;
use crate::strips::RectifyingStrip;

/// Hours between the sun rays of the check (every day of the dates).
pub const CHECK_HOUR_STEP: f64 = 1.0;

/// The outcome of [`sun_path_check`].
#[derive(Clone, Debug, PartialEq)]
pub struct SunPathCheck {
    /// The suns of the block site and of the pass site.
    pub block_suns: Vec<SunSample>,
    pub pass_suns: Vec<SunSample>,
    /// Every sample against the block site's suns, and against the pass site's.
    pub block: SunPathEvaluation,
    pub pass: SunPathEvaluation,
    /// Per vertex: the blocked fraction of its direct-sun hours of its own region (`None` where
    /// the sun never reaches it).
    pub vertex_fractions: Vec<Option<f64>>,
}

impl SunPathCheck {
    /// Blocked fraction of the direct-sun hours of the block region's vertices (block suns).
    pub fn block_fraction(&self) -> Option<f64> {
        self.block.regions.block
    }

    /// Blocked fraction of the direct-sun hours of the pass region's vertices (pass suns).
    pub fn pass_fraction(&self) -> Option<f64> {
        self.pass.regions.pass
    }

    /// Rays cast in both evaluations.
    pub fn rays(&self) -> usize {
        self.block.rays + self.pass.rays
    }
}

/// Checks `strips` on `mesh` (with one label per vertex) against the suns of `site` (block and
/// free vertices) and `pass_site` (pass vertices), from samples `offset` (> 0) behind the
/// vertices. Errors name the parameter.
pub fn sun_path_check(mesh: &TriMesh, labels: &[VertexLabel], strips: &[RectifyingStrip], site: &Site, pass_site: &Site, offset: f64) -> Result<SunPathCheck, ShadingError> {
    let block_suns = sun_samples(site, 1, CHECK_HOUR_STEP)?;
    let pass_suns = sun_samples(pass_site, 1, CHECK_HOUR_STEP)?;
    let triangles = strip_triangles(strips);
    let all_suns: Vec<SunSample> = block_suns.iter().chain(&pass_suns).copied().collect();
    let samples = samples_behind(mesh, labels, &all_suns, offset)?;
    let block = evaluate_sun_path(&triangles, &samples, &block_suns)?;
    let pass = evaluate_sun_path(&triangles, &samples, &pass_suns)?;
    let vertex_fractions =
        labels.iter().enumerate().map(|(v, l)| if *l == VertexLabel::Pass { pass.sample_fractions[v] } else { block.sample_fractions[v] }).collect();
    Ok(SunPathCheck { block_suns, pass_suns, block, pass, vertex_fractions })
}
