//! The base-mesh optimisation of a 3-web (paper Sec. 3.5 and 4.2.1): the AAG web extracted from
//! the level sets of z = xy/5, whose diagonals are only nearly geodesic, made an AAG web to the
//! degree, judged against the exact surface: the rows' and columns' segments tangent to it and
//! its normal orthogonal to their discrete osculating planes, the diagonals' discrete binormals
//! orthogonal to its normal, the vertices on it.

use crate::base_mesh_optimisation::polyline_angles;
use crate::field_support::line_fit;
use crate::net_two_families::hypar;
use lamella::base_mesh::{BaseMeshError, BaseMeshParams, BaseMeshSolver, BaseMeshWeights, NetMesh};
use lamella::field::Family;
use lamella::initialisation::SearchOptions;
use lamella::mesh::Vec3;
use lamella::net::{extract_web, net_start, web_levels, NetParams, NetSolver};

/// The exact unit normal of z = xy/5.
fn normal(p: &Vec3) -> Vec3 {
    Vec3::new(-p.y / 5.0, -p.x / 5.0, 1.0).normalize()
}

/// The largest angle (degrees) of a segment of family `k`'s polylines against the exact tangent
/// plane at its midpoint.
fn worst_segment_off_tangent(net: &NetMesh, k: usize) -> f64 {
    let p = net.positions();
    net.polylines(k)
        .iter()
        .flat_map(|line| line.windows(2).map(|w| (p[w[0] as usize], p[w[1] as usize])))
        .map(|(a, b)| (b - a).normalize().dot(&normal(&((a + b) * 0.5))).abs().asin().to_degrees())
        .fold(0.0, f64::max)
}

#[test]
fn the_level_set_aag_web_of_a_hyperbolic_paraboloid_is_optimised_to_an_aag_web() {
    let mesh = hypar(1500);
    let params = NetParams::web(Family::Asymptotic, Family::Asymptotic, Family::Geodesic);
    let fields = net_start(&mesh, &params, &SearchOptions::default()).expect("a start");
    let mut web_solver = NetSolver::new(&mesh, &fields, params).expect("a web solver");
    while !web_solver.step(10).expect("a step").converged && web_solver.iterations() < 300 {}
    let f = web_solver.fields();
    let levels = web_levels(&mesh, &f[0], &f[1], &f[2], [8, 8], false).expect("levels");
    let web = NetMesh::from_web(&extract_web(&mesh, &f[0], &f[1], levels)).expect("a web mesh");
    assert_eq!(web.family_count(), 3);
    let geodesic_before = polyline_angles(&web, 2, normal).iter().map(|a| (a - 90.0).abs()).fold(0.0, f64::max);

    let mut solver = BaseMeshSolver::new(&web, &mesh, BaseMeshParams::web(Family::Asymptotic, Family::Asymptotic, Family::Geodesic)).expect("a solver");
    while !solver.step(10).expect("a step").converged && solver.iterations() < 400 {}
    let report = solver.report().clone();
    let optimised = solver.net();
    // The web slides on the surface to make its diagonals geodesic, and covers less of it: its
    // extent in x shrinks by 21 % (a known defect: only the weak pull to the start holds the web's
    // extent; at fairness 1e-4 it shrank 9 % here but 60 % on the C harness's coarser web).
    let extent = |n: &NetMesh| {
        let xs = n.positions().iter().map(|p| p.x);
        xs.clone().fold(f64::MIN, f64::max) - xs.fold(f64::MAX, f64::min)
    };
    let shrink = 1.0 - extent(&optimised) / extent(&web);
    assert!(shrink <= 0.25, "the web's extent shrank by {:.1} %", 100.0 * shrink);
    let geodesic_after = polyline_angles(&optimised, 2, normal).iter().map(|a| (a - 90.0).abs()).fold(0.0, f64::max);
    // The diagonals geodesic to the degree (before: 1.7°, a level-set web's accuracy; after 0.85°).
    assert!(report.converged, "{report:?}");
    assert!(geodesic_before > 1.0, "the level-set web is already geodesic to {geodesic_before:.2}°: nothing to show");
    assert!(geodesic_after <= 1.0, "a diagonal's binormal is {geodesic_after:.2}° off 90° to the exact normal");
    // The rows and columns still the rulings: straight in plan, every segment tangent.
    for k in 0..2 {
        for line in optimised.polylines(k) {
            let plan: Vec<(f64, f64)> = line.iter().map(|&v| (optimised.positions()[v as usize].x, optimised.positions()[v as usize].y)).collect();
            let (deviation, length) = line_fit(&plan);
            // As the level-set web gave them (two short corner polylines about 0.57 %, the rest 0.1 %).
            assert!(deviation <= 0.0075 * length, "family {k}: a polyline bends by {:.3} % of its length", 100.0 * deviation / length);
        }
        let off_tangent = worst_segment_off_tangent(&optimised, k);
        assert!(off_tangent <= 1.0, "family {k}: a segment leaves the tangent plane by {off_tangent:.2}°");
    }
    // On the surface: within 0.1 % of the 14 m diagonal, as the report says.
    let off_surface = optimised.positions().iter().map(|p| (p.z - p.x * p.y / 5.0).abs() / (1.0 + (p.x * p.x + p.y * p.y) / 25.0).sqrt()).fold(0.0, f64::max);
    assert!(off_surface <= 0.014, "a vertex is {off_surface:.4} m off z = xy/5");
    assert!((report.deviation.max - off_surface).abs() <= 0.01, "reported {} m against {off_surface} m", report.deviation.max);
    assert_eq!(report.families[2].straight, 0);
    // The report measures the rulings by their segments' angle to the reference's tangent planes
    // at their ends: 1.2° against the mesh's interpolated normals (0.4° above against the exact
    // ones), the diagonals by their binormals.
    let reported: Vec<f64> = report.families.iter().map(|f| f.max_error_degrees).collect();
    assert!(reported[0] <= 1.5 && reported[1] <= 1.5 && reported[2] <= 1.0, "{reported:?}");
    assert!(report.families[2].max_error_degrees <= 1.0, "{:?}", report.families[2]);
    // The web's triangles survive: every interior vertex of the web keeps its six.
    assert_eq!(optimised.triangles().len(), web.triangles().len());
    assert!(web.triangles().len() >= 50);
}

