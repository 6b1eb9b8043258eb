//! Gridshells from nets of two curve families (paper Sec. 4.1): two scalar fields on one mesh,
//! each optimised toward its family (pseudo-geodesic, geodesic or asymptotic, Eq. 8 and 13) with
//! its fairness and gradient terms (Eq. 12), crossing at a controlled angle (per triangle through
//! the normalised gradients); the net extracted as a quad mesh, strips for each family and the
//! nodes where they cross.

mod intersection;
mod nodes;
mod params;
mod problem;
mod quad_net;
mod report;
mod session;
mod solver;
mod start;
mod strip_net;

pub use intersection::intersection_angles;
pub use nodes::{flat_point, net_nodes, Node};
pub use params::NetParams;
pub use quad_net::{extract_quad_net, quad_net_at, NetVertex, QuadNet};
pub use problem::NetProblem;
pub use report::{IntersectionReport, NetReport};
pub use session::{NET_SESSION_MAGIC, NET_SESSION_VERSION};
pub use solver::NetSolver;
pub use start::{net_start, START_CROSSING_DEGREES};
pub use strip_net::{strip_levels, strip_net, StripNet, NODE_TOLERANCE_EDGES};
