//! The surface optimisation of Sec. 3.3 as a sparse least-squares problem:
//! `E^M_pg = λ_fair E^S_fair + λ_close E^S_close + λ_angle E^S_angle + λ_edge E^S_edge` over the
//! vertex positions (global, `3v + c`) and, per curve vertex, its binormal `b` and side vector `u`
//! (a local group of six, eliminated by Schur complement). F is fixed.
//!
//! Blocks, in this order:
//! * one fairness block per vertex: `E^S_H`, the squared Hessian energy (Eq. 6, [Stein et al.
//!   2018]) of each coordinate x, y, z, and at interior vertices `E^S_uni`, the uniform Laplacian
//!   `v − mean(neighbours)` [Taubin 1995];
//! * one closeness block per vertex (Eq. 14): `(v − v*)·n*` (weighted by the tolerance guard on
//!   top of λ_close, see [`super::ReshapeParams::tolerance`]) and `v − v_ori`;
//! * one edge block per edge (Eq. 15): `l_e − l*_e`;
//! * one curve block per curve vertex: the eight rows of `E_angle` (Eq. 8–10, as in the level-set
//!   problem) on the chords `v0 − p⁺`, `v0 − q⁺`, `q⁺ − p⁺` of the moving mesh (about three edges
//!   along the curve on each side, see [`super::curve_star`]), the two rows `b·ê_p`, `b·ê_q` on
//!   the star chords `v0 − p`, `v0 − q` (the curve bends in the plane of the binormal at both
//!   scales), then the three rows of `E^S_c = ‖(p − v0)/‖p − v0‖ + (q − v0)/‖q − v0‖‖²`
//!   (weighted by λ_fair).
//!
//! As in the authors' implementation, the chord lengths, the smooth vertex normals, the fairness
//! operator and the closest points `v*`, `n*` are frozen within an iteration and recomputed on
//! the moved mesh after each step ([`super::linearisation`]). Unlike theirs, the normal `n` of
//! the angle rows follows the moving ring of `v0` within the iteration: the surface turns the
//! binormal's angle to the normal mostly by turning the normal, and with `n` frozen the
//! iterations circle (on the test cylinder they stall at 1° RMS with the angle energy 10³ times
//! higher). Everything else is differentiated exactly. The angle rows carry `√(λ_angle A_v)`
//! with `A` the vertex areas normalised to mean 1.

use super::curve_star::{combine, Combination, CurveStar};
use super::linearisation::{ring_area_vector, Linearisation};
use super::params::ReshapeWeights;
use crate::field::hessian_energy::HessianEnergy;
use crate::field::pseudo_geodesic::{frame_rows, TargetAngle, AUXILIARIES};
use crate::mesh::{TriMesh, Vec3};
use crate::solver::{LeastSquaresProblem, VariableLayout};

/// Rows of a curve block: those of `E_angle`, then three of `E^S_c`.
pub(crate) const CURVE_ROWS: usize = ANGLE_ROWS + 3;
/// Smallest ring vector area taken for the normalisation of the ring normal (mean edge 1).
const MIN_AREA: f64 = 1e-12;
/// Rows of `E_angle` at the start of a curve block: the eight of Eq. 8–10 on the far chords,
/// then `b·ê_p`, `b·ê_q` on the star chords.
const ANGLE_ROWS: usize = FRAME_ROWS + STAR_ROWS;
/// The rows of Eq. 8–10 ([`frame_rows`]).
const FRAME_ROWS: usize = 8;
/// `b·ê_p = 0`, `b·ê_q = 0` on the star chords `v0 − p`, `v0 − q`.
const STAR_ROWS: usize = 2;

/// Which energy a block belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Block {
    Fair(usize),
    Close(usize),
    Edge(usize),
    Curve(usize),
}

