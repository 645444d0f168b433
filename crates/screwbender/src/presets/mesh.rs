//! Triangle meshes of the scene objects ([`Shape`]) and of user OBJ files (f64, no GPU).
//!
//! A [`Mesh`] is an indexed triangle list in the object's local frame, counter-clockwise seen
//! from outside, with one normal per vertex. Flat faces (boxes, prisms, caps) get their own
//! vertices so their normals stay sharp; curved sides share vertices for smooth shading. The
//! playground draws these meshes (converting to `f32` only when it fills GPU buffers), and the
//! glTF export of another part of the project reuses them.

use glam::DVec3;

use crate::error::{Error, ErrorKind};
use crate::presets::{self, Shape};

/// Segments around the circumference of cylinders, cones and spheres.
pub const ROUND_SEGMENTS: u32 = 32;

/// The largest OBJ text [`Mesh::from_obj`] accepts, in bytes (16 MiB).
pub const MAX_OBJ_BYTES: usize = 16 << 20;

/// The most triangles [`Mesh::from_obj`] accepts (the playground draws the mesh up to 10,000
/// times per frame).
pub const MAX_OBJ_TRIANGLES: usize = 200_000;

/// Normals shorter than this (degenerate triangles) are replaced by a fallback direction.
pub const NORMAL_EPSILON: f64 = 1e-12;

/// An indexed triangle mesh with per-vertex normals, in local coordinates.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Mesh {
    /// Vertex positions.
    pub positions: Vec<DVec3>,
    /// Unit vertex normals (same length as `positions`).
    pub normals: Vec<DVec3>,
    /// Triangle vertex indices, three per triangle, counter-clockwise from outside.
    pub indices: Vec<u32>,
}

impl Mesh {
    /// The number of triangles.
    pub fn triangle_count(&self) -> usize {
        self.indices.len() / 3
    }

    /// The axis-aligned bounding box `(min, max)`; `None` for an empty mesh.
    pub fn bounds(&self) -> Option<(DVec3, DVec3)> {
        let first = *self.positions.first()?;
        Some(
            self.positions
                .iter()
                .fold((first, first), |(lo, hi), p| (lo.min(*p), hi.max(*p))),
        )
    }

    /// Appends `other` (indices shifted).
    pub fn append(&mut self, other: &Mesh) {
        let base = self.positions.len() as u32;
        self.positions.extend_from_slice(&other.positions);
        self.normals.extend_from_slice(&other.normals);
        self.indices.extend(other.indices.iter().map(|i| i + base));
    }

    /// The mesh moved by `offset`.
    pub fn translated(mut self, offset: DVec3) -> Mesh {
        for p in &mut self.positions {
            *p += offset;
        }
        self
    }

    /// Adds a flat convex polygon, vertices counter-clockwise seen from the side its normal
    /// points to.
    fn flat_polygon(&mut self, pts: &[DVec3]) {
        let n = face_normal(pts);
        let base = self.positions.len() as u32;
        for p in pts {
            self.positions.push(*p);
            self.normals.push(n);
        }
        for k in 1..pts.len() as u32 - 1 {
            self.indices.extend([base, base + k, base + k + 1]);
        }
    }

    /// A box with the given half extents, centred on the origin.
    pub fn cuboid(half: DVec3) -> Mesh {
        let mut m = Mesh::default();
        let c = |x: f64, y: f64, z: f64| DVec3::new(x * half.x, y * half.y, z * half.z);
        let faces = [
            [
                c(1., -1., -1.),
                c(1., 1., -1.),
                c(1., 1., 1.),
                c(1., -1., 1.),
            ],
            [
                c(-1., 1., -1.),
                c(-1., -1., -1.),
                c(-1., -1., 1.),
                c(-1., 1., 1.),
            ],
            [
                c(1., 1., -1.),
                c(-1., 1., -1.),
                c(-1., 1., 1.),
                c(1., 1., 1.),
            ],
            [
                c(-1., -1., -1.),
                c(1., -1., -1.),
                c(1., -1., 1.),
                c(-1., -1., 1.),
            ],
            [
                c(-1., -1., 1.),
                c(1., -1., 1.),
                c(1., 1., 1.),
                c(-1., 1., 1.),
            ],
            [
                c(-1., 1., -1.),
                c(1., 1., -1.),
                c(1., -1., -1.),
                c(-1., -1., -1.),
            ],
        ];
        for f in &faces {
            m.flat_polygon(f);
        }
        m
    }

