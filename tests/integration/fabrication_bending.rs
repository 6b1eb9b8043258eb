//! The bending and twisting check: a geodesic strip along a circle of radius R on a cylinder
//! (θ = 90°, built by the library's own pipeline: cylinder mesh → level curve of the height →
//! rectifying strip) bends by the strain t/(2R) and does not twist; a helix strip's stresses
//! follow its curvature and torsion; the presets and every parameter are checked.

use crate::fabrication_support;

use fabrication_support::{helix_pattern, helix_strip, timber_params};
use lamella::curves::extract_level_curves;
use lamella::fabrication::{check_strip, plan_fabrication, FabricationError, FabricationStrip, Material, Stock};
use lamella::strips::{rectifying_strips, StripParams};
use lamella::surfaces::{cylinder_patch, CylinderPatch};

const RADIUS: f64 = 3.0;
const THICKNESS: f64 = 0.006;

#[test]
fn a_geodesic_strip_along_a_circle_of_a_cylinder_bends_by_t_over_2r() {
    let patch = CylinderPatch { radius: RADIUS, span: 2.0, height: 2.0, target_vertices: 1500, irregularity: 0.3, seed: 7 };
    let mesh = cylinder_patch(&patch).expect("valid patch").into_mesh().expect("valid mesh");
    let height: Vec<f64> = mesh.positions().iter().map(|p| p.z).collect();
    let curves = extract_level_curves(&mesh, &height, &[1.03]).expect("a level in range");
    assert_eq!(curves.len(), 1);
    // Resampled every three mean edges: the piecewise-linear level set is a polygon through
    // points on the mesh's chords, whose turning at the scale of one edge is not the circle's.
    let curve = curves[0].resampled(3.0 * mesh.mean_edge_length()).expect("valid spacing");
    let pattern = rectifying_strips(&mesh, &[curve], &StripParams::new(90.0, 0.2)).expect("valid parameters");
    assert_eq!(pattern.strips.len(), 1);
    let strip = FabricationStrip::from_rectifying("strip_0", &pattern.strips[0]);
    let timber = Material::preset("timber").expect("preset");
    let check = check_strip(&strip, &timber, THICKNESS);
    let expected = THICKNESS / (2.0 * RADIUS);
    let n = check.curvature.len();
    for i in 1..n - 1 {
        let strain = 0.5 * THICKNESS * check.curvature[i];
        assert!((strain / expected - 1.0).abs() < 0.01, "strain {strain} at point {i} of {n}, expected {expected}");
        assert!(check.twist_rate[i] < 0.01 / RADIUS, "twist {} rad/m at point {i}", check.twist_rate[i]);
    }
    assert!((check.max_strain / expected - 1.0).abs() < 0.01, "max strain {} vs {expected}", check.max_strain);
    let stress = timber.youngs_modulus * expected;
    assert!((check.max_bending_stress / stress - 1.0).abs() < 0.01);
    // 11 GPa × 1e-3 = 11 MPa of 24 MPa.
    assert!((check.max_utilisation - stress / timber.allowable_stress).abs() < 0.01 * stress / timber.allowable_stress);
    assert!(!check.is_overstressed());
    let radius = check.min_bending_radius().expect("a bent strip");
    assert!((radius / RADIUS - 1.0).abs() < 0.01, "min radius {radius}");
}

#[test]
fn thicker_or_stiffer_strips_are_flagged_at_their_worst_point() {
    let strips = helix_pattern();
    let mut params = timber_params();
    // 6 mm timber on radii of 5 to 12 m: within the allowable stress.
    let plan = plan_fabrication(&strips, &params).expect("valid plan");
    assert!(plan.overstressed_strips().is_empty(), "{:?}", plan.checks.iter().map(|c| c.max_utilisation).collect::<Vec<_>>());
    // 10 mm steel on the 5 m helix: E t κ / 2 = 210 GPa × 5 mm × 5/26 /m ≈ 202 MPa bending plus
    // the torsional shear G t τ = 81 GPa × 10 mm × 1/26 /m ≈ 31 MPa: √(σ² + 3τ²) ≈ 209 MPa < 355 MPa.
    params.material = Material::preset("steel").expect("preset");
    params.thickness = 0.01;
    let plan = plan_fabrication(&strips, &params).expect("valid plan");
    let helix = &plan.checks[3];
    let (sigma, shear): (f64, f64) = (210e9 * 0.005 * 5.0 / 26.0, 81e9 * 0.01 / 26.0);
    let expected = (sigma * sigma + 3.0 * shear * shear).sqrt() / 355e6;
    assert!((helix.max_utilisation / expected - 1.0).abs() < 1e-3, "{} vs {expected}", helix.max_utilisation);
    // 20 mm: twice the stress, over 100 %, flagged on the strip and its pieces.
    params.thickness = 0.02;
    let plan = plan_fabrication(&strips, &params).expect("valid plan");
    assert!(plan.overstressed_strips().contains(&3));
    let worst = &plan.checks[3];
    assert!(worst.is_overstressed() && worst.worst_point < worst.utilisation.len());
    for piece in plan.pieces.iter().filter(|p| p.strip == 3) {
        assert!(piece.is_overstressed());
        assert!(piece.shape.label.text.ends_with(" %)"), "label {}", piece.shape.label.text);
    }
}

#[test]
fn every_parameter_is_checked_and_named() {
    let strips = helix_pattern();
    let named = |params: lamella::fabrication::FabricationParams, name: &str| {
        let error = plan_fabrication(&strips, &params).expect_err("invalid");
        assert!(matches!(&error, FabricationError::InvalidParameter { name: n, .. } if *n == name), "{error}");
    };
    let base = timber_params();
    named(lamella::fabrication::FabricationParams { thickness: -0.006, ..base.clone() }, "thickness");
    named(lamella::fabrication::FabricationParams { thickness: f64::NAN, ..base.clone() }, "thickness");
    named(lamella::fabrication::FabricationParams { stock: Stock { overlap: 3.0, ..Stock::boards(4.8) }, ..base.clone() }, "stock_length");
    named(lamella::fabrication::FabricationParams { stock: Stock { width: Some(0.0), ..Stock::boards(4.8) }, ..base.clone() }, "stock_width");
    named(lamella::fabrication::FabricationParams { stock: Stock { overlap: -0.1, ..Stock::boards(4.8) }, ..base.clone() }, "overlap");
    named(lamella::fabrication::FabricationParams { theta_degrees: Some(200.0), ..base.clone() }, "theta");
    let mut material = base.clone();
    material.material.youngs_modulus = 0.0;
    named(material, "youngs_modulus");
    // A strip too wide for the sheets, and a broken strip, are named.
    let narrow = lamella::fabrication::FabricationParams { stock: Stock { width: Some(0.1), ..Stock::boards(4.8) }, ..base.clone() };
    let error = plan_fabrication(&strips, &narrow).expect_err("too wide");
    assert!(matches!(&error, FabricationError::PieceDoesNotFit { piece, .. } if piece == "strip_0-1"), "{error}");
    let mut broken = helix_strip("strip_9", 5.0, 1.0, 1.0, 10, 0.1);
    broken.centre[4] = broken.centre[3];
    let error = plan_fabrication(&[broken], &base).expect_err("zero-length segment");
    assert!(error.to_string().contains("strip_9") && error.to_string().contains("segment 3"), "{error}");
    assert_eq!(plan_fabrication(&[], &base).expect_err("no strips"), FabricationError::NoStrips);
}
