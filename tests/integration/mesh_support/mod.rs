//! Small mesh generators shared by the mesh integration tests.
#![allow(dead_code)]

use lamella::mesh::{TriMesh, Vec3};

pub type Soup = (Vec<Vec3>, Vec<[u32; 3]>);

/// Planar grid of nx × ny square cells of side h in the xy-plane, vertex (i, j) at index
/// j (nx + 1) + i; each cell split along its (i, j)–(i+1, j+1) diagonal, counter-clockwise about +z.
/// Cells for which `keep(i, j)` is false are left out; unused vertices are dropped.
pub fn grid_with(nx: usize, ny: usize, h: f64, keep: impl Fn(usize, usize) -> bool) -> Soup {
    let id = |i: usize, j: usize| (j * (nx + 1) + i) as u32;
    let positions = (0..=ny)
        .flat_map(|j| (0..=nx).map(move |i| Vec3::new(i as f64 * h, j as f64 * h, 0.0)))
        .collect();
    let mut faces = Vec::new();
    for j in 0..ny {
        for i in (0..nx).filter(|&i| keep(i, j)) {
            faces.push([id(i, j), id(i + 1, j), id(i + 1, j + 1)]);
            faces.push([id(i, j), id(i + 1, j + 1), id(i, j + 1)]);
        }
    }
    compact((positions, faces))
}

pub fn grid(nx: usize, ny: usize, h: f64) -> Soup {
    grid_with(nx, ny, h, |_, _| true)
}

/// The n × n grid of unit cells on a gentle dome, with a vertex `eps` inside the middle of the
/// boundary edge y = 0 of cell (n/2, 0): it splits that cell's first triangle (face n, which
/// becomes the sliver of area ≈ eps / 2 on the boundary) and adds two faces at the end.
pub fn sliver_grid(n: usize, eps: f64) -> Soup {
    let (mut positions, mut faces) = mapped(grid(n, n, 1.0), |p| {
        let (x, y) = (p.x - n as f64 / 2.0, p.y - n as f64 / 2.0);
        Vec3::new(p.x, p.y, 0.1 * (x * x + y * y) / 16.0)
    });
    let [a, b, c] = faces[n];
    let m = positions.len() as u32;
    let (pa, pb) = (positions[a as usize], positions[b as usize]);
    positions.push(Vec3::new((pa.x + pb.x) / 2.0, eps, (pa.z + pb.z) / 2.0));
    faces[n] = [a, b, m];
    faces.extend([[a, m, c], [m, b, c]]);
    (positions, faces)
}

/// `mesh` with its first interior vertex whose neighbours are all interior moved across the
/// column (x, y) of its first neighbour, half an edge beyond it: the triangles between them turn
/// over (a fold), while the topology stays that of a disk.
pub fn folded(mesh: &TriMesh) -> Soup {
    let mut positions = mesh.positions().to_vec();
    let deep = |v: usize| !mesh.is_boundary_vertex(v) && mesh.star(v).neighbours.iter().all(|&n| !mesh.is_boundary_vertex(n as usize));
    let v = (0..mesh.vertex_count()).find(|&v| deep(v)).expect("a deep interior vertex");
    let (from, to) = (positions[v], positions[mesh.star(v).neighbours[0] as usize]);
    positions[v].x = to.x + 0.5 * (to.x - from.x);
    positions[v].y = to.y + 0.5 * (to.y - from.y);
    (positions, mesh.faces().to_vec())
}

/// OBJ text of a soup (1-based indices).
pub fn obj_text((positions, faces): &Soup) -> String {
    let vertices = positions.iter().map(|p| format!("v {} {} {}\n", p.x, p.y, p.z));
    vertices.chain(faces.iter().map(|f| format!("f {} {} {}\n", f[0] + 1, f[1] + 1, f[2] + 1))).collect()
}

/// Drops vertices used by no face and renumbers the rest in order.
pub fn compact((positions, faces): Soup) -> Soup {
    let mut new_id = vec![u32::MAX; positions.len()];
    for f in &faces {
        for &v in f {
            new_id[v as usize] = 0;
        }
    }
    let mut kept = Vec::new();
    for (v, p) in positions.iter().enumerate() {
        if new_id[v] == 0 {
            new_id[v] = kept.len() as u32;
            kept.push(*p);
        }
    }
    let faces = faces.iter().map(|f| f.map(|v| new_id[v as usize])).collect();
    (kept, faces)
}

/// Applies `map` to every position.
pub fn mapped((positions, faces): Soup, map: impl FnMut(Vec3) -> Vec3) -> Soup {
    (positions.into_iter().map(map).collect(), faces)
}

/// A spherical cap: the n × n grid over [−0.5, 0.5]² at height 1, projected onto the sphere of radius r.
pub fn sphere_cap(n: usize, r: f64) -> Soup {
    let h = 1.0 / n as f64;
    mapped(grid(n, n, h), |p| Vec3::new(p.x - 0.5, p.y - 0.5, 1.0).normalize() * r)
}

/// An open cylinder tube: n segments around, m rows along z, radius 1, outward normals.
pub fn tube(n: usize, m: usize) -> Soup {
    let id = |i: usize, j: usize| (j * n + i % n) as u32;
    let positions = (0..=m)
        .flat_map(|j| {
            (0..n).map(move |i| {
                let a = std::f64::consts::TAU * i as f64 / n as f64;
                Vec3::new(a.cos(), a.sin(), j as f64 * 0.5)
            })
        })
        .collect();
    let mut faces = Vec::new();
    for j in 0..m {
        for i in 0..n {
            faces.push([id(i, j), id(i + 1, j), id(i + 1, j + 1)]);
            faces.push([id(i, j), id(i + 1, j + 1), id(i, j + 1)]);
        }
    }
    (positions, faces)
}

pub fn mesh((positions, faces): Soup) -> TriMesh {
    match TriMesh::from_vertices_and_faces(positions, faces) {
        Ok(m) => m,
        Err(e) => panic!("test mesh rejected: {e}"),
    }
}

/// Deterministic pseudo-random numbers in [0, 1) (64-bit LCG), for perturbations and fuzzing.
pub struct Lcg(pub u64);

impl Lcg {
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        self.0 >> 11
    }
    pub fn unit(&mut self) -> f64 {
        self.next_u64() as f64 / (1u64 << 53) as f64
    }
}
