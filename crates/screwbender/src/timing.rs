//! Non-uniform timing (docs/math/timing.md; paper §1): a C¹ piecewise-cubic map from animation time to the
//! motion parameter, so control pose `i` is reached at a chosen time `T_i`.
//!
//! The motion's path is unchanged; only the speed along it changes. The map interpolates
//! `p(T_k) = k` with slopes from centred differences, limited by Fritsch–Carlson so that `p` is
//! monotone (the object never moves backwards), and is C¹, so a C¹ motion stays C¹ in time.

use crate::error::{Error, ErrorKind};

/// A monotone C¹ cubic Hermite map `u = p(t)` from time to the coarse motion parameter.
///
/// For `n` control poses, `knots` holds the times `T_0 < T_1 < …` at which they are reached:
/// `n` times for an open motion (domain `[T_0, T_{n−1}]`) and `n + 1` for a cycle (the last is
/// the time at which pose 0 is reached again; the map repeats with period `T_n − T_0`).
#[derive(Clone, Debug, PartialEq)]
pub struct Timing {
    knots: Vec<f64>,
    slopes: Vec<f64>,
    closed: bool,
}

impl Timing {
    /// Uniform timing: pose `i` at time `i` (the identity map).
    pub fn uniform(poses: usize, closed: bool) -> Timing {
        let count = if closed { poses + 1 } else { poses };
        Timing::new((0..count).map(|i| i as f64).collect(), closed)
            .expect("uniform knots are valid")
    }

    /// A timing through the given knot times (see the type's docs for how many).
    ///
    /// Errors: fewer than 2 knots, a non-finite time, or times that do not strictly increase
    /// (naming `times[i]`).
    pub fn new(knots: Vec<f64>, closed: bool) -> Result<Timing, Error> {
        if knots.len() < 2 {
            return Err(Error::new(
                "times",
                ErrorKind::TooFewPoses {
                    found: knots.len(),
                    min: 2,
                },
            ));
        }
        check_increasing_times(&knots, "")?;
        let slopes = monotone_slopes(&knots, closed);
        Ok(Timing {
            knots,
            slopes,
            closed,
        })
    }

    /// The timing of a motion with `poses` control poses: through `times` when given (`poses`
    /// times for an open motion, `poses + 1` for a cycle: the last is when pose 0 is reached
    /// again), else uniform. Errors name `times` (wrong count) or `times[i]`.
    pub fn for_poses(times: Option<Vec<f64>>, poses: usize, closed: bool) -> Result<Timing, Error> {
        let Some(times) = times else {
            return Ok(Timing::uniform(poses, closed));
        };
        let want = poses + usize::from(closed);
        if times.len() != want {
            return Err(Error::new(
                "times",
                ErrorKind::Unsupported {
                    reason: format!(
                        "{} times given, expected {want} ({poses} control poses{})",
                        times.len(),
                        if closed {
                            ", plus the time pose 0 is reached again"
                        } else {
                            ""
                        }
                    ),
                },
            ));
        }
        Timing::new(times, closed)
    }

    /// The knot times.
    pub fn knots(&self) -> &[f64] {
        &self.knots
    }

    /// The time interval `[T_0, T_last]`.
    pub fn duration(&self) -> (f64, f64) {
        (
            self.knots[0],
            *self.knots.last().expect("at least two knots"),
        )
    }

    /// The motion parameter `u = p(t)` and its rate `du/dt` at time `t`.
    ///
    /// A cycle wraps `t` into one period (and `u` into `[0, n)`); an open timing holds the end
    /// values outside its interval (the object rests at the end poses).
    pub fn parameter(&self, t: f64) -> (f64, f64) {
        let (u, du, _) = self.parameter_derivatives(t);
        (u, du)
    }

    /// `u = p(t)`, `du/dt` and `d²u/dt²` at time `t` (see [`Timing::parameter`]). With them a
    /// body point's velocity in time is `v_u u'` and its acceleration `a_u u'² + v_u u''`
    /// ([`crate::Kinematics::retimed`]).
    pub fn parameter_derivatives(&self, t: f64) -> (f64, f64, f64) {
        let (t0, t1) = self.duration();
        let last = self.knots.len() - 1;
        let t = if self.closed {
            t0 + (t - t0).rem_euclid(t1 - t0)
        } else if t < t0 {
            return (0.0, 0.0, 0.0);
        } else if t > t1 {
            return (last as f64, 0.0, 0.0);
        } else {
            t
        };
        // The span k with T_k ≤ t < T_{k+1} (binary search; knots strictly increase).
        let k = self.knots.partition_point(|&x| x <= t).clamp(1, last) - 1;
        let h = self.knots[k + 1] - self.knots[k];
        let s = ((t - self.knots[k]) / h).clamp(0.0, 1.0);
        let (p0, p1) = (k as f64, (k + 1) as f64);
        let (m0, m1) = (self.slopes[k] * h, self.slopes[k + 1] * h);
        let s2 = s * s;
        let s3 = s2 * s;
        let u = (2.0 * s3 - 3.0 * s2 + 1.0) * p0
            + (s3 - 2.0 * s2 + s) * m0
            + (-2.0 * s3 + 3.0 * s2) * p1
            + (s3 - s2) * m1;
        let du = ((6.0 * s2 - 6.0 * s) * p0
            + (3.0 * s2 - 4.0 * s + 1.0) * m0
            + (-6.0 * s2 + 6.0 * s) * p1
            + (3.0 * s2 - 2.0 * s) * m1)
            / h;
        let ddu = ((12.0 * s - 6.0) * p0
            + (6.0 * s - 4.0) * m0
            + (-12.0 * s + 6.0) * p1
            + (6.0 * s - 2.0) * m1)
            / (h * h);
        let u = if self.closed {
            u.rem_euclid(last as f64)
        } else {
            u
        };
        (u, du, ddu)
    }
}

