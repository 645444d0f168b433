//! The method comparison: `compare_methods(poses, closed, methods, body_points)` and
//! `Motion.compare_methods(methods, body_points)`, the metrics of the comparison methods on one
//! set of control poses, as `screwbender compare --json` prints them and the JS API's
//! `Motion.compareMethods` returns them.
//!
//! The table crosses into Python as the core's own JSON
//! ([`MetricsTable::to_json`](screwbender::methods::MetricsTable::to_json)) read by
//! `json.loads`: the three APIs then agree on every field name by construction, and a field the
//! core adds or renames reaches Python without a change here.

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyString;
use screwbender::frontend::compare::{
    body_points, compare, parse_methods, split_names, MAX_BODY_POINTS,
};
use screwbender::Pose;

use crate::convert::{detached, expected, flag, parameters, poses_from, shape_text, value_error};

/// The method names of `methods=`: `None` (every method that applies), a string (names
/// separated by commas, as the CLI's `--methods`) or a sequence of names; they are resolved by
/// the core ([`parse_methods`]: unknown names at `methods[i]`, each method measured once).
fn methods_from(obj: Option<&Bound<'_, PyAny>>) -> PyResult<Option<Vec<String>>> {
    let Some(obj) = obj.filter(|o| !o.is_none()) else {
        return Ok(None);
    };
    if obj.is_instance_of::<PyString>() {
        let text: String = obj.extract()?;
        return Ok(Some(split_names(&[text])));
    }
    let items = obj
        .try_iter()
        .map_err(|_| expected(obj, "methods", "a method name (str)"))?;
    let mut names = Vec::new();
    for (i, item) in items.enumerate() {
        let item = item?;
        if !item.is_instance_of::<PyString>() {
            return Err(expected(
                &item,
                &format!("methods[{i}]"),
                "a method name (str)",
            ));
        }
        names.push(item.extract::<String>()?);
    }
    parse_methods(&names).map_err(value_error)?;
    Ok(Some(names))
}

/// The body points of `body_points=`: `None` (the core's default, `(0, 0, 0)` and `(2, 0, 0)`)
/// or a `(k, 3)` array of points in local coordinates; their count and values are checked by the
/// core (`screwbender::frontend::compare::body_points`), its error naming `body_points`.
fn body_points_from(obj: Option<&Bound<'_, PyAny>>) -> PyResult<Option<Vec<[f64; 3]>>> {
    let Some(obj) = obj.filter(|o| !o.is_none()) else {
        return Ok(None);
    };
    let (numbers, shape) = parameters(obj, "body_points")?;
    let [_, 3] = shape[..] else {
        return Err(PyValueError::new_err(format!(
            "body_points: shape {} is not (k, 3) with k from 1 to {MAX_BODY_POINTS} (x, y, z \
             in the body's local frame)",
            shape_text(&shape)
        )));
    };
    let points: Vec<[f64; 3]> = numbers
        .chunks_exact(3)
        .map(|p| [p[0], p[1], p[2]])
        .collect();
    body_points(&points).map_err(|e| {
        let text = e.to_string();
        PyValueError::new_err(match text.strip_prefix("bodyPoints") {
            Some(rest) => format!("body_points{rest}"),
            None => text,
        })
    })?;
    Ok(Some(points))
}

/// The comparison table of `methods` (all that apply when `None`) on `poses`, as the Python
/// data of the core's JSON. Computed without the GIL.
pub fn table<'py>(
    py: Python<'py>,
    poses: &[Pose],
    closed: bool,
    methods: Option<&Bound<'py, PyAny>>,
    body_points: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    let methods = methods_from(methods)?;
    let points = body_points_from(body_points)?;
    let json = detached(py, || {
        // As the CLI and JavaScript: with no names, a method that does not support these poses
        // is listed in `skipped`.
        compare(poses, closed, methods.as_deref(), points.as_deref()).map(|t| t.to_json())
    })?
    .map_err(value_error)?;
    py.import("json")?.call_method1("loads", (json,))
}

/// See `compare_methods` in `screwbender/_screwbender.pyi`.
#[pyfunction]
#[pyo3(name = "compare_methods", signature = (poses, closed=None, methods=None, body_points=None))]
pub fn compare_methods<'py>(
    py: Python<'py>,
    poses: &Bound<'py, PyAny>,
    closed: Option<&Bound<'py, PyAny>>,
    methods: Option<&Bound<'py, PyAny>>,
    body_points: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    let poses = poses_from(poses, "poses")?;
    let closed = closed
        .map(|c| flag(c, "closed"))
        .transpose()?
        .unwrap_or(true);
    table(py, &poses, closed, methods, body_points)
}
