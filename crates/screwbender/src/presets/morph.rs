//! Shape morphing along a motion (paper Fig. 7b): the object changes from the shape of one
//! control pose to that of the next, with weights that depend smoothly on the motion parameter.
//!
//! [`PipMorph`] is the paper's construction, Kaul & Rossignac's PIPs: every shape is a union of
//! convex pieces ([`PipShape`]) and the shape between `A = ∪ Aᵢ` and `B = ∪ Bⱼ` at blend `s` is
//! `∪ᵢⱼ ((1 − s) Aᵢ ⊕ s Bⱼ)`, the union of the Minkowski combinations of every pair of pieces.
//! At `s = 0` it is `A` exactly and at `s = 1` `B`, concavities included (docs/math/pip-morph.md).
//!
//! A Minkowski combination is easiest in terms of support points: the point of `Σ wₖ Sₖ` that
//! is extreme in direction `d` is `Σ wₖ sₖ(d)`, with `sₖ(d)` the extreme point of `Sₖ` (for
//! `wₖ ≥ 0`). For two convex polyhedra the pairs `(aᵢ, bⱼ)` that are extreme together, and how
//! they join into faces, are the same for every `s` strictly between 0 and 1, so [`PipMorph`]
//! finds them once (the hull of the pair sums at `s = ½`) and each frame only evaluates the
//! support points `(1 − s) aᵢ + s bⱼ`. [`morph_mesh`] samples the support points over a sphere
//! of directions instead: the Minkowski combination of the shapes' convex hulls (no concavity
//! survives), kept as the baseline the morph's speed is measured against.

use glam::DVec3;

use super::hull::extreme_hull;
use super::pieces::{ConvexPiece, PipShape};
use crate::error::{Error, ErrorKind};
use crate::presets::mesh::Mesh;
use crate::presets::{trig, Shape};

/// Latitude bands of the direction sphere ([`morph_mesh`]); longitudes are twice as many.
pub const MORPH_RESOLUTION: usize = 24;

/// The extreme point of a point set in direction `d` (the support point of its convex hull).
fn support(points: &[DVec3], d: DVec3) -> DVec3 {
    points
        .iter()
        .copied()
        .max_by(|a, b| a.dot(d).total_cmp(&b.dot(d)))
        .unwrap_or(DVec3::ZERO)
}

/// The C¹ blend weights at motion parameter `u` of `count` control shapes (pose `i` at `u = i`;
/// a cycle wraps): on span `i → i + 1` the weight moves from shape `i` to `i + 1` by the
/// smoothstep `3f² − 2f³`, so the shape equals the control pose's at `u = i` and changes with
/// zero rate there. Weights are non-negative and sum to 1.
pub fn morph_weights(count: usize, closed: bool, u: f64) -> Vec<f64> {
    let mut w = vec![0.0; count];
    if count == 0 || !u.is_finite() {
        return w;
    }
    let spans = if closed { count } else { count - 1 };
    if spans == 0 {
        w[0] = 1.0;
        return w;
    }
    let u = if closed {
        u.rem_euclid(spans as f64)
    } else {
        u.clamp(0.0, spans as f64)
    };
    let i = (u.floor() as usize).min(spans - 1);
    let f = u - i as f64;
    let s = f * f * (3.0 - 2.0 * f);
    w[i] += 1.0 - s;
    w[(i + 1) % count] += s;
    w
}

