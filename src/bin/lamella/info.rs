//! `lamella info`: the validation report of an OBJ mesh.
use crate::args::InfoArgs;
use crate::error::{CliError, CliResult};
use crate::mesh_input::read_text;
use lamella::mesh::{MeshError, TriMesh};

pub fn run(args: &InfoArgs) -> CliResult<()> {
    let path = &args.mesh;
    let text = read_text(path)?;
    let problems = TriMesh::diagnose_obj(&text).map_err(|e| CliError::bad_input(format!("{}: {e}", path.display())))?;
    println!("mesh {}", path.display());
    if problems.is_empty() {
        let mesh = TriMesh::parse_obj(&text).map_err(|e| CliError::internal(format!("{}: diagnosed valid but rejected: {e}", path.display())))?;
        print_valid(&mesh);
        return Ok(());
    }
    let not_disk = problems.iter().any(|p| matches!(p, MeshError::NotDisk { .. }) || matches!(p, MeshError::ObjLine { error, .. } if matches!(**error, MeshError::NotDisk { .. })));
    println!("  valid:           no, {} problem(s)", problems.len());
    println!("  disk:            {}", if not_disk { "no" } else { "unknown (invalid mesh)" });
    for problem in &problems {
        println!("  problem: {problem}");
    }
    Err(CliError::bad_input(format!("{}: invalid mesh ({} problem(s), listed above)", path.display(), problems.len())))
}

fn print_valid(mesh: &TriMesh) {
    let loops = mesh.boundary_loops();
    let (low, high) = mesh.bounding_box();
    let size = high - low;
    println!("  valid:           yes");
    println!("  vertices:        {}", mesh.vertex_count());
    println!("  faces:           {}", mesh.face_count());
    println!("  edges:           {}", mesh.edges().len());
    let lengths: Vec<String> = loops.iter().map(|l| l.len().to_string()).collect();
    println!("  boundary loops:  {} (vertices per loop: {})", loops.len(), lengths.join(", "));
    println!("  disk:            yes, with {} hole(s)", loops.len().saturating_sub(1));
    println!(
        "  bounding box:    ({:.4}, {:.4}, {:.4}) to ({:.4}, {:.4}, {:.4}), size {:.4} × {:.4} × {:.4}",
        low.x, low.y, low.z, high.x, high.y, high.z, size.x, size.y, size.z
    );
    println!("  mean edge:       {:.6}", mesh.mean_edge_length());
    println!("  problems:        none");
}
