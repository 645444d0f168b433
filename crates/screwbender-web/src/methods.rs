//! The comparison methods for JavaScript (module [`screwbender::methods`]): every method built on a
//! `Motion`'s control poses, sampled for display, measured by the same metrics as
//! `screwbender compare`, and the Ramamoorthi–Barr construction in detail (stages, variable
//! frames, Euler–Lagrange error).

use std::str::FromStr;

use glam::DQuat;
use serde::Serialize;
use wasm_bindgen::prelude::*;

use super::convert::{count, is_absent, plain, poses_from_fn, push_kinematics, to_js};
use super::motion::sample_parameters;
use super::MotionHandle;
use screwbender::methods::{
    fit_barr, fit_quaternion_spline, interpolation_error, kinematics_at, single_step_metrics,
    triangle_samples, BarrOptions, Continuity, Derivatives, EndCondition, Method, MetricsOptions,
    RationalMotion, RbOptions, ReferenceTriangle, Side, SingleStepMetrics, TRIANGLE_STRIDE,
};
use screwbender::{
    Error, ErrorKind, Motion, MotionDocument, Pose, Scheme, ScrewBender, Subdivision,
    MAX_REFINED_POSES,
};

#[wasm_bindgen(typescript_custom_section)]
const TS_METHODS: &'static str = r#"
/** Names of the motion methods (see `methods()`). */
export type MethodId =
  'polyscrew' | 'bspline' | 'fourpoint' | 'jarek' | 'slerp' | 'decoupled' | 'kks' | 'se3bspline'
  | 'se3interp' | 'splitinterp' | 'rb' | 'cc0' | 'cc1' | 'barr';

/** A motion method of the comparison. */
export interface MethodInfo {
  id: MethodId;
  /** Human-readable name, e.g. `Chaudhry–Cameron C¹ (end condition 18)`. */
  title: string;
  /** Whether it has a closed (cyclic) form. */
  supportsClosed: boolean;
}

/**
 * One row of `Motion.compareMethods` (the fields of `screwbender compare --json` and of Python's
 * `compare_methods`, snake_case; a metric that could not be computed is absent, with the reason
 * in `notes`). The smoothness fields are the converged values, measured the same way for every
 * method; `single_step` holds the same metrics at one step along the method's own derivative
 * route, for diagnosis only.
 */
export interface MetricsRow extends ConvergedMetrics {
  method: MethodId;
  motion: string;
  interpolation_error: number;
  frame_dependence?: number;
  line_error?: number;
  circle_error?: number;
  helix_error?: number;
  notes: string[];
  single_step: SingleStepMetrics;
}

/** Smoothness metrics at one step along a motion's own derivative route (analytic, finite differences, or differences of refined poses): not comparable across methods. */
export interface SingleStepMetrics {
  /** `analytic`, `finite differences, …` or `pose differences, step h`. */
  derivatives: string;
  velocity_jump: number;
  angular_velocity_jump: number;
  acceleration_jump: number;
  angular_acceleration_jump: number;
  acceleration_energy: number[];
  angular_acceleration_energy: number;
}

/** `Motion.motionMetrics`: this motion's own metrics at its refined span, and its interpolation error. */
export interface MotionMetricsRow extends SingleStepMetrics {
  interpolation_error: number;
}

/** What a converged metric tends to: a value, zero, an impulse at the knots (the value is the size of the velocity jump that carries it) or nothing (divergent). */
export type MetricLimit = 'value' | 'zero' | 'impulse' | 'diverges';

/** One converged metric: its limit, the extrapolated value, a bound on its error, and the raw estimates at the three steps. */
export interface ConvergedMetric {
  limit: MetricLimit;
  value: number;
  error: number;
  estimates: [number, number, number];
}

/** The converged smoothness metrics of one method (the same derivative route and steps for every method). */
export interface ConvergedMetrics {
  steps: [number, number, number];
  velocity_jump: ConvergedMetric;
  angular_velocity_jump: ConvergedMetric;
  acceleration_jump: ConvergedMetric;
  angular_acceleration_jump: ConvergedMetric;
  acceleration_energy: ConvergedMetric[];
  angular_acceleration_energy: ConvergedMetric;
}

