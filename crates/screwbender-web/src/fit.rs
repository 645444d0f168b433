//! `fitPoses(document, options)`: the control poses of a smooth motion fitted to the many
//! measured poses of a document (an imported CSV or glTF animation), with the residual report —
//! [`screwbender::fit_poses`], as `screwbender fit` runs it (docs/math/fitting.md).

use js_sys::Object;
use serde::Deserialize;
use wasm_bindgen::prelude::*;

use super::convert::{check_keys, check_object, document_from_js, document_to_js, from_js, plain};
use super::files::set;
use screwbender::{
    fit_poses, measure_fit, ControlCount, Error, ErrorKind, FitMethod, FitOptions, FitReport,
    RobustLoss,
};

#[wasm_bindgen(typescript_custom_section)]
const TS_FIT: &'static str = r#"
/** Options of `fitPoses`: exactly one of `controls` and `tolerance`. */
export interface FitPosesOptions {
  /** The motion fitted (default `"screwbender"`, its cubic B-spline scheme). */
  method?: "screwbender" | "se3bspline";
  /** This many control poses (≥ 2, at most the number of samples). */
  controls?: number;
  /** As few control poses as keep the RMS deviation (distance + radius × angle) within this. */
  tolerance?: number;
  /** Weight of the smoothness term (default 0). */
  smoothness?: number;
  /** Robust loss against outliers (default `"none"`). */
  robust?: "none" | "huber" | "cauchy";
  /** The robust loss's scale (default 1.5 × the median residual of the least-squares fit). */
  robustScale?: number;
  /** Length weighing angles against distances: the body's extent around its origin (default 1). */
  radius?: number;
}

/** How far a fitted motion is from the measured poses (distances in scene units, angles in radians). */
export interface FitReport {
  controls: number;
  samples: number;
  rmsPosition: number;
  maxPosition: number;
  rmsAngle: number;
  maxAngle: number;
  rmsDeviation: number;
  maxDeviation: number;
  iterations: number;
}

/** Options of `measureFit`. */
export interface MeasureFitOptions {
  /** The motion the control poses are of (default `"screwbender"`, its cubic B-spline scheme). */
  method?: "screwbender" | "se3bspline";
  /** Length weighing angles against distances in the deviation (default 1). */
  radius?: number;
}

/** A fitted motion: its open document (key times spread over the samples' times) and its residuals. */
export interface FittedMotion {
  document: MotionDocument;
  report: FitReport;
}
"#;

/// The control poses of a smooth open motion fitted to the poses of `document` at their times
/// (see `FitPosesOptions` in the typings), and the residual report. Throws naming the bad
/// element (`options.controls`, `times[3]`, `poses[5]`, …); nothing else changes.
#[wasm_bindgen(js_name = fitPoses, unchecked_return_type = "FittedMotion")]
pub fn fit_poses_js(
    #[wasm_bindgen(unchecked_param_type = "MotionDocumentInput")] document: JsValue,
    #[wasm_bindgen(unchecked_param_type = "FitPosesOptions")] options: JsValue,
) -> Result<JsValue, JsError> {
    #[derive(Deserialize)]
    #[serde(deny_unknown_fields, rename_all = "camelCase")]
    struct Options {
        method: Option<String>,
        controls: Option<f64>,
        tolerance: Option<f64>,
        smoothness: Option<f64>,
        robust: Option<String>,
        robust_scale: Option<f64>,
        radius: Option<f64>,
    }
    const KEYS: &[&str] = &[
        "method",
        "controls",
        "tolerance",
        "smoothness",
        "robust",
        "robustScale",
        "radius",
    ];
    let doc = document_from_js(&document)?;
    let options = plain(&options, "options")?;
    check_object(
        &options,
        "options",
        "fit options",
        "{controls} or {tolerance}",
    )?;
    check_keys(&options, KEYS, "options", "fit options")?;
    let o: Options = from_js(&options, "options", "fit options")?;
    let within = |e: Error| e.within("options");
    let method = match &o.method {
        Some(m) => FitMethod::from_name(m).map_err(within)?,
        None => FitMethod::ScrewBender,
    };
    let robust = match &o.robust {
        Some(r) => RobustLoss::from_name(r).map_err(within)?,
        None => RobustLoss::None,
    };
    let controls = match (o.controls, o.tolerance) {
        (Some(n), None) => {
            if !(n.is_finite() && n.fract() == 0.0 && (2.0..=1e9).contains(&n)) {
                return Err(Error::new(
                    "options.controls",
                    ErrorKind::OutOfRange {
                        value: n.to_string(),
                        expected: "a whole number ≥ 2".into(),
                    },
                )
                .into());
            }
            ControlCount::Count(n as usize)
        }
        (None, Some(t)) => ControlCount::Tolerance(t),
        _ => {
            return Err(Error::new(
                "options",
                ErrorKind::Unsupported {
                    reason: "give exactly one of controls and tolerance".into(),
                },
            )
            .into())
        }
    };
    let defaults = FitOptions::default();
    let fit = fit_poses(
        &doc,
        &FitOptions {
            method,
            controls,
            smoothness: o.smoothness.unwrap_or(defaults.smoothness),
            robust,
            robust_scale: o.robust_scale,
            radius: o.radius.unwrap_or(defaults.radius),
            ..defaults
        },
    )
    .map_err(|e| match e.path() {
        // Option errors are named as the options object spells them.
        "smoothness" | "radius" | "tolerance" | "controls" => e.within("options"),
        "robust_scale" => Error::new("options.robustScale", e.kind().clone()),
        _ => e,
    })?;
    let report = report_to_js(&fit.report);
    let out = Object::new();
    set(&out, "document", document_to_js(&fit.document)?);
    set(&out, "report", report);
    Ok(out.into())
}

