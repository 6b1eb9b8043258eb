//! Closest points on the triangle mesh: where a strip's base curve should stay (Sec. 3.4, the
//! binormal-strip optimisation) and how far it is from the surface (Appro of Table 4).
use crate::mesh::{FaceBvh, TriMesh, Vec3};

/// The point of the mesh closest to a query point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfacePoint {
    pub point: Vec3,
    /// Unit normal interpolated linearly (barycentrically) from the smooth (second-order) vertex
    /// normals, [`TriMesh::smooth_normals`].
    pub normal: Vec3,
    pub distance: f64,
}

/// Closest-point queries through a bounding-volume hierarchy of the faces, built once.
pub struct SurfaceProjector<'a> {
    mesh: &'a TriMesh,
    bvh: FaceBvh,
}

impl<'a> SurfaceProjector<'a> {
    pub fn new(mesh: &'a TriMesh) -> Self {
        SurfaceProjector { mesh, bvh: FaceBvh::new(mesh) }
    }

    /// The closest point of the mesh to `query` (ties: the lowest face index). `None` only for a
    /// non-finite query.
    pub fn project(&self, query: &Vec3) -> Option<SurfacePoint> {
        project_on(self.mesh, &self.bvh, query)
    }
}

/// The closest point of `mesh` to `query` through `bvh` (built on `mesh`), as
/// [`SurfaceProjector::project`]: for holders of a mesh and its hierarchy that outlive one query
/// pass.
pub fn project_on(mesh: &TriMesh, bvh: &FaceBvh, query: &Vec3) -> Option<SurfacePoint> {
    let closest = bvh.closest(mesh, query)?;
    let (distance, f, w) = (closest.distance, closest.face, closest.weights);
    let face = mesh.faces()[f];
    let normals = face.map(|v| mesh.smooth_normals()[v as usize]);
    let corners = face.map(|v| mesh.positions()[v as usize]);
    let normal = (normals[0] * w[0] + normals[1] * w[1] + normals[2] * w[2]).try_normalize(0.0).unwrap_or(mesh.face_normals()[f]);
    Some(SurfacePoint { point: corners[0] * w[0] + corners[1] * w[1] + corners[2] * w[2], normal, distance })
}