/** The metrics table (see `MetricsRow`). */
export interface MetricsTable {
  pose_count: number;
  closed: boolean;
  body_points: Vec3[];
  rows: MetricsRow[];
  skipped: string[];
}

/** Options of `Motion.rational` and `Motion.rationalFromTriangles` (Chaudhry–Cameron). */
export interface RationalOptions {
  /** `'c1'` (default): quadratic quaternion spline; `'c0'`: piecewise linear quaternions. */
  continuity?: 'c0' | 'c1';
  /** C¹ end condition: 18 (default, zero curvature at the start) or 19 (at the end). */
  end?: 18 | 19;
  /** Uniform samples of the vertex trajectories (default 200, 2 to 100 000). */
  samples?: number;
  /** `rationalFromTriangles` only: close the motion (C⁰) back to the first key at this time. */
  closingTime?: number;
}

/** One segment of the rational Bézier form (homogeneous control points `ω_k c_k`). */
export interface RationalBezierSegment {
  t_start: number;
  t_end: number;
  /** 2 (C⁰) or 4 (C¹). */
  degree: number;
  weights: number[];
  /** `[w, x, y, z]`: `Q_i, Q_{i+1}` (C⁰) or `Q_i, M_i, Q_{i+1}` (C¹). */
  quaternions: number[][];
  a: Vec3[];
  x: Vec3[];
  y: Vec3[];
}

/** The Chaudhry–Cameron motion: its rational Bézier form and the triangle's vertex paths. */
export interface RationalReport {
  bezier: { continuity: string; reference: Vec3[]; segments: RationalBezierSegment[] };
  /** How far the C¹ recursion has carried the middle control points (0 for C⁰). */
  growth: number;
  /** The smallest denominator |Q(t)|². */
  minDenominator: number;
  /** Where the motion is poor though it was built (the C¹ recursion running away). */
  warnings: string[];
  /** Sample times, and the vertices a, x, y at each (9 numbers per sample). */
  t: Float64Array;
  vertices: Float64Array;
}

/** The discrete baseline of Barr et al. (`Motion.barrBaseline`). */
export interface BarrReport {
  /** The objective (3) reached: covariant acceleration plus unit penalty. */
  objective: number;
  covariantAcceleration: number;
  /** The objective of the SLERP polyline it starts from. */
  initialObjective: number;
  frames: number;
  iterations: number;
}

/** Options of `Motion.quaternionSpline` (Ramamoorthi–Barr). */
export interface QuaternionSplineOptions {
  /** Unit-norm penalty weight α (default 1000). */
  alpha?: number;
  /** Variable frames to insert (default 4). */
  variableFrames?: number;
  /** Samples of the Euler–Lagrange error and |q| (default 600). */
  samples?: number;
}

/** The Ramamoorthi–Barr construction on a motion's rotations (keyframe i at t = i). */
export interface QuaternionSplineReport {
  /** One entry per stage: initial, keyframe velocities optimised, then one per inserted frame. */
  stages: { variable_frames: number; inserted_at?: number; objective: number; iterations: number }[];
  /** Times of the keyframes and of the variable frames. */
  keyTimes: number[];
  frameTimes: number[];
  /** Sample times, |EL(t)| before and after optimisation, and |q(t)| after. */
  t: Float64Array;
  elBefore: Float64Array;
  elAfter: Float64Array;
  norm: Float64Array;
  /** max | |q| − 1 | before and after. */
  unitDeviationBefore: number;
  unitDeviationAfter: number;
}
"#;

fn method(name: &JsValue, at: &str) -> Result<Method, Error> {
    let name = name.as_string().ok_or_else(|| {
        Error::new(
            at,
            ErrorKind::Parse {
                message: "expected a method name".into(),
            },
        )
    })?;
    Method::from_str(&name).map_err(|e| match e.kind() {
        ErrorKind::UnknownValue { value, expected } => Error::new(
            at,
            ErrorKind::UnknownValue {
                value: value.clone(),
                expected,
            },
        ),
        _ => e,
    })
}

