//! Triangle meshes of the scene objects ([`Shape`]) (f64, no GPU). User files become meshes in
//! `formats` ([`Mesh::from_obj`], and [`Mesh::from_gltf`] with the feature `json`).
//!
//! A [`Mesh`] is an indexed triangle list in the object's local frame, counter-clockwise seen
//! from outside, with one normal per vertex. Flat faces (boxes, prisms, caps) get their own
//! vertices so their normals stay sharp; curved sides share vertices for smooth shading. The
//! playground draws these meshes (converting to `f32` only when it fills GPU buffers), and the
//! glTF export of another part of the project reuses them.

use glam::DVec3;

use crate::error::{Error, ErrorKind};
use crate::presets::{self, trig, Shape};

/// Segments around the circumference of cylinders, cones and spheres.
pub const ROUND_SEGMENTS: u32 = 32;

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
    pub(crate) fn flat_polygon(&mut self, pts: &[DVec3]) {
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
            let (s, c) = trig::sin_cos(a);
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
                    DVec3::new(r * trig::cos(a), r * trig::sin(a), z)
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
                    trig::sin(theta) * trig::cos(phi),
                    trig::sin(theta) * trig::sin(phi),
                    trig::cos(theta),
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
                        [r * trig::cos(a), r * trig::sin(a)]
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
                    let c = DVec3::new(ring * trig::cos(a), ring * trig::sin(a), 0.0);
                    m.append(&Mesh::sphere(atom, 16).translated(c));
                }
                let heavy = DVec3::new(ring * 1.9, 0.0, 0.0);
                m.append(&Mesh::sphere(atom * 2.0, 20).translated(heavy));
                m
            }
        }
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
        Mesh::bunny_from_obj(include_str!("../../assets/bunny.obj"))
            .expect("the bundled bunny parses")
    }

    /// The Stanford bunny from the OBJ text of `assets/bunny.obj`, scaled as `Mesh::bunny`
    /// scales the compiled-in copy: builds without the `bunny` feature (the page's wasm, which
    /// fetches the file instead of carrying it) make the very same mesh from the same text.
    /// Errors: those of [`Mesh::from_obj`].
    pub fn bunny_from_obj(text: &str) -> Result<Mesh, Error> {
        Ok(Mesh::from_obj(text)?.normalized(BUNNY_SIZE))
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
