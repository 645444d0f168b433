//! The `Motion` class: control poses (a cycle or an open sequence), their key timing and the
//! subdivision options, and the smooth motion they define.
//!
//! A wrapper of the core's [`EditableMotion`], which the JavaScript class wraps too: every change
//! converts its arguments and hands them to it, which validates the new state completely (poses,
//! options, timing, the memory guard [`screwbender::MAX_REFINED_POSES`]) and only then stores
//! it, so after any raised error the object keeps its exact previous state. The refined motion
//! is computed on first use (without the GIL) and cached until the next change.

use std::path::Path;

use glam::DVec3;
use numpy::{PyArrayDyn, PyArrayMethods};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyType};
use screwbender::frontend::{self, EditableMotion, OptionsInput};
use screwbender::{
    presets, Error, ErrorKind, Motion, MotionDocument, Pose, Rules, Scheme, ScrewBender,
    Subdivision,
};

use crate::convert::{
    detached, expected, flag, number, optional_number, optional_text, parameters, pose_from,
    poses_from, poses_to_array, text, to_array, value_error, write_matrices, write_rows,
    POSE_STRIDE,
};
use crate::{compare, files};

/// The default number of subdivision levels: the core's, as the CLI and the JS API.
pub use screwbender::frontend::DEFAULT_LEVELS;

/// A rule set's name: `"direct"` or `"split"`, and the core's aliases ([`Rules`]' `FromStr`:
/// `"split-then-tweak"`, `"v1"`, `"v2"`, …), with the core's error words.
pub fn parse_rules(name: &str) -> Result<Rules, Error> {
    name.parse::<Rules>()
}

/// A rule set's id as files, the JS API and the CLI write it: `"direct"` or `"split"`.
pub fn rules_name(rules: Rules) -> &'static str {
    frontend::rules_name(&rules)
}

/// A scheme's id as every front end writes it (`"j"` for the J_s family; its parameter is `s`).
pub fn scheme_name(scheme: Scheme) -> &'static str {
    frontend::scheme_name(&scheme)
}

/// The scheme of `scheme=` and `s=` over the `current` one, by the core's front-end rules (as
/// the CLI's `--scheme` and `--s` and JavaScript's options): `s` alone selects the J_s family,
/// with a named scheme it must agree with it, with `"j"` it is the parameter.
fn scheme_from(scheme: Option<&str>, s: Option<f64>, current: Scheme) -> Result<Scheme, Error> {
    let base = Subdivision::new(current, Rules::Direct, 0);
    let input = OptionsInput {
        scheme,
        s,
        ..OptionsInput::default()
    };
    frontend::resolve(base, &input).map(|sub| sub.scheme)
}

/// A level count: a number (Python's or numpy's, not a `bool`) that the core's front-end rules
/// accept ([`frontend::parse_levels`]: a whole number from 0 to [`frontend::MAX_LEVELS`]), so
/// `levels=2.5` gets the same words here as in JavaScript and on the command line.
fn level_count(obj: &Bound<'_, PyAny>) -> PyResult<u32> {
    let numeric = !obj.is_instance_of::<PyBool>()
        && (obj.is_instance_of::<PyInt>()
            || obj.is_instance_of::<PyFloat>()
            || obj
                .py()
                .import("numpy")?
                .getattr("number")
                .and_then(|t| obj.is_instance(&t))
                .unwrap_or(false));
    if !numeric {
        return Err(expected(obj, "levels", "a whole number ≥ 0"));
    }
    // Integers beyond f64's exact range are far beyond the cap either way.
    let v = match obj.extract::<i64>() {
        Ok(i) => i as f64,
        Err(_) => obj.extract::<f64>()?,
    };
    frontend::parse_levels(v).map_err(value_error)
}

/// Key times: `None` or a 1-D array of numbers (validated against the poses later).
fn times_from(obj: Option<&Bound<'_, PyAny>>) -> PyResult<Option<Vec<f64>>> {
    match obj {
        None => Ok(None),
        Some(o) if o.is_none() => Ok(None),
        Some(o) => {
            let (times, shape) = parameters(o, "times")?;
            if shape.len() != 1 {
                return Err(PyValueError::new_err(format!(
                    "times: shape {} is not (n,) (one time per key)",
                    crate::convert::shape_text(&shape)
                )));
            }
            Ok(Some(times))
        }
    }
}

