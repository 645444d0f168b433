//! Non-uniform timing (docs/math/timing.md; paper §1): a C¹ piecewise-cubic map from animation time to the
//! motion parameter, so control pose `i` is reached at a chosen time `T_i`.
//!
//! The motion's path is unchanged; only the speed along it changes. The map interpolates
//! `p(T_k) = k` and, at keys that carry one, a given velocity `p'(T_k) = v_k` (docs/math/timing.md
//! §3); the other slopes come from centred differences, limited by Fritsch–Carlson so that `p` is
//! monotone (the object never moves backwards). It is C¹, so a C¹ motion stays C¹ in time.

use crate::error::{Error, ErrorKind};

/// A monotone C¹ cubic Hermite map `u = p(t)` from time to the coarse motion parameter.
///
/// For `n` control poses, `knots` holds the times `T_0 < T_1 < …` at which they are reached:
/// `n` times for an open motion (domain `[T_0, T_{n−1}]`) and `n + 1` for a cycle (the last is
/// the time at which pose 0 is reached again; the map repeats with period `T_n − T_0`).
///
/// Each key may carry a velocity `p'(T_k)` in poses per second ([`Timing::with_velocities`]);
/// the map then has exactly that slope there (a cycle's pose 0 has one velocity, used at both
/// ends of the period).
#[derive(Clone, Debug, PartialEq)]
pub struct Timing {
    knots: Vec<f64>,
    slopes: Vec<f64>,
    velocities: Vec<Option<f64>>,
    closed: bool,
}

/// How far below zero the normalised rate of a span may dip through rounding and still count as
/// monotone (relative to the span's secant; `p'` itself is clamped at zero nowhere).
const MONOTONE_SLACK: f64 = 1e-12;

/// The largest normalised slope `α = p'(T_k) / δ` (`δ` the span's secant) for which any
/// monotone cubic exists on a span (the monotonicity region of docs/math/timing.md §3 reaches
/// `α = 4` at `β = 1`).
const MAX_NORMALISED_SLOPE: f64 = 4.0;

