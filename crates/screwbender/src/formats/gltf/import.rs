//! Control poses from a glTF 2.0 asset (`.glb`, or `.gltf` with its buffers).
//!
//! Two sources ([`NodeSelection`]):
//!
//! * the keyframes of one node's translation/rotation animation — the node named by the user, or
//!   else the node [`crate::CONTROL_NODE_NAME`] written by [`crate::GltfAsset`] (so an exported
//!   file gives back its control poses), or else the first animated node;
//! * the static transforms (`translation`/`rotation`, or `matrix`) of a list of named nodes.
//!
//! A cycle is recognised from `extras.screwbender.closed` of the animation when present, else when
//! the last keyframe repeats the first (within [`crate::REPEAT_TOLERANCE`]); the repeat is dropped.
//! Only `FLOAT` keyframes are read (normalized-integer rotations are refused). Every structural
//! problem is an [`Error::Parse`] naming the element (`accessors[2]`, `bufferViews[0]`, `glb`).

use gltf_json as json;
use json::validation::Checked;

use super::glb::{check_size, parse_err, split_glb};
use super::names::{CONTROL_NODE_NAME, EXTRAS_KEY};
use crate::error::{Error, ErrorKind};
use crate::formats::document::MotionDocument;
use crate::formats::keyframes::{last_repeats_first, MAX_KEYFRAME_FILE_BYTES, REPEAT_TOLERANCE};
use crate::pose::Pose;

/// Largest glTF / GLB / buffer file accepted: 64 MiB. Larger input is refused before parsing.
pub const MAX_GLTF_BYTES: usize = MAX_KEYFRAME_FILE_BYTES;

/// Which node(s) give the poses.
#[derive(Clone, Debug, Default, PartialEq)]
pub enum NodeSelection {
    /// [`crate::CONTROL_NODE_NAME`] if it is animated, else the first animated node.
    #[default]
    Auto,
    /// The animated node with this name.
    Animated(String),
    /// The static transforms of these nodes, in this order.
    Transforms(Vec<String>),
}

/// Reads control poses from a `.glb` file's bytes.
pub fn import_glb(bytes: &[u8], selection: &NodeSelection) -> Result<MotionDocument, Error> {
    let (text, bin) = split_glb(bytes)?;
    let mut resolve = |uri: &str| -> Result<Vec<u8>, Error> {
        Err(parse_err(
            "buffers",
            format!("external buffer '{uri}' in a GLB file is not supported"),
        ))
    };
    import_json(text, bin, &mut resolve, selection)
}

/// Reads control poses from a `.gltf` JSON text; `resolve` loads a buffer's `uri` (relative to
/// the `.gltf` file; `data:` URIs are refused).
pub fn import_gltf(
    text: &[u8],
    resolve: &mut dyn FnMut(&str) -> Result<Vec<u8>, Error>,
    selection: &NodeSelection,
) -> Result<MotionDocument, Error> {
    check_size(text.len(), "gltf")?;
    import_json(text, None, resolve, selection)
}