/// Key velocities: `None`, or a sequence of numbers ≥ 0 and `None` (a free key).
fn velocities_from(obj: Option<&Bound<'_, PyAny>>) -> PyResult<Option<Vec<Option<f64>>>> {
    let Some(obj) = obj.filter(|o| !o.is_none()) else {
        return Ok(None);
    };
    const SEQUENCE: &str = "a sequence of numbers and None";
    if obj.is_instance_of::<pyo3::types::PyString>() {
        return Err(expected(obj, "velocities", SEQUENCE));
    }
    let items = obj
        .try_iter()
        .map_err(|_| expected(obj, "velocities", SEQUENCE))?;
    let mut out = Vec::new();
    for (i, item) in items.enumerate() {
        let item = item?;
        if item.is_none() {
            out.push(None);
            continue;
        }
        if item.is_instance_of::<PyBool>() {
            return Err(PyTypeError::new_err(format!(
                "velocities[{i}]: expected a number or None, got a bool"
            )));
        }
        let v: f64 = item
            .extract()
            .map_err(|_| expected(&item, &format!("velocities[{i}]"), "a number or None"))?;
        out.push(Some(v));
    }
    Ok(Some(out))
}

/// A body point: `None` (the local origin) or 3 numbers.
fn point_from(obj: Option<&Bound<'_, PyAny>>, name: &str) -> PyResult<Option<DVec3>> {
    let Some(obj) = obj.filter(|o| !o.is_none()) else {
        return Ok(None);
    };
    let (p, shape) = parameters(obj, name)?;
    match p[..] {
        [x, y, z] if shape.len() == 1 => Ok(Some(DVec3::new(x, y, z))),
        _ => Err(PyValueError::new_err(format!(
            "{name}: shape {} is not (3,) (x, y, z in the body's local frame)",
            crate::convert::shape_text(&shape)
        ))),
    }
}

/// Control poses (a cycle or an open sequence) smoothed by screw subdivision.
#[pyclass(module = "screwbender._screwbender", name = "Motion")]
#[derive(Clone)]
pub struct PyMotion {
    inner: EditableMotion,
}

impl PyMotion {
    /// A motion of a document and options that are valid together.
    pub fn from_state(doc: MotionDocument, subdivision: Subdivision) -> PyResult<PyMotion> {
        Ok(PyMotion {
            inner: EditableMotion::new(doc, subdivision).map_err(value_error)?,
        })
    }

    /// The motion document.
    pub fn document(&self) -> &MotionDocument {
        self.inner.document()
    }

    /// The subdivision options.
    pub fn subdivision(&self) -> Subdivision {
        self.inner.subdivision()
    }

    /// Applies an edit of the core's (validated there; on error nothing changes).
    fn edit(
        &mut self,
        change: impl FnOnce(&mut EditableMotion) -> Result<(), Error>,
    ) -> PyResult<()> {
        change(&mut self.inner).map_err(value_error)
    }

    /// The refined poses (subdividing without the GIL if not done since the last change).
    fn refined_poses(&mut self, py: Python<'_>) -> PyResult<&[Pose]> {
        let inner = &mut self.inner;
        detached(py, || inner.refined_poses())?.map_err(value_error)
    }

    /// The refined motion (built without the GIL if not done since the last change).
    fn motion(&mut self, py: Python<'_>) -> PyResult<&ScrewBender> {
        let inner = &mut self.inner;
        detached(py, || inner.refined())?.map_err(value_error)
    }
}

