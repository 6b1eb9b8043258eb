//! The point of a triangle closest to a point in space, as barycentric coordinates: the
//! projection used to put sketched strokes and strip points onto the surface.

use super::Vec3;

/// Barycentric coordinates of the point of triangle `[a, b, c]` closest to `p` (Ericson,
/// Real-Time Collision Detection, Sec. 5.1.5: Voronoi regions of vertices, edges, face).
pub(crate) fn closest_barycentric(p: &Vec3, [a, b, c]: &[Vec3; 3]) -> [f64; 3] {
    let (ab, ac, ap) = (b - a, c - a, p - a);
    let (d1, d2) = (ab.dot(&ap), ac.dot(&ap));
    if d1 <= 0.0 && d2 <= 0.0 {
        return [1.0, 0.0, 0.0];
    }
    let bp = p - b;
    let (d3, d4) = (ab.dot(&bp), ac.dot(&bp));
    if d3 >= 0.0 && d4 <= d3 {
        return [0.0, 1.0, 0.0];
    }
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        let v = d1 / (d1 - d3);
        return [1.0 - v, v, 0.0];
    }
    let cp = p - c;
    let (d5, d6) = (ab.dot(&cp), ac.dot(&cp));
    if d6 >= 0.0 && d5 <= d6 {
        return [0.0, 0.0, 1.0];
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        let w = d2 / (d2 - d6);
        return [1.0 - w, 0.0, w];
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0 {
        let w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return [0.0, 1.0 - w, w];
    }
    // Inside the face; the mesh has no degenerate faces, so the denominator is positive.
    let denominator = 1.0 / (va + vb + vc);
    let (v, w) = (vb * denominator, vc * denominator);
    [1.0 - v - w, v, w]
}

#[cfg(test)]
mod tests {
    use super::closest_barycentric;
    use crate::mesh::Vec3;

    #[test]
    fn regions_of_a_triangle() {
        let t = [Vec3::zeros(), Vec3::x(), Vec3::y()];
        let inside = closest_barycentric(&Vec3::new(0.2, 0.3, 5.0), &t);
        assert!((inside[0] - 0.5).abs() < 1e-15 && (inside[1] - 0.2).abs() < 1e-15 && (inside[2] - 0.3).abs() < 1e-15);
        assert_eq!(closest_barycentric(&Vec3::new(-1.0, -1.0, 0.0), &t), [1.0, 0.0, 0.0]);
        let edge = closest_barycentric(&Vec3::new(0.5, -2.0, 1.0), &t);
        assert!((edge[1] - 0.5).abs() < 1e-15 && edge[2] == 0.0);
    }

    /// Brute force: the closest of many sample points of the triangle.
    fn sampled_distance(p: &Vec3, t: &[Vec3; 3]) -> f64 {
        let n = 200;
        let mut best = f64::INFINITY;
        for i in 0..=n {
            for j in 0..=n - i {
                let (u, v) = (i as f64 / n as f64, j as f64 / n as f64);
                let q = t[0] * (1.0 - u - v) + t[1] * u + t[2] * v;
                best = best.min((q - p).norm());
            }
        }
        best
    }

    #[test]
    fn closest_point_matches_dense_sampling_in_every_region() {
        let t = [Vec3::new(0.0, 0.0, 0.0), Vec3::new(2.0, 0.0, 0.3), Vec3::new(0.5, 1.5, -0.2)];
        let queries = [
            Vec3::new(0.7, 0.4, 1.0),   // above the face
            Vec3::new(-1.0, -1.0, 0.0), // vertex a
            Vec3::new(3.0, -0.5, 0.0),  // vertex b
            Vec3::new(0.5, 3.0, 0.0),   // vertex c
            Vec3::new(1.0, -1.0, 0.5),  // edge ab
            Vec3::new(-0.8, 0.8, 0.0),  // edge ac
            Vec3::new(1.8, 1.2, 0.0),   // edge bc
        ];
        for p in &queries {
            let w = closest_barycentric(p, &t);
            assert!(w.iter().all(|&x| (-1e-12..=1.0 + 1e-12).contains(&x)) && (w.iter().sum::<f64>() - 1.0).abs() < 1e-12);
            let q = t[0] * w[0] + t[1] * w[1] + t[2] * w[2];
            let exact = (q - p).norm();
            let sampled = sampled_distance(p, &t);
            assert!(exact <= sampled + 1e-12 && sampled - exact < 2e-2, "{p:?}: {exact} vs {sampled}");
        }
    }
}
