//! Kaul & Rossignac's PIP morph (scene A8, paper Fig. 7b): every shape a union of convex pieces,
//! the shape in between the union of the Minkowski combinations of every pair of pieces. At each
//! control pose the object is that pose's shape (the star keeps its points and notches, which
//! its convex hull would fill); in between its volume changes continuously.
//!
//! Native only: its fits or sampling are among the heaviest of these modules, and the browser
//! test runner gives up on a page that does not answer for 30 s, which a test that long holds
//! up; the wasm stage leaves it out (tests/properties/main.rs).
#![cfg(not(target_arch = "wasm32"))]

use glam::DVec3;
use screwbender::mesh::Mesh;
use screwbender::presets::{preset, Shape};
use screwbender::{morph_mesh, morph_weights, ErrorKind, PipMorph, PipShape, MORPH_RESOLUTION};

/// The closest point of triangle `abc` to `p` (Ericson, Real-Time Collision Detection §5.1.5).
fn closest_on_triangle(p: DVec3, a: DVec3, b: DVec3, c: DVec3) -> DVec3 {
    let (ab, ac, ap) = (b - a, c - a, p - a);
    let (d1, d2) = (ab.dot(ap), ac.dot(ap));
    if d1 <= 0.0 && d2 <= 0.0 {
        return a;
    }
    let bp = p - b;
    let (d3, d4) = (ab.dot(bp), ac.dot(bp));
    if d3 >= 0.0 && d4 <= d3 {
        return b;
    }
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        return a + ab * (d1 / (d1 - d3));
    }
    let cp = p - c;
    let (d5, d6) = (ab.dot(cp), ac.dot(cp));
    if d6 >= 0.0 && d5 <= d6 {
        return c;
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        return a + ac * (d2 / (d2 - d6));
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0 {
        return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    }
    let denom = 1.0 / (va + vb + vc);
    a + ab * (vb * denom) + ac * (vc * denom)
}

fn triangles(m: &Mesh) -> impl Iterator<Item = [DVec3; 3]> + '_ {
    m.indices
        .chunks_exact(3)
        .map(|t| [0, 1, 2].map(|k| m.positions[t[k] as usize]))
}

/// Distance from `p` to the surface of `m`.
fn distance_to(m: &Mesh, p: DVec3) -> f64 {
    triangles(m)
        .map(|[a, b, c]| closest_on_triangle(p, a, b, c).distance(p))
        .fold(f64::INFINITY, f64::min)
}

/// Whether `p` lies inside the convex piece `m` (deeper than `margin` behind every face).
fn inside_convex(m: &Mesh, p: DVec3, margin: f64) -> bool {
    triangles(m).all(|[a, b, c]| {
        let n = (b - a).cross(c - a);
        n.length() < 1e-14 || n.normalize().dot(p - a) < -margin
    })
}

/// Points on a triangle: its corners, its centroid and (`dense`) nine inner points.
fn samples([a, b, c]: [DVec3; 3], dense: bool) -> Vec<DVec3> {
    let mut out = vec![a, b, c, (a + b + c) / 3.0];
    if !dense {
        return out;
    }
    for (u, v) in [
        (0.1, 0.1),
        (0.8, 0.1),
        (0.1, 0.8),
        (0.45, 0.45),
        (0.45, 0.1),
        (0.1, 0.45),
        (0.3, 0.6),
        (0.6, 0.3),
        (0.25, 0.25),
    ] {
        out.push(a + (b - a) * u + (c - a) * v);
    }
    out
}

/// Sample points of the union's boundary: points of the pieces' faces that no other piece
/// covers just outside them.
fn union_boundary(pieces: &[Mesh], size: f64, dense: bool) -> Vec<DVec3> {
    let delta = 1e-7 * size;
    let mut out = Vec::new();
    for (k, m) in pieces.iter().enumerate() {
        for tri @ [a, b, c] in triangles(m) {
            let n = (b - a).cross(c - a);
            if n.length() < 1e-14 * size * size {
                continue;
            }
            let n = n.normalize();
            for p in samples(tri, dense) {
                let out_of_others = pieces
                    .iter()
                    .enumerate()
                    .all(|(j, o)| j == k || !inside_convex(o, p + n * delta, 0.0));
                if out_of_others {
                    out.push(p);
                }
            }
        }
    }
    out
}

