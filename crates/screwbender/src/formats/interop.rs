//! Whole-file export and import of a motion: the one place that turns a motion document plus
//! settings into a glTF / CSV file, and a file of any supported kind into a motion document.
//! The command line (`screwbender export` / `import`) and the JavaScript API (the page's export
//! buttons and drag-and-drop import) both call these, so the two give byte-identical results.

use std::io::{self, Write};

use glam::DVec3;

use crate::error::{Error, ErrorKind};
use crate::formats::csv::{parse_csv_poses, write_poses_csv, write_trajectory_csv};
#[cfg(doc)]
use crate::formats::csv::{poses_csv, trajectory_csv};
use crate::formats::document::MotionDocument;
use crate::formats::gltf::export::PLACEHOLDER_HALF_EXTENTS;
use crate::formats::gltf::export::{GltfAsset, GltfMotion};
use crate::formats::gltf::glb::is_glb;
use crate::formats::gltf::import::{import_glb, import_gltf, NodeSelection, MAX_GLTF_BYTES};
use crate::formats::sampling::Deviation;
use crate::formats::tracks::{sample_document, DocumentSamples, SamplingMode};
use crate::presets::mesh::{Mesh, BUNNY_PRESET};
use crate::presets::morph::PipMorph;
use crate::subdivision::Subdivision;

/// The file formats of [`export_motion`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ExportFormat {
    /// Binary glTF (one file).
    Glb,
    /// glTF JSON plus a separate `.bin` buffer.
    Gltf,
    /// CSV of sampled poses (`t,u,x,y,z,qw,qx,qy,qz`) or of a body-point trajectory.
    Csv,
}

impl ExportFormat {
    /// Parses `glb`, `gltf` or `csv` (`at` names the option in errors).
    pub fn parse(name: &str, at: &str) -> Result<ExportFormat, Error> {
        match name {
            "glb" => Ok(ExportFormat::Glb),
            "gltf" => Ok(ExportFormat::Gltf),
            "csv" => Ok(ExportFormat::Csv),
            other => Err(Error::new(
                at,
                ErrorKind::UnknownValue {
                    value: other.into(),
                    expected: "glb, gltf, csv",
                },
            )),
        }
    }
}

/// What [`export_motion`] writes, beside the document and subdivision.
#[derive(Clone, Debug)]
pub struct ExportSettings<'a> {
    /// Output format.
    pub format: ExportFormat,
    /// Time sampling.
    pub sampling: SamplingMode,
    /// Control-pose times in seconds (`n` for an open motion, `n + 1` for a cycle); `None`:
    /// the document's own ([`MotionDocument::times`]; one second per span when it has none).
    /// The document's key velocities apply either way.
    pub times: Option<Vec<f64>>,
    /// Adaptive sampling of poses: the largest distance of the object's points from its local
    /// origin, at which the tolerance is met; `None`: the morph's ([`PipMorph::radius`]), the
    /// mesh's ([`mesh_radius`]), else the placeholder box's. (A CSV trajectory is bounded at its point instead.)
    pub radius: Option<f64>,
    /// CSV only: write the trajectory of this body point instead of the poses.
    pub point: Option<DVec3>,
    /// glTF only: also one empty node per control pose.
    pub control_nodes: bool,
    /// glTF only: the object's mesh (`None`: the placeholder box).
    pub mesh: Option<&'a Mesh>,
    /// glTF only: a morphing object, one shape per control pose (replaces `mesh`; the file
    /// layout is in docs/math/pip-morph.md).
    pub morph: Option<&'a PipMorph>,
    /// glTF `.gltf` only: the file name the JSON uses for its buffer (`motion.bin`).
    pub bin_name: &'a str,
}

impl Default for ExportSettings<'_> {
    fn default() -> Self {
        ExportSettings {
            format: ExportFormat::Glb,
            sampling: SamplingMode::default(),
            times: None,
            radius: None,
            point: None,
            control_nodes: false,
            mesh: None,
            morph: None,
            bin_name: "motion.bin",
        }
    }
}

/// The object an export draws when the caller gives none: for a document named after a
/// preset, the preset's object ([`Mesh::for_preset`]) and, when the preset has one shape per
/// control pose and the document still has that many poses, its morph
/// ([`PipMorph::for_preset`], which [`ExportSettings::morph`] draws instead of the mesh).
///
/// The command line, the Python package and the JavaScript API all take their default object
/// from here, so the three exports of one document draw the same thing.
#[derive(Clone, Debug, Default)]
pub struct PresetObject {
    /// The preset's object; `None` when the document is not named after a preset.
    pub mesh: Option<Mesh>,
    /// The preset's morph; `None` when it has none or the poses no longer match its shapes.
    pub morph: Option<PipMorph>,
}

impl PresetObject {
    /// The preset object of `doc` (both parts `None` when its name is no preset's).
    pub fn of(doc: &MotionDocument) -> PresetObject {
        match doc.name.as_deref() {
            Some(name) => PresetObject::of_preset(name, doc),
            None => PresetObject::default(),
        }
    }

