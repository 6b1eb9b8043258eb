//! The strip optimisation of Sec. 3.4 as a sparse least-squares problem on one polyline.
//!
//! Variables: per vertex `c_i` (position), `b_i` (binormal, Eq. 9) and `d_i` (ruling, Eq. 16),
//! then per edge the unit normal `N_{i,i+1}` of the strip quad (Eq. 17). Blocks per vertex:
//! curve (Eq. 8–9), fairness, surface proximity, ruling (Eq. 16 and the ruling anchor); per edge:
//! planarity (Eq. 17). The unit edge vectors `ê_i` and the principal normals `n_i^p` of Eq. 16 are
//! not separate variables: they enter as functions of the positions with exact derivatives, which
//! satisfies the first two constraints of Eq. 16 exactly; `d_i ⟂ n_i^p` is written as
//! `d_i·(ê_i − ê_{i−1}) = 0`, whose value directly measures the defect of the angle sum
//! `α_i⁻ + α_i⁺ − π` that bends the unrolled strip. The unrolling adds these defects up along the
//! whole strip, so this row is weighted [`STRAIGHTNESS_SCALE`] times the other planarity rows.
//!
//! A planar block also holds the quad to the angle: Eq. 8 on the quad normal `N_{j,j+1}`, the
//! discrete principal normal of the edge, which makes the angle 90° − θ with the surface normal on
//! a P-curve (`N = sin θ n̄ − cos θ ū` up to sign, with `ū = n̄ × ê`):
//! `(N·n̄)² − sin²θ` and `(N·n̄)(N·ū) + sin θ cos θ`. Eq. 8 at the vertices holds the binormals
//! `b_i`, but where the centre line is nearly straight its discrete osculating planes, and with
//! them the rectifying planes `R_i` the rulings lie in, turn by degrees for displacements of a
//! thousandth of an edge; these rows keep the quads, which are what is built, at θ there.
//! Freed that way, neighbouring rulings could lean to opposite sides of the centre line (a quad
//! crossed like a bow tie, d_j·d_{j+1} < 0); a hinge row `max(0, cos β_max − d̂_j·d̂_{j+1})` bounds
//! their turn ([`MAX_RULING_TURN_DEGREES`]).
//!
//! A ruling block also bounds the ruling's angle to the centre line from below
//! ([`MIN_RULING_ANGLE_DEGREES`]): a hinge row `max(0, (d̂·t̂)² − cos²α_min)` with `t̂` the unit
//! chord `c_{i+1} − c_{i−1}` (the end edge at the ends).
//!
//! Surface normals `n_i`, side vectors `u_i`, closest surface points and ruling anchors are frozen
//! data, refreshed between rounds by the caller.

use super::params::StripWeights;
use crate::mesh::Vec3;
use crate::solver::LeastSquaresProblem;

/// Variables per vertex: `c`, `b`, `d`.
const PER_VERTEX: usize = 9;
/// Rows of each block kind (planar: Eq. 17, Eq. 8 on the quad normal, the ruling-turn hinge).
const CURVE_ROWS: usize = 5;
const FAIR_ROWS: usize = 3;
const SURFACE_ROWS: usize = 4;
const RULING_ROWS: usize = 6;

