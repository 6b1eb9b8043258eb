//! Closest points on the triangle mesh: where a strip's base curve should stay (Sec. 3.4, the
//! binormal-strip optimisation) and how far it is from the surface (Appro of Table 4).
use crate::mesh::{TriMesh, Vec3};

/// The point of the mesh closest to a query point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfacePoint {
    pub point: Vec3,
    /// Unit normal interpolated linearly (barycentrically) from the vertex normals.
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
        let normals = face.map(|v| self.mesh.vertex_normals()[v as usize]);
        let corners = face.map(|v| self.mesh.positions()[v as usize]);
        let normal = (normals[0] * w[0] + normals[1] * w[1] + normals[2] * w[2])
            .try_normalize(0.0)
            .unwrap_or(self.mesh.face_normals()[f]);
        Some(SurfacePoint { point: corners[0] * w[0] + corners[1] * w[1] + corners[2] * w[2], normal, distance })
    }
}

/// Barycentric coordinates of the point of triangle `[a, b, c]` closest to `p` (Ericson,
/// Real-Time Collision Detection, Sec. 5.1.5: Voronoi regions of vertices, edges, face).
fn closest_barycentric(p: &Vec3, [a, b, c]: &[Vec3; 3]) -> [f64; 3] {
    let (ab, ac, ap) = (b - a, c - a, p - a);
    let (d1, d2) = (ab.dot(&ap), ac.dot(&ap));
    if d1 <= 0.0 && d2 <= 0.0 {
        return [1.0, 0.0, 0.0];
    }
    let bp = p - b;
    let (d3, d4) = (ab.dot(&bp), ac.dot(&bp));
    if d3 >= 0.0 && d4 <= d3 {
        return [0.0, 1.0, 0.0];
    }
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        let v = d1 / (d1 - d3);
        return [1.0 - v, v, 0.0];
    }
    let cp = p - c;
    let (d5, d6) = (ab.dot(&cp), ac.dot(&cp));
    if d6 >= 0.0 && d5 <= d6 {
        return [0.0, 0.0, 1.0];
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        let w = d2 / (d2 - d6);
        return [1.0 - w, 0.0, w];
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0 {
        let w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return [0.0, 1.0 - w, w];
    }
    // Inside the face; the mesh has no degenerate faces, so the denominator is positive.
    let denominator = 1.0 / (va + vb + vc);
    let (v, w) = (vb * denominator, vc * denominator);
    [1.0 - v - w, v, w]
}

#[cfg(test)]
mod tests {
    use super::closest_barycentric;
    use crate::mesh::Vec3;

    #[test]
    fn regions_of_a_triangle() {
        let t = [Vec3::zeros(), Vec3::x(), Vec3::y()];
        let inside = closest_barycentric(&Vec3::new(0.2, 0.3, 5.0), &t);
        assert!((inside[0] - 0.5).abs() < 1e-15 && (inside[1] - 0.2).abs() < 1e-15 && (inside[2] - 0.3).abs() < 1e-15);
        assert_eq!(closest_barycentric(&Vec3::new(-1.0, -1.0, 0.0), &t), [1.0, 0.0, 0.0]);
        let edge = closest_barycentric(&Vec3::new(0.5, -2.0, 1.0), &t);
        assert!((edge[1] - 0.5).abs() < 1e-15 && edge[2] == 0.0);
    }
}
