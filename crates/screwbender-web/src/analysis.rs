//! Analysis in real time for the plots: a motion retimed by per-pose times (the C¹ monotone map
//! `u = p(t)` of [`screwbender::Timing`]), its body-point kinematics per second, and the map itself.

use wasm_bindgen::prelude::*;

use super::convert::{
    count, f64_array, from_js, is_absent, plain, point_from_js, push_kinematics, string,
};
use super::motion::sample_parameters;
use super::MotionHandle;
use screwbender::methods::{sampled_difference, Side};
use screwbender::{Error, ErrorKind, Timing, MAX_REFINED_POSES};

/// The timing of a motion with `poses` control poses from optional `times` (default uniform)
/// and optional key `velocities` (numbers ≥ 0 in poses per second, or `null` where free).
fn timing(
    times: &JsValue,
    velocities: &JsValue,
    poses: usize,
    closed: bool,
) -> Result<Timing, Error> {
    let times = if is_absent(times) {
        None
    } else {
        Some(f64_array(times, "times", poses + 2)?)
    };
    let velocities = if is_absent(velocities) {
        None
    } else {
        let list = plain(velocities, "velocities")?;
        Some(from_js::<Vec<Option<f64>>>(
            &list,
            "velocities",
            "velocity list (numbers or null)",
        )?)
    };
    Timing::for_keys(times, velocities.as_deref(), poses, closed)
}

#[wasm_bindgen(js_class = Motion)]
impl MotionHandle {
    /// Kinematics of the body point `local` in real time: the motion retimed so that control
    /// pose `i` is reached at `times[i]` (a cycle has one more time: pose 0 again), sampled at
    /// `count` uniform times. 16 numbers per sample as in `sampleKinematics`, except that the
    /// first is the time `t` and the derivatives are per second (chain rule through the C¹ map).
    /// Without `times`, the motion's own key times and velocities (`motion.times`,
    /// `motion.velocities`; uniform when it has none: pose `i` at `t = i`).
    ///
    /// `derivatives`: `'analytic'` (default) gives the closed-form kinematics of the refined
    /// polyscrew (one screw per refined span: constant angular velocity inside a span, jumps at
    /// refined knots that shrink with each level); `'limit'` gives differences of the refined
    /// poses with the refined span as step, which approximate the smooth limit motion (what the
    /// paper's Fig. 8 plots).
    #[wasm_bindgen(js_name = timedKinematics)]
    pub fn timed_kinematics(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] samples: JsValue,
        #[wasm_bindgen(unchecked_optional_param_type = "Vec3")] local: JsValue,
        #[wasm_bindgen(unchecked_optional_param_type = "Float64Array | number[]")] times: JsValue,
        #[wasm_bindgen(unchecked_optional_param_type = "'analytic' | 'limit'")]
        derivatives: JsValue,
    ) -> Result<Vec<f64>, JsError> {
        let n = count(&samples, "count", MAX_REFINED_POSES)?;
        let local = point_from_js(&local, "local")?;
        let limit = if is_absent(&derivatives) {
            false
        } else {
            match string(&derivatives, "derivatives")?.as_str() {
                "analytic" => false,
                "limit" => true,
                other => {
                    return Err(Error::new(
                        "derivatives",
                        ErrorKind::UnknownValue {
                            value: other.into(),
                            expected: "analytic, limit",
                        },
                    )
                    .into())
                }
            }
        };
        let (doc, sub) = self.snapshot()?;
        let timing = if is_absent(&times) {
            doc.timing()?
        } else {
            timing(&times, &JsValue::UNDEFINED, doc.poses.len(), doc.closed)?
        };
        let (start, end) = (0.0, (doc.poses.len() - usize::from(!doc.closed)) as f64);
        let h = 0.5f64.powi(sub.levels as i32);
        self.with_refined(|m| {
            let mut out = Vec::with_capacity(n * super::KINEMATICS_STRIDE);
            for t in sample_parameters(timing.duration(), doc.closed, n) {
                let (u, du, ddu) = timing.parameter_derivatives(t);
                let k = if limit {
                    // One-sided within three steps of an open motion's ends.
                    let side = match () {
                        _ if doc.closed => Side::Central,
                        _ if u - 3.0 * h < start => Side::Right,
                        _ if u + 3.0 * h > end => Side::Left,
                        _ => Side::Central,
                    };
                    sampled_difference(m, u, local, side, h, h)
                } else {
                    m.refined().point_kinematics(u, local)
                };
                push_kinematics(&mut out, t, &k.retimed(du, ddu));
            }
            out
        })
    }
}

/// The retiming map of a motion with `poses` control poses reached at `times` (a cycle: one more
/// time, when pose 0 is reached again): `count` triples `t, u = p(t), du/dt` at uniform times.
/// The map is C¹ and monotone (Fritsch–Carlson slopes), so the object never moves backwards.
/// Optional `velocities` (one per control pose, a number ≥ 0 in poses per second or `null`)
/// fix the rate `du/dt` at those keys (docs/math/timing.md §3).
#[wasm_bindgen(js_name = timingMap)]
pub fn timing_map(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] times: JsValue,
    #[wasm_bindgen(unchecked_param_type = "number")] poses: JsValue,
    #[wasm_bindgen(unchecked_param_type = "boolean")] closed: JsValue,
    #[wasm_bindgen(unchecked_param_type = "number")] samples: JsValue,
    #[wasm_bindgen(unchecked_optional_param_type = "(number | null)[]")] velocities: JsValue,
) -> Result<Vec<f64>, JsError> {
    let poses = count(&poses, "poses", MAX_REFINED_POSES)?;
    let closed = super::convert::boolean(&closed, "closed")?;
    let n = count(&samples, "count", MAX_REFINED_POSES)?;
    let timing = timing(&times, &velocities, poses, closed)?;
    let mut out = Vec::with_capacity(3 * n);
    for t in sample_parameters(timing.duration(), closed, n) {
        let (u, du) = timing.parameter(t);
        out.extend_from_slice(&[t, u, du]);
    }
    Ok(out)
}
