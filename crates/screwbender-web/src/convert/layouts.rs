//! Poses, documents and kinematics as JavaScript sees them: pose objects, and the fixed
//! typed-array layouts of the module docs.

use glam::DVec3;
use js_sys::Array;
use screwbender::{Error, ErrorKind, Kinematics, MotionDocument, Pose, RawDocument, RawPose};
use serde::Serialize;
use wasm_bindgen::{JsError, JsValue};

use super::bridge::{check_keys, check_len, check_object, fields_of, from_js, get, join, to_js};
use super::typed_arrays::read_f64_array;
use super::values::{is_absent, plain};

/// Numbers per pose in a pose `Float64Array`: origin `x, y, z`, then quaternion `w, x, y, z`.
pub const POSE_STRIDE: usize = 7;

/// Numbers per pose in a matrix `Float32Array`: a column-major 4×4 matrix.
pub const MATRIX_STRIDE: usize = 16;

/// Numbers per sample in a kinematics `Float64Array` (see the module docs for the order).
pub const KINEMATICS_STRIDE: usize = 16;

thread_local! {
    /// The numbers of pose batches, kept from call to call: refilling it costs only the copy,
    /// where a fresh buffer was also zeroed (a fifth of a `screwPairs` call's time in wasm).
    static POSE_NUMBERS: std::cell::RefCell<Vec<f64>> = const { std::cell::RefCell::new(Vec::new()) };
}

/// Poses (7 numbers each, validated: see [`poses_from_array`]) from a `Float64Array` or an
/// array of numbers, at most [`screwbender::MAX_REFINED_POSES`] of them.
pub(crate) fn poses_from_js_array(value: &JsValue, at: &str) -> Result<Vec<Pose>, Error> {
    let max = screwbender::MAX_REFINED_POSES * POSE_STRIDE;
    let read = |numbers: &mut Vec<f64>| {
        read_f64_array(value, at, max, numbers)?;
        poses_from_array(numbers, at)
    };
    // Reading an array may run a caller's getter, which may call back into this module: the
    // inner call then finds the buffer borrowed and uses a fresh one.
    POSE_NUMBERS.with(|numbers| match numbers.try_borrow_mut() {
        Ok(mut numbers) => read(&mut numbers),
        Err(_) => read(&mut Vec::new()),
    })
}

pub(crate) fn check_pose_shape(value: &JsValue, at: &str, what: &str) -> Result<(), Error> {
    let fields = fields_of::<RawPose>();
    check_keys(value, fields, at, what)?;
    check_len(&get(value, "origin", at)?, 3, &join(at, "origin"), what)?;
    check_len(&get(value, "rotation", at)?, 4, &join(at, "rotation"), what)?;
    let basis = get(value, "basis", at)?;
    let basis_at = join(at, "basis");
    check_len(&basis, 3, &basis_at, what)?;
    if Array::is_array(&basis) {
        for (k, v) in Array::from(&basis).iter().enumerate() {
            check_len(&v, 3, &format!("{basis_at}[{k}]"), what)?;
        }
    }
    Ok(())
}

// ---- poses and documents ----------------------------------------------------------------------

pub(crate) const POSE_SHAPE: &str = "{origin, rotation} or {origin, basis}";

/// A pose object `{origin, rotation}` or `{origin, basis}`, validated like a pose of a motion
/// document; errors are prefixed with `at` (e.g. `pose.rotation: zero quaternion`).
pub(crate) fn pose_from_js(value: &JsValue, at: &str) -> Result<Pose, Error> {
    let value = &plain(value, at)?;
    check_object(value, at, "pose", POSE_SHAPE)?;
    let raw: RawPose = from_js(value, at, "pose")?;
    check_pose_shape(value, at, "pose")?;
    raw.to_pose().map_err(|e| e.within(at))
}

/// A motion document object, through the same [`RawDocument::validate`] as the JSON parser.
pub(crate) fn document_from_js(value: &JsValue) -> Result<MotionDocument, Error> {
    const WHAT: &str = "motion document";
    let value = &plain(value, "")?;
    check_object(value, "", WHAT, "{closed?, name?, poses: [...]}")?;
    let poses = get(value, "poses", "")?;
    let poses = if Array::is_array(&poses) {
        Array::from(&poses).to_vec()
    } else {
        Vec::new()
    };
    for (i, p) in poses.iter().enumerate() {
        check_object(p, &format!("poses[{i}]"), WHAT, POSE_SHAPE)?;
    }
    let raw: RawDocument = from_js(value, "", WHAT)?;
    check_keys(value, fields_of::<RawDocument>(), "", WHAT)?;
    for (i, p) in poses.iter().enumerate() {
        check_pose_shape(p, &format!("poses[{i}]"), WHAT)?;
    }
    raw.validate()
}

/// A pose as the plain object `{origin: [x, y, z], rotation: [w, x, y, z]}`.
pub(crate) fn pose_to_js(pose: &Pose) -> Result<JsValue, JsError> {
    to_js(&RawPose::from_pose(pose))
}

/// A motion document as a plain object (every pose as `origin` + `rotation`).
pub(crate) fn document_to_js(doc: &MotionDocument) -> Result<JsValue, JsError> {
    to_js(&doc.to_raw())
}