/// Builds a state from the constructor's arguments.
#[allow(clippy::too_many_arguments)]
fn state_from(
    poses: Vec<Pose>,
    closed: bool,
    scheme: Option<&str>,
    levels: Option<&Bound<'_, PyAny>>,
    rules: &str,
    s: Option<f64>,
    times: Option<&Bound<'_, PyAny>>,
    velocities: Option<&Bound<'_, PyAny>>,
    name: Option<String>,
    defaults: Subdivision,
) -> PyResult<(MotionDocument, Subdivision)> {
    let scheme = scheme_from(scheme, s, defaults.scheme).map_err(value_error)?;
    let rules = parse_rules(rules).map_err(value_error)?;
    let levels = match levels {
        Some(l) => level_count(l)?,
        None => defaults.levels,
    };
    let times = times_from(times)?;
    let velocities = velocities_from(velocities)?;
    let subdivision = Subdivision::new(scheme, rules, levels);
    // Options and the pose count first: the timing is defined for 2 poses or more.
    subdivision.validate().map_err(value_error)?;
    subdivision
        .output_len(poses.len(), closed)
        .map_err(value_error)?;
    let mut doc = MotionDocument::new(poses, closed);
    doc.name = name;
    doc.set_timing(times, velocities).map_err(value_error)?;
    Ok((doc, subdivision))
}

#[pymethods]
impl PyMotion {
    /// Makes a motion from control poses; `help(Motion)` describes the arguments.
    #[new]
    #[pyo3(signature = (poses, closed=None, scheme=None, levels=None, rules=None, s=None, times=None, velocities=None, name=None))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        poses: &Bound<'_, PyAny>,
        closed: Option<&Bound<'_, PyAny>>,
        scheme: Option<&Bound<'_, PyAny>>,
        levels: Option<&Bound<'_, PyAny>>,
        rules: Option<&Bound<'_, PyAny>>,
        s: Option<&Bound<'_, PyAny>>,
        times: Option<&Bound<'_, PyAny>>,
        velocities: Option<&Bound<'_, PyAny>>,
        name: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<PyMotion> {
        let poses = poses_from(poses, "poses")?;
        let closed = closed
            .map(|c| flag(c, "closed"))
            .transpose()?
            .unwrap_or(true);
        let defaults = frontend::default_subdivision();
        let (scheme, rules) = (
            optional_text(scheme, "scheme")?,
            optional_text(rules, "rules")?,
        );
        let (s, name) = (optional_number(s, "s")?, optional_text(name, "name")?);
        let (doc, subdivision) = state_from(
            poses,
            closed,
            scheme.as_deref(),
            levels,
            rules.as_deref().unwrap_or("direct"),
            s,
            times,
            velocities,
            name,
            defaults,
        )?;
        PyMotion::from_state(doc, subdivision)
    }

