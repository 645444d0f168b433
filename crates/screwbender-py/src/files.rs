//! Files: `Motion.load` (`.json`, `.csv`, `.glb`, `.gltf`, as `screwbender import`) and
//! `Motion.export` (`.glb`, `.gltf` + `.bin`, `.csv`, `.json`, as `screwbender export`), through
//! the core's importers and exporters.

use std::path::Path;

use glam::DVec3;
use pyo3::exceptions::{PyFileNotFoundError, PyOSError, PyPermissionError, PyValueError};
use pyo3::prelude::*;
use screwbender::{
    export_motion, Error, ExportFormat, ExportSamples, ExportSettings, MotionDocument,
    NodeSelection, PresetObject, Subdivision,
};

use crate::convert::detached;
use crate::convert::value_error;
use screwbender::frontend::export as export_request;
use screwbender::frontend::files::{import_motion_path, FileError};

/// An `OSError` of the matching subclass whose message names `path`.
fn os_error(path: &Path, e: std::io::Error) -> PyErr {
    let message = format!("{}: {e}", path.display());
    match e.kind() {
        std::io::ErrorKind::NotFound => PyFileNotFoundError::new_err(message),
        std::io::ErrorKind::PermissionDenied => PyPermissionError::new_err(message),
        _ => PyOSError::new_err(message),
    }
}

/// A `ValueError` naming the file and the element inside it.
fn file_error(path: &Path, e: Error) -> PyErr {
    PyValueError::new_err(format!("{}: {e}", path.display()))
}

/// A core file error as the matching Python exception: an `OSError` subclass for the system's
/// errors, a `ValueError` for a bad or too large file, each naming the file.
fn file_failure(e: FileError) -> PyErr {
    match e {
        FileError::Io { path, error } => os_error(&path, error),
        FileError::Content { path, error } => file_error(&path, error),
    }
}

/// The control poses of the file at `path`, read by the core as the CLI reads it (size limits,
/// `.gltf` buffers beside it by their percent-decoded URIs); `node` / `nodes` pick glTF nodes as
/// the CLI's `--node` / `--nodes`.
pub fn load(
    path: &Path,
    node: Option<String>,
    nodes: Option<Vec<String>>,
) -> PyResult<MotionDocument> {
    let selection =
        match (node, nodes) {
            (Some(_), Some(_)) => return Err(PyValueError::new_err(
                "nodes: give either node (an animated node) or nodes (static transforms), not both",
            )),
            (Some(n), None) => NodeSelection::Animated(n),
            (None, Some(ns)) => NodeSelection::Transforms(ns),
            (None, None) => NodeSelection::Auto,
        };
    import_motion_path(path, &selection).map_err(file_failure)
}

/// The options of `Motion.export`.
pub struct ExportOptions<'a> {
    /// `glb`, `gltf`, `csv` or `json`; `None`: from the file name's extension.
    pub format: Option<&'a str>,
    /// Adaptive keyframes within this distance (default [`DEFAULT_TOLERANCE`]).
    pub tolerance: Option<f64>,
    /// Fixed-rate keyframes instead.
    pub fps: Option<f64>,
    /// CSV: the trajectory of this body point instead of the poses.
    pub point: Option<DVec3>,
    /// The radius the tolerance holds at.
    pub radius: Option<f64>,
    /// glTF: one empty node per control pose too.
    pub control_nodes: bool,
}

/// The format asked for, or the one the extension of `path` names.
fn format_of(path: &Path, format: Option<&str>) -> PyResult<Option<ExportFormat>> {
    let name = match format {
        Some(f) => f.to_ascii_lowercase(),
        None => path
            .extension()
            .and_then(|e| e.to_str())
            .map(|e| e.to_ascii_lowercase())
            .unwrap_or_default(),
    };
    if name == "json" {
        return Ok(None);
    }
    ExportFormat::parse(&name, "format").map(Some).map_err(|_| {
        PyValueError::new_err(match format {
            Some(f) => format!("format: unknown value '{f}' (expected glb, gltf, csv or json)"),
            None => format!(
                "format: cannot tell the format from the file name '{}' (use .glb, .gltf, .csv or .json, or give format=)",
                path.display()
            ),
        })
    })
}

/// Writes the motion of `doc` subdivided by `sub` to `path`; returns the number of samples written.
pub fn export(
    py: Python<'_>,
    doc: &MotionDocument,
    sub: Subdivision,
    path: &Path,
    o: &ExportOptions,
) -> PyResult<usize> {
    let write = |p: &Path, data: &[u8]| std::fs::write(p, data).map_err(|e| os_error(p, e));
    let Some(format) = format_of(path, o.format)? else {
        write(path, doc.to_json().as_bytes())?;
        return Ok(doc.poses.len());
    };
    let sampling = export_request::sampling(o.tolerance, o.fps).map_err(value_error)?;
    let object = PresetObject::of(doc);
    let (gltf_path, bin_path) = export_request::gltf_paths(path);
    let bin_name = export_request::bin_name(&bin_path).map_err(value_error)?;
    let settings = ExportSettings {
        format,
        sampling,
        times: None,
        radius: o.radius,
        point: o.point,
        control_nodes: o.control_nodes,
        mesh: object.mesh.as_ref(),
        morph: object.morph.as_ref(),
        bin_name: &bin_name,
    };
    let settings = &settings;
    if format == ExportFormat::Csv {
        let samples = detached(py, || ExportSamples::new(doc, sub, settings))?
            .map_err(|e| file_error(path, e))?;
        let mut out = Vec::new();
        samples.write_csv(&mut out).map_err(|e| os_error(path, e))?;
        write(path, &out)?;
        return Ok(samples.sampled.samples.len());
    }
    let exported =
        detached(py, || export_motion(doc, sub, settings))?.map_err(|e| file_error(path, e))?;
    if format == ExportFormat::Gltf {
        write(&gltf_path, &exported.data)?;
        write(&bin_path, exported.bin.as_deref().unwrap_or_default())?;
    } else {
        write(path, &exported.data)?;
    }
    Ok(exported.sample_count)
}
