//! The base-mesh optimisation of Sec. 3.5 (and the torsion-free nodes of Eq. 21) as a sparse
//! least-squares problem on a net scaled to mean segment length 1.
//!
//! Variables: the vertex positions `v` (global, `3v + c`); with torsion-free nodes, a ruling
//! `d` per vertex (global, after the positions). Per vertex a local group (eliminated by Schur
//! complement): its normal `n`, then for each family (rows, columns, a web's diagonals) whose
//! polyline passes through the vertex (both neighbours present) its binormal `b` (P and G) and
//! side vector `u` (P). Torsion-free nodes are held in nets of two families only. With
//! torsion-free nodes, per segment a local group: its discrete principal normal `n_{0,i}`.
//!
//! One block per vertex, with the neighbours `v_back`, `v_front` along each family (Fig. 21):
//!
//! | rows | residual | weight |
//! |---|---|---|
//! | normal | `n·t̂_k` per family whose polyline passes through (`t̂ = (v_front − v_back)/‖·‖`), `n·n − 1`; where fewer than two pass through (the net's boundary), `n − n*`, the reference normal | curve |
//! | P(θ) | `b·ê_f`, `b·ê_b`, `b·b − 1` (binormal), `(b·n)² − cos²θ`, `(b·n)(b·u) − sinθ cosθ` (Eq. 8), `u·u − 1`, `u·n`, `u·t̂` (Eq. 10) | curve |
//! | G | `b·ê_f`, `b·ê_b`, `b·b − 1`, `n·b` | curve |
//! | A | `n·ê_f`, `n·ê_b` | curve |
//! | slope | `ê_f·a − sin β` for the segment to the front neighbour (Eq. 22 per segment); inside the polyline `a·(ê_f + ê_b)/‖ê_f + ê_b‖`, the axis in the rectifying plane (parallel node axes, Sec. 5.2.2) | curve |
//! | fairness | `v_back − 2v + v_front` per family | fair |
//! | closeness | `(v − v*)·n*` (Eq. 14: the distance to the reference along its normal at the closest point `v*`, frozen per iteration); past the reference's boundary also the tangential part of `v − v*` (zero rows elsewhere); `v − v_start` | close, pull |
//! | torsion-free | `d·(ê_f + ê_b)/‖ê_f + ê_b‖` per family (Eq. 21, first row, normalised: `d` in both rectifying planes), `d·d − 1`; on no polyline `d − n*` | torsion |
//!
//! and with torsion-free nodes one block per segment `a → b`: `n_e·d_a`, `n_e·d_b`, `n_e·ê`,
//! `n_e·n_e − 1` (Eq. 21, second and third rows: consecutive rulings and the segment in one plane,
//! a planar quad of a developable strip). `ê = e/‖e‖` are unit segment vectors; every norm is
//! differentiated exactly.

use super::net_mesh::NetMesh;
use super::params::BaseMeshWeights;
use crate::field::Family;
use crate::mesh::Vec3;
use crate::solver::{LeastSquaresProblem, VariableLayout};

/// The rows a family adds at a vertex inside its polyline.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum CurveRows {
    /// Pseudo-geodesic of target `cos θ`, `sin θ` (θ read along the polyline's direction).
    Pseudo { cos: f64, sin: f64 },
    Geodesic,
    Asymptotic,
    /// Constant slope (Eq. 22, per segment): every unit segment `ê` along the polyline's
    /// direction has `ê·a = sin β` for the unit axis `a`; then the discrete principal normal
    /// `ê_f + ê_b` is orthogonal to `a`, so `a` lies in every rectifying plane and rulings along
    /// `a` make planar quads: parallel node axes.
    Slope { axis: Vec3, sin: f64 },
}

