//! Smooth motions fitted to many measured poses (docs/math/fitting.md): a motion capture or an
//! odometry log of thousands of timestamped poses, noisy and with a few wild samples, becomes
//! the few control poses of a cubic B-spline motion — ScrewBender's B-spline scheme or the
//! cumulative B-spline on SE(3) — that pass as close to the samples as the motion's smoothness
//! allows. Where [`reduce_poses`](crate::reduce_poses) keeps some of the measured poses (and with
//! them their noise), a fit places the control poses freely.
//!
//! From the bottom up: `banded.rs` (the banded Cholesky solve), `loss.rs` (robust losses),
//! `residual.rs` (one sample's residual, the report), `model.rs` (the two motions),
//! `solve.rs` (Levenberg–Marquardt), `measure.rs` (the report of a motion not fitted here),
//! and here the checks, the start and the choice of the number
//! of control poses.

mod banded;
mod loss;
mod measure;
mod model;
mod residual;
mod solve;

pub use loss::RobustLoss;
pub use measure::measure_fit;
pub use model::{FitMethod, FIT_LEVELS};
pub use residual::FitReport;

use crate::error::{Error, ErrorKind};
use crate::formats::document::MotionDocument;
use crate::formats::sampling::check_tolerance;
use crate::pose::Pose;
use crate::screw::screw;
use solve::Problem;

/// Most control poses a tolerance may grow a fit to.
pub const MAX_FIT_CONTROLS: usize = 4096;

/// Default cap on the Levenberg–Marquardt iterations of each stage.
pub const DEFAULT_FIT_ITERATIONS: usize = 50;

/// A robust loss's scale, when not given, is this multiple of the median sample residual of the
/// least-squares fit: the median ignores the outliers, and most inliers stay in the quadratic
/// part.
pub const ROBUST_SCALE_FACTOR: f64 = 1.5;

/// How many control poses a fit has.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ControlCount {
    /// Exactly this many (at least 2, at most the number of samples).
    Count(usize),
    /// Few enough that one fewer misses it: a count whose fit has an RMS deviation
    /// ([`FitReport::rms_deviation`]) within this tolerance (scene units), found by doubling
    /// from 4, then bisection down to a count whose predecessor fails. The residual does not
    /// always fall with the count (a spline of `m` control poses is not one of `m + 1`), so a
    /// smaller count further down may also meet it.
    Tolerance(f64),
}

/// Options of [`fit_poses`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FitOptions {
    /// The motion fitted.
    pub method: FitMethod,
    /// Its number of control poses.
    pub controls: ControlCount,
    /// Weight `W ≥ 0` of the smoothness term (0: none).
    pub smoothness: f64,
    /// The robust loss against outliers.
    pub robust: RobustLoss,
    /// The loss's scale in scene units (`None`: [`ROBUST_SCALE_FACTOR`] × the median residual
    /// of the least-squares fit).
    pub robust_scale: Option<f64>,
    /// Length that turns an angle into a distance in the residual, as `reduce_poses`' radius:
    /// the extent of the body around its local origin (> 0, scene units).
    pub radius: f64,
    /// Cap on the iterations of each stage.
    pub max_iterations: usize,
}

impl Default for FitOptions {
    fn default() -> Self {
        FitOptions {
            method: FitMethod::ScrewBender,
            controls: ControlCount::Tolerance(1e-2),
            smoothness: 0.0,
            robust: RobustLoss::None,
            robust_scale: None,
            radius: 1.0,
            max_iterations: DEFAULT_FIT_ITERATIONS,
        }
    }
}

/// A fitted motion: its document and how well it fits.
#[derive(Clone, Debug, PartialEq)]
pub struct FittedMotion {
    /// The control poses as an open document, named as the input, with key times spread
    /// uniformly over the samples' times.
    pub document: MotionDocument,
    /// The residuals.
    pub report: FitReport,
}

