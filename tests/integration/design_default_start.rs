//! The default design on surfaces the project has not prepared, judged from outside: level
//! curves against analytic answers (catenaries in a cylinder's development, the straight rulings
//! of a hyperbolic paraboloid) and strip planes against the exact surface normals. No start is
//! given: the default start search picks it.

use crate::field_support;

use field_support::{catenary_hausdorff, develop, line_fit};
use lamella::curves::{extract_level_curves, uniform_levels, LevelCurve};
use lamella::field::{Family, FieldError, FieldParams, FieldSolver};
use lamella::initialisation::{search_start, Candidate, SearchError, SearchOptions, StartKind};
use lamella::mesh::{TriMesh, Vec3};
use lamella::quality::{family_angles, FamilyAngles};
use lamella::strips::{rectifying_strips, StripParams, StripPattern};
use lamella::surfaces::{cylinder_patch, hall_roof, hyperbolic_paraboloid, CylinderPatch, HyperbolicParaboloid, SplitMix64};

const RADIUS: f64 = 5.0;

/// A cylinder patch like the outside reviewer's: R 5 m, 120° span, 8 m high, irregular.
fn cylinder(target_vertices: usize) -> TriMesh {
    let patch = CylinderPatch { radius: RADIUS, span: 120f64.to_radians(), height: 8.0, target_vertices, irregularity: 0.5, seed: 21 };
    cylinder_patch(&patch).expect("valid patch").into_mesh().expect("valid mesh")
}

/// The field of the family of `theta` from the default start, converged.
fn default_design(mesh: &TriMesh, theta: f64) -> FieldSolver {
    let outcome = search_start(mesh, FieldParams::pseudo_geodesic(theta), SearchOptions::default()).expect("a start");
    // Meshes well above the default stand-in size are searched on a coarsening of it.
    let proxy = SearchOptions::default().proxy_vertices;
    assert_eq!(outcome.proxy_vertices.is_some(), 2 * mesh.vertex_count() > 3 * proxy, "{:?}", outcome.proxy_vertices);
    let mut solver = outcome.solver;
    let report = solver.step(400).expect("solver runs");
    assert!(report.converged, "not converged after {} iterations", report.iterations);
    solver
}

fn level_curves(mesh: &TriMesh, field: &[f64], count: usize) -> Vec<LevelCurve> {
    let levels = uniform_levels(mesh, field, count).expect("levels");
    extract_level_curves(mesh, field, &levels).expect("curves")
}

/// Largest symmetric Hausdorff distance between a level curve and its best catenary
/// `v = c cosh(u/c)` (c = R tan θ) in the development, over the curve's length; curves shorter
/// than a quarter of the height are left out (corner pieces).
fn worst_catenary_deviation(mesh: &TriMesh, field: &[f64], theta: f64) -> f64 {
    let k = 1.0 / (RADIUS * theta.to_radians().tan());
    let mut worst: f64 = 0.0;
    let mut measured = 0;
    for curve in level_curves(mesh, field, 12) {
        let points: Vec<(f64, f64)> = curve.points.iter().map(|p| develop(p, RADIUS)).collect();
        let length: f64 = points.windows(2).map(|w| (w[1].0 - w[0].0).hypot(w[1].1 - w[0].1)).sum();
        if length < 2.0 {
            continue;
        }
        worst = worst.max(catenary_hausdorff(&points, k) / length);
        measured += 1;
    }
    assert!(measured >= 8, "only {measured} level curves measured");
    worst
}

/// The signed angle (Sec. 3.1) of each strip quad's plane against the exact normal `normal`:
/// the quad's direction across its centre line, `ê × N̂`, compared with θ (without sign at 0°).
pub(crate) fn worst_quad_angle_error(pattern: &StripPattern, theta: f64, normal: impl Fn(&Vec3) -> Vec3) -> f64 {
    quad_angle_errors(pattern, theta, normal).into_iter().fold(0.0, f64::max)
}

