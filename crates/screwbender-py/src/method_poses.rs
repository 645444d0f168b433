//! `method_poses(method, poses, u, closed)`: the poses of one comparison method's motion at
//! chosen parameters, so that a method can be checked against an implementation built on
//! another library (the Lie-group B-splines against SciPy in `python/tests/test_lie_spline.py`).

use std::str::FromStr;

use pyo3::prelude::*;
use screwbender::methods::Method;
use screwbender::{Error, Pose};

use crate::convert::{detached, flag, parameters, poses_from, poses_to_array, text, value_error};

/// See `method_poses` in `screwbender/_screwbender.pyi`.
#[pyfunction]
#[pyo3(name = "method_poses", signature = (method, poses, u, closed=None))]
pub fn method_poses<'py>(
    py: Python<'py>,
    method: &Bound<'py, PyAny>,
    poses: &Bound<'py, PyAny>,
    u: &Bound<'py, PyAny>,
    closed: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    let name = text(method, "method")?;
    let method =
        Method::from_str(&name).map_err(|e| value_error(Error::new("method", e.kind().clone())))?;
    let poses = poses_from(poses, "poses")?;
    let closed = closed
        .map(|c| flag(c, "closed"))
        .transpose()?
        .unwrap_or(true);
    let (us, shape) = parameters(u, "u")?;
    let out = detached(py, move || {
        let motion = method
            .build(&poses, closed)
            .map_err(|e| e.within(method.name()))?;
        Ok::<Vec<Pose>, Error>(us.iter().map(|&u| motion.pose_at(u)).collect())
    })?
    .map_err(value_error)?;
    Ok(poses_to_array(py, &shape, &out)?.into_any())
}