/// Fits the motion of `options.method` to the poses of `doc`, each reached at its key time
/// (`doc.times`, or one second apart). See the module documentation and docs/math/fitting.md.
///
/// A closed document is fitted as the open sequence of its poses (an imported file whose last
/// sample repeats its first reads as a cycle).
///
/// Errors (nothing is fitted): fewer samples than control poses
/// (`poses`), a pose or time that is not finite (`poses[i]`, `times[i]`), times not strictly
/// increasing (`times[i]`), a bad option (`controls`, `tolerance`, `smoothness`, `radius`,
/// `robust_scale`, `max_iterations`), or a tolerance no fit of up to [`MAX_FIT_CONTROLS`]
/// control poses meets (`tolerance`).
pub fn fit_poses(doc: &MotionDocument, options: &FitOptions) -> Result<FittedMotion, Error> {
    let doc = &*as_open(doc);
    let fractions = check_input(doc)?;
    check_options(options)?;
    let n = doc.poses.len();
    let (controls, report) = match options.controls {
        ControlCount::Count(m) => {
            if m < 2 {
                return Err(Error::new(
                    "controls",
                    ErrorKind::OutOfRange {
                        value: m.to_string(),
                        expected: "a whole number ≥ 2".into(),
                    },
                ));
            }
            if n < m {
                return Err(Error::new(
                    "poses",
                    ErrorKind::TooFewPoses { found: n, min: m },
                ));
            }
            fit_count(doc, &fractions, m, options)?
        }
        ControlCount::Tolerance(tolerance) => {
            check_tolerance(tolerance)?;
            fit_tolerance(doc, &fractions, tolerance, options)?
        }
    };
    let m = controls.len();
    let mut document = MotionDocument::new(controls, false);
    document.name = doc.name.clone();
    document.times = Some(key_times(doc, m));
    Ok(FittedMotion { document, report })
}

/// The first and last sample times.
/// `doc` as an open sequence: samples are a sequence in time, and a cycle's return to its first
/// pose is no sample (an imported file whose last sample repeats its first reads as a cycle).
fn as_open(doc: &MotionDocument) -> std::borrow::Cow<'_, MotionDocument> {
    if !doc.closed {
        return std::borrow::Cow::Borrowed(doc);
    }
    let mut d = doc.clone();
    d.set_closed(false);
    std::borrow::Cow::Owned(d)
}

/// The key times of `m` control poses spread uniformly over the samples' time span, as a fit
/// places them.
fn key_times(samples: &MotionDocument, m: usize) -> Vec<f64> {
    let (t0, t1) = time_range(samples);
    (0..m)
        .map(|k| t0 + (t1 - t0) * k as f64 / (m - 1) as f64)
        .collect()
}

fn time_range(doc: &MotionDocument) -> (f64, f64) {
    match &doc.times {
        Some(t) if !t.is_empty() => (t[0], t[t.len() - 1]),
        _ => (0.0, doc.poses.len().saturating_sub(1) as f64),
    }
}

/// Checks the samples; returns each one's time as a fraction of the whole, in `[0, 1]`.
fn check_input(doc: &MotionDocument) -> Result<Vec<f64>, Error> {
    let n = doc.poses.len();
    if n < 2 {
        return Err(Error::new(
            "poses",
            ErrorKind::TooFewPoses { found: n, min: 2 },
        ));
    }
    if let Some(i) = doc.poses.iter().position(|p| !p.is_finite()) {
        return Err(Error::new(format!("poses[{i}]"), ErrorKind::NonFinite));
    }
    let times: Vec<f64> = match &doc.times {
        Some(t) => {
            if t.len() != n {
                return Err(Error::new(
                    "times",
                    ErrorKind::OutOfRange {
                        value: format!("{} times", t.len()),
                        expected: format!("one time per pose ({n})"),
                    },
                ));
            }
            t.clone()
        }
        None => (0..n).map(|i| i as f64).collect(),
    };
    for (i, t) in times.iter().enumerate() {
        if !t.is_finite() {
            return Err(Error::new(format!("times[{i}]"), ErrorKind::NonFinite));
        }
        if i > 0 && *t <= times[i - 1] {
            return Err(Error::new(
                format!("times[{i}]"),
                ErrorKind::OutOfRange {
                    value: t.to_string(),
                    expected: format!("a time after times[{}] = {}", i - 1, times[i - 1]),
                },
            ));
        }
    }
    let (t0, span) = (times[0], times[n - 1] - times[0]);
    Ok(times
        .iter()
        .map(|t| ((t - t0) / span).clamp(0.0, 1.0))
        .collect())
}