fn import_json(
    text: &[u8],
    glb_bin: Option<&[u8]>,
    resolve: &mut dyn FnMut(&str) -> Result<Vec<u8>, Error>,
    selection: &NodeSelection,
) -> Result<MotionDocument, Error> {
    let root = json::Root::from_slice(text)
        .map_err(|e| parse_err("gltf", format!("invalid glTF JSON: {e}")))?;
    if !root.asset.version.starts_with("2.") {
        return Err(parse_err(
            "asset.version",
            format!("'{}', only glTF 2.x is supported", root.asset.version),
        ));
    }
    let node_index = |name: &str| -> Result<usize, Error> {
        root.nodes
            .iter()
            .position(|n| n.name.as_deref() == Some(name))
            .ok_or_else(|| parse_err("nodes", format!("no node named '{name}'")))
    };
    match selection {
        NodeSelection::Transforms(names) => {
            let poses = names
                .iter()
                .map(|name| {
                    let i = node_index(name)?;
                    node_pose(&root.nodes[i]).map_err(|e| e.within(&format!("nodes[{i}]")))
                })
                .collect::<Result<Vec<_>, _>>()?;
            let doc = MotionDocument::new(poses, false);
            finish(doc, None)
        }
        NodeSelection::Auto | NodeSelection::Animated(_) => {
            if root.animations.is_empty() {
                return Err(parse_err(
                    "animations",
                    "the file has no animations (use --node NAME,NAME,… to read node transforms)",
                ));
            }
            let animated = |node: usize| {
                root.animations.iter().enumerate().find_map(|(a, anim)| {
                    anim.channels
                        .iter()
                        .any(|c| c.target.node.value() == node)
                        .then_some(a)
                })
            };
            let node = match selection {
                NodeSelection::Animated(name) => node_index(name)?,
                _ => root
                    .nodes
                    .iter()
                    .position(|n| n.name.as_deref() == Some(CONTROL_NODE_NAME))
                    .filter(|&i| animated(i).is_some())
                    .or_else(|| {
                        root.animations
                            .iter()
                            .flat_map(|a| a.channels.first())
                            .map(|c| c.target.node.value())
                            .next()
                    })
                    .ok_or_else(|| parse_err("animations", "no animation has channels"))?,
            };
            if node >= root.nodes.len() {
                return Err(parse_err(
                    "animations",
                    format!(
                        "a channel targets node {node}, but there are {}",
                        root.nodes.len()
                    ),
                ));
            }
            let a = animated(node)
                .ok_or_else(|| parse_err(format!("nodes[{node}]"), "the node is not animated"))?;
            let mut buffers = Buffers {
                root: &root,
                glb_bin,
                loaded: vec![None; root.buffers.len()],
            };
            let (poses, times) = animation_poses(&root, a, node, &mut buffers, resolve)
                .map_err(|e| e.within(&format!("animations[{a}]")))?;
            let extras = root.animations[a]
                .extras
                .as_ref()
                .and_then(|raw| serde_json::from_str::<serde_json::Value>(raw.get()).ok());
            let closed = extras
                .as_ref()
                .and_then(|v| v[EXTRAS_KEY]["closed"].as_bool());
            let offset = extras
                .as_ref()
                .and_then(|v| v[EXTRAS_KEY]["timeOffset"].as_f64())
                .filter(|t| t.is_finite())
                .unwrap_or(0.0);
            let mut doc = MotionDocument::new(poses, false);
            // The control node's name says nothing: take the scene's (the motion's) name.
            doc.name = match root.nodes[node].name.as_deref() {
                Some(CONTROL_NODE_NAME) | None => root
                    .scene
                    .and_then(|s| root.scenes.get(s.value()))
                    .or(root.scenes.first())
                    .and_then(|s| s.name.clone()),
                Some(name) => Some(name.to_string()),
            };
            let mut doc = finish(doc, closed)?;
            doc.times = key_times(&doc, &times, offset);
            if let Some(v) = extras.as_ref().map(|v| &v[EXTRAS_KEY]["velocities"]) {
                if !v.is_null() {
                    let parent = format!("animations[{a}].extras.{EXTRAS_KEY}");
                    let velocities = key_velocities(v).ok_or_else(|| {
                        parse_err(
                            format!("{parent}.velocities"),
                            "not a list of numbers and nulls",
                        )
                    })?;
                    doc.set_timing(doc.times.clone(), Some(velocities))
                        .map_err(|e| e.within(&parent))?;
                }
            }
            Ok(doc)
        }
    }
}

/// Detects a cycle from a repeated last pose (or `closed` from extras) and checks the count.
fn finish(mut doc: MotionDocument, closed: Option<bool>) -> Result<MotionDocument, Error> {
    let repeats = last_repeats_first(&doc.poses);
    doc.closed = closed.unwrap_or(repeats);
    if doc.closed && repeats {
        doc.poses.pop();
    }
    if doc.poses.len() < 2 {
        return Err(Error::new(
            "poses",
            ErrorKind::TooFewPoses {
                found: doc.poses.len(),
                min: 2,
            },
        ));
    }
    Ok(doc)
}