impl CurveRows {
    /// The rows of `family` at the target `target_degrees` (an angle, or a slope) for the
    /// polyline direction.
    pub fn new(family: Family, target_degrees: f64) -> CurveRows {
        match family {
            Family::Geodesic => CurveRows::Geodesic,
            Family::Asymptotic => CurveRows::Asymptotic,
            Family::ConstantSlope { .. } => CurveRows::Slope { axis: family.slope_axis().unwrap_or_else(Vec3::z), sin: target_degrees.to_radians().sin() },
            Family::PseudoGeodesic { .. } => {
                let (sin, cos) = target_degrees.to_radians().sin_cos();
                CurveRows::Pseudo { cos, sin }
            }
        }
    }

    /// Rows at a vertex inside the polyline (the slope row is per segment, counted apart).
    fn rows(&self) -> usize {
        match self {
            CurveRows::Pseudo { .. } => 8,
            CurveRows::Geodesic => 4,
            CurveRows::Asymptotic => 2,
            CurveRows::Slope { .. } => 0,
        }
    }

    /// Local variables per inner vertex: `b` (P, G) and `u` (P).
    fn auxiliaries(&self) -> usize {
        match self {
            CurveRows::Pseudo { .. } => 6,
            CurveRows::Geodesic => 3,
            CurveRows::Asymptotic | CurveRows::Slope { .. } => 0,
        }
    }
}

/// The reference surface at a vertex's closest point, frozen for an iteration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Anchor {
    pub point: Vec3,
    pub normal: Vec3,
    /// The vertex has slid past the reference's boundary (its offset from `point` was mostly
    /// tangential, now or before): the tangential offset is held too.
    pub beyond_boundary: bool,
}

/// Where a vertex block's variables sit: its stencil vertices' positions first (three columns
/// each), then the ruling (torsion-free), then the local group.
#[derive(Clone, Debug)]
struct VertexBlock {
    /// The vertex, then its distinct neighbours.
    stencil: Vec<u32>,
    /// First variable of the local group (`n`, then per family `b`, `u`).
    local_start: usize,
    /// Offset of family `k`'s `b` in the local group, if it has one here.
    binormal: [Option<usize>; 3],
    rows: usize,
    variables: Vec<u32>,
}

/// The problem.
pub(crate) struct BaseMeshProblem {
    net: NetMesh,
    /// Each family's rows (two for a net, three for a web).
    pub curves: Vec<CurveRows>,
    pub torsion_free: bool,
    pub weights: BaseMeshWeights,
    /// `v_start` of the pull rows.
    start: Vec<Vec3>,
    pub anchors: Vec<Anchor>,
    vertices: Vec<VertexBlock>,
    /// Torsion-free: the segments of both families, with their block variables.
    segments: Vec<[u32; 2]>,
    segment_variables: Vec<[u32; 15]>,
    layout: VariableLayout,
}

/// Rows of a segment block.
const SEGMENT_ROWS: usize = 4;

/// Floor of `‖ê_f + ê_b‖` (2 sin of half the turning angle) by which the torsion-free row
/// `d·(ê_f + ê_b)` is divided: above it the row is the sine of the ruling's angle to the rectifying
/// plane, whatever the turn; a nearly straight polyline (turn below about 3°), whose rectifying
/// plane is barely defined, keeps the paper's unnormalised row, scaled.
const MIN_BISECTOR: f64 = 0.05;