#[test]
fn a_web_needs_three_families_and_no_torsion_free_nodes() {
    let mesh = hypar(300);
    let p: Vec<Vec3> = (0..9).map(|i| Vec3::new((i % 3) as f64, (i / 3) as f64, 0.0)).collect();
    let (rows, columns) = ((0..3).map(|i| vec![3 * i, 3 * i + 1, 3 * i + 2]).collect::<Vec<_>>(), (0..3).map(|j| vec![j, j + 3, j + 6]).collect::<Vec<_>>());
    let web = NetMesh::web(p, rows, columns, vec![vec![2, 4, 6], vec![1, 3], vec![5, 7]]).expect("a web");
    let error = BaseMeshSolver::new(&web, &mesh, BaseMeshParams::new(Family::Asymptotic, Family::Asymptotic)).err().expect("refused");
    assert!(error.to_string().contains("2 families for a net of 3"), "{error}");
    let mut params = BaseMeshParams::web(Family::Asymptotic, Family::Asymptotic, Family::Geodesic);
    params.torsion_free = true;
    let error = BaseMeshSolver::new(&web, &mesh, params).err().expect("refused");
    assert!(error.to_string().contains("torsion_free"), "{error}");
}

/// The web of the heights `x`, `y` and `−x − y` on `mesh` (`levels` of the first two): the AAG
/// web of `z = xy/5` as its level sets give it, before any optimisation.
fn height_web(mesh: &lamella::mesh::TriMesh, levels: usize) -> NetMesh {
    let x: Vec<f64> = mesh.positions().iter().map(|p| p.x).collect();
    let y: Vec<f64> = mesh.positions().iter().map(|p| p.y).collect();
    let third: Vec<f64> = x.iter().zip(&y).map(|(a, b)| -a - b).collect();
    let levels = web_levels(mesh, &x, &y, &third, [levels, levels], false).expect("levels");
    NetMesh::from_web(&extract_web(mesh, &x, &y, levels)).expect("a web mesh")
}

