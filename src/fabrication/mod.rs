//! Fabrication: what a workshop needs to make the strips of a pattern.
//!
//! - [`Material`]: presets (timber, plywood, steel, aluminium) or the user's `E`, `G` and
//!   allowable stress;
//! - [`check_strip`]: the bending and twisting check of a strip of given thickness from its centre
//!   line and rectifying frame (weak-axis stress `E t κ / 2`, torsional shear `G t τ`, von Mises
//!   utilisation, the worst point);
//! - [`plan_fabrication`]: strips longer than the [`Stock`] split into overlapping pieces
//!   `<strip>-<k>` with splices where they bend least and away from nodes, the pieces laid out
//!   by first-fit-decreasing shelf packing on boards, with the material yield;
//! - outputs: [`cut_dxf`] (R12 DXF, mm, layers OUTLINE, LABEL, MARKS, CENTRELINE, STOCK),
//!   [`cut_svg`] (the same drawing), [`bom_csv`] / [`bom_rows`] (the bill of materials).
//!
//! The strips are those of Sec. 3.4 (Fig. 20): centre line, rulings and flat unrolling.
mod bending;
mod bom;
mod dxf;
mod error;
mod material;
mod packing;
mod piece;
mod plan;
mod sheet;
mod splicing;
mod strip_input;
mod svg;

pub use bending::{check_strip, validate_thickness, StripCheck};
pub use bom::{bom_csv, bom_rows, BomRow};
pub use dxf::cut_dxf;
pub use error::FabricationError;
pub use material::{Material, PRESET_NAMES};
pub use packing::Placement;
pub use piece::{FlatShape, Label, CHARACTER_WIDTH};
pub use plan::{family_name, plan_fabrication, FabricationParams, FabricationPlan, Piece, Stock};
pub use sheet::{sheet, utilisation_rgb, Item, Layer, Sheet, MM};
pub use strip_input::FabricationStrip;
pub use svg::cut_svg;
