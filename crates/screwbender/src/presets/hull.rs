//! The convex hull of a point set in 3D (quickhull), as triangles over the input's indices.
//!
//! The shape morph needs the hull of the pairwise sums of two convex pieces with each hull
//! vertex still knowing which pair it came from, so that the same faces can be evaluated at
//! every blend weight ([`super::morph`]). The point sets are small (at most a few tens of
//! thousands of points, made once per pair of pieces), so a plain quickhull with outside sets
//! is enough; a general geometry library would add far more to the WebAssembly modules than
//! these few functions.
//!
//! Points within a relative tolerance ([`HULL_EPSILON`] times the set's size) of a face count as
//! on it: coplanar points never become vertices, so a box's faces stay two triangles however
//! many points lie on them.

use std::collections::HashMap;

use glam::DVec3;

/// Points closer than this fraction of the point set's bounding-box diagonal to a face's plane
/// count as on the face.
pub const HULL_EPSILON: f64 = 1e-11;

struct Face {
    v: [u32; 3],
    n: DVec3,
    d: f64,
    outside: Vec<u32>,
    alive: bool,
}

fn plane(p: &[DVec3], v: [u32; 3]) -> (DVec3, f64) {
    let [a, b, c] = v.map(|i| p[i as usize]);
    let n = (b - a).cross(c - a).normalize_or_zero();
    (n, n.dot(a))
}

fn key(a: u32, b: u32) -> u64 {
    (u64::from(a) << 32) | u64::from(b)
}