/// Steps of the searches for the monotone range of a free slope (ternary search for the best
/// point, then bisection for each edge: `(2/3)^100` and `2^-60` of the range `[0, 4]`).
const RANGE_SEARCH_STEPS: u32 = 100;
const EDGE_BISECTION_STEPS: u32 = 60;

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
        let keys = knots.len() - usize::from(closed);
        Ok(Timing {
            knots,
            slopes,
            velocities: vec![None; keys],
            closed,
        })
    }

    /// A timing through the knot times `knots` whose keys carry the velocities `velocities`
    /// (`p'(T_k)` in poses per second, `None`: free, chosen as in [`Timing::new`]): one per key,
    /// that is one per knot for an open motion and one fewer for a cycle (pose 0's velocity holds
    /// at both ends of the period).
    ///
    /// Free slopes next to a given one are limited so that each span stays monotone
    /// (docs/math/timing.md §3). Without any velocity the result equals [`Timing::new`]'s bit for
    /// bit.
    ///
    /// Errors: those of [`Timing::new`]; a wrong velocity count (`velocities`); a velocity that
    /// is negative or not finite (`velocities[i]`); a velocity that would make time run
    /// backwards, i.e. no monotone cubic exists on a span with it (`velocities[i]`, with the
    /// range that would work).
    pub fn with_velocities(
        knots: Vec<f64>,
        velocities: &[Option<f64>],
        closed: bool,
    ) -> Result<Timing, Error> {
        let plain = Timing::new(knots, closed)?;
        let keys = plain.velocities.len();
        if velocities.len() != keys {
            return Err(Error::new(
                "velocities",
                ErrorKind::Unsupported {
                    reason: format!(
                        "{} velocities given, expected {keys} (one per key{})",
                        velocities.len(),
                        if closed {
                            "; pose 0's holds at both ends of the cycle"
                        } else {
                            ""
                        }
                    ),
                },
            ));
        }
        check_velocities(velocities)?;
        if velocities.iter().all(Option::is_none) {
            return Ok(plain);
        }
        let slopes = constrained_slopes(&plain.knots, velocities, closed)?;
        Ok(Timing {
            slopes,
            velocities: velocities.to_vec(),
            ..plain
        })
    }

    /// The timing of a motion with `poses` control poses: through `times` when given, else
    /// uniform, and with the key velocities `velocities` when given (one per control pose; see
    /// [`Timing::with_velocities`]). Errors name `times`, `times[i]`, `velocities` or
    /// `velocities[i]`.
    pub fn for_keys(
        times: Option<Vec<f64>>,
        velocities: Option<&[Option<f64>]>,
        poses: usize,
        closed: bool,
    ) -> Result<Timing, Error> {
        let timing = Timing::for_poses(times, poses, closed)?;
        match velocities {
            None => Ok(timing),
            Some(v) => Timing::with_velocities(timing.knots, v, closed),
        }
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

    /// The given key velocities, one per key (`None` where the slope is free).
    pub fn velocities(&self) -> &[Option<f64>] {
        &self.velocities
    }

    /// The slope `p'(T_k)` at every knot (poses per second): the given velocities, and the
    /// limited centred differences elsewhere.
    pub fn slopes(&self) -> &[f64] {
        &self.slopes
    }

    /// Whether the timing is periodic (a cycle).
    pub fn is_closed(&self) -> bool {
        self.closed
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

/// Checks key velocities: each given one finite and ≥ 0 (naming `velocities[i]`).
pub(crate) fn check_velocities(velocities: &[Option<f64>]) -> Result<(), Error> {
    for (i, v) in velocities.iter().enumerate() {
        match v {
            Some(v) if !v.is_finite() => {
                return Err(Error::new(format!("velocities[{i}]"), ErrorKind::NonFinite))
            }
            Some(v) if *v < 0.0 => {
                return Err(Error::new(
                    format!("velocities[{i}]"),
                    ErrorKind::OutOfRange {
                        value: v.to_string(),
                        expected: "a velocity ≥ 0 (poses per second; time never runs backwards)"
                            .into(),
                    },
                ))
            }
            _ => {}
        }
    }
    Ok(())
}

/// The least value over `σ ∈ [0, 1]` of the normalised rate `p'(σ) / δ` of one span with end
/// slopes `α`, `β` (in units of the secant `δ`): `α + (6 − 4α − 2β) σ + 3(α + β − 2) σ²`
/// (docs/math/timing.md §3). The span is monotone when this is ≥ 0.
fn least_rate(alpha: f64, beta: f64) -> f64 {
    let a = 3.0 * (alpha + beta - 2.0);
    let b = 6.0 - 4.0 * alpha - 2.0 * beta;
    let mut least = alpha.min(beta);
    if a > 0.0 {
        let s = -b / (2.0 * a);
        if s > 0.0 && s < 1.0 {
            least = least.min(alpha - b * b / (4.0 * a));
        }
    }
    least
}

/// The interval of normalised slopes `β` that keep a span monotone when the other end has
/// `α` (`None` when there is none: `α > 4`). The set is convex (the rate at each `σ` is linear
/// in `β`), so it is found from its best point (ternary search of the concave [`least_rate`])
/// by bisection towards each edge.
fn monotone_range(alpha: f64) -> Option<(f64, f64)> {
    let g = |beta: f64| least_rate(alpha, beta);
    let (mut lo, mut hi) = (0.0, MAX_NORMALISED_SLOPE);
    for _ in 0..RANGE_SEARCH_STEPS {
        let (m1, m2) = (lo + (hi - lo) / 3.0, hi - (hi - lo) / 3.0);
        if g(m1) < g(m2) {
            lo = m1;
        } else {
            hi = m2;
        }
    }
    let best = 0.5 * (lo + hi);
    if g(best) < -MONOTONE_SLACK {
        return None;
    }
    let edge = |mut inside: f64, mut outside: f64| {
        if g(outside) >= -MONOTONE_SLACK {
            return outside;
        }
        for _ in 0..EDGE_BISECTION_STEPS {
            let mid = 0.5 * (inside + outside);
            if g(mid) >= -MONOTONE_SLACK {
                inside = mid;
            } else {
                outside = mid;
            }
        }
        inside
    };
    Some((edge(best, 0.0), edge(best, MAX_NORMALISED_SLOPE)))
}

/// The error for a given velocity at knot `k` that no monotone span admits; `key_count` keys
/// (a cycle's last knot is key 0), `range` the velocities that would work (poses per second).
fn backwards(k: usize, key_count: usize, value: f64, range: Option<(f64, f64)>) -> Error {
    let key = k % key_count;
    let expected = match range {
        Some((lo, hi)) if lo > 0.0 => format!(
            "a velocity in [{lo:.6}, {hi:.6}] poses/s here: otherwise time runs backwards next \
             to key {key}"
        ),
        Some((_, hi)) => format!(
            "a velocity ≤ {hi:.6} poses/s here: a faster one makes time run backwards next to \
             key {key}"
        ),
        None => format!(
            "a smaller velocity: with its neighbours' this one makes time run backwards next to \
             key {key}"
        ),
    };
    Error::new(
        format!("velocities[{key}]"),
        ErrorKind::OutOfRange {
            value: value.to_string(),
            expected,
        },
    )
}

/// Slopes through given key velocities: the free ones start as in [`monotone_slopes`]; on a span
/// with both ends free they are limited as there, on a span with one given end the free one is
/// clamped into [`monotone_range`], and a span with both ends given must already be monotone.
/// A final check of every span names the first key that breaks monotonicity.
fn constrained_slopes(
    knots: &[f64],
    velocities: &[Option<f64>],
    closed: bool,
) -> Result<Vec<f64>, Error> {
    let last = knots.len() - 1;
    let keys = velocities.len();
    let fixed = |k: usize| velocities[k % keys];
    let secant = |k: usize| 1.0 / (knots[k + 1] - knots[k]);
    let mut v = centred_slopes(knots, closed);
    for (k, slope) in v.iter_mut().enumerate() {
        if let Some(given) = fixed(k) {
            *slope = given;
        }
    }
    for k in 0..last {
        let d = secant(k);
        let (a, b) = (v[k] / d, v[k + 1] / d);
        match (fixed(k), fixed(k + 1)) {
            (None, None) => {
                let r = a * a + b * b;
                if r > 9.0 {
                    let tau = 3.0 / r.sqrt();
                    v[k] = tau * a * d;
                    v[k + 1] = tau * b * d;
                }
            }
            (Some(_), None) => match monotone_range(a) {
                Some((lo, hi)) => v[k + 1] = b.clamp(lo, hi) * d,
                None => {
                    return Err(backwards(
                        k,
                        keys,
                        v[k],
                        Some((0.0, MAX_NORMALISED_SLOPE * d)),
                    ))
                }
            },
            (None, Some(_)) => match monotone_range(b) {
                Some((lo, hi)) => v[k] = a.clamp(lo, hi) * d,
                None => {
                    return Err(backwards(
                        k + 1,
                        keys,
                        v[k + 1],
                        Some((0.0, MAX_NORMALISED_SLOPE * d)),
                    ))
                }
            },
            (Some(_), Some(_)) => {}
        }
    }
    if closed && fixed(0).is_none() {
        let m = v[0].min(v[last]);
        v[0] = m;
        v[last] = m;
    }
    for k in 0..last {
        let d = secant(k);
        let (a, b) = (v[k] / d, v[k + 1] / d);
        if least_rate(a, b) < -MONOTONE_SLACK {
            // Name a given key of the span: the one further outside its range.
            let blame = |j: usize, own: f64, other: f64| {
                let range = monotone_range(other).map(|(lo, hi)| (lo * d, hi * d));
                let excess =
                    range.map_or(f64::INFINITY, |(lo, hi)| (lo - own * d).max(own * d - hi));
                (excess, backwards(j, keys, own * d, range))
            };
            let candidates = [(k, a, b), (k + 1, b, a)]
                .into_iter()
                .filter(|&(j, _, _)| fixed(j).is_some())
                .map(|(j, own, other)| blame(j, own, other));
            let worst = candidates.max_by(|x, y| x.0.total_cmp(&y.0));
            return Err(worst.map_or_else(|| backwards(k, keys, v[k], None), |w| w.1));
        }
    }
    Ok(v)
}

/// Centred-difference slopes `v_k = (p_{k+1} − p_{k−1}) / (T_{k+1} − T_{k−1})` with `p_k = k`
/// (one-sided at open ends, wrapped for cycles), before any limiting.
fn centred_slopes(knots: &[f64], closed: bool) -> Vec<f64> {
    let n = knots.len();
    let last = n - 1;
    let secant = |k: usize| 1.0 / (knots[k + 1] - knots[k]);
    (0..n)
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
        .collect()
}

/// Slopes [`centred_slopes`], then limited by Fritsch–Carlson: zero where a secant is zero, and
/// scaled so that `α² + β² ≤ 9` on every span (sufficient for monotonicity). Values are `p_k = k`.
fn monotone_slopes(knots: &[f64], closed: bool) -> Vec<f64> {
    let last = knots.len() - 1;
    // Secant of span k (value step is always 1).
    let secant = |k: usize| 1.0 / (knots[k + 1] - knots[k]);
    let mut v = centred_slopes(knots, closed);
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
    fn given_velocities_hold_and_stay_monotone() {
        let knots = vec![0.0, 1.0, 3.0, 4.0, 6.0];
        for closed in [false, true] {
            let keys = knots.len() - usize::from(closed);
            let mut given = vec![None; keys];
            given[1] = Some(0.0);
            given[2] = Some(1.2);
            given[0] = Some(0.25);
            let t = Timing::with_velocities(knots.clone(), &given, closed).unwrap();
            for (k, &tk) in t.knots().iter().enumerate() {
                let (u, du) = t.parameter(tk);
                let want = if closed && k == keys { 0.0 } else { k as f64 };
                assert!((u - want).abs() < 1e-12, "p(T_{k}) = {u}");
                if let Some(v) = given[k % keys] {
                    // Both one-sided rates equal the given velocity (C¹ at the key).
                    let h = 1e-7;
                    let right = (t.parameter(tk + h).0 - u).rem_euclid(keys as f64) / h;
                    assert!((du - v).abs() < 1e-12, "p'(T_{k}) = {du}, want {v}");
                    if tk + h < 6.0 || closed {
                        assert!((right - v).abs() < 1e-5, "right rate {right}, want {v}");
                    }
                }
            }
            let mut x = 0.0;
            while x < 6.0 {
                assert!(t.parameter(x).1 >= -1e-12, "rate < 0 at {x}");
                x += 1e-3;
            }
        }
    }

    #[test]
    fn no_velocities_is_new_bit_for_bit() {
        let knots = vec![0.0, 0.5, 3.0, 3.2, 6.0];
        for closed in [false, true] {
            let keys = knots.len() - usize::from(closed);
            let a = Timing::new(knots.clone(), closed).unwrap();
            let b = Timing::with_velocities(knots.clone(), &vec![None; keys], closed).unwrap();
            assert_eq!(a, b);
        }
    }

    #[test]
    fn velocities_that_run_time_backwards_are_refused() {
        let knots = vec![0.0, 1.0, 2.0, 3.0];
        // Secant 1 pose/s: more than 4 at a key with a free neighbour is never monotone.
        let e = Timing::with_velocities(knots.clone(), &[None, Some(4.5), None, None], false)
            .unwrap_err();
        assert_eq!(e.path(), "velocities[1]");
        assert!(e.to_string().contains("backwards"), "{e}");
        // Two given ends that cannot share a monotone cubic: 3.5 and 3.5.
        let e = Timing::with_velocities(knots.clone(), &[None, Some(3.5), Some(3.5), None], false)
            .unwrap_err();
        assert!(e.path().starts_with("velocities["), "{e}");
        for (bad, path) in [
            (vec![Some(-1.0), None, None, None], "velocities[0]"),
            (vec![None, Some(f64::NAN), None, None], "velocities[1]"),
            (vec![None, None, Some(f64::INFINITY), None], "velocities[2]"),
            (vec![None, None, None], "velocities"),
        ] {
            let e = Timing::with_velocities(knots.clone(), &bad, false).unwrap_err();
            assert_eq!(e.path(), path, "{e}");
        }
    }

    #[test]
    fn least_rate_matches_a_dense_scan() {
        for (a, b) in [
            (0.0, 0.0),
            (3.0, 0.0),
            (4.0, 1.0),
            (3.5, 3.5),
            (1.0, 5.0),
            (0.2, 2.9),
        ] {
            let scan = (0..=10_000)
                .map(|i| {
                    let s = i as f64 / 10_000.0;
                    a + (6.0 - 4.0 * a - 2.0 * b) * s + 3.0 * (a + b - 2.0) * s * s
                })
                .fold(f64::INFINITY, f64::min);
            assert!((least_rate(a, b) - scan).abs() < 1e-6, "{a} {b}");
        }
        // Edges are found to within √(3 · MONOTONE_SLACK) (the rate dips quadratically there).
        let (lo, hi) = monotone_range(0.0).unwrap();
        assert!(lo == 0.0 && (hi - 3.0).abs() < 2e-6, "{lo} {hi}");
        let (lo, hi) = monotone_range(4.0).unwrap();
        assert!(
            (lo - 1.0).abs() < 1e-3 && (hi - 1.0).abs() < 1e-3,
            "{lo} {hi}"
        );
        assert!(monotone_range(4.01).is_none());
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
