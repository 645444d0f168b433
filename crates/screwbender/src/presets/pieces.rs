//! Shapes as unions of convex pieces, what the PIP morph ([`super::morph`]) combines.
//!
//! The preset shapes say how they split: the star prism is a pentagonal core prism with a
//! triangular prism on each of its five sides (one per point); every other shape's mesh is
//! already a union of convex parts that share no vertex (a pendulum's bob, rod and pivot, an
//! I-beam's flanges and web, a molecule's atoms). An imported mesh is split the same way, by
//! its connected components (vertices welded by position): each component must be convex (all
//! its vertices on its convex hull), else it is refused with a message saying which one. This
//! is exact where it applies; it does not guess a decomposition of a non-convex part (an
//! approximate convex decomposition would change the shape the user gave).

use std::collections::HashMap;

use glam::DVec3;

use super::hull::extreme_hull;
use super::mesh::Mesh;
use super::{trig, Shape};
use crate::error::{Error, ErrorKind};

/// The most hull vertices one convex piece may have (the morph builds the hull of every pair
/// of vertices of two pieces).
pub const MAX_PIECE_VERTICES: usize = 1024;

/// The most convex pieces one shape may have (the morph combines every pair of pieces).
pub const MAX_PIECES: usize = 64;

/// How far inside its hull, relative to the component's size, a vertex may lie and still count
/// as on it (rounded coordinates of a convex part in a file).
pub const CONVEX_TOLERANCE: f64 = 1e-6;

/// One convex piece: its hull's vertices and triangles (counter-clockwise from outside).
#[derive(Clone, Debug, PartialEq)]
pub struct ConvexPiece {
    /// The hull vertices.
    pub points: Vec<DVec3>,
    /// The hull triangles, as indices into `points`.
    pub triangles: Vec<[u32; 3]>,
}

impl ConvexPiece {
    /// The convex hull of `points` as a piece; errors at `at` when the points span no volume or
    /// the hull has more than [`MAX_PIECE_VERTICES`] vertices.
    pub fn hull(points: &[DVec3], at: &str) -> Result<ConvexPiece, Error> {
        let tris = extreme_hull(points).ok_or_else(|| {
            Error::new(
                at,
                ErrorKind::Unsupported {
                    reason: "a convex piece must span a volume (its points are flat, too few \
                             or not finite)"
                        .into(),
                },
            )
        })?;
        // Keep only the hull's vertices, renumbered.
        let mut map = HashMap::new();
        let mut kept = Vec::new();
        let triangles: Vec<[u32; 3]> = tris
            .iter()
            .map(|t| {
                t.map(|i| {
                    *map.entry(i).or_insert_with(|| {
                        kept.push(points[i as usize]);
                        kept.len() as u32 - 1
                    })
                })
            })
            .collect();
        if kept.len() > MAX_PIECE_VERTICES {
            return Err(Error::new(
                at,
                ErrorKind::OutOfRange {
                    value: format!("{} hull vertices", kept.len()),
                    expected: format!("at most {MAX_PIECE_VERTICES} per convex piece"),
                },
            ));
        }
        Ok(ConvexPiece {
            points: kept,
            triangles,
        })
    }

    /// The piece's volume (divergence theorem over its triangles).
    pub fn volume(&self) -> f64 {
        self.triangles
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|i| self.points[i as usize]);
                a.dot(b.cross(c)) / 6.0
            })
            .sum()
    }
}

/// A solid given as the union of convex pieces.
#[derive(Clone, Debug, PartialEq)]
pub struct PipShape {
    /// The pieces (their interiors may overlap).
    pub pieces: Vec<ConvexPiece>,
}

impl PipShape {
    /// The pieces of a preset shape (see the module docs).
    pub fn from_shape(shape: &Shape) -> PipShape {
        let pieces = match *shape {
            Shape::StarPrism {
                outer,
                inner,
                thickness,
            } => star_pieces(outer, inner, thickness),
            _ => {
                return PipShape::from_mesh(&Mesh::from_shape(shape))
                    .expect("every preset shape is a union of convex parts")
            }
        };
        PipShape {
            pieces: pieces
                .iter()
                .map(|p| ConvexPiece::hull(p, "shape").expect("star pieces span a volume"))
                .collect(),
        }
    }

    /// A mesh split into its connected components, each of which must be convex (see the
    /// module docs). Errors at `mesh.components[k]`: a flat or non-convex component (with how
    /// far inside its hull a vertex lies), more than [`MAX_PIECES`] components or a component
    /// with more than [`MAX_PIECE_VERTICES`] hull vertices.
    pub fn from_mesh(mesh: &Mesh) -> Result<PipShape, Error> {
        let parts = components(mesh);
        if parts.len() > MAX_PIECES {
            return Err(Error::new(
                "mesh.components",
                ErrorKind::OutOfRange {
                    value: format!("{} connected components", parts.len()),
                    expected: format!("at most {MAX_PIECES} convex parts"),
                },
            ));
        }
        let mut pieces = Vec::with_capacity(parts.len());
        for (k, part) in parts.iter().enumerate() {
            let at = format!("mesh.components[{k}]");
            let piece = ConvexPiece::hull(&part.points, &at)?;
            let (lo, hi) = bounds(&part.points);
            let tol = CONVEX_TOLERANCE * (hi - lo).length();
            // Convex: every face's plane has the whole part on its inner side.
            for [a, b, c] in &part.triangles {
                let n = (*b - *a).cross(*c - *a);
                if n.length() <= tol * tol {
                    continue;
                }
                let n = n.normalize();
                let (far, height) = part
                    .points
                    .iter()
                    .map(|p| (*p, n.dot(*p - *a)))
                    .fold((*a, 0.0), |best, x| if x.1 > best.1 { x } else { best });
                if height > tol {
                    return Err(Error::new(
                        at,
                        ErrorKind::Unsupported {
                            reason: format!(
                                "not convex: vertex ({:.6}, {:.6}, {:.6}) lies {height:.3e} \
                                 outside the plane of a face at ({:.6}, {:.6}, {:.6}); a morphing \
                                 shape must be a union of convex parts that share no vertex \
                                 (split the part into convex ones before importing)",
                                far.x, far.y, far.z, a.x, a.y, a.z
                            ),
                        },
                    ));
                }
            }
            pieces.push(piece);
        }
        if pieces.is_empty() {
            return Err(Error::new(
                "mesh",
                ErrorKind::Unsupported {
                    reason: "no triangles to split into convex parts".into(),
                },
            ));
        }
        Ok(PipShape { pieces })
    }