    /// The preset `name` (see `presets()`), with the preset's scheme and levels unless given.
    #[classmethod]
    #[pyo3(signature = (name, *, closed=None, scheme=None, levels=None, rules=None, s=None, times=None, velocities=None))]
    #[allow(clippy::too_many_arguments)]
    fn from_preset(
        _cls: &Bound<'_, PyType>,
        name: &str,
        closed: Option<&Bound<'_, PyAny>>,
        scheme: Option<&Bound<'_, PyAny>>,
        levels: Option<&Bound<'_, PyAny>>,
        rules: Option<&Bound<'_, PyAny>>,
        s: Option<&Bound<'_, PyAny>>,
        times: Option<&Bound<'_, PyAny>>,
        velocities: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<PyMotion> {
        let preset = presets::preset(name).ok_or_else(|| {
            value_error(Error::new(
                "name",
                ErrorKind::OutOfRange {
                    value: format!("'{name}'"),
                    expected: format!("a preset: {}", preset_names().join(", ")),
                },
            ))
        })?;
        let closed = closed.map(|c| flag(c, "closed")).transpose()?;
        let defaults = Subdivision::new(preset.scheme, Rules::Direct, preset.levels);
        let (scheme, rules) = (
            optional_text(scheme, "scheme")?,
            optional_text(rules, "rules")?,
        );
        let s = optional_number(s, "s")?;
        let (doc, subdivision) = state_from(
            preset.poses,
            closed.unwrap_or(preset.closed),
            scheme.as_deref(),
            levels,
            rules.as_deref().unwrap_or("direct"),
            s,
            times,
            velocities,
            Some(preset.id.to_string()),
            defaults,
        )?;
        PyMotion::from_state(doc, subdivision)
    }

    /// A motion document from JSON text (the CLI's and the page's format).
    #[classmethod]
    fn from_json(_cls: &Bound<'_, PyType>, text: &str) -> PyResult<PyMotion> {
        let doc = MotionDocument::from_json(text).map_err(value_error)?;
        PyMotion::from_state(doc, frontend::default_subdivision())
    }

    /// Control poses from a `.json`, `.csv`, `.glb` or `.gltf` file (as `screwbender import`).
    #[classmethod]
    #[pyo3(signature = (path, *, node=None, nodes=None, closed=None))]
    fn load(
        _cls: &Bound<'_, PyType>,
        path: std::path::PathBuf,
        node: Option<String>,
        nodes: Option<Vec<String>>,
        closed: Option<bool>,
    ) -> PyResult<PyMotion> {
        let mut doc = files::load(&path, node, nodes)?;
        if let Some(closed) = closed {
            doc.set_closed(closed);
        }
        PyMotion::from_state(doc, frontend::default_subdivision())
    }

    /// The motion document as JSON text (two-space indent, one pose per line).
    fn to_json(&self) -> String {
        self.document().to_json()
    }

    /// Writes the motion as `.glb`, `.gltf` (+ `.bin`), `.csv` or `.json` (as `screwbender
    /// export`); returns the number of samples written (control poses for JSON).
    #[pyo3(signature = (path, *, format=None, tolerance=None, fps=None, point=None, radius=None, control_nodes=false))]
    #[allow(clippy::too_many_arguments)]
    fn export(
        &self,
        py: Python<'_>,
        path: std::path::PathBuf,
        format: Option<&str>,
        tolerance: Option<f64>,
        fps: Option<f64>,
        point: Option<&Bound<'_, PyAny>>,
        radius: Option<f64>,
        control_nodes: bool,
    ) -> PyResult<usize> {
        let point = point_from(point, "point")?;
        let options = files::ExportOptions {
            format,
            tolerance,
            fps,
            point,
            radius,
            control_nodes,
        };
        files::export(
            py,
            self.inner.document(),
            self.inner.subdivision(),
            Path::new(&path),
            &options,
        )
    }

    /// An independent copy.
    fn copy(&self) -> PyMotion {
        self.clone()
    }

    fn __copy__(&self) -> PyMotion {
        self.clone()
    }

    fn __deepcopy__(&self, _memo: &Bound<'_, PyAny>) -> PyMotion {
        self.clone()
    }

    fn __repr__(&self) -> String {
        let (doc, sub) = (self.inner.document(), self.inner.subdivision());
        let scheme = match sub.scheme {
            Scheme::J(v) => format!("s={v}"),
            other => format!("scheme='{}'", scheme_name(other)),
        };
        let name = doc
            .name
            .as_ref()
            .map(|n| format!(", name={n:?}"))
            .unwrap_or_default();
        format!(
            "Motion({} poses, closed={}, {scheme}, levels={}, rules='{}'{name})",
            doc.poses.len(),
            if doc.closed { "True" } else { "False" },
            sub.levels,
            rules_name(sub.rules),
        )
    }

    // ---- the document --------------------------------------------------------------------

    /// The control poses, `(n, 7)`: `x y z qw qx qy qz` (unit quaternions).
    #[getter]
    fn get_poses<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let poses = &self.document().poses;
        poses_to_array(py, &[poses.len()], poses)
    }

    #[setter]
    fn set_poses(&mut self, value: &Bound<'_, PyAny>) -> PyResult<()> {
        let poses = poses_from(value, "poses")?;
        self.edit(|m| m.set_poses(poses))
    }