    /// A frustum about local z from `z0` (radius `r0`) to `z1` (radius `r1`), with caps;
    /// `r1 = 0` makes a cone, `r0 = r1` a cylinder.
    pub fn frustum(r0: f64, r1: f64, z0: f64, z1: f64, segments: u32) -> Mesh {
        let segments = segments.max(3);
        let mut m = Mesh::default();
        let h = z1 - z0;
        // Side normal: perpendicular to the slanted side line.
        let slope = (r0 - r1) / h;
        for k in 0..=segments {
            let a = std::f64::consts::TAU * k as f64 / segments as f64;
            let (s, c) = a.sin_cos();
            let n = DVec3::new(c, s, slope).normalize();
            m.positions.push(DVec3::new(r0 * c, r0 * s, z0));
            m.normals.push(n);
            m.positions.push(DVec3::new(r1 * c, r1 * s, z1));
            m.normals.push(n);
        }
        for k in 0..segments {
            let b = 2 * k;
            m.indices.extend([b, b + 2, b + 1, b + 1, b + 2, b + 3]);
        }
        let ring = |r: f64, z: f64, reverse: bool| -> Vec<DVec3> {
            let mut v: Vec<DVec3> = (0..segments)
                .map(|k| {
                    let a = std::f64::consts::TAU * k as f64 / segments as f64;
                    DVec3::new(r * a.cos(), r * a.sin(), z)
                })
                .collect();
            if reverse {
                v.reverse();
            }
            v
        };
        if r0 > 0.0 {
            m.flat_polygon(&ring(r0, z0, true));
        }
        if r1 > 0.0 {
            m.flat_polygon(&ring(r1, z1, false));
        }
        m
    }

    /// A UV sphere centred on the origin.
    pub fn sphere(radius: f64, segments: u32) -> Mesh {
        let segments = segments.max(3);
        let rings = (segments / 2).max(2);
        let mut m = Mesh::default();
        for i in 0..=rings {
            let theta = std::f64::consts::PI * i as f64 / rings as f64;
            for k in 0..=segments {
                let phi = std::f64::consts::TAU * k as f64 / segments as f64;
                let n = DVec3::new(
                    theta.sin() * phi.cos(),
                    theta.sin() * phi.sin(),
                    theta.cos(),
                );
                m.positions.push(n * radius);
                m.normals.push(n);
            }
        }
        let row = segments + 1;
        for i in 0..rings {
            for k in 0..segments {
                let a = i * row + k;
                let b = a + row;
                m.indices.extend([a, b, a + 1, a + 1, b, b + 1]);
            }
        }
        m
    }

    /// A prism over a polygon in the xy plane (vertices counter-clockwise), from `z0` to `z1`.
    /// The polygon must be star-shaped about the origin (caps are fans from the centre).
    pub fn prism(outline: &[[f64; 2]], z0: f64, z1: f64) -> Mesh {
        let mut m = Mesh::default();
        let n = outline.len();
        let p = |i: usize, z: f64| DVec3::new(outline[i % n][0], outline[i % n][1], z);
        for i in 0..n {
            m.flat_polygon(&[p(i, z0), p(i + 1, z0), p(i + 1, z1), p(i, z1)]);
        }
        for (z, up) in [(z1, true), (z0, false)] {
            let base = m.positions.len() as u32;
            let normal = if up { DVec3::Z } else { -DVec3::Z };
            m.positions.push(DVec3::new(0.0, 0.0, z));
            m.normals.push(normal);
            for i in 0..n {
                m.positions.push(p(i, z));
                m.normals.push(normal);
            }
            for i in 0..n as u32 {
                let (a, b) = (base + 1 + i, base + 1 + (i + 1) % n as u32);
                if up {
                    m.indices.extend([base, a, b]);
                } else {
                    m.indices.extend([base, b, a]);
                }
            }
        }
        m
    }

