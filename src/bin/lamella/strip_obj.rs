//! OBJ files of a design: curves.obj (level polylines as `l` elements), strips.obj (quad strips,
//! one named group per strip) and rulings.obj (one segment per ruling); and reading strips.obj
//! back for `unroll`, `metrics` and `view`, and curves.obj for `view`.
use crate::error::{CliError, CliResult};
use crate::mesh_input::read_text;
use lamella::curves::LevelCurve;
use lamella::mesh::Vec3;
use lamella::strips::StripPattern;
use std::fmt::Write as _;
use std::path::Path;

/// A strip as stored in strips.obj: its boundaries `left_i = c_i + s_i d_i`, `right_i = c_i − s_i d_i`.
#[derive(Clone, Debug, PartialEq)]
pub struct StripShape {
    pub name: String,
    pub left: Vec<Vec3>,
    pub right: Vec<Vec3>,
}

impl StripShape {
    /// The medial polyline `c_i`, midway between the boundaries.
    pub fn centre(&self) -> Vec<Vec3> {
        self.left.iter().zip(&self.right).map(|(l, r)| (l + r) * 0.5).collect()
    }

    /// The half-rulings `s_i d_i` from the centre to the left boundary.
    pub fn offsets(&self) -> Vec<Vec3> {
        self.left.iter().zip(&self.right).map(|(l, r)| (l - r) * 0.5).collect()
    }
}

/// The name of strip `id` in every output.
pub fn strip_name(id: usize) -> String {
    format!("strip_{id}")
}

fn vertex(text: &mut String, p: &Vec3) {
    let _ = writeln!(text, "v {} {} {}", p.x, p.y, p.z);
}

/// curves.obj: one object per level curve, its vertices joined by one `l` element (closed
/// curves repeat their first vertex).
pub fn curves_obj(curves: &[LevelCurve]) -> String {
    let mut text = String::from("# lamella level curves (resampled), one `l` polyline per curve\n");
    let mut base = 1;
    for (k, curve) in curves.iter().enumerate() {
        let _ = writeln!(text, "o curve_{k}\n# level {}", curve.level);
        curve.points.iter().for_each(|p| vertex(&mut text, p));
        let mut indices: Vec<String> = (0..curve.points.len()).map(|i| (base + i).to_string()).collect();
        if curve.closed && !curve.points.is_empty() {
            indices.push(base.to_string());
        }
        let _ = writeln!(text, "l {}", indices.join(" "));
        base += curve.points.len();
    }
    text
}

/// strips.obj: per strip a group `strip_<id>` with vertices `left_i, right_i` alternating and the
/// planar quads `(left_j, left_{j+1}, right_{j+1}, right_j)`.
pub fn strips_obj(pattern: &StripPattern) -> String {
    let mut text = String::from("# lamella rectifying strips: per group, vertices left_i, right_i alternate\n");
    let mut base = 1;
    for (id, strip) in pattern.strips.iter().enumerate() {
        let _ = writeln!(text, "g {}\n# curve {} level {}", strip_name(id), strip.curve, strip.level);
        for (l, r) in strip.left.iter().zip(&strip.right) {
            vertex(&mut text, l);
            vertex(&mut text, r);
        }
        let n = strip.left.len().min(strip.right.len());
        for j in 0..n.saturating_sub(1) {
            let (l0, r0, l1, r1) = (base + 2 * j, base + 2 * j + 1, base + 2 * j + 2, base + 2 * j + 3);
            let _ = writeln!(text, "f {l0} {l1} {r1} {r0}");
        }
        base += 2 * n;
    }
    text
}

/// rulings.obj: per strip a group `rulings_<id>`, each ruling a segment from `right_i` to `left_i`.
pub fn rulings_obj(pattern: &StripPattern) -> String {
    let mut text = String::from("# lamella rulings: one segment per ruling, right boundary to left boundary\n");
    let mut base = 1;
    for (id, strip) in pattern.strips.iter().enumerate() {
        let _ = writeln!(text, "g rulings_{id}");
        for (l, r) in strip.left.iter().zip(&strip.right) {
            vertex(&mut text, r);
            vertex(&mut text, l);
            let _ = writeln!(text, "l {base} {}", base + 1);
            base += 2;
        }
    }
    text
}