impl BaseMeshProblem {
    /// The problem on `net` (scaled to mean segment 1), its start positions being the pull target.
    pub fn new(net: NetMesh, curves: Vec<CurveRows>, torsion_free: bool, weights: BaseMeshWeights, anchors: Vec<Anchor>) -> BaseMeshProblem {
        let n = net.vertex_count();
        let global = if torsion_free { 6 * n } else { 3 * n };
        let mut group_sizes = Vec::with_capacity(n);
        let mut local_start = global;
        let mut vertices = Vec::with_capacity(n);
        for v in 0..n {
            let mut stencil = vec![v as u32];
            for k in 0..curves.len() {
                let along = net.along(v, k);
                for w in [along.back, along.front].into_iter().flatten() {
                    if !stencil.contains(&w) {
                        stencil.push(w);
                    }
                }
            }
            let mut size = 3;
            let mut binormal = [None; 3];
            let mut rows = 0;
            let tangents = (0..curves.len()).filter(|&k| net.along(v, k).inner().is_some()).count();
            rows += tangents + 1 + if tangents < 2 { 3 } else { 0 };
            for k in 0..curves.len() {
                if net.along(v, k).inner().is_some() {
                    if curves[k].auxiliaries() > 0 {
                        binormal[k] = Some(size);
                    }
                    size += curves[k].auxiliaries();
                    rows += curves[k].rows() + 3;
                }
            }
            for k in (0..curves.len()).filter(|&k| matches!(curves[k], CurveRows::Slope { .. })) {
                rows += usize::from(net.along(v, k).front.is_some()) + usize::from(net.along(v, k).inner().is_some());
            }
            rows += 7;
            if torsion_free {
                let inner = (0..2).filter(|&k| net.along(v, k).inner().is_some()).count();
                let on_any = (0..2).any(|k| net.along(v, k).on_polyline());
                rows += inner + 1 + if on_any { 0 } else { 3 };
            }
            let mut variables: Vec<u32> = stencil.iter().flat_map(|&w| [3 * w, 3 * w + 1, 3 * w + 2]).collect();
            if torsion_free {
                let d = (3 * n + 3 * v) as u32;
                variables.extend([d, d + 1, d + 2]);
            }
            variables.extend((local_start..local_start + size).map(|i| i as u32));
            vertices.push(VertexBlock { stencil, local_start, binormal, rows, variables });
            group_sizes.push(size);
            local_start += size;
        }
        let segments: Vec<[u32; 2]> = if torsion_free { (0..2).flat_map(|k| net.segments(k).collect::<Vec<_>>()).collect() } else { Vec::new() };
        let mut segment_variables = Vec::with_capacity(segments.len());
        for &[a, b] in &segments {
            let (a, b) = (a as usize, b as usize);
            let mut variables = [0u32; 15];
            for c in 0..3 {
                variables[c] = (3 * a + c) as u32;
                variables[3 + c] = (3 * b + c) as u32;
                variables[6 + c] = (3 * n + 3 * a + c) as u32;
                variables[9 + c] = (3 * n + 3 * b + c) as u32;
                variables[12 + c] = (local_start + c) as u32;
            }
            segment_variables.push(variables);
            group_sizes.push(3);
            local_start += 3;
        }
        // Invariant: every group has three or more variables.
        let layout = VariableLayout::with_local_groups(global, &group_sizes).expect("non-empty groups");
        let start = net.positions().to_vec();
        BaseMeshProblem { net, curves, torsion_free, weights, start, anchors, vertices, segments, segment_variables, layout }
    }

    pub fn net(&self) -> &NetMesh {
        &self.net
    }

    /// First variable of vertex `v`'s normal `n`.
    pub fn normal(&self, v: usize) -> usize {
        self.vertices[v].local_start
    }

    /// First variable of family `k`'s binormal `b` at `v` (its side vector `u` follows), if any.
    pub fn binormal(&self, v: usize, k: usize) -> Option<usize> {
        let block = &self.vertices[v];
        block.binormal[k].map(|offset| block.local_start + offset)
    }

    /// First variable of vertex `v`'s ruling (torsion-free nodes only).
    pub fn ruling(&self, v: usize) -> usize {
        3 * self.net.vertex_count() + 3 * v
    }

