//! Gridshells from nets of two curve families (paper Sec. 4.1) and 3-webs of three (Sec. 4.2):
//! two or three scalar fields on one mesh, each optimised toward its family (pseudo-geodesic,
//! geodesic or asymptotic, Eq. 8 and 13) with its fairness and gradient terms (Eq. 12), crossing
//! at a controlled angle (per triangle through the normalised gradients), a web's three held to
//! `F + G + H = 0` (Eq. 18); the net extracted as a quad mesh, the web as a triangle mesh (or a
//! Kagome pattern), strips for each family and the nodes where they cross.

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
mod strip_web;
mod web;

pub use intersection::intersection_angles;
pub use nodes::{flat_point, net_nodes, web_nodes, Node};
pub use params::{NetParams, WEB_GRADIENT_WEIGHT};
pub use quad_net::{extract_quad_net, quad_net_at, NetVertex, QuadNet};
pub use problem::NetProblem;
pub use report::{IntersectionReport, NetReport, WebReport};
pub use session::{NET_SESSION_MAGIC, NET_SESSION_VERSION};
pub use solver::NetSolver;
pub use start::{net_start, net_start_search, NetCandidate, NetStart, NetStartKind, ACCEPTABLE_FAMILY_SCORE, CLEARANCE_DEGREES, MAX_TANGENT_AREA, PAIR_HALF_ANGLE_DEGREES, START_CROSSING_DEGREES, TANGENT_PENALTY};
pub use strip_net::{strip_levels, strip_net, StripNet, NODE_TOLERANCE_EDGES};
pub use strip_web::{strip_web, StripWeb};
pub use web::{extract_web, web_levels, Web, WebLevels, WebVertex};
