//! The core's properties, one module per subject, natively and in the browser: each module's
//! tests are `#[test]` natively and `wasm_bindgen_test` on wasm32 (the module's
//! `use wasm_bindgen_test::wasm_bindgen_test as test;`), which the wasm test stage runs in
//! headless Chromium. Native only, each saying so with `#![cfg(not(target_arch = "wasm32"))]`:
//! `fuzz_regressions`, which replays the native fuzz targets' checks (fuzz/), and the heaviest
//! fits and samplings (`fit`, `methods_barr`, `methods_continuity`, `methods_converged`, `pip_morph`,
//! `rational_growth`): the browser test runner gives up on a page that does not answer for
//! 30 s, which one long test holds up, and the wasm stage's time would grow by their whole run.
//!
//! They form one test binary rather than one per file: each binary is linked on its own and, on
//! wasm32, started in a browser of its own by `wasm-bindgen-test-runner`, so a binary per file
//! pays the link and the browser start once per file for the same tests.

#[cfg(target_arch = "wasm32")]
wasm_bindgen_test::wasm_bindgen_test_configure!(run_in_browser);

mod support;

mod batch_blends;
mod control_poses_csv;
mod export_tolerance;
mod fit;
mod frame_independence;
mod frontend_editable;
mod frontend_options;
mod fuzz_regressions;
mod interop;
mod key_velocities;
mod local_update_buffers;
mod mesh;
mod methods_barr;
mod methods_continuity;
mod methods_converged;
mod methods_lie_spline;
mod methods_metrics;
mod methods_peers;
mod methods_quaternion_spline;
mod methods_rational;
mod methods_robustness;
mod morph;
mod one_call_screw;
mod pip_morph;
mod polyscrew;
mod rational_growth;
mod screw_properties;
mod spec_vectors;
mod split_tweak;
mod streamed_output;
mod stress;
mod subdivision_buffers;
mod subdivision_properties;
mod subdivision_warnings;
mod timing_kinematics;

/// Each module's tests run in the browser too (the module doc above): a module whose `#[test]`
/// is the plain one would pass the wasm stage without running there. Native-only modules say so
/// with `#![cfg(not(target_arch = "wasm32"))]`.
#[cfg(not(target_arch = "wasm32"))]
#[test]
fn every_module_runs_in_the_browser_too() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/properties");
    let mut checked = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_none_or(|e| e != "rs") || path.ends_with("main.rs") {
            continue;
        }
        let text = std::fs::read_to_string(&path).unwrap();
        let native_only = text.contains("#![cfg(not(target_arch = \"wasm32\"))]");
        assert!(
            native_only || text.contains("use wasm_bindgen_test::wasm_bindgen_test as test;"),
            "{}: its tests would not run in the browser (no `use wasm_bindgen_test::wasm_bindgen_test as test;`)",
            path.display()
        );
        checked += 1;
    }
    assert!(
        checked > 30,
        "only {checked} modules found in {}",
        dir.display()
    );
}