    /// The object of preset `id` moved by `doc`'s poses, whatever the document is named: what
    /// a figure that draws preset `id`'s object shows (both parts `None` for an unknown id; the
    /// morph only while `doc` has one pose per shape).
    pub fn of_preset(id: &str, doc: &MotionDocument) -> PresetObject {
        PresetObject {
            mesh: crate::presets::preset(id).map(|scene| Mesh::for_preset(&scene)),
            morph: PipMorph::for_preset(id, doc.poses.len(), doc.closed),
        }
    }

    /// For preset [`BUNNY_PRESET`], the Stanford bunny read from `obj`, the text of the crate's
    /// `assets/bunny.obj` ([`Mesh::bunny_from_obj`]); other presets' objects are kept. A build
    /// without the `bunny` feature draws a wedge in the bunny's place; one that gets the file
    /// by other means (the page fetches it) writes the same bytes as the command line this way.
    /// Errors: those of [`Mesh::from_obj`], at `bunny`.
    pub fn with_bunny_obj(mut self, id: &str, obj: &str) -> Result<PresetObject, Error> {
        if id == BUNNY_PRESET && self.mesh.is_some() {
            self.mesh = Some(Mesh::bunny_from_obj(obj).map_err(|e| e.within("bunny"))?);
        }
        Ok(self)
    }
}

/// The result of [`export_motion`].
#[derive(Clone, Debug, PartialEq)]
pub struct ExportedMotion {
    /// The file: GLB bytes, glTF JSON text or CSV text.
    pub data: Vec<u8>,
    /// The `.gltf` format's buffer (to be saved under [`ExportSettings::bin_name`]).
    pub bin: Option<Vec<u8>>,
    /// How many keyframes / CSV rows were sampled.
    pub sample_count: usize,
    /// The radius the adaptive tolerance was met at (`0` for a CSV trajectory, whose point is
    /// bounded; `None` for fixed-rate sampling).
    pub radius: Option<f64>,
    /// The sampled motion's name (e.g. `screwbender 4-point ×5 (direct)`).
    pub motion_name: String,
}

/// A motion sampled for export, before it is written: the first half of [`export_motion`].
///
/// The command line writes a CSV from it row by row ([`ExportSamples::write_csv`]) instead of
/// building the whole text first: an export of a million samples then never holds its text in
/// memory beside the samples.
#[derive(Clone, Debug, PartialEq)]
pub struct ExportSamples {
    /// The samples, their timing and the motion's name.
    pub sampled: DocumentSamples,
    /// The radius the adaptive tolerance was met at (`0` for a CSV trajectory, whose point is
    /// bounded; `None` for fixed-rate sampling).
    pub radius: Option<f64>,
    /// The body point of a CSV trajectory (`None`: the poses).
    pub point: Option<DVec3>,
}

impl ExportSamples {
    /// Samples the motion of `doc` (subdivided by `sub`; level 0 is the plain polyscrew) as
    /// `settings` say. Errors: those of [`export_motion`].
    pub fn new(
        doc: &MotionDocument,
        sub: Subdivision,
        settings: &ExportSettings,
    ) -> Result<ExportSamples, Error> {
        if settings.point.is_some() && settings.format != ExportFormat::Csv {
            return Err(Error::new(
                "point",
                ErrorKind::Unsupported {
                    reason: "a body-point trajectory needs --format csv".into(),
                },
            ));
        }
        let radius = match settings.point {
            Some(_) => 0.0,
            None => settings
                .radius
                .unwrap_or_else(|| match (settings.morph, settings.mesh) {
                    (Some(morph), _) => morph.radius(),
                    (None, Some(mesh)) => mesh_radius(mesh),
                    (None, None) => DVec3::from_array(PLACEHOLDER_HALF_EXTENTS).length(),
                }),
        };
        let deviation = match settings.point {
            Some(p) => Deviation::Point(p),
            None => Deviation::Body { radius },
        };
        let sampled = sample_document(
            doc,
            sub,
            settings.sampling,
            settings.times.as_deref(),
            deviation,
        )?;
        Ok(ExportSamples {
            sampled,
            radius: match settings.sampling {
                SamplingMode::Adaptive(_) => Some(radius),
                SamplingMode::FixedRate(_) => None,
            },
            point: settings.point,
        })
    }

    /// Writes the CSV file ([`poses_csv`], or [`trajectory_csv`] of the point) to `w` row by
    /// row. Errors: only those of `w`.
    pub fn write_csv<W: Write + ?Sized>(&self, w: &mut W) -> io::Result<()> {
        match self.point {
            Some(p) => write_trajectory_csv(w, &self.sampled.samples, p),
            None => write_poses_csv(w, &self.sampled.samples),
        }
    }
}

