//! File export and import for JavaScript: `motion.exportFile(settings)` writes the motion as
//! glTF 2.0 (`.glb`, or `.gltf` + `.bin`) or CSV, exactly like `screwbender export`, and
//! `importMotionFile(name, bytes)` reads control poses from a `.glb`, `.gltf`, `.csv` or `.json`
//! file, exactly like `screwbender import` (both call [`screwbender::export_motion`] and
//! [`screwbender::import_motion_file`]). `reducePoses(document, how)` thins a dense import
//! (more than [`MANY_POSES`] poses, e.g. a CSV of samples) to fewer control poses, and
//! `importedMesh(name, bytes)` gives a dropped glTF's mesh.

use std::collections::HashMap;

use glam::DVec3;
use js_sys::{Float64Array, Object, Reflect, Uint32Array, Uint8Array};
use serde::Deserialize;
use wasm_bindgen::prelude::*;

use super::convert::{
    bytes, check_keys, check_object, document_from_js, document_to_js, from_js, is_absent, plain,
    string,
};
use super::MotionHandle;
use screwbender::mesh::Mesh;
use screwbender::{
    export_motion, import_motion_file, mesh_radius, reduce_poses, Error, ErrorKind, ExportFormat,
    ExportSettings, NodeSelection, Reduction, SamplingMode, DEFAULT_TOLERANCE, MANY_POSES,
    MAX_GLTF_BYTES,
};

#[wasm_bindgen(typescript_custom_section)]
const TS_INTEROP: &'static str = r#"
/** What `Motion.exportFile` writes. */
export interface ExportSettings {
  /** `glb` (one file), `gltf` (JSON + `.bin` buffer) or `csv` (sampled poses or a trajectory). */
  format: 'glb' | 'gltf' | 'csv';
  /** Adaptive sampling: the largest distance (scene units) between the keyframe interpolation and the true motion at the object's points (default 1e-4). */
  tolerance?: number;
  /** Adaptive sampling of poses: the object's extent around its local origin at which the tolerance holds (default: the mesh's farthest vertex, else the placeholder box's). */
  radius?: number;
  /** Fixed-rate sampling instead (frames per second); not with `tolerance`. */
  fps?: number;
  /** Control-pose times in seconds (n for an open motion, n + 1 for a cycle); default: the motion's own (`motion.times`), else 1 s per span. The motion's key velocities apply either way. */
  times?: number[];
  /** CSV only: the trajectory of this body point (local coordinates) instead of the poses. */
  point?: Vec3;
  /** glTF only: also one empty node per control pose. */
  controlNodes?: boolean;
  /** glTF only: the object's mesh by name (`bar`, `block`, …, `scene:<id>`); default: the preset's object if the document is named after a preset (the morphing shapes of a preset with one shape per pose, such as `pip_morph5`), else a placeholder box. */
  object?: string;
  /** glTF only: an imported mesh (OBJ text or glTF/GLB bytes), scaled to fit a cube of side `size`. */
  mesh?: { kind: 'obj' | 'gltf'; data: string | Uint8Array; size: number };
  /** The file name's stem (default: the document's name, else `motion`); the suggested name adds what the file holds: `<name>-motion.glb` / `.gltf` (+ `-motion.bin`), `<name>-poses.csv`, `<name>-path.csv` (not repeated when the stem already ends with it). */
  name?: string;
}

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

/** The result of `Motion.exportFile`. */
export interface ExportedFile {
  /** Suggested file name: `<name>-motion.glb`, `<name>-motion.gltf`, `<name>-poses.csv` or `<name>-path.csv`. */
  fileName: string;
  /** MIME type of `data`. */
  mimeType: string;
  /** The file's bytes. */
  data: Uint8Array;
  /** `.gltf` only: the buffer file's name and bytes (the JSON refers to it by this name). */
  binName?: string;
  bin?: Uint8Array;
  /** Keyframes (glTF) or rows (CSV) written. */
  sampleCount: number;
  /** Adaptive sampling: the radius the tolerance holds at (0 for a trajectory, which is bounded at its point). */
  radius?: number;
  /** The sampled motion, e.g. `screwbender 4-point ×5 (direct)`. */
  motionName: string;
}
"#;