/// The surface problem on a unit-scaled mesh.
pub(crate) struct SurfaceProblem {
    vertex_count: usize,
    curves: Vec<CurveStar>,
    /// Fairness block variables (three per vertex of the closed one-ring), CSR by vertex.
    fair_offsets: Vec<usize>,
    fair_variables: Vec<u32>,
    edges: Vec<[u32; 2]>,
    /// The six coordinates of each edge's ends.
    edge_variables: Vec<u32>,
    /// `l*_e` of Eq. 15.
    rest_lengths: Vec<f64>,
    /// `v_ori` of Eq. 14.
    original_positions: Vec<Vec3>,
    /// Curve block variables (three per distinct vertex, then the six auxiliaries), CSR by curve.
    curve_offsets: Vec<usize>,
    curve_variables: Vec<u32>,
    pub weights: ReshapeWeights,
    /// Extra factor on the normal rows of `E^S_close`, raised when a step leaves the tolerance.
    pub guard: f64,
    pub target: TargetAngle,
    pub lin: Linearisation,
}

impl SurfaceProblem {
    /// The problem for the curve vertices `curves` of a field, on the mesh of `lin` (whose
    /// topology is that of `original`, the mesh at the start, unit-scaled).
    pub fn new(original: &TriMesh, curves: Vec<CurveStar>, lin: Linearisation, weights: ReshapeWeights, theta_degrees: f64) -> SurfaceProblem {
        let n = original.vertex_count();
        let triple = |v: u32| [3 * v, 3 * v + 1, 3 * v + 2];
        let mut fair_offsets = vec![0];
        let mut fair_variables = Vec::new();
        for v in 0..n {
            for &w in lin.hessian.vertex_variables(v) {
                fair_variables.extend_from_slice(&triple(w));
            }
            fair_offsets.push(fair_variables.len());
        }
        let mut curve_offsets = vec![0];
        let mut curve_variables = Vec::new();
        for (k, curve) in curves.iter().enumerate() {
            let mut vertices = curve.vertices();
            for &w in original.star(curve.vertex as usize).neighbours {
                if !vertices.contains(&w) {
                    vertices.push(w);
                }
            }
            for w in vertices {
                curve_variables.extend_from_slice(&triple(w));
            }
            let first = (3 * n + AUXILIARIES * k) as u32;
            curve_variables.extend(first..first + AUXILIARIES as u32);
            curve_offsets.push(curve_variables.len());
        }
        // Plain loops: valgrind flags the nested flat_map of arrays this replaced (uninitialised
        // reads inside the optimised array iterator).
        let mut edge_variables = Vec::with_capacity(6 * original.edges().len());
        for &[a, b] in original.edges() {
            edge_variables.extend_from_slice(&triple(a));
            edge_variables.extend_from_slice(&triple(b));
        }
        let positions = original.positions();
        let rest_lengths = original.edges().iter().map(|e| (positions[e[1] as usize] - positions[e[0] as usize]).norm()).collect();
        SurfaceProblem {
            vertex_count: n,
            curves,
            fair_offsets,
            fair_variables,
            edges: original.edges().to_vec(),
            edge_variables,
            rest_lengths,
            original_positions: positions.to_vec(),
            curve_offsets,
            curve_variables,
            weights,
            guard: 1.0,
            target: TargetAngle::from_degrees(theta_degrees),
            lin,
        }
    }

    pub fn curves(&self) -> &[CurveStar] {
        &self.curves
    }

    /// Index of the first auxiliary (`b`, then `u`) of the `k`-th curve vertex.
    pub fn auxiliary_start(&self, k: usize) -> usize {
        3 * self.vertex_count + AUXILIARIES * k
    }

    pub(crate) fn block(&self, b: usize) -> Block {
        let n = self.vertex_count;
        if b < n {
            Block::Fair(b)
        } else if b < 2 * n {
            Block::Close(b - n)
        } else if b < 2 * n + self.edges.len() {
            Block::Edge(b - 2 * n)
        } else {
            Block::Curve(b - 2 * n - self.edges.len())
        }
    }

    fn fair_rows(&self, v: usize) -> usize {
        let interior = self.lin.mesh.star(v).closed;
        3 * HessianEnergy::ROWS_PER_VERTEX + if interior { 3 } else { 0 }
    }

