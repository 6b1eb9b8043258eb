//! Lamella: rectifying strip patterns (Wang, Wang, Schling, Pottmann, SIGGRAPH Asia 2023).
pub mod mesh;
pub mod solver;
pub mod field;
pub mod surfaces;
pub mod curves;
pub mod strips;