/// A human-readable title of each method.
fn title(m: Method) -> &'static str {
    match m {
        Method::Polyscrew => "Polyscrew (ScLERP polyline)",
        Method::BSpline => "ScrewBender B-spline",
        Method::FourPoint => "ScrewBender 4-point",
        Method::Jarek => "ScrewBender Jarek",
        Method::Slerp => "SLERP + linear translation",
        Method::Decoupled => "Decoupled: Catmull–Rom + Squad",
        Method::Kks => "Kim–Kim–Shin B-spline quaternions",
        Method::Se3BSpline => "SE(3) cumulative B-spline",
        Method::Se3Interp => "SE(3) cumulative B-spline, interpolating",
        Method::SplitInterp => "R³ × SO(3) cumulative B-spline, interpolating",
        Method::Rb => "Ramamoorthi–Barr quaternion spline",
        Method::Cc0 => "Chaudhry–Cameron rational C⁰",
        Method::Cc1 => "Chaudhry–Cameron rational C¹ (18)",
        Method::Barr => "Barr et al. discrete baseline (R–B objective, dense frames)",
    }
}

/// The motion methods of the comparison, in table order.
#[wasm_bindgen(unchecked_return_type = "MethodInfo[]")]
pub fn methods() -> Result<JsValue, JsError> {
    #[derive(Serialize)]
    #[serde(rename_all = "camelCase")]
    struct Info {
        id: &'static str,
        title: &'static str,
        supports_closed: bool,
    }
    let list: Vec<Info> = Method::ALL
        .iter()
        .map(|&m| Info {
            id: m.name(),
            title: title(m),
            supports_closed: m.supports_closed(),
        })
        .collect();
    to_js(&list)
}

/// Body points from an optional array of `[x, y, z]` (checked by the core).
fn body_points(value: &JsValue) -> Result<Option<Vec<[f64; 3]>>, Error> {
    if is_absent(value) {
        return Ok(None);
    }
    let v = plain(value, "bodyPoints")?;
    super::convert::from_js(&v, "bodyPoints", "body points").map(Some)
}

/// An optional non-negative number option.
fn option_number(obj: &JsValue, key: &str) -> Result<Option<f64>, Error> {
    let v = js_sys::Reflect::get(obj, &JsValue::from_str(key)).unwrap_or(JsValue::UNDEFINED);
    if is_absent(&v) {
        return Ok(None);
    }
    match v.as_f64() {
        Some(x) if x.is_finite() && x >= 0.0 => Ok(Some(x)),
        _ => Err(Error::new(
            format!("options.{key}"),
            ErrorKind::OutOfRange {
                value: format!("{v:?}"),
                expected: "a finite non-negative number".into(),
            },
        )),
    }
}

fn build(doc: &MotionDocument, m: Method) -> Result<Box<dyn Motion>, Error> {
    m.build(&doc.poses, doc.closed)
        .map_err(|e| e.within(m.name()))
}

#[wasm_bindgen(js_class = Motion)]
impl MotionHandle {
    /// `count` poses of `method` built on this motion's control poses (pose `i` at `u = i`),
    /// uniform over its domain (the end included for an open motion): 7 numbers per pose.
    /// Throws when the method does not apply (e.g. `cc1` on a cycle) or rejects the poses.
    #[wasm_bindgen(js_name = methodSample)]
    pub fn method_sample(
        &self,
        #[wasm_bindgen(unchecked_param_type = "MethodId")] name: JsValue,
        #[wasm_bindgen(unchecked_param_type = "number")] samples: JsValue,
    ) -> Result<Vec<f64>, JsError> {
        let m = method(&name, "method")?;
        let n = count(&samples, "count", MAX_REFINED_POSES)?;
        let (doc, _) = self.snapshot()?;
        let motion = build(&doc, m)?;
        let us: Vec<f64> = sample_parameters(motion.domain(), doc.closed, n).collect();
        Ok(poses_from_fn(n, |k| motion.pose_at(us[k])))
    }

