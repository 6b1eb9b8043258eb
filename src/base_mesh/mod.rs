//! Optimisation of base meshes for strip structures (paper Sec. 3.5) and torsion-free nodes
//! (Sec. 5.2.1, Eq. 21): a net of rows and columns (from [`crate::net`] or given) is moved so
//! that its polylines form the asked families exactly (pseudo-geodesic, geodesic or asymptotic)
//! near a reference surface, optionally with a common ruling at every node shared by both strips;
//! then every polyline carries a developable strip of planar quads. A session saves to bytes and
//! restores bit for bit ([`BaseMeshSolver::to_bytes`], [`BaseMeshSolver::from_bytes`]).

mod error;
mod net_mesh;
mod node_torsion;
mod params;
mod problem;
mod report;
mod session;
mod solver;
mod start;
mod strips;

pub use error::BaseMeshError;
pub use net_mesh::{NetMesh, MAX_NET_VERTICES};
pub use node_torsion::{node_rulings, polyline_rulings, NodeRuling, NodeTorsion, PolylineRulings, TORSION_FREE_DEGREES};
pub use params::{BaseMeshParams, BaseMeshWeights};
pub use report::{BaseMeshReport, Deviation};
pub use session::{BASE_MESH_SESSION_MAGIC, BASE_MESH_SESSION_VERSION};
pub use solver::BaseMeshSolver;
