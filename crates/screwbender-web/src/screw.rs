//! Free functions on screws: one screw at one or many fractions, many screws at once, and the
//! display parameters of a screw.

use wasm_bindgen::prelude::*;

use js_sys::Float64Array;

use super::convert::{
    finite, pose_from_js, pose_to_js, poses_from_array, poses_from_fn, poses_from_js_array,
    poses_to_matrices, push_valid_poses, to_js, write_pose, NumberList, ScrewInfo, POSE_STRIDE,
};
use super::motion::batch;
use screwbender::{Blend, Error, ErrorKind, Pose, Screw, MAX_REFINED_POSES};

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
    pose_to_js(&screwbender::screw(&a, t, &b))
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
) -> Result<Float64Array, JsError> {
    let ts = batch(&ts, "ts")?;
    let max = MAX_REFINED_POSES * POSE_STRIDE;
    let starts = NumberList::from_js(&starts, "starts", max)?;
    let ends = NumberList::from_js(&ends, "ends", max)?;
    Ok(screw_pairs_of(&starts, &ends, &ts)?)
}

/// Pairs per chunk of [`screw_pairs_of`]: its numbers and poses stay in the nearest caches (a
/// chunk takes about 100 KB).
const PAIRS_PER_CHUNK: usize = 256;

/// `screwPairs` chunk by chunk: each chunk's poses are read, validated, screwed (the batch
/// route: several screws at a time on SIMD lanes, bit for bit the same as `screw`) and copied into
/// the result while they are in the cache. Going through whole arrays of poses instead spent
/// more time on memory traffic than on the screws.
fn screw_pairs_of(
    starts: &NumberList,
    ends: &NumberList,
    ts: &[f64],
) -> Result<Float64Array, Error> {
    let n = ts.len();
    if starts.len() != n * POSE_STRIDE || ends.len() != n * POSE_STRIDE {
        return Err(screw_pairs_error(starts, ends, ts));
    }
    let out = Float64Array::new_with_length((n * POSE_STRIDE) as u32);
    let chunk = PAIRS_PER_CHUNK.min(n);
    let (mut a, mut b) = (Vec::with_capacity(chunk), Vec::with_capacity(chunk));
    let mut poses = Vec::with_capacity(chunk);
    let mut numbers = Vec::with_capacity(chunk * POSE_STRIDE);
    for first in (0..n).step_by(PAIRS_PER_CHUNK) {
        let last = (first + PAIRS_PER_CHUNK).min(n);
        let range = first * POSE_STRIDE..last * POSE_STRIDE;
        for (list, poses) in [(starts, &mut a), (ends, &mut b)] {
            list.read(range.clone(), &mut numbers)?;
            poses.clear();
            if !push_valid_poses(&numbers, poses) {
                return Err(screw_pairs_error(starts, ends, ts));
            }
        }
        poses.clear();
        Pose::blends(last - first, |k| (&a[k], ts[first + k], &b[k]), &mut poses);
        for (slot, pose) in numbers.chunks_exact_mut(POSE_STRIDE).zip(&poses) {
            write_pose(slot, pose);
        }
        out.subarray(range.start as u32, range.end as u32)
            .copy_from(&numbers);
    }
    Ok(out)
}

/// What is wrong with the arguments of a `screwPairs` call that [`screw_pairs_of`] refused: the
/// first invalid start pose, else the first invalid end pose, else the counts.
#[cold]
fn screw_pairs_error(starts: &NumberList, ends: &NumberList, ts: &[f64]) -> Error {
    let poses = |list: &NumberList, at: &str| {
        let mut numbers = Vec::new();
        list.read(0..list.len(), &mut numbers)?;
        poses_from_array(&numbers, at).map(|poses| poses.len())
    };
    let counts = poses(starts, "starts").and_then(|starts| Ok((starts, poses(ends, "ends")?)));
    match counts {
        Err(e) => e,
        Ok((starts, ends)) => Error::new(
            "ends",
            ErrorKind::OutOfRange {
                value: format!(
                    "{starts} start poses, {ends} end poses and {} fractions",
                    ts.len()
                ),
                expected: "as many start poses and end poses as fractions".into(),
            },
        ),
    }
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