/// Smallest angle between a ruling and the centre line (degrees). Where the centre line is
/// nearly straight or turns through an inflection, the exact rectifying developable's rulings
/// turn towards the tangent (the Darboux vector `τ t + κ b` with κ → 0), so the strip's edges
/// run off to infinity and quads flip as the ruling passes the tangent. Below this angle a ruling
/// pays a penalty (weighted like planarity), which keeps every ruling segment from the centre line
/// to a boundary within `1 / (2 sin 20°) ≈ 1.46` strip widths; the strip then gives up a little
/// of its angle or bends its centre line there, which the verdict measures.
pub(crate) const MIN_RULING_ANGLE_DEGREES: f64 = 20.0;
/// Largest turn between the rulings of one quad (degrees); see the module notes.
const MAX_RULING_TURN_DEGREES: f64 = 60.0;
/// Factor on `√λ_planarity` of the angle-sum row `d_i·(ê_i − ê_{i−1})`: Table 4's `e_straight`
/// is the sum of these defects along a strip of some fifty vertices, weighed against single-quad
/// residuals (planarity, angle), so it is held ten times tighter (a hundred times in energy).
/// Measured on the paper's Wave mesh (θ = 60°), at factor 1 the worst strip's unrolling strays by
/// 6e-4 of its length, at 10 by 4e-6.
const STRAIGHTNESS_SCALE: f64 = 10.0;
const PLANAR_ROWS: usize = 7;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Block {
    Curve(usize),
    Fair(usize),
    Surface(usize),
    Ruling(usize),
    Planar(usize),
}

/// Frozen per-vertex data of a round.
#[derive(Clone, Debug, Default)]
pub(crate) struct Frozen {
    /// Unit surface normal at the closest surface point.
    pub normals: Vec<Vec3>,
    /// Unit side vector `u = n × t` of the Darboux frame.
    pub sides: Vec<Vec3>,
    /// Closest surface points.
    pub anchors: Vec<Vec3>,
    /// Initial rulings (the version-1 model).
    pub rulings: Vec<Vec3>,
    /// Per edge `j`: unit surface normal `n̄_j` of the quad (the normalised sum of the normals at
    /// its two centre vertices) and side vector `ū_j = n̄_j × ê_j`.
    pub quad_normals: Vec<Vec3>,
    pub quad_sides: Vec<Vec3>,
}

/// The strip problem of one open polyline with `n ≥ 3` vertices.
pub(crate) struct StripProblem {
    n: usize,
    cos: f64,
    sin: f64,
    /// 1 / mean edge length: lengths enter the residuals in units of the edge length.
    inverse_length: f64,
    pub weights: StripWeights,
    pub frozen: Frozen,
    blocks: Vec<Block>,
    offsets: Vec<usize>,
    variables: Vec<u32>,
}

pub(crate) fn position(i: usize) -> usize {
    PER_VERTEX * i
}
pub(crate) fn binormal(i: usize) -> usize {
    PER_VERTEX * i + 3
}
pub(crate) fn ruling(i: usize) -> usize {
    PER_VERTEX * i + 6
}

/// Reads the 3-vector starting at `start`.
pub(crate) fn vec3(x: &[f64], start: usize) -> Vec3 {
    Vec3::new(x[start], x[start + 1], x[start + 2])
}

/// `ê = e/‖e‖` of `e = to − from` and the derivative of `v·ê` with respect to `to`
/// (`(v − (v·ê)ê)/‖e‖`; the derivative with respect to `from` is its negative).
fn unit_and_partial(from: Vec3, to: Vec3, v: &Vec3) -> (Vec3, Vec3) {
    let e = to - from;
    let length = e.norm();
    if length > 0.0 {
        let unit = e / length;
        (unit, (v - unit * v.dot(&unit)) / length)
    } else {
        (Vec3::zeros(), Vec3::zeros())
    }
}

impl StripProblem {
    pub fn new(n: usize, theta_degrees: f64, mean_edge: f64, weights: StripWeights) -> Self {
        let (sin, cos) = theta_degrees.to_radians().sin_cos();
        let mut problem = StripProblem {
            n,
            cos,
            sin,
            inverse_length: 1.0 / mean_edge,
            weights,
            frozen: Frozen::default(),
            blocks: Vec::new(),
            offsets: vec![0],
            variables: Vec::new(),
        };
        for i in 0..n {
            let neighbours = || (i.saturating_sub(1)..(i + 2).min(n)).map(position);
            problem.push(Block::Curve(i), neighbours().chain([binormal(i)]));
            if i > 0 && i + 1 < n {
                problem.push(Block::Fair(i), neighbours());
            }
            problem.push(Block::Surface(i), [position(i)].into_iter());
            problem.push(Block::Ruling(i), neighbours().chain([ruling(i)]));
        }
        for j in 0..n - 1 {
            let normal = PER_VERTEX * n + 3 * j;
            problem.push(Block::Planar(j), [position(j), position(j + 1), ruling(j), ruling(j + 1), normal].into_iter());
        }
        problem
    }