    /// Evaluates block `b` with the given weights and guard (the solver uses the problem's own;
    /// reports use 1).
    pub(crate) fn evaluate_weighted(&self, b: usize, weights: &ReshapeWeights, guard: f64, x: &[f64], residuals: &mut [f64], jacobian: Option<&mut [f64]>) {
        match self.block(b) {
            Block::Fair(v) => self.evaluate_fair(v, weights.fair.sqrt(), x, residuals, jacobian),
            Block::Close(v) => {
                let anchor = &self.lin.anchors[v];
                let position = Vec3::new(x[3 * v], x[3 * v + 1], x[3 * v + 2]);
                let (scale, normal_scale) = (weights.close.sqrt(), (weights.close * guard).sqrt());
                residuals[0] = normal_scale * (position - anchor.point).dot(&anchor.normal);
                let offset = position - self.original_positions[v];
                for c in 0..3 {
                    residuals[1 + c] = scale * offset[c];
                }
                if let Some(jac) = jacobian {
                    for c in 0..3 {
                        jac[c] = normal_scale * anchor.normal[c];
                        jac[3 * (1 + c) + c] = scale;
                    }
                }
            }
            Block::Edge(e) => {
                let [a, b] = self.edges[e].map(|v| 3 * v as usize);
                let along = Vec3::new(x[b] - x[a], x[b + 1] - x[a + 1], x[b + 2] - x[a + 2]);
                let length = along.norm();
                let scale = weights.edge.sqrt();
                residuals[0] = scale * (length - self.rest_lengths[e]);
                if let (Some(jac), Some(direction)) = (jacobian, along.try_normalize(0.0)) {
                    for c in 0..3 {
                        jac[c] = -scale * direction[c];
                        jac[3 + c] = scale * direction[c];
                    }
                }
            }
            Block::Curve(k) => self.evaluate_curve(k, weights, x, residuals, jacobian),
        }
    }

    /// `E^S_H` of the three coordinates, then `E^S_uni` at interior vertices.
    fn evaluate_fair(&self, v: usize, scale: f64, x: &[f64], residuals: &mut [f64], jacobian: Option<&mut [f64]>) {
        let ring = self.lin.hessian.vertex_variables(v);
        let operator = self.lin.hessian.vertex_operator(v);
        let (k, columns) = (ring.len(), 3 * ring.len());
        let rows = HessianEnergy::ROWS_PER_VERTEX;
        let uniform = residuals.len() > 3 * rows;
        for c in 0..3 {
            for r in 0..rows {
                let coefficients = &operator[r * k..(r + 1) * k];
                residuals[c * rows + r] = scale * coefficients.iter().zip(ring).map(|(m, &w)| m * x[3 * w as usize + c]).sum::<f64>();
            }
            if uniform {
                let mean = ring[1..].iter().map(|&w| x[3 * w as usize + c]).sum::<f64>() / (k - 1) as f64;
                residuals[3 * rows + c] = scale * (x[3 * v + c] - mean);
            }
        }
        let Some(jac) = jacobian else { return };
        for c in 0..3 {
            for r in 0..rows {
                for (i, m) in operator[r * k..(r + 1) * k].iter().enumerate() {
                    jac[(c * rows + r) * columns + 3 * i + c] = scale * m;
                }
            }
            if uniform {
                let row = (3 * rows + c) * columns;
                jac[row + c] = scale;
                for i in 1..k {
                    jac[row + 3 * i + c] = -scale / (k - 1) as f64;
                }
            }
        }
    }

