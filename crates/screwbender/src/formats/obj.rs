//! Wavefront OBJ text into a [`Mesh`]: the user's own objects and the bundled bunny.

use glam::DVec3;

use crate::error::{Error, ErrorKind};
use crate::presets::mesh::Mesh;

/// The largest OBJ text [`Mesh::from_obj`] accepts, in bytes (16 MiB).
pub const MAX_OBJ_BYTES: usize = 16 << 20;

/// The most triangles [`Mesh::from_obj`] (and [`Mesh::from_gltf`]) accepts (the playground
/// draws the mesh up to 10,000 times per frame).
pub const MAX_OBJ_TRIANGLES: usize = 200_000;

impl Mesh {
    /// Parses a Wavefront OBJ text: `v` and `f` lines (polygons are fanned into triangles,
    /// negative indices count from the end, `v/vt/vn` forms accepted); everything else is
    /// ignored. Normals are recomputed: flat per face (each face gets its own vertices).
    ///
    /// Errors ([`ErrorKind::Parse`] / [`ErrorKind::OutOfRange`], path `obj` or `obj line N`): text over
    /// [`MAX_OBJ_BYTES`], more than [`MAX_OBJ_TRIANGLES`] triangles, malformed or non-finite
    /// numbers, out-of-range indices, no faces.
    pub fn from_obj(text: &str) -> Result<Mesh, Error> {
        crate::error::check_size(text.len(), MAX_OBJ_BYTES, "obj")?;
        let parse_err = |line: usize, message: String| {
            Error::new(format!("obj line {line}"), ErrorKind::Parse { message })
        };
        let mut verts: Vec<DVec3> = Vec::new();
        let mut mesh = Mesh::default();
        for (no, raw) in text.lines().enumerate() {
            let line = no + 1;
            let mut words = raw.split_whitespace();
            match words.next() {
                Some("v") => {
                    let mut c = [0.0; 3];
                    for slot in &mut c {
                        let w = words
                            .next()
                            .ok_or_else(|| parse_err(line, "vertex needs 3 coordinates".into()))?;
                        *slot = w
                            .parse::<f64>()
                            .map_err(|e| parse_err(line, format!("bad number {w:?}: {e}")))?;
                        if !slot.is_finite() {
                            return Err(Error::new(
                                format!("obj line {line}"),
                                ErrorKind::NonFinite,
                            ));
                        }
                    }
                    verts.push(DVec3::from_array(c));
                }
                Some("f") => {
                    let mut face = Vec::new();
                    for w in words {
                        let first = w.split('/').next().unwrap_or("");
                        let i: i64 = first
                            .parse()
                            .map_err(|e| parse_err(line, format!("bad index {w:?}: {e}")))?;
                        let n = verts.len() as i64;
                        let k = if i < 0 { n + i } else { i - 1 };
                        if i == 0 || k < 0 || k >= n {
                            return Err(parse_err(
                                line,
                                format!("vertex index {i} out of range (1..={n} or negative)"),
                            ));
                        }
                        face.push(verts[k as usize]);
                    }
                    if face.len() < 3 {
                        return Err(parse_err(line, "a face needs at least 3 vertices".into()));
                    }
                    if mesh.triangle_count() + face.len() - 2 > MAX_OBJ_TRIANGLES {
                        return Err(Error::new(
                            "obj",
                            ErrorKind::OutOfRange {
                                value: "more triangles".into(),
                                expected: format!("at most {MAX_OBJ_TRIANGLES} triangles"),
                            },
                        ));
                    }
                    mesh.flat_polygon(&face);
                }
                _ => {}
            }
        }
        if mesh.indices.is_empty() {
            return Err(Error::new(
                "obj",
                ErrorKind::Parse {
                    message: "no faces (`f` lines) found".into(),
                },
            ));
        }
        Ok(mesh)
    }
}
