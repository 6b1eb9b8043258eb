//! The triangle mesh: a validated, immutable [`TriMesh`] (a topological disk, possibly with
//! holes, paper Sec. 7) with the differential-geometry data the level-set optimiser needs:
//! normals, mixed Voronoi areas, ordered vertex stars (Fig. 7), per-face gradient operators,
//! boundary loops, edge → face adjacency, and unit scaling.

mod closest_point;
mod decimation;
mod edge_faces;
mod edge_point;
mod error;
mod face_bvh;
mod gradient;
mod local_quadric;
mod normals;
mod obj;
mod scaling;
pub(crate) mod small_fit;
mod star;
mod topology;
mod triangle;
mod trimesh;
mod union_find;
mod validation;
mod voronoi_area;

pub(crate) use closest_point::closest_barycentric;
pub use decimation::{coarsened, MAX_BOUNDARY_TURN_DEGREES, MAX_NORMAL_DEVIATION_DEGREES, MIN_TRIANGLE_QUALITY};
pub use edge_faces::EdgeFaces;
pub use edge_point::EdgePoint;
pub use error::MeshError;
pub use face_bvh::{ClosestFace, FaceBvh};
pub use local_quadric::{tangent_basis, vertex_neighbourhood, LocalQuadric};
pub use star::VertexStar;
pub use topology::BoundaryEdge;
pub use trimesh::TriMesh;
pub use validation::{diagnose, MAX_FOLD_DEGREES, MIN_NEIGHBOUR_AREA_RATIO};

/// A point or vector in 3-space.
pub type Vec3 = nalgebra::Vector3<f64>;
