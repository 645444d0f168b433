//! File import for JavaScript: `importMotionFile(name, bytes)` reads control poses from a `.glb`,
//! `.gltf`, `.csv` or `.json` file, exactly like `screwbender import` (both call
//! [`screwbender::import_motion_file`]; export, `motion.exportFile`, is the `export` module).
//! `reducePoses(document, how)` thins a dense import (more than [`MANY_POSES`] poses, e.g. a CSV
//! of samples) to fewer control poses, and `importedMesh(name, bytes)` gives a dropped glTF's mesh.

use std::collections::HashMap;

use js_sys::{Float64Array, Object, Reflect, Uint32Array};
use serde::Deserialize;
use wasm_bindgen::prelude::*;

use super::convert::{
    bytes, check_keys, check_object, document_from_js, document_to_js, from_js, is_absent, plain,
    string,
};
use screwbender::mesh::Mesh;
use screwbender::{
    import_motion_file, mesh_radius, reduce_poses, Error, ErrorKind, NodeSelection, Reduction,
    MANY_POSES, MAX_GLTF_BYTES,
};

#[wasm_bindgen(typescript_custom_section)]
const TS_INTEROP: &'static str = r#"
/** How `reducePoses` thins a dense pose sequence: keep every k-th pose, or the fewest poses whose polyscrew stays within `tolerance` (scene units, at body points within `radius` of the origin; default 0) of all of them. */
export type Reduction = { every: number } | { tolerance: number; radius?: number };

/** A mesh read from a glTF file (its own units and frame). */
export interface ImportedMesh {
  /** Vertex positions, 3 numbers each. */
  positions: Float64Array;
  /** Triangle vertex indices, 3 each. */
  indices: Uint32Array;
  /** The farthest vertex's distance from the origin. */
  radius: number;
}
"#;

/// Sets `obj[key] = value` on a plain object of the module's own making.
pub(crate) fn set(obj: &Object, key: &str, value: JsValue) {
    // Defining a property on a fresh plain object cannot fail.
    let _ = Reflect::set(obj, &JsValue::from_str(key), &value);
}

/// A thinner copy of a motion document (e.g. an imported CSV of more than [`MANY_POSES`]
/// samples): `{every: k}` keeps poses `0, k, 2k, …` (and an open motion's last), `{tolerance,
/// radius?}` the fewest poses whose polyscrew stays within `tolerance` of all of them (origin
/// distance plus `radius` × rotation angle; docs/math/formats.md §7). The name, `closed` and the
/// kept poses' times are kept. Throws naming `every`, `tolerance` or `radius`.
#[wasm_bindgen(js_name = reducePoses, unchecked_return_type = "MotionDocument")]
pub fn reduce_poses_js(
    #[wasm_bindgen(unchecked_param_type = "MotionDocumentInput")] document: JsValue,
    #[wasm_bindgen(unchecked_param_type = "Reduction")] how: JsValue,
) -> Result<JsValue, JsError> {
    #[derive(Deserialize)]
    #[serde(deny_unknown_fields)]
    struct How {
        every: Option<f64>,
        tolerance: Option<f64>,
        radius: Option<f64>,
    }
    let doc = document_from_js(&document)?;
    let how = plain(&how, "how")?;
    check_object(&how, "how", "reduction", "{every} or {tolerance, radius?}")?;
    check_keys(&how, &["every", "tolerance", "radius"], "how", "reduction")?;
    let h: How = from_js(&how, "how", "reduction")?;
    let reduction = match (h.every, h.tolerance) {
        (Some(k), None) if h.radius.is_none() => {
            if !(k.is_finite() && k >= 1.0 && k.fract() == 0.0 && k <= MANY_POSES as f64 * 1e6) {
                return Err(Error::new(
                    "every",
                    ErrorKind::OutOfRange {
                        value: k.to_string(),
                        expected: "a whole number ≥ 1".into(),
                    },
                )
                .into());
            }
            Reduction::Every(k as usize)
        }
        (None, Some(tolerance)) => Reduction::Fit {
            tolerance,
            radius: h.radius.unwrap_or(0.0),
        },
        _ => {
            return Err(Error::new(
                "how",
                ErrorKind::Unsupported {
                    reason: "give either {every: k} or {tolerance, radius?}".into(),
                },
            )
            .into())
        }
    };
    document_to_js(&reduce_poses(&doc, reduction)?)
}