/// A node's static transform as a pose (scale must be 1).
fn node_pose(node: &json::Node) -> Result<Pose, Error> {
    if let Some(m) = node.matrix {
        let m: Vec<f64> = m.iter().map(|&x| x as f64).collect();
        // Column-major 4×4: columns 0..2 are the basis, column 3 the translation.
        let col = |c: usize| [m[4 * c], m[4 * c + 1], m[4 * c + 2]];
        return Pose::from_basis([m[12], m[13], m[14]], [col(0), col(1), col(2)])
            .map_err(|e| e.within("matrix"));
    }
    if let Some(s) = node.scale {
        if s.iter().any(|&x| (x as f64 - 1.0).abs() > REPEAT_TOLERANCE) {
            return Err(Error::new(
                "scale",
                ErrorKind::Unsupported {
                    reason: format!("scale {s:?} is not 1: a pose is a rigid transform"),
                },
            ));
        }
    }
    let t = node.translation.unwrap_or([0.0; 3]).map(|x| x as f64);
    let q = node
        .rotation
        .as_ref()
        .map_or([0.0, 0.0, 0.0, 1.0], |q| q.0)
        .map(|x| x as f64);
    Pose::from_wxyz(t, [q[3], q[0], q[1], q[2]]).map_err(|e| e.within("rotation"))
}

struct Buffers<'a> {
    root: &'a json::Root,
    glb_bin: Option<&'a [u8]>,
    loaded: Vec<Option<Vec<u8>>>,
}

impl Buffers<'_> {
    fn get(
        &mut self,
        i: usize,
        resolve: &mut dyn FnMut(&str) -> Result<Vec<u8>, Error>,
    ) -> Result<&[u8], Error> {
        let at = format!("buffers[{i}]");
        let buffer = self
            .root
            .buffers
            .get(i)
            .ok_or_else(|| parse_err(&at, "no such buffer"))?;
        if self.loaded[i].is_none() {
            let data = match (&buffer.uri, self.glb_bin) {
                (None, Some(bin)) if i == 0 => bin.to_vec(),
                (None, _) => return Err(parse_err(&at, "no uri and no GLB binary chunk")),
                (Some(uri), _) if uri.starts_with("data:") => {
                    return Err(Error::new(
                        at,
                        ErrorKind::Unsupported {
                            reason: "data: URIs are not supported (use .glb or a .bin file)".into(),
                        },
                    ))
                }
                (Some(uri), _) => resolve(uri).map_err(|e| e.within(&at))?,
            };
            check_size(data.len(), &at)?;
            if (data.len() as u64) < buffer.byte_length.0 {
                return Err(parse_err(
                    &at,
                    format!(
                        "{} bytes, but byteLength is {} (truncated)",
                        data.len(),
                        buffer.byte_length.0
                    ),
                ));
            }
            self.loaded[i] = Some(data);
        }
        Ok(self.loaded[i].as_deref().expect("just loaded"))
    }
}

