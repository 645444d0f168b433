//! The extension module `screwbender._screwbender` of the Python package `screwbender`
//! (python/): the ScrewBender motion core on numpy arrays, built by maturin.
//!
//! * [`motion`]: the `Motion` class (control poses, options, timing; subdivision, evaluation,
//!   kinematics).
//! * [`screw`]: `screw(a, t, b)` for one pair or batches.
//! * [`compare`]: `compare_methods`, the metrics of the comparison methods (as `screwbender
//!   compare --json`).
//! * [`method_poses`]: `method_poses`, one comparison method's poses at chosen parameters.
//! * [`files`]: `Motion.load` / `Motion.export` in the CLI's formats.
//! * [`fit`]: `fit`, a smooth motion fitted to many measured poses (as `screwbender fit`), and
//!   `measure_fit`, any motion's residuals against such poses.
//! * [`convert`]: numpy arrays ↔ poses, with errors naming the element.
//!
//! Every function validates its input and raises `ValueError` / `TypeError` naming the
//! element; the math runs without the GIL, and a panic (a bug) becomes a `RuntimeError` instead
//! of unwinding into the interpreter. The Python side (`screwbender/__init__.py`) adds the
//! notebook figure; the type stubs are `screwbender/_screwbender.pyi`.

pub mod compare;
pub mod convert;
pub mod files;
pub mod fit;
pub mod method_poses;
pub mod motion;
pub mod screw;

use pyo3::prelude::*;
use pyo3::types::PyDict;

/// The preset ids (`Motion.from_preset(id)`), in the order of the page's menu.
#[pyfunction]
fn presets() -> Vec<&'static str> {
    motion::preset_names()
}

/// The preset ids with their labels and descriptions: a list of `(id, label, description)`.
#[pyfunction]
fn preset_descriptions() -> Vec<(&'static str, &'static str, &'static str)> {
    screwbender::presets::all()
        .iter()
        .map(|s| (s.id, s.label, s.description))
        .collect()
}

/// How the page shows preset `id` (the core's table, which the page's chooser and figure
/// read): a dict with `name` (in words), `strobe` (copies of the object), `selected` (the pose
/// selected on load, or `None`) and `body_points` (the local points whose trajectories are
/// drawn, a list of `[x, y, z]`). An unknown id raises `ValueError` naming `id`.
#[pyfunction]
fn preset_display<'py>(py: Python<'py>, id: &str) -> PyResult<Bound<'py, PyDict>> {
    let preset = screwbender::presets::preset(id).ok_or_else(|| {
        pyo3::exceptions::PyValueError::new_err(format!(
            "id: '{id}' is not a preset (expected one of: {})",
            presets().join(", ")
        ))
    })?;
    let display = screwbender::presets::display(preset.id);
    let out = PyDict::new(py);
    out.set_item("name", display.name)?;
    out.set_item("strobe", display.strobe)?;
    out.set_item("selected", display.selected)?;
    out.set_item(
        "body_points",
        screwbender::presets::body_points(&preset.shape),
    )?;
    Ok(out)
}

/// The module.
#[pymodule]
fn _screwbender(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<motion::PyMotion>()?;
    m.add_function(wrap_pyfunction!(screw::screw, m)?)?;
    m.add_function(wrap_pyfunction!(compare::compare_methods, m)?)?;
    m.add_function(wrap_pyfunction!(method_poses::method_poses, m)?)?;
    m.add_function(wrap_pyfunction!(fit::fit, m)?)?;
    m.add_function(wrap_pyfunction!(fit::measure_fit, m)?)?;
    m.add_function(wrap_pyfunction!(presets, m)?)?;
    m.add_function(wrap_pyfunction!(preset_descriptions, m)?)?;
    m.add_function(wrap_pyfunction!(preset_display, m)?)?;
    m.add("MAX_REFINED_POSES", screwbender::MAX_REFINED_POSES)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
