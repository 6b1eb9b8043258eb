//! The sun-path evaluation (not in the paper; what a designer needs to trust a shading design):
//! from sample points behind the surface, cast a ray towards the sun at every sampled hour and
//! count how many of the direct-sun hours the strips block, per sample and per region.
//!
//! A sample sees the sun directly at an hour when the sun lies in front of the surface there
//! (`l · n > 0`, `n` the surface normal turned towards the sun). Rays are tested against the
//! strips' triangles through a bounding-volume hierarchy ([`FaceBvh::ray_hits`]); samples are
//! processed in parallel and the result does not depend on the thread count.

use super::error::ShadingError;
use super::labels::VertexLabel;
use super::sun_path::SunSample;
use crate::mesh::{FaceBvh, TriMesh, Vec3};
use crate::strips::RectifyingStrip;
use rayon::prelude::*;

/// A point behind the surface and the region it belongs to.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SamplePoint {
    pub position: Vec3,
    /// Unit surface normal at the sample, turned towards the sun side.
    pub normal: Vec3,
    pub label: VertexLabel,
}

/// Blocked fraction of the direct-sun hours, per region (`None` for a region without samples
/// that see the sun).
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize)]
pub struct RegionFractions {
    pub block: Option<f64>,
    pub pass: Option<f64>,
    pub free: Option<f64>,
}

/// The outcome of the evaluation.
#[derive(Clone, Debug, PartialEq)]
pub struct SunPathEvaluation {
    /// Per sample: blocked fraction of its direct-sun hours (`None` if the sun never reaches it).
    pub sample_fractions: Vec<Option<f64>>,
    /// Per sun sample: fraction of the samples in direct sun at that hour that are blocked.
    pub sun_fractions: Vec<Option<f64>>,
    /// Over all (sample, hour) pairs with direct sun, per region.
    pub regions: RegionFractions,
    /// Rays cast.
    pub rays: usize,
}

/// The samples of a surface: its vertices moved `offset` (> 0, model units) along the vertex
/// normal away from the sun, labelled as the vertices. The normals are turned as one, towards
/// the side the mean sun direction of `suns` lies on over the whole surface (area-weighted), so
/// that "behind" is the same side everywhere: on a curved facade the mean sun may lie behind
/// some vertices' tangent planes, and those must not be turned on their own.
pub fn samples_behind(mesh: &TriMesh, labels: &[VertexLabel], suns: &[SunSample], offset: f64) -> Result<Vec<SamplePoint>, ShadingError> {
    if labels.len() != mesh.vertex_count() {
        return Err(ShadingError::invalid("labels", format!("{} labels for {} vertices", labels.len(), mesh.vertex_count())));
    }
    if !(offset.is_finite() && offset > 0.0) {
        return Err(ShadingError::invalid("offset", format!("must be finite and > 0, got {offset}")));
    }
    if suns.is_empty() {
        return Err(ShadingError::SunNeverUp);
    }
    let mean_sun: Vec3 = suns.iter().map(|s| s.direction).sum();
    let facing: f64 = mesh.smooth_normals().iter().zip(mesh.vertex_areas()).map(|(n, area)| area * n.dot(&mean_sun)).sum();
    let side = if facing < 0.0 { -1.0 } else { 1.0 };
    Ok(mesh
        .positions()
        .iter()
        .zip(mesh.smooth_normals())
        .zip(labels)
        .map(|((p, n), &label)| {
            let normal = side * n;
            SamplePoint { position: p - normal * offset, normal, label }
        })
        .collect())
}

/// The triangles of the strips (two per quad between the left and right boundaries).
pub fn strip_triangles(strips: &[RectifyingStrip]) -> Vec<[Vec3; 3]> {
    let mut triangles = Vec::new();
    for strip in strips {
        for i in 0..strip.left.len().saturating_sub(1).min(strip.right.len().saturating_sub(1)) {
            let (a, b, c, d) = (strip.left[i], strip.left[i + 1], strip.right[i + 1], strip.right[i]);
            triangles.push([a, b, c]);
            triangles.push([a, c, d]);
        }
    }
    triangles
}

/// Casts the rays of every sample towards every sun of `suns` it sees directly, through the
/// triangles `obstacles`. Errors on non-finite input (naming the sample or triangle).
pub fn evaluate_sun_path(obstacles: &[[Vec3; 3]], samples: &[SamplePoint], suns: &[SunSample]) -> Result<SunPathEvaluation, ShadingError> {
    let finite = |v: &Vec3| v.iter().all(|x| x.is_finite());
    if let Some(k) = samples.iter().position(|s| !finite(&s.position) || !finite(&s.normal)) {
        return Err(ShadingError::invalid("samples", format!("sample {k} is not finite")));
    }
    if let Some(k) = obstacles.iter().position(|t| !t.iter().all(finite)) {
        return Err(ShadingError::invalid("obstacles", format!("triangle {k} is not finite")));
    }
    let bvh = FaceBvh::over_triangles(obstacles);
    // Per sample: (blocked, lit) flags per sun.
    let outcomes: Vec<Vec<Option<bool>>> = samples
        .par_iter()
        .map(|sample| suns.iter().map(|sun| (sun.direction.dot(&sample.normal) > 0.0).then(|| bvh.ray_hits(obstacles, &sample.position, &sun.direction))).collect())
        .collect();
    let fraction = |blocked: usize, lit: usize| (lit > 0).then(|| blocked as f64 / lit as f64);
    let count = |flags: &mut dyn Iterator<Item = &Option<bool>>| flags.flatten().fold((0, 0), |(b, l), &hit| (b + hit as usize, l + 1));
    let sample_fractions = outcomes.iter().map(|o| { let (b, l) = count(&mut o.iter()); fraction(b, l) }).collect();
    let sun_fractions = (0..suns.len()).map(|s| { let (b, l) = count(&mut outcomes.iter().map(|o| &o[s])); fraction(b, l) }).collect();
    let region = |label: VertexLabel| {
        let (b, l) = count(&mut samples.iter().zip(&outcomes).filter(|(s, _)| s.label == label).flat_map(|(_, o)| o.iter()));
        fraction(b, l)
    };
    let rays = outcomes.iter().map(|o| o.iter().flatten().count()).sum();
    Ok(SunPathEvaluation {
        sample_fractions,
        sun_fractions,
        regions: RegionFractions { block: region(VertexLabel::Block), pass: region(VertexLabel::Pass), free: region(VertexLabel::Free) },
        rays,
    })
}
