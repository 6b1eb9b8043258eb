//! net.obj: a net of rows and columns (paper Sec. 3.5) as OBJ: its vertices, its quads as faces,
//! then the rows after `o rows` and the columns after `o columns`, each an `l` polyline (a 3-web:
//! triangles or a Kagome pattern's triangles and hexagons, and its third family after
//! `o diagonals`). `net` writes it from the crossings of its level sets; `optimise` reads it and
//! writes the result.
use crate::error::{CliError, CliResult};
use crate::mesh_input::read_text;
use lamella::base_mesh::NetMesh;
use lamella::mesh::Vec3;
use std::fmt::Write as _;
use std::path::Path;

/// The text of a net.obj, under the comment `title`: `faces` of any size, then each family's
/// polylines under its name (`rows`, `columns`, `diagonals`).
pub fn net_obj<F: AsRef<[u32]>>(title: &str, positions: &[Vec3], faces: &[F], families: &[(&str, &[Vec<u32>])]) -> String {
    let mut text = format!("# {title}\n");
    for p in positions {
        let _ = writeln!(text, "v {} {} {}", p.x, p.y, p.z);
    }
    for face in faces {
        let indices: Vec<String> = face.as_ref().iter().map(|v| (v + 1).to_string()).collect();
        let _ = writeln!(text, "f {}", indices.join(" "));
    }
    for &(name, lines) in families {
        let _ = writeln!(text, "o {name}");
        for line in lines {
            let indices: Vec<String> = line.iter().map(|v| (v + 1).to_string()).collect();
            let _ = writeln!(text, "l {}", indices.join(" "));
        }
    }
    text
}

/// Reads a net.obj. Errors name the file and line: a malformed vertex or index, an `l` before
/// `o rows` / `o columns`, no polyline of either family, or a net [`NetMesh::new`] refuses.
pub fn read_net_obj(path: &Path) -> CliResult<NetMesh> {
    let text = read_text(path)?;
    let bad = |line: usize, what: &str| CliError::bad_input(format!("{}: line {line}: {what}", path.display()));
    let mut positions: Vec<Vec3> = Vec::new();
    let mut families: [Vec<Vec<u32>>; 3] = Default::default();
    let mut family: Option<usize> = None;
    for (i, raw) in text.lines().enumerate() {
        let line = i + 1;
        let mut tokens = raw.split('#').next().unwrap_or("").split_whitespace();
        match tokens.next() {
            Some("v") => {
                let coordinates: Option<Vec<f64>> = tokens.take(3).map(|t| t.parse::<f64>().ok().filter(|x| x.is_finite())).collect();
                match coordinates.as_deref() {
                    Some(&[x, y, z]) => positions.push(Vec3::new(x, y, z)),
                    _ => return Err(bad(line, "a vertex needs 3 finite coordinates")),
                }
            }
            Some("o") => {
                family = match tokens.next() {
                    Some("rows") => Some(0),
                    Some("columns") => Some(1),
                    Some("diagonals") => Some(2),
                    _ => None,
                };
            }
            Some("l") => {
                let k = family.ok_or_else(|| bad(line, "a polyline outside `o rows`, `o columns` and `o diagonals`"))?;
                let polyline = tokens
                    .map(|t| t.parse::<usize>().ok().and_then(|k| k.checked_sub(1)).filter(|&k| k < positions.len()).map(|k| k as u32))
                    .collect::<Option<Vec<u32>>>()
                    .ok_or_else(|| bad(line, "a polyline index is not a vertex defined above"))?;
                families[k].push(polyline);
            }
            _ => {}
        }
    }
    if families[..2].iter().any(Vec::is_empty) {
        return Err(CliError::bad_input(format!("{}: needs `l` polylines after both `o rows` and `o columns` (the net.obj of `lamella net`)", path.display())));
    }
    let [rows, columns, diagonals] = families;
    let net = if diagonals.is_empty() { NetMesh::new(positions, rows, columns) } else { NetMesh::web(positions, rows, columns, diagonals) };
    net.map_err(|e| CliError::bad_input(format!("{}: {e}", path.display())))
}