/// Checks that `times` are finite and strictly increasing, naming the first bad `times[i]`;
/// `note` is appended to the out-of-order message (e.g. why equal times are not allowed).
pub(crate) fn check_increasing_times(times: &[f64], note: &str) -> Result<(), Error> {
    for (i, &t) in times.iter().enumerate() {
        if !t.is_finite() {
            return Err(Error::new(format!("times[{i}]"), ErrorKind::NonFinite));
        }
        if i > 0 && t <= times[i - 1] {
            return Err(Error::new(
                format!("times[{i}]"),
                ErrorKind::OutOfRange {
                    value: t.to_string(),
                    expected: format!("a time after times[{}] = {}{note}", i - 1, times[i - 1]),
                },
            ));
        }
    }
    Ok(())
}

/// Slopes `v_k = (p_{k+1} − p_{k−1}) / (T_{k+1} − T_{k−1})` (one-sided at open ends, wrapped for
/// cycles), then limited by Fritsch–Carlson: zero where a secant is zero, and scaled so that
/// `α² + β² ≤ 9` on every span (sufficient for monotonicity). Values are `p_k = k`.
fn monotone_slopes(knots: &[f64], closed: bool) -> Vec<f64> {
    let n = knots.len();
    let last = n - 1;
    // Secant of span k (value step is always 1).
    let secant = |k: usize| 1.0 / (knots[k + 1] - knots[k]);
    let mut v: Vec<f64> = (0..n)
        .map(|k| {
            if closed && (k == 0 || k == last) {
                // Wrap: the span before knot 0 is the last span.
                let before = knots[last] - knots[last - 1];
                let after = knots[1] - knots[0];
                2.0 / (before + after)
            } else if k == 0 {
                secant(0)
            } else if k == last {
                secant(last - 1)
            } else {
                2.0 / (knots[k + 1] - knots[k - 1])
            }
        })
        .collect();
    for k in 0..last {
        let d = secant(k);
        let (a, b) = (v[k] / d, v[k + 1] / d);
        let r = a * a + b * b;
        if r > 9.0 {
            let tau = 3.0 / r.sqrt();
            v[k] = tau * a * d;
            v[k + 1] = tau * b * d;
        }
    }
    if closed {
        // Both ends are the same knot: keep one slope for C¹ across the wrap.
        let m = v[0].min(v[last]);
        v[0] = m;
        v[last] = m;
    }
    v
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn second_derivative_matches_differences_of_the_rate() {
        let t = Timing::new(vec![0.0, 0.5, 2.0, 2.4, 4.0], true).unwrap();
        for k in 1..80 {
            let x = 0.05 * k as f64 + 0.013;
            let h = 1e-6;
            let (_, d0, dd) = t.parameter_derivatives(x);
            let (_, dm, _) = t.parameter_derivatives(x - h);
            let (_, dp, _) = t.parameter_derivatives(x + h);
            assert!((d0 - t.parameter(x).1).abs() < 1e-15);
            assert!(
                ((dp - dm) / (2.0 * h) - dd).abs() < 1e-5 * (1.0 + dd.abs()),
                "t = {x}"
            );
        }
    }

    #[test]
    fn uniform_is_the_identity() {
        let t = Timing::uniform(5, false);
        for x in [0.0, 0.3, 1.5, 3.99, 4.0] {
            let (u, du) = t.parameter(x);
            assert!(
                (u - x).abs() < 1e-15 && (du - 1.0).abs() < 1e-15,
                "{x}: {u} {du}"
            );
        }
        let c = Timing::uniform(4, true);
        assert!((c.parameter(4.5).0 - 0.5).abs() < 1e-15);
        assert!((c.parameter(-0.25).0 - 3.75).abs() < 1e-15);
    }

    #[test]
    fn interpolates_monotone_and_c1() {
        let t = Timing::new(vec![0.0, 0.5, 3.0, 3.2, 6.0], false).unwrap();
        for (k, &tk) in t.knots().iter().enumerate() {
            assert!((t.parameter(tk).0 - k as f64).abs() < 1e-12);
        }
        let mut last = -1.0;
        let mut x = 0.0;
        while x <= 6.0 {
            let (u, du) = t.parameter(x);
            assert!(u >= last - 1e-12 && du >= -1e-12, "not monotone at {x}");
            last = u;
            x += 1e-3;
        }
        // C¹: the rate is continuous at interior knots.
        for &tk in &t.knots()[1..4] {
            let (l, r) = (t.parameter(tk - 1e-9).1, t.parameter(tk + 1e-9).1);
            assert!((l - r).abs() < 1e-6, "rate jumps at {tk}: {l} vs {r}");
        }
    }

    #[test]
    fn bad_times_are_named() {
        let e = Timing::new(vec![0.0, 1.0, 1.0], false).unwrap_err();
        assert_eq!(e.path(), "times[2]");
        let e = Timing::new(vec![0.0, f64::NAN], false).unwrap_err();
        assert_eq!(e.path(), "times[1]");
        assert!(Timing::new(vec![0.0], false).is_err());
    }
}