/// The point of an OBJ `v` line from the tokens after `v`: 3 finite coordinates, or what is wrong.
fn obj_point<'a>(tokens: impl Iterator<Item = &'a str>) -> Result<Vec3, &'static str> {
    let coordinates: Vec<f64> = tokens.take(3).map(|t| t.parse::<f64>()).collect::<Result<_, _>>().map_err(|_| "malformed vertex")?;
    let [x, y, z] = coordinates[..] else { return Err("a vertex needs 3 coordinates") };
    if ![x, y, z].iter().all(|c| c.is_finite()) {
        return Err("non-finite coordinate");
    }
    Ok(Vec3::new(x, y, z))
}

/// Reads the strips of a strips.obj written by [`strips_obj`]: the `v` lines of each `g` group,
/// alternately left and right, at least 2 pairs per strip. Faces and comments are not needed.
pub fn read_strips_obj(path: &Path) -> CliResult<Vec<StripShape>> {
    let text = read_text(path)?;
    let bad = |line: usize, what: &str| CliError::bad_input(format!("{}: line {line}: {what}", path.display()));
    let mut shapes: Vec<StripShape> = Vec::new();
    let mut pending_left: Option<Vec3> = None;
    for (i, raw) in text.lines().enumerate() {
        let line = i + 1;
        let mut tokens = raw.split('#').next().unwrap_or("").split_whitespace();
        match tokens.next() {
            Some("g") => {
                if pending_left.take().is_some() {
                    return Err(bad(line, "the previous strip has an odd number of vertices"));
                }
                let name = tokens.collect::<Vec<_>>().join(" ");
                shapes.push(StripShape { name, left: Vec::new(), right: Vec::new() });
            }
            Some("v") => {
                let p = obj_point(tokens).map_err(|what| bad(line, what))?;
                let shape = shapes.last_mut().ok_or_else(|| bad(line, "vertex before the first `g strip_<id>` group"))?;
                match pending_left.take() {
                    None => pending_left = Some(p),
                    Some(left) => {
                        shape.left.push(left);
                        shape.right.push(p);
                    }
                }
            }
            _ => {}
        }
    }
    if pending_left.is_some() {
        return Err(CliError::bad_input(format!("{}: the last strip has an odd number of vertices", path.display())));
    }
    if shapes.is_empty() {
        return Err(CliError::bad_input(format!("{}: no strips (no `g` groups)", path.display())));
    }
    if let Some(short) = shapes.iter().find(|s| s.left.len() < 2) {
        return Err(CliError::bad_input(format!("{}: strip `{}` has fewer than 2 rulings", path.display(), lamella::input::clip(&short.name))));
    }
    Ok(shapes)
}

/// Reads the polylines of a curves.obj written by [`curves_obj`]: one per `l` element, its
/// vertices by their 1-based indices (a closed curve repeats its first vertex).
pub fn read_curves_obj(path: &Path) -> CliResult<Vec<Vec<Vec3>>> {
    let text = read_text(path)?;
    let bad = |line: usize, what: &str| CliError::bad_input(format!("{}: line {line}: {what}", path.display()));
    let mut vertices: Vec<Vec3> = Vec::new();
    let mut polylines = Vec::new();
    for (i, raw) in text.lines().enumerate() {
        let line = i + 1;
        let mut tokens = raw.split('#').next().unwrap_or("").split_whitespace();
        match tokens.next() {
            Some("v") => {
                vertices.push(obj_point(tokens).map_err(|what| bad(line, what))?);
            }
            Some("l") => {
                let polyline = tokens
                    .map(|t| t.parse::<usize>().ok().and_then(|k| k.checked_sub(1)).and_then(|k| vertices.get(k).copied()))
                    .collect::<Option<Vec<Vec3>>>()
                    .ok_or_else(|| bad(line, "a polyline index is not a vertex defined above"))?;
                polylines.push(polyline);
            }
            _ => {}
        }
    }
    Ok(polylines)
}