/// The web's extent in x after at most 400 iterations with `weights`, as a fraction of its start,
/// and the worst family error the report gives.
fn optimised_extent(web: &NetMesh, mesh: &lamella::mesh::TriMesh, weights: Option<BaseMeshWeights>) -> (f64, f64) {
    let mut solver = BaseMeshSolver::new(web, mesh, BaseMeshParams::web(Family::Asymptotic, Family::Asymptotic, Family::Geodesic)).expect("a solver");
    if let Some(weights) = weights {
        solver.set_weights(weights).expect("set before the first step");
    }
    while !solver.step(20).expect("a step").converged && solver.iterations() < 400 {}
    let extent = |n: &NetMesh| {
        let xs = n.positions().iter().map(|p| p.x);
        xs.clone().fold(f64::MIN, f64::max) - xs.fold(f64::MAX, f64::min)
    };
    let worst = solver.report().families.iter().map(|f| f.max_error_degrees).fold(0.0, f64::max);
    (extent(&solver.net()) / extent(web), worst)
}

#[test]
fn the_pull_weight_holds_a_webs_extent_where_the_defaults_let_it_shrink() {
    let mesh = hypar(1500);
    let web = height_web(&mesh, 8);
    assert!(web.vertex_count() >= 40, "a web of {} vertices", web.vertex_count());
    let (default_extent, _) = optimised_extent(&web, &mesh, None);
    // The weights of the paper's Table 3 are per figure: a pull 100 times the default holds the
    // web where it was extracted, and the families come out no worse than 3°.
    let held = BaseMeshWeights { pull: 1e-2, ..BaseMeshWeights::default() };
    let (held_extent, worst) = optimised_extent(&web, &mesh, Some(held));
    assert!(default_extent < 0.9, "with the default weights the web kept {:.1} % of its extent", 100.0 * default_extent);
    assert!((held_extent - 1.0).abs() < 0.06, "with the pull at 1e-2 the web kept {:.1} % of its extent", 100.0 * held_extent);
    assert!(worst < 3.0, "a family ends {worst:.2}° off");
}

#[test]
fn weights_are_set_before_the_first_iteration_as_if_given_at_creation() {
    let mesh = hypar(600);
    let web = height_web(&mesh, 5);
    let params = BaseMeshParams::web(Family::Asymptotic, Family::Asymptotic, Family::Geodesic);
    let weights = BaseMeshWeights { fair: 1e-4, close: 0.5, pull: 1e-3, ..BaseMeshWeights::default() };
    let mut given = BaseMeshSolver::new(&web, &mesh, BaseMeshParams { weights, ..params.clone() }).expect("a solver");
    let mut set = BaseMeshSolver::new(&web, &mesh, params).expect("a solver");
    set.set_weights(weights).expect("before the first step");
    assert_eq!(set.params().weights, weights);
    assert_eq!(set.initial_report(), given.initial_report());
    let bits = |s: &BaseMeshSolver| s.positions().iter().flat_map(|p| p.iter().map(|x| x.to_bits()).collect::<Vec<_>>()).collect::<Vec<u64>>();
    assert_eq!(set.step(10).expect("steps"), given.step(10).expect("steps"));
    assert_eq!(bits(&set), bits(&given));
    // Once the net has moved, the weights are refused by name, and so is a weight out of range.
    let error = set.set_weights(BaseMeshWeights::default()).expect_err("after a step");
    assert!(matches!(error, BaseMeshError::InvalidParameter { name: "weights", .. }), "{error}");
    let mut fresh = BaseMeshSolver::new(&web, &mesh, BaseMeshParams::web(Family::Asymptotic, Family::Asymptotic, Family::Geodesic)).expect("a solver");
    for (bad, name) in [(BaseMeshWeights { pull: -1.0, ..weights }, "weights.pull"), (BaseMeshWeights { curve: 0.0, ..weights }, "weights.curve"), (BaseMeshWeights { fair: f64::NAN, ..weights }, "weights.fair")] {
        match fresh.set_weights(bad) {
            Err(BaseMeshError::InvalidParameter { name: got, .. }) => assert_eq!(got, name),
            other => panic!("{bad:?}: {other:?}"),
        }
    }
    assert_eq!(fresh.params().weights, BaseMeshWeights::default(), "a refused weight leaves the session as it was");
}