    /// Kinematics of body point `local` of `method` at `count` uniform parameters, 16 numbers
    /// per sample as in `sampleKinematics` (analytic where the method has them, else finite
    /// differences).
    #[wasm_bindgen(js_name = methodKinematics)]
    pub fn method_kinematics(
        &self,
        #[wasm_bindgen(unchecked_param_type = "MethodId")] name: JsValue,
        #[wasm_bindgen(unchecked_param_type = "number")] samples: JsValue,
        #[wasm_bindgen(unchecked_optional_param_type = "Vec3")] local: JsValue,
    ) -> Result<Vec<f64>, JsError> {
        let m = method(&name, "method")?;
        let n = count(&samples, "count", MAX_REFINED_POSES)?;
        let local = super::convert::point_from_js(&local, "local")?;
        let (doc, _) = self.snapshot()?;
        let motion = build(&doc, m)?;
        let mut out = Vec::with_capacity(n * super::KINEMATICS_STRIDE);
        let end = motion.domain().1;
        for u in sample_parameters(motion.domain(), doc.closed, n) {
            // One-sided at the end of an open motion (nothing lies after it).
            let side = if u >= end { Side::Left } else { Side::Right };
            let k = kinematics_at(motion.as_ref(), u, local, side);
            push_kinematics(&mut out, u, &k);
        }
        Ok(out)
    }

    /// The metrics of `methods` (default: every method that applies) on this motion's control
    /// poses, as `screwbender compare --json` prints them. `bodyPoints` (default `[0,0,0]`,
    /// `[2,0,0]`) are the local points whose trajectories are measured.
    #[wasm_bindgen(js_name = compareMethods, unchecked_return_type = "MetricsTable")]
    pub fn compare(
        &self,
        #[wasm_bindgen(unchecked_optional_param_type = "MethodId[]")] names: JsValue,
        #[wasm_bindgen(js_name = bodyPoints, unchecked_optional_param_type = "Vec3[]")]
        points: JsValue,
    ) -> Result<JsValue, JsError> {
        let (doc, _) = self.snapshot()?;
        let names = if is_absent(&names) {
            None
        } else {
            let names = plain(&names, "methods")?;
            let arr = names.dyn_ref::<js_sys::Array>().ok_or_else(|| {
                Error::new(
                    "methods",
                    ErrorKind::Parse {
                        message: "expected an array of method names".into(),
                    },
                )
            })?;
            let texts = arr
                .iter()
                .enumerate()
                .map(|(i, v)| {
                    v.as_string().ok_or_else(|| {
                        Error::new(
                            format!("methods[{i}]"),
                            ErrorKind::Parse {
                                message: "expected a method name".into(),
                            },
                        )
                    })
                })
                .collect::<Result<Vec<_>, Error>>()?;
            Some(texts)
        };
        let table = screwbender::frontend::compare::compare(
            &doc.poses,
            doc.closed,
            names.as_deref(),
            body_points(&points)?.as_deref(),
        )?;
        to_js(&table)
    }

    /// The metrics of this motion itself (its scheme, rules and levels): velocity and
    /// acceleration jumps at the knots and the integrated squared accelerations, measured by
    /// differences of the refined poses (step: the refined span), and the interpolation error;
    /// plus `fourPointGap`, the largest distance between the 4-point motion at the same levels
    /// and the control poses (0 up to rounding: 4-point interpolates).
    #[wasm_bindgen(js_name = motionMetrics, unchecked_return_type = "{ row: MotionMetricsRow; fourPointGap: number }")]
    pub fn motion_metrics_js(
        &self,
        #[wasm_bindgen(js_name = bodyPoints, unchecked_optional_param_type = "Vec3[]")]
        points: JsValue,
    ) -> Result<JsValue, JsError> {
        let mut options = MetricsOptions::default();
        if let Some(p) = body_points(&points)? {
            options.body_points = screwbender::frontend::compare::body_points(&p)?;
        }
        let (doc, sub) = self.snapshot()?;
        let h = 0.5f64.powi(sub.levels as i32);
        let row = self.with_refined(|m| MotionMetricsRow {
            metrics: single_step_metrics(m, Derivatives::Sampled(h), &options),
            interpolation_error: interpolation_error(m, &doc.poses),
        })?;
        let four = Subdivision::new(Scheme::FourPoint, sub.rules, sub.levels);
        let four = ScrewBender::new(doc.poses.clone(), doc.closed, four)?;
        let gap = doc
            .poses
            .iter()
            .enumerate()
            .map(|(i, p)| {
                let q = four.pose_at(i as f64);
                p.origin.distance(q.origin) + p.rotation.angle_between(q.rotation)
            })
            .fold(0.0, f64::max);
        #[derive(Serialize)]
        #[serde(rename_all = "camelCase")]
        struct Out {
            row: MotionMetricsRow,
            four_point_gap: f64,
        }
        /// The row of `motionMetrics`: the single-step metrics with the interpolation error.
        #[derive(Serialize)]
        struct MotionMetricsRow {
            #[serde(flatten)]
            metrics: SingleStepMetrics,
            interpolation_error: f64,
        }
        to_js(&Out {
            row,
            four_point_gap: gap,
        })
    }