    fn push(&mut self, block: Block, starts: impl Iterator<Item = usize>) {
        for start in starts {
            self.variables.extend((start..start + 3).map(|v| v as u32));
        }
        self.offsets.push(self.variables.len());
        self.blocks.push(block);
    }

    /// Index of the first edge-normal variable `N_{j,j+1}`.
    pub fn edge_normal(&self, j: usize) -> usize {
        PER_VERTEX * self.n + 3 * j
    }
}

/// Writes derivative 3-vectors into a row-major block Jacobian.
struct JacobianWriter<'a> {
    jacobian: Option<&'a mut [f64]>,
    variables: &'a [u32],
}

impl JacobianWriter<'_> {
    /// Adds `d` to row `row` at the three columns of the variable triple starting at `start`.
    fn add(&mut self, row: usize, start: usize, d: Vec3) {
        let Some(jacobian) = self.jacobian.as_deref_mut() else { return };
        let columns = self.variables.len();
        // Blocks declare every variable triple they write (see `StripProblem::new`).
        let column = self.variables.iter().position(|&v| v as usize == start).expect("declared variable");
        for k in 0..3 {
            jacobian[row * columns + column + k] += d[k];
        }
    }

    /// Adds `scale · I` (rows `row..row+3`) at the variable triple starting at `start`.
    fn add_identity(&mut self, row: usize, start: usize, scale: f64) {
        for k in 0..3 {
            let mut d = Vec3::zeros();
            d[k] = scale;
            self.add(row + k, start, d);
        }
    }
}

impl LeastSquaresProblem for StripProblem {
    fn variable_count(&self) -> usize {
        PER_VERTEX * self.n + 3 * (self.n - 1)
    }

    fn block_count(&self) -> usize {
        self.blocks.len()
    }

    fn block_variables(&self, b: usize) -> &[u32] {
        &self.variables[self.offsets[b]..self.offsets[b + 1]]
    }

    fn block_residual_count(&self, b: usize) -> usize {
        match self.blocks[b] {
            Block::Curve(_) => CURVE_ROWS,
            Block::Fair(_) => FAIR_ROWS,
            Block::Surface(_) => SURFACE_ROWS,
            Block::Ruling(_) => RULING_ROWS,
            Block::Planar(_) => PLANAR_ROWS,
        }
    }