/// How far the motion whose control poses (and key times) are those of `document` is from the
/// poses of `samples` at their times: the `FitReport` a fit gives for its own result
/// (`iterations` 0), for any motion — a fit, a reduction, poses moved by hand. Throws naming
/// the bad element (`controls.times[2]`, `samples.poses[5]`, `options.radius`, …).
#[wasm_bindgen(js_name = measureFit, unchecked_return_type = "FitReport")]
pub fn measure_fit_js(
    #[wasm_bindgen(unchecked_param_type = "MotionDocumentInput")] document: JsValue,
    #[wasm_bindgen(unchecked_param_type = "MotionDocumentInput")] samples: JsValue,
    #[wasm_bindgen(unchecked_param_type = "MeasureFitOptions | undefined")] options: JsValue,
) -> Result<JsValue, JsError> {
    #[derive(Deserialize)]
    #[serde(deny_unknown_fields)]
    struct Options {
        method: Option<String>,
        radius: Option<f64>,
    }
    let controls = document_from_js(&document).map_err(|e| e.within("controls"))?;
    let samples = document_from_js(&samples).map_err(|e| e.within("samples"))?;
    let o = if options.is_undefined() || options.is_null() {
        Options {
            method: None,
            radius: None,
        }
    } else {
        let options = plain(&options, "options")?;
        check_object(&options, "options", "measure options", "{method, radius}")?;
        check_keys(
            &options,
            &["method", "radius"],
            "options",
            "measure options",
        )?;
        from_js(&options, "options", "measure options")?
    };
    let method = match &o.method {
        Some(m) => FitMethod::from_name(m).map_err(|e| e.within("options"))?,
        None => FitMethod::ScrewBender,
    };
    let radius = o.radius.unwrap_or(FitOptions::default().radius);
    let report = measure_fit(&controls, &samples, method, radius).map_err(|e| match e.path() {
        "radius" => e.within("options"),
        _ => e,
    })?;
    Ok(report_to_js(&report))
}

/// A `FitReport` as the typings spell it.
fn report_to_js(r: &FitReport) -> JsValue {
    let report = Object::new();
    for (key, value) in [
        ("controls", r.controls as f64),
        ("samples", r.samples as f64),
        ("rmsPosition", r.rms_position),
        ("maxPosition", r.max_position),
        ("rmsAngle", r.rms_angle),
        ("maxAngle", r.max_angle),
        ("rmsDeviation", r.rms_deviation),
        ("maxDeviation", r.max_deviation),
        ("iterations", r.iterations as f64),
    ] {
        set(&report, key, value.into());
    }
    report.into()
}
