//! File export for JavaScript (feature `export`): `motion.exportFile(settings)` writes the motion
//! as glTF 2.0 (`.glb`, or `.gltf` + `.bin`) or CSV, exactly like `screwbender export` (both call
//! [`screwbender::export_motion`]). A feature apart from `files` (import), so that a module that
//! only shows motions (the `<screw-bender>` figure's, the playground's first one) leaves out the
//! glTF writer, the keyframe sampler and the document model's serialisation.

use glam::DVec3;
use js_sys::{Object, Reflect, Uint8Array};
use serde::Deserialize;
use wasm_bindgen::prelude::*;

use super::convert::{bytes, check_keys, check_object, from_js, is_absent, plain, string};
use super::files::set;
use super::MotionHandle;
use screwbender::mesh::Mesh;
use screwbender::{
    export_motion, Error, ErrorKind, ExportFormat, ExportSettings, PresetObject, MAX_GLTF_BYTES,
};

#[wasm_bindgen(typescript_custom_section)]
const TS_EXPORT: &'static str = r#"
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
  /** glTF only: the object's mesh by name (`bar`, `block`, …), or `scene:<id>` for preset `<id>`'s object as the playground draws it (the morphing shapes of a preset with one shape per pose, such as `pip_morph5`; the Stanford bunny for `bunny6` given `bunny`); default: the preset's object if the document is named after a preset, else a placeholder box. */
  object?: string;
  /** glTF only: the OBJ text of the Stanford bunny (the playground's `vendor/bunny.obj`, the file the CLI compiles in), the object of preset `bunny6`, which this module leaves out; without it a wedge stands in, as the page draws it until the file arrives. */
  bunny?: string;
  /** glTF only: an imported mesh (OBJ text or glTF/GLB bytes), scaled to fit a cube of side `size`. */
  mesh?: { kind: 'obj' | 'gltf'; data: string | Uint8Array; size: number };
  /** The file name's stem (default: the document's name, else `motion`); the suggested name adds what the file holds: `<name>-motion.glb` / `.gltf` (+ `-motion.bin`), `<name>-poses.csv`, `<name>-path.csv` (not repeated when the stem already ends with it). */
  name?: string;
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
    bunny: Option<String>,
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
                "bunny",
                "mesh",
                "name",
            ],
            "settings",
            "export settings",
        )?;
        let input: ExportInput = from_js(&settings, "settings", "export settings")?;
        let format = ExportFormat::parse(&input.format, "format")?;
        let sampling = screwbender::frontend::export::sampling(input.tolerance, input.fps)?;
        let imported = mesh_input(&settings)?;
        let (doc, sub) = self.snapshot()?;
        // `scene:<id>` is a preset's whole object (its morph, the bunny), not only its shape:
        // the same object the command line draws for a document named after that preset.
        let scene = input
            .object
            .as_deref()
            .and_then(|name| name.strip_prefix("scene:"));
        let named = match (&input.object, scene) {
            (Some(name), None) => Some(Mesh::named(name).map_err(|e| e.within("object"))?),
            (Some(name), Some(_)) => {
                // Checked as a mesh name, so an unknown id fails as any unknown object does.
                Mesh::named(name).map_err(|e| e.within("object"))?;
                None
            }
            (None, _) => None,
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
        // The preset's object (and morph) unless another object or mesh is asked for.
        let preset_id = match (scene, &imported) {
            (Some(id), None) => Some(id),
            (None, None) if input.object.is_none() => doc.name.as_deref(),
            _ => None,
        };
        let preset = match preset_id {
            Some(id) => {
                let object = PresetObject::of_preset(id, &doc);
                match &input.bunny {
                    Some(obj) => object.with_bunny_obj(id, obj)?,
                    None => object,
                }
            }
            None => PresetObject::default(),
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
                mesh: imported
                    .as_ref()
                    .or(named.as_ref())
                    .or(preset.mesh.as_ref()),
                morph: preset.morph.as_ref(),
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
