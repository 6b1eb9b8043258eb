//! Lamella's integration tests, one module per capability, compiled into one test binary (one
//! build and link instead of fifty; the suite's shared fixtures, such as the optimised 60° cylinder
//! field, are computed once per run). Run one area with a filter: `cargo test --test integration
//! strips_` or one module: `cargo test --test integration cli_design::`.
//!
//! `fuzz` (its own driver), `solver_allocation` (a counting global allocator) and `ffi_header`
//! (regenerates include/lamella.h) stay separate binaries.

// Shared fixtures and independent reference computations.
mod cli_support;
mod fabrication_support;
mod field_support;
mod initialisation_support;
mod mesh_support;
mod solver_support;
mod strips_support;
mod tracing_support;

mod cli_design;
mod cli_errors;
mod cli_fabricate;
mod cli_guides;
mod cli_net;
mod cli_optimise;
mod cli_reshape;
mod cli_shade;
mod cli_slope;
mod cli_steps;
mod cli_surface;
mod cli_view;

mod curves_extraction;

mod design_default_start;

mod fabrication_bending;
mod fabrication_cut_files;

mod field_asymptotic;
mod field_constant_slope;
mod field_cylinder;
mod field_input;
mod field_residuals;
mod field_session;
mod field_varying_angle;

mod hessian_energy;

mod hostile_input;

mod initialisation_conformal;
mod initialisation_errors;
mod initialisation_guides;
mod initialisation_strokes;
mod initialisation_traced;

mod mesh_decimation;
mod mesh_geometry;
mod mesh_topology;
mod mesh_validation;

mod net_two_families;
mod net_webs;

mod obj_io;

mod reshape_cylinder;

mod shading;

mod solver_constant_jacobians;
mod solver_errors;
mod solver_jacobian_check;
mod solver_lm;
mod solver_schur;

mod strips_cylinder;
mod strips_diagnostics;
mod strips_frenet;
mod strips_input;
mod strips_vault;

mod surfaces_brauner;
mod surfaces_generators;

mod tracing_asymptotic;
mod tracing_cylinder;
mod tracing_errors;
mod tracing_intersections;
mod tracing_seeding;

mod view_page;
mod base_mesh_optimisation;
mod base_mesh_webs;
mod base_mesh_session;