    /// `E_angle` on the chords of the moving mesh (with the normal of `v0` through its ring, see
    /// [`Linearisation::normal_offsets`]), the binormal on the star chords, then `E^S_c`.
    fn evaluate_curve(&self, k: usize, weights: &ReshapeWeights, x: &[f64], residuals: &mut [f64], jacobian: Option<&mut [f64]>) {
        let curve = &self.curves[k];
        let v0 = curve.vertex as usize;
        let variables = &self.curve_variables[self.curve_offsets[k]..self.curve_offsets[k + 1]];
        let columns = variables.len();
        let aux_column = columns - AUXILIARIES;
        let lengths = self.lin.chords[k];
        let (to_p, to_q) = (curve.from(&curve.p), curve.from(&curve.q));
        let (to_far_p, to_far_q, tangent) = (curve.from(&curve.far_p), curve.from(&curve.far_q), curve.tangent());
        let ep = combine(&to_far_p, x) / lengths.to_far_p;
        let eq = combine(&to_far_q, x) / lengths.to_far_q;
        let t = combine(&tangent, x) / lengths.tangent;
        let (near_p, near_q) = (combine(&to_p, x) / lengths.to_p, combine(&to_q, x) / lengths.to_q);
        let start = self.auxiliary_start(k);
        let aux = &x[start..start + AUXILIARIES];
        let (b, u) = (Vec3::new(aux[0], aux[1], aux[2]), Vec3::new(aux[3], aux[4], aux[5]));
        let position = |w: u32| Vec3::new(x[3 * w as usize], x[3 * w as usize + 1], x[3 * w as usize + 2]);
        let ring = self.lin.mesh.star(v0).neighbours;
        let area = ring_area_vector(ring.iter().map(|&w| position(w)));
        let ring_normal = area.try_normalize(0.0).unwrap_or_else(Vec3::zeros);
        let normal = ring_normal + self.lin.normal_offsets[k];
        let angle_scale = (weights.angle * self.lin.mesh.normalized_vertex_areas()[v0]).sqrt();
        let smooth_scale = weights.fair.sqrt();
        let (frame, rest) = residuals.split_at_mut(FRAME_ROWS);
        let (star, smooth) = rest.split_at_mut(STAR_ROWS);
        star[0] = angle_scale * b.dot(&near_p);
        star[1] = angle_scale * b.dot(&near_q);
        let curvature = -(near_p + near_q);
        for c in 0..3 {
            smooth[c] = smooth_scale * curvature[c];
        }
        let Some(jac) = jacobian else {
            frame_rows(&normal, aux, &[ep, eq, t], self.target, angle_scale, frame, None);
            return;
        };
        frame_rows(&normal, aux, &[ep, eq, t], self.target, angle_scale, frame, Some((&mut *jac, columns, aux_column)));
        // The column of the first coordinate of vertex w (one of the block's distinct vertices).
        let column = |w: u32| 3 * (variables[..aux_column].iter().step_by(3).position(|&i| i == 3 * w).unwrap_or(0));
        // Rows 0, 1 and 6 through the ring normal N = m / ‖m‖: ∂N = (I − N Nᵀ) ∂m / ‖m‖, and
        // ∂(g·m)/∂x_i = ½ g × (x_{i−1} − x_{i+1}) for the ring vertex x_i.
        let (bn, bu) = (b.dot(&normal), b.dot(&u));
        let area_norm = area.norm().max(MIN_AREA);
        for (row, d_normal) in [(0, b * (2.0 * bn)), (1, b * bu), (6, u)] {
            let g = (d_normal - ring_normal * ring_normal.dot(&d_normal)) * (angle_scale / area_norm);
            for (i, &w) in ring.iter().enumerate() {
                let (before, after) = (ring[(i + ring.len() - 1) % ring.len()], ring[(i + 1) % ring.len()]);
                let partial = g.cross(&(position(before) - position(after))) * 0.5;
                let col = column(w);
                for c in 0..3 {
                    jac[row * columns + col + c] += partial[c];
                }
            }
        }
        for (row, chord) in [(FRAME_ROWS, near_p), (FRAME_ROWS + 1, near_q)] {
            for c in 0..3 {
                jac[row * columns + aux_column + c] = angle_scale * chord[c];
            }
        }
        // Row `row` = scale · a · (Σ c_i x_{w_i}) for a fixed vector `a`.
        let mut add_dot = |row: usize, combination: &Combination, a: &Vec3, scale: f64| {
            for &(w, coefficient) in combination {
                let col = column(w);
                for i in 0..3 {
                    jac[row * columns + col + i] += scale * coefficient * a[i];
                }
            }
        };
        add_dot(2, &to_far_p, &b, angle_scale / lengths.to_far_p);
        add_dot(3, &to_far_q, &b, angle_scale / lengths.to_far_q);
        add_dot(5, &tangent, &u, angle_scale / lengths.tangent);
        add_dot(FRAME_ROWS, &to_p, &b, angle_scale / lengths.to_p);
        add_dot(FRAME_ROWS + 1, &to_q, &b, angle_scale / lengths.to_q);
        for (combination, length) in [(&to_p, lengths.to_p), (&to_q, lengths.to_q)] {
            for &(w, coefficient) in combination.iter() {
                let col = column(w);
                for i in 0..3 {
                    jac[(ANGLE_ROWS + i) * columns + col + i] -= smooth_scale * coefficient / length;
                }
            }
        }
    }