/// The hull's triangles, counter-clockwise seen from outside, as indices into `points`; `None`
/// when the points span no volume (fewer than four points off a common plane) or are not finite.
pub fn convex_hull(points: &[DVec3]) -> Option<Vec<[u32; 3]>> {
    if points.len() < 4 || points.iter().any(|p| !p.is_finite()) {
        return None;
    }
    let (lo, hi) = points
        .iter()
        .fold((points[0], points[0]), |(l, h), p| (l.min(*p), h.max(*p)));
    let eps = HULL_EPSILON * (hi - lo).length();
    if eps <= 0.0 {
        return None;
    }
    // The initial tetrahedron: the two points farthest apart along an axis, the point farthest
    // from their line, the point farthest from their plane.
    let axis = (hi - lo).max_position();
    let arg = |f: &dyn Fn(DVec3) -> f64| {
        (0..points.len())
            .max_by(|&i, &j| f(points[i]).total_cmp(&f(points[j])))
            .expect("non-empty") as u32
    };
    let i0 = arg(&|p| -p[axis]);
    let i1 = arg(&|p| p[axis]);
    let (a, b) = (points[i0 as usize], points[i1 as usize]);
    let dir = (b - a).normalize_or_zero();
    let i2 = arg(&|p| (p - a).cross(dir).length());
    let c = points[i2 as usize];
    let n = (b - a).cross(c - a).normalize_or_zero();
    if (c - a).cross(dir).length() <= eps || n == DVec3::ZERO {
        return None;
    }
    let i3 = arg(&|p| (p - a).dot(n).abs());
    if (points[i3 as usize] - a).dot(n).abs() <= eps {
        return None;
    }
    let mut faces: Vec<Face> = Vec::new();
    let mut edges: HashMap<u64, usize> = HashMap::new();
    let add = |faces: &mut Vec<Face>, edges: &mut HashMap<u64, usize>, v: [u32; 3]| {
        let (n, d) = plane(points, v);
        let f = faces.len();
        for k in 0..3 {
            edges.insert(key(v[k], v[(k + 1) % 3]), f);
        }
        faces.push(Face {
            v,
            n,
            d,
            outside: Vec::new(),
            alive: true,
        });
        f
    };
    // Orient the tetrahedron outwards: i3 must lie behind face (i0, i1, i2).
    let base = if (points[i3 as usize] - a).dot(n) > 0.0 {
        [i0, i2, i1]
    } else {
        [i0, i1, i2]
    };
    let [p, q, r] = base;
    for v in [[p, q, r], [p, i3, q], [q, i3, r], [r, i3, p]] {
        add(&mut faces, &mut edges, v);
    }
    let assign = |faces: &mut Vec<Face>, candidates: &[usize], i: u32| {
        let x = points[i as usize];
        let best = candidates
            .iter()
            .map(|&f| (f, faces[f].n.dot(x) - faces[f].d))
            .filter(|&(_, h)| h > eps)
            .max_by(|a, b| a.1.total_cmp(&b.1));
        if let Some((f, _)) = best {
            faces[f].outside.push(i);
        }
    };
    let first: Vec<usize> = (0..4).collect();
    for i in 0..points.len() as u32 {
        if ![i0, i1, i2, i3].contains(&i) {
            assign(&mut faces, &first, i);
        }
    }
    let mut pending: Vec<usize> = (0..4).collect();
    while let Some(f) = pending.pop() {
        if !faces[f].alive || faces[f].outside.is_empty() {
            continue;
        }
        // The outside point farthest from this face becomes a vertex.
        let far = *faces[f]
            .outside
            .iter()
            .max_by(|&&i, &&j| {
                let h = |k: u32| faces[f].n.dot(points[k as usize]);
                h(i).total_cmp(&h(j))
            })
            .expect("non-empty");
        let x = points[far as usize];
        // The faces that see it, grown from `f` across edges.
        let mut visible = vec![f];
        let mut seen = std::collections::HashSet::from([f]);
        let mut k = 0;
        while k < visible.len() {
            let g = visible[k];
            k += 1;
            let v = faces[g].v;
            for e in 0..3 {
                if let Some(&h) = edges.get(&key(v[(e + 1) % 3], v[e])) {
                    if seen.insert(h) && faces[h].n.dot(x) - faces[h].d > eps {
                        visible.push(h);
                    }
                }
            }
        }
        let is_visible: std::collections::HashSet<usize> = visible.iter().copied().collect();
        let mut horizon = Vec::new();
        let mut orphans = Vec::new();
        for &g in &visible {
            let v = faces[g].v;
            for e in 0..3 {
                let (s, t) = (v[e], v[(e + 1) % 3]);
                match edges.get(&key(t, s)) {
                    Some(h) if is_visible.contains(h) => {}
                    _ => horizon.push((s, t)),
                }
            }
            faces[g].alive = false;
            orphans.append(&mut faces[g].outside);
        }
        for &g in &visible {
            let v = faces[g].v;
            for e in 0..3 {
                if edges.get(&key(v[e], v[(e + 1) % 3])) == Some(&g) {
                    edges.remove(&key(v[e], v[(e + 1) % 3]));
                }
            }
        }
        let new: Vec<usize> = horizon
            .iter()
            .map(|&(s, t)| add(&mut faces, &mut edges, [s, t, far]))
            .collect();
        for i in orphans {
            if i != far {
                assign(&mut faces, &new, i);
            }
        }
        pending.extend(new);
    }
    Some(faces.iter().filter(|f| f.alive).map(|f| f.v).collect())
}

