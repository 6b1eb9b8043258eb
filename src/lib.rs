//! Lamella: rectifying strip patterns (Wang, Wang, Schling, Pottmann, SIGGRAPH Asia 2023).
//!
//! The pipeline, one module per stage: a validated triangle [`mesh`]; guide curves [`tracing`]
//! on it (Sec. 3.2.1); a scalar [`field`] whose level sets are pseudo-geodesics, optimised by
//! the sparse Levenberg–Marquardt [`solver`] from an [`initialisation`] (guide curves or
//! sketched strokes, and the automatic design);
//! its level [`curves`]; the rectifying developable [`strips`] along them with their flat
//! unrollings; gridshells from [`net`]s of two families (Sec. 4.1) and the optimisation of their
//! [`base_mesh`] toward exact families and torsion-free nodes (Sec. 3.5, 5.2); what a workshop needs to
//! make them in [`fabrication`]; the outside reviewer's measures of the results in [`quality`];
//! a self-contained interactive 3D [`view`] of a design (one HTML file); the C ABI in
//! [`ffi`]; procedural [`surfaces`] for tests and the demo; [`input`]: the size limit of input
//! files and the bounds on text quoted in error messages.
pub mod base_mesh;
pub mod curves;
pub mod fabrication;
pub mod ffi;
pub mod field;
pub mod initialisation;
pub mod input;
pub mod mesh;
pub mod net;
pub mod quality;
pub mod reshape;
pub mod shading;
pub mod solver;
pub mod strips;
pub mod surfaces;
pub mod tracing;
pub mod view;