/// The angle error of [`worst_quad_angle_error`] of every quad, strip by strip.
pub(crate) fn quad_angle_errors(pattern: &StripPattern, theta: f64, normal: impl Fn(&Vec3) -> Vec3) -> Vec<f64> {
    let mut errors = Vec::new();
    for strip in &pattern.strips {
        for j in 0..strip.centre.len() - 1 {
            let edge = (strip.centre[j + 1] - strip.centre[j]).normalize();
            let quad_normal = edge.cross(&(strip.left[j] - strip.centre[j])).normalize();
            let n = normal(&((strip.centre[j] + strip.centre[j + 1]) * 0.5));
            let across = edge.cross(&quad_normal);
            let sign = if across.dot(&n.cross(&edge)) < 0.0 { -1.0 } else { 1.0 };
            let angle = (sign * across.dot(&n)).clamp(-1.0, 1.0).acos().to_degrees();
            // At θ = 0° (asymptotic curves) a binormal at 180° is the same family.
            errors.push(if theta == 0.0 { angle.min(180.0 - angle) } else { (angle - theta).abs() });
        }
    }
    errors
}

fn strips(mesh: &TriMesh, field: &[f64], theta: f64) -> StripPattern {
    let curves: Vec<LevelCurve> = level_curves(mesh, field, 10).iter().map(|c| c.resampled(mesh.mean_edge_length()).expect("resampled")).collect();
    rectifying_strips(mesh, &curves, &StripParams::new(theta, 0.25)).expect("valid parameters")
}

#[test]
fn cylinder_families_from_the_default_start_are_the_catenaries() {
    let mesh = cylinder(3000);
    let radial = |p: &Vec3| Vec3::new(p.x, p.y, 0.0).normalize();
    for theta in [45.0, 60.0, 75.0] {
        let solver = default_design(&mesh, theta);
        let field = solver.field();
        // Paper Fig. 10: 0.47 % of the curve length; the issue asks 0.45 % at ~3,000 vertices.
        let deviation = worst_catenary_deviation(&mesh, &field, theta);
        assert!(deviation <= 0.0045, "θ = {theta}°: a level curve is {:.3} % of its length off its catenary", 100.0 * deviation);
        let pattern = strips(&mesh, &field, theta);
        assert!(pattern.verdict.is_acceptable(), "θ = {theta}°: {}", pattern.verdict.message());
        assert_eq!(pattern.metrics.flipped_quads, 0);
        let error = worst_quad_angle_error(&pattern, theta, radial);
        assert!(error <= 1.5, "θ = {theta}°: a strip plane is {error}° off against the exact normal");
    }
}

#[test]
fn cylinder_catenaries_get_closer_as_the_mesh_is_refined() {
    let coarse = worst_catenary_deviation(&cylinder(3000), &default_design(&cylinder(3000), 60.0).field(), 60.0);
    let fine_mesh = cylinder(10000);
    // Both meshes are searched on a 1,500-vertex coarsening, and the winner carried over.
    let fine_field = default_design(&fine_mesh, 60.0).field();
    let fine = worst_catenary_deviation(&fine_mesh, &fine_field, 60.0);
    assert!(coarse <= 0.0045, "3,000 vertices: {:.3} %", 100.0 * coarse);
    assert!(fine <= 0.0025, "10,000 vertices: {:.3} %", 100.0 * fine);
    let pattern = strips(&fine_mesh, &fine_field, 60.0);
    assert!(pattern.verdict.is_acceptable(), "10,000 vertices: {}", pattern.verdict.message());
    let error = worst_quad_angle_error(&pattern, 60.0, |p: &Vec3| Vec3::new(p.x, p.y, 0.0).normalize());
    assert!(error <= 1.5, "10,000 vertices: a strip plane is {error}° off against the exact normal");
}