    /// Control pose `i` as 7 numbers.
    fn pose<'py>(&self, py: Python<'py>, i: isize) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let k = self.index(i)?;
        poses_to_array(py, &[], &self.document().poses[k..k + 1])
    }

    /// Replaces control pose `i` (`(7,)` or `(4, 4)`; negative `i` counts from the end).
    fn set_pose(&mut self, i: isize, pose: &Bound<'_, PyAny>) -> PyResult<()> {
        let k = self.index(i)?;
        let pose = pose_from(pose, "pose")?;
        self.edit(|m| m.set_pose(k, pose))
    }

    /// Inserts a pose between control poses `i` and `i + 1` and returns its index, `i + 1`
    /// (negative `i` counts from the end). Without `pose`, inserts the screw midpoint
    /// `screw(P_i, ½, P_{i+1})` (a cycle's last pose is followed by its first; after an open
    /// motion's last pose a pose must be given).
    #[pyo3(signature = (i, pose=None))]
    fn insert_pose(&mut self, i: isize, pose: Option<&Bound<'_, PyAny>>) -> PyResult<usize> {
        let k = self.index(i)?;
        let pose = pose.map(|p| pose_from(p, "pose")).transpose()?;
        self.inner.insert_pose(k, pose).map_err(value_error)
    }

    /// Removes control pose `i` (negative `i` counts from the end; a motion keeps at least 2).
    fn remove_pose(&mut self, i: isize) -> PyResult<()> {
        let k = self.index(i)?;
        self.edit(|m| m.remove_pose(k))
    }

    /// Whether the poses form a cycle.
    #[getter]
    fn get_closed(&self) -> bool {
        self.document().closed
    }

    #[setter]
    fn set_closed(&mut self, closed: &Bound<'_, PyAny>) -> PyResult<()> {
        let closed = flag(closed, "closed")?;
        self.edit(|m| m.set_closed(closed))
    }

    /// The document's name (a preset's id), or `None`.
    #[getter]
    fn get_name(&self) -> Option<String> {
        self.document().name.clone()
    }

    #[setter]
    fn set_name(&mut self, name: Option<&Bound<'_, PyAny>>) -> PyResult<()> {
        let name = optional_text(name, "name")?;
        self.edit(|m| m.set_name(name))
    }

    /// Key times in seconds (`n` for an open motion, `n + 1` for a cycle), or `None` (one
    /// second per span).
    #[getter]
    fn get_times(&self) -> Option<Vec<f64>> {
        self.document().times.clone()
    }

    #[setter]
    fn set_times(&mut self, times: Option<&Bound<'_, PyAny>>) -> PyResult<()> {
        let times = times_from(times)?;
        self.edit(|m| m.set_times(times))
    }

    /// Key velocities (poses per second, `None` where free), or `None` (all free).
    #[getter]
    fn get_velocities(&self) -> Option<Vec<Option<f64>>> {
        self.document().velocities.clone()
    }

    #[setter]
    fn set_velocities(&mut self, velocities: Option<&Bound<'_, PyAny>>) -> PyResult<()> {
        let velocities = velocities_from(velocities)?;
        self.edit(|m| m.set_velocities(velocities))
    }

    // ---- the options -----------------------------------------------------------------------

    /// The scheme: `"bspline"`, `"fourpoint"`, `"jarek"`, or `"j"` for the J_s family.
    #[getter]
    fn get_scheme(&self) -> &'static str {
        scheme_name(self.subdivision().scheme)
    }

    #[setter]
    fn set_scheme(&mut self, scheme: &Bound<'_, PyAny>) -> PyResult<()> {
        let scheme = text(scheme, "scheme")?;
        let current = self.subdivision().scheme;
        let scheme = scheme_from(Some(&scheme), None, current).map_err(value_error)?;
        self.edit(|m| {
            m.update(|_, sub| {
                sub.scheme = scheme;
                Ok(())
            })
        })
    }

    /// The J_s parameter of the scheme (`1` B-spline, `0` 4-point, `0.5` Jarek); setting it
    /// selects the J_s family.
    #[getter]
    fn get_s(&self) -> f64 {
        self.subdivision().scheme.s()
    }

    #[setter]
    fn set_s(&mut self, s: &Bound<'_, PyAny>) -> PyResult<()> {
        let s = number(s, "s")?;
        self.edit(|m| {
            m.update(|_, sub| {
                sub.scheme = Scheme::J(s);
                Ok(())
            })
        })
    }

    /// The rule set: `"direct"` or `"split"` (also accepts the core's aliases, e.g.
    /// `"split-then-tweak"`).
    #[getter]
    fn get_rules(&self) -> &'static str {
        rules_name(self.subdivision().rules)
    }

    #[setter]
    fn set_rules(&mut self, rules: &Bound<'_, PyAny>) -> PyResult<()> {
        let rules = parse_rules(&text(rules, "rules")?).map_err(value_error)?;
        self.edit(|m| {
            m.update(|_, sub| {
                sub.rules = rules;
                Ok(())
            })
        })
    }

    /// Subdivision levels (`0`: the plain polyscrew).
    #[getter]
    fn get_levels(&self) -> u32 {
        self.subdivision().levels
    }

    #[setter]
    fn set_levels(&mut self, levels: &Bound<'_, PyAny>) -> PyResult<()> {
        let levels = level_count(levels)?;
        self.edit(|m| {
            m.update(|_, sub| {
                sub.levels = levels;
                Ok(())
            })
        })
    }

    /// Warnings about the options on these poses (e.g. a span close to a half turn).
    fn warnings(&self) -> Vec<String> {
        self.inner.warnings()
    }

    // ---- the motion ------------------------------------------------------------------------

    /// How many poses `subdivide()` returns.
    #[getter]
    fn refined_count(&self) -> PyResult<usize> {
        self.inner.refined_count().map_err(value_error)
    }

    /// The parameter interval `(0, n)` for a cycle of `n` poses, `(0, m - 1)` for an open one.
    #[getter]
    fn domain(&self) -> (f64, f64) {
        self.inner.domain()
    }

    /// The refined poses, `(N, 7)`; refined pose `j` sits at `u = j / 2**levels`.
    fn subdivide<'py>(&mut self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let poses = self.refined_poses(py)?;
        filled_array(py, vec![poses.len(), POSE_STRIDE], |out| {
            write_rows(out, poses)
        })
    }

    /// The refined poses as homogeneous matrices, `(N, 4, 4)` (the JS API's
    /// `refinedMatrices`).
    fn refined_matrices<'py>(&mut self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let poses = self.refined_poses(py)?;
        filled_array(py, vec![poses.len(), 4, 4], |out| {
            write_matrices(out, poses)
        })
    }

    /// Former name of `refined_matrices`, kept for one release (a `DeprecationWarning`).
    fn matrices<'py>(&mut self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        deprecated(
            py,
            c"Motion.matrices() is deprecated: use Motion.refined_matrices()",
        )?;
        self.refined_matrices(py)
    }

    /// The poses at parameters `u` (a number: `(7,)`; an array: `u.shape + (7,)`). Cycles wrap
    /// `u`; open motions extrapolate their end screws.
    fn poses_at<'py>(
        &mut self,
        py: Python<'py>,
        u: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let (us, shape) = parameters(u, "u")?;
        let motion = self.motion(py)?;
        let poses = detached(py, || {
            us.iter().map(|&u| motion.pose_at(u)).collect::<Vec<_>>()
        })?;
        poses_to_array(py, &shape, &poses)
    }

    /// `count` poses at uniformly spaced parameters (a cycle's `[0, n)`, an open motion's
    /// `[0, m - 1]` inclusive), `(count, 7)`.
    fn sample<'py>(
        &mut self,
        py: Python<'py>,
        count: usize,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        if count > screwbender::MAX_SAMPLES {
            return Err(value_error(Error::new(
                "count",
                ErrorKind::OutOfRange {
                    value: count.to_string(),
                    expected: format!("at most {}", screwbender::MAX_SAMPLES),
                },
            )));
        }
        let motion = self.motion(py)?;
        let poses = detached(py, || motion.sample(count))?;
        poses_to_array(py, &[count], &poses)
    }

    /// Closed-form kinematics at `u` of the body point `point` (local coordinates, default the
    /// origin): a dict of `u.shape + (3,)` arrays `position`, `velocity`, `acceleration`,
    /// `angular_velocity`, `angular_acceleration` (world frame, per unit of `u`).
    #[pyo3(signature = (u, point=None))]
    fn kinematics_at<'py>(
        &mut self,
        py: Python<'py>,
        u: &Bound<'py, PyAny>,
        point: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let (us, shape) = parameters(u, "u")?;
        let local = point_from(point, "point")?.unwrap_or(DVec3::ZERO);
        let motion = self.motion(py)?;
        let columns = detached(py, || {
            let mut columns: Vec<Vec<f64>> =
                (0..5).map(|_| Vec::with_capacity(us.len() * 3)).collect();
            for &u in &us {
                let k = motion.refined().point_kinematics(u, local);
                let values = [
                    k.position,
                    k.velocity,
                    k.acceleration,
                    k.angular_velocity,
                    k.angular_acceleration,
                ];
                for (column, v) in columns.iter_mut().zip(values) {
                    column.extend_from_slice(&v.to_array());
                }
            }
            columns
        })?;
        let dict = PyDict::new(py);
        let names = [
            "position",
            "velocity",
            "acceleration",
            "angular_velocity",
            "angular_acceleration",
        ];
        let mut out_shape = shape.clone();
        out_shape.push(3);
        for (name, column) in names.iter().zip(columns) {
            dict.set_item(name, to_array(py, out_shape.clone(), column)?)?;
        }
        Ok(dict)
    }

    /// Former name of `kinematics_at`, kept for one release (a `DeprecationWarning`).
    #[pyo3(signature = (u, point=None))]
    fn kinematics<'py>(
        &mut self,
        py: Python<'py>,
        u: &Bound<'py, PyAny>,
        point: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        deprecated(
            py,
            c"Motion.kinematics() is deprecated: use Motion.kinematics_at()",
        )?;
        self.kinematics_at(py, u, point)
    }

    /// The metrics of the comparison methods on the control poses (the motion's own scheme,
    /// rules and levels play no part), as `screwbender compare --json` prints them: see
    /// `compare_methods` in `screwbender/_screwbender.pyi`.
    #[pyo3(signature = (methods=None, body_points=None))]
    fn compare_methods<'py>(
        &self,
        py: Python<'py>,
        methods: Option<&Bound<'py, PyAny>>,
        body_points: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let doc = self.document();
        compare::table(py, &doc.poses, doc.closed, methods, body_points)
    }

    /// The number of control poses (also `len(m)`).
    #[getter]
    fn pose_count(&self) -> usize {
        self.document().poses.len()
    }

    /// The number of control poses.
    fn __len__(&self) -> usize {
        self.document().poses.len()
    }
}

