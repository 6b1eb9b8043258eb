//! What the viewer shows: the surface, the level curves and the strips with their flat
//! unrollings and Table 4 measures, grouped in named families.
use super::error::ViewError;
use crate::curves::LevelCurve;
use crate::mesh::{TriMesh, Vec3};
use crate::strips::{RectifyingStrip, StripMetrics, Unrolling};

/// The surface as a triangle mesh.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ViewSurface {
    pub positions: Vec<Vec3>,
    pub triangles: Vec<[u32; 3]>,
}

impl ViewSurface {
    /// The vertices and triangles of `mesh`.
    pub fn from_mesh(mesh: &TriMesh) -> ViewSurface {
        ViewSurface { positions: mesh.positions().to_vec(), triangles: mesh.faces().to_vec() }
    }
}

/// One strip: its boundaries `left_i = c_i + s_i d_i` and `right_i = c_i − s_i d_i` (the
/// rulings join `left_i` and `right_i`), its flat unrolling and measures.
#[derive(Clone, Debug, PartialEq)]
pub struct ViewStrip {
    /// Its name in every output (`strip_<id>`).
    pub name: String,
    /// Index into [`ViewScene::families`].
    pub family: usize,
    pub left: Vec<Vec3>,
    pub right: Vec<Vec3>,
    /// The strip laid flat, one point per ruling.
    pub unrolling: Unrolling,
    pub metrics: StripMetrics,
    /// Largest bending utilisation (von Mises stress over the allowable stress), when a
    /// fabrication check ran.
    pub utilisation: Option<f64>,
}

impl ViewStrip {
    /// A strip of a computed pattern, in family `family`.
    pub fn from_rectifying(name: &str, family: usize, strip: &RectifyingStrip) -> ViewStrip {
        ViewStrip {
            name: name.to_string(),
            family,
            left: strip.left.clone(),
            right: strip.right.clone(),
            unrolling: strip.unrolling.clone(),
            metrics: strip.metrics,
            utilisation: None,
        }
    }

    /// Checks the strip (index `index` in the scene) against `families` families.
    fn validate(&self, index: usize, families: usize) -> Result<(), ViewError> {
        let bad = |message: String| ViewError::InvalidStrip { strip: index, name: self.name.clone(), message };
        let n = self.left.len();
        if n < 2 {
            return Err(bad(format!("{n} rulings, at least 2 are needed")));
        }
        let u = &self.unrolling;
        if self.right.len() != n || u.left.len() != n || u.right.len() != n {
            return Err(bad(format!(
                "{n} left boundary points, {} right, {} and {} in the unrolling",
                self.right.len(),
                u.left.len(),
                u.right.len()
            )));
        }
        if let Some(i) = self.left.iter().zip(&self.right).position(|(l, r)| !l.iter().chain(r.iter()).all(|x| x.is_finite())) {
            return Err(bad(format!("ruling {i} has a non-finite end")));
        }
        if let Some(i) = u.left.iter().zip(&u.right).position(|(l, r)| !l.iter().chain(r).all(|x| x.is_finite())) {
            return Err(bad(format!("ruling {i} of the unrolling has a non-finite end")));
        }
        if self.family >= families {
            return Err(bad(format!("family {} does not exist ({families} families)", self.family)));
        }
        if let Some(u) = self.utilisation.filter(|u| !u.is_finite()) {
            return Err(bad(format!("utilisation {u} is not finite")));
        }
        Ok(())
    }
}

/// Everything one page shows.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ViewScene {
    /// The page title (the design's name).
    pub title: String,
    pub surface: Option<ViewSurface>,
    /// The level curves as polylines (a closed curve repeats its first point).
    pub curves: Vec<Vec<Vec3>>,
    /// Family names (`P60`, `G`, …), at least one when there are strips.
    pub families: Vec<String>,
    pub strips: Vec<ViewStrip>,
}

/// How the viewer names the family of strips built for θ (degrees).
pub fn family_name(theta: f64) -> String {
    format!("θ = {theta}°")
}

impl ViewScene {
    /// The scene of the strip families `families` (name, level curves, strips) on `mesh` (none:
    /// the strips and curves alone). The
    /// strips are named as in the CLI's files: `strip_<id>` for one family, `f<k>_strip_<id>`
    /// for family `k` of several.
    pub fn of_families(title: &str, mesh: Option<&TriMesh>, families: &[(&str, &[LevelCurve], &[RectifyingStrip])]) -> ViewScene {
        let name = |k: usize, id: usize| if families.len() == 1 { format!("strip_{id}") } else { format!("f{k}_strip_{id}") };
        ViewScene {
            title: title.to_string(),
            surface: mesh.map(ViewSurface::from_mesh),
            curves: families.iter().flat_map(|f| f.1.iter().map(polyline)).collect(),
            families: families.iter().map(|f| f.0.to_string()).collect(),
            strips: families
                .iter()
                .enumerate()
                .flat_map(|(k, f)| f.2.iter().enumerate().map(move |(id, s)| ViewStrip::from_rectifying(&name(k, id), k, s)))
                .collect(),
        }
    }

    /// Checks every element: finite points, triangles within the surface, strips as
    /// [`ViewStrip`] documents.
    pub fn validate(&self) -> Result<(), ViewError> {
        if let Some(surface) = &self.surface {
            if let Some(v) = surface.positions.iter().position(|p| !p.iter().all(|x| x.is_finite())) {
                return Err(ViewError::InvalidSurface { message: format!("vertex {v} is not finite") });
            }
            let count = surface.positions.len();
            if let Some(t) = surface.triangles.iter().position(|t| t.iter().any(|&v| v as usize >= count)) {
                return Err(ViewError::InvalidSurface { message: format!("triangle {t} addresses a vertex beyond the {count} vertices") });
            }
        }
        for (k, curve) in self.curves.iter().enumerate() {
            if let Some(i) = curve.iter().position(|p| !p.iter().all(|x| x.is_finite())) {
                return Err(ViewError::InvalidCurve { curve: k, message: format!("point {i} is not finite") });
            }
        }
        self.strips.iter().enumerate().try_for_each(|(i, s)| s.validate(i, self.families.len()))
    }

    /// The bounding box of every 3D point of the scene (the unit cube when there is none).
    pub fn bounding_box(&self) -> ([f64; 3], [f64; 3]) {
        let surface = self.surface.iter().flat_map(|s| s.positions.iter());
        let curves = self.curves.iter().flatten();
        let strips = self.strips.iter().flat_map(|s| s.left.iter().chain(&s.right));
        let (low, high) = surface.chain(curves).chain(strips).fold(([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]), |(low, high), p| {
            (std::array::from_fn(|k| low[k].min(p[k])), std::array::from_fn(|k| high[k].max(p[k])))
        });
        if low[0] > high[0] {
            ([0.0; 3], [1.0; 3])
        } else {
            (low, high)
        }
    }
}

/// The points of a level curve as a polyline, a closed curve's first point repeated at the end.
pub fn polyline(curve: &LevelCurve) -> Vec<Vec3> {
    let mut points = curve.points.clone();
    if curve.closed {
        points.extend(curve.points.first().copied());
    }
    points
}