#[test]
fn the_search_rejects_the_rulings_of_the_cylinder() {
    // The height along the chord of the arc has the rulings as level sets: straight, so every
    // P-curve condition holds in the limit. The search must reject it as degenerate.
    let mesh = cylinder(1500);
    let outcome = search_start(&mesh, FieldParams::pseudo_geodesic(60.0), SearchOptions::default()).expect("a start");
    let rulings: Vec<_> = outcome
        .candidates
        .iter()
        .filter(|c| matches!(c.kind, StartKind::Height { direction, .. } if direction[2].abs() < 0.1))
        .collect();
    assert!(!rulings.is_empty());
    for c in &rulings {
        assert!(c.rejected.is_some(), "{} was not rejected: {c:?}", c.kind.describe());
    }
    let winner = &outcome.candidates[outcome.winner];
    assert!(winner.rejected.is_none() && winner.straight_fraction < 0.5, "{winner:?}");
}

/// The guide candidates follow the heights only when no height scores at most
/// `SearchOptions::acceptable_score`: on the hall roof at θ = 45° the heights score above the
/// default, so the guides are probed after them; told that the best height's score is good
/// enough, the search stops after the heights, with the same winner.
#[test]
fn guide_candidates_follow_only_when_no_height_is_good_enough() {
    let mesh = hall_roof(3_000).into_mesh().expect("the built-in roof is valid");
    let params = FieldParams::pseudo_geodesic(45.0);
    let is_height = |c: &&Candidate| matches!(c.kind, StartKind::Height { .. });
    let strict = search_start(&mesh, params.clone(), SearchOptions::default()).expect("a start");
    let heights: Vec<&Candidate> = strict.candidates.iter().filter(is_height).collect();
    let best_height = heights.iter().filter_map(|c| c.score).fold(f64::INFINITY, f64::min);
    assert!(best_height.is_finite() && best_height > SearchOptions::default().acceptable_score, "best height {best_height}");
    assert!(strict.candidates.len() > heights.len(), "no guide candidate after heights scoring {best_height}");
    assert!(strict.candidates[heights.len()..].iter().all(|c| matches!(c.kind, StartKind::Guides { .. })));

    let lenient = SearchOptions { acceptable_score: best_height, ..SearchOptions::default() };
    let outcome = search_start(&mesh, params, lenient).expect("a start");
    assert_eq!(outcome.candidates.len(), heights.len(), "{:?}", outcome.candidates.iter().map(|c| c.kind.describe()).collect::<Vec<_>>());
    assert_eq!(outcome.candidates[outcome.winner].score, Some(best_height));
}

/// Search options out of range are refused before any probe, naming the option.
#[test]
fn search_options_out_of_range_are_refused_by_name() {
    let mesh = hall_roof(600).into_mesh().expect("the built-in roof is valid");
    let cases: [(&str, SearchOptions); 10] = [
        ("probe_iterations", SearchOptions { probe_iterations: 0, ..SearchOptions::default() }),
        ("levels", SearchOptions { levels: 1, ..SearchOptions::default() }),
        ("spacing_edges", SearchOptions { spacing_edges: f64::NAN, ..SearchOptions::default() }),
        ("directions", SearchOptions { directions: 0, ..SearchOptions::default() }),
        ("guides", SearchOptions { guides: 1, ..SearchOptions::default() }),
        ("guide_angles", SearchOptions { guide_angles: vec![60.0, 180.0], ..SearchOptions::default() }),
        ("proxy_vertices", SearchOptions { proxy_vertices: 50, ..SearchOptions::default() }),
        ("acceptable_score", SearchOptions { acceptable_score: f64::NAN, ..SearchOptions::default() }),
        ("stall_factor", SearchOptions { stall_factor: 0.5, ..SearchOptions::default() }),
        ("stall_factor", SearchOptions { stall_factor: f64::NAN, ..SearchOptions::default() }),
    ];
    for (name, options) in cases {
        match search_start(&mesh, FieldParams::pseudo_geodesic(60.0), options) {
            Err(SearchError::Field(FieldError::InvalidParameter { name: named, .. })) => assert_eq!(named, name),
            Err(other) => panic!("{name}: {other}"),
            Ok(_) => panic!("{name}: accepted"),
        }
    }
    let never = SearchOptions { stall_factor: f64::INFINITY, ..SearchOptions::default() };
    assert!(search_start(&mesh, FieldParams::pseudo_geodesic(60.0), never).is_ok());
}

