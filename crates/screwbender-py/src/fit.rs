//! `fit(path, …)`: a smooth motion fitted to the many timestamped poses of a file, as
//! `screwbender fit` fits it (the core's `fit_poses`, docs/math/fitting.md), with the residual
//! report under the CLI's `--json` names; `measure_fit(motion, path, …)`: the same report for
//! any motion against such poses (the core's `measure_fit`, as the page's lesson checks do).

use std::path::PathBuf;

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use screwbender::frontend::DEFAULT_LEVELS;
use screwbender::{
    fit_poses, measure_fit as core_measure_fit, ControlCount, FitMethod, FitOptions, FitReport,
    RobustLoss, Rules, Scheme, Subdivision,
};

use crate::convert::{detached, value_error};
use crate::files;
use crate::motion::PyMotion;

/// The control poses of the open motion `method` (`"screwbender"`: the cubic B-spline scheme;
/// `"se3bspline"`: the cumulative B-spline on SE(3)) fitted to the poses of the file at `path`
/// (`.json`, `.csv`, `.glb`, `.gltf`, read as `Motion.load` reads it), with exactly one of
/// `controls` (a count) and `tolerance` (the RMS deviation to stay within). Returns
/// `(motion, report)`: the motion has the fitted control poses, their key times and the
/// B-spline scheme (direct rules); the report is a dict of `method`, `controls`, `samples`,
/// `rms_position`, `max_position`, `rms_angle`, `max_angle`, `rms_deviation`, `max_deviation`
/// and `iterations` (as `screwbender fit --json`). Raises `ValueError` naming the bad element.
#[pyfunction]
#[pyo3(signature = (path, *, method="screwbender", controls=None, tolerance=None,
    smoothness=0.0, robust="none", robust_scale=None, radius=1.0, node=None, nodes=None))]
#[allow(clippy::too_many_arguments)]
pub fn fit<'py>(
    py: Python<'py>,
    path: PathBuf,
    method: &str,
    controls: Option<usize>,
    tolerance: Option<f64>,
    smoothness: f64,
    robust: &str,
    robust_scale: Option<f64>,
    radius: f64,
    node: Option<String>,
    nodes: Option<Vec<String>>,
) -> PyResult<(PyMotion, Bound<'py, PyDict>)> {
    let method = FitMethod::from_name(method).map_err(value_error)?;
    let robust = RobustLoss::from_name(robust).map_err(value_error)?;
    let controls = match (controls, tolerance) {
        (Some(n), None) => ControlCount::Count(n),
        (None, Some(t)) => ControlCount::Tolerance(t),
        _ => {
            return Err(PyValueError::new_err(
                "controls: give exactly one of controls and tolerance",
            ))
        }
    };
    let doc = files::load(&path, node, nodes)?;
    let options = FitOptions {
        method,
        controls,
        smoothness,
        robust,
        robust_scale,
        radius,
        ..FitOptions::default()
    };
    let fitted = detached(py, || fit_poses(&doc, &options))?.map_err(value_error)?;
    let report = report_dict(py, method, &fitted.report)?;
    let motion = PyMotion::from_state(
        fitted.document,
        Subdivision::new(Scheme::BSpline, Rules::Direct, DEFAULT_LEVELS),
    )?;
    Ok((motion, report))
}

/// The residuals of the open motion `method` whose control poses (and key times) are those of
/// `motion` against the timestamped poses of the file at `path` (read as [`fit`] reads it): the
/// report [`fit`] gives for its own result, for any motion (a reduced or edited one). Control
/// poses without key times are spread over the samples' time span, as a fit places them.
/// Raises `ValueError` naming the bad element (`controls.…`, `samples.…`, `radius`).
#[pyfunction]
#[pyo3(signature = (motion, path, *, method="screwbender", radius=1.0, node=None, nodes=None))]
pub fn measure_fit<'py>(
    py: Python<'py>,
    motion: PyRef<'_, PyMotion>,
    path: PathBuf,
    method: &str,
    radius: f64,
    node: Option<String>,
    nodes: Option<Vec<String>>,
) -> PyResult<Bound<'py, PyDict>> {
    let method = FitMethod::from_name(method).map_err(value_error)?;
    let samples = files::load(&path, node, nodes)?;
    let controls = motion.document().clone();
    drop(motion);
    let report = detached(py, || core_measure_fit(&controls, &samples, method, radius))?
        .map_err(value_error)?;
    report_dict(py, method, &report)
}

/// A residual report under `screwbender fit --json`'s names.
fn report_dict<'py>(
    py: Python<'py>,
    method: FitMethod,
    r: &FitReport,
) -> PyResult<Bound<'py, PyDict>> {
    let report = PyDict::new(py);
    report.set_item("method", method.name())?;
    report.set_item("controls", r.controls)?;
    report.set_item("samples", r.samples)?;
    report.set_item("rms_position", r.rms_position)?;
    report.set_item("max_position", r.max_position)?;
    report.set_item("rms_angle", r.rms_angle)?;
    report.set_item("max_angle", r.max_angle)?;
    report.set_item("rms_deviation", r.rms_deviation)?;
    report.set_item("max_deviation", r.max_deviation)?;
    report.set_item("iterations", r.iterations)?;
    Ok(report)
}