    /// The Ramamoorthi–Barr construction on this motion's rotations (keyframe `i` at `t = i`,
    /// free end velocities): its stages, variable frames, and the Euler–Lagrange error and
    /// `|q|` sampled before and after optimisation (docs/math/quaternion-splines.md §7).
    #[wasm_bindgen(js_name = quaternionSpline, unchecked_return_type = "QuaternionSplineReport")]
    pub fn quaternion_spline(
        &self,
        #[wasm_bindgen(unchecked_optional_param_type = "QuaternionSplineOptions")] options: JsValue,
    ) -> Result<JsValue, JsError> {
        let mut o = RbOptions::default();
        let mut samples = 600usize;
        if !is_absent(&options) {
            let v = plain(&options, "options")?;
            super::convert::check_keys(
                &v,
                &["alpha", "variableFrames", "samples"],
                "options",
                "quaternion spline options",
            )?;
            if let Some(a) = option_number(&v, "alpha")? {
                o.alpha = a;
            }
            if let Some(m) = option_number(&v, "variableFrames")? {
                o.variable_frames = integer(m, "options.variableFrames", 64)?;
            }
            if let Some(s) = option_number(&v, "samples")? {
                samples = integer(s, "options.samples", 100_000)?.max(2);
            }
        }
        let (doc, _) = self.snapshot()?;
        let closed = doc.closed;
        let keys: Vec<DQuat> = doc.poses.iter().map(|p: &Pose| p.rotation).collect();
        let times: Vec<f64> = (0..keys.len() + usize::from(closed))
            .map(|i| i as f64)
            .collect();
        let rename = |e: Error| e.within("quaternionSpline");
        let before = fit_quaternion_spline(
            &times,
            &keys,
            closed,
            &RbOptions {
                optimise: false,
                ..o
            },
        )
        .map_err(rename)?;
        let after = fit_quaternion_spline(&times, &keys, closed, &o).map_err(rename)?;
        let (a, b) = after.spline.domain();
        let mut t = Vec::with_capacity(samples);
        let (mut el_before, mut el_after, mut norm) = (Vec::new(), Vec::new(), Vec::new());
        for k in 0..samples {
            let x = a + (b - a) * k as f64 / (samples - 1) as f64;
            t.push(x);
            el_before.push(before.spline.euler_lagrange_at(x).norm());
            el_after.push(after.spline.euler_lagrange_at(x).norm());
            norm.push(after.spline.eval(x)[0].length());
        }
        #[derive(Serialize)]
        #[serde(rename_all = "camelCase")]
        struct Report<'a> {
            stages: &'a [screwbender::methods::RbStage],
            key_times: &'a [f64],
            frame_times: Vec<f64>,
            unit_deviation_before: f64,
            unit_deviation_after: f64,
        }
        let report = Report {
            stages: &after.stages,
            key_times: &after.key_times,
            frame_times: after
                .spline
                .frames()
                .iter()
                .filter(|f| !f.keyframe)
                .map(|f| f.t)
                .collect(),
            unit_deviation_before: before.spline.unit_deviation(samples).0,
            unit_deviation_after: after.spline.unit_deviation(samples).0,
        };
        let out = to_js(&report)?;
        for (key, data) in [
            ("t", t),
            ("elBefore", el_before),
            ("elAfter", el_after),
            ("norm", norm),
        ] {
            let arr = js_sys::Float64Array::from(&data[..]);
            // Setting a property of the plain object just made cannot fail.
            let _ = js_sys::Reflect::set(&out, &JsValue::from_str(key), &arr);
        }
        Ok(out)
    }
}