/// `Motion.exportFile` settings (see the TypeScript `ExportSettings`).
#[derive(Deserialize)]
#[serde(rename_all = "camelCase")]
struct ExportInput {
    format: String,
    tolerance: Option<f64>,
    radius: Option<f64>,
    fps: Option<f64>,
    times: Option<Vec<f64>>,
    point: Option<[f64; 3]>,
    control_nodes: Option<bool>,
    object: Option<String>,
    name: Option<String>,
}

/// Reads the optional `mesh` entry: `{kind: 'obj' | 'gltf', data, size}`.
fn mesh_input(settings: &JsValue) -> Result<Option<Mesh>, Error> {
    let value = Reflect::get(settings, &JsValue::from_str("mesh")).unwrap_or(JsValue::UNDEFINED);
    if is_absent(&value) {
        return Ok(None);
    }
    check_object(&value, "mesh", "mesh", "{kind, data, size}")?;
    let field = |k: &str| Reflect::get(&value, &JsValue::from_str(k)).unwrap_or(JsValue::UNDEFINED);
    let kind = string(&field("kind"), "mesh.kind")?;
    let size = field("size")
        .as_f64()
        .filter(|s| s.is_finite() && *s > 0.0)
        .ok_or_else(|| {
            Error::new(
                "mesh.size",
                ErrorKind::OutOfRange {
                    value: format!("{:?}", field("size")),
                    expected: "a positive number".into(),
                },
            )
        })?;
    let data = bytes(&field("data"), "mesh.data", MAX_GLTF_BYTES)?;
    let mesh = match kind.as_str() {
        "obj" => {
            let text = std::str::from_utf8(&data).map_err(|e| {
                Error::new(
                    "mesh.data",
                    ErrorKind::Parse {
                        message: format!("OBJ is not UTF-8 text: {e}"),
                    },
                )
            })?;
            Mesh::from_obj(text)
        }
        "gltf" => Mesh::from_gltf(&data),
        other => {
            return Err(Error::new(
                "mesh.kind",
                ErrorKind::UnknownValue {
                    value: other.into(),
                    expected: "obj, gltf",
                },
            ))
        }
    }
    .map_err(|e| e.within("mesh"))?;
    Ok(Some(mesh.normalized(size)))
}

fn set(obj: &Object, key: &str, value: JsValue) {
    // Defining a property on a fresh plain object cannot fail.
    let _ = Reflect::set(obj, &JsValue::from_str(key), &value);
}

#[wasm_bindgen(js_class = Motion)]
impl MotionHandle {
    /// The control poses as CSV (`x,y,z,qw,qx,qy,qz,time,velocity`; a cycle's pose 0 again at
    /// its end time): the design itself, with its key times and velocities, which
    /// `importMotionFile` reads back to the same document. `exportFile({format: 'csv'})` writes
    /// samples of the motion instead.
    #[wasm_bindgen(js_name = controlPosesCsv)]
    pub fn control_poses_csv_js(&self) -> Result<String, JsError> {
        let (doc, _) = self.snapshot()?;
        Ok(screwbender::control_poses_csv(&doc))
    }

