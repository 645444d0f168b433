//! `screwbender compare [--methods a,b,c] [--json] [FILE]`: the metrics of the comparison
//! methods on one set of control poses, as an aligned text table or JSON; and `screwbender
//! rational`: the Chaudhry–Cameron motion's rational Bézier form, from poses or triangles; and
//! the warning lines where a result is silently poor.

use std::io::Read;
use std::time::Instant;

use glam::DQuat;

use screwbender::frontend::compare::{parse_methods, split_names};
use screwbender::methods::{
    fit_barr, fit_quaternion_spline, triangle_samples, BarrOptions, Continuity, EndCondition,
    Method, RationalMotion, RbOptions, ReferenceTriangle, TriangleSample, TRIANGLE_STRIDE,
};
use screwbender::{Error, ErrorKind, Pose, Subdivision, MAX_DOCUMENT_BYTES};

use crate::cli::RationalArgs;
use crate::failure::Failure;
use crate::input::read_document;

/// The comparison table of the named `methods` on `poses` (pose `i` at parameter `u = i`; a
/// closed input is a cycle of period `n`).
///
/// Names are those of [`Method::NAMES`]; each entry may also be a comma-separated list
/// (`"rb,cc0"`), duplicates are measured once. With no names, every method that applies is used
/// (all but `cc1` for a closed input), and one that does not support these particular poses is
/// listed as skipped. An unknown name gives [`ErrorKind::UnknownValue`] at `methods`; a named method
/// that rejects the input (e.g. `cc1` on a closed input) gives its error, prefixed with the
/// method's name. A motion that is poor though it was built ([`Method::warnings`]) is noted in
/// its row and gets a `screwbender: warning: METHOD: …` line on standard error.
pub fn compare(
    poses: &[Pose],
    closed: bool,
    methods: &[String],
    json: bool,
) -> Result<String, Error> {
    let names = split_names(methods);
    let chosen = parse_methods(&names)?;
    let table = screwbender::frontend::compare::compare(
        poses,
        closed,
        (!names.is_empty()).then_some(&names[..]),
        None,
    )?;
    // Where a motion is poor though it was built: one line each on standard error.
    for row in &table.rows {
        for note in &row.notes {
            if let Some(w) = note.strip_prefix("warning: ") {
                eprintln!("screwbender: warning: {}: {w}", row.method);
            }
        }
    }
    if !chosen.contains(&Method::Barr) {
        return Ok(if json {
            table.to_json() + "\n"
        } else {
            table.to_text()
        });
    }
    // The discrete baseline named: its objective and time beside Ramamoorthi–Barr's.
    let o = objectives(poses, closed)?;
    Ok(if json {
        let mut v: serde_json::Value = serde_json::from_str(&table.to_json()).map_err(|e| {
            Error::new(
                "table",
                ErrorKind::Parse {
                    message: e.to_string(),
                },
            )
        })?;
        v["objectives"] = serde_json::json!({
            "rb": {"objective": o.rb, "seconds": o.rb_seconds},
            "barr": {"objective": o.barr, "seconds": o.barr_seconds, "frames": o.frames,
                     "iterations": o.iterations},
        });
        v.to_string() + "\n"
    } else {
        format!(
            "{}\nObjective (3) of Ramamoorthi–Barr (docs/math/quaternion-splines.md §2, §9):\n  \
             rb    {:.6}  in {:.4} s ({} variable frames)\n  \
             barr  {:.6}  in {:.4} s ({} frames, {} Gauss–Newton steps)\n  \
             rb/barr: objective {:.5}, time {:.3}\n",
            table.to_text(),
            o.rb,
            o.rb_seconds,
            o.rb_frames,
            o.barr,
            o.barr_seconds,
            o.frames,
            o.iterations,
            o.rb / o.barr,
            o.rb_seconds / o.barr_seconds,
        )
    })
}

/// Ramamoorthi–Barr's objective and the discrete baseline's on the same rotations, with the
/// time each fit took here.
struct Objectives {
    rb: f64,
    rb_seconds: f64,
    rb_frames: usize,
    barr: f64,
    barr_seconds: f64,
    frames: usize,
    iterations: usize,
}

fn objectives(poses: &[Pose], closed: bool) -> Result<Objectives, Error> {
    let keys: Vec<DQuat> = poses.iter().map(|p| p.rotation).collect();
    let times: Vec<f64> = (0..keys.len()).map(|i| i as f64).collect();
    if closed {
        return Err(Error::new(
            "barr",
            ErrorKind::Unsupported {
                reason: "the discrete baseline of Barr et al. is built for open sequences only"
                    .into(),
            },
        ));
    }
    let start = Instant::now();
    let rb = fit_quaternion_spline(&times, &keys, false, &RbOptions::default())?;
    let rb_seconds = start.elapsed().as_secs_f64();
    let start = Instant::now();
    let barr = fit_barr(&times, &keys, &BarrOptions::for_keys(keys.len()))?;
    let barr_seconds = start.elapsed().as_secs_f64();
    Ok(Objectives {
        rb: rb.spline.objective(),
        rb_seconds,
        rb_frames: rb.stages.last().map_or(0, |s| s.variable_frames),
        barr: barr.objective,
        barr_seconds,
        frames: barr.frames.len(),
        iterations: barr.iterations,
    })
}

/// Prints a `screwbender: warning: …` line on standard error for each place where subdividing
/// `poses` gives a poor result without an error (`Subdivision::warnings`), for `subdivide`,
/// `eval` and `export`; standard output is untouched.
pub fn warn_subdivision(sub: &Subdivision, poses: &[Pose], closed: bool) {
    for w in sub.warnings(poses, closed) {
        eprintln!("screwbender: warning: {w}");
    }
}

