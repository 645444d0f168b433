//! The triangles of a glTF 2.0 asset (binary `.glb` or `.gltf` with embedded buffers) into a
//! [`Mesh`], for objects the user brings.

use glam::DVec3;

use crate::error::{Error, ErrorKind};
use crate::formats::obj::MAX_OBJ_TRIANGLES;
use crate::presets::mesh::Mesh;

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
    pub fn from_gltf(bytes: &[u8]) -> Result<Mesh, Error> {
        let err = |at: &str, message: String| {
            Error::new(format!("gltf{at}"), ErrorKind::Parse { message })
        };
        crate::error::check_size(bytes.len(), MAX_GLTF_MESH_BYTES, "gltf")?;
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
                    crate::formats::base64::decode(data)
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