/// The options of `Motion.rational` / `Motion.rationalFromTriangles`: the continuity, the
/// number of trajectory samples and (`closing` allowed) the closing time.
fn rational_options(
    options: &JsValue,
    closing: bool,
) -> Result<(Continuity, usize, Option<f64>), Error> {
    let (mut c1, mut end, mut samples, mut closing_time) =
        (true, EndCondition::ZeroCurvatureStart, 200usize, None);
    if !is_absent(options) {
        let v = plain(options, "options")?;
        let keys: &[&str] = if closing {
            &["continuity", "end", "samples", "closingTime"]
        } else {
            &["continuity", "end", "samples"]
        };
        super::convert::check_keys(&v, keys, "options", "rational motion options")?;
        let get = |k: &str| js_sys::Reflect::get(&v, &JsValue::from_str(k)).unwrap_or_default();
        let c = get("continuity");
        if !is_absent(&c) {
            c1 = match c.as_string().as_deref() {
                Some("c0") => false,
                Some("c1") => true,
                _ => {
                    return Err(Error::new(
                        "options.continuity",
                        ErrorKind::UnknownValue {
                            value: format!("{c:?}"),
                            expected: "c0, c1",
                        },
                    ))
                }
            };
        }
        if let Some(e) = option_number(&v, "end")? {
            end = match e {
                18.0 => EndCondition::ZeroCurvatureStart,
                19.0 => EndCondition::ZeroCurvatureEnd,
                _ => {
                    return Err(Error::new(
                        "options.end",
                        ErrorKind::UnknownValue {
                            value: e.to_string(),
                            expected: "18, 19",
                        },
                    ))
                }
            };
        }
        if let Some(n) = option_number(&v, "samples")? {
            samples = integer(n, "options.samples", 100_000)?.max(2);
        }
        if closing {
            closing_time = option_number(&v, "closingTime")?;
        }
    }
    let continuity = if c1 {
        Continuity::C1(end)
    } else {
        Continuity::C0
    };
    Ok((continuity, samples, closing_time))
}

/// The report of a fitted rational motion (see `RationalReport`).
fn rational_report(motion: &RationalMotion, samples: usize) -> Result<JsValue, JsError> {
    #[derive(Serialize)]
    #[serde(rename_all = "camelCase")]
    struct Report {
        bezier: screwbender::methods::RationalBezierExport,
        growth: f64,
        min_denominator: f64,
        warnings: Vec<String>,
    }
    let out = to_js(&Report {
        bezier: motion.bezier(),
        growth: motion.growth(),
        min_denominator: motion.min_denominator(),
        warnings: motion.warning().into_iter().collect(),
    })?;
    let (a, b) = motion.domain();
    let mut t = Vec::with_capacity(samples);
    let mut vertices = Vec::with_capacity(9 * samples);
    for k in 0..samples {
        let x = a + (b - a) * k as f64 / (samples - 1) as f64;
        t.push(x);
        for v in motion.vertices(x) {
            vertices.extend_from_slice(&v.to_array());
        }
    }
    for (key, data) in [("t", t), ("vertices", vertices)] {
        let arr = js_sys::Float64Array::from(&data[..]);
        // Setting a property of the plain object just made cannot fail.
        let _ = js_sys::Reflect::set(&out, &JsValue::from_str(key), &arr);
    }
    Ok(out)
}