/// Warns that a former name was called: a `DeprecationWarning` attributed to the caller's line
/// (a method written in Rust has no frame of its own, so stack level 1 is the caller's, as
/// `stacklevel=2` in a Python function).
fn deprecated(py: Python<'_>, message: &std::ffi::CStr) -> PyResult<()> {
    PyErr::warn(
        py,
        &py.get_type::<pyo3::exceptions::PyDeprecationWarning>(),
        message,
        1,
    )
}

impl PyMotion {
    /// Control pose index `i` (negative counts from the end), or a named `IndexError`.
    fn index(&self, i: isize) -> PyResult<usize> {
        let n = self.document().poses.len();
        let k = if i < 0 { i + n as isize } else { i };
        usize::try_from(k).ok().filter(|&k| k < n).ok_or_else(|| {
            pyo3::exceptions::PyIndexError::new_err(format!(
                "index: {i} is out of range (expected -{n} to {})",
                n - 1
            ))
        })
    }
}

/// A new float64 array of shape `shape` whose every number `fill` writes, without the GIL,
/// straight into numpy's memory (no second copy of the result). The array comes zeroed from
/// numpy's allocator, for which fresh pages cost no pass: they are zero already.
fn filled_array<'py>(
    py: Python<'py>,
    shape: Vec<usize>,
    fill: impl FnOnce(&mut [f64]) + Send,
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let array = PyArrayDyn::<f64>::zeros(py, shape, false);
    {
        let mut numbers = array.readwrite();
        let out = numbers.as_slice_mut().map_err(|e| {
            pyo3::exceptions::PyRuntimeError::new_err(format!("screwbender: internal error: {e}"))
        })?;
        detached(py, || fill(out))?;
    }
    Ok(array)
}

/// The preset ids, in the order of the page's menu.
pub fn preset_names() -> Vec<&'static str> {
    presets::all().iter().map(|s| s.id).collect()
}