    /// The segments of the torsion-free rows and the first variable of each one's normal.
    pub fn segments(&self) -> impl Iterator<Item = ([u32; 2], usize)> + '_ {
        self.segments.iter().zip(&self.segment_variables).map(|(&s, vars)| (s, vars[12] as usize))
    }

    fn evaluate_vertex(&self, v: usize, x: &[f64], residuals: &mut [f64], jacobian: Option<&mut [f64]>) {
        let block = &self.vertices[v];
        let columns = block.variables.len();
        let mut rows = Rows { residuals, jacobian, columns, row: 0 };
        let column = |w: u32| 3 * block.stencil.iter().position(|&s| s == w).unwrap_or(0);
        let p = |w: u32| vec3(x, 3 * w as usize);
        let d_column = 3 * block.stencil.len();
        let local_column = d_column + if self.torsion_free { 3 } else { 0 };
        let n = vec3(x, block.local_start);
        let w = &self.weights;
        let curve = w.curve.sqrt();
        let vv = v as u32;
        let anchor = self.anchors[v];

        // Normal rows.
        let mut tangents = 0;
        for k in 0..self.curves.len() {
            let Some((back, front)) = self.net.along(v, k).inner() else { continue };
            tangents += 1;
            let chord = Chord::new(p(front) - p(back));
            rows.value(curve * n.dot(&chord.unit));
            rows.add(local_column, &(chord.unit * curve));
            let g = chord.partial(&n) * curve;
            rows.add(column(front), &g);
            rows.add(column(back), &-g);
            rows.next();
        }
        rows.value(curve * (n.dot(&n) - 1.0));
        rows.add(local_column, &(n * (2.0 * curve)));
        rows.next();
        if tangents < 2 {
            for c in 0..3 {
                rows.value(curve * (n[c] - anchor.normal[c]));
                rows.set(local_column + c, curve);
                rows.next();
            }
        }

        // Family rows and fairness.
        let fair = w.fair.sqrt();
        for k in 0..self.curves.len() {
            let Some((back, front)) = self.net.along(v, k).inner() else { continue };
            let to_front = Chord::new(p(front) - p(vv));
            let to_back = Chord::new(p(back) - p(vv));
            let (cf, cb, cv) = (column(front), column(back), column(vv));
            let offset = block.binormal[k].unwrap_or(0);
            let bc = local_column + offset;
            let b = vec3(x, block.local_start + offset);
            // `a·ê` of a chord from v, with its partials in `a` (column `a_column`) and the ends.
            let chord_row = |rows: &mut Rows, chord: &Chord, end: usize, a: &Vec3, a_column: usize| {
                rows.value(curve * a.dot(&chord.unit));
                rows.add(a_column, &(chord.unit * curve));
                let g = chord.partial(a) * curve;
                rows.add(end, &g);
                rows.add(cv, &-g);
                rows.next();
            };
            match self.curves[k] {
                CurveRows::Pseudo { cos, sin } => {
                    let uc = bc + 3;
                    let u = vec3(x, block.local_start + offset + 3);
                    chord_row(&mut rows, &to_front, cf, &b, bc);
                    chord_row(&mut rows, &to_back, cb, &b, bc);
                    rows.value(curve * (b.dot(&b) - 1.0));
                    rows.add(bc, &(b * (2.0 * curve)));
                    rows.next();
                    let (bn, bu) = (b.dot(&n), b.dot(&u));
                    rows.value(curve * (bn * bn - cos * cos));
                    rows.add(bc, &(n * (2.0 * bn * curve)));
                    rows.add(local_column, &(b * (2.0 * bn * curve)));
                    rows.next();
                    rows.value(curve * (bn * bu - sin * cos));
                    rows.add(bc, &((n * bu + u * bn) * curve));
                    rows.add(uc, &(b * (bn * curve)));
                    rows.add(local_column, &(b * (bu * curve)));
                    rows.next();
                    rows.value(curve * (u.dot(&u) - 1.0));
                    rows.add(uc, &(u * (2.0 * curve)));
                    rows.next();
                    rows.value(curve * u.dot(&n));
                    rows.add(uc, &(n * curve));
                    rows.add(local_column, &(u * curve));
                    rows.next();
                    let tangent = Chord::new(p(front) - p(back));
                    rows.value(curve * u.dot(&tangent.unit));
                    rows.add(uc, &(tangent.unit * curve));
                    let g = tangent.partial(&u) * curve;
                    rows.add(cf, &g);
                    rows.add(cb, &-g);
                    rows.next();
                }
                CurveRows::Geodesic => {
                    chord_row(&mut rows, &to_front, cf, &b, bc);
                    chord_row(&mut rows, &to_back, cb, &b, bc);
                    rows.value(curve * (b.dot(&b) - 1.0));
                    rows.add(bc, &(b * (2.0 * curve)));
                    rows.next();
                    rows.value(curve * n.dot(&b));
                    rows.add(bc, &(n * curve));
                    rows.add(local_column, &(b * curve));
                    rows.next();
                }
                CurveRows::Asymptotic => {
                    chord_row(&mut rows, &to_front, cf, &n, local_column);
                    chord_row(&mut rows, &to_back, cb, &n, local_column);
                }
                CurveRows::Slope { .. } => {}
            }
            let second = p(back) - p(vv) * 2.0 + p(front);
            for c in 0..3 {
                rows.value(fair * second[c]);
                rows.set(cb + c, fair);
                rows.set(cf + c, fair);
                rows.set(cv + c, -2.0 * fair);
                rows.next();
            }
        }

        // Constant slope: the segment to the front neighbour, and the axis in the rectifying plane.
        for k in 0..self.curves.len() {
            let CurveRows::Slope { axis, sin } = self.curves[k] else { continue };
            let along = self.net.along(v, k);
            if let Some(front) = along.front {
                let segment = Chord::new(p(front) - p(vv));
                rows.value(curve * (segment.unit.dot(&axis) - sin));
                let g = segment.partial(&axis) * curve;
                rows.add(column(front), &g);
                rows.add(column(vv), &-g);
                rows.next();
            }
            if let Some((back, front)) = along.inner() {
                let (to_front, to_back) = (Chord::new(p(front) - p(vv)), Chord::new(p(back) - p(vv)));
                plane_row(&mut rows, &to_front, &to_back, &axis, curve, [column(front), column(back), column(vv)]);
                rows.next();
            }
        }

        // Closeness to the reference and the pull to the start.
        let (close, pull) = (w.close.sqrt(), w.pull.sqrt());
        let here = p(vv);
        let offset = here - anchor.point;
        rows.value(close * offset.dot(&anchor.normal));
        rows.add(0, &(anchor.normal * close));
        rows.next();
        if anchor.beyond_boundary {
            let tangential = offset - anchor.normal * offset.dot(&anchor.normal);
            for c in 0..3 {
                rows.value(close * tangential[c]);
                rows.add(0, &((Vec3::ith(c, 1.0) - anchor.normal * anchor.normal[c]) * close));
                rows.next();
            }
        } else {
            rows.row += 3;
        }
        for c in 0..3 {
            rows.value(pull * (here[c] - self.start[v][c]));
            rows.set(c, pull);
            rows.next();
        }

        // Torsion-free nodes (Eq. 21): the ruling in the rectifying plane of each polyline.
        if self.torsion_free {
            let torsion = w.torsion.sqrt();
            let d = vec3(x, self.ruling(v));
            for k in 0..2 {
                let Some((back, front)) = self.net.along(v, k).inner() else { continue };
                let (to_front, to_back) = (Chord::new(p(front) - p(vv)), Chord::new(p(back) - p(vv)));
                let sum = plane_row(&mut rows, &to_front, &to_back, &d, torsion, [column(front), column(back), column(vv)]);
                rows.add(d_column, &(sum * torsion));
                rows.next();
            }
            rows.value(torsion * (d.dot(&d) - 1.0));
            rows.add(d_column, &(d * (2.0 * torsion)));
            rows.next();
            if !(0..2).any(|k| self.net.along(v, k).on_polyline()) {
                for c in 0..3 {
                    rows.value(torsion * (d[c] - anchor.normal[c]));
                    rows.set(d_column + c, torsion);
                    rows.next();
                }
            }
        }
    }

    fn evaluate_segment(&self, s: usize, x: &[f64], residuals: &mut [f64], jacobian: Option<&mut [f64]>) {
        let [a, b] = self.segments[s].map(|v| v as usize);
        let vars = &self.segment_variables[s];
        let mut rows = Rows { residuals, jacobian, columns: 15, row: 0 };
        let torsion = self.weights.torsion.sqrt();
        let (da, db) = (vec3(x, self.ruling(a)), vec3(x, self.ruling(b)));
        let normal = vec3(x, vars[12] as usize);
        let chord = Chord::new(vec3(x, 3 * b) - vec3(x, 3 * a));
        rows.value(torsion * normal.dot(&da));
        rows.add(6, &(normal * torsion));
        rows.add(12, &(da * torsion));
        rows.next();
        rows.value(torsion * normal.dot(&db));
        rows.add(9, &(normal * torsion));
        rows.add(12, &(db * torsion));
        rows.next();
        rows.value(torsion * normal.dot(&chord.unit));
        let g = chord.partial(&normal) * torsion;
        rows.add(3, &g);
        rows.add(0, &-g);
        rows.add(12, &(chord.unit * torsion));
        rows.next();
        rows.value(torsion * (normal.dot(&normal) - 1.0));
        rows.add(12, &(normal * (2.0 * torsion)));
    }
}