    /// Unweighted energies at x: (fair, close, angle, edge).
    pub(crate) fn energies(&self, x: &[f64]) -> [f64; 4] {
        let unit = ReshapeWeights { fair: 1.0, close: 1.0, angle: 1.0, edge: 1.0 };
        let mut sums = [0.0; 4];
        let mut residuals = vec![0.0; 3 * HessianEnergy::ROWS_PER_VERTEX + 3];
        for b in 0..self.block_count() {
            let rows = self.block_residual_count(b);
            residuals.resize(rows.max(residuals.len()), 0.0);
            let r = &mut residuals[..rows];
            r.fill(0.0);
            self.evaluate_weighted(b, &unit, 1.0, x, r, None);
            let squares = |r: &[f64]| r.iter().map(|v| v * v).sum::<f64>();
            match self.block(b) {
                Block::Fair(_) => sums[0] += squares(r),
                Block::Close(_) => sums[1] += squares(r),
                Block::Curve(_) => {
                    sums[2] += squares(&r[..ANGLE_ROWS]);
                    sums[0] += squares(&r[ANGLE_ROWS..]);
                }
                Block::Edge(_) => sums[3] += squares(r),
            }
        }
        sums
    }
}

impl LeastSquaresProblem for SurfaceProblem {
    fn variable_count(&self) -> usize {
        3 * self.vertex_count + AUXILIARIES * self.curves.len()
    }

    fn block_count(&self) -> usize {
        2 * self.vertex_count + self.edges.len() + self.curves.len()
    }

    fn block_variables(&self, b: usize) -> &[u32] {
        match self.block(b) {
            Block::Fair(v) => &self.fair_variables[self.fair_offsets[v]..self.fair_offsets[v + 1]],
            Block::Close(v) => &self.fair_variables[self.fair_offsets[v]..self.fair_offsets[v] + 3],
            Block::Edge(e) => &self.edge_variables[6 * e..6 * e + 6],
            Block::Curve(k) => &self.curve_variables[self.curve_offsets[k]..self.curve_offsets[k + 1]],
        }
    }

    fn block_residual_count(&self, b: usize) -> usize {
        match self.block(b) {
            Block::Fair(v) => self.fair_rows(v),
            Block::Close(_) => 4,
            Block::Edge(_) => 1,
            Block::Curve(_) => CURVE_ROWS,
        }
    }

    fn evaluate_block(&self, b: usize, x: &[f64], residuals: &mut [f64], jacobian: Option<&mut [f64]>) {
        self.evaluate_weighted(b, &self.weights, self.guard, x, residuals, jacobian);
    }

    fn variable_layout(&self) -> VariableLayout {
        let sizes = vec![AUXILIARIES; self.curves.len()];
        // Invariant: the groups tile [3n, variable_count) exactly, so the layout is valid.
        VariableLayout::with_local_groups(3 * self.vertex_count, &sizes).expect("auxiliary groups tile the local variables")
    }
}
