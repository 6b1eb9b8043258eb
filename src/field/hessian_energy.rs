//! The fairness energy `E_fair = Σ_v ‖H(v)‖² A(v)` of the paper (Eq. 6): the squared Hessian
//! energy with natural boundary conditions of Stein, Grinspun, Wardetzky & Jacobson 2018
//! ("Natural boundary conditions for smoothing in geometry processing"). Unlike the Laplacian
//! energy, its null space contains every affine function, boundary included, so it does not
//! bend level sets where they meet the boundary.
//!
//! # Discretisation (mixed FEM with lumped mass)
//!
//! For a piecewise linear field F (values `F_j` at the vertices, gradient `g_f = Σ_j F_j ∇φ_j|_f`
//! on face f) the weak Hessian at vertex i with hat function `φ_i` follows from integrating
//! `∫ φ_i ∇∇F` by parts, keeping the boundary term:
//!
//! ```text
//! A_i H_i = Σ_{boundary edges e ∋ i} (|e| / 2) ν_e ⊗ g_{f(e)}  −  Σ_{faces f ∋ i} A_f ∇φ_i|_f ⊗ g_f
//! ```
//!
//! where `ν_e` is the outward unit conormal of the boundary edge e in the plane of its face
//! `f(e)`, `|e| / 2 = ∫_e φ_i`, and `A_i` is the mixed Voronoi area of vertex i. For an affine F
//! on a flat mesh the right-hand side is exactly zero at every vertex, boundary vertices included
//! (per face `A_f ∇φ_i|_f` is the integral of `φ_i`'s gradient, and by the divergence theorem the
//! interior edge contributions cancel, leaving the boundary term).
//!
//! On a curved surface `H_i` also has a component along the normal (the tangent plane turns);
//! it is removed by projecting onto the tangent plane at vertex i: with an orthonormal frame
//! `(t1, t2) ⊥ n_i`, `T_ab = t_aᵀ H_i t_b` is symmetrised to `S` and vertex i contributes the three
//! residuals `r_i = √A_i · (S_11, S_22, √2 S_12)`, so that `‖r_i‖² = A_i ‖S‖_F²` and
//! `E_fair(F) = Σ_i ‖r_i‖²`. Functions that are affine in the development of a developable
//! surface (e.g. arc length or height on a cylinder) then have energy tending to zero under
//! refinement. Each `r_i = M_i F[closed one-ring of i]` with a constant 3 × k matrix `M_i`,
//! precomputed once per mesh.

use crate::mesh::{TriMesh, Vec3};

/// The precomputed residual operators of the fairness energy (Eq. 6), stored CSR-like: per vertex
/// its variables (the closed one-ring, the vertex itself first) and a row-major
/// `ROWS_PER_VERTEX × k` operator.
#[derive(Debug, Clone, PartialEq)]
pub struct HessianEnergy {
    /// Variables of vertex v: `variables[variable_start[v]..variable_start[v + 1]]`.
    variable_start: Vec<usize>,
    variables: Vec<u32>,
    /// Operator of vertex v: `operator[3 · variable_start[v]..3 · variable_start[v + 1]]`.
    operator: Vec<f64>,
}

/// The in-plane part `(t_aᵀ · A_i H_i · t_b)` of one vertex's weak Hessian, per variable.
type TangentBlock = [[f64; 2]; 2];

impl HessianEnergy {
    /// Residuals per vertex: `√A (S_11, S_22, √2 S_12)` of the symmetrised tangential Hessian `S`.
    pub const ROWS_PER_VERTEX: usize = 3;

    /// Precomputes the residual operator of every vertex of `mesh`.
    pub fn new(mesh: &TriMesh) -> HessianEnergy {
        let boundary_edges_of = boundary_edges_by_vertex(mesh);
        let mut energy = HessianEnergy {
            variable_start: Vec::with_capacity(mesh.vertex_count() + 1),
            variables: Vec::new(),
            operator: Vec::new(),
        };
        energy.variable_start.push(0);
        let mut blocks: Vec<TangentBlock> = Vec::new();
        for (v, boundary_edges) in boundary_edges_of.iter().enumerate() {
            let star = mesh.star(v);
            let first = energy.variables.len();
            energy.variables.push(v as u32);
            energy.variables.extend_from_slice(star.neighbours);
            let variables = &energy.variables[first..];
            let frame = tangent_frame(&mesh.vertex_normals()[v]);
            blocks.clear();
            blocks.resize(variables.len(), [[0.0; 2]; 2]);

            // Interior term −Σ_f A_f ∇φ_v|_f ⊗ g_f.
            for &f in star.faces {
                let f = f as usize;
                let face = &mesh.faces()[f];
                // Internal invariant: every face of the star has v as a corner.
                let corner = face.iter().position(|&c| c as usize == v).expect("star face contains its vertex");
                let weight = -mesh.face_areas()[f] * mesh.face_gradients(f)[corner];
                accumulate(&mut blocks, variables, mesh, f, &weight, &frame);
            }
            // Boundary term Σ_e (|e| / 2) ν_e ⊗ g_f(e), with |e| ν_e = (to − from) × n_f.
            for &e in boundary_edges {
                let edge = &mesh.boundary_edges()[e];
                let f = edge.face as usize;
                let along = mesh.positions()[edge.to as usize] - mesh.positions()[edge.from as usize];
                let weight = 0.5 * along.cross(&mesh.face_normals()[f]);
                accumulate(&mut blocks, variables, mesh, f, &weight, &frame);
            }

            // H_v = (A_v H_v) / A_v, residual √A_v · S = S(A_v H_v) / √A_v. Validated meshes have
            // positive areas; a zero area would contribute nothing rather than a NaN.
            let area = mesh.vertex_areas()[v];
            let scale = if area > 0.0 && area.is_finite() { area.sqrt().recip() } else { 0.0 };
            energy.operator.extend(blocks.iter().map(|b| scale * b[0][0]));
            energy.operator.extend(blocks.iter().map(|b| scale * b[1][1]));
            energy.operator.extend(blocks.iter().map(|b| scale * (b[0][1] + b[1][0]) * std::f64::consts::FRAC_1_SQRT_2));
            energy.variable_start.push(energy.variables.len());
        }
        energy
    }