    /// The mesh of a scene object, in its local frame (see [`Shape`] for where each origin is).
    pub fn from_shape(shape: &Shape) -> Mesh {
        match *shape {
            Shape::Bar { length, section } => {
                let h = section / 2.0;
                Mesh::cuboid(DVec3::new(length / 2.0, h, h)).translated(DVec3::new(
                    length / 2.0,
                    0.0,
                    0.0,
                ))
            }
            Shape::Block { size, base } => {
                let half = DVec3::from_array(size) / 2.0;
                let m = Mesh::cuboid(half);
                if base {
                    m.translated(DVec3::new(0.0, 0.0, half.z))
                } else {
                    m
                }
            }
            Shape::Cylinder { radius, height } => {
                Mesh::frustum(radius, radius, -height / 2.0, height / 2.0, ROUND_SEGMENTS)
            }
            Shape::Cone { radius, height } => {
                Mesh::frustum(radius, 0.0, -height / 2.0, height / 2.0, ROUND_SEGMENTS)
            }
            Shape::Sphere { radius } => Mesh::sphere(radius, ROUND_SEGMENTS),
            Shape::StarPrism {
                outer,
                inner,
                thickness,
            } => {
                let outline: Vec<[f64; 2]> = (0..10)
                    .map(|k| {
                        let a = std::f64::consts::FRAC_PI_2 + std::f64::consts::PI * k as f64 / 5.0;
                        let r = if k % 2 == 0 { outer } else { inner };
                        [r * a.cos(), r * a.sin()]
                    })
                    .collect();
                Mesh::prism(&outline, -thickness / 2.0, thickness / 2.0)
            }
            Shape::Pendulum { rod, bob } => {
                let mut m = Mesh::sphere(bob, ROUND_SEGMENTS);
                let r = (bob * 0.15).max(1e-3);
                m.append(&Mesh::frustum(r, r, 0.0, rod, 12));
                m.append(&Mesh::sphere(r * 2.0, 12).translated(DVec3::new(0.0, 0.0, rod)));
                m
            }
            Shape::Wedge { size } => {
                // A right-triangle profile in xz (tall at x = 0), extruded along y.
                let [x, y, z] = size;
                let mut m = Mesh::default();
                let (y0, y1) = (-y / 2.0, y / 2.0);
                let a = |yy: f64| DVec3::new(0.0, yy, 0.0);
                let b = |yy: f64| DVec3::new(x, yy, 0.0);
                let c = |yy: f64| DVec3::new(0.0, yy, z);
                m.flat_polygon(&[a(y0), b(y0), c(y0)]);
                m.flat_polygon(&[a(y1), c(y1), b(y1)]);
                m.flat_polygon(&[a(y0), a(y1), b(y1), b(y0)]);
                m.flat_polygon(&[a(y0), c(y0), c(y1), a(y1)]);
                m.flat_polygon(&[b(y0), b(y1), c(y1), c(y0)]);
                m
            }
            Shape::Triangle { x, y, thickness } => {
                let (x, y) = (DVec3::from_array(x), DVec3::from_array(y));
                // Extrude along the plate normal (local z for the B1 triangle).
                let n = x.cross(y).normalize_or_zero() * (thickness / 2.0);
                let mut m = Mesh::default();
                let (a0, b0, c0) = (-n, x - n, y - n);
                let (a1, b1, c1) = (n, x + n, y + n);
                m.flat_polygon(&[a1, b1, c1]);
                m.flat_polygon(&[a0, c0, b0]);
                m.flat_polygon(&[a0, b0, b1, a1]);
                m.flat_polygon(&[b0, c0, c1, b1]);
                m.flat_polygon(&[c0, a0, a1, c1]);
                m
            }
            Shape::IBeam {
                flange,
                web,
                web_section,
            } => {
                let f = DVec3::from_array(flange) / 2.0;
                let offset = DVec3::new(0.0, 0.0, (web + flange[2]) / 2.0);
                let mut m = Mesh::cuboid(DVec3::new(web_section[0], web_section[1], web) / 2.0);
                m.append(&Mesh::cuboid(f).translated(offset));
                m.append(&Mesh::cuboid(f).translated(-offset));
                m
            }
            Shape::Molecule { ring, atom } => {
                let mut m = Mesh::default();
                for k in 0..6 {
                    let a = std::f64::consts::TAU * k as f64 / 6.0;
                    let c = DVec3::new(ring * a.cos(), ring * a.sin(), 0.0);
                    m.append(&Mesh::sphere(atom, 16).translated(c));
                }
                let heavy = DVec3::new(ring * 1.9, 0.0, 0.0);
                m.append(&Mesh::sphere(atom * 2.0, 20).translated(heavy));
                m
            }
        }
    }

