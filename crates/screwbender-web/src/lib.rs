//! The WebAssembly / JavaScript API (compiled for `wasm32` only; the npm package `screwbender`).
//!
//! * `MotionHandle` — the JS class `Motion`: an editable motion document with subdivision
//!   options, and the smooth motion it defines (poses, samples, kinematics, span screws).
//! * Free functions: `screw`, `screwPoses`, `screwPairs`, `screwInfo`, `posesToMatrices`,
//!   `presets`, `limits`, `version`, `importMotionFile` (feature `files`; `Motion.exportFile`
//!   and `Motion.controlPosesCsv` are feature `export`), `methods` (feature `methods`: the comparison methods; see `Motion.methodSample`,
//!   `compareMethods`, `quaternionSpline`); `Motion.keyframeTracks` (three.js keyframe arrays,
//!   feature `tracks`); the teaching views' `subdividePolygon`, `polygonPresets`, `spanScrewsOf`,
//!   `splitTweakStep`, `subdivideDecoupled`, `compareFrames` (feature `teaching`).
//!
//! Bulk results are typed arrays with fixed layouts (see `convert`): 7 `f64` per pose
//! (origin `x, y, z`, quaternion `w, x, y, z`), 16 `f32` per column-major 4×4 matrix, 16 `f64`
//! per kinematics sample. Every call that takes input validates it completely before changing
//! anything and throws a JS `Error` whose message names the bad element (the core [`Error`]'s
//! `Display`, e.g. `poses[3].rotation: zero quaternion`).
//!
//! [`Error`]: screwbender::Error

#![cfg(target_arch = "wasm32")]

use wasm_bindgen::prelude::*;

mod analysis;
pub mod convert;
#[cfg(feature = "export")]
mod export;
#[cfg(feature = "files")]
mod files;
#[cfg(feature = "fit")]
mod fit;
#[cfg(feature = "methods")]
mod methods;
mod motion;
pub mod options;
mod presets;
mod screw;
#[cfg(feature = "teaching")]
mod teaching;
#[cfg(feature = "tracks")]
mod tracks;
mod types;

pub use analysis::timing_map;
#[cfg(feature = "files")]
pub use files::import_motion_file_js;
#[cfg(feature = "fit")]
pub use fit::{fit_poses_js, measure_fit_js};
#[cfg(feature = "methods")]
pub use methods::methods;
pub use motion::MotionHandle;
pub use presets::{object_body_points, presets, scenes_alias};
pub use screw::{poses_to_matrices_js, screw, screw_info, screw_pairs, screw_poses};
#[cfg(feature = "teaching")]
pub use teaching::{
    compare_frames_js, polygon_presets, polygon_scenes_alias, span_screws_of, split_tweak_step_js,
    subdivide_decoupled_js, subdivide_polygon,
};

use convert::{to_js, KINEMATICS_STRIDE, MATRIX_STRIDE, POSE_STRIDE};

/// Installs the panic hook (panics, which should not happen, are logged with their message to
/// the console). Runs once when the module is instantiated.
#[wasm_bindgen(start)]
pub fn start() {
    console_error_panic_hook::set_once();
}

/// The crate version (also the npm package version).
#[wasm_bindgen]
pub fn version() -> String {
    env!("CARGO_PKG_VERSION").to_string()
}

/// The API's size limits and typed-array strides.
#[wasm_bindgen(unchecked_return_type = "Limits")]
pub fn limits() -> Result<JsValue, JsError> {
    #[derive(serde::Serialize)]
    #[serde(rename_all = "camelCase")]
    struct Limits {
        max_refined_poses: usize,
        max_levels: u32,
        default_levels: u32,
        max_batch: usize,
        max_document_bytes: usize,
        pose_stride: usize,
        matrix_stride: usize,
        kinematics_stride: usize,
    }
    to_js(&Limits {
        max_refined_poses: screwbender::MAX_REFINED_POSES,
        max_levels: screwbender::frontend::MAX_LEVELS,
        default_levels: screwbender::frontend::DEFAULT_LEVELS,
        max_batch: screwbender::MAX_REFINED_POSES,
        max_document_bytes: screwbender::MAX_DOCUMENT_BYTES,
        pose_stride: POSE_STRIDE,
        matrix_stride: MATRIX_STRIDE,
        kinematics_stride: KINEMATICS_STRIDE,
    })
}
#[cfg(feature = "renderer")]
pub mod render;