/// Samples the motion of `doc` (subdivided by `sub`; level 0 is the plain polyscrew) and writes
/// it in `settings.format`.
///
/// Errors name the element: a time count that does not match the poses (`times`), times not
/// increasing, a bad tolerance or frame rate, `point` with a glTF format, too many samples.
pub fn export_motion(
    doc: &MotionDocument,
    sub: Subdivision,
    settings: &ExportSettings,
) -> Result<ExportedMotion, Error> {
    let export = ExportSamples::new(doc, sub, settings)?;
    let DocumentSamples {
        samples, timing, ..
    } = &export.sampled;
    let (data, bin) = match settings.format {
        ExportFormat::Csv => {
            let mut data = Vec::new();
            export
                .write_csv(&mut data)
                .expect("writing to memory cannot fail");
            (data, None)
        }
        ExportFormat::Glb | ExportFormat::Gltf => {
            let asset = GltfAsset::new(&GltfMotion {
                name: doc.name.as_deref(),
                samples,
                control: &doc.poses,
                control_times: timing.knots(),
                // Free keys only: nothing to record.
                control_velocities: Some(timing.velocities())
                    .filter(|v| v.iter().any(Option::is_some)),
                closed: doc.closed,
                mesh: settings.mesh,
                morph: settings.morph,
                tolerance: match settings.sampling {
                    SamplingMode::Adaptive(t) => Some(t),
                    SamplingMode::FixedRate(_) => None,
                },
                control_nodes: settings.control_nodes,
            })?;
            if settings.format == ExportFormat::Glb {
                (asset.to_glb(), None)
            } else {
                (
                    asset.to_gltf(settings.bin_name).into_bytes(),
                    Some(asset.bin().to_vec()),
                )
            }
        }
    };
    Ok(ExportedMotion {
        data,
        bin,
        sample_count: samples.len(),
        radius: export.radius,
        motion_name: export.sampled.motion_name,
    })
}

/// The largest distance of a mesh vertex from the local origin (0 for an empty mesh): the
/// radius at which exports of that object meet their tolerance.
pub fn mesh_radius(mesh: &Mesh) -> f64 {
    mesh.positions
        .iter()
        .map(|p| p.length())
        .fold(0.0, f64::max)
}

/// The kinds of file [`import_motion_file`] reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ImportKind {
    /// Binary glTF.
    Glb,
    /// glTF JSON (buffers resolved by the caller).
    Gltf,
    /// CSV poses (`x,y,z,qw,qx,qy,qz`, header optional).
    Csv,
    /// A JSON motion document.
    Json,
}

impl ImportKind {
    /// The kind of a file from its name's extension and its first bytes (a GLB header wins over
    /// the name). `None` for other files.
    pub fn detect(file_name: &str, bytes: &[u8]) -> Option<ImportKind> {
        if is_glb(bytes) {
            return Some(ImportKind::Glb);
        }
        let ext = file_name
            .rsplit_once('.')
            .map(|(_, e)| e.to_ascii_lowercase())?;
        match ext.as_str() {
            "glb" => Some(ImportKind::Glb),
            "gltf" => Some(ImportKind::Gltf),
            "csv" => Some(ImportKind::Csv),
            "json" => Some(ImportKind::Json),
            _ => None,
        }
    }
}

/// Reads control poses from a file of any supported kind (see [`ImportKind::detect`]).
/// `resolve` loads the external buffers a `.gltf` names (by URI); `selection` picks glTF nodes
/// (it must be [`NodeSelection::Auto`] for CSV and JSON).
///
/// Errors name the element inside the file (`line 4, column qw: …`, `accessors[2]: …`); callers
/// prefix the file name. Files over [`MAX_GLTF_BYTES`] are refused before parsing.
pub fn import_motion_file(
    file_name: &str,
    bytes: &[u8],
    resolve: &mut dyn FnMut(&str) -> Result<Vec<u8>, Error>,
    selection: &NodeSelection,
) -> Result<MotionDocument, Error> {
    crate::error::check_size(bytes.len(), MAX_GLTF_BYTES, "")?;
    let kind = ImportKind::detect(file_name, bytes).ok_or_else(|| {
        Error::new(
            String::new(),
            ErrorKind::Unsupported {
                reason: "unknown file type (expected .glb, .gltf, .csv or .json)".into(),
            },
        )
    })?;
    let text = || {
        std::str::from_utf8(bytes).map_err(|e| {
            Error::new(
                String::new(),
                ErrorKind::Parse {
                    message: format!("not UTF-8 text: {e}"),
                },
            )
        })
    };
    match kind {
        ImportKind::Glb => import_glb(bytes, selection),
        ImportKind::Gltf => import_gltf(bytes, resolve, selection),
        ImportKind::Csv | ImportKind::Json if *selection != NodeSelection::Auto => Err(Error::new(
            "node",
            ErrorKind::UnknownValue {
                value: "a node selection".into(),
                expected: "none: node selections apply to glTF files only",
            },
        )),
        ImportKind::Csv => text().and_then(parse_csv_poses),
        ImportKind::Json => text().and_then(MotionDocument::from_json),
    }
}
