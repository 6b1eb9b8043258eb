//! Closest points on the triangle mesh: where a strip's base curve should stay (Sec. 3.4, the
//! binormal-strip optimisation) and how far it is from the surface (Appro of Table 4).
use crate::mesh::{closest_barycentric, TriMesh, Vec3};

/// The point of the mesh closest to a query point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfacePoint {
    pub point: Vec3,
    /// Unit normal interpolated linearly (barycentrically) from the smooth (second-order) vertex
    /// normals, [`TriMesh::smooth_normals`].
    pub normal: Vec3,
    pub distance: f64,
}

/// Brute-force closest-point queries, pruned by bounding spheres of the faces.
pub struct SurfaceProjector<'a> {
    mesh: &'a TriMesh,
    /// Centroid and circumscribing radius (about the centroid) of each face.
    spheres: Vec<(Vec3, f64)>,
}

impl<'a> SurfaceProjector<'a> {
    pub fn new(mesh: &'a TriMesh) -> Self {
        let spheres = mesh
            .faces()
            .iter()
            .map(|f| {
                let corners = f.map(|v| mesh.positions()[v as usize]);
                let centre = (corners[0] + corners[1] + corners[2]) / 3.0;
                let radius = corners.iter().map(|c| (c - centre).norm()).fold(0.0, f64::max);
                (centre, radius)
            })
            .collect();
        SurfaceProjector { mesh, spheres }
    }

    /// The closest point of the mesh to `query` (ties: the lowest face index). `None` only for a
    /// non-finite query.
    pub fn project(&self, query: &Vec3) -> Option<SurfacePoint> {
        if !query.iter().all(|x| x.is_finite()) {
            return None;
        }
        let mut best: Option<(f64, usize, [f64; 3])> = None;
        for (f, &(centre, radius)) in self.spheres.iter().enumerate() {
            let bound = (query - centre).norm() - radius;
            if best.is_some_and(|(d, _, _)| bound > d) {
                continue;
            }
            let corners = self.mesh.faces()[f].map(|v| self.mesh.positions()[v as usize]);
            let weights = closest_barycentric(query, &corners);
            let point = corners[0] * weights[0] + corners[1] * weights[1] + corners[2] * weights[2];
            let distance = (query - point).norm();
            if best.is_none_or(|(d, _, _)| distance < d) {
                best = Some((distance, f, weights));
            }
        }
        let (distance, f, w) = best?;
        let face = self.mesh.faces()[f];
        let normals = face.map(|v| self.mesh.smooth_normals()[v as usize]);
        let corners = face.map(|v| self.mesh.positions()[v as usize]);
        let normal = (normals[0] * w[0] + normals[1] * w[1] + normals[2] * w[2])
            .try_normalize(0.0)
            .unwrap_or(self.mesh.face_normals()[f]);
        Some(SurfacePoint { point: corners[0] * w[0] + corners[1] * w[1] + corners[2] * w[2], normal, distance })
    }
}