/// The options of `screwbender rational`, checked.
struct RationalOptions {
    continuity: Continuity,
    triangles: bool,
    closing_time: Option<f64>,
    file: Option<String>,
}

fn rational_options(a: RationalArgs) -> Result<RationalOptions, Failure> {
    let c1 = match a.continuity.map(|c| c.to_ascii_lowercase()).as_deref() {
        None | Some("c1") => true,
        Some("c0") => false,
        Some(other) => {
            return Err(Failure(format!(
                "--continuity: unknown value '{other}' (expected c0 or c1)"
            )))
        }
    };
    let end = match a.end.as_deref() {
        None | Some("18") => EndCondition::ZeroCurvatureStart,
        Some("19") => EndCondition::ZeroCurvatureEnd,
        Some(other) => {
            return Err(Failure(format!(
                "--end: unknown value '{other}' (expected 18: zero curvature at the start, or \
                 19: at the end)"
            )))
        }
    };
    Ok(RationalOptions {
        continuity: if c1 {
            Continuity::C1(end)
        } else {
            Continuity::C0
        },
        triangles: a.triangles,
        closing_time: a.closing_time,
        file: a.file,
    })
}

/// The text of `file` (`None` or `-`: standard input), at most [`MAX_DOCUMENT_BYTES`], and the
/// name to report it by.
fn read_text(file: Option<&str>) -> Result<(String, String), Failure> {
    let mut text = String::new();
    let name = match file {
        None | Some("-") => {
            std::io::stdin()
                .take(MAX_DOCUMENT_BYTES as u64 + 1)
                .read_to_string(&mut text)
                .map_err(|e| Failure(format!("standard input: {e}")))?;
            "standard input".to_string()
        }
        Some(path) => {
            std::fs::File::open(path)
                .and_then(|f| {
                    f.take(MAX_DOCUMENT_BYTES as u64 + 1)
                        .read_to_string(&mut text)
                })
                .map_err(|e| Failure(format!("{path}: {e}")))?;
            path.to_string()
        }
    };
    if text.len() > MAX_DOCUMENT_BYTES {
        return Err(Failure(format!(
            "{name}: larger than the limit of {MAX_DOCUMENT_BYTES} bytes"
        )));
    }
    Ok((name, text))
}

/// A raw triangle sequence: one key per line, `t` and the vertices `a`, `x`, `y` (10 numbers
/// separated by commas or spaces); empty lines and `#` comments are skipped.
fn parse_triangles(text: &str) -> Result<Vec<TriangleSample>, Error> {
    let mut data = Vec::new();
    for (i, line) in text.lines().enumerate() {
        let line = line.split('#').next().unwrap_or("").trim();
        if line.is_empty() {
            continue;
        }
        let fields: Vec<&str> = line
            .split(|c: char| c == ',' || c.is_whitespace())
            .filter(|f| !f.is_empty())
            .collect();
        let at = format!("line {}", i + 1);
        if fields.len() != TRIANGLE_STRIDE {
            return Err(Error::new(
                at,
                ErrorKind::OutOfRange {
                    value: format!("{} numbers", fields.len()),
                    expected: format!("{TRIANGLE_STRIDE}: t, then a, x, y (3 each)"),
                },
            ));
        }
        for f in fields {
            data.push(f.parse::<f64>().map_err(|_| {
                Error::new(
                    at.clone(),
                    ErrorKind::Parse {
                        message: format!("'{f}' is not a number"),
                    },
                )
            })?);
        }
    }
    triangle_samples(&data)
}

/// `screwbender rational [--continuity c0|c1] [--end 18|19] [--triangles] [--closing-time T]
/// [FILE]`: the Chaudhry–Cameron rational motion (docs/math/rational-motion.md) as its rational
/// Bézier control points (JSON), fitted to a motion document's poses (at the document's key
/// times, else one second per span) or, with `--triangles`, to a raw triangle sequence
/// ([`parse_triangles`]; closed only with `--closing-time`, C⁰). A C¹ fit whose recursion runs
/// away gets a `screwbender: warning: …` line on standard error.
pub fn rational(args: RationalArgs) -> Result<String, Failure> {
    let o = rational_options(args)?;
    let motion = if o.triangles {
        let (name, text) = read_text(o.file.as_deref())?;
        let samples = parse_triangles(&text).map_err(|e| Failure(format!("{name}: {e}")))?;
        match o.closing_time {
            Some(tc) => RationalMotion::fit_closed(&samples, tc, o.continuity)?,
            None => RationalMotion::fit(&samples, o.continuity)?,
        }
    } else {
        if o.closing_time.is_some() {
            return Err(Failure(
                "--closing-time is for --triangles (a document gives its own times)".into(),
            ));
        }
        let doc = read_document(o.file.as_deref())?;
        let times = doc.times.clone().unwrap_or_else(|| {
            (0..doc.poses.len() + usize::from(doc.closed))
                .map(|i| i as f64)
                .collect()
        });
        RationalMotion::from_poses(
            &doc.poses,
            &times,
            doc.closed,
            o.continuity,
            &ReferenceTriangle::SCENE_B1,
        )?
    };
    if let Some(w) = motion.warning() {
        eprintln!("screwbender: warning: {w}");
    }
    let bezier = serde_json::to_string_pretty(&motion.bezier())
        .map_err(|e| Failure(format!("writing the Bézier form: {e}")))?;
    Ok(bezier + "\n")
}
