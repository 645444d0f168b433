//! glTF 2.0 export of a sampled motion (`.glb`, or `.gltf` + `.bin`), with the document model of
//! the `gltf-json` crate.
//!
//! The asset holds:
//!
//! * node 0, [`OBJECT_NODE_NAME`] (or the motion's name): the object's mesh (positions, normals,
//!   `u32` indices), animated by animation 0 — `LINEAR` translation and rotation samplers sharing
//!   one time accessor (seconds, with `min`/`max`); rotations are `x, y, z, w` as glTF requires,
//!   with signs made consistent from sample to sample (a sample whose dot with the previous one is
//!   negative is negated);
//! * node 1, [`CONTROL_NODE_NAME`]: an empty node animated by animation 1, whose keyframes are
//!   exactly the control poses at their knot times (a cycle repeats pose 0 at the end) — this is
//!   what [`crate::import_gltf`] reads back by default;
//! * optionally one empty node per control pose (`control pose i`), placed at the pose;
//! * for a morphing object ([`GltfMotion::morph`], scene A8) the object node has no mesh of its
//!   own but one child per span of the morph (`<name> span i`), whose mesh is the PIP morph's
//!   pieces of that span at blend 0 with one morph target, the displacement to blend 1 (every
//!   pair of pieces keeps its triangles across the span, so the blend is exactly a morph
//!   target's weight). Animation 0 then also keys each child's `weights` (`LINEAR`, the blend
//!   at every sample and control time: exact there) and its `scale` (`STEP`, 1 during its span
//!   and 0 elsewhere), so a player shows one span at a time and the object is each control
//!   pose's shape at that pose's time.
//!
//! Both animations carry `extras.screwbender = {"loop": closed, "closed": closed, …}` (a cycle
//! loops); the control poses' also carries the key velocities (`velocities`) when any is
//! given. Times start at 0: the first knot time is subtracted (and noted as `timeOffset`).
//! Values are stored as `f32` (rounding about `6e-8 |x|`).

use std::collections::BTreeMap;

use gltf_json as json;
use json::validation::{Checked::Valid, USize64};
use serde_json::json as js;

use super::names::{CONTROL_NODE_NAME, EXTRAS_KEY};
use crate::error::{Error, ErrorKind};
use crate::formats::sampling::Sample;
use crate::formats::tracks::consistent_rotations;
use crate::pose::Pose;
use crate::presets::mesh::Mesh;
use crate::presets::morph::{BlendMesh, PipMorph};

/// Default name of the animated object node.
pub const OBJECT_NODE_NAME: &str = "object";

/// The generator string written to `asset.generator`.
pub const GENERATOR: &str = concat!("screwbender ", env!("CARGO_PKG_VERSION"));

/// Half extents of the placeholder box used when no mesh is given.
pub const PLACEHOLDER_HALF_EXTENTS: [f64; 3] = [0.5, 0.25, 0.125];

/// GLB magic `glTF`, version 2 and chunk types.
const GLB_MAGIC: u32 = 0x4654_6C67;
const GLB_VERSION: u32 = 2;
const GLB_CHUNK_JSON: u32 = 0x4E4F_534A;
const GLB_CHUNK_BIN: u32 = 0x004E_4942;

