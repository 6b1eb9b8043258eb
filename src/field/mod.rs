pub mod hessian_energy;