#[test]
fn asymptotic_family_of_a_hyperbolic_paraboloid_is_its_rulings() {
    let surface = HyperbolicParaboloid { c: 5.0, half_width: 5.0, target_vertices: 2000, irregularity: 0.5, seed: 8 };
    let mesh = hyperbolic_paraboloid(&surface).expect("valid surface").into_mesh().expect("valid mesh");
    // θ = 0 names the asymptotic family (E_asy, Eq. 13), not the pseudo-geodesic energy at 0°.
    let solver = default_design(&mesh, 0.0);
    assert_eq!(solver.params().family, Family::Asymptotic);
    let field = solver.field();
    let mut measured = 0;
    for curve in level_curves(&mesh, &field, 12) {
        let plan: Vec<(f64, f64)> = curve.points.iter().map(|p| (p.x, p.y)).collect();
        let (deviation, length) = line_fit(&plan);
        if length < 2.0 {
            continue;
        }
        // Straight lines, along x or along y in plan: the rulings of z = xy/5.
        assert!(deviation <= 0.005 * length, "a level curve bends by {:.3} % of its length", 100.0 * deviation / length);
        let (first, last) = (plan[0], plan[plan.len() - 1]);
        let (dx, dy) = ((last.0 - first.0).abs(), (last.1 - first.1).abs());
        assert!(dx.min(dy) <= 0.01 * dx.max(dy), "a level curve runs diagonally ({dx}, {dy})");
        measured += 1;
    }
    assert!(measured >= 8, "only {measured} curves measured");
    // The strips' binormals against the exact normal (−y/c, −x/c, 1): asymptotic curves have no
    // sign, so a binormal measured at 180° meets θ = 0° (Table 4's diff θ as well as the planes).
    let pattern = strips(&mesh, &field, 0.0);
    let normal = |p: &Vec3| Vec3::new(-p.y / surface.c, -p.x / surface.c, 1.0).normalize();
    assert!(pattern.metrics.max_diff_theta_degrees <= 1.5, "max diff θ {}°", pattern.metrics.max_diff_theta_degrees);
    let error = worst_quad_angle_error(&pattern, 0.0, normal);
    assert!(error <= 1.5, "a strip plane is {error}° off against the exact normal");
}

#[test]
fn theta_ninety_is_the_geodesic_family() {
    let mesh = cylinder(1500);
    let solver = default_design(&mesh, 90.0);
    assert_eq!(solver.params().family, Family::Geodesic);
    // Geodesics of a cylinder are helices: straight lines in the development.
    for curve in level_curves(&mesh, &solver.field(), 8) {
        let points: Vec<(f64, f64)> = curve.points.iter().map(|p| develop(p, RADIUS)).collect();
        let (deviation, length) = line_fit(&points);
        if length > 2.0 {
            assert!(deviation <= 0.005 * length, "a geodesic bends by {:.3} % of its length", 100.0 * deviation / length);
        }
    }
}

#[test]
fn a_cone_carries_a_sixty_degree_family_with_acceptable_strips() {
    // A cone (a developable surface) with axis z and half-angle 30°, mapped from a jittered grid.
    let half_angle = 30f64.to_radians();
    let patch = CylinderPatch { radius: 6.0, span: 120f64.to_radians(), height: 6.0, target_vertices: 2500, irregularity: 0.5, seed: 5 };
    let grid = cylinder_patch(&patch).expect("valid patch");
    let positions = grid
        .positions
        .iter()
        .map(|p| {
            let (phi, s) = (p.y.atan2(p.x), 3.0 + p.z);
            Vec3::new(s * half_angle.sin() * phi.cos(), s * half_angle.sin() * phi.sin(), s * half_angle.cos())
        })
        .collect();
    let mesh = TriMesh::from_vertices_and_faces(positions, grid.faces).expect("valid cone");
    // Exact outward normal of the cone: radial in plan, tilted by the half-angle.
    let normal = |p: &Vec3| {
        let radial = Vec3::new(p.x, p.y, 0.0).normalize();
        (radial * half_angle.cos() - Vec3::z() * half_angle.sin()).normalize()
    };
    let solver = default_design(&mesh, 60.0);
    let pattern = strips(&mesh, &solver.field(), 60.0);
    assert!(pattern.verdict.is_acceptable(), "{}", pattern.verdict.message());
    let error = worst_quad_angle_error(&pattern, 60.0, normal);
    assert!(error <= 1.5, "a strip plane is {error}° off against the exact normal");
    assert!(pattern.metrics.max_planar <= 1e-5 && pattern.metrics.max_e_straight <= 1e-3, "{:?}", pattern.metrics);
}

