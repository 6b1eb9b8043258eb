//! Wavefront OBJ input and output of [`TriMesh`].
//!
//! Reads `v x y z` (extra values ignored) and `f` statements with `i`, `i/t`, `i//n`, `i/t/n`
//! and negative (relative) indices; polygons are fan-triangulated keeping the face-vertex order.
//! Texture/normal data, grouping, material, smoothing, line and point statements and comments
//! are ignored. Errors name the 1-based line of the offending statement and quote the offending
//! token clipped to [`crate::input::MAX_QUOTED_CHARS`] characters.

use std::io::Write;
use std::path::Path;

use super::error::{Culprit, MeshError};
use super::trimesh::TriMesh;
use super::Vec3;
use crate::input::{clip, read_limited};

/// Statements that carry nothing the mesh needs.
const IGNORED: &[&str] = &["vt", "vn", "vp", "o", "g", "s", "mg", "usemtl", "mtllib", "l", "p"];

/// The raw content of an OBJ file, with the source line of every vertex and triangle.
struct ObjContent {
    positions: Vec<Vec3>,
    vertex_lines: Vec<usize>,
    faces: Vec<[u32; 3]>,
    face_lines: Vec<usize>,
}

impl TriMesh {
    /// Parses OBJ text; errors name the OBJ line number (mesh errors about a vertex or face are
    /// wrapped in [`MeshError::ObjLine`], malformed lines give [`MeshError::ObjParse`]).
    pub fn parse_obj(text: &str) -> Result<TriMesh, MeshError> {
        let content = parse_content(text)?;
        let ObjContent { positions, vertex_lines, faces, face_lines } = content;
        TriMesh::from_vertices_and_faces(positions, faces).map_err(|error| with_line(error, &vertex_lines, &face_lines))
    }

    /// Every problem of the mesh in OBJ text (see [`crate::mesh::diagnose`]), each naming its OBJ
    /// line where it concerns one vertex or face; empty if [`TriMesh::parse_obj`] accepts it.
    /// A malformed line is returned as the error.
    pub fn diagnose_obj(text: &str) -> Result<Vec<MeshError>, MeshError> {
        let ObjContent { positions, vertex_lines, faces, face_lines } = parse_content(text)?;
        Ok(super::diagnose(&positions, &faces).into_iter().map(|e| with_line(e, &vertex_lines, &face_lines)).collect())
    }

    /// Reads and parses an OBJ file (invalid UTF-8 is replaced, which only matters in comments).
    /// Files larger than [`crate::input::MAX_INPUT_BYTES`] are refused with [`MeshError::Io`].
    pub fn read_obj(path: &Path) -> Result<TriMesh, MeshError> {
        let bytes = read_limited(path).map_err(|e| MeshError::Io {
            path: path.to_path_buf(),
            kind: e.kind(),
            message: e.to_string(),
        })?;
        TriMesh::parse_obj(&String::from_utf8_lossy(&bytes))
    }

    /// Writes `v` and `f` lines (1-based indices); coordinates use the shortest representation
    /// that parses back to the identical f64.
    pub fn write_obj<W: Write>(&self, out: W) -> std::io::Result<()> {
        let mut out = std::io::BufWriter::new(out);
        writeln!(out, "# lamella mesh: {} vertices, {} faces", self.vertex_count(), self.face_count())?;
        for p in self.positions() {
            writeln!(out, "v {} {} {}", p.x, p.y, p.z)?;
        }
        for f in self.faces() {
            writeln!(out, "f {} {} {}", u64::from(f[0]) + 1, u64::from(f[1]) + 1, u64::from(f[2]) + 1)?;
        }
        out.flush()
    }
}

/// Wraps a mesh error about one vertex or face in [`MeshError::ObjLine`] with its source line.
fn with_line(error: MeshError, vertex_lines: &[usize], face_lines: &[usize]) -> MeshError {
    let line = match error.culprit() {
        Some(Culprit::Vertex(v)) => vertex_lines.get(v).copied(),
        Some(Culprit::Face(f)) => face_lines.get(f).copied(),
        None => None,
    };
    match line {
        Some(line) => MeshError::ObjLine { line, error: Box::new(error) },
        None => error,
    }
}

fn parse_content(text: &str) -> Result<ObjContent, MeshError> {
    let mut content =
        ObjContent { positions: Vec::new(), vertex_lines: Vec::new(), faces: Vec::new(), face_lines: Vec::new() };
    for (i, raw) in text.lines().enumerate() {
        let line = i + 1;
        let statement = raw.split('#').next().unwrap_or("");
        let mut tokens = statement.split_whitespace();
        let parse_error = |message: String| MeshError::ObjParse { line, message };
        match tokens.next() {
            None => {}
            Some("v") => {
                let mut coordinate = || -> Result<f64, MeshError> {
                    let token = tokens.next().ok_or_else(|| parse_error("vertex needs 3 coordinates".into()))?;
                    token.parse().map_err(|_| parse_error(format!("invalid coordinate '{}'", clip(token))))
                };
                let p = Vec3::new(coordinate()?, coordinate()?, coordinate()?);
                content.positions.push(p);
                content.vertex_lines.push(line);
            }
            Some("f") => {
                let corners = tokens
                    .map(|token| resolve_index(token, content.positions.len()).map_err(parse_error))
                    .collect::<Result<Vec<u32>, MeshError>>()?;
                if corners.len() < 3 {
                    return Err(parse_error(format!("face needs at least 3 vertices, has {}", corners.len())));
                }
                for k in 1..corners.len() - 1 {
                    content.faces.push([corners[0], corners[k], corners[k + 1]]);
                    content.face_lines.push(line);
                }
            }
            Some(keyword) if IGNORED.contains(&keyword) => {}
            Some(keyword) => return Err(parse_error(format!("unknown statement '{}'", clip(keyword)))),
        }
    }
    Ok(content)
}

/// 0-based vertex index of a face token `i`, `i/t`, `i//n` or `i/t/n`; negative `i` counts back
/// from the last vertex read so far. Positive indices may refer to later vertices (checked by
/// mesh validation).
fn resolve_index(token: &str, vertices_so_far: usize) -> Result<u32, String> {
    let text = token.split('/').next().unwrap_or("");
    let index: i64 = text.parse().map_err(|_| format!("invalid vertex index '{}'", clip(token)))?;
    let resolved = if index > 0 {
        index - 1
    } else if index < 0 {
        vertices_so_far as i64 + index
    } else {
        return Err("vertex index 0 (OBJ indices start at 1)".into());
    };
    u32::try_from(resolved).map_err(|_| format!("vertex index {index} out of range"))
}
