//! `lamella`: designs a θ = 60° pseudo-geodesic strip family on the built-in hall roof and
//! writes the result to `./lamella-out/` (the first command of the README).

use lamella::field::{FieldParams, FieldSolver, StepReport};
use lamella::mesh::TriMesh;
use lamella::surfaces::hall_roof;
use std::fmt::Write as _;
use std::path::Path;
use std::process::ExitCode;
use std::time::Instant;

/// Target angle between strip binormals and surface normals, in degrees.
const THETA: f64 = 60.0;
/// Vertices of the built-in hall roof.
const ROOF_VERTICES: usize = 3000;
/// Iterations between progress lines.
const ITERATIONS_PER_STEP: usize = 5;
/// Upper bound on iterations for the demo.
const MAX_ITERATIONS: usize = 400;
const OUTPUT: &str = "lamella-out";

fn main() -> ExitCode {
    match run() {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("lamella: {message}");
            ExitCode::FAILURE
        }
    }
}

fn run() -> Result<(), String> {
    let started = Instant::now();
    let mesh = hall_roof(ROOF_VERTICES).into_mesh().map_err(|e| format!("built-in surface: {e}"))?;
    // Start from the coordinate along the hall: its level sets are the arches across it.
    let initial: Vec<f64> = mesh.positions().iter().map(|p| p.x).collect();
    println!("hall roof: {} vertices, {} triangles; θ = {THETA}°", mesh.vertex_count(), mesh.face_count());
    let mut solver = FieldSolver::new(&mesh, &initial, FieldParams::pseudo_geodesic(THETA)).map_err(|e| e.to_string())?;
    let mut report = solver.report().clone();
    print_progress(&report);
    while !report.converged && report.iterations < MAX_ITERATIONS {
        report = solver.step(ITERATIONS_PER_STEP).map_err(|e| e.to_string())?;
        print_progress(&report);
    }
    write_outputs(Path::new(OUTPUT), &mesh, &solver).map_err(|e| format!("writing {OUTPUT}: {e}"))?;
    println!(
        "{} after {} iterations in {:.2} s: E_angle {:.2e}, angle error max {:.3}° (RMS {:.3}°), {} singular vertices",
        if report.converged { "converged" } else { "stopped" },
        report.iterations,
        started.elapsed().as_secs_f64(),
        report.energies.angle,
        report.angle_error_max_degrees,
        report.angle_error_rms_degrees,
        report.singular_vertices.len()
    );
    println!("wrote {OUTPUT}/surface.obj, {OUTPUT}/field.csv, {OUTPUT}/binormals.csv");
    Ok(())
}

fn print_progress(r: &StepReport) {
    println!(
        "  iteration {:4}  stage {}  E_angle {:9.3e}  E_fair {:9.3e}  E_grad {:9.3e}  angle error max {:7.3}°  singular {}",
        r.iterations,
        r.stage,
        r.energies.angle,
        r.energies.fair,
        r.energies.grad,
        r.angle_error_max_degrees,
        r.singular_vertices.len()
    );
}

fn write_outputs(dir: &Path, mesh: &TriMesh, solver: &FieldSolver) -> std::io::Result<()> {
    std::fs::create_dir_all(dir)?;
    mesh.write_obj(std::io::BufWriter::new(std::fs::File::create(dir.join("surface.obj"))?))?;
    let mut field = String::from("# field value per vertex\n");
    for value in solver.field() {
        let _ = writeln!(field, "{value}");
    }
    std::fs::write(dir.join("field.csv"), field)?;
    let mut binormals = String::from("# bx,by,bz per vertex (0,0,0 at boundary and singular vertices)\n");
    for b in solver.binormals() {
        let _ = writeln!(binormals, "{},{},{}", b.x, b.y, b.z);
    }
    std::fs::write(dir.join("binormals.csv"), binormals)
}