fn check_options(options: &FitOptions) -> Result<(), Error> {
    let bad = |path: &str, value: f64, expected: &str| {
        Err(Error::new(
            path,
            ErrorKind::OutOfRange {
                value: value.to_string(),
                expected: expected.into(),
            },
        ))
    };
    if !(options.smoothness.is_finite() && options.smoothness >= 0.0) {
        return bad("smoothness", options.smoothness, "a finite number ≥ 0");
    }
    if !(options.radius.is_finite() && options.radius > 0.0) {
        return bad(
            "radius",
            options.radius,
            "a finite number > 0 (scene units)",
        );
    }
    if let Some(s) = options.robust_scale {
        if !(s.is_finite() && s > 0.0) {
            return bad("robust_scale", s, "a finite number > 0 (scene units)");
        }
    }
    if options.max_iterations == 0 {
        return bad("max_iterations", 0.0, "a whole number ≥ 1");
    }
    Ok(())
}

/// The start of the solver: control pose `k` on the polyscrew of the samples at the time of
/// `u = k`.
fn initial_controls(samples: &[Pose], fractions: &[f64], m: usize) -> Vec<Pose> {
    (0..m)
        .map(|k| {
            let s = k as f64 / (m - 1) as f64;
            let b = fractions.partition_point(|&f| f < s).min(samples.len() - 1);
            if b == 0 || fractions[b] == s {
                return samples[b];
            }
            let a = b - 1;
            let t = (s - fractions[a]) / (fractions[b] - fractions[a]);
            screw(&samples[a], t, &samples[b])
        })
        .collect()
}

/// The fit with exactly `m` control poses: least squares, then (with a robust loss) the robust
/// objective from there.
fn fit_count(
    doc: &MotionDocument,
    fractions: &[f64],
    m: usize,
    options: &FitOptions,
) -> Result<(Vec<Pose>, FitReport), Error> {
    let samples = &doc.poses;
    let problem = Problem::new(
        options.method,
        samples,
        fractions,
        m,
        options.radius,
        options.smoothness,
    );
    let start = initial_controls(samples, fractions, m);
    let (mut controls, mut model, mut iterations) =
        problem.solve(start, RobustLoss::None, 1.0, options.max_iterations)?;
    if options.robust != RobustLoss::None {
        let scale = match options.robust_scale {
            Some(s) => s,
            None => {
                let mut norms: Vec<f64> = problem
                    .residuals(&model)
                    .iter()
                    .map(|r| r.iter().map(|x| x * x).sum::<f64>().sqrt())
                    .collect();
                norms.sort_by(f64::total_cmp);
                ROBUST_SCALE_FACTOR * norms[norms.len() / 2]
            }
        };
        if scale > 0.0 {
            let (c, mo, it) =
                problem.solve(controls, options.robust, scale, options.max_iterations)?;
            (controls, model, iterations) = (c, mo, iterations + it);
        }
    }
    let report = residual::FitReport::measure(
        problem.params.iter().map(|&u| model.pose_at(u)),
        samples,
        options.radius,
        m,
        iterations,
    );
    Ok((controls, report))
}

/// The fewest control poses whose fit meets `tolerance` (RMS deviation): doubling from 4, then
/// bisection between the last count that failed and the first that met it.
fn fit_tolerance(
    doc: &MotionDocument,
    fractions: &[f64],
    tolerance: f64,
    options: &FitOptions,
) -> Result<(Vec<Pose>, FitReport), Error> {
    let n = doc.poses.len();
    let cap = n.min(MAX_FIT_CONTROLS);
    let mut failed = 1;
    let mut m = 4.min(cap);
    let mut best_miss = f64::INFINITY;
    let mut found = loop {
        let fit = fit_count(doc, fractions, m, options)?;
        if fit.1.rms_deviation <= tolerance {
            break fit;
        }
        best_miss = best_miss.min(fit.1.rms_deviation);
        failed = m;
        if m == cap {
            return Err(Error::new(
                "tolerance",
                ErrorKind::Unsupported {
                    reason: format!(
                        "no fit of up to {cap} control poses has an RMS deviation within \
                         {tolerance} (the closest: {best_miss:.3e}); raise the tolerance, \
                         or lower the radius if the angles dominate"
                    ),
                },
            ));
        }
        m = (2 * m).min(cap);
    };
    while found.0.len() - failed > 1 {
        let mid = (failed + found.0.len()) / 2;
        let fit = fit_count(doc, fractions, mid, options)?;
        if fit.1.rms_deviation <= tolerance {
            found = fit;
        } else {
            failed = mid;
        }
    }
    Ok(found)
}