impl LeastSquaresProblem for BaseMeshProblem {
    fn variable_count(&self) -> usize {
        self.layout.variable_count()
    }

    fn block_count(&self) -> usize {
        self.vertices.len() + self.segments.len()
    }

    fn block_variables(&self, b: usize) -> &[u32] {
        match self.vertices.get(b) {
            Some(block) => &block.variables,
            None => &self.segment_variables[b - self.vertices.len()],
        }
    }

    fn block_residual_count(&self, b: usize) -> usize {
        self.vertices.get(b).map_or(SEGMENT_ROWS, |block| block.rows)
    }

    fn evaluate_block(&self, b: usize, x: &[f64], residuals: &mut [f64], jacobian: Option<&mut [f64]>) {
        if b < self.vertices.len() {
            self.evaluate_vertex(b, x, residuals, jacobian);
        } else {
            self.evaluate_segment(b - self.vertices.len(), x, residuals, jacobian);
        }
    }

    fn variable_layout(&self) -> VariableLayout {
        self.layout.clone()
    }
}

/// Writes the value and the position partials of the row `scale · d·(ê_f + ê_b)/‖ê_f + ê_b‖`
/// (the sine of `d`'s angle to the rectifying plane, the norm floored at [`MIN_BISECTOR`]) for
/// the chords to the front and back neighbours, whose stencil columns are `[front, back, v]`;
/// returns its partial in `d` divided by `scale`.
fn plane_row(rows: &mut Rows, to_front: &Chord, to_back: &Chord, d: &Vec3, scale: f64, [front, back, v]: [usize; 3]) -> Vec3 {
    let sum = to_front.unit + to_back.unit;
    let length = sum.norm().max(MIN_BISECTOR);
    rows.value(scale * d.dot(&sum) / length);
    // Through `s = ê_f + ê_b`: ∂(d·s/‖s‖)/∂s = (d − (d·ŝ) ŝ)/‖s‖ (d/‖s‖ below the floor).
    let unit = sum / length;
    let through = if sum.norm() > MIN_BISECTOR { (d - unit * d.dot(&unit)) / length } else { d / length };
    let (gf, gb) = (to_front.partial(&through) * scale, to_back.partial(&through) * scale);
    rows.add(front, &gf);
    rows.add(back, &gb);
    rows.add(v, &-(gf + gb));
    sum / length
}