/// Like [`convex_hull`], but every vertex of the result is extreme: points that the hull kept
/// on an edge or inside a face (their faces have at most two planes) are dropped and the hull
/// made again. A morph needs this: such a point moves along its edge as the blend changes and
/// may pass its neighbours there, folding the triangles that use it.
pub fn extreme_hull(points: &[DVec3]) -> Option<Vec<[u32; 3]>> {
    let tris = convex_hull(points)?;
    let mut planes: HashMap<u32, Vec<DVec3>> = HashMap::new();
    for t in &tris {
        let (n, _) = plane(points, *t);
        for v in t {
            let list = planes.entry(*v).or_default();
            if list.len() < 3 && list.iter().all(|m| m.dot(n) < 1.0 - 1e-9) {
                list.push(n);
            }
        }
    }
    if planes.values().all(|l| l.len() >= 3) {
        return Some(tris);
    }
    let mut kept: Vec<u32> = planes
        .iter()
        .filter(|(_, l)| l.len() >= 3)
        .map(|(v, _)| *v)
        .collect();
    // In the points' order: a HashMap's order changes from one map to the next, and so would
    // the hull made again from it (its triangles' order and the exported meshes' bytes).
    kept.sort_unstable();
    let sub: Vec<DVec3> = kept.iter().map(|&v| points[v as usize]).collect();
    let again = convex_hull(&sub)?;
    Some(again.iter().map(|t| t.map(|i| kept[i as usize])).collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn volume(p: &[DVec3], tris: &[[u32; 3]]) -> f64 {
        tris.iter()
            .map(|t| {
                let [a, b, c] = t.map(|i| p[i as usize]);
                a.dot(b.cross(c)) / 6.0
            })
            .sum()
    }

    #[test]
    fn a_cube_with_inner_and_face_points_has_twelve_triangles() {
        let mut p = Vec::new();
        for i in 0..27 {
            p.push(DVec3::new(
                (i % 3) as f64 - 1.0,
                (i / 3 % 3) as f64 - 1.0,
                (i / 9) as f64 - 1.0,
            ));
        }
        let tris = convex_hull(&p).unwrap();
        assert!((volume(&p, &tris) - 8.0).abs() < 1e-12);
        assert_eq!(extreme_hull(&p).unwrap().len(), 12);
        // Every point lies on or behind every face.
        for t in &tris {
            let (n, d) = plane(&p, *t);
            assert!(p.iter().all(|x| n.dot(*x) <= d + 1e-12));
        }
    }

    #[test]
    fn points_on_edges_are_not_vertices_of_the_extreme_hull() {
        // A box with extra points along its edges and on its faces.
        let mut p = Vec::new();
        for i in 0..64 {
            let c = |k: u32| f64::from((i >> (2 * k)) % 4) / 3.0;
            p.push(DVec3::new(c(0), c(1), c(2)));
        }
        let tris = extreme_hull(&p).unwrap();
        let used: std::collections::HashSet<u32> = tris.iter().flatten().copied().collect();
        assert_eq!(used.len(), 8);
        assert!(used.iter().all(|&v| {
            let q = p[v as usize];
            [q.x, q.y, q.z].iter().all(|x| *x == 0.0 || *x == 1.0)
        }));
        assert!((volume(&p, &tris) - 1.0).abs() < 1e-12);
    }

    #[test]
    fn the_extreme_hull_is_the_same_every_time() {
        let mut p = Vec::new();
        for i in 0..64 {
            let c = |k: u32| f64::from((i >> (2 * k)) % 4) / 3.0;
            p.push(DVec3::new(c(0), c(1), c(2)));
        }
        let first = extreme_hull(&p).unwrap();
        for _ in 0..8 {
            assert_eq!(extreme_hull(&p).unwrap(), first);
        }
    }

    #[test]
    fn flat_or_too_few_points_have_no_hull() {
        let flat: Vec<DVec3> = (0..10)
            .map(|i| DVec3::new(i as f64, (i * i) as f64, 0.0))
            .collect();
        assert!(convex_hull(&flat).is_none());
        assert!(convex_hull(&flat[..3]).is_none());
        assert!(convex_hull(&[DVec3::NAN; 5]).is_none());
    }

    #[test]
    fn points_on_a_sphere_are_all_vertices() {
        let p: Vec<DVec3> = (0..200)
            .map(|i| {
                let z = 1.0 - 2.0 * (i as f64 + 0.5) / 200.0;
                let a = i as f64 * 2.399963;
                let r = (1.0 - z * z).sqrt();
                DVec3::new(r * a.cos(), r * a.sin(), z)
            })
            .collect();
        let tris = convex_hull(&p).unwrap();
        // A closed triangulated sphere: V − E + F = 2 with E = 3F/2.
        assert_eq!(tris.len(), 2 * 200 - 4);
        let v = volume(&p, &tris);
        assert!(v > 4.0 && v < 4.0 * std::f64::consts::PI / 3.0, "{v}");
    }
}
