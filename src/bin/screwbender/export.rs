//! `screwbender export --format glb|gltf|csv …`: the motion of a document as a glTF 2.0 asset
//! (the object's mesh animated by adaptive or fixed-rate keyframes, plus the control poses) or as
//! CSV samples / a body-point trajectory.

use std::path::{Path, PathBuf};

use glam::DVec3;
use screwbender::mesh::Mesh;
use screwbender::{
    poses_csv, sample_fixed_rate, sample_polyscrew, scenes, trajectory_csv, GltfAsset, GltfMotion,
    Motion, Polyscrew, ScrewBender, Timing, DEFAULT_TOLERANCE,
};

use crate::args::{number, numbers, ArgReader, SubdivisionArgs};
use crate::{read_document, Failure};

/// The output formats.
#[derive(Clone, Copy, PartialEq)]
enum Format {
    Glb,
    Gltf,
    Csv,
}

/// Parsed `export` options.
#[derive(Default)]
struct ExportOptions {
    format: Option<Format>,
    tolerance: Option<f64>,
    fps: Option<f64>,
    times: Option<Vec<f64>>,
    point: Option<DVec3>,
    sub: SubdivisionArgs,
    control_nodes: bool,
    verbose: bool,
    file: Option<String>,
    output: Option<String>,
}

fn parse(args: &[String]) -> Result<ExportOptions, Failure> {
    let mut o = ExportOptions::default();
    let mut r = ArgReader::new(args);
    while let Some(arg) = r.next_arg() {
        if o.sub.take(arg, &mut r)? {
            continue;
        }
        match arg {
            "--format" => {
                o.format = Some(match r.value(arg)?.as_str() {
                    "glb" => Format::Glb,
                    "gltf" => Format::Gltf,
                    "csv" => Format::Csv,
                    other => {
                        return Err(Failure(format!(
                            "--format: unknown value '{other}' (expected glb, gltf, csv)"
                        )))
                    }
                })
            }
            "--tolerance" => o.tolerance = Some(number(arg, &r.value(arg)?)?),
            "--fps" => o.fps = Some(number(arg, &r.value(arg)?)?),
            "--times" => o.times = Some(numbers(arg, &r.value(arg)?)?),
            "--point" => {
                let v = numbers(arg, &r.value(arg)?)?;
                let [x, y, z] = v[..] else {
                    return Err(Failure(format!(
                        "--point: {} number(s) given, expected x,y,z",
                        v.len()
                    )));
                };
                o.point = Some(DVec3::new(x, y, z));
            }
            "--control-nodes" => o.control_nodes = true,
            "--verbose" | "-v" => o.verbose = true,
            "-o" | "--output" => o.output = Some(r.value("-o")?),
            other => r.positional(other)?,
        }
    }
    o.sub.subdivision(5)?;
    o.file = r.file;
    if o.tolerance.is_some() && o.fps.is_some() {
        return Err(Failure(
            "give either --tolerance (adaptive sampling) or --fps (fixed rate), not both".into(),
        ));
    }
    Ok(o)
}

/// The `.gltf` + `.bin` pair for `OUT`: a `.gltf`/`.glb`/`.bin` extension of `OUT` is replaced,
/// anything else is kept (`out.v2` gives `out.v2.gltf` + `out.v2.bin`).
fn gltf_paths(out: &str) -> (PathBuf, PathBuf) {
    let stem = [".gltf", ".glb", ".bin"]
        .iter()
        .find_map(|ext| out.strip_suffix(ext))
        .unwrap_or(out);
    (
        PathBuf::from(format!("{stem}.gltf")),
        PathBuf::from(format!("{stem}.bin")),
    )
}

fn write(path: &Path, data: &[u8]) -> Result<(), Failure> {
    std::fs::write(path, data).map_err(|e| Failure(format!("{}: {e}", path.display())))
}