    /// The union's volume when the pieces' interiors do not overlap (the presets' star): the
    /// sum of the pieces' volumes.
    pub fn volume_of_disjoint_pieces(&self) -> f64 {
        self.pieces.iter().map(ConvexPiece::volume).sum()
    }
}

fn bounds(points: &[DVec3]) -> (DVec3, DVec3) {
    points.iter().fold(
        (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)),
        |(l, h), p| (l.min(*p), h.max(*p)),
    )
}

/// The five-point star prism (its outline as [`Mesh::from_shape`] draws it) as a pentagonal
/// core through the five inner corners and one triangular prism per point.
fn star_pieces(outer: f64, inner: f64, thickness: f64) -> Vec<Vec<DVec3>> {
    let corner = |k: usize| {
        let a = std::f64::consts::FRAC_PI_2 + std::f64::consts::PI * k as f64 / 5.0;
        let r = if k % 2 == 0 { outer } else { inner };
        [r * trig::cos(a), r * trig::sin(a)]
    };
    let prism = |outline: &[[f64; 2]]| -> Vec<DVec3> {
        [-thickness / 2.0, thickness / 2.0]
            .iter()
            .flat_map(|&z| outline.iter().map(move |c| DVec3::new(c[0], c[1], z)))
            .collect()
    };
    let core: Vec<[f64; 2]> = (0..5).map(|k| corner(2 * k + 1)).collect();
    let mut pieces = vec![prism(&core)];
    for k in 0..5 {
        let tip = 2 * k;
        pieces.push(prism(&[
            corner((tip + 9) % 10),
            corner(tip),
            corner(tip + 1),
        ]));
    }
    pieces
}

/// One connected component of a mesh: its (welded) vertices and its triangles' corners.
struct Component {
    points: Vec<DVec3>,
    triangles: Vec<[DVec3; 3]>,
}

/// The connected components of a mesh, vertices welded by position (within
/// `1e-9` of the mesh's size: the same corner written twice with different rounding).
fn components(mesh: &Mesh) -> Vec<Component> {
    let Some((lo, hi)) = mesh.bounds() else {
        return Vec::new();
    };
    let cell = 1e-9 * (hi - lo).length().max(f64::MIN_POSITIVE);
    let mut grid: HashMap<[i64; 3], Vec<usize>> = HashMap::new();
    let mut welded: Vec<DVec3> = Vec::new();
    let id: Vec<usize> = mesh
        .positions
        .iter()
        .map(|p| {
            let c = ((*p - lo) / cell).floor().as_i64vec3().to_array();
            for dx in -1..=1 {
                for dy in -1..=1 {
                    for dz in -1..=1 {
                        if let Some(list) = grid.get(&[c[0] + dx, c[1] + dy, c[2] + dz]) {
                            if let Some(&w) = list.iter().find(|&&w| welded[w].distance(*p) <= cell)
                            {
                                return w;
                            }
                        }
                    }
                }
            }
            welded.push(*p);
            grid.entry(c).or_default().push(welded.len() - 1);
            welded.len() - 1
        })
        .collect();
    let mut parent: Vec<usize> = (0..welded.len()).collect();
    fn root(parent: &mut [usize], mut i: usize) -> usize {
        while parent[i] != i {
            parent[i] = parent[parent[i]];
            i = parent[i];
        }
        i
    }
    let mut used = vec![false; welded.len()];
    for t in mesh.indices.chunks_exact(3) {
        let [a, b, c] = [0, 1, 2].map(|k| id[t[k] as usize]);
        for v in [a, b, c] {
            used[v] = true;
        }
        for v in [b, c] {
            let (ra, rv) = (root(&mut parent, a), root(&mut parent, v));
            parent[rv] = ra;
        }
    }
    let mut index: HashMap<usize, usize> = HashMap::new();
    let mut out: Vec<Component> = Vec::new();
    for v in 0..welded.len() {
        if !used[v] {
            continue;
        }
        let r = root(&mut parent, v);
        let k = *index.entry(r).or_insert_with(|| {
            out.push(Component {
                points: Vec::new(),
                triangles: Vec::new(),
            });
            out.len() - 1
        });
        out[k].points.push(welded[v]);
    }
    for t in mesh.indices.chunks_exact(3) {
        let r = root(&mut parent, id[t[0] as usize]);
        out[index[&r]]
            .triangles
            .push([0, 1, 2].map(|k| welded[id[t[k] as usize]]));
    }
    out
}