/// The mesh of the Minkowski combination `Σ weights[k] · hull(shapes[k])` (the convex hulls:
/// [`PipMorph`] keeps the shapes' concavities): a sphere of
/// `resolution` latitude bands of directions, each mapped to the combination's support point,
/// with the direction as normal. Errors: no shapes, a weight count that differs from the shape
/// count, or weights that are negative or not finite (a Minkowski combination needs `wₖ ≥ 0`).
pub fn morph_mesh(shapes: &[Shape], weights: &[f64], resolution: usize) -> Result<Mesh, Error> {
    if shapes.is_empty() {
        return Err(Error::new(
            "shapes",
            ErrorKind::TooFewPoses { found: 0, min: 1 },
        ));
    }
    if weights.len() != shapes.len() {
        return Err(Error::new(
            "weights",
            ErrorKind::OutOfRange {
                value: format!("{} weights", weights.len()),
                expected: format!("{} (one per shape)", shapes.len()),
            },
        ));
    }
    if let Some(k) = weights.iter().position(|w| !(w.is_finite() && *w >= 0.0)) {
        return Err(Error::new(
            format!("weights[{k}]"),
            ErrorKind::OutOfRange {
                value: weights[k].to_string(),
                expected: "a finite non-negative weight".into(),
            },
        ));
    }
    let hulls: Vec<(f64, Vec<DVec3>)> = shapes
        .iter()
        .zip(weights)
        .filter(|(_, &w)| w > 0.0)
        .map(|(s, &w)| (w, Mesh::from_shape(s).positions))
        .collect();
    let lat = resolution.max(4);
    let lon = 2 * lat;
    let mut mesh = Mesh::default();
    for i in 0..=lat {
        let theta = std::f64::consts::PI * i as f64 / lat as f64;
        for j in 0..lon {
            let phi = std::f64::consts::TAU * j as f64 / lon as f64;
            let d = DVec3::new(
                trig::sin(theta) * trig::cos(phi),
                trig::sin(theta) * trig::sin(phi),
                trig::cos(theta),
            );
            let p = hulls.iter().map(|(w, pts)| support(pts, d) * *w).sum();
            mesh.positions.push(p);
            mesh.normals.push(d);
        }
    }
    let at = |i: usize, j: usize| (i * lon + j % lon) as u32;
    for i in 0..lat {
        for j in 0..lon {
            // Counter-clockwise seen from outside (normals point outwards).
            mesh.indices
                .extend([at(i, j), at(i + 1, j), at(i + 1, j + 1)]);
            mesh.indices
                .extend([at(i, j), at(i + 1, j + 1), at(i, j + 1)]);
        }
    }
    Ok(mesh)
}

/// Cosine of the crease angle (40°): faces of a morph mesh whose normals differ by less share
/// smooth vertex normals, sharper edges keep each face's own (a block stays sharp, a sphere
/// smooth).
pub const CREASE_COSINE: f64 = 0.766_044_443_118_978;

/// A convex polyhedron whose corners move linearly with the blend `s`: corner `k` sits at
/// `(1 − s) from[k] + s to[k]` (three corners per triangle, counter-clockwise from outside).
/// The faces' planes keep their normals for every `s` in `(0, 1)`, so the normals are fixed.
#[derive(Clone, Debug, PartialEq)]
pub struct BlendMesh {
    /// Corner positions at `s = 0`.
    pub from: Vec<DVec3>,
    /// Corner positions at `s = 1`.
    pub to: Vec<DVec3>,
    /// Unit corner normals.
    pub normals: Vec<DVec3>,
}

impl BlendMesh {
    /// Appends the polyhedron at blend `s` to `out` (its own vertices, sequential indices).
    pub fn append_at(&self, s: f64, out: &mut Mesh) {
        let base = out.positions.len() as u32;
        out.positions.extend(
            self.from
                .iter()
                .zip(&self.to)
                .map(|(a, b)| *a + (*b - *a) * s),
        );
        out.normals.extend_from_slice(&self.normals);
        out.indices.extend(base..base + self.from.len() as u32);
    }

    /// The polyhedron at blend `s`.
    pub fn at(&self, s: f64) -> Mesh {
        let mut m = Mesh::default();
        self.append_at(s, &mut m);
        m
    }

    /// The number of triangles.
    pub fn triangle_count(&self) -> usize {
        self.from.len() / 3
    }
}

