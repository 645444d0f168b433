//! Free functions on screws: one screw at one or many fractions, many screws at once, and the
//! display parameters of a screw.

use wasm_bindgen::prelude::*;

use super::convert::{
    finite, pose_from_js, pose_to_js, poses_from_fn, poses_from_js_array, poses_to_array,
    poses_to_matrices, to_js, ScrewInfo,
};
use super::motion_api::batch;
use crate::{Blend, Error, Pose, Screw};

/// `screw(a, t, b)`: the pose after the fraction `t` of the screw motion from `a` to `b`
/// (`t = 0` gives `a`, `t = 1` gives `b`, any real `t` extrapolates).
#[wasm_bindgen(unchecked_return_type = "Pose")]
pub fn screw(
    #[wasm_bindgen(unchecked_param_type = "PoseInput")] a: JsValue,
    #[wasm_bindgen(unchecked_param_type = "number")] t: JsValue,
    #[wasm_bindgen(unchecked_param_type = "PoseInput")] b: JsValue,
) -> Result<JsValue, JsError> {
    let a = pose_from_js(&a, "a")?;
    let t = finite(&t, "t")?;
    let b = pose_from_js(&b, "b")?;
    pose_to_js(&crate::screw(&a, t, &b))
}

/// The screw from `a` to `b` evaluated at every fraction in `ts` (the logarithm is computed
/// once): 7 numbers per pose (origin `x, y, z`, quaternion `w, x, y, z`). At most
/// `limits().maxBatch` fractions per call.
#[wasm_bindgen(js_name = screwPoses)]
pub fn screw_poses(
    #[wasm_bindgen(unchecked_param_type = "PoseInput")] a: JsValue,
    #[wasm_bindgen(unchecked_param_type = "PoseInput")] b: JsValue,
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] ts: JsValue,
) -> Result<Vec<f64>, JsError> {
    let a = pose_from_js(&a, "a")?;
    let b = pose_from_js(&b, "b")?;
    let ts = batch(&ts, "ts")?;
    let s = Screw::between(&a, &b);
    Ok(poses_from_fn(ts.len(), |k| s.at(ts[k])))
}

/// Full screw evaluations `screw(starts[k], ts[k], ends[k])` (logarithm and exponential each
/// time): `starts` and `ends` hold 7 numbers per pose, `ts` one fraction per pair; returns 7
/// numbers per pose.
#[wasm_bindgen(js_name = screwPairs)]
pub fn screw_pairs(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] starts: JsValue,
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] ends: JsValue,
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] ts: JsValue,
) -> Result<Vec<f64>, JsError> {
    let ts = batch(&ts, "ts")?;
    let starts = poses_from_js_array(&starts, "starts")?;
    let ends = poses_from_js_array(&ends, "ends")?;
    if starts.len() != ts.len() || ends.len() != ts.len() {
        return Err(Error::OutOfRange {
            at: "ends".into(),
            value: format!(
                "{} start poses, {} end poses and {} fractions",
                starts.len(),
                ends.len(),
                ts.len()
            ),
            expected: "as many start poses and end poses as fractions".into(),
        }
        .into());
    }
    // The batch route: two screws at a time on SIMD lanes, bit for bit the same as `screw`.
    let mut poses = Vec::with_capacity(ts.len());
    Pose::blends(ts.len(), |k| (&starts[k], ts[k], &ends[k]), &mut poses);
    Ok(poses_to_array(&poses))
}

/// The display parameters of the screw from `a` to `b`: its kind (`identity`, `translation`,
/// `general`), axis point and direction, angle in `[0, π]`, slide and pitch.
#[wasm_bindgen(js_name = screwInfo, unchecked_return_type = "ScrewInfo")]
pub fn screw_info(
    #[wasm_bindgen(unchecked_param_type = "PoseInput")] a: JsValue,
    #[wasm_bindgen(unchecked_param_type = "PoseInput")] b: JsValue,
) -> Result<JsValue, JsError> {
    let a = pose_from_js(&a, "a")?;
    let b = pose_from_js(&b, "b")?;
    to_js(&ScrewInfo::from(Screw::between(&a, &b).parameters()))
}

/// Converts poses (7 numbers each, validated) to column-major 4×4 `f32` matrices (16 each).
#[wasm_bindgen(js_name = posesToMatrices)]
pub fn poses_to_matrices_js(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] poses: JsValue,
) -> Result<Vec<f32>, JsError> {
    Ok(poses_to_matrices(&poses_from_js_array(&poses, "poses")?))
}