/// The mesh of a glTF file (`.glb`, or `.gltf` with embedded buffers) in its own units, or
/// `undefined` when the file has none (a motion without an object). Throws on a malformed file,
/// starting with the file name.
#[wasm_bindgen(js_name = importedMesh, unchecked_return_type = "ImportedMesh | undefined")]
pub fn imported_mesh(
    #[wasm_bindgen(js_name = fileName, unchecked_param_type = "string")] file_name: JsValue,
    #[wasm_bindgen(unchecked_param_type = "Uint8Array")] data: JsValue,
) -> Result<JsValue, JsError> {
    let name = string(&file_name, "fileName")?;
    let content =
        bytes(&data, "data", MAX_GLTF_BYTES).map_err(|e| JsError::new(&format!("{name}: {e}")))?;
    let mesh = match Mesh::from_gltf(&content) {
        Ok(mesh) => mesh,
        // A file without any mesh is a motion without an object, not an error.
        Err(e) if e.to_string().contains("no triangles found") => return Ok(JsValue::UNDEFINED),
        Err(e) => return Err(JsError::new(&format!("{name}: {e}"))),
    };
    let positions: Vec<f64> = mesh.positions.iter().flat_map(|p| p.to_array()).collect();
    let out = Object::new();
    set(&out, "positions", Float64Array::from(&positions[..]).into());
    set(&out, "indices", Uint32Array::from(&mesh.indices[..]).into());
    set(&out, "radius", mesh_radius(&mesh).into());
    Ok(out.into())
}

/// Reads control poses from a file, like `screwbender import`: a `.glb` / `.gltf` (the keyframes
/// of the control-pose node, else of the first animated node; or, with `nodes`, the transforms
/// of those nodes in that order), a CSV (`x,y,z,qw,qx,qy,qz` per line, header optional) or a
/// JSON motion document. `bytes` is the file's `Uint8Array` (or its text); `buffers` maps the
/// URIs a `.gltf` names to their bytes (files dropped together). Throws an `Error` starting
/// with the file name and naming the line, column or accessor at fault.
#[wasm_bindgen(js_name = importMotionFile, unchecked_return_type = "MotionDocument")]
pub fn import_motion_file_js(
    #[wasm_bindgen(js_name = fileName, unchecked_param_type = "string")] file_name: JsValue,
    #[wasm_bindgen(unchecked_param_type = "Uint8Array | string")] data: JsValue,
    #[wasm_bindgen(unchecked_optional_param_type = "Record<string, Uint8Array>")] buffers: JsValue,
    #[wasm_bindgen(unchecked_optional_param_type = "string | string[]")] nodes: JsValue,
) -> Result<JsValue, JsError> {
    let name = string(&file_name, "fileName")?;
    let prefix = |e: Error| JsError::new(&format!("{name}: {e}"));
    let content = bytes(&data, "data", MAX_GLTF_BYTES).map_err(prefix)?;
    let mut files: HashMap<String, Vec<u8>> = HashMap::new();
    if !is_absent(&buffers) {
        check_object(&buffers, "buffers", "buffers", "{uri: Uint8Array}").map_err(prefix)?;
        let obj: &Object = buffers.unchecked_ref();
        let mut total = content.len();
        for key in Object::keys(obj).iter() {
            let key = key.as_string().unwrap_or_default();
            let at = format!("buffers[{key:?}]");
            let value = Reflect::get(obj, &JsValue::from_str(&key)).unwrap_or(JsValue::UNDEFINED);
            let b = bytes(&value, &at, MAX_GLTF_BYTES).map_err(prefix)?;
            total += b.len();
            if total > MAX_GLTF_BYTES {
                return Err(prefix(Error::new(
                    "buffers",
                    ErrorKind::OutOfRange {
                        value: format!("{total} bytes in all"),
                        expected: format!("at most {MAX_GLTF_BYTES} bytes"),
                    },
                )));
            }
            files.insert(key, b);
        }
    }
    let selection = if is_absent(&nodes) {
        NodeSelection::Auto
    } else if let Some(node) = nodes.as_string() {
        NodeSelection::Animated(node)
    } else {
        let list = plain(&nodes, "nodes").map_err(prefix)?;
        let arr = list.dyn_ref::<js_sys::Array>().ok_or_else(|| {
            prefix(Error::new(
                "nodes",
                ErrorKind::Parse {
                    message: "expected a node name or an array of node names".into(),
                },
            ))
        })?;
        let names: Result<Vec<String>, Error> = arr
            .iter()
            .enumerate()
            .map(|(i, v)| string(&v, &format!("nodes[{i}]")))
            .collect();
        NodeSelection::Transforms(names.map_err(prefix)?)
    };
    let mut resolve = |uri: &str| -> Result<Vec<u8>, Error> {
        files.get(uri).cloned().ok_or_else(|| {
            Error::new(
                "buffers",
                ErrorKind::Unsupported {
                    reason: format!(
                        "the glTF refers to the file '{uri}': drop it together with the .gltf file"
                    ),
                },
            )
        })
    };
    let mut doc = import_motion_file(&name, &content, &mut resolve, &selection).map_err(prefix)?;
    if doc.name.is_none() {
        // A file whose assets name nothing is titled by its file name.
        let stem = name
            .rsplit_once('.')
            .map_or(name.as_str(), |(stem, _)| stem);
        doc.name = Some(stem.rsplit(['/', '\\']).next().unwrap_or(stem).to_string());
    }
    document_to_js(&doc)
}