    /// Parses a Wavefront OBJ text: `v` and `f` lines (polygons are fanned into triangles,
    /// negative indices count from the end, `v/vt/vn` forms accepted); everything else is
    /// ignored. Normals are recomputed: flat per face (each face gets its own vertices).
    ///
    /// Errors ([`ErrorKind::Parse`] / [`ErrorKind::OutOfRange`], path `obj` or `obj line N`): text over
    /// [`MAX_OBJ_BYTES`], more than [`MAX_OBJ_TRIANGLES`] triangles, malformed or non-finite
    /// numbers, out-of-range indices, no faces.
    pub fn from_obj(text: &str) -> Result<Mesh, Error> {
        if text.len() > MAX_OBJ_BYTES {
            return Err(Error::new(
                "obj",
                ErrorKind::OutOfRange {
                    value: format!("{} bytes", text.len()),
                    expected: format!("at most {MAX_OBJ_BYTES} bytes"),
                },
            ));
        }
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

    /// The mesh scaled and moved so its bounding box is centred on the origin with largest side
    /// `size` (used for imported meshes, whose units are unknown).
    pub fn normalized(mut self, size: f64) -> Mesh {
        if let Some((lo, hi)) = self.bounds() {
            let extent = (hi - lo).max_element();
            let scale = if extent > NORMAL_EPSILON {
                size / extent
            } else {
                1.0
            };
            let centre = (lo + hi) / 2.0;
            for p in &mut self.positions {
                *p = (*p - centre) * scale;
            }
        }
        self
    }
}

/// The unit normal of a planar polygon (Newell's method), `+z` if degenerate.
fn face_normal(pts: &[DVec3]) -> DVec3 {
    let mut n = DVec3::ZERO;
    for (i, a) in pts.iter().enumerate() {
        let b = pts[(i + 1) % pts.len()];
        n += a.cross(b);
    }
    if n.length() > NORMAL_EPSILON {
        n.normalize()
    } else {
        DVec3::Z
    }
}

#[cfg(feature = "gltf")]
/// The largest glTF input [`Mesh::from_gltf`] accepts, in bytes (32 MiB).
pub const MAX_GLTF_MESH_BYTES: usize = 32 << 20;

impl Mesh {
    /// Reads the triangles of every mesh primitive of a glTF 2.0 asset: binary `.glb`, or JSON
    /// `.gltf` whose buffers are embedded as base64 `data:` URIs (external files cannot be
    /// fetched). Uses `POSITION` (float VEC3) and the optional indices (unsigned byte, short or
    /// int); node transforms, materials and non-triangle primitives are ignored. Normals are
    /// recomputed flat, as for [`Mesh::from_obj`].
    ///
    /// Errors ([`ErrorKind::Parse`], path `gltf…`): over [`MAX_GLTF_MESH_BYTES`], more than
    /// [`MAX_OBJ_TRIANGLES`] triangles, malformed JSON or GLB framing, accessors out of their
    /// buffers, non-finite positions, indices out of range, no triangles.
    #[cfg(feature = "gltf")]
    pub fn from_gltf(bytes: &[u8]) -> Result<Mesh, Error> {
        let err = |at: &str, message: String| {
            Error::new(format!("gltf{at}"), ErrorKind::Parse { message })
        };
        if bytes.len() > MAX_GLTF_MESH_BYTES {
            return Err(Error::new(
                "gltf",
                ErrorKind::OutOfRange {
                    value: format!("{} bytes", bytes.len()),
                    expected: format!("at most {MAX_GLTF_MESH_BYTES} bytes"),
                },
            ));
        }
        // GLB framing: header, JSON chunk, optional BIN chunk (shared with the pose importer).
        let (json_bytes, bin): (&[u8], Option<&[u8]>) = if crate::formats::gltf::glb::is_glb(bytes)
        {
            crate::formats::gltf::glb::split_glb(bytes)?
        } else {
            (bytes, None)
        };
        let doc: serde_json::Value = serde_json::from_slice(json_bytes)
            .map_err(|e| err("", format!("invalid JSON: {e}")))?;
        let list = |key: &str| {
            doc.get(key)
                .and_then(|v| v.as_array())
                .cloned()
                .unwrap_or_default()
        };
        let buffers: Vec<Vec<u8>> = list("buffers")
            .iter()
            .enumerate()
            .map(|(i, b)| match b.get("uri").and_then(|u| u.as_str()) {
                None => bin
                    .map(|b| b.to_vec())
                    .ok_or_else(|| err(&format!(".buffers[{i}]"), "no GLB binary chunk".into())),
                Some(uri) => {
                    let data = uri
                        .strip_prefix("data:")
                        .and_then(|u| u.split_once(";base64,"))
                        .map(|(_, d)| d)
                        .ok_or_else(|| {
                            err(
                                &format!(".buffers[{i}].uri"),
                                "only embedded base64 data: URIs are supported (use .glb)".into(),
                            )
                        })?;
                    base64_decode(data)
                        .ok_or_else(|| err(&format!(".buffers[{i}].uri"), "invalid base64".into()))
                }
            })
            .collect::<Result<_, _>>()?;
        let views = list("bufferViews");
        let accessors = list("accessors");
        let num =
            |v: &serde_json::Value, k: &str| v.get(k).and_then(|x| x.as_u64()).map(|x| x as usize);
        // Reads accessor `a` as `comps`-component rows of u32 or f64.
        let read = |a: usize, at: &str| -> Result<(Vec<f64>, usize), Error> {
            let acc = accessors
                .get(a)
                .ok_or_else(|| err(at, format!("accessor {a} missing")))?;
            let count =
                num(acc, "count").ok_or_else(|| err(at, "accessor without count".into()))?;
            let ctype = num(acc, "componentType").unwrap_or(0);
            let comps = match acc.get("type").and_then(|t| t.as_str()) {
                Some("SCALAR") => 1,
                Some("VEC3") => 3,
                t => return Err(err(at, format!("unsupported accessor type {t:?}"))),
            };
            let size = match ctype {
                5121 => 1,
                5123 => 2,
                5125 | 5126 => 4,
                c => return Err(err(at, format!("unsupported component type {c}"))),
            };
            let view = views
                .get(
                    num(acc, "bufferView")
                        .ok_or_else(|| err(at, "sparse or empty accessor".into()))?,
                )
                .ok_or_else(|| err(at, "bufferView missing".into()))?;
            let buffer = buffers
                .get(num(view, "buffer").unwrap_or(usize::MAX))
                .ok_or_else(|| err(at, "buffer missing".into()))?;
            let start = num(view, "byteOffset").unwrap_or(0) + num(acc, "byteOffset").unwrap_or(0);
            let stride = num(view, "byteStride").unwrap_or(size * comps);
            let mut out = Vec::with_capacity(count * comps);
            for i in 0..count {
                for c in 0..comps {
                    let o = start + i * stride + c * size;
                    let b = buffer
                        .get(o..o + size)
                        .ok_or_else(|| err(at, "accessor reads past its buffer".into()))?;
                    out.push(match ctype {
                        5121 => b[0] as f64,
                        5123 => u16::from_le_bytes([b[0], b[1]]) as f64,
                        5125 => u32::from_le_bytes([b[0], b[1], b[2], b[3]]) as f64,
                        _ => f32::from_le_bytes([b[0], b[1], b[2], b[3]]) as f64,
                    });
                }
            }
            Ok((out, count))
        };
        let mut mesh = Mesh::default();
        for (m, me) in list("meshes").iter().enumerate() {
            let prims = me
                .get("primitives")
                .and_then(|p| p.as_array())
                .cloned()
                .unwrap_or_default();
            for (p, prim) in prims.iter().enumerate() {
                let at = format!(".meshes[{m}].primitives[{p}]");
                if num(prim, "mode").unwrap_or(4) != 4 {
                    continue;
                }
                let pos = prim
                    .get("attributes")
                    .and_then(|a| num(a, "POSITION"))
                    .ok_or_else(|| err(&at, "no POSITION attribute".into()))?;
                let (xyz, n) = read(pos, &at)?;
                if xyz.iter().any(|x| !x.is_finite()) {
                    return Err(Error::new(format!("gltf{at}"), ErrorKind::NonFinite));
                }
                let indices: Vec<usize> = match num(prim, "indices") {
                    Some(i) => read(i, &at)?.0.into_iter().map(|x| x as usize).collect(),
                    None => (0..n).collect(),
                };
                if mesh.triangle_count() + indices.len() / 3 > MAX_OBJ_TRIANGLES {
                    return Err(Error::new(
                        "gltf",
                        ErrorKind::OutOfRange {
                            value: "more triangles".into(),
                            expected: format!("at most {MAX_OBJ_TRIANGLES} triangles"),
                        },
                    ));
                }
                for t in indices.chunks_exact(3) {
                    if let Some(&bad) = t.iter().find(|&&i| i >= n) {
                        return Err(err(&at, format!("index {bad} out of range (< {n})")));
                    }
                    let v = |i: usize| DVec3::new(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
                    mesh.flat_polygon(&[v(t[0]), v(t[1]), v(t[2])]);
                }
            }
        }
        if mesh.indices.is_empty() {
            return Err(err("", "no triangles found".into()));
        }
        Ok(mesh)
    }
}

/// Decodes standard base64 (padding optional); `None` on an invalid character.
#[cfg(feature = "gltf")]
fn base64_decode(text: &str) -> Option<Vec<u8>> {
    let mut out = Vec::with_capacity(text.len() * 3 / 4);
    let (mut acc, mut bits) = (0u32, 0u32);
    for c in text.bytes() {
        let v = match c {
            b'A'..=b'Z' => c - b'A',
            b'a'..=b'z' => c - b'a' + 26,
            b'0'..=b'9' => c - b'0' + 52,
            b'+' | b'-' => 62,
            b'/' | b'_' => 63,
            b'=' | b'\n' | b'\r' => continue,
            _ => return None,
        } as u32;
        acc = (acc << 6) | v;
        bits += 6;
        if bits >= 8 {
            bits -= 8;
            out.push((acc >> bits) as u8);
            acc &= (1 << bits) - 1;
        }
    }
    Some(out)
}

/// The side of the cube the Stanford bunny is scaled to fit (`Mesh::bunny`, feature `bunny`), as the page
/// shows it for preset `bunny6`.
pub const BUNNY_SIZE: f64 = 1.2;

/// The preset whose object is the paper's bunny (a wedge stands in without the `bunny` feature).
pub const BUNNY_PRESET: &str = "bunny6";

impl Mesh {
    /// The Stanford bunny (feature `bunny`; origin and terms in the crate's
    /// `assets/bunny.NOTICE`): 3,674 triangles, z up, centred, fitting a cube of side
    /// [`BUNNY_SIZE`].
    #[cfg(feature = "bunny")]
    pub fn bunny() -> Mesh {
        Mesh::from_obj(include_str!("../../assets/bunny.obj"))
            .expect("the bundled bunny parses")
            .normalized(BUNNY_SIZE)
    }