/// What to export.
#[derive(Clone, Copy, Debug)]
pub struct GltfMotion<'a> {
    /// Display name (used for the object node, the animation and the mesh).
    pub name: Option<&'a str>,
    /// The keyframes of the object (see [`crate::sample_polyscrew`]); at least 2, times
    /// increasing.
    pub samples: &'a [Sample],
    /// The control poses.
    pub control: &'a [Pose],
    /// The knot times of the control poses (`n + 1` for a cycle: the last is pose 0 again).
    pub control_times: &'a [f64],
    /// The key velocities of the control poses (one per pose, `None` where free; `None` when all
    /// are free), recorded in the control animation's `extras` so that import restores them:
    /// glTF keyframes carry the key times but not the retiming's slopes.
    pub control_velocities: Option<&'a [Option<f64>]>,
    /// Whether the motion is a cycle (the animations loop).
    pub closed: bool,
    /// The object's mesh; `None` draws a placeholder box ([`PLACEHOLDER_HALF_EXTENTS`]).
    pub mesh: Option<&'a Mesh>,
    /// A morphing object (one shape per control pose), which replaces `mesh`: see the module
    /// docs. Its shape count must equal the control poses'.
    pub morph: Option<&'a PipMorph>,
    /// The tolerance the samples were made for, recorded in `extras` (`None` for fixed-rate).
    pub tolerance: Option<f64>,
    /// Also add one empty node per control pose.
    pub control_nodes: bool,
}

/// A built glTF asset: the JSON document model and its binary buffer.
#[derive(Clone, Debug)]
pub struct GltfAsset {
    root: json::Root,
    bin: Vec<u8>,
}

/// Appends `data` to the buffer as one 4-byte-aligned buffer view and one `FLOAT`/`UNSIGNED_INT`
/// accessor.
struct Builder {
    root: json::Root,
    bin: Vec<u8>,
}