/// Per-corner normals of a closed triangle mesh: each corner averages, weighted by their angle
/// at the vertex, the normals of the vertex's faces within the crease angle of its own face.
fn corner_normals(p: &[DVec3], tris: &[[u32; 3]]) -> Vec<DVec3> {
    let face: Vec<DVec3> = tris
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(|i| p[i as usize]);
            (b - a).cross(c - a).normalize_or(DVec3::Z)
        })
        .collect();
    let mut around: Vec<Vec<(usize, f64)>> = vec![Vec::new(); p.len()];
    for (f, t) in tris.iter().enumerate() {
        for k in 0..3 {
            let v = p[t[k] as usize];
            let e1 = p[t[(k + 1) % 3] as usize] - v;
            let e2 = p[t[(k + 2) % 3] as usize] - v;
            around[t[k] as usize].push((f, trig::angle_between(e1, e2)));
        }
    }
    let mut out = Vec::with_capacity(3 * tris.len());
    for (f, t) in tris.iter().enumerate() {
        for &v in t {
            let n: DVec3 = around[v as usize]
                .iter()
                .filter(|(g, _)| face[*g].dot(face[f]) >= CREASE_COSINE)
                .map(|(g, w)| face[*g] * *w)
                .sum();
            out.push(n.normalize_or(face[f]));
        }
    }
    out
}

/// The corners of `tris` over vertices that move from `from[v]` to `to[v]`, with the normals
/// of the polyhedron at `mid`.
fn blend_mesh(from: &[DVec3], to: &[DVec3], mid: &[DVec3], tris: &[[u32; 3]]) -> BlendMesh {
    let corner = |v: &[DVec3]| {
        tris.iter()
            .flat_map(|t| t.map(|i| v[i as usize]))
            .collect::<Vec<_>>()
    };
    BlendMesh {
        from: corner(from),
        to: corner(to),
        normals: corner_normals(mid, tris),
    }
}

/// A convex piece that does not move (`from = to`).
fn still(piece: &ConvexPiece) -> BlendMesh {
    blend_mesh(
        &piece.points,
        &piece.points,
        &piece.points,
        &piece.triangles,
    )
}

/// `(1 − s) a ⊕ s b` for every `s` at once: the hull of the pair sums at `s = ½`, each vertex
/// remembering its pair `(aᵢ, bⱼ)`.
fn pair(a: &ConvexPiece, b: &ConvexPiece) -> BlendMesh {
    let nb = b.points.len();
    let (mut from, mut to, mut mid) = (Vec::new(), Vec::new(), Vec::new());
    for pa in &a.points {
        for pb in &b.points {
            from.push(*pa);
            to.push(*pb);
            mid.push((*pa + *pb) * 0.5);
        }
    }
    debug_assert_eq!(mid.len(), a.points.len() * nb);
    let tris = extreme_hull(&mid).expect("the sum of two solid pieces is solid");
    blend_mesh(&from, &to, &mid, &tris)
}

/// Kaul & Rossignac's PIP morph through one shape per control pose (see the module docs): the
/// pairs of pieces of every span are combined once, each frame evaluates their corners.
#[derive(Clone, Debug, PartialEq)]
pub struct PipMorph {
    closed: bool,
    /// Per shape: its pieces.
    shapes: Vec<Vec<BlendMesh>>,
    /// Per span `i → i + 1` (a cycle's last span ends at shape 0): every pair of pieces.
    spans: Vec<Vec<BlendMesh>>,
}

impl PipMorph {
    /// The morph through `shapes` (shape `i` at `u = i`; a cycle wraps). Errors: no shapes.
    pub fn new(shapes: &[PipShape], closed: bool) -> Result<PipMorph, Error> {
        if shapes.is_empty() {
            return Err(Error::new(
                "shapes",
                ErrorKind::TooFewPoses { found: 0, min: 1 },
            ));
        }
        let n = shapes.len();
        let spans = if n == 1 {
            0
        } else if closed {
            n
        } else {
            n - 1
        };
        Ok(PipMorph {
            closed,
            shapes: shapes
                .iter()
                .map(|s| s.pieces.iter().map(still).collect())
                .collect(),
            spans: (0..spans)
                .map(|i| {
                    let (a, b) = (&shapes[i], &shapes[(i + 1) % n]);
                    a.pieces
                        .iter()
                        .flat_map(|pa| b.pieces.iter().map(move |pb| pair(pa, pb)))
                        .collect()
                })
                .collect(),
        })
    }

