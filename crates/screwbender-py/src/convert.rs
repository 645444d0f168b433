//! Between numpy arrays and poses: reading `(n, 7)` rows (`x y z qw qx qy qz`) or `(n, 4, 4)`
//! homogeneous matrices into validated [`Pose`]s, finite parameter arrays, and writing results
//! back as float64 arrays.
//!
//! Anything that is not an array of numbers (strings, booleans, complex numbers, object arrays,
//! ragged lists) raises `TypeError`; a wrong shape or a bad value raises `ValueError`; both name
//! the element (`poses[3].rotation: zero quaternion`, `u[2]: not a finite number`).

use std::borrow::Cow;

use numpy::ndarray::{ArrayD, IxDyn};
use numpy::{IntoPyArray, PyArrayDyn, PyReadonlyArrayDyn, PyUntypedArrayMethods};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyBytes, PyString};
use screwbender::{Error, ErrorKind, Pose};

/// Numbers per pose row: origin `x, y, z`, quaternion `w, x, y, z`.
pub const POSE_STRIDE: usize = 7;

/// A tolerance for the bottom row `[0, 0, 0, 1]` of a homogeneous matrix: rows computed in
/// floating point (a product of matrices) are accepted, anything that is not an affine rigid
/// transform is not.
const BOTTOM_ROW_TOLERANCE: f64 = 1e-9;

/// The `ValueError` for a core error (its message names the element).
pub fn value_error(e: Error) -> PyErr {
    PyValueError::new_err(e.to_string())
}

/// The `TypeError` for an argument of the wrong type, in the one wording every function uses:
/// `NAME: expected WHAT, got a TYPE` (TYPE: the Python type's name).
pub fn expected(obj: &Bound<'_, PyAny>, name: &str, what: &str) -> PyErr {
    let type_name = obj
        .get_type()
        .name()
        .map(|n| n.to_string())
        .unwrap_or_else(|_| "value".into());
    PyTypeError::new_err(format!("{name}: expected {what}, got a {type_name}"))
}

/// A float64 view of `obj` (any array-like of real numbers: floats, integers), or a `TypeError`
/// naming `name` for anything else.
pub fn float_array<'py>(
    obj: &Bound<'py, PyAny>,
    name: &str,
) -> PyResult<PyReadonlyArrayDyn<'py, f64>> {
    if let Ok(array) = obj.extract::<PyReadonlyArrayDyn<'py, f64>>() {
        return Ok(array);
    }
    if obj.is_instance_of::<PyString>() || obj.is_instance_of::<PyBytes>() {
        return Err(expected(obj, name, "numbers"));
    }
    if obj.is_instance_of::<PyBool>() {
        return Err(PyTypeError::new_err(format!(
            "{name}: expected a number, got a bool"
        )));
    }
    let numpy = obj.py().import("numpy")?;
    let array = numpy.call_method1("asarray", (obj,)).map_err(|e| {
        PyValueError::new_err(format!(
            "{name}: not a rectangular array of numbers ({})",
            e.value(obj.py())
        ))
    })?;
    let dtype = array.getattr("dtype")?;
    let kind: String = dtype.getattr("kind")?.extract()?;
    match kind.as_str() {
        "f" | "i" | "u" => {
            let converted = array.call_method1("astype", ("float64",))?;
            Ok(converted.extract::<PyReadonlyArrayDyn<'py, f64>>()?)
        }
        "b" => Err(PyTypeError::new_err(format!(
            "{name}: expected numbers, got an array of booleans"
        ))),
        "O" => Err(PyTypeError::new_err(format!(
            "{name}: expected numbers, got an object array (mixed or non-numeric elements)"
        ))),
        _ => Err(PyTypeError::new_err(format!(
            "{name}: expected real numbers, got an array of dtype {}",
            dtype.str()?
        ))),
    }
}

/// The numbers of `array` in C order (borrowed when it is contiguous).
pub fn numbers<'a>(array: &'a PyReadonlyArrayDyn<'_, f64>) -> Cow<'a, [f64]> {
    // `as_slice` also accepts Fortran order (memory order, not C order): only C order borrows.
    match array.as_slice() {
        Ok(s) if array.is_c_contiguous() => Cow::Borrowed(s),
        _ => Cow::Owned(array.as_array().iter().copied().collect()),
    }
}

/// A flag: a Python `bool` or a numpy `bool_` (not a number or a string).
pub fn flag(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<bool> {
    if obj.is_instance_of::<PyBool>() {
        return obj.extract();
    }
    let numpy_bool = obj.py().import("numpy")?.getattr("bool_")?;
    if obj.is_instance(&numpy_bool)? {
        return obj.extract();
    }
    Err(expected(obj, name, "True or False"))
}

/// A shape as Python writes it: `(3, 7)`, `(5,)`, `()`.
pub fn shape_text(shape: &[usize]) -> String {
    match shape {
        [n] => format!("({n},)"),
        _ => format!(
            "({})",
            shape
                .iter()
                .map(|d| d.to_string())
                .collect::<Vec<_>>()
                .join(", ")
        ),
    }
}

/// How an array holds its poses.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PoseLayout {
    /// Rows of 7 numbers: `x y z qw qx qy qz`.
    Rows,
    /// 4×4 homogeneous matrices (row-major as numpy prints them: `M[:3, 3]` is the origin).
    Matrices,
}

