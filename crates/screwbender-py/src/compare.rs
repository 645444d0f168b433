//! The method comparison: `compare_methods(poses, closed, methods, body_points)` and
//! `Motion.compare_methods(methods, body_points)`, the metrics of the comparison methods on one
//! set of control poses, as `screwbender compare --json` prints them and the JS API's
//! `Motion.compareMethods` returns them.
//!
//! The table crosses into Python as the core's own JSON
//! ([`MetricsTable::to_json`](screwbender::methods::MetricsTable::to_json)) read by
//! `json.loads`: the three APIs then agree on every field name by construction, and a field the
//! core adds or renames reaches Python without a change here.

use std::str::FromStr;

use glam::DVec3;
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyString;
use screwbender::methods::{compare_applicable, compare_methods, Method, MetricsOptions};
use screwbender::{Error, ErrorKind, Pose};

use crate::convert::{detached, flag, parameters, poses_from, shape_text, value_error};

/// The most body points one comparison measures (as the JS API's `bodyPoints`).
pub const MAX_BODY_POINTS: usize = 16;

/// The core's error for an unknown method name, located at `at` (`methods[2]` in a list).
fn method_named(name: &str, at: &str) -> Result<Method, Error> {
    Method::from_str(name).map_err(|e| match e.kind() {
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

/// The methods of `methods=`: `None` (every method that applies), a string (names separated by
/// commas, as the CLI's `--methods`) or a sequence of names. A method named twice is measured
/// once, as by the CLI.
fn methods_from(obj: Option<&Bound<'_, PyAny>>) -> PyResult<Option<Vec<Method>>> {
    let Some(obj) = obj.filter(|o| !o.is_none()) else {
        return Ok(None);
    };
    let mut chosen = Vec::new();
    let mut add = |m: Method| {
        if !chosen.contains(&m) {
            chosen.push(m);
        }
    };
    if obj.is_instance_of::<PyString>() {
        let text: String = obj.extract()?;
        for name in text.split(',').map(str::trim).filter(|s| !s.is_empty()) {
            add(method_named(name, "methods").map_err(value_error)?);
        }
        return Ok(Some(chosen));
    }
    let type_error = |what: &Bound<'_, PyAny>, at: &str| {
        PyTypeError::new_err(format!(
            "{at}: expected a method name (str), got a {}",
            what.get_type()
                .name()
                .map(|n| n.to_string())
                .unwrap_or_default()
        ))
    };
    let items = obj.try_iter().map_err(|_| type_error(obj, "methods"))?;
    for (i, item) in items.enumerate() {
        let item = item?;
        let at = format!("methods[{i}]");
        if !item.is_instance_of::<PyString>() {
            return Err(type_error(&item, &at));
        }
        let name: String = item.extract()?;
        add(method_named(&name, &at).map_err(value_error)?);
    }
    Ok(Some(chosen))
}

/// The body points of `body_points=`: `None` (the core's default, `(0, 0, 0)` and `(2, 0, 0)`)
/// or a `(k, 3)` array of 1 to [`MAX_BODY_POINTS`] points in local coordinates.
fn body_points_from(obj: Option<&Bound<'_, PyAny>>) -> PyResult<Option<Vec<DVec3>>> {
    let Some(obj) = obj.filter(|o| !o.is_none()) else {
        return Ok(None);
    };
    let (numbers, shape) = parameters(obj, "body_points")?;
    match shape[..] {
        [k, 3] if (1..=MAX_BODY_POINTS).contains(&k) => Ok(Some(
            numbers
                .chunks_exact(3)
                .map(|p| DVec3::new(p[0], p[1], p[2]))
                .collect(),
        )),
        _ => Err(PyValueError::new_err(format!(
            "body_points: shape {} is not (k, 3) with k from 1 to {MAX_BODY_POINTS} (x, y, z \
             in the body's local frame)",
            shape_text(&shape)
        ))),
    }
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
    let mut options = MetricsOptions::default();
    if let Some(points) = body_points_from(body_points)? {
        options.body_points = points;
    }
    let json = detached(py, || {
        let table = match &methods {
            // As the CLI: a method that does not support these poses is listed in `skipped`.
            None => compare_applicable(poses, closed, &options)?,
            Some(list) => compare_methods(poses, closed, list, &options)?,
        };
        Ok::<_, Error>(table.to_json())
    })?
    .map_err(value_error)?;
    py.import("json")?.call_method1("loads", (json,))
}

/// See `compare_methods` in `screwbender/_screwbender.pyi`.
#[pyfunction]
#[pyo3(name = "compare_methods", signature = (poses, closed=None, methods=None, body_points=None))]
pub fn compare<'py>(
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