/// An optional local point `[x, y, z]` (absent: the local origin).
pub(crate) fn point_from_js(value: &JsValue, at: &str) -> Result<DVec3, Error> {
    if is_absent(value) {
        return Ok(DVec3::ZERO);
    }
    let value = &plain(value, at)?;
    let p: [f64; 3] = from_js(value, at, "point")?;
    check_len(value, 3, at, "point")?;
    if !p.iter().all(|v| v.is_finite()) {
        return Err(Error::new(at.to_string(), ErrorKind::NonFinite));
    }
    Ok(DVec3::from_array(p))
}

// ---- typed arrays -----------------------------------------------------------------------------

/// Writes one pose in the [`POSE_STRIDE`] layout into `out` (7 numbers).
#[inline]
pub(crate) fn write_pose(out: &mut [f64], p: &Pose) {
    let q = p.rotation_wxyz();
    out.copy_from_slice(&[p.origin.x, p.origin.y, p.origin.z, q[0], q[1], q[2], q[3]]);
}

/// `count` poses `pose(k)` in the [`POSE_STRIDE`] layout (the bulk functions' inner loop: one
/// zeroed allocation, no capacity checks).
#[inline]
pub(crate) fn poses_from_fn(count: usize, mut pose: impl FnMut(usize) -> Pose) -> Vec<f64> {
    let mut out = vec![0.0; count * POSE_STRIDE];
    for (k, chunk) in out.chunks_exact_mut(POSE_STRIDE).enumerate() {
        write_pose(chunk, &pose(k));
    }
    out
}

/// Poses in the [`POSE_STRIDE`] layout.
pub(crate) fn poses_to_array(poses: &[Pose]) -> Vec<f64> {
    poses_from_fn(poses.len(), |k| poses[k])
}

/// Poses as column-major 4×4 `f32` matrices ([`MATRIX_STRIDE`] layout) — the only place in the
/// JS API where `f64` becomes `f32`.
pub(crate) fn poses_to_matrices(poses: &[Pose]) -> Vec<f32> {
    let mut out = Vec::with_capacity(poses.len() * MATRIX_STRIDE);
    for p in poses {
        out.extend(p.to_matrix().to_cols_array().iter().map(|v| *v as f32));
    }
    out
}

/// Poses from the [`POSE_STRIDE`] layout, each validated by [`Pose::from_wxyz`]; errors name
/// `at[i]`.
pub(crate) fn poses_from_array(data: &[f64], at: &str) -> Result<Vec<Pose>, Error> {
    if data.len() % POSE_STRIDE != 0 {
        return Err(Error::new(
            at.to_string(),
            ErrorKind::OutOfRange {
                value: format!("length {}", data.len()),
                expected: format!(
                "a multiple of {POSE_STRIDE} (origin x, y, z and quaternion w, x, y, z per pose)"
            ),
            },
        ));
    }
    let mut poses = Vec::with_capacity(data.len() / POSE_STRIDE);
    // The valid poses in one go; `from_wxyz` only to describe what is wrong.
    while !push_valid_poses(&data[poses.len() * POSE_STRIDE..], &mut poses) {
        let (i, c) = (poses.len(), &data[poses.len() * POSE_STRIDE..]);
        let pose = Pose::from_wxyz([c[0], c[1], c[2]], [c[3], c[4], c[5], c[6]])
            .map_err(|e| e.within(&format!("{at}[{i}]")))?;
        poses.push(pose);
    }
    Ok(poses)
}

/// Appends the poses of `numbers` (the [`POSE_STRIDE`] layout, a whole number of poses) to
/// `out`, as [`Pose::from_wxyz`] makes them, up to the first invalid one; returns whether they
/// were all valid. (Out of line: one copy for every batch of poses from JavaScript.)
#[inline(never)]
pub(crate) fn push_valid_poses(numbers: &[f64], out: &mut Vec<Pose>) -> bool {
    let (before, count) = (out.len(), numbers.len() / POSE_STRIDE);
    out.extend(
        numbers
            .chunks_exact(POSE_STRIDE)
            .map_while(|c| Pose::from_valid_wxyz([c[0], c[1], c[2]], [c[3], c[4], c[5], c[6]])),
    );
    out.len() - before == count
}

/// Appends one kinematics sample in the [`KINEMATICS_STRIDE`] layout.
pub(crate) fn push_kinematics(out: &mut Vec<f64>, u: f64, k: &Kinematics) {
    out.push(u);
    for v in [
        k.position,
        k.velocity,
        k.acceleration,
        k.angular_velocity,
        k.angular_acceleration,
    ] {
        out.extend_from_slice(&v.to_array());
    }
}

/// The kinematics of one body point as a plain object.
pub(crate) fn kinematics_to_js(k: &Kinematics) -> Result<JsValue, JsError> {
    #[derive(Serialize)]
    #[serde(rename_all = "camelCase")]
    struct Out {
        position: [f64; 3],
        velocity: [f64; 3],
        acceleration: [f64; 3],
        angular_velocity: [f64; 3],
        angular_acceleration: [f64; 3],
    }
    to_js(&Out {
        position: k.position.to_array(),
        velocity: k.velocity.to_array(),
        acceleration: k.acceleration.to_array(),
        angular_velocity: k.angular_velocity.to_array(),
        angular_acceleration: k.angular_acceleration.to_array(),
    })
}