/// Reads a `FLOAT` accessor of `width` components per element.
fn read_floats(
    root: &json::Root,
    index: usize,
    width: usize,
    buffers: &mut Buffers,
    resolve: &mut dyn FnMut(&str) -> Result<Vec<u8>, Error>,
) -> Result<Vec<Vec<f64>>, Error> {
    let at = format!("accessors[{index}]");
    let acc = root
        .accessors
        .get(index)
        .ok_or_else(|| parse_err(&at, "no such accessor"))?;
    match (&acc.component_type, &acc.type_) {
        (Checked::Valid(c), Checked::Valid(t))
            if c.0 == json::accessor::ComponentType::F32 && t.multiplicity() == width => {}
        _ => {
            return Err(Error::new(
                at,
                ErrorKind::Unsupported {
                    reason: format!(
                    "expected FLOAT keyframes with {width} component(s) (normalized integers and \
                     other types are not supported)"
                ),
                },
            ))
        }
    }
    if acc.sparse.is_some() {
        return Err(Error::new(
            at,
            ErrorKind::Unsupported {
                reason: "sparse accessors are not supported".into(),
            },
        ));
    }
    let count = usize::try_from(acc.count.0).unwrap_or(usize::MAX);
    let view_index = acc
        .buffer_view
        .ok_or_else(|| parse_err(&at, "no bufferView"))?
        .value();
    let view_at = format!("bufferViews[{view_index}]");
    let view = root
        .buffer_views
        .get(view_index)
        .ok_or_else(|| parse_err(&view_at, "no such buffer view"))?;
    let data = buffers.get(view.buffer.value(), resolve)?;
    let view_start = view.byte_offset.map_or(0, |o| o.0 as usize);
    let view_len = view.byte_length.0 as usize;
    let view_bytes = view_start
        .checked_add(view_len)
        .and_then(|end| data.get(view_start..end))
        .ok_or_else(|| parse_err(&view_at, "runs past the end of its buffer"))?;
    let elem = 4 * width;
    let stride = view.byte_stride.map_or(elem, |s| s.0);
    let offset = acc.byte_offset.map_or(0, |o| o.0 as usize);
    let needed = if count == 0 {
        Some(0)
    } else {
        stride
            .checked_mul(count - 1)
            .and_then(|n| n.checked_add(offset))
            .and_then(|n| n.checked_add(elem))
    };
    if stride < elem || needed.is_none_or(|n| n > view_bytes.len()) {
        let needed = needed.map_or("more than 2^64".to_string(), |n| n.to_string());
        return Err(parse_err(
            &at,
            format!(
                "{count} elements need {needed} bytes, the buffer view has {} (truncated)",
                view_bytes.len()
            ),
        ));
    }
    (0..count)
        .map(|k| {
            let base = offset + k * stride;
            let v: Vec<f64> = (0..width)
                .map(|c| {
                    let b = &view_bytes[base + 4 * c..base + 4 * c + 4];
                    f32::from_le_bytes(b.try_into().expect("4 bytes")) as f64
                })
                .collect();
            if v.iter().all(|x| x.is_finite()) {
                Ok(v)
            } else {
                Err(Error::new(format!("{at}[{k}]"), ErrorKind::NonFinite))
            }
        })
        .collect()
}