/// The Hausdorff distance between the union of `pieces` and the solid whose surface is `shape`,
/// measured between their boundaries at sample points of every face (and every vertex).
fn hausdorff(pieces: &[Mesh], shape: &Mesh, size: f64, dense: bool) -> f64 {
    let boundary = union_boundary(pieces, size, dense);
    assert!(!boundary.is_empty());
    let mut all = Mesh::default();
    for p in pieces {
        all.append(p);
    }
    let there = boundary
        .iter()
        .map(|p| distance_to(shape, *p))
        .fold(0.0, f64::max);
    let back = triangles(shape)
        .flat_map(|t| samples(t, true))
        .map(|p| distance_to(&all, p))
        .fold(0.0, f64::max);
    there.max(back)
}

fn size_of(m: &Mesh) -> f64 {
    let (lo, hi) = m.bounds().unwrap();
    (hi - lo).length()
}

fn volume(m: &Mesh) -> f64 {
    triangles(m).map(|[a, b, c]| a.dot(b.cross(c)) / 6.0).sum()
}

/// The volume of a union of convex pieces: exact for one piece, else by rays along z through a
/// fixed 60 × 60 grid over about `[-1.2, 1.2]²` (each ray meets a convex piece in one interval; the
/// intervals are merged). The estimate moves continuously with the pieces, so a jump in it is
/// a jump in the shape.
fn union_volume(pieces: &[Mesh]) -> f64 {
    if pieces.len() == 1 {
        return volume(&pieces[0]);
    }
    grid_volume(pieces)
}

/// The ray estimate of [`union_volume`], for any number of pieces.
fn grid_volume(pieces: &[Mesh]) -> f64 {
    // Offset so that no face of the presets' axis-aligned shapes lies on a row of rays (where a
    // tiny change of the shape would move a whole row in or out).
    let (lo, hi) = (
        DVec3::new(-1.213_7, -1.192_9, -1.2),
        DVec3::new(1.201_3, 1.217_1, 1.2),
    );
    for p in pieces {
        let (l, h) = p.bounds().unwrap();
        assert!(
            l.cmpge(lo).all() && h.cmple(hi).all(),
            "the grid covers the pieces"
        );
    }
    let planes: Vec<Vec<(DVec3, f64)>> = pieces
        .iter()
        .map(|m| {
            triangles(m)
                .filter_map(|[a, b, c]| {
                    let n = (b - a).cross(c - a);
                    (n.length() > 1e-14).then(|| {
                        let n = n.normalize();
                        (n, n.dot(a))
                    })
                })
                .collect()
        })
        .collect();
    let g = 60;
    let (dx, dy) = ((hi.x - lo.x) / g as f64, (hi.y - lo.y) / g as f64);
    let mut total = 0.0;
    for i in 0..g {
        for j in 0..g {
            let (x, y) = (lo.x + (i as f64 + 0.5) * dx, lo.y + (j as f64 + 0.5) * dy);
            let mut spans: Vec<(f64, f64)> = planes
                .iter()
                .filter_map(|pl| {
                    let (mut z0, mut z1) = (f64::NEG_INFINITY, f64::INFINITY);
                    for (n, d) in pl {
                        let rest = d - n.x * x - n.y * y;
                        if n.z.abs() < 1e-12 {
                            if rest < 0.0 {
                                return None;
                            }
                        } else if n.z > 0.0 {
                            z1 = z1.min(rest / n.z);
                        } else {
                            z0 = z0.max(rest / n.z);
                        }
                    }
                    (z1 > z0).then_some((z0, z1))
                })
                .collect();
            spans.sort_by(|a, b| a.0.total_cmp(&b.0));
            let mut end = f64::NEG_INFINITY;
            for (z0, z1) in spans {
                let start = z0.max(end);
                if z1 > start {
                    total += z1 - start;
                }
                end = end.max(z1);
            }
        }
    }
    total * dx * dy
}

