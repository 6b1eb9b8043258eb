//! Base-mesh optimisation (paper Sec. 3.5) and torsion-free nodes (Sec. 5.2.1, Eq. 21), judged
//! from outside against nets known in closed form: the ±45° helices of a cylinder (geodesics
//! whose rectifying developables all have rulings along the axis) and the two families of
//! constant-slope spirals of a cone (pseudo-geodesics of one angle, Sec. 5.2.2: parallel node
//! axes), both torsion-free. Each is perturbed, optimised back, and measured with the exact
//! surface normals and the strips' own rulings.

use lamella::base_mesh::{BaseMeshError, BaseMeshParams, BaseMeshSolver, NetMesh, TORSION_FREE_DEGREES};
use lamella::field::Family;
use lamella::mesh::{TriMesh, Vec3};
use lamella::strips::StripPattern;
use std::collections::BTreeMap;

/// A deterministic jitter in `[-amplitude, amplitude]`.
fn jitter(amplitude: f64) -> impl FnMut() -> f64 {
    let mut state = 12345u64;
    move || {
        state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        amplitude * (((state >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0)
    }
}

/// The net of the vertices `index[(i, j)]`: rows of constant `i` (increasing `j`), columns of
/// constant `j`, cut where a vertex is missing.
fn grid_polylines(index: &BTreeMap<(i32, i32), u32>, size: i32) -> (Vec<Vec<u32>>, Vec<Vec<u32>>) {
    let runs = |key: &dyn Fn(i32, i32) -> (i32, i32)| {
        let mut lines = Vec::new();
        for a in 0..size {
            let mut run = Vec::new();
            for b in 0..=size {
                match index.get(&key(a, b)) {
                    Some(&v) if b < size => run.push(v),
                    _ => {
                        if run.len() >= 2 {
                            lines.push(std::mem::take(&mut run));
                        }
                        run.clear();
                    }
                }
            }
        }
        lines
    };
    (runs(&|a, b| (a, b)), runs(&|a, b| (b, a)))
}

pub(crate) const HELIX_RADIUS: f64 = 10.0;

/// A net of ±45° helices on the cylinder of radius 10 (development coordinates `s = Rφ`, `z`),
/// each vertex moved by up to `noise` in each coordinate; rows and columns, and the surface.
pub(crate) fn helix_net(noise: f64) -> (NetMesh, TriMesh) {
    use lamella::surfaces::{cylinder_patch, CylinderPatch};
    let radius = HELIX_RADIUS;
    let surface = cylinder_patch(&CylinderPatch { radius, span: 2.6, height: 15.0, target_vertices: 3000, irregularity: 0.3, seed: 4 }).unwrap().into_mesh().unwrap();
    let h = 1.2;
    let mut index = BTreeMap::new();
    let mut positions = Vec::new();
    let mut jitter = jitter(noise);
    for i in 0..40i32 {
        for j in 0..40i32 {
            let (s, z) = (1.5 + f64::from(i + j) * h * 0.5, 7.5 + f64::from(j - i) * h * 0.5);
            if s > 24.5 || !(0.8..=14.2).contains(&z) {
                continue;
            }
            let phi = s / radius;
            index.insert((i, j), positions.len() as u32);
            positions.push(Vec3::new(radius * phi.cos() + jitter(), radius * phi.sin() + jitter(), z + jitter()));
        }
    }
    let (rows, columns) = grid_polylines(&index, 40);
    (NetMesh::new(positions, rows, columns).unwrap(), surface)
}

/// The cone `z = a r` of the spiral nets.
const CONE: f64 = 0.6;
/// Inclination of the spirals against the horizontal planes (below the cone's 31°).
pub(crate) const SPIRAL_SLOPE_DEGREES: f64 = 20.0;

fn cone_point(r: f64, phi: f64) -> Vec3 {
    Vec3::new(r * phi.cos(), r * phi.sin(), CONE * r)
}

/// The exact unit normal of the cone at `p`.
fn cone_normal(p: &Vec3) -> Vec3 {
    let r = p.x.hypot(p.y);
    Vec3::new(-CONE * p.x / r, -CONE * p.y / r, 1.0).normalize()
}

/// The cone for `r` in [3.5, 12.5], `φ` in [−1.3, 1.3], as a triangulated grid.
pub(crate) fn cone_surface() -> TriMesh {
    let (nr, nphi) = (46usize, 70usize);
    let mut positions = Vec::new();
    for i in 0..nr {
        for j in 0..nphi {
            positions.push(cone_point(3.5 + 9.0 * i as f64 / (nr - 1) as f64, -1.3 + 2.6 * j as f64 / (nphi - 1) as f64));
        }
    }
    let mut faces = Vec::new();
    for i in 0..nr - 1 {
        for j in 0..nphi - 1 {
            let v = (i * nphi + j) as u32;
            let (right, up) = (v + 1, v + nphi as u32);
            faces.push([v, right, up + 1]);
            faces.push([v, up + 1, up]);
        }
    }
    TriMesh::from_vertices_and_faces(positions, faces).unwrap()
}

/// The two families of constant-slope spirals of the cone, `φ = u + c ln r` (rows) and
/// `φ = w − c ln r` (columns), at equal steps of `u` and `w`, each vertex moved by up to `noise`
/// in each coordinate. On a cone each family is a family of pseudo-geodesics of one angle (the
/// cone is self-similar along them), and both share the vertical as the ruling of their
/// rectifying developables (Sec. 5.2.2), a torsion-free PP net.
pub(crate) fn spiral_net(noise: f64) -> NetMesh {
    let s = SPIRAL_SLOPE_DEGREES.to_radians().sin();
    // Along a spiral dz/ds = sin β with z = a r: dr/ds = s/a, and r dφ/ds = √(1 − (1 + a²) s²/a²).
    let c = CONE * (1.0 - (1.0 + CONE * CONE) * s * s / (CONE * CONE)).sqrt() / s;
    let step = 0.15;
    let mut index = BTreeMap::new();
    let mut positions = Vec::new();
    let mut jitter = jitter(noise);
    for i in 0..40i32 {
        for j in 0..40i32 {
            let (u, w) = (-4.6 + step * f64::from(i), 0.5 + step * f64::from(j));
            let (r, phi) = (((w - u) / (2.0 * c)).exp(), 0.5 * (u + w));
            if !(4.2..=11.8).contains(&r) || phi.abs() > 1.05 {
                continue;
            }
            index.insert((i, j), positions.len() as u32);
            positions.push(cone_point(r, phi) + Vec3::new(jitter(), jitter(), jitter()));
        }
    }
    let (rows, columns) = grid_polylines(&index, 40);
    NetMesh::new(positions, rows, columns).unwrap()
}

/// Steps `solver` until it converges, at most `cap` iterations.
fn converge(solver: &mut BaseMeshSolver, cap: usize) {
    while solver.iterations() < cap && !solver.step(10).unwrap().converged {}
    assert!(solver.is_converged(), "not converged in {cap} iterations: {:?}", solver.report());
}

/// The signed angle of Sec. 3.1 between the discrete binormal at every inner vertex of family
/// `k`'s polylines and the exact surface normal `normal`.
pub(crate) fn polyline_angles(net: &NetMesh, k: usize, normal: impl Fn(&Vec3) -> Vec3) -> Vec<f64> {
    let p = net.positions();
    let mut angles = Vec::new();
    for line in net.polylines(k) {
        for w in line.windows(3) {
            let (a, b, c) = (p[w[0] as usize], p[w[1] as usize], p[w[2] as usize]);
            let binormal = (b - a).cross(&(c - b)).normalize();
            let n = normal(&b);
            let side = n.cross(&(c - a)).normalize();
            let sign = if binormal.dot(&side) < 0.0 { -1.0 } else { 1.0 };
            angles.push((sign * binormal.dot(&n)).clamp(-1.0, 1.0).acos().to_degrees());
        }
    }
    angles
}

/// From the strips themselves: the largest |det(d_j, d_{j+1}, ê_j)| of a quad (Eq. 17) and the
/// largest angle between the two families' rulings at a vertex both strips pass through.
fn strips_planarity_and_shared_rulings(net: &NetMesh, strips: &[StripPattern]) -> (f64, f64) {
    let mut planarity: f64 = 0.0;
    let mut at: BTreeMap<u32, [Option<Vec3>; 2]> = BTreeMap::new();
    for (k, pattern) in strips.iter().enumerate() {
        for strip in &pattern.strips {
            let line = &net.polylines(k)[strip.curve];
            for j in 0..strip.centre.len() - 1 {
                let e = (strip.centre[j + 1] - strip.centre[j]).normalize();
                planarity = planarity.max(strip.rulings[j].dot(&strip.rulings[j + 1].cross(&e)).abs());
            }
            for (i, &v) in line.iter().enumerate() {
                assert!((strip.centre[i] - net.positions()[v as usize]).norm() < 1e-12, "the strip's centre is its polyline");
                at.entry(v).or_default()[k] = Some(strip.rulings[i]);
            }
        }
    }
    let shared = at.values().filter_map(|[a, b]| Some(a.as_ref()?.dot(b.as_ref()?).abs().min(1.0).acos().to_degrees())).fold(0.0, f64::max);
    (planarity, shared)
}

#[test]
fn a_perturbed_net_of_helices_is_restored_to_a_torsion_free_geodesic_net() {
    let geodesic = Family::Geodesic;
    // The measures on the exact net: geodesic, torsion-free.
    let (exact, surface) = helix_net(0.0);
    let start = BaseMeshSolver::new(&exact, &surface, BaseMeshParams::new(geodesic, geodesic)).unwrap();
    let report = start.initial_report();
    assert!(report.node_torsion.nodes > 200 && report.node_torsion.max_degrees < 1e-4, "{:?}", report.node_torsion);
    assert!(report.families.iter().all(|f| f.max_error_degrees < 0.01), "{:?}", report.families);

    let (net, surface) = helix_net(0.02);
    let mut params = BaseMeshParams::new(geodesic, geodesic);
    params.torsion_free = true;
    let mut solver = BaseMeshSolver::new(&net, &surface, params).unwrap();
    let before = solver.initial_report().clone();
    assert!(before.node_torsion.max_degrees > 20.0 && !before.families_met, "{before:?}");
    converge(&mut solver, 400);
    let report = solver.report();
    assert!(report.families_met && report.torsion_free, "{report:?}");
    assert!(report.node_torsion.max_degrees <= TORSION_FREE_DEGREES, "{:?}", report.node_torsion);
    // From outside: on the cylinder, geodesic (binormal tangent to it) to 1°.
    let optimised = solver.net();
    for p in optimised.positions() {
        assert!((p.x.hypot(p.y) - HELIX_RADIUS).abs() <= 1e-3 * HELIX_RADIUS, "{p:?} off the cylinder");
    }
    let radial = |p: &Vec3| Vec3::new(p.x, p.y, 0.0).normalize();
    for k in 0..2 {
        let worst = polyline_angles(&optimised, k, radial).iter().map(|a| (a - 90.0).abs()).fold(0.0, f64::max);
        assert!(worst <= 1.0, "family {k}: {worst}° from geodesic");
    }
    // The strips: planar quads, the same ruling at every node, and that ruling the axis (the
    // rectifying developable of a helix is its cylinder, ruled along the axis).
    let strips = solver.strips(0.3, 1.0).unwrap();
    assert!(strips.iter().all(|p| p.strips.len() >= 10), "{} and {} strips", strips[0].strips.len(), strips[1].strips.len());
    let (planarity, shared) = strips_planarity_and_shared_rulings(&optimised, &strips);
    assert!(planarity < 1e-9 && shared <= TORSION_FREE_DEGREES, "planarity {planarity}, rulings {shared}° apart at a node");
    for pattern in &strips {
        for strip in &pattern.strips {
            for d in &strip.rulings {
                assert!(d.z.abs() >= 1.0f64.to_radians().cos(), "a ruling {d:?} leaves the axis direction");
            }
        }
    }
}

#[test]
fn a_perturbed_net_of_constant_slope_spirals_on_a_cone_is_restored_to_a_torsion_free_pp_net() {
    let exact = spiral_net(0.0);
    let surface = cone_surface();
    // θ of the spirals, from the exact net's own discrete binormals against the exact normal:
    // one angle along the whole family (the cone is self-similar along them).
    let angles = polyline_angles(&exact, 0, cone_normal);
    let theta = angles[angles.len() / 2];
    assert!(angles.iter().all(|a| (a - theta).abs() < 0.01) && (10.0..170.0).contains(&theta) && (theta - 90.0).abs() > 10.0, "rows: {theta}° ± {:?}", angles.iter().map(|a| a - theta).fold(0.0, f64::max));
    let family = Family::PseudoGeodesic { theta_degrees: theta };
    let start = BaseMeshSolver::new(&exact, &surface, BaseMeshParams::new(family, family)).unwrap();
    let report = start.initial_report();
    assert!(report.node_torsion.nodes > 100 && report.node_torsion.max_degrees < 1e-3, "{:?}", report.node_torsion);
    assert!(report.families.iter().all(|f| f.max_error_degrees < 0.1 && f.straight == 0), "{:?}", report.families);

    let net = spiral_net(0.01);
    let mut params = BaseMeshParams::new(family, family);
    params.torsion_free = true;
    let mut solver = BaseMeshSolver::new(&net, &surface, params).unwrap();
    assert!(solver.initial_report().node_torsion.max_degrees > 10.0, "{:?}", solver.initial_report().node_torsion);
    converge(&mut solver, 400);
    let report = solver.report().clone();
    assert!(report.families_met && report.torsion_free, "{report:?}");
    let optimised = solver.net();
    for p in optimised.positions() {
        let r = p.x.hypot(p.y);
        assert!((p.z - CONE * r).abs() * cone_normal(p).z <= 1e-3 * 12.0, "{p:?} off the cone");
    }
    for k in 0..2 {
        let target = report.targets_degrees[k];
        assert!((target - theta).abs() < 1e-9 || (target - (180.0 - theta)).abs() < 1e-9, "family {k} held at {target}°");
        let worst = polyline_angles(&optimised, k, cone_normal).iter().map(|a| (a - target).abs()).fold(0.0, f64::max);
        assert!(worst <= 1.0, "family {k}: {worst}° from {target}°");
    }
    let strips = solver.strips(0.3, 1.0).unwrap();
    let (planarity, shared) = strips_planarity_and_shared_rulings(&optimised, &strips);
    assert!(planarity < 1e-9 && shared <= TORSION_FREE_DEGREES, "planarity {planarity}, rulings {shared}° apart at a node");
}

#[test]
fn the_optimisation_gives_the_same_bits_on_any_number_of_threads() {
    let (net, surface) = helix_net(0.02);
    let run = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
        pool.install(|| {
            let mut params = BaseMeshParams::new(Family::Geodesic, Family::Geodesic);
            params.torsion_free = true;
            let mut solver = BaseMeshSolver::new(&net, &surface, params).unwrap();
            solver.step(30).unwrap();
            solver.positions().iter().flat_map(|p| p.iter().map(|x| x.to_bits()).collect::<Vec<_>>()).collect::<Vec<u64>>()
        })
    };
    assert_eq!(run(1), run(3));
}

#[test]
fn bad_requests_are_refused_by_name() {
    let (net, surface) = helix_net(0.0);
    let slope = Family::ConstantSlope { axis: [0.0, 0.0, 1.0], slope_degrees: 20.0, free_slope: true };
    let error = BaseMeshSolver::new(&net, &surface, BaseMeshParams::new(slope, Family::Geodesic)).err().unwrap();
    assert!(matches!(error, BaseMeshError::InvalidParameter { name: "families", .. }), "{error}");
    let mut params = BaseMeshParams::new(Family::Geodesic, Family::Geodesic);
    params.weights.curve = f64::NAN;
    let error = BaseMeshSolver::new(&net, &surface, params).err().unwrap();
    assert!(error.to_string().contains("weights.curve"), "{error}");
    // Two-vertex polylines only: no vertex inside a polyline.
    let pairs = NetMesh::new(net.positions()[..4].to_vec(), vec![vec![0, 1]], vec![vec![2, 3]]).unwrap();
    assert_eq!(BaseMeshSolver::new(&pairs, &surface, BaseMeshParams::new(Family::Geodesic, Family::Geodesic)).err(), Some(BaseMeshError::NothingToOptimise));
    let solver = BaseMeshSolver::new(&net, &surface, BaseMeshParams::new(Family::Geodesic, Family::Geodesic)).unwrap();
    assert!(solver.strips(f64::INFINITY, 1.0).unwrap_err().to_string().contains("width"));
}

#[test]
fn a_perturbed_net_of_spirals_optimised_for_constant_slope_gets_vertical_node_axes() {
    let net = spiral_net(0.01);
    let surface = cone_surface();
    let slope = Family::ConstantSlope { axis: [0.0, 0.0, 1.0], slope_degrees: SPIRAL_SLOPE_DEGREES, free_slope: false };
    let mut solver = BaseMeshSolver::new(&net, &surface, BaseMeshParams::new(slope, slope)).unwrap();
    assert!(solver.initial_report().node_torsion.max_degrees > 10.0, "{:?}", solver.initial_report().node_torsion);
    converge(&mut solver, 400);
    let report = solver.report().clone();
    assert!(report.families_met && report.torsion_free, "{report:?}");
    // From outside: every segment at the slope, the net on the cone, the strips' rulings (fitted
    // to the polylines alone) vertical and shared at the nodes: parallel node axes (Sec. 5.2.2).
    let optimised = solver.net();
    for k in 0..2 {
        let target = report.targets_degrees[k];
        assert!((target.abs() - SPIRAL_SLOPE_DEGREES).abs() < 1e-9, "family {k} held at {target}°");
        for line in optimised.polylines(k) {
            for w in line.windows(2) {
                let e = (optimised.positions()[w[1] as usize] - optimised.positions()[w[0] as usize]).normalize();
                let measured = e.z.asin().to_degrees();
                assert!((measured - target).abs() <= 0.5, "family {k}: a segment at {measured}°, not {target}°");
            }
        }
    }
    for p in optimised.positions() {
        let r = p.x.hypot(p.y);
        assert!((p.z - CONE * r).abs() * cone_normal(p).z <= 1e-3 * 12.0, "{p:?} off the cone");
    }
    let strips = solver.strips(0.3, 1.0).unwrap();
    let (planarity, shared) = strips_planarity_and_shared_rulings(&optimised, &strips);
    assert!(planarity < 1e-9 && shared <= TORSION_FREE_DEGREES, "planarity {planarity}, rulings {shared}° apart at a node");
    for pattern in &strips {
        assert!(pattern.strips.len() >= 10, "{} strips", pattern.strips.len());
        for strip in &pattern.strips {
            for d in &strip.rulings[1..strip.rulings.len() - 1] {
                assert!(d.z.abs() >= 0.5f64.to_radians().cos(), "a ruling {d:?} is not vertical");
            }
        }
    }
}