/// Pitch of the helicoid below, per radian.
const HELICOID_PITCH: f64 = 1.2;

/// A helicoid `(r cos a, r sin a, 1.2 a)`, `r ∈ [1, 6]`, `a ∈ [0, 2.5]`, from a jittered grid.
pub(crate) fn helicoid(target_vertices: usize) -> TriMesh {
    let patch = CylinderPatch { radius: 2.0, span: 2.5, height: 5.0, target_vertices, irregularity: 0.5, seed: 13 };
    let grid = cylinder_patch(&patch).expect("valid patch");
    let positions = grid
        .positions
        .iter()
        .map(|p| {
            let (a, r) = (p.y.atan2(p.x), 1.0 + p.z);
            Vec3::new(r * a.cos(), r * a.sin(), HELICOID_PITCH * a)
        })
        .collect();
    TriMesh::from_vertices_and_faces(positions, grid.faces).expect("valid helicoid")
}

/// The helicoid's exact unit normal at `p` (`a = z / pitch`, `r` the distance from the axis):
/// `∂_r × ∂_a = (c sin a, −c cos a, r)`.
pub(crate) fn helicoid_normal(p: &Vec3) -> Vec3 {
    let a = p.z / HELICOID_PITCH;
    let r = p.x.hypot(p.y);
    Vec3::new(HELICOID_PITCH * a.sin(), -HELICOID_PITCH * a.cos(), r).normalize()
}

#[test]
fn where_every_family_is_nearly_straight_the_search_falls_back_on_the_least_straight() {
    // Away from its axis a helicoid bends little (principal curvatures ±c/(c² + r²): radius 31 m
    // at r = 6 m on a 9 m model), so every 60° family is nearly straight over most of it and the
    // search rejects all of them as degenerate. It continues from the best of those instead of
    // giving up, says so (the winner keeps its rejection), and the strips are judged as always.
    let mesh = helicoid(2000);
    let outcome = search_start(&mesh, FieldParams::pseudo_geodesic(60.0), SearchOptions::default()).expect("the fallback start");
    assert!(outcome.candidates.iter().all(|c| c.rejected.is_some()), "some candidate was accepted: the fallback is not tested");
    let winner = &outcome.candidates[outcome.winner];
    let reason = winner.rejected.as_deref().unwrap_or_default();
    assert!(reason.starts_with("degenerate") && winner.straight_fraction > 0.5, "{winner:?}");
    let least_straight = outcome.candidates.iter().filter(|c| c.rejected.as_deref().is_some_and(|r| r.contains("nearly straight"))).map(|c| c.straight_fraction).fold(f64::INFINITY, f64::min);
    let mut solver = outcome.solver;
    let report = solver.step(400).expect("solver runs");
    assert!(report.converged, "not converged after {} iterations", report.iterations);
    let pattern = strips(&mesh, &solver.field(), 60.0);
    let mut errors = quad_angle_errors(&pattern, 60.0, helicoid_normal);
    errors.sort_by(f64::total_cmp);
    let within = errors.iter().filter(|&&e| e <= 2.0).count() as f64 / errors.len() as f64;
    let worst = errors.last().copied().unwrap_or(0.0);
    eprintln!(
        "winner {} ({:.0} % nearly straight, least {:.0} %); {} quads, {:.1} % within 2° of θ against the exact normal, median {:.2}°, worst {worst:.2}°; verdict: {}",
        winner.kind.describe(),
        100.0 * winner.straight_fraction,
        100.0 * least_straight,
        errors.len(),
        100.0 * within,
        errors[errors.len() / 2],
        pattern.verdict.message()
    );
    // The fallback family is a family of θ where it bends: most strip quads keep θ against the
    // exact normal (measured: 95 % of 216 within 2°, median 0.04°; the worst, 2.9°, and a
    // flipped quad lie on one strip's nearly straight stretch near r = 6).
    assert!(errors.len() > 150 && within >= 0.9 && errors[errors.len() / 2] <= 0.5, "{within} within 2°, median {}", errors[errors.len() / 2]);
    // Where it does not, the verdict says so: it accepts the strips only if every quad keeps θ.
    assert!(!pattern.verdict.is_acceptable() || (worst <= 2.5 && pattern.metrics.flipped_quads == 0), "accepted with a quad {worst}° off");
}