/// Scene A8's shapes and their morph (built once for all tests).
fn a8() -> (Vec<Shape>, &'static PipMorph) {
    static MORPH: std::sync::OnceLock<PipMorph> = std::sync::OnceLock::new();
    let s = preset("pip_morph5").unwrap();
    let morph = MORPH.get_or_init(|| PipMorph::from_shapes(&s.morph_shapes, s.closed).unwrap());
    (s.morph_shapes, morph)
}

#[test]
fn at_each_control_pose_the_object_is_that_poses_shape() {
    let (shapes, morph) = a8();
    assert_eq!(morph.shape_count(), 5);
    assert_eq!(morph.span_count(), 5);
    for (i, shape) in shapes.iter().enumerate() {
        let want = Mesh::from_shape(shape);
        let size = size_of(&want);
        let got = morph.pieces_at(i as f64).unwrap();
        let d = hausdorff(&got, &want, size, true);
        assert!(d <= 1e-9 * size, "shape {i}: Hausdorff {d:.3e}");
        // A cycle: u = n is pose 0 again.
        if i == 0 {
            let again = morph.pieces_at(5.0).unwrap();
            assert!(hausdorff(&again, &want, size, true) <= 1e-9 * size);
        }
    }
}

#[test]
fn just_off_a_control_pose_the_object_is_within_the_blend_of_that_shape() {
    // The in-between construction itself (not the pose's own pieces) tends to the shape: at
    // s = 1e-10 its corners are within 1e-10 of the combined pieces' span of it.
    let (shapes, morph) = a8();
    for (i, shape) in shapes.iter().enumerate() {
        let want = Mesh::from_shape(shape);
        let size = size_of(&want);
        // f = 1e-5 gives s = 3e-10.
        let got = morph.pieces_at(i as f64 + 1e-5).unwrap();
        let d = hausdorff(&got, &want, size, false);
        assert!(d <= 1e-8 * size, "shape {i} + 1e-5: Hausdorff {d:.3e}");
    }
}

#[test]
fn the_star_keeps_its_notches_that_its_hull_would_fill() {
    let (shapes, morph) = a8();
    let Shape::StarPrism { outer, inner, .. } = shapes[1] else {
        panic!("A8's second shape is the star");
    };
    // Halfway between an inner corner and the hull's edge between the two points beside it.
    let a = std::f64::consts::FRAC_PI_2 + std::f64::consts::PI / 5.0;
    let r = 0.5 * (inner + outer * (std::f64::consts::PI / 5.0).cos());
    let notch = DVec3::new(r * a.cos(), r * a.sin(), 0.0);
    let star = morph.pieces_at(1.0).unwrap();
    assert_eq!(star.len(), 6, "a core and five points");
    assert!(star.iter().all(|p| !inside_convex(p, notch, -1e-12)));
    // The hull morph fills it.
    let hull = morph_mesh(&shapes, &morph_weights(5, true, 1.0), MORPH_RESOLUTION).unwrap();
    assert!(inside_convex(&hull, notch, 1e-6));
    // The tips are there: the farthest point from the axis is a star point.
    let reach = star
        .iter()
        .flat_map(|m| m.positions.iter())
        .map(|p| p.truncate().length())
        .fold(0.0, f64::max);
    assert!((reach - outer).abs() < 1e-12);
    // Volume: the star prism's, not its hull's.
    let want = volume(&Mesh::from_shape(&shapes[1]));
    let got = union_volume(&star);
    assert!((got - want).abs() < 0.02 * want, "{got} vs {want}");
    let pieces_sum: f64 = star.iter().map(volume).sum();
    assert!(
        (pieces_sum - want).abs() < 1e-12 * want,
        "the pieces tile the star"
    );
}