/// The keyframe poses of `node` in animation `a`.
fn animation_poses(
    root: &json::Root,
    a: usize,
    node: usize,
    buffers: &mut Buffers,
    resolve: &mut dyn FnMut(&str) -> Result<Vec<u8>, Error>,
) -> Result<(Vec<Pose>, Vec<f64>), Error> {
    use json::animation::{Interpolation, Property};
    let anim = &root.animations[a];
    let mut inputs: Vec<(usize, Vec<f64>)> = Vec::new();
    let mut translations = None;
    let mut rotations = None;
    for (c, ch) in anim.channels.iter().enumerate() {
        if ch.target.node.value() != node {
            continue;
        }
        let at = format!("channels[{c}]");
        let sampler_index = ch.sampler.value();
        let sampler = anim
            .samplers
            .get(sampler_index)
            .ok_or_else(|| parse_err(&at, "no such sampler"))?;
        let (property, width) = match ch.target.path {
            Checked::Valid(Property::Translation) => (0, 3),
            Checked::Valid(Property::Rotation) => (1, 4),
            _ => continue,
        };
        let cubic = sampler.interpolation == Checked::Valid(Interpolation::CubicSpline);
        let times = read_floats(root, sampler.input.value(), 1, buffers, resolve)?
            .into_iter()
            .map(|v| v[0])
            .collect::<Vec<_>>();
        let mut values = read_floats(root, sampler.output.value(), width, buffers, resolve)?;
        if cubic {
            // In-tangent, value, out-tangent per keyframe: keep the values.
            values = values.into_iter().skip(1).step_by(3).collect();
        }
        if values.len() != times.len() {
            return Err(parse_err(
                format!("samplers[{sampler_index}]"),
                format!("{} keyframe times but {} values", times.len(), values.len()),
            ));
        }
        inputs.push((sampler.input.value(), times));
        if property == 0 {
            translations = Some(values);
        } else {
            rotations = Some(values);
        }
    }
    let (_, times) = inputs.first().ok_or_else(|| {
        parse_err(
            "channels",
            "no translation or rotation channel for the node",
        )
    })?;
    if inputs.iter().any(|(_, t)| t != times) {
        return Err(Error::new(
            "samplers",
            ErrorKind::Unsupported {
                reason: "translation and rotation keyframes at different times".into(),
            },
        ));
    }
    let rest = node_pose(&root.nodes[node]).map_err(|e| e.within(&format!("nodes[{node}]")))?;
    let poses = (0..times.len())
        .map(|k| {
            let t = translations
                .as_ref()
                .map_or(rest.origin.to_array(), |v| [v[k][0], v[k][1], v[k][2]]);
            let q = rotations.as_ref().map_or(rest.rotation_wxyz(), |v| {
                [v[k][3], v[k][0], v[k][1], v[k][2]]
            });
            Pose::from_wxyz(t, q).map_err(|e| e.within(&format!("keyframe[{k}]")))
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok((poses, times.clone()))
}

/// The key velocities the exporter records (`extras.screwbender.velocities`: a number or `null`
/// per control pose); `None` when the value is not such a list.
fn key_velocities(value: &serde_json::Value) -> Option<Vec<Option<f64>>> {
    value
        .as_array()?
        .iter()
        .map(|v| match v {
            serde_json::Value::Null => Some(None),
            v => v.as_f64().map(Some),
        })
        .collect()
}

/// The key times of imported keyframes (`times` as stored plus the exporter's `timeOffset`):
/// `None` when they are the uniform `0, 1, 2, …` (the default timing, so such files round-trip
/// unchanged), when their count does not fit the document (`n`, or `n + 1` for a cycle), or when
/// they do not make a valid timing (docs/math/timing.md §3).
fn key_times(doc: &MotionDocument, times: &[f64], offset: f64) -> Option<Vec<f64>> {
    let uniform = offset == 0.0 && times.iter().enumerate().all(|(k, &t)| t == k as f64);
    let want = doc.poses.len() + usize::from(doc.closed);
    if uniform || times.len() != want {
        return None;
    }
    let times: Vec<f64> = times.iter().map(|t| t + offset).collect();
    crate::timing::Timing::for_poses(Some(times.clone()), doc.poses.len(), doc.closed)
        .ok()
        .map(|_| times)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn truncated_and_foreign_glb_are_named() {
        assert_eq!(split_glb(b"nope").unwrap_err().path(), "glb");
        let mut glb = b"glTF".to_vec();
        glb.extend_from_slice(&2u32.to_le_bytes());
        glb.extend_from_slice(&100u32.to_le_bytes());
        let e = split_glb(&glb).unwrap_err();
        assert!(e.to_string().contains("truncated"), "{e}");
    }

    #[test]
    fn gltf_without_animations_is_refused() {
        let text = br#"{"asset":{"version":"2.0"},"nodes":[{"name":"a"}]}"#;
        let mut none = |_: &str| -> Result<Vec<u8>, Error> { unreachable!() };
        let e = import_gltf(text, &mut none, &NodeSelection::Auto).unwrap_err();
        assert_eq!(e.path(), "animations");
    }

    #[test]
    fn node_transforms_give_poses() {
        let text = br#"{"asset":{"version":"2.0"},"nodes":[
            {"name":"a","translation":[1,2,3]},
            {"name":"b","rotation":[0,0,0.7071068,0.7071068]}]}"#;
        let mut none = |_: &str| -> Result<Vec<u8>, Error> { unreachable!() };
        let sel = NodeSelection::Transforms(vec!["b".into(), "a".into()]);
        let doc = import_gltf(text, &mut none, &sel).unwrap();
        assert_eq!(doc.poses.len(), 2);
        assert!((doc.poses[1].origin.y - 2.0).abs() < 1e-12);
        let e = import_gltf(
            text,
            &mut none,
            &NodeSelection::Transforms(vec!["c".into(), "a".into()]),
        )
        .unwrap_err();
        assert!(e.to_string().contains("no node named 'c'"));
    }
}