/// A 55 × 55 grid over `[u0, u1] × [v0, v1]` mapped by `point`, its inner points jittered by up
/// to 22 % of a cell in each parameter, cells split along the shorter diagonal: 3,025 vertices.
/// (The meshes of `cargo bench --bench unseen_surfaces`, with the same seeds.)
fn jittered_grid(point: impl Fn(f64, f64) -> Vec3, [u0, u1, v0, v1]: [f64; 4], seed: u64) -> TriMesh {
    const GRID: usize = 55;
    let (du, dv) = ((u1 - u0) / (GRID - 1) as f64, (v1 - v0) / (GRID - 1) as f64);
    let mut rng = SplitMix64::new(seed);
    let inner = |k: usize| k > 0 && k < GRID - 1;
    let mut positions = Vec::with_capacity(GRID * GRID);
    for j in 0..GRID {
        for i in 0..GRID {
            let u = u0 + i as f64 * du + if inner(i) { rng.symmetric(0.22 * du) } else { 0.0 };
            let v = v0 + j as f64 * dv + if inner(j) { rng.symmetric(0.22 * dv) } else { 0.0 };
            positions.push(point(u, v));
        }
    }
    let mut faces = Vec::new();
    for j in 0..GRID - 1 {
        for i in 0..GRID - 1 {
            let (a, b) = ((j * GRID + i) as u32, (j * GRID + i + 1) as u32);
            let (d, c) = (a + GRID as u32, b + GRID as u32);
            let length = |p: u32, q: u32| (positions[p as usize] - positions[q as usize]).norm();
            faces.extend(if length(a, c) <= length(b, d) { [[a, b, c], [a, c, d]] } else { [[a, b, d], [b, c, d]] });
        }
    }
    TriMesh::from_vertices_and_faces(positions, faces).expect("a valid grid mesh")
}

/// Radius of the centre circle of [`torus_patch`]'s tube.
const TORUS_MAJOR_RADIUS: f64 = 6.0;

/// A patch of the outer side of a torus (radii 6 and 2, 92° × 138°): doubly curved, and none of
/// the library's generators.
fn torus_patch() -> TriMesh {
    let (major, minor) = (TORUS_MAJOR_RADIUS, 2.0);
    let point = |u: f64, v: f64| Vec3::new((major + minor * v.cos()) * u.cos(), (major + minor * v.cos()) * u.sin(), minor * v.sin());
    jittered_grid(point, [-0.8, 0.8, -1.2, 1.2], 4)
}

/// The monkey saddle `z = (x³ − 3xy²)/25` over 8 m × 8 m.
fn monkey_saddle() -> TriMesh {
    jittered_grid(|u, v| Vec3::new(u, v, (u * u * u - 3.0 * u * v * v) / 25.0), [-4.0, 4.0, -4.0, 4.0], 6)
}

