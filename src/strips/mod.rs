//! Rectifying developable strips along level curves (paper Sec. 2.1, 3.4, Fig. 18–20, Table 4):
//! binormal-strip optimisation of each polyline (Eq. 8–10 on polyline vertices), discrete
//! rectifying developables (version 1, Fig. 19, and the preferred strip of planar quads, Fig. 20,
//! Eq. 16–17, solved with the crate's Levenberg–Marquardt), flat unrollings, the quality measures
//! of Table 4, the verdict on a pattern and the node diagnostics of Sec. 5.1 (Prop. 1–2).

mod builder;
mod diagnostics;
mod error;
mod frenet;
mod metrics;
mod params;
mod problem;
mod reflection;
mod strip;
mod surface_distance;
mod unrolling;
mod verdict;

pub use builder::rectifying_strips;
pub(crate) use builder::{strip_with_rulings, StripLines};
pub use diagnostics::{strip_diagnostics, VertexDiagnostics, SINGULAR_POINT_CLEARANCE_WIDTHS};
pub use error::{StripError, StripWarning};
pub use frenet::{discrete_binormals, initial_rulings, principal_normals, unit_edges, version_one_rulings};
pub use metrics::{PatternMetrics, StripGeometry, StripMetrics, StripShape};
pub use params::{StripParams, StripWeights, MAX_STRIP_ITERATIONS, MAX_STRIP_ROUNDS};
pub use reflection::{fitted_rulings, reflected_rulings};
pub use strip::{RectifyingStrip, SkippedCurve, StripPattern};
pub use surface_distance::{project_on, SurfacePoint, SurfaceProjector};
pub use unrolling::{straightness, unroll, Unrolling};
pub use verdict::{Verdict, WorstQuad, DEFAULT_TOLERANCE_DEGREES, MAX_APPRO_PERCENT};
