//! Closest points on a triangle mesh within a fixed reach, for projecting sketched stroke points
//! onto the surface (Sec. 3.2.2, "Interactive steering").
//!
//! A uniform grid over the mesh's bounding box lists, per cell, the faces whose bounding box
//! grown by the reach overlaps the cell. Any face within the reach of a point is then listed in
//! the point's own cell, so a query tests only that cell's few faces.

use crate::mesh::{closest_barycentric, TriMesh, Vec3};

/// Most grid cells per face (bounds the memory of very flat or very long meshes).
const CELLS_PER_FACE: f64 = 4.0;

/// The closest surface point found for a query.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct SurfacePoint {
    pub face: u32,
    /// Barycentric coordinates with respect to the face's corners, in winding order.
    pub barycentric: [f64; 3],
    pub distance: f64,
}

pub(crate) struct SurfaceLocator<'a> {
    mesh: &'a TriMesh,
    reach: f64,
    origin: Vec3,
    cell: f64,
    dims: [usize; 3],
    /// Faces of cell c: `faces[cell_start[c]..cell_start[c + 1]]`, in increasing order.
    cell_start: Vec<usize>,
    faces: Vec<u32>,
}

impl<'a> SurfaceLocator<'a> {
    /// A locator for points within `reach` (finite, > 0) of `mesh`.
    pub(crate) fn new(mesh: &'a TriMesh, reach: f64) -> SurfaceLocator<'a> {
        let (lo, hi) = mesh.bounding_box();
        let origin = lo - Vec3::repeat(reach);
        let extent = hi - lo + Vec3::repeat(2.0 * reach);
        // Cells about twice the mean edge (and at least the reach), fewer if there would be too many.
        let budget = CELLS_PER_FACE * mesh.face_count() as f64;
        let mut cell = (2.0 * mesh.mean_edge_length()).max(reach);
        while extent.iter().map(|e| (e / cell).ceil().max(1.0)).product::<f64>() > budget {
            cell *= 1.5;
        }
        let dims = [0, 1, 2].map(|k| (extent[k] / cell).ceil().max(1.0) as usize);
        let index_range = |lo: f64, hi: f64, k: usize| {
            let clamp = |x: f64| ((x / cell).floor().max(0.0) as usize).min(dims[k] - 1);
            clamp(lo)..=clamp(hi)
        };
        // Counting pass, then fill (CSR), faces in increasing order within each cell.
        let mut boxes = Vec::with_capacity(mesh.face_count());
        for face in mesh.faces() {
            let corners = face.map(|c| mesh.positions()[c as usize] - origin);
            let fl = corners[0].inf(&corners[1]).inf(&corners[2]) - Vec3::repeat(reach);
            let fh = corners[0].sup(&corners[1]).sup(&corners[2]) + Vec3::repeat(reach);
            boxes.push([0, 1, 2].map(|k| index_range(fl[k], fh[k], k)));
        }
        let cell_index = |i: usize, j: usize, k: usize| (k * dims[1] + j) * dims[0] + i;
        let mut cell_start = vec![0usize; dims[0] * dims[1] * dims[2] + 1];
        let for_each_cell = |b: &[std::ops::RangeInclusive<usize>; 3], visit: &mut dyn FnMut(usize)| {
            for k in b[2].clone() {
                for j in b[1].clone() {
                    for i in b[0].clone() {
                        visit(cell_index(i, j, k));
                    }
                }
            }
        };
        for b in &boxes {
            for_each_cell(b, &mut |c| cell_start[c + 1] += 1);
        }
        for c in 0..cell_start.len() - 1 {
            cell_start[c + 1] += cell_start[c];
        }
        let mut fill = cell_start.clone();
        let mut faces = vec![0u32; cell_start[cell_start.len() - 1]];
        for (f, b) in boxes.iter().enumerate() {
            for_each_cell(b, &mut |c| {
                faces[fill[c]] = f as u32;
                fill[c] += 1;
            });
        }
        SurfaceLocator { mesh, reach, origin, cell, dims, cell_start, faces }
    }

    /// The closest point of the mesh to `p` if it lies within the reach; ties go to the lower face.
    pub(crate) fn closest(&self, p: &Vec3) -> Option<SurfacePoint> {
        let local = p - self.origin;
        let mut index = [0usize; 3];
        for k in 0..3 {
            let x = local[k] / self.cell;
            if !(x >= 0.0 && x < self.dims[k] as f64) {
                return None;
            }
            index[k] = x as usize;
        }
        let c = (index[2] * self.dims[1] + index[1]) * self.dims[0] + index[0];
        let mut best: Option<SurfacePoint> = None;
        for &f in &self.faces[self.cell_start[c]..self.cell_start[c + 1]] {
            let corners = self.mesh.faces()[f as usize].map(|v| self.mesh.positions()[v as usize]);
            let barycentric = closest_barycentric(p, &corners);
            let q = corners[0] * barycentric[0] + corners[1] * barycentric[1] + corners[2] * barycentric[2];
            let distance = (q - p).norm();
            if distance <= self.reach && best.is_none_or(|b| distance < b.distance) {
                best = Some(SurfacePoint { face: f, barycentric, distance });
            }
        }
        best
    }
}