/// A probe whose level curves have stopped improving far above the best score so far is cut
/// short (`SearchOptions::stall_factor`). On the monkey saddle at θ = 45° no height is good
/// enough, and most of the guide candidates that follow stall. The rule changes nothing but the
/// stalled candidates: with it off, every other candidate is the same to the bit, the same one
/// wins with the same field, and each candidate it cut scores above the winner after its full
/// probe.
#[test]
fn stalled_probes_are_cut_short_without_changing_the_winner() {
    let mesh = monkey_saddle();
    let params = FieldParams::pseudo_geodesic(45.0);
    let cut = search_start(&mesh, params.clone(), SearchOptions::default()).expect("a start");
    let full = search_start(&mesh, params, SearchOptions { stall_factor: f64::INFINITY, ..SearchOptions::default() }).expect("a start");
    let stalled = |c: &Candidate| c.rejected.as_deref().is_some_and(|r| r.starts_with("stalled"));
    assert!(cut.candidates.iter().filter(|c| stalled(c)).count() >= 3, "{:?}", cut.candidates);
    assert!(!full.candidates.iter().any(stalled));
    assert_eq!(cut.candidates.len(), full.candidates.len());
    assert_eq!(cut.winner, full.winner);
    let best = full.candidates[full.winner].score.expect("an accepted winner");
    for (c, f) in cut.candidates.iter().zip(&full.candidates) {
        if stalled(c) {
            assert!(f.score.is_none_or(|s| s > best), "{} stalled, but scores {:?} after its full probe (best {best})", c.kind.describe(), f.score);
        } else {
            assert_eq!(c, f);
        }
    }
    assert_eq!(cut.solver.field(), full.solver.field());
}

#[test]
fn the_solve_ends_once_its_level_curves_stop_improving() {
    // On this torus patch at θ = 45° the energy's own tests let the solve run 135 iterations,
    // each lowering the regularisers and the auxiliaries' constraints by 1 to 2 % while the level
    // curves, judged from outside, no longer improved (BENCHMARKS.md). The solver now measures
    // its level curves every 5 iterations (12 of them) and stops when they stop improving. Judged
    // here on 20 level curves, the curves it ends with are as good as any it passed through, and
    // the strips on them keep θ against the torus's exact normal (away from the tube's centre
    // circle), not only the mesh's fitted one.
    let mesh = torus_patch();
    let theta = 45.0;
    let family = Family::PseudoGeodesic { theta_degrees: theta };
    let (low, high) = mesh.bounding_box();
    let measure = |field: &[f64]| -> FamilyAngles {
        family_angles(&level_curves(&mesh, field, 20), family, 3.0 * mesh.mean_edge_length(), (high - low).norm()).expect("measured")
    };
    let mut solver = search_start(&mesh, FieldParams::pseudo_geodesic(theta), SearchOptions::default()).expect("a start").solver;
    let mut best_rms = f64::INFINITY;
    let (report, last) = loop {
        let report = solver.step(5).expect("solver runs");
        let angles = measure(&solver.field());
        best_rms = best_rms.min(angles.rms_error_degrees);
        if report.converged || report.iterations >= 400 {
            break (report, angles);
        }
    };
    assert!(report.converged && report.iterations <= 60, "converged: {}, after {} iterations", report.converged, report.iterations);
    assert!(report.energies.angle <= 1e-5, "E_angle {:e}", report.energies.angle);
    assert!(last.rms_error_degrees <= 1.25 * best_rms, "the curves end {:.2}° RMS off θ, they were {best_rms:.2}°", last.rms_error_degrees);
    assert!(last.rms_error_degrees <= 2.0 && last.max_error_degrees <= 8.0 && last.straight_fraction() < 0.05, "{last:?}");
    let pattern = strips(&mesh, &solver.field(), theta);
    assert!(pattern.verdict.is_acceptable(), "{}", pattern.verdict.message());
    assert_eq!(pattern.metrics.flipped_quads, 0);
    let exact_normal = |p: &Vec3| {
        let centre = Vec3::new(p.x, p.y, 0.0).normalize() * TORUS_MAJOR_RADIUS;
        (p - centre).normalize()
    };
    let error = worst_quad_angle_error(&pattern, theta, exact_normal);
    assert!(error <= 1.5, "a strip plane is {error}° off against the exact normal");
}
