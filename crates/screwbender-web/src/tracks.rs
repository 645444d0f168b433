//! three.js interop: `motion.keyframeTracks(options)` gives the motion as keyframe arrays for
//! three.js `VectorKeyframeTrack` / `QuaternionKeyframeTrack`, sampled exactly as
//! `motion.exportFile` samples the glTF animation (the core's [`screwbender::keyframe_tracks`]:
//! the keys of `sample_document`, which the export calls, for adaptive sampling).
//!
//! Feature `tracks`: in the playground's build and the npm package's `screwbender/full` entry
//! (the light main module leaves it out for its size budget). Kept small all the same: adaptive
//! sampling only (a fixed frame rate is `exportFile`'s), options read without serde, and the
//! object's extent given as a radius or its points (no named meshes).

use js_sys::{Float32Array, Object, Reflect};
use wasm_bindgen::prelude::*;

use super::convert::{check_keys, check_object, f64_array, finite, get, is_absent, plain};
use super::MotionHandle;
use screwbender::{keyframe_tracks, Error, ErrorKind, DEFAULT_TOLERANCE, MAX_REFINED_POSES};

/// Most numbers accepted in `points` (x, y, z per point).
const MAX_POINT_NUMBERS: usize = 3 << 22;

/// The radius used when the options give neither `radius` nor `points`: 1 scene unit.
const DEFAULT_RADIUS: f64 = 1.0;

#[wasm_bindgen(typescript_custom_section)]
const TS_TRACKS: &'static str = r#"
/** What `Motion.keyframeTracks` samples. */
export interface TrackOptions {
  /** Adaptive sampling: the largest distance (scene units) between the keyframe interpolation (lerped position, slerped rotation) and the true motion at the object's points (default 1e-4). */
  tolerance?: number;
  /** Control-pose times in seconds (n for an open motion, n + 1 for a cycle); default: the motion's own (`motion.times`), else 1 s per span. The motion's key velocities apply either way. */
  times?: number[];
  /** The object's extent around its local origin at which the tolerance holds (scene units); not with `points`. Default: from `points`, else 1. */
  radius?: number;
  /** The object's points in its local frame, x, y, z each (e.g. a three.js geometry's `attributes.position.array`): the radius is their farthest distance from the origin. */
  points?: Float32Array | Float64Array | number[];
}

/** The result of `Motion.keyframeTracks`: arrays for three.js keyframe tracks. */
export interface KeyframeTracks {
  /** Key times in seconds from 0 (the motion's first key time, `startTime`, is subtracted), strictly increasing. */
  times: Float32Array;
  /** The local origin's position per key: x, y, z. For `new VectorKeyframeTrack('.position', times, positions)`. */
  positions: Float32Array;
  /** The rotation per key as a unit quaternion **x, y, z, w** (three.js and glTF order — NOT the `[w, x, y, z]` of `Pose.rotation`), consecutive keys with a non-negative dot. For `new QuaternionKeyframeTrack('.quaternion', times, quaternions)`. */
  quaternions: Float32Array;
  /** The motion's first key time (seconds). */
  startTime: number;
  /** The clip's length in seconds (the last key time). */
  duration: number;
  /** The radius the tolerance holds at (scene units). */
  radius: number;
  /** The tolerance (scene units). */
  tolerance: number;
}
"#;

/// The farthest distance from the origin of the points `x, y, z, …` in `value` (a
/// `Float32Array`, `Float64Array` or array of numbers).
fn points_radius(value: &JsValue) -> Result<f64, Error> {
    let numbers: Vec<f64> = match value.dyn_ref::<Float32Array>() {
        Some(a) if a.length() as usize <= MAX_POINT_NUMBERS => {
            a.to_vec().into_iter().map(f64::from).collect()
        }
        Some(a) => {
            return Err(Error::new(
                "points",
                ErrorKind::OutOfRange {
                    value: format!("{} numbers", a.length()),
                    expected: format!("at most {MAX_POINT_NUMBERS} numbers"),
                },
            ))
        }
        None => f64_array(value, "points", MAX_POINT_NUMBERS)?,
    };
    if numbers.is_empty() || numbers.len() % 3 != 0 {
        return Err(Error::new(
            "points",
            ErrorKind::OutOfRange {
                value: format!("{} numbers", numbers.len()),
                expected: "x, y, z per point (a positive multiple of 3 numbers)".into(),
            },
        ));
    }
    if numbers.iter().any(|x| !x.is_finite()) {
        return Err(Error::new("points", ErrorKind::NonFinite));
    }
    Ok(numbers
        .chunks_exact(3)
        .map(|p| (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt())
        .fold(0.0, f64::max))
}

fn set(obj: &Object, key: &str, value: JsValue) {
    // Defining a property on a fresh plain object cannot fail.
    let _ = Reflect::set(obj, &JsValue::from_str(key), &value);
}

#[wasm_bindgen(js_class = Motion)]
impl MotionHandle {
    /// The motion as keyframe arrays for three.js (`times`, `positions` x,y,z, `quaternions`
    /// x,y,z,w), sampled adaptively as `exportFile` samples the glTF animation: a player lerping
    /// positions and slerping rotations stays within `tolerance` of the motion at every object
    /// point within `radius` of the origin; the motion's key times and velocities apply. Throws
    /// on bad options (the message names the option); the motion is never changed.
    #[wasm_bindgen(js_name = keyframeTracks, unchecked_return_type = "KeyframeTracks")]
    pub fn keyframe_tracks_js(
        &self,
        #[wasm_bindgen(unchecked_optional_param_type = "TrackOptions")] options: JsValue,
    ) -> Result<JsValue, JsError> {
        let (mut tolerance, mut times, mut radius) = (DEFAULT_TOLERANCE, None, None);
        if !is_absent(&options) {
            let options = plain(&options, "options")?;
            check_object(&options, "options", "track options", "{tolerance?, …}")?;
            check_keys(
                &options,
                &["tolerance", "times", "radius", "points"],
                "options",
                "track options",
            )?;
            let field = |key: &str| get(&options, key, key);
            let value = field("tolerance")?;
            if !is_absent(&value) {
                tolerance = finite(&value, "tolerance")?;
            }
            let value = field("times")?;
            if !is_absent(&value) {
                times = Some(f64_array(&value, "times", MAX_REFINED_POSES)?);
            }
            let value = field("radius")?;
            if !is_absent(&value) {
                radius = Some(finite(&value, "radius")?);
            }
            let points = field("points")?;
            if !is_absent(&points) {
                if radius.is_some() {
                    return Err(Error::new(
                        "points",
                        ErrorKind::Unsupported {
                            reason: "give either radius or points, not both".into(),
                        },
                    )
                    .into());
                }
                radius = Some(points_radius(&points)?);
            }
        }
        let radius = radius.unwrap_or(DEFAULT_RADIUS);
        let (doc, sub) = self.snapshot()?;
        let tracks = keyframe_tracks(&doc, sub, tolerance, times.as_deref(), radius)?;
        let duration = tracks.times.last().copied().unwrap_or(0.0);
        let out = Object::new();
        set(&out, "times", Float32Array::from(&tracks.times[..]).into());
        set(
            &out,
            "positions",
            Float32Array::from(&tracks.positions[..]).into(),
        );
        set(
            &out,
            "quaternions",
            Float32Array::from(&tracks.quaternions[..]).into(),
        );
        set(&out, "startTime", tracks.start_time.into());
        set(&out, "duration", f64::from(duration).into());
        set(&out, "radius", radius.into());
        set(&out, "tolerance", tolerance.into());
        Ok(out.into())
    }
}