impl PoseLayout {
    /// Numbers per pose.
    fn stride(self) -> usize {
        match self {
            PoseLayout::Rows => POSE_STRIDE,
            PoseLayout::Matrices => 16,
        }
    }
}

/// Poses read from an array: one pose (`(7,)` or `(4, 4)`) or a batch (`(n, 7)` or `(n, 4, 4)`).
pub struct PoseArray {
    /// The poses.
    pub poses: Vec<Pose>,
    /// Whether the array was a single pose rather than a batch.
    pub single: bool,
}

/// The layout and count of a pose array of shape `shape`, `None` if it is not one.
fn pose_shape(shape: &[usize]) -> Option<(PoseLayout, usize, bool)> {
    match *shape {
        [7] => Some((PoseLayout::Rows, 1, true)),
        [4, 4] => Some((PoseLayout::Matrices, 1, true)),
        [n, 7] => Some((PoseLayout::Rows, n, false)),
        [n, 4, 4] => Some((PoseLayout::Matrices, n, false)),
        _ => None,
    }
}

/// Reads one pose or a batch of poses from `obj` (see [`PoseArray`]); errors name `name` and the
/// pose (`poses[3].rotation`). `single` decides what is accepted: `Some(true)` one pose only,
/// `Some(false)` a batch only, `None` either.
pub fn pose_array(obj: &Bound<'_, PyAny>, name: &str, single: Option<bool>) -> PyResult<PoseArray> {
    let array = float_array(obj, name)?;
    let shape = array.shape().to_vec();
    let expected = match single {
        Some(true) => "(7,) (x y z qw qx qy qz) or (4, 4) (a homogeneous matrix)",
        Some(false) => "(n, 7) (x y z qw qx qy qz per pose) or (n, 4, 4) (homogeneous matrices)",
        None => "(7,), (4, 4), (n, 7) or (n, 4, 4)",
    };
    let wrong_shape = || {
        PyValueError::new_err(format!(
            "{name}: shape {} is not {expected}",
            shape_text(&shape)
        ))
    };
    let (layout, n, is_single) = pose_shape(&shape).ok_or_else(wrong_shape)?;
    if single.is_some_and(|s| s != is_single) {
        return Err(wrong_shape());
    }
    let data = numbers(&array);
    let poses = parse_poses(&data, layout, n, |i| {
        if is_single {
            name.to_string()
        } else {
            format!("{name}[{i}]")
        }
    })
    .map_err(value_error)?;
    Ok(PoseArray {
        poses,
        single: is_single,
    })
}