    /// Number of vertices of the mesh the energy was built for.
    pub fn vertex_count(&self) -> usize {
        self.variable_start.len() - 1
    }

    /// The variables of vertex `v`'s residuals: `v` itself, then its one-ring neighbours.
    /// Panics if `v >= vertex_count()`.
    pub fn vertex_variables(&self, v: usize) -> &[u32] {
        &self.variables[self.variable_start[v]..self.variable_start[v + 1]]
    }

    /// The `ROWS_PER_VERTEX × vertex_variables(v).len()` row-major operator `M_v` with
    /// `r_v = M_v F[vertex_variables(v)]`. Panics if `v >= vertex_count()`.
    pub fn vertex_operator(&self, v: usize) -> &[f64] {
        let rows = Self::ROWS_PER_VERTEX;
        &self.operator[rows * self.variable_start[v]..rows * self.variable_start[v + 1]]
    }

    /// The residuals `r_v` of vertex `v` for the vertex values `field`.
    /// Panics if `v >= vertex_count()` or `field.len() < vertex_count()`.
    pub fn vertex_residuals(&self, v: usize, field: &[f64], out: &mut [f64; 3]) {
        let variables = self.vertex_variables(v);
        let operator = self.vertex_operator(v);
        for (r, row) in out.iter_mut().zip(operator.chunks_exact(variables.len().max(1))) {
            *r = row.iter().zip(variables).map(|(m, &j)| m * field[j as usize]).sum();
        }
    }

    /// `E_fair(F) = Σ_v ‖r_v‖²` (Eq. 6). Panics if `field.len() < vertex_count()`.
    pub fn energy(&self, field: &[f64]) -> f64 {
        let mut residuals = [0.0; 3];
        (0..self.vertex_count())
            .map(|v| {
                self.vertex_residuals(v, field, &mut residuals);
                residuals.iter().map(|r| r * r).sum::<f64>()
            })
            .sum()
    }
}

/// Adds `weight ⊗ g_f`, projected to the tangent frame, to the blocks of the corners of face `f`:
/// corner c contributes `(t_a · weight)(t_b · ∇φ_c|_f)` to its variable's block.
fn accumulate(
    blocks: &mut [TangentBlock],
    variables: &[u32],
    mesh: &TriMesh,
    f: usize,
    weight: &Vec3,
    frame: &[Vec3; 2],
) {
    let left = frame.map(|t| t.dot(weight));
    for (&corner, gradient) in mesh.faces()[f].iter().zip(mesh.face_gradients(f)) {
        // Internal invariant: faces of v's star (and its boundary edges' faces) have their
        // corners in v's closed one-ring.
        let k = variables.iter().position(|&j| j == corner).expect("face corner in the closed one-ring");
        let right = frame.map(|t| t.dot(gradient));
        for a in 0..2 {
            for b in 0..2 {
                blocks[k][a][b] += left[a] * right[b];
            }
        }
    }
}

/// An orthonormal tangent frame `(t1, t2)` with `t1 × t2 = n` for the unit normal `n`.
fn tangent_frame(normal: &Vec3) -> [Vec3; 2] {
    // Cross with the coordinate axis least aligned with n, which is far from parallel to it.
    let axis = normal.iamin();
    let t1 = normal.cross(&Vec3::ith(axis, 1.0)).normalize();
    [t1, normal.cross(&t1)]
}

/// For every vertex, the indices into `mesh.boundary_edges()` of the boundary edges that end at it.
fn boundary_edges_by_vertex(mesh: &TriMesh) -> Vec<Vec<usize>> {
    let mut by_vertex = vec![Vec::new(); mesh.vertex_count()];
    for (e, edge) in mesh.boundary_edges().iter().enumerate() {
        by_vertex[edge.from as usize].push(e);
        by_vertex[edge.to as usize].push(e);
    }
    by_vertex
}
