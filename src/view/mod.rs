//! A self-contained interactive 3D viewer of a design: one HTML file with the geometry embedded
//! (quantised, base64) and a small WebGL viewer written for the project, no network access and
//! no other files needed.
//!
//! The page shows the surface, the rectifying strips coloured per strip (or by family, by the
//! angle error of their rectifying planes, by bending utilisation when known), the level curves,
//! the rulings on demand and the flat (unrolled) strips beside the 3D view; hovering or clicking
//! a strip shows its Table 4 measures ([`crate::strips::StripMetrics`]). [`view_html`] builds the
//! page from a [`ViewScene`]; the same scene gives the same bytes.

mod base64;
mod error;
mod flat_layout;
mod page;
mod quantise;
mod scene;

pub use error::ViewError;
pub use flat_layout::{flat_layout, FlatPlacement};
pub use page::{view_html, SELF_CHECK_ID};
pub use quantise::{dequantise, QuantisedPoints, QUANTISATION_STEPS};
pub use scene::{family_name, polyline, ViewScene, ViewStrip, ViewSurface};