    /// The morph through preset shapes ([`PipShape::from_shape`]).
    pub fn from_shapes(shapes: &[Shape], closed: bool) -> Result<PipMorph, Error> {
        let pieces: Vec<PipShape> = shapes.iter().map(PipShape::from_shape).collect();
        PipMorph::new(&pieces, closed)
    }

    /// The morph of the preset named `id` when it has one shape per control pose (scene A8) and
    /// the motion still has `pose_count` poses; `None` otherwise (a preset without shapes, an
    /// unknown name, or a document whose poses were added or removed).
    pub fn for_preset(id: &str, pose_count: usize, closed: bool) -> Option<PipMorph> {
        let s = crate::presets::preset(id)?;
        if s.morph_shapes.is_empty() || s.morph_shapes.len() != pose_count {
            return None;
        }
        PipMorph::from_shapes(&s.morph_shapes, closed).ok()
    }

    /// The number of shapes (one per control pose).
    pub fn shape_count(&self) -> usize {
        self.shapes.len()
    }

    /// Whether the morph is a cycle.
    pub fn closed(&self) -> bool {
        self.closed
    }

    /// The number of spans (`n` for a cycle, `n − 1` for an open morph, 0 for one shape).
    pub fn span_count(&self) -> usize {
        self.spans.len()
    }

    /// The pieces of shape `i` (each with `from = to`).
    pub fn shape(&self, i: usize) -> &[BlendMesh] {
        &self.shapes[i]
    }

    /// The largest distance of any shape's vertex from the local origin: every in-between
    /// shape lies within it too (its points are convex combinations of the shapes' points).
    pub fn radius(&self) -> f64 {
        self.shapes
            .iter()
            .flatten()
            .flat_map(|m| m.from.iter())
            .map(|p| p.length())
            .fold(0.0, f64::max)
    }

    /// The pieces of span `i` (every pair of pieces of shapes `i` and `i + 1`), `s` from 0 to 1.
    pub fn span(&self, i: usize) -> &[BlendMesh] {
        &self.spans[i]
    }

    /// The span and blend at motion parameter `u`, as [`morph_weights`] has them: span `i`
    /// with blend `s = 3f² − 2f³`, `f = u − i`; `None` for one shape. Errors: `u` not finite.
    pub fn blend_at(&self, u: f64) -> Result<Option<(usize, f64)>, Error> {
        if !u.is_finite() {
            return Err(Error::new("u", ErrorKind::NonFinite));
        }
        let spans = self.spans.len();
        if spans == 0 {
            return Ok(None);
        }
        let u = if self.closed {
            u.rem_euclid(spans as f64)
        } else {
            u.clamp(0.0, spans as f64)
        };
        let i = (u.floor() as usize).min(spans - 1);
        let f = u - i as f64;
        Ok(Some((i, f * f * (3.0 - 2.0 * f))))
    }

    /// The convex pieces of the object at motion parameter `u`: at a control pose (`s` exactly
    /// 0 or 1) that pose's pieces, in between every pair's combination. Errors: `u` not finite.
    pub fn pieces_at(&self, u: f64) -> Result<Vec<Mesh>, Error> {
        let (parts, s) = self.parts_at(u)?;
        Ok(parts.iter().map(|m| m.at(s)).collect())
    }

    fn parts_at(&self, u: f64) -> Result<(&[BlendMesh], f64), Error> {
        Ok(match self.blend_at(u)? {
            None => (&self.shapes[0], 0.0),
            Some((i, s)) if s <= 0.0 => (&self.shapes[i], 0.0),
            Some((i, s)) if s >= 1.0 => (&self.shapes[(i + 1) % self.shapes.len()], 0.0),
            Some((i, s)) => (&self.spans[i], s),
        })
    }

    /// The object at motion parameter `u` as one mesh (the pieces of [`PipMorph::pieces_at`]
    /// appended; drawn together they show the union). Errors: `u` not finite.
    pub fn mesh_at(&self, u: f64) -> Result<Mesh, Error> {
        let (parts, s) = self.parts_at(u)?;
        let mut m = Mesh::default();
        for p in parts {
            p.append_at(s, &mut m);
        }
        Ok(m)
    }
}
