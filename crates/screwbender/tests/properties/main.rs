//! The core's properties, one module per subject, natively and in the browser.
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
mod frame_independence;
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