/// A batch of poses (`(n, 7)` or `(n, 4, 4)`) read from `obj`.
pub fn poses_from(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<Vec<Pose>> {
    Ok(pose_array(obj, name, Some(false))?.poses)
}

/// One pose (`(7,)` or `(4, 4)`) read from `obj`.
pub fn pose_from(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<Pose> {
    let mut poses = pose_array(obj, name, Some(true))?.poses;
    poses
        .pop()
        .ok_or_else(|| PyValueError::new_err(format!("{name}: no pose")))
}

/// Validates `n` poses laid out as `layout` in `data`; `at(i)` names pose `i`.
fn parse_poses(
    data: &[f64],
    layout: PoseLayout,
    n: usize,
    at: impl Fn(usize) -> String,
) -> Result<Vec<Pose>, Error> {
    let mut poses = Vec::with_capacity(n);
    for (i, p) in data.chunks_exact(layout.stride()).enumerate() {
        let pose = match layout {
            PoseLayout::Rows => {
                let origin = [p[0], p[1], p[2]];
                let rotation = [p[3], p[4], p[5], p[6]];
                match Pose::from_valid_wxyz(origin, rotation) {
                    Some(pose) => Ok(pose),
                    None => Pose::from_wxyz(origin, rotation),
                }
            }
            PoseLayout::Matrices => matrix_pose(p),
        };
        poses.push(pose.map_err(|e| e.within(&at(i)))?);
    }
    Ok(poses)
}

/// The pose of a row-major 4×4 homogeneous matrix `m` (16 numbers).
fn matrix_pose(m: &[f64]) -> Result<Pose, Error> {
    let bottom = [m[12], m[13], m[14], m[15]];
    let row_ok = bottom
        .iter()
        .zip([0.0, 0.0, 0.0, 1.0])
        .all(|(v, want)| (v - want).abs() <= BOTTOM_ROW_TOLERANCE);
    if !row_ok {
        return Err(Error::new(
            "matrix[3]",
            ErrorKind::Unsupported {
                reason: format!(
                    "bottom row {bottom:?} of a homogeneous matrix must be [0, 0, 0, 1]"
                ),
            },
        ));
    }
    let origin = [m[3], m[7], m[11]];
    let basis = [[m[0], m[4], m[8]], [m[1], m[5], m[9]], [m[2], m[6], m[10]]];
    Pose::from_basis(origin, basis)
}

/// Finite parameters read from `obj` (a number or an array of any shape), with the shape.
pub fn parameters(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<(Vec<f64>, Vec<usize>)> {
    let array = float_array(obj, name)?;
    let shape = array.shape().to_vec();
    let data = numbers(&array).into_owned();
    if let Some(i) = data.iter().position(|v| !v.is_finite()) {
        let at = if shape.is_empty() {
            name.to_string()
        } else {
            format!("{name}[{i}]")
        };
        return Err(value_error(Error::new(at, ErrorKind::NonFinite)));
    }
    Ok((data, shape))
}

/// Writes `pose` as 7 numbers into `out`.
pub fn write_pose(out: &mut [f64], pose: &Pose) {
    let [w, x, y, z] = pose.rotation_wxyz();
    out.copy_from_slice(&[pose.origin.x, pose.origin.y, pose.origin.z, w, x, y, z]);
}

/// Poses as 7 numbers each.
pub fn pose_rows(poses: &[Pose]) -> Vec<f64> {
    let mut out = vec![0.0; poses.len() * POSE_STRIDE];
    write_rows(&mut out, poses);
    out
}

/// Writes `poses` as 7 numbers each into `out` (`7 · poses.len()` numbers).
pub fn write_rows(out: &mut [f64], poses: &[Pose]) {
    debug_assert_eq!(out.len(), poses.len() * POSE_STRIDE);
    for (slot, pose) in out.chunks_exact_mut(POSE_STRIDE).zip(poses) {
        write_pose(slot, pose);
    }
}

/// Writes `poses` as row-major 4×4 homogeneous matrices into `out` (`16 · poses.len()` numbers).
pub fn write_matrices(out: &mut [f64], poses: &[Pose]) {
    debug_assert_eq!(out.len(), poses.len() * 16);
    for (slot, pose) in out.chunks_exact_mut(16).zip(poses) {
        let m = pose.to_matrix();
        for r in 0..4 {
            for c in 0..4 {
                slot[4 * r + c] = m.col(c)[r];
            }
        }
    }
}

/// A float64 array of shape `shape` holding `data` (moved, not copied).
pub fn to_array<'py>(
    py: Python<'py>,
    shape: Vec<usize>,
    data: Vec<f64>,
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let array = ArrayD::from_shape_vec(IxDyn(&shape), data).map_err(|e| {
        pyo3::exceptions::PyRuntimeError::new_err(format!("screwbender: internal error: {e}"))
    })?;
    Ok(array.into_pyarray(py))
}

/// A float64 array of shape `lead + (7,)` (or `(7,)` when `lead` is empty) of poses.
pub fn poses_to_array<'py>(
    py: Python<'py>,
    lead: &[usize],
    poses: &[Pose],
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let mut shape = lead.to_vec();
    shape.push(POSE_STRIDE);
    to_array(py, shape, pose_rows(poses))
}

/// Runs `f` without the GIL, turning a panic (a bug: the core's math does not fail) into a
/// `RuntimeError` instead of an exception that most code does not catch.
pub fn detached<T: Send>(py: Python<'_>, f: impl FnOnce() -> T + Send) -> PyResult<T> {
    py.detach(|| std::panic::catch_unwind(std::panic::AssertUnwindSafe(f)))
        .map_err(|_| {
            pyo3::exceptions::PyRuntimeError::new_err(
                "screwbender: internal error (a bug: please report it with the input)",
            )
        })
}

/// A string argument, or a `TypeError` naming `name`.
pub fn text(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<String> {
    if obj.is_instance_of::<PyString>() {
        return obj.extract();
    }
    Err(expected(obj, name, "a str"))
}

/// An optional string argument (`None` is absent).
pub fn optional_text(obj: Option<&Bound<'_, PyAny>>, name: &str) -> PyResult<Option<String>> {
    obj.filter(|o| !o.is_none())
        .map(|o| text(o, name))
        .transpose()
}

/// A real number argument (a float or an int, not a bool), or a `TypeError` naming `name`.
/// Finiteness is checked where the value is used (with the element's name).
pub fn number(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<f64> {
    let is_bool = obj.is_instance_of::<PyBool>()
        || obj.is_instance(&obj.py().import("numpy")?.getattr("bool_")?)?;
    if !is_bool {
        if let Ok(v) = obj.extract::<f64>() {
            return Ok(v);
        }
    }
    Err(expected(obj, name, "a number"))
}

/// An optional real number argument (`None` is absent).
pub fn optional_number(obj: Option<&Bound<'_, PyAny>>, name: &str) -> PyResult<Option<f64>> {
    obj.filter(|o| !o.is_none())
        .map(|o| number(o, name))
        .transpose()
}
