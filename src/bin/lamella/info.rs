//! `lamella info`: the validation report of an OBJ mesh.
use crate::args::InfoArgs;
use crate::console::out_line;
use crate::error::{CliError, CliResult};
use crate::mesh_input::read_text;
use lamella::input::thousands;
use lamella::mesh::{MeshError, TriMesh};
use std::fmt::Write as _;

/// Most problems `info` lists one per line; the rest are counted.
const MAX_PROBLEM_LINES: usize = 100;

pub fn run(args: &InfoArgs) -> CliResult<()> {
    let path = &args.mesh;
    let text = read_text(path)?;
    let problems = TriMesh::diagnose_obj(&text).map_err(|e| CliError::bad_input(format!("{}: {e}", path.display())))?;
    let mut report = format!("mesh {}\n", path.display());
    if problems.is_empty() {
        let mesh = TriMesh::parse_obj(&text).map_err(|e| CliError::internal(format!("{}: diagnosed valid but rejected: {e}", path.display())))?;
        write_valid(&mut report, &mesh);
        return out_line(report.trim_end());
    }
    let not_disk = problems.iter().any(|p| matches!(p, MeshError::NotDisk { .. }) || matches!(p, MeshError::ObjLine { error, .. } if matches!(**error, MeshError::NotDisk { .. })));
    let _ = writeln!(report, "  valid:           no, {} problem(s)", problems.len());
    let _ = writeln!(report, "  disk:            {}", if not_disk { "no" } else { "unknown (invalid mesh)" });
    for problem in problems.iter().take(MAX_PROBLEM_LINES) {
        let _ = writeln!(report, "  problem: {problem}");
    }
    if problems.len() > MAX_PROBLEM_LINES {
        let _ = writeln!(report, "  problems:        and {} more", thousands(problems.len() - MAX_PROBLEM_LINES));
    }
    out_line(report.trim_end())?;
    Err(CliError::bad_input(format!("{}: invalid mesh ({} problem(s), listed above)", path.display(), problems.len())))
}

fn write_valid(report: &mut String, mesh: &TriMesh) {
    let loops = mesh.boundary_loops();
    let (low, high) = mesh.bounding_box();
    let size = high - low;
    let lengths: Vec<String> = loops.iter().map(|l| l.len().to_string()).collect();
    let _ = writeln!(report, "  valid:           yes");
    let _ = writeln!(report, "  vertices:        {}", mesh.vertex_count());
    let _ = writeln!(report, "  faces:           {}", mesh.face_count());
    let _ = writeln!(report, "  edges:           {}", mesh.edges().len());
    let _ = writeln!(report, "  boundary loops:  {} (vertices per loop: {})", loops.len(), lengths.join(", "));
    let _ = writeln!(report, "  disk:            yes, with {} hole(s)", loops.len().saturating_sub(1));
    let _ = writeln!(
        report,
        "  bounding box:    ({:.4}, {:.4}, {:.4}) to ({:.4}, {:.4}, {:.4}), size {:.4} × {:.4} × {:.4}",
        low.x, low.y, low.z, high.x, high.y, high.z, size.x, size.y, size.z
    );
    let _ = writeln!(report, "  mean edge:       {:.6}", mesh.mean_edge_length());
    let _ = writeln!(report, "  problems:        none");
}