    fn evaluate_block(&self, b: usize, x: &[f64], r: &mut [f64], jacobian: Option<&mut [f64]>) {
        let mut jac = JacobianWriter { jacobian, variables: self.block_variables(b) };
        let w = &self.weights;
        let c = |i: usize| vec3(x, position(i));
        let last = self.n - 1;
        match self.blocks[b] {
            Block::Curve(i) => {
                let (s_angle, s_binormal) = (w.angle.sqrt(), w.binormal.sqrt());
                let bv = vec3(x, binormal(i));
                let (n, u) = (self.frozen.normals[i], self.frozen.sides[i]);
                let (bn, bu) = (bv.dot(&n), bv.dot(&u));
                r[0] = s_angle * (bn * bn - self.cos * self.cos);
                r[1] = s_angle * (bn * bu - self.sin * self.cos);
                jac.add(0, binormal(i), n * (2.0 * s_angle * bn));
                jac.add(1, binormal(i), (n * bu + u * bn) * s_angle);
                if i > 0 {
                    let (unit, partial) = unit_and_partial(c(i - 1), c(i), &bv);
                    r[2] = s_binormal * bv.dot(&unit);
                    jac.add(2, binormal(i), unit * s_binormal);
                    jac.add(2, position(i), partial * s_binormal);
                    jac.add(2, position(i - 1), -partial * s_binormal);
                }
                if i < last {
                    let (unit, partial) = unit_and_partial(c(i), c(i + 1), &bv);
                    r[3] = s_binormal * bv.dot(&unit);
                    jac.add(3, binormal(i), unit * s_binormal);
                    jac.add(3, position(i + 1), partial * s_binormal);
                    jac.add(3, position(i), -partial * s_binormal);
                }
                r[4] = s_binormal * (bv.dot(&bv) - 1.0);
                jac.add(4, binormal(i), bv * (2.0 * s_binormal));
            }
            Block::Fair(i) => {
                let s = w.fair.sqrt() * self.inverse_length;
                let second = c(i - 1) - c(i) * 2.0 + c(i + 1);
                for k in 0..3 {
                    r[k] = s * second[k];
                }
                jac.add_identity(0, position(i - 1), s);
                jac.add_identity(0, position(i), -2.0 * s);
                jac.add_identity(0, position(i + 1), s);
            }
            Block::Surface(i) => {
                let offset = c(i) - self.frozen.anchors[i];
                let n = self.frozen.normals[i];
                let s_normal = w.surface.sqrt() * self.inverse_length;
                let s_slide = w.slide.sqrt() * self.inverse_length;
                r[0] = s_normal * offset.dot(&n);
                jac.add(0, position(i), n * s_normal);
                for k in 0..3 {
                    r[1 + k] = s_slide * offset[k];
                }
                jac.add_identity(1, position(i), s_slide);
            }
            Block::Ruling(i) => {
                let (s_planar, s_anchor) = (w.planarity.sqrt(), w.ruling_anchor.sqrt());
                let d = vec3(x, ruling(i));
                if i > 0 && i < last {
                    let s_planar = s_planar * STRAIGHTNESS_SCALE;
                    let (before, partial_before) = unit_and_partial(c(i - 1), c(i), &d);
                    let (after, partial_after) = unit_and_partial(c(i), c(i + 1), &d);
                    r[0] = s_planar * d.dot(&(after - before));
                    jac.add(0, ruling(i), (after - before) * s_planar);
                    jac.add(0, position(i + 1), partial_after * s_planar);
                    jac.add(0, position(i), -(partial_after + partial_before) * s_planar);
                    jac.add(0, position(i - 1), partial_before * s_planar);
                }
                r[1] = s_planar * (d.dot(&d) - 1.0);
                jac.add(1, ruling(i), d * (2.0 * s_planar));
                let offset = d - self.frozen.rulings[i];
                for k in 0..3 {
                    r[2 + k] = s_anchor * offset[k];
                }
                jac.add_identity(2, ruling(i), s_anchor);
                // Hinge on the ruling's angle to the centre line.
                let (from, to) = (i.saturating_sub(1), (i + 1).min(last));
                let chord = c(to) - c(from);
                let (d_norm, chord_norm) = (d.norm(), chord.norm());
                if d_norm > 0.0 && chord_norm > 0.0 {
                    let (d_unit, t_unit) = (d / d_norm, chord / chord_norm);
                    let cosine = d_unit.dot(&t_unit);
                    let bound = MIN_RULING_ANGLE_DEGREES.to_radians().cos();
                    let excess = cosine * cosine - bound * bound;
                    if excess > 0.0 {
                        r[5] = s_planar * excess;
                        let scale = s_planar * 2.0 * cosine;
                        jac.add(5, ruling(i), (t_unit - d_unit * cosine) * (scale / d_norm));
                        let along = (d_unit - t_unit * cosine) * (scale / chord_norm);
                        jac.add(5, position(to), along);
                        jac.add(5, position(from), -along);
                    }
                }
            }
            Block::Planar(j) => {
                let s = w.planarity.sqrt();
                let normal = self.edge_normal(j);
                let nv = vec3(x, normal);
                let (d0, d1) = (vec3(x, ruling(j)), vec3(x, ruling(j + 1)));
                let (unit, partial) = unit_and_partial(c(j), c(j + 1), &nv);
                r[0] = s * nv.dot(&d0);
                jac.add(0, normal, d0 * s);
                jac.add(0, ruling(j), nv * s);
                r[1] = s * nv.dot(&d1);
                jac.add(1, normal, d1 * s);
                jac.add(1, ruling(j + 1), nv * s);
                r[2] = s * nv.dot(&unit);
                jac.add(2, normal, unit * s);
                jac.add(2, position(j + 1), partial * s);
                jac.add(2, position(j), -partial * s);
                r[3] = s * (nv.dot(&nv) - 1.0);
                jac.add(3, normal, nv * (2.0 * s));
                // Eq. 8 on the quad normal, weighted √(λ_angle λ_planarity): it exists only while
                // the rulings are solved for, and the polish (angle weight 0) leaves it out.
                let s_angle = (w.angle * w.planarity).sqrt();
                if let (Some(n), Some(u)) = (self.frozen.quad_normals.get(j), self.frozen.quad_sides.get(j)) {
                    let (nn, nu) = (nv.dot(n), nv.dot(u));
                    r[4] = s_angle * (nn * nn - self.sin * self.sin);
                    r[5] = s_angle * (nn * nu + self.sin * self.cos);
                    jac.add(4, normal, n * (2.0 * s_angle * nn));
                    jac.add(5, normal, (n * nu + u * nn) * s_angle);
                }
                // Hinge on the turn between consecutive rulings.
                let (n0, n1) = (d0.norm(), d1.norm());
                if n0 > 0.0 && n1 > 0.0 {
                    let (u0, u1) = (d0 / n0, d1 / n1);
                    let cosine = u0.dot(&u1);
                    let bound = MAX_RULING_TURN_DEGREES.to_radians().cos();
                    if cosine < bound {
                        r[6] = s * (bound - cosine);
                        jac.add(6, ruling(j), -(u1 - u0 * cosine) * (s / n0));
                        jac.add(6, ruling(j + 1), -(u0 - u1 * cosine) * (s / n1));
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::solver::check_block_jacobian;

    #[test]
    fn analytic_jacobians_match_central_differences() {
        let n = 6;
        let weights = StripWeights { angle: 2.0, binormal: 1.5, surface: 0.7, slide: 0.3, fair: 0.2, planarity: 1.3, ruling_anchor: 0.4 };
        let mut problem = StripProblem::new(n, 60.0, 0.8, weights);
        let wobble = |k: usize| ((k * 7919 % 1000) as f64 / 1000.0) - 0.5;
        let mut x = vec![0.0; problem.variable_count()];
        for (k, value) in x.iter_mut().enumerate() {
            *value = wobble(k);
        }
        for i in 0..n {
            let t = i as f64;
            let p = Vec3::new(t, 0.3 * t * t, 0.1 * t * t * t) + Vec3::new(wobble(3 * i), wobble(3 * i + 1), wobble(3 * i + 2)) * 0.1;
            x[position(i)..position(i) + 3].copy_from_slice(p.as_slice());
        }
        let unit = |k: usize| Vec3::new(wobble(k), wobble(k + 1), 1.0).normalize();
        problem.frozen = Frozen {
            normals: (0..n).map(|i| unit(10 * i)).collect(),
            sides: (0..n).map(|i| unit(10 * i + 3)).collect(),
            anchors: (0..n).map(|i| Vec3::new(i as f64, 0.1, 0.2)).collect(),
            rulings: (0..n).map(|i| unit(10 * i + 6)).collect(),
            quad_normals: (0..n - 1).map(|j| unit(10 * j + 1)).collect(),
            quad_sides: (0..n - 1).map(|j| unit(10 * j + 4)).collect(),
        };
        for b in 0..problem.block_count() {
            let error = check_block_jacobian(&problem, &x, b, 1e-6);
            assert!(error < 1e-6, "block {b} ({:?}): {error}", problem.blocks[b]);
        }
    }
}