/// The three values of `x` from `start` as a vector.
pub(crate) fn vec3(x: &[f64], start: usize) -> Vec3 {
    Vec3::new(x[start], x[start + 1], x[start + 2])
}

/// A chord `c` with its unit vector, for rows `a·ĉ`.
struct Chord {
    unit: Vec3,
    length: f64,
}

impl Chord {
    fn new(c: Vec3) -> Chord {
        let length = c.norm();
        Chord { unit: if length > 0.0 { c / length } else { Vec3::zeros() }, length }
    }

    /// `∂(a·ĉ)/∂c = (a − (a·ĉ) ĉ) / ‖c‖`.
    fn partial(&self, a: &Vec3) -> Vec3 {
        if self.length > 0.0 {
            (a - self.unit * a.dot(&self.unit)) / self.length
        } else {
            Vec3::zeros()
        }
    }
}

/// Writes a block's rows one after another: the value, then its partials.
struct Rows<'a> {
    residuals: &'a mut [f64],
    jacobian: Option<&'a mut [f64]>,
    columns: usize,
    row: usize,
}

impl Rows<'_> {
    fn value(&mut self, value: f64) {
        self.residuals[self.row] = value;
    }

    /// Adds `d` to the three columns from `column` of the current row.
    fn add(&mut self, column: usize, d: &Vec3) {
        if let Some(jac) = self.jacobian.as_deref_mut() {
            for c in 0..3 {
                jac[self.row * self.columns + column + c] += d[c];
            }
        }
    }

    fn set(&mut self, column: usize, value: f64) {
        if let Some(jac) = self.jacobian.as_deref_mut() {
            jac[self.row * self.columns + column] += value;
        }
    }

    fn next(&mut self) {
        self.row += 1;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::solver::check_block_jacobian;

    /// A 4 × 5 patch of a wavy surface with every kind of row, randomised auxiliaries.
    fn problem(curves: [CurveRows; 2], torsion_free: bool) -> (BaseMeshProblem, Vec<f64>) {
        let curves = curves.to_vec();
        let (rows, columns) = (4usize, 5usize);
        let positions: Vec<Vec3> = (0..rows)
            .flat_map(|i| (0..columns).map(move |j| Vec3::new(j as f64 + 0.1 * i as f64, i as f64, 0.3 * (j as f64 * 0.7).sin() + 0.2 * (i as f64).cos())))
            .collect();
        let r = (0..rows).map(|i| (0..columns).map(|j| (i * columns + j) as u32).collect()).collect();
        let c = (0..columns).map(|j| (0..rows).map(|i| (i * columns + j) as u32).collect()).collect();
        let net = NetMesh::new(positions.clone(), r, c).unwrap();
        let anchors = positions.iter().map(|p| Anchor { point: p + Vec3::new(0.01, -0.02, 0.05), normal: Vec3::new(0.1, 0.2, 1.0).normalize(), beyond_boundary: p.x > 2.0 }).collect();
        let weights = BaseMeshWeights { curve: 2.0, fair: 0.3, close: 0.5, pull: 0.1, torsion: 1.5 };
        let problem = BaseMeshProblem::new(net, curves, torsion_free, weights, anchors);
        let mut x: Vec<f64> = (0..problem.variable_count()).map(|i| ((i * 7919) % 113) as f64 / 113.0 - 0.4).collect();
        for (v, p) in positions.iter().enumerate() {
            x[3 * v..3 * v + 3].copy_from_slice(p.as_slice());
        }
        (problem, x)
    }

    #[test]
    fn every_block_jacobian_matches_finite_differences() {
        let pseudo = CurveRows::new(Family::PseudoGeodesic { theta_degrees: 60.0 }, 60.0);
        let slope = CurveRows::Slope { axis: Vec3::new(0.2, 0.1, 1.0).normalize(), sin: 0.3 };
        for curves in [[pseudo, pseudo], [CurveRows::Geodesic, CurveRows::Asymptotic], [CurveRows::Asymptotic, pseudo], [slope, pseudo], [slope, slope]] {
            for torsion_free in [false, true] {
                let (problem, x) = problem(curves, torsion_free);
                for b in 0..problem.block_count() {
                    let error = check_block_jacobian(&problem, &x, b, 1e-6);
                    assert!(error < 1e-6, "{curves:?}, torsion-free {torsion_free}: block {b} off by {error}");
                }
            }
        }
    }
}
