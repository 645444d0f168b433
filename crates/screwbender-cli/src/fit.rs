//! `screwbender fit FILE [-o OUT] --method screwbender|se3bspline (--controls N | --tolerance T)
//! [--smoothness W] [--robust none|huber|cauchy] [--radius R] [--json]`: the control poses of a
//! smooth motion fitted to the many timestamped poses of a glTF animation, a CSV file or a
//! motion document (docs/math/fitting.md), with the residual report. `--measure MOTION` fits
//! nothing and reports how far that motion is from the poses (the core's `measure_fit`).

use std::path::Path;

use screwbender::frontend::files::import_motion_path;
use screwbender::{
    fit_poses, measure_fit, ControlCount, FitMethod, FitOptions, FitReport, NodeSelection,
    RobustLoss,
};
use serde_json::json;

use crate::cli::FitArgs;
use crate::failure::Failure;
use crate::output::Output;

/// The report as JSON (the field names of [`FitReport`]).
pub fn report_json(method: FitMethod, r: &FitReport) -> serde_json::Value {
    json!({
        "method": method.name(),
        "controls": r.controls,
        "samples": r.samples,
        "rms_position": r.rms_position,
        "max_position": r.max_position,
        "rms_angle": r.rms_angle,
        "max_angle": r.max_angle,
        "rms_deviation": r.rms_deviation,
        "max_deviation": r.max_deviation,
        "iterations": r.iterations,
    })
}

/// The report as lines of text.
fn report_text(method: FitMethod, r: &FitReport) -> String {
    format!(
        "fit: {} control poses ({}) to {} samples in {} iterations\n\
         position: RMS {:.6e}, max {:.6e}\n\
         angle (rad): RMS {:.6e}, max {:.6e}\n\
         deviation: RMS {:.6e}, max {:.6e}\n",
        r.controls,
        method.name(),
        r.samples,
        r.iterations,
        r.rms_position,
        r.max_position,
        r.rms_angle,
        r.max_angle,
        r.rms_deviation,
        r.max_deviation
    )
}

/// Runs `screwbender fit`: with `-o`, the document goes to OUT and the report to standard
/// output; without, the document to standard output and the report (as text) to standard error.
pub fn fit(args: FitArgs) -> Result<Output, Failure> {
    let method = FitMethod::from_name(&args.method).map_err(|e| Failure(format!("--{e}")))?;
    if let Some(motion) = &args.measure {
        return measure(&args, method, motion);
    }
    let robust = RobustLoss::from_name(&args.robust).map_err(|e| Failure(format!("--{e}")))?;
    let controls = match (args.controls, args.tolerance) {
        (Some(n), None) => ControlCount::Count(n),
        (None, Some(t)) => ControlCount::Tolerance(t),
        _ => {
            return Err(Failure(
                "fit needs exactly one of --controls N and --tolerance T".into(),
            ))
        }
    };
    let options = FitOptions {
        method,
        controls,
        smoothness: args.smoothness,
        robust,
        robust_scale: None,
        radius: args.radius,
        ..FitOptions::default()
    };
    let file = args
        .file
        .ok_or_else(|| Failure("fit needs a FILE (.glb, .gltf, .csv or .json)".into()))?;
    let doc = import_motion_path(Path::new(&file), &NodeSelection::Auto)
        .map_err(|e| Failure(e.to_string()))?;
    let fitted = fit_poses(&doc, &options).map_err(|e| Failure(format!("fit: {e}")))?;
    let report = report_in(args.json, method, &fitted.report)?;
    let document = fitted.document;
    let text = Output::writer(move |w| document.write_json(w));
    match args.output {
        Some(out) => {
            text.write_file(&out)?;
            Ok(Output::text(report))
        }
        None => {
            eprint!("{report}");
            Ok(text)
        }
    }
}

/// The report as `--json` asks.
fn report_in(json: bool, method: FitMethod, r: &FitReport) -> Result<String, Failure> {
    Ok(if json {
        format!(
            "{}\n",
            serde_json::to_string_pretty(&report_json(method, r))
                .map_err(|e| Failure(e.to_string()))?
        )
    } else {
        report_text(method, r)
    })
}

/// `screwbender fit FILE --measure MOTION`: the report of MOTION against FILE's poses, on
/// standard output.
fn measure(args: &FitArgs, method: FitMethod, motion: &str) -> Result<Output, Failure> {
    let file = args
        .file
        .as_deref()
        .ok_or_else(|| Failure("fit needs a FILE (.glb, .gltf, .csv or .json)".into()))?;
    let samples = import_motion_path(Path::new(file), &NodeSelection::Auto)
        .map_err(|e| Failure(e.to_string()))?;
    let controls = import_motion_path(Path::new(motion), &NodeSelection::Auto)
        .map_err(|e| Failure(format!("--measure: {e}")))?;
    let report = measure_fit(&controls, &samples, method, args.radius)
        .map_err(|e| Failure(format!("fit --measure: {e}")))?;
    Ok(Output::text(report_in(args.json, method, &report)?))
}
