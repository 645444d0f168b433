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
//! * [`fit`]: `fit`, a smooth motion fitted to many measured poses (as `screwbender fit`).
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

/// The module.
#[pymodule]
fn _screwbender(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<motion::PyMotion>()?;
    m.add_function(wrap_pyfunction!(screw::screw, m)?)?;
    m.add_function(wrap_pyfunction!(compare::compare_methods, m)?)?;
    m.add_function(wrap_pyfunction!(method_poses::method_poses, m)?)?;
    m.add_function(wrap_pyfunction!(fit::fit, m)?)?;
    m.add_function(wrap_pyfunction!(presets, m)?)?;
    m.add_function(wrap_pyfunction!(preset_descriptions, m)?)?;
    m.add("MAX_REFINED_POSES", screwbender::MAX_REFINED_POSES)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
