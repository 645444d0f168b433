//! Analysis in real time for the plots: a motion retimed by per-pose times (the C¹ monotone map
//! `u = p(t)` of [`screwbender::Timing`]), its body-point kinematics per second, and the map itself.

use std::cell::RefCell;

use wasm_bindgen::prelude::*;

use super::convert::{
    count, f64_array, finite, from_js, is_absent, plain, point_from_js, push_kinematics, string,
};
use super::motion::sample_parameters;
use super::MotionHandle;
use screwbender::methods::{sampled_difference, Side};
use screwbender::{Error, ErrorKind, MotionDocument, Timing, MAX_REFINED_POSES};

/// Bisection steps of [`MotionHandle::time_at`]: the span's length over `2^64`, below one ulp.
const INVERSE_BISECTION_STEPS: u32 = 64;

/// A playback clock's view of a motion: its timing, whether it is uniform (pose `i` at `i` s:
/// then `u = t` exactly, with no rounding of the cubic) and its parameter interval.
struct Clock {
    timing: Timing,
    uniform: bool,
    closed: bool,
    /// The last key index: `n − 1` (open) or `n` (a cycle's return to pose 0).
    last: f64,
    /// What the timing was built from (the cache key of [`with_clock`]).
    key: ClockKey,
}

/// The parts of a document a [`Clock`] depends on.
#[derive(PartialEq)]
struct ClockKey {
    poses: usize,
    closed: bool,
    times: Option<Vec<f64>>,
    velocities: Option<Vec<Option<f64>>>,
}

thread_local! {
    /// The clock of the last document asked about: playback asks several times per frame, and a
    /// timing with key velocities costs a search per key to build (wasm is single-threaded).
    static CLOCK: RefCell<Option<Clock>> = const { RefCell::new(None) };
}

/// Runs `f` on the clock of `doc`, built only when the document's timing differs from the last.
fn with_clock<R>(doc: MotionDocument, f: impl FnOnce(&Clock) -> R) -> Result<R, Error> {
    let key = ClockKey {
        poses: doc.poses.len(),
        closed: doc.closed,
        times: doc.times,
        velocities: doc.velocities,
    };
    CLOCK.with(|cell| {
        let mut cached = cell.borrow_mut();
        let clock = match cached.take() {
            Some(c) if c.key == key => c,
            _ => Clock::of(key)?,
        };
        let out = f(&clock);
        *cached = Some(clock);
        Ok(out)
    })
}

impl Clock {
    fn of(key: ClockKey) -> Result<Clock, Error> {
        Ok(Clock {
            timing: Timing::for_keys(
                key.times.clone(),
                key.velocities.as_deref(),
                key.poses,
                key.closed,
            )?,
            uniform: key.times.is_none() && key.velocities.is_none(),
            closed: key.closed,
            last: (key.poses - usize::from(!key.closed)) as f64,
            key,
        })
    }

    /// `u = p(t)`: a cycle wraps `t` into one period, an open motion rests at its end poses.
    fn parameter(&self, t: f64) -> f64 {
        if !self.uniform {
            return self.timing.parameter(t).0;
        }
        if self.closed {
            t.rem_euclid(self.last)
        } else {
            t.clamp(0.0, self.last)
        }
    }

    /// `t = p⁻¹(u)`: a cycle wraps `u` into `[0, n)` (and `t` into one period), an open motion
    /// clamps `u` to its interval. Key `k` gives exactly `T_k`; between keys, bisection on the
    /// span (`p` increases strictly there: it is monotone and rises by 1 over the span).
    fn time(&self, u: f64) -> f64 {
        let u = if self.closed {
            u.rem_euclid(self.last)
        } else {
            u.clamp(0.0, self.last)
        };
        if self.uniform {
            return u;
        }
        let knots = self.timing.knots();
        if u.fract() == 0.0 {
            return knots[(u as usize).min(knots.len() - 1)];
        }
        let k = (u.floor() as usize).min(knots.len() - 2);
        let (mut lo, mut hi) = (knots[k], knots[k + 1]);
        for _ in 0..INVERSE_BISECTION_STEPS {
            let mid = 0.5 * (lo + hi);
            if mid <= lo || mid >= hi {
                break;
            }
            // Inside the span, so no wrapping: p(mid) is the span's cubic.
            if self.timing.parameter(mid).0 < u {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    }
}

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
    /// The playback interval `[T_0, T_last]` in seconds of the motion's own timing
    /// (`motion.times`; uniform: `[0, n − 1]` for an open motion, `[0, n]` for a cycle, whose
    /// last time is the return to pose 0).
    #[wasm_bindgen(js_name = timeDomain)]
    pub fn time_domain(&self) -> Result<Vec<f64>, JsError> {
        let (doc, _) = self.snapshot()?;
        let (t0, t1) = with_clock(doc, |c| c.timing.duration())?;
        Ok(vec![t0, t1])
    }

    /// The motion parameter `u = p(t)` shown at time `t` seconds: the C¹ monotone retiming by
    /// the motion's own key times and velocities (docs/math/timing.md §3), so pose `i` is
    /// reached at `motion.times[i]`. A cycle repeats with its period; an open motion rests at
    /// its first pose before `T_0` and at its last after `T_last`. Uniform timing gives `u = t`
    /// exactly (wrapped into `[0, n)` for a cycle, clamped to `[0, n − 1]` otherwise). Throws
    /// naming `t` when it is not a finite number.
    #[wasm_bindgen(js_name = parameterAt)]
    pub fn parameter_at(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] t: JsValue,
    ) -> Result<f64, JsError> {
        let t = finite(&t, "t")?;
        let (doc, _) = self.snapshot()?;
        Ok(with_clock(doc, |c| c.parameter(t))?)
    }

    /// The time in seconds at which the motion shows parameter `u` (the inverse of
    /// [`parameterAt`](MotionHandle::parameter_at)): `motion.times[k]` exactly at key `k`, and
    /// to within one rounding of `t` between keys. A cycle wraps `u` into `[0, n)`, an open
    /// motion clamps it to `[0, n − 1]`. Throws naming `u` when it is not a finite number.
    #[wasm_bindgen(js_name = timeAt)]
    pub fn time_at(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] u: JsValue,
    ) -> Result<f64, JsError> {
        let u = finite(&u, "u")?;
        let (doc, _) = self.snapshot()?;
        Ok(with_clock(doc, |c| c.time(u))?)
    }

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