#[test]
fn between_poses_the_volume_changes_continuously() {
    let (_, morph) = a8();
    let v = |u: f64| union_volume(&morph.pieces_at(u).unwrap());
    let vmax = (0..5).map(|i| v(i as f64)).fold(0.0, f64::max);
    let h = 1e-4;
    for k in 0..25 {
        let u = k as f64 * 0.2 + 0.013;
        let (a, b) = (v(u), v(u + h));
        // |dV/du| is bounded by a few times the largest volume (the smoothstep's rate is at
        // most 1.5): a jump would be a sizeable fraction of a volume.
        assert!((a - b).abs() <= 10.0 * vmax * h, "u = {u}: {a} → {b}");
    }
    // Across each control pose, from the in-between pieces to the pose's own and on (the
    // same estimate on both sides).
    let g = |u: f64| grid_volume(&morph.pieces_at(u).unwrap());
    for i in 0..5 {
        let at = g(i as f64);
        for u in [i as f64 - 1e-5, i as f64 + 1e-5] {
            let near = g(u.rem_euclid(5.0));
            assert!(
                (near - at).abs() <= 1e-6 * vmax,
                "pose {i}, u = {u}: {near} vs {at}"
            );
        }
    }
}

/// An L of two boxes that overlap but share no vertex, and the same L as one welded block.
fn l_shapes() -> (Mesh, Mesh) {
    let mut two = Mesh::cuboid(DVec3::new(1.0, 0.5, 0.5)).translated(DVec3::new(1.0, 0.5, 0.5));
    two.append(&Mesh::cuboid(DVec3::new(0.5, 0.55, 0.5)).translated(DVec3::new(0.5, 1.45, 0.5)));
    let outline = [
        [0.0, 0.0],
        [2.0, 0.0],
        [2.0, 1.0],
        [1.0, 1.0],
        [1.0, 2.0],
        [0.0, 2.0],
    ];
    // Mesh::prism needs an outline star-shaped about the origin: the L is, about (0.5, 0.5).
    let shifted: Vec<[f64; 2]> = outline.iter().map(|p| [p[0] - 0.5, p[1] - 0.5]).collect();
    let one = Mesh::prism(&shifted, 0.0, 1.0).translated(DVec3::new(0.5, 0.5, 0.0));
    (two, one)
}

#[test]
fn an_imported_union_of_convex_parts_keeps_its_concavity() {
    let (two, _) = l_shapes();
    let l = PipShape::from_mesh(&two).unwrap();
    assert_eq!(l.pieces.len(), 2);
    let ball = PipShape::from_shape(&Shape::Sphere { radius: 0.6 });
    let morph = PipMorph::new(&[l, ball], false).unwrap();
    let inner_corner = DVec3::new(1.5, 1.5, 0.5);
    let at_l = morph.pieces_at(0.0).unwrap();
    assert!(at_l.iter().all(|p| !inside_convex(p, inner_corner, -1e-12)));
    let hull = morph_mesh(
        &[Shape::Block {
            size: [2.0, 2.0, 1.0],
            base: false,
        }],
        &[1.0],
        8,
    )
    .unwrap()
    .translated(DVec3::new(1.0, 1.0, 0.5));
    assert!(
        inside_convex(&hull, inner_corner, 1e-6),
        "the hull fills it"
    );
    // Between: every pair combined, and the ball at the end.
    assert_eq!(morph.pieces_at(0.5).unwrap().len(), 2);
    assert_eq!(morph.pieces_at(1.0).unwrap().len(), 1);
}

#[test]
fn a_non_convex_part_is_refused_with_its_name() {
    let (_, one) = l_shapes();
    let e = PipShape::from_mesh(&one).unwrap_err();
    assert_eq!(e.path(), "mesh.components[0]");
    assert!(matches!(e.kind(), ErrorKind::Unsupported { .. }));
    assert!(e.to_string().contains("not convex"), "{e}");
    let flat = Mesh::prism(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]], 0.0, 0.0);
    let e = PipShape::from_mesh(&flat).unwrap_err();
    assert!(e.to_string().contains("span a volume"), "{e}");
    assert!(PipMorph::new(&[], true).is_err());
    let (_, morph) = a8();
    assert!(morph.mesh_at(f64::NAN).is_err());
}

#[test]
fn every_preset_shape_splits_into_convex_pieces() {
    let mut all: Vec<Shape> = Vec::new();
    for s in screwbender::presets::all() {
        all.push(s.shape);
        all.extend(s.morph_shapes);
    }
    for shape in all {
        let p = PipShape::from_shape(&shape);
        assert!(!p.pieces.is_empty(), "{shape:?}");
        assert!(p.pieces.iter().all(|c| c.volume() > 0.0), "{shape:?}");
    }
}