/// Runs `screwbender export`; returns what goes to standard output (CSV without `-o`).
pub fn export(args: &[String]) -> Result<String, Failure> {
    let o = parse(args)?;
    let format = o
        .format
        .ok_or_else(|| Failure("export needs --format glb|gltf|csv".into()))?;
    if format != Format::Csv && o.output.is_none() {
        return Err(Failure("export --format glb|gltf needs -o OUT".into()));
    }
    if o.point.is_some() && format != Format::Csv {
        return Err(Failure(
            "--point (a body-point trajectory) needs --format csv".into(),
        ));
    }
    let doc = read_document(o.file.as_deref())?;
    let closed = doc.closed && !o.sub.open;
    let n = doc.poses.len();
    let coarse_spans = if closed { n } else { n - 1 };
    let timing = match &o.times {
        Some(t) => Timing::new(t.clone(), closed)?,
        None => Timing::uniform(n, closed),
    };
    if timing.knots().len() != coarse_spans + 1 {
        return Err(Failure(format!(
            "times: {} times given, expected {} ({} control poses{})",
            timing.knots().len(),
            coarse_spans + 1,
            n,
            if closed {
                ", plus the time pose 0 is reached again"
            } else {
                ""
            }
        )));
    }
    let sub = o.sub.subdivision(5)?;
    let (motion, polyscrew): (Box<dyn Motion>, Polyscrew) = if sub.levels == 0 {
        let p = Polyscrew::new(doc.poses.clone(), closed)?;
        (Box::new(p.clone()), p)
    } else {
        let sb = ScrewBender::new(doc.poses.clone(), closed, sub)?;
        let p = sb.refined().clone();
        (Box::new(sb), p)
    };
    let tolerance = o.tolerance.unwrap_or(DEFAULT_TOLERANCE);
    let samples = match o.fps {
        Some(fps) => sample_fixed_rate(motion.as_ref(), &timing, fps)?,
        None => sample_polyscrew(&polyscrew, coarse_spans, &timing, tolerance)?,
    };
    let sampling = match o.fps {
        Some(fps) => format!("{fps} fps"),
        None => format!("tolerance {tolerance:e}"),
    };
    let mut stdout = String::new();
    let written = match format {
        Format::Csv => {
            let text = match o.point {
                Some(p) => trajectory_csv(&samples, p),
                None => poses_csv(&samples),
            };
            match &o.output {
                Some(out) => {
                    write(Path::new(out), text.as_bytes())?;
                    out.clone()
                }
                None => {
                    stdout = text;
                    "standard output".into()
                }
            }
        }
        Format::Glb | Format::Gltf => {
            let mesh = doc
                .name
                .as_deref()
                .and_then(scenes::scene)
                .map(|sc| Mesh::from_shape(&sc.shape));
            let asset = GltfAsset::new(&GltfMotion {
                name: doc.name.as_deref(),
                samples: &samples,
                control: &doc.poses,
                control_times: timing.knots(),
                closed,
                mesh: mesh.as_ref(),
                tolerance: o.fps.is_none().then_some(tolerance),
                control_nodes: o.control_nodes,
            })?;
            let out = o.output.as_deref().expect("checked above");
            if format == Format::Glb {
                write(Path::new(out), &asset.to_glb())?;
                out.to_string()
            } else {
                let (gltf, bin) = gltf_paths(out);
                let bin_name = bin
                    .file_name()
                    .and_then(|f| f.to_str())
                    .ok_or_else(|| Failure(format!("{out}: not a valid file name")))?;
                write(&gltf, asset.to_gltf(bin_name).as_bytes())?;
                write(&bin, asset.bin())?;
                format!("{} + {}", gltf.display(), bin.display())
            }
        }
    };
    if o.verbose {
        eprintln!(
            "screwbender: export: {} samples ({sampling}, {}) -> {written}",
            samples.len(),
            motion.name()
        );
    }
    Ok(stdout)
}
