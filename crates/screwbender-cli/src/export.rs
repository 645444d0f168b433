//! `screwbender export --format glb|gltf|csv …`: the motion of a document as a glTF 2.0 asset
//! (the object's mesh animated by adaptive or fixed-rate keyframes, plus the control poses) or as
//! CSV samples / a body-point trajectory.

use std::path::Path;

use glam::DVec3;
use screwbender::frontend;
use screwbender::{
    export_motion, ExportFormat, ExportSamples, ExportSettings, PresetObject, SamplingMode,
};

use crate::args::{numbers, velocities};
use crate::cli::ExportArgs;
use crate::failure::Failure;
use crate::input::read_document;
use crate::output::Output;

/// The `export` options, checked (the subdivision options stay with [`ExportArgs::sub`]).
struct ExportOptions {
    format: Option<ExportFormat>,
    tolerance: Option<f64>,
    fps: Option<f64>,
    times: Option<Vec<f64>>,
    velocities: Option<Vec<Option<f64>>>,
    radius: Option<f64>,
    point: Option<DVec3>,
    control_nodes: bool,
    verbose: bool,
    output: Option<String>,
}

fn check(a: &ExportArgs) -> Result<ExportOptions, Failure> {
    let format = a
        .format
        .as_deref()
        .map(|f| ExportFormat::parse(f, "--format"))
        .transpose()?;
    let point = match a.point.as_deref() {
        None => None,
        Some(text) => {
            let v = numbers("--point", text)?;
            let [x, y, z] = v[..] else {
                return Err(Failure(format!(
                    "--point: {} number(s) given, expected x,y,z",
                    v.len()
                )));
            };
            Some(DVec3::new(x, y, z))
        }
    };
    let o = ExportOptions {
        format,
        tolerance: a.tolerance,
        fps: a.fps,
        times: a
            .times
            .as_deref()
            .map(|t| numbers("--times", t))
            .transpose()?,
        velocities: a
            .velocities
            .as_deref()
            .map(|v| velocities("--velocities", v))
            .transpose()?,
        radius: a.radius,
        point,
        control_nodes: a.control_nodes,
        verbose: a.verbose,
        output: a.output.clone(),
    };
    // Checked before the input is read.
    frontend::export::sampling(o.tolerance, o.fps)?;
    Ok(o)
}

fn write(path: &Path, data: &[u8]) -> Result<(), Failure> {
    std::fs::write(path, data).map_err(|e| Failure(format!("{}: {e}", path.display())))
}

/// Runs `screwbender export`; returns what goes to standard output (CSV without `-o`).
pub fn export(args: ExportArgs) -> Result<Output, Failure> {
    let o = check(&args)?;
    // The subdivision options are checked before the input is read.
    let sub = args.sub.subdivision()?;
    let format = o
        .format
        .ok_or_else(|| Failure("export needs --format glb|gltf|csv".into()))?;
    if format != ExportFormat::Csv && o.output.is_none() {
        return Err(Failure("export --format glb|gltf needs -o OUT".into()));
    }
    let mut doc = read_document(args.file.as_deref())?;
    doc.set_closed(doc.closed && !args.sub.open);
    // Key times and velocities: the options override the document's own.
    let times = o.times.clone().or_else(|| doc.times.clone());
    let given = o.velocities.clone().or_else(|| doc.velocities.clone());
    doc.set_timing(times, given)?;
    crate::compare::warn_subdivision(&sub, &doc.poses, doc.closed);
    let object = PresetObject::of(&doc);
    let out = o.output.as_deref();
    let (gltf_path, bin_path) = frontend::export::gltf_paths(Path::new(out.unwrap_or("motion")));
    let bin_name = frontend::export::bin_name(&bin_path)?;
    let sampling = frontend::export::sampling(o.tolerance, o.fps)?;
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
    // A CSV is written row by row from the samples (to `-o` or standard output), never as
    // one string; a glTF asset is built whole (its binary buffer's length heads the file).
    let (output, written, summary) = if format == ExportFormat::Csv {
        let export = ExportSamples::new(&doc, sub, &settings)?;
        let summary = (
            export.sampled.samples.len(),
            export.radius,
            export.sampled.motion_name.clone(),
        );
        let output = Output::writer(move |w| export.write_csv(w));
        match out {
            Some(out) => {
                output.write_file(out)?;
                (Output::text(String::new()), out.to_string(), summary)
            }
            None => (output, "standard output".into(), summary),
        }
    } else {
        let exported = export_motion(&doc, sub, &settings)?;
        let written = if format == ExportFormat::Gltf {
            write(&gltf_path, &exported.data)?;
            write(&bin_path, exported.bin.as_deref().unwrap_or_default())?;
            format!("{} + {}", gltf_path.display(), bin_path.display())
        } else {
            let out = out.expect("checked above: glTF needs -o");
            write(Path::new(out), &exported.data)?;
            out.to_string()
        };
        let summary = (exported.sample_count, exported.radius, exported.motion_name);
        (Output::text(String::new()), written, summary)
    };
    let (sample_count, radius, motion_name) = summary;
    if o.verbose {
        let sampling = match sampling {
            SamplingMode::FixedRate(fps) => format!("{fps} fps"),
            SamplingMode::Adaptive(t) => match radius {
                Some(r) if o.point.is_none() => format!("tolerance {t:e} at radius {r:.4}"),
                _ => format!("tolerance {t:e}"),
            },
        };
        eprintln!(
            "screwbender: export: {} samples ({sampling}, {}) -> {written}",
            sample_count, motion_name
        );
    }
    Ok(output)
}