    /// The object of a preset: its [`Shape`]'s mesh, or for [`BUNNY_PRESET`] the Stanford bunny
    /// when the crate is built with the `bunny` feature.
    pub fn for_preset(scene: &presets::Preset) -> Mesh {
        #[cfg(feature = "bunny")]
        if scene.id == BUNNY_PRESET {
            return Mesh::bunny();
        }
        Mesh::from_shape(&scene.shape)
    }

    /// The mesh for a name: a named object ([`crate::presets::object_shape`]), a scene's own
    /// object (`scene:<id>`), the `k`-th morph shape of a scene (`morph:<id>:<k>`), or the
    /// gizmo parts `unit-sphere` / `unit-cone` (radius 1, cone apex at `z = +1`, base at
    /// `z = 0`). Unknown names are an [`ErrorKind::UnknownValue`] at `mesh`.
    pub fn named(name: &str) -> Result<Mesh, Error> {
        if let Some(shape) = presets::object_shape(name) {
            return Ok(Mesh::from_shape(&shape));
        }
        let unknown = || {
            Error::new(
                "mesh",
                ErrorKind::UnknownValue {
                    value: name.into(),
                    expected:
                        "an object name, scene:<id>, morph:<id>:<k>, unit-sphere or unit-cone",
                },
            )
        };
        match name {
            "unit-sphere" => return Ok(Mesh::sphere(1.0, ROUND_SEGMENTS)),
            "unit-cone" => return Ok(Mesh::frustum(1.0, 0.0, 0.0, 1.0, ROUND_SEGMENTS)),
            _ => {}
        }
        let mut parts = name.split(':');
        let scene = |id: Option<&str>| id.and_then(presets::preset).ok_or_else(unknown);
        match parts.next() {
            Some("scene") => Ok(Mesh::from_shape(&scene(parts.next())?.shape)),
            Some("morph") => {
                let s = scene(parts.next())?;
                let k: usize = parts
                    .next()
                    .and_then(|k| k.parse().ok())
                    .ok_or_else(unknown)?;
                s.morph_shapes
                    .get(k)
                    .map(Mesh::from_shape)
                    .ok_or_else(unknown)
            }
            _ => Err(unknown()),
        }
    }
}