    /// Writes the motion (its document and subdivision options) as a file, like
    /// `screwbender export`: glTF 2.0 with the object animated by adaptive keyframes (or a
    /// fixed rate), or CSV samples / a body-point trajectory. Throws on bad settings (the
    /// message names the setting); the motion is never changed.
    #[wasm_bindgen(js_name = exportFile, unchecked_return_type = "ExportedFile")]
    pub fn export_file(
        &self,
        #[wasm_bindgen(unchecked_param_type = "ExportSettings")] settings: JsValue,
    ) -> Result<JsValue, JsError> {
        let settings = plain(&settings, "settings")?;
        check_object(&settings, "settings", "export settings", "{format, …}")?;
        check_keys(
            &settings,
            &[
                "format",
                "tolerance",
                "radius",
                "fps",
                "times",
                "point",
                "controlNodes",
                "object",
                "mesh",
                "name",
            ],
            "settings",
            "export settings",
        )?;
        let input: ExportInput = from_js(&settings, "settings", "export settings")?;
        let format = ExportFormat::parse(&input.format, "format")?;
        let sampling = match (input.tolerance, input.fps) {
            (Some(_), Some(_)) => return Err(Error::new(
                "fps",
                ErrorKind::Unsupported {
                    reason:
                        "give either tolerance (adaptive sampling) or fps (fixed rate), not both"
                            .into(),
                },
            )
            .into()),
            (_, Some(fps)) => SamplingMode::FixedRate(fps),
            (t, None) => SamplingMode::Adaptive(t.unwrap_or(DEFAULT_TOLERANCE)),
        };
        let imported = mesh_input(&settings)?;
        let (doc, sub) = self.snapshot()?;
        let named = match (&input.object, &doc.name) {
            (Some(name), _) => Some(Mesh::named(name).map_err(|e| e.within("object"))?),
            (None, Some(name)) => {
                screwbender::presets::preset(name).map(|s| Mesh::from_shape(&s.shape))
            }
            (None, None) => None,
        };
        if imported.is_some() && input.object.is_some() {
            return Err(Error::new(
                "mesh",
                ErrorKind::Unsupported {
                    reason: "give either object (a named mesh) or mesh (an imported one), not both"
                        .into(),
                },
            )
            .into());
        }
        // A preset with one shape per control pose (A8) exports its morph, unless another
        // object or mesh is asked for.
        let morph = match (&input.object, &imported, &doc.name) {
            (None, None, Some(name)) => {
                screwbender::PipMorph::for_preset(name, doc.poses.len(), doc.closed)
            }
            _ => None,
        };
        // File names say what the file holds (a glTF motion, sampled poses, a path).
        let stem = input
            .name
            .clone()
            .or_else(|| doc.name.clone())
            .unwrap_or_else(|| "motion".into());
        let holds = match (format, input.point) {
            (ExportFormat::Csv, Some(_)) => "path",
            (ExportFormat::Csv, None) => "poses",
            _ => "motion",
        };
        let base = if stem == holds || stem.ends_with(&format!("-{holds}")) {
            stem
        } else {
            format!("{stem}-{holds}")
        };
        let bin_name = format!("{base}.bin");
        let exported = export_motion(
            &doc,
            sub,
            &ExportSettings {
                format,
                sampling,
                times: input.times,
                radius: input.radius,
                point: input.point.map(DVec3::from_array),
                control_nodes: input.control_nodes.unwrap_or(false),
                mesh: imported.as_ref().or(named.as_ref()),
                morph: morph.as_ref(),
                bin_name: &bin_name,
            },
        )?;
        let (ext, mime) = match format {
            ExportFormat::Glb => ("glb", "model/gltf-binary"),
            ExportFormat::Gltf => ("gltf", "model/gltf+json"),
            ExportFormat::Csv => ("csv", "text/csv"),
        };
        let out = Object::new();
        set(&out, "fileName", format!("{base}.{ext}").into());
        set(&out, "mimeType", mime.into());
        set(&out, "data", Uint8Array::from(&exported.data[..]).into());
        if let Some(bin) = &exported.bin {
            set(&out, "binName", bin_name.into());
            set(&out, "bin", Uint8Array::from(&bin[..]).into());
        }
        set(&out, "sampleCount", (exported.sample_count as f64).into());
        if let Some(r) = exported.radius {
            set(&out, "radius", r.into());
        }
        set(&out, "motionName", exported.motion_name.into());
        Ok(out.into())
    }
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
