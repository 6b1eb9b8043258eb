//! Uniform scaling about the origin (no translation), in particular to mean edge length 1
//! (the "unit scale" the paper's default parameters assume).

use super::error::MeshError;
use super::trimesh::TriMesh;

impl TriMesh {
    /// A copy with every coordinate multiplied by `factor`, all derived data recomputed.
    /// Fails if `factor` is not finite and positive, or if the scaled geometry leaves the range
    /// of `f64` (overflowing coordinates, underflowing areas).
    pub fn try_scaled(&self, factor: f64) -> Result<TriMesh, MeshError> {
        if !(factor > 0.0 && factor.is_finite()) {
            return Err(MeshError::InvalidScaleFactor { factor });
        }
        let positions = self.positions().iter().map(|p| p * factor).collect();
        TriMesh::from_vertices_and_faces(positions, self.faces().to_vec())
    }

    /// Uniformly scaled copy (no translation), all derived data consistent. If `factor` is not
    /// finite and positive, or the scaled geometry would leave the range of `f64`, the copy is
    /// unscaled (use [`TriMesh::try_scaled`] to detect that).
    pub fn scaled(&self, factor: f64) -> TriMesh {
        self.try_scaled(factor).unwrap_or_else(|_| self.clone())
    }

    /// Copy with mean edge length 1, and the factor applied (1 / old mean edge length).
    pub fn unit_scaled(&self) -> (TriMesh, f64) {
        let factor = 1.0 / self.mean_edge_length();
        match self.try_scaled(factor) {
            Ok(mesh) => (mesh, factor),
            Err(_) => (self.clone(), 1.0),
        }
    }
}