#[wasm_bindgen(js_class = Motion)]
impl MotionHandle {
    /// The Chaudhry–Cameron rational motion through this motion's poses (the scene-B1 triangle
    /// placed by each pose, at the key times, else one second per span): its rational Bézier
    /// control points, growth, warnings and the vertices' paths (docs/math/rational-motion.md).
    /// Throws for C¹ on a cycle or where the C¹ denominator would vanish.
    #[wasm_bindgen(unchecked_return_type = "RationalReport")]
    pub fn rational(
        &self,
        #[wasm_bindgen(unchecked_optional_param_type = "RationalOptions")] options: JsValue,
    ) -> Result<JsValue, JsError> {
        let (continuity, samples, _) =
            rational_options(&options, false).map_err(|e| e.within("rational"))?;
        let (doc, _) = self.snapshot()?;
        let times = doc.times.clone().unwrap_or_else(|| {
            (0..doc.poses.len() + usize::from(doc.closed))
                .map(|i| i as f64)
                .collect()
        });
        let motion = RationalMotion::from_poses(
            &doc.poses,
            &times,
            doc.closed,
            continuity,
            &ReferenceTriangle::SCENE_B1,
        )
        .map_err(|e| e.within("rational"))?;
        rational_report(&motion, samples)
    }

    /// The discrete baseline of Barr et al. on this motion's rotations (keyframe `i` at `t = i`,
    /// open only, free end velocities, up to 100 frames per span): the objective (3) it reaches,
    /// its covariant part, the starting objective, frames and Gauss–Newton steps
    /// (docs/math/quaternion-splines.md §9). Compare with `quaternionSpline()`'s last stage.
    #[wasm_bindgen(js_name = barrBaseline, unchecked_return_type = "BarrReport")]
    pub fn barr_baseline(&self) -> Result<JsValue, JsError> {
        let (doc, _) = self.snapshot()?;
        if doc.closed {
            return Err(Error::new(
                "barrBaseline",
                ErrorKind::Unsupported {
                    reason: "the discrete baseline of Barr et al. is built for open sequences only"
                        .into(),
                },
            )
            .into());
        }
        let keys: Vec<DQuat> = doc.poses.iter().map(|p| p.rotation).collect();
        let times: Vec<f64> = (0..keys.len()).map(|i| i as f64).collect();
        let fit = fit_barr(&times, &keys, &BarrOptions::for_keys(keys.len()))
            .map_err(|e| e.within("barrBaseline"))?;
        #[derive(Serialize)]
        #[serde(rename_all = "camelCase")]
        struct Report {
            objective: f64,
            covariant_acceleration: f64,
            initial_objective: f64,
            frames: usize,
            iterations: usize,
        }
        to_js(&Report {
            objective: fit.objective,
            covariant_acceleration: fit.covariant_acceleration,
            initial_objective: fit.initial_objective,
            frames: fit.frames.len(),
            iterations: fit.iterations,
        })
    }

    /// The Chaudhry–Cameron rational motion of a raw triangle sequence: 10 numbers per key (`t`,
    /// then the vertices `a`, `x`, `y`), as a `Float64Array` or an array of numbers; open, or
    /// closed (C⁰) at `options.closingTime`. The same report as `Motion.rational`.
    #[wasm_bindgen(js_name = rationalFromTriangles, unchecked_return_type = "RationalReport")]
    pub fn rational_from_triangles(
        #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] data: JsValue,
        #[wasm_bindgen(unchecked_optional_param_type = "RationalOptions")] options: JsValue,
    ) -> Result<JsValue, JsError> {
        let (continuity, samples, closing) = rational_options(&options, true)?;
        let numbers = super::convert::f64_array(&data, "samples", TRIANGLE_STRIDE * 100_000)?;
        let keys = triangle_samples(&numbers)?;
        let motion = match closing {
            Some(tc) => RationalMotion::fit_closed(&keys, tc, continuity)?,
            None => RationalMotion::fit(&keys, continuity)?,
        };
        rational_report(&motion, samples)
    }
}

/// A whole number from 0 to `max`.
fn integer(v: f64, at: &str, max: usize) -> Result<usize, Error> {
    if v.fract() == 0.0 && v <= max as f64 {
        Ok(v as usize)
    } else {
        Err(Error::new(
            at,
            ErrorKind::OutOfRange {
                value: v.to_string(),
                expected: format!("a whole number from 0 to {max}"),
            },
        ))
    }
}