enum Data<'a> {
    F32(&'a [f32]),
    U32(&'a [u32]),
}

impl Builder {
    fn accessor(
        &mut self,
        data: Data,
        type_: json::accessor::Type,
        target: Option<json::buffer::Target>,
        with_bounds: bool,
    ) -> json::Index<json::Accessor> {
        let width = type_.multiplicity();
        while self.bin.len() % 4 != 0 {
            self.bin.push(0);
        }
        let offset = self.bin.len();
        let (count, component, min, max) = match data {
            Data::F32(v) => {
                for x in v {
                    self.bin.extend_from_slice(&x.to_le_bytes());
                }
                let (min, max) = if with_bounds {
                    let mut lo = vec![f32::INFINITY; width];
                    let mut hi = vec![f32::NEG_INFINITY; width];
                    for (i, x) in v.iter().enumerate() {
                        lo[i % width] = lo[i % width].min(*x);
                        hi[i % width] = hi[i % width].max(*x);
                    }
                    (Some(js!(lo)), Some(js!(hi)))
                } else {
                    (None, None)
                };
                (
                    v.len() / width,
                    json::accessor::ComponentType::F32,
                    min,
                    max,
                )
            }
            Data::U32(v) => {
                for x in v {
                    self.bin.extend_from_slice(&x.to_le_bytes());
                }
                (v.len(), json::accessor::ComponentType::U32, None, None)
            }
        };
        let view = self.root.push(json::buffer::View {
            buffer: json::Index::new(0),
            byte_length: USize64::from(self.bin.len() - offset),
            byte_offset: Some(USize64::from(offset)),
            byte_stride: None,
            name: None,
            target: target.map(Valid),
            extensions: None,
            extras: None,
        });
        self.root.push(json::Accessor {
            buffer_view: Some(view),
            byte_offset: None,
            count: USize64::from(count),
            component_type: Valid(json::accessor::GenericComponentType(component)),
            extensions: None,
            extras: None,
            type_: Valid(type_),
            min,
            max,
            name: None,
            normalized: false,
            sparse: None,
        })
    }

    /// A mesh of one primitive: positions (with bounds), normals, `u32` indices.
    fn mesh(&mut self, name: &str, mesh: &Mesh) -> json::Index<json::Mesh> {
        let normals: Vec<glam::DVec3> = mesh
            .normals
            .iter()
            .map(|n| n.normalize_or(glam::DVec3::Z))
            .collect();
        self.primitive_mesh(
            name,
            &f32s(&mesh.positions),
            &f32s(&normals),
            Some(&mesh.indices),
            None,
        )
    }

    /// The pieces of one morph span as one mesh at blend 0 (no indices: every triangle has its
    /// own corners) with one morph target, the displacement to blend 1.
    fn blend_mesh(&mut self, name: &str, parts: &[BlendMesh]) -> json::Index<json::Mesh> {
        let (mut from, mut to, mut normals) = (Vec::new(), Vec::new(), Vec::new());
        for p in parts {
            from.extend_from_slice(&p.from);
            to.extend_from_slice(&p.to);
            normals.extend_from_slice(&p.normals);
        }
        let base = f32s(&from);
        // The target's displacement in f32, so that base + displacement is the end position
        // as closely as f32 allows.
        let delta: Vec<f32> = f32s(&to).iter().zip(&base).map(|(e, b)| e - b).collect();
        self.primitive_mesh(name, &base, &f32s(&normals), None, Some(&delta))
    }

    /// A mesh of one triangle primitive from `f32` triples, with optional indices and one
    /// optional morph target of position displacements (its weight starts at 0).
    fn primitive_mesh(
        &mut self,
        name: &str,
        positions: &[f32],
        normals: &[f32],
        indices: Option<&[u32]>,
        target: Option<&[f32]>,
    ) -> json::Index<json::Mesh> {
        use json::accessor::Type;
        use json::buffer::Target;
        let vec3 = |b: &mut Self, data: &[f32], bounds: bool| {
            b.accessor(
                Data::F32(data),
                Type::Vec3,
                Some(Target::ArrayBuffer),
                bounds,
            )
        };
        let pos = vec3(self, positions, true);
        let nor = vec3(self, normals, false);
        let target = target.map(|t| json::mesh::MorphTarget {
            positions: Some(vec3(self, t, true)),
            normals: None,
            tangents: None,
        });
        let indices = indices.map(|i| {
            self.accessor(
                Data::U32(i),
                Type::Scalar,
                Some(Target::ElementArrayBuffer),
                false,
            )
        });
        let mut attributes = BTreeMap::new();
        attributes.insert(Valid(json::mesh::Semantic::Positions), pos);
        attributes.insert(Valid(json::mesh::Semantic::Normals), nor);
        let morphing = target.is_some();
        self.root.push(json::Mesh {
            extensions: None,
            extras: if morphing {
                raw(&js!({ "targetNames": ["blend"] })).ok()
            } else {
                None
            },
            name: Some(name.to_string()),
            primitives: vec![json::mesh::Primitive {
                attributes,
                extensions: None,
                extras: None,
                indices,
                material: None,
                mode: Valid(json::mesh::Mode::Triangles),
                targets: target.map(|t| vec![t]),
            }],
            weights: morphing.then(|| vec![0.0]),
        })
    }

    /// Adds to animation `anim` the morph's channels on the span nodes: `weights` (`LINEAR`,
    /// the span's blend at each key) and `scale` (`STEP`: 1 while its span plays, else 0).
    fn morph_channels(
        &mut self,
        anim: json::Index<json::Animation>,
        spans: &[json::Index<json::Node>],
        keys: &[(f64, f64)],
        morph: &PipMorph,
    ) -> Result<(), Error> {
        use json::animation::{Channel, Interpolation, Property, Sampler, Target};
        let times: Vec<f32> = keys.iter().map(|k| k.0 as f32).collect();
        let input = self.accessor(Data::F32(&times), json::accessor::Type::Scalar, None, true);
        let mut blends = Vec::with_capacity(keys.len());
        for (t, u) in keys {
            blends.push(
                morph
                    .blend_at(*u)
                    .map_err(|e| e.within(&format!("morph key at time {t}")))?,
            );
        }
        for (i, node) in spans.iter().enumerate() {
            // The visible span at a key and its blend there; a span's blend is 0 before it and
            // 1 after it, so that a player interpolating across a switch stays on the shape.
            let weights: Vec<f32> = keys
                .iter()
                .zip(&blends)
                .map(|((_, u), b)| match b {
                    Some((j, s)) if *j == i => *s as f32,
                    _ if *u < i as f64 => 0.0,
                    _ => 1.0,
                })
                .collect();
            let scales: Vec<f32> = blends
                .iter()
                .flat_map(|b| {
                    let on = b.is_none_or(|(j, _)| j == i);
                    [if on { 1.0 } else { 0.0 }; 3]
                })
                .collect();
            let w_out = self.accessor(
                Data::F32(&weights),
                json::accessor::Type::Scalar,
                None,
                false,
            );
            let s_out = self.accessor(Data::F32(&scales), json::accessor::Type::Vec3, None, false);
            let a = &mut self.root.animations[anim.value()];
            for (out, path, interpolation) in [
                (w_out, Property::MorphTargetWeights, Interpolation::Linear),
                (s_out, Property::Scale, Interpolation::Step),
            ] {
                a.channels.push(Channel {
                    sampler: json::Index::new(a.samplers.len() as u32),
                    target: Target {
                        extensions: None,
                        extras: None,
                        node: *node,
                        path: Valid(path),
                    },
                    extensions: None,
                    extras: None,
                });
                a.samplers.push(Sampler {
                    extensions: None,
                    extras: None,
                    input,
                    interpolation: Valid(interpolation),
                    output: out,
                });
            }
        }
        Ok(())
    }

    /// A `LINEAR` translation + rotation animation of `node` through `poses` at `times`.
    fn animation(
        &mut self,
        name: &str,
        node: json::Index<json::Node>,
        times: &[f64],
        poses: &[Pose],
        extras: serde_json::Value,
    ) -> Result<json::Index<json::Animation>, Error> {
        use json::animation::{Channel, Interpolation, Property, Sampler, Target};
        let times32: Vec<f32> = times.iter().map(|&t| t as f32).collect();
        let translations: Vec<f32> = poses
            .iter()
            .flat_map(|p| p.origin.to_array().map(|x| x as f32))
            .collect();
        let rotations: Vec<f32> = consistent_rotations(poses).into_iter().flatten().collect();
        let input = self.accessor(
            Data::F32(&times32),
            json::accessor::Type::Scalar,
            None,
            true,
        );
        let t_out = self.accessor(
            Data::F32(&translations),
            json::accessor::Type::Vec3,
            None,
            false,
        );
        let r_out = self.accessor(
            Data::F32(&rotations),
            json::accessor::Type::Vec4,
            None,
            false,
        );
        let sampler = |output| Sampler {
            extensions: None,
            extras: None,
            input,
            interpolation: Valid(Interpolation::Linear),
            output,
        };
        let channel = |i: u32, path| Channel {
            sampler: json::Index::new(i),
            target: Target {
                extensions: None,
                extras: None,
                node,
                path: Valid(path),
            },
            extensions: None,
            extras: None,
        };
        let animation = json::Animation {
            extensions: None,
            extras: Some(raw(&js!({ EXTRAS_KEY: extras }))?),
            channels: vec![
                channel(0, Property::Translation),
                channel(1, Property::Rotation),
            ],
            name: Some(name.to_string()),
            samplers: vec![sampler(t_out), sampler(r_out)],
        };
        Ok(self.root.push(animation))
    }
}

/// Vectors as `f32` triples.
fn f32s(v: &[glam::DVec3]) -> Vec<f32> {
    v.iter()
        .flat_map(|p| p.to_array().map(|x| x as f32))
        .collect()
}

/// The morph's keys: every sample's `(time, u)` and every control time's `(time, i)`, sorted,
/// one per `f32` time (a control time that a sample already has is kept once, as its knot).
fn merge_keys(samples: &[(f64, f64)], knots: &[(f64, f64)]) -> Vec<(f64, f64)> {
    let mut all: Vec<(f64, f64, bool)> = samples
        .iter()
        .map(|&(t, u)| (t, u, false))
        .chain(knots.iter().map(|&(t, u)| (t, u, true)))
        .collect();
    all.sort_by(|a, b| a.0.total_cmp(&b.0).then(b.2.cmp(&a.2)));
    let mut out: Vec<(f64, f64)> = Vec::with_capacity(all.len());
    for (t, u, _) in all {
        if out.last().is_none_or(|l| (l.0 as f32) < (t as f32)) {
            out.push((t, u));
        }
    }
    out
}

fn raw(v: &serde_json::Value) -> Result<Box<serde_json::value::RawValue>, Error> {
    serde_json::value::to_raw_value(v).map_err(|e| {
        Error::new(
            "extras",
            ErrorKind::Parse {
                message: e.to_string(),
            },
        )
    })
}

fn node_trs(name: String, pose: &Pose, mesh: Option<json::Index<json::Mesh>>) -> json::Node {
    let q = pose.rotation.normalize();
    json::Node {
        mesh,
        name: Some(name),
        translation: Some(pose.origin.to_array().map(|x| x as f32)),
        rotation: Some(json::scene::UnitQuaternion([
            q.x as f32, q.y as f32, q.z as f32, q.w as f32,
        ])),
        ..Default::default()
    }
}

impl GltfAsset {
    /// Builds the asset (see the module docs for its layout).
    ///
    /// Errors: fewer than 2 samples or times that do not strictly increase once stored as `f32`
    /// (`samples[i]`), control times that do not match the control poses (`times`).
    pub fn new(m: &GltfMotion) -> Result<GltfAsset, Error> {
        if m.samples.len() < 2 {
            return Err(Error::new(
                "samples",
                ErrorKind::TooFewPoses {
                    found: m.samples.len(),
                    min: 2,
                },
            ));
        }
        let expected = m.control.len() + usize::from(m.closed);
        if m.control_times.len() != expected || m.control.len() < 2 {
            return Err(Error::new(
                "times",
                ErrorKind::OutOfRange {
                    value: format!("{} times", m.control_times.len()),
                    expected: format!("{expected} times"),
                },
            ));
        }
        if let Some(v) = m.control_velocities {
            if v.len() != m.control.len() || v.iter().flatten().any(|v| !v.is_finite()) {
                return Err(Error::new(
                    "velocities",
                    ErrorKind::OutOfRange {
                        value: format!("{} velocities", v.len()),
                        expected: format!("{} finite velocities or nulls", m.control.len()),
                    },
                ));
            }
        }
        let offset = m.control_times[0];
        let times: Vec<f64> = m.samples.iter().map(|s| s.time - offset).collect();
        for (i, w) in times.windows(2).enumerate() {
            if (w[1] as f32) <= (w[0] as f32) || !w[1].is_finite() {
                return Err(Error::new(
                    format!("samples[{}]", i + 1),
                    ErrorKind::OutOfRange {
                        value: format!("time {}", w[1]),
                        expected: "times strictly increasing in f32 (samples too dense)".into(),
                    },
                ));
            }
        }
        // The object node must not take the control node's name (import looks for it).
        let name = match m.name {
            None | Some(CONTROL_NODE_NAME) => OBJECT_NODE_NAME,
            Some(name) => name,
        }
        .to_string();
        let mut b = Builder {
            root: json::Root {
                asset: json::Asset {
                    copyright: None,
                    extensions: None,
                    extras: None,
                    generator: Some(GENERATOR.to_string()),
                    min_version: None,
                    version: "2.0".to_string(),
                },
                ..Default::default()
            },
            bin: Vec::new(),
        };

        if let Some(morph) = m.morph {
            if morph.shape_count() != m.control.len() || morph.closed() != m.closed {
                return Err(Error::new(
                    "morph",
                    ErrorKind::OutOfRange {
                        value: format!("{} shapes", morph.shape_count()),
                        expected: format!(
                            "one shape per control pose ({}) and the motion's closure",
                            m.control.len()
                        ),
                    },
                ));
            }
        }
        // The mesh (a morphing object's meshes hang below its node).
        let placeholder;
        let mesh = match m.mesh {
            Some(mesh) => mesh,
            None => {
                placeholder = Mesh::cuboid(glam::DVec3::from_array(PLACEHOLDER_HALF_EXTENTS));
                &placeholder
            }
        };
        let mesh_index = match m.morph {
            Some(_) => None,
            None => Some(b.mesh(&name, mesh)),
        };

        // The nodes.
        let poses: Vec<Pose> = m.samples.iter().map(|s| s.pose).collect();
        let object = b.root.push(node_trs(name.clone(), &poses[0], mesh_index));
        let spans: Vec<json::Index<json::Node>> = match m.morph {
            None => Vec::new(),
            Some(morph) => {
                let parts: Vec<&[BlendMesh]> = if morph.span_count() == 0 {
                    vec![morph.shape(0)]
                } else {
                    (0..morph.span_count()).map(|i| morph.span(i)).collect()
                };
                let nodes: Vec<_> = parts
                    .iter()
                    .enumerate()
                    .map(|(i, part)| {
                        let span_name = format!("{name} span {i}");
                        let mesh = b.blend_mesh(&span_name, part);
                        b.root.push(json::Node {
                            mesh: Some(mesh),
                            name: Some(span_name),
                            ..Default::default()
                        })
                    })
                    .collect();
                b.root.nodes[object.value()].children = Some(nodes.clone());
                nodes
            }
        };
        let control_node = b
            .root
            .push(node_trs(CONTROL_NODE_NAME.into(), &m.control[0], None));
        let mut scene_nodes = vec![object, control_node];
        if m.control_nodes {
            for (i, p) in m.control.iter().enumerate() {
                scene_nodes.push(b.root.push(node_trs(format!("control pose {i}"), p, None)));
            }
        }
        let scene = b.root.push(json::Scene {
            extensions: None,
            extras: None,
            name: Some(name.clone()),
            nodes: scene_nodes,
        });
        b.root.scene = Some(scene);

        // The animations.
        let common = js!({
            "loop": m.closed,
            "closed": m.closed,
            "timeOffset": offset,
        });
        let mut object_extras = common.clone();
        object_extras["samples"] = js!(m.samples.len());
        if let Some(t) = m.tolerance {
            object_extras["tolerance"] = js!(t);
        }
        let anim = b.animation(&name, object, &times, &poses, object_extras)?;
        if let Some(morph) = m.morph {
            let knots: Vec<(f64, f64)> = m
                .control_times
                .iter()
                .enumerate()
                .map(|(i, t)| (t - offset, i as f64))
                .collect();
            let keys: Vec<(f64, f64)> = m.samples.iter().map(|s| (s.time - offset, s.u)).collect();
            b.morph_channels(anim, &spans, &merge_keys(&keys, &knots), morph)?;
        }
        let mut control_poses = m.control.to_vec();
        if m.closed {
            control_poses.push(m.control[0]);
        }
        let control_times: Vec<f64> = m.control_times.iter().map(|t| t - offset).collect();
        let mut control_extras = common;
        if let Some(v) = m.control_velocities {
            control_extras["velocities"] = js!(v);
        }
        b.animation(
            CONTROL_NODE_NAME,
            control_node,
            &control_times,
            &control_poses,
            control_extras,
        )?;

        while b.bin.len() % 4 != 0 {
            b.bin.push(0);
        }
        b.root.buffers.push(json::Buffer {
            byte_length: USize64::from(b.bin.len()),
            name: None,
            uri: None,
            extensions: None,
            extras: None,
        });
        Ok(GltfAsset {
            root: b.root,
            bin: b.bin,
        })
    }

    /// The JSON document model.
    pub fn root(&self) -> &json::Root {
        &self.root
    }

    /// The binary buffer (buffer 0).
    pub fn bin(&self) -> &[u8] {
        &self.bin
    }

    /// Number of keyframes of the object's animation.
    pub fn sample_count(&self) -> usize {
        self.root
            .animations
            .first()
            .and_then(|a| a.samplers.first())
            .and_then(|s| self.root.accessors.get(s.input.value()))
            .map_or(0, |a| a.count.0 as usize)
    }

    /// The binary `.glb` file: JSON chunk (space-padded) and BIN chunk (zero-padded).
    pub fn to_glb(&self) -> Vec<u8> {
        let mut text = self.root.to_vec().expect("the document model serializes");
        while text.len() % 4 != 0 {
            text.push(b' ');
        }
        let total = 12 + 8 + text.len() + 8 + self.bin.len();
        let mut out = Vec::with_capacity(total);
        for word in [GLB_MAGIC, GLB_VERSION, total as u32] {
            out.extend_from_slice(&word.to_le_bytes());
        }
        out.extend_from_slice(&(text.len() as u32).to_le_bytes());
        out.extend_from_slice(&GLB_CHUNK_JSON.to_le_bytes());
        out.extend_from_slice(&text);
        out.extend_from_slice(&(self.bin.len() as u32).to_le_bytes());
        out.extend_from_slice(&GLB_CHUNK_BIN.to_le_bytes());
        out.extend_from_slice(&self.bin);
        out
    }

    /// The `.gltf` JSON text (pretty-printed), whose buffer 0 refers to `bin_uri` (e.g.
    /// `motion.bin`, relative to the `.gltf` file); write [`GltfAsset::bin`] there.
    pub fn to_gltf(&self, bin_uri: &str) -> String {
        let mut root = self.root.clone();
        root.buffers[0].uri = Some(uri_escape(bin_uri));
        root.to_string_pretty()
            .expect("the document model serializes")
            + "\n"
    }
}

/// Percent-encodes the characters of a file name that a URI reference may not contain.
fn uri_escape(name: &str) -> String {
    let mut s = String::new();
    for b in name.bytes() {
        if b.is_ascii_alphanumeric() || b"-._~/".contains(&b) {
            s.push(b as char);
        } else {
            s += &format!("%{b:02X}");
        }
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{sample_polyscrew, Polyscrew, Timing};

    #[test]
    fn glb_has_header_chunks_and_aligned_lengths() {
        let poses = vec![
            Pose::IDENTITY,
            Pose::from_axis_angle(glam::DVec3::Z, 1.0),
            Pose::from_translation(glam::DVec3::X),
        ];
        let p = Polyscrew::new(poses.clone(), true).unwrap();
        let timing = Timing::uniform(3, true);
        let samples = sample_polyscrew(&p, 3, &timing, 1e-3).unwrap();
        let asset = GltfAsset::new(&GltfMotion {
            name: None,
            samples: &samples,
            control: &poses,
            control_times: timing.knots(),
            control_velocities: None,
            closed: true,
            mesh: None,
            morph: None,
            tolerance: Some(1e-3),
            control_nodes: true,
        })
        .unwrap();
        let glb = asset.to_glb();
        assert_eq!(&glb[0..4], b"glTF");
        assert_eq!(
            u32::from_le_bytes(glb[8..12].try_into().unwrap()) as usize,
            glb.len()
        );
        assert_eq!(glb.len() % 4, 0);
        assert_eq!(asset.sample_count(), samples.len());
        let text = asset.to_gltf("a b.bin");
        assert!(text.contains("\"uri\": \"a%20b.bin\""));
        assert!(text.contains("\"loop\":true"), "{text}");
    }

    #[test]
    fn quaternion_signs_are_consistent() {
        let a = Pose::IDENTITY;
        let mut b = Pose::from_axis_angle(glam::DVec3::Z, 0.5);
        b.rotation = -b.rotation;
        let q = consistent_rotations(&[a, b]);
        assert!(q[1][3] > 0.0);
    }
}
