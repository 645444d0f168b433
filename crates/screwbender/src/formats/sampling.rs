//! Sampling a motion in time for keyframe formats (glTF, CSV), adaptively to a stated tolerance.
//!
//! A keyframe player interpolates linearly between samples: it lerps the translation and slerps
//! the rotation (glTF `LINEAR`). Along one screw the slerp follows the screw's rotation exactly,
//! but the lerped origin leaves the helix: for a sub-step of angle `Δθ` the deviation is at most
//! `ρ Δθ² / 8`, with `ρ` the origin's distance from the screw axis (the linear-interpolation error
//! bound `max|x''| / 8` with `|x''| = ρ θ'²` on a helix; the slide is linear and exact).
//!
//! [`sample_polyscrew`] uses that bound in closed form: each span of a (refined) polyscrew is one
//! screw, so it gets `k` uniform sub-steps in time from its angle, slide and axis distance, and the
//! spans are merged. Non-uniform [`Timing`] adds the bound's speed terms (see
//! [`sample_polyscrew`]); [`sample_polyscrew_within`] bounds the error where it is seen, at the
//! object's points in scene units ([`Deviation`], docs/math/sampling.md §3). Any other [`Motion`]
//! goes through [`sample_motion`], which bisects numerically. [`sample_fixed_rate`] samples at a
//! fixed frame rate instead.

use std::f64::consts::FRAC_PI_2;

use glam::DVec3;

use crate::error::{Error, ErrorKind};
use crate::motion::Motion;
use crate::polyscrew::Polyscrew;
use crate::pose::Pose;
use crate::screwbender::ScrewBender;
use crate::timing::Timing;

/// Default deviation tolerance of the adaptive samplers: 1e-4 scene units (0.1 mm when one unit
/// is 1 m). Bounds the distance between the linearly interpolated origin and the true one.
pub const DEFAULT_TOLERANCE: f64 = 1e-4;

/// Smallest tolerance accepted: the keyframes are stored as `f32`, whose rounding (about
/// `6e-8 |x|`) makes tighter tolerances meaningless.
pub const MIN_TOLERANCE: f64 = 1e-9;

/// Largest rotation between two consecutive samples. Slerp takes the short arc, which is the
/// screw's own arc only below a half turn; a quarter turn keeps well clear of that edge.
pub const MAX_SAMPLE_ANGLE: f64 = FRAC_PI_2;

/// The most samples a sampler produces (the memory guard, the same as
/// [`crate::MAX_REFINED_POSES`]).
pub const MAX_SAMPLES: usize = 1 << 20;

/// Bisection steps when inverting the timing map (2⁻⁶⁰ of a knot interval: below `f64`
/// resolution).
const INVERSE_STEPS: u32 = 60;

/// Depth limit of [`sample_motion`]'s bisection (2⁻³⁰ of a knot interval).
const MAX_BISECTION_DEPTH: u32 = 30;

/// Initial uniform sub-steps per knot interval in [`sample_motion`] (so that features narrower
/// than a knot interval are not skipped by the first probes).
const INITIAL_STEPS_PER_KNOT: usize = 8;

/// What the tolerance of [`sample_polyscrew_within`] bounds (docs/math/sampling.md §3).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Deviation {
    /// The origin's distance (scene units) and, separately, the rotation angle (radians): what
    /// [`sample_polyscrew`] bounds.
    OriginAndAngle,
    /// A keyframe player's pose (lerped origin, slerped rotation, as glTF `LINEAR`): the
    /// distance of every body point within `radius` of the local origin (scene units), e.g. the
    /// vertices of the object's mesh with `radius` = [`mesh_radius`](crate::formats::interop::mesh_radius).
    Body {
        /// The largest distance of a body point from the local origin.
        radius: f64,
    },
    /// A body point's trajectory interpolated linearly (CSV positions): its distance.
    Point(DVec3),
}

/// One keyframe: time, motion parameter and pose.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sample {
    /// Animation time in seconds (the [`Timing`]'s clock).
    pub time: f64,
    /// Coarse motion parameter `u = p(time)`; for a cycle the last sample has `u = n`.
    pub u: f64,
    /// The pose at `u`.
    pub pose: Pose,
}

/// Checks a user tolerance (path `tolerance`).
pub fn check_tolerance(tolerance: f64) -> Result<(), Error> {
    if tolerance.is_finite() && tolerance >= MIN_TOLERANCE {
        Ok(())
    } else {
        Err(Error::new(
            "tolerance",
            ErrorKind::OutOfRange {
                value: tolerance.to_string(),
                expected: format!("a finite number ≥ {MIN_TOLERANCE:e}"),
            },
        ))
    }
}

/// Checks that `timing` has one knot per control pose of `motion` (plus one for a cycle).
pub fn check_timing(motion: &dyn Motion, timing: &Timing) -> Result<(), Error> {
    let controls = motion.knots().len();
    let expected = if motion.is_closed() {
        controls + 1
    } else {
        controls
    };
    if timing.knots().len() == expected {
        Ok(())
    } else {
        Err(Error::new(
            "times",
            ErrorKind::OutOfRange {
                value: format!("{} times", timing.knots().len()),
                expected: format!(
                    "{expected} times ({controls} control poses{})",
                    if motion.is_closed() {
                        ", plus the time pose 0 is reached again"
                    } else {
                        ""
                    }
                ),
            },
        ))
    }
}

/// The time `t` in knot interval `k` at which `timing` reaches parameter `u ∈ [k, k + 1]`.
fn time_of(timing: &Timing, k: usize, u: f64) -> f64 {
    let knots = timing.knots();
    let (mut lo, mut hi) = (knots[k], knots[k + 1]);
    if u <= k as f64 {
        return lo;
    }
    if u >= (k + 1) as f64 {
        return hi;
    }
    for _ in 0..INVERSE_STEPS {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if timing.parameter(mid).0 < u {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// The rate `p'(t)` on knot interval `k` as the quadratic `q(s) = a + b s + c s²`, `s ∈ [0, 1]`
/// (exact: the timing map is a cubic on each interval; sampled where it cannot wrap).
fn rate_quadratic(timing: &Timing, k: usize) -> (f64, f64, f64) {
    let knots = timing.knots();
    let (t0, t1) = (knots[k], knots[k + 1]);
    let at = |s: f64| timing.parameter(t0 + s * (t1 - t0)).1;
    let (d0, dm, d3) = (at(0.0), at(0.5), at(0.75));
    // Fit through s = 0, 0.5, 0.75 (the end s = 1 may wrap for a cycle's last interval).
    let c = (d3 - d0 - 1.5 * (dm - d0)) / (0.75 * 0.75 - 1.5 * 0.25);
    let b = (dm - d0 - 0.25 * c) / 0.5;
    (d0, b, c)
}

/// `max |p'|` and `max |p''|` on `[sa, sb]` of knot interval `k` (length `h`).
fn rate_bounds((a, b, c): (f64, f64, f64), h: f64, sa: f64, sb: f64) -> (f64, f64) {
    let q = |s: f64| a + b * s + c * s * s;
    let mut p1 = q(sa).abs().max(q(sb).abs());
    if c != 0.0 {
        let v = -b / (2.0 * c);
        if v > sa && v < sb {
            p1 = p1.max(q(v).abs());
        }
    }
    let p2 = ((b + 2.0 * c * sa).abs()).max((b + 2.0 * c * sb).abs()) / h;
    (p1, p2)
}

/// The largest time step on one span such that linear keyframes stay within `tolerance`:
/// `ω` = rotation rate and `v` = the tracked point's speed (per coarse unit), `rho` = its axis
/// distance, `p1 = max |p'|`, `p2 = max |p''|`, `radius` = the body's extent around the origin
/// (`None`: bound the rotation angle in radians on its own).
fn max_step(
    omega: f64,
    v: f64,
    rho: f64,
    (p1, p2): (f64, f64),
    radius: Option<f64>,
    tolerance: f64,
) -> f64 {
    // Tracked point: |x''(t)| ≤ ρ ω² p'² + v |p''|; rotation angle: |φ''(t)| ≤ ω |p''|, which
    // moves a body point at distance r by at most r |Δφ| (docs/math/sampling.md §3).
    let c_pos = rho * omega * omega * p1 * p1 + v * p2;
    let c_ang = omega * p2;
    let bounds = match radius {
        None => [c_pos, c_ang],
        Some(r) => [c_pos + r * c_ang, 0.0],
    };
    let mut step = f64::INFINITY;
    for c in bounds {
        if c > 0.0 {
            step = step.min((8.0 * tolerance / c).sqrt());
        }
    }
    if omega * p1 > 0.0 {
        step = step.min(MAX_SAMPLE_ANGLE / (omega * p1));
    }
    step
}

/// Adaptive samples of a polyscrew (e.g. [`crate::ScrewBender::refined`]) under `timing`.
///
/// Span `i` covers `u ∈ [i h, (i + 1) h]` and the times `[t_a, t_b]` with `p(t_a) = i h`. It gets
/// `k = ⌈(t_b − t_a) / Δt⌉` uniform sub-steps in time, where `Δt` is the largest step with
///
/// * `Δt² (ρ ω² P₁² + v P₂) / 8 ≤ tolerance` — the origin (speed `v = |Δx| / h`, angle rate
///   `ω = θ / h`, axis distance `ρ`, `P₁ = max |p'|`, `P₂ = max |p''|` over the span; with uniform
///   timing `P₂ = 0` and this is `ρ (θ / k)² / 8 ≤ tolerance`);
/// * `Δt² ω P₂ / 8 ≤ tolerance` (radians) — the rotation angle, which slerp advances at a constant
///   rate while a non-uniform timing does not;
/// * `ω P₁ Δt ≤` [`MAX_SAMPLE_ANGLE`].
///
/// The spans' sample lists are merged (shared ends once). The first sample is at the first knot
/// time, the last at the last (for a cycle: pose 0 again, `u = n`). The timing must have one knot
/// per control pose of the polyscrew (plus one for a cycle): for a refined polyscrew pass a
/// timing of the coarse control poses and the coarse span count `coarse_spans`.
///
/// Errors: bad tolerance (`tolerance`), wrong knot count (`times`), more than [`MAX_SAMPLES`].
pub fn sample_polyscrew(
    polyscrew: &Polyscrew,
    coarse_spans: usize,
    timing: &Timing,
    tolerance: f64,
) -> Result<Vec<Sample>, Error> {
    sample_polyscrew_within(
        polyscrew,
        coarse_spans,
        timing,
        tolerance,
        Deviation::OriginAndAngle,
    )
}

/// [`sample_polyscrew`] with the tolerance bounding `deviation`: with
/// [`Deviation::Body`] the keyframe player's error at every body point within the radius
/// (`Δt² (ρ ω² P₁² + v P₂ + r ω P₂) / 8 ≤ tolerance`: the origin's lerp error plus the slerp's
/// angle error times the radius), with [`Deviation::Point`] the error of a linearly interpolated
/// trajectory of that point (its own `ρ` and `v`). With uniform timing (`P₂ = 0`) the body
/// bound equals the origin's, because slerp is then exact along each screw.
///
/// Errors: those of [`sample_polyscrew`]; a radius that is negative or not finite (`radius`), a
/// point not finite (`point`).
pub fn sample_polyscrew_within(
    polyscrew: &Polyscrew,
    coarse_spans: usize,
    timing: &Timing,
    tolerance: f64,
    deviation: Deviation,
) -> Result<Vec<Sample>, Error> {
    check_tolerance(tolerance)?;
    let (local, radius) = match deviation {
        Deviation::OriginAndAngle => (DVec3::ZERO, None),
        Deviation::Body { radius } => {
            if !(radius.is_finite() && radius >= 0.0) {
                return Err(Error::new(
                    "radius",
                    ErrorKind::OutOfRange {
                        value: radius.to_string(),
                        expected: "a finite number ≥ 0 (scene units)".into(),
                    },
                ));
            }
            (DVec3::ZERO, Some(radius))
        }
        Deviation::Point(p) => {
            if !p.is_finite() {
                return Err(Error::new("point", ErrorKind::NonFinite));
            }
            (p, Some(0.0))
        }
    };
    // One knot per coarse pose, plus the return to pose 0 for a cycle: spans + 1 either way.
    let expected = coarse_spans + 1;
    if timing.knots().len() != expected {
        return Err(Error::new(
            "times",
            ErrorKind::OutOfRange {
                value: format!("{} times", timing.knots().len()),
                expected: format!("{expected} times"),
            },
        ));
    }
    let h = polyscrew.span_length();
    let per_coarse = (1.0 / h).round().max(1.0) as usize;
    let span_count = (coarse_spans * per_coarse).min(polyscrew.spans().len());
    let mut out: Vec<Sample> = Vec::new();
    for (i, span) in polyscrew.spans()[..span_count].iter().enumerate() {
        let k = i / per_coarse;
        let (u0, u1) = (i as f64 * h, (i + 1) as f64 * h);
        let (ta, tb) = (time_of(timing, k, u0), time_of(timing, k, u1));
        let kh = timing.knots()[k + 1] - timing.knots()[k];
        let quad = rate_quadratic(timing, k);
        let (sa, sb) = ((ta - timing.knots()[k]) / kh, (tb - timing.knots()[k]) / kh);
        let (p1, p2) = rate_bounds(quad, kh, sa, sb);
        let theta = span.angle();
        let (omega_t, v0) = span.twist();
        let start = span.start().transform_point(local);
        let vel = omega_t.cross(start) + v0;
        let rho = if theta > 0.0 {
            let n = omega_t / theta;
            (vel - n * n.dot(vel)).length() / theta
        } else {
            0.0
        };
        let step = max_step(
            theta / h,
            vel.length() / h,
            rho,
            (p1, p2),
            radius,
            tolerance,
        );
        let steps = if step.is_finite() {
            ((tb - ta) / step).ceil().max(1.0)
        } else {
            1.0
        };
        if steps + out.len() as f64 > MAX_SAMPLES as f64 {
            return Err(too_many());
        }
        let steps = steps as usize;
        // Spans share their end samples: only the first span adds its start.
        if out.is_empty() {
            out.push(Sample {
                time: ta,
                u: u0,
                pose: *span.start(),
            });
        }
        for j in 1..=steps {
            let time = ta + (tb - ta) * j as f64 / steps as f64;
            let (u, s) = if j == steps {
                (u1, 1.0)
            } else {
                let u = timing.parameter(time).0;
                // A cycle's parameter wraps at the period: stay on this span.
                let u = if u < u0 - 0.5 {
                    u + coarse_spans as f64
                } else {
                    u
                };
                (u, ((u - u0) / h).clamp(0.0, 1.0))
            };
            out.push(Sample {
                time,
                u,
                pose: span.at(s),
            });
        }
    }
    Ok(out)
}

/// The sample-count guard's error (the count is not known exactly when it trips).
fn too_many() -> Error {
    Error::new(
        "tolerance",
        ErrorKind::TooManyPoses {
            requested: MAX_SAMPLES + 1,
            max: MAX_SAMPLES,
        },
    )
}

/// Adaptive samples of a [`ScrewBender`] motion: [`sample_polyscrew`] on its refined polyscrew,
/// with `timing` over its control poses (e.g. `Timing::uniform(n, closed)`: 1 s per span).
///
/// ```
/// use screwbender::{sample_screwbender, presets, Rules, Scheme, ScrewBender, Subdivision, Timing};
///
/// let scene = presets::preset("circle4").unwrap();
/// let sub = Subdivision::new(Scheme::FourPoint, Rules::Direct, 5);
/// let motion = ScrewBender::new(scene.poses.clone(), true, sub)?;
/// let samples = sample_screwbender(&motion, &Timing::uniform(4, true), 1e-4)?;
/// // A cycle: the last keyframe is pose 0 again, 4 s later.
/// assert_eq!(samples.last().unwrap().time, 4.0);
/// assert!(samples[0].pose.approx_eq(&samples.last().unwrap().pose, 1e-12));
/// assert!(samples.len() > 128); // at least one keyframe per refined span
/// # Ok::<(), screwbender::Error>(())
/// ```
pub fn sample_screwbender(
    motion: &ScrewBender,
    timing: &Timing,
    tolerance: f64,
) -> Result<Vec<Sample>, Error> {
    let n = motion.control().len();
    let spans = if motion.is_closed() { n } else { n - 1 };
    sample_polyscrew(motion.refined(), spans, timing, tolerance)
}

/// Deviation of the linear keyframe interpolation between `a` and `b` from the true pose at
/// fraction `s`: `(origin distance, rotation angle)`.
pub fn linear_deviation(a: &Pose, b: &Pose, s: f64, truth: &Pose) -> (f64, f64) {
    let p = interpolate_linear(a, b, s);
    (p.origin.distance(truth.origin), p.angle_to(truth))
}

/// glTF `LINEAR` interpolation between two keyframes: lerp of the origin, slerp of the rotation
/// (along the short arc).
pub fn interpolate_linear(a: &Pose, b: &Pose, s: f64) -> Pose {
    let mut qb = b.rotation;
    if a.rotation.dot(qb) < 0.0 {
        qb = -qb;
    }
    Pose::new(
        a.origin.lerp(b.origin, s),
        a.rotation.slerp(qb, s).normalize(),
    )
}

/// Adaptive samples of any motion by bisection: starting from a uniform grid, an interval is
/// split while the linear interpolation deviates by more than `tolerance` (origin distance, or
/// rotation angle in radians) at its quarter points. A numerical check, not a bound: prefer
/// [`sample_polyscrew`] for polyscrews.
pub fn sample_motion(
    motion: &dyn Motion,
    timing: &Timing,
    tolerance: f64,
) -> Result<Vec<Sample>, Error> {
    check_tolerance(tolerance)?;
    check_timing(motion, timing)?;
    let span_count = timing.knots().len() - 1;
    let eval = |t: f64, k: usize, at_end: bool| -> Sample {
        let u = if at_end {
            (k + 1) as f64
        } else {
            timing.parameter(t).0
        };
        Sample {
            time: t,
            u,
            pose: motion.pose_at(u),
        }
    };
    let mut out = Vec::new();
    for k in 0..span_count {
        let (t0, t1) = (timing.knots()[k], timing.knots()[k + 1]);
        let grid: Vec<Sample> = (0..=INITIAL_STEPS_PER_KNOT)
            .map(|j| {
                let t = t0 + (t1 - t0) * j as f64 / INITIAL_STEPS_PER_KNOT as f64;
                eval(t, k, j == INITIAL_STEPS_PER_KNOT)
            })
            .collect();
        if out.is_empty() {
            out.push(grid[0]);
        }
        for w in grid.windows(2) {
            refine(&eval, k, w[0], w[1], tolerance, 0, &mut out)?;
        }
    }
    Ok(out)
}

/// Appends the samples after `a` up to and including `b`, bisecting where needed.
fn refine(
    eval: &dyn Fn(f64, usize, bool) -> Sample,
    k: usize,
    a: Sample,
    b: Sample,
    tolerance: f64,
    depth: u32,
    out: &mut Vec<Sample>,
) -> Result<(), Error> {
    let too_far = depth < MAX_BISECTION_DEPTH
        && [0.25, 0.5, 0.75].iter().any(|&s| {
            let truth = eval(a.time + s * (b.time - a.time), k, false);
            let (d, ang) = linear_deviation(&a.pose, &b.pose, s, &truth.pose);
            d > tolerance || ang > tolerance || a.pose.angle_to(&b.pose) > MAX_SAMPLE_ANGLE
        });
    if too_far {
        let m = eval(0.5 * (a.time + b.time), k, false);
        refine(eval, k, a, m, tolerance, depth + 1, out)?;
        refine(eval, k, m, b, tolerance, depth + 1, out)
    } else {
        if out.len() >= MAX_SAMPLES {
            return Err(too_many());
        }
        out.push(b);
        Ok(())
    }
}

/// Samples at a fixed frame rate `fps` from the first knot time to the last (the last sample is
/// always at the last time, so a cycle closes exactly).
///
/// Errors: `fps` not finite and positive (path `fps`), wrong knot count, more than
/// [`MAX_SAMPLES`].
pub fn sample_fixed_rate(
    motion: &dyn Motion,
    timing: &Timing,
    fps: f64,
) -> Result<Vec<Sample>, Error> {
    if !(fps.is_finite() && fps > 0.0) {
        return Err(Error::new(
            "fps",
            ErrorKind::OutOfRange {
                value: fps.to_string(),
                expected: "a finite number > 0".into(),
            },
        ));
    }
    check_timing(motion, timing)?;
    let (t0, t1) = timing.duration();
    let frames = ((t1 - t0) * fps).ceil();
    if frames + 1.0 > MAX_SAMPLES as f64 {
        return Err(Error::new(
            "fps",
            ErrorKind::TooManyPoses {
                requested: frames as usize + 1,
                max: MAX_SAMPLES,
            },
        ));
    }
    let frames = frames.max(1.0) as usize;
    let last_u = (timing.knots().len() - 1) as f64;
    Ok((0..=frames)
        .map(|j| {
            let (time, u) = if j == frames {
                (t1, last_u)
            } else {
                let t = t0 + j as f64 / fps;
                (t, timing.parameter(t).0)
            };
            Sample {
                time,
                u,
                pose: motion.pose_at(u),
            }
        })
        .collect())
}

/// The world trajectory of the body point `local` at the samples: `(time, u, position)`.
pub fn trajectory(samples: &[Sample], local: DVec3) -> Vec<(f64, f64, DVec3)> {
    samples
        .iter()
        .map(|s| (s.time, s.u, s.pose.transform_point(local)))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Rules, Scheme, Subdivision};

    fn helix() -> Polyscrew {
        let poses = (0..4)
            .map(|i| {
                let a = i as f64 * FRAC_PI_2;
                Pose::new(
                    DVec3::new(3.0 * a.cos(), 3.0 * a.sin(), 0.0),
                    glam::DQuat::from_rotation_z(a),
                )
            })
            .collect();
        Polyscrew::new(poses, true).unwrap()
    }

    #[test]
    fn circle_needs_the_closed_form_count() {
        // Quarter turns at radius 3: k = ⌈(π/2) √(3 / (8 tol))⌉ per span.
        let p = helix();
        let tol = 1e-4;
        let s = sample_polyscrew(&p, 4, &Timing::uniform(4, true), tol).unwrap();
        let k = (FRAC_PI_2 * (3.0 / (8.0 * tol)).sqrt()).ceil() as usize;
        assert_eq!(s.len(), 4 * k + 1);
        assert!(s[0].pose.approx_eq(&s[s.len() - 1].pose, 1e-12));
        for w in s.windows(2) {
            for &f in &[0.25, 0.5, 0.75] {
                let t = w[0].time + f * (w[1].time - w[0].time);
                let truth = p.pose_at(t);
                let (d, a) = linear_deviation(&w[0].pose, &w[1].pose, f, &truth);
                assert!(d <= tol && a < 1e-9, "{d} {a}");
            }
        }
    }

    #[test]
    fn nonuniform_timing_stays_within_tolerance() {
        let sb = ScrewBender::new(
            helix().poses().to_vec(),
            true,
            Subdivision::new(Scheme::FourPoint, Rules::Direct, 3),
        )
        .unwrap();
        let timing = Timing::new(vec![0.0, 0.4, 2.0, 2.3, 4.0], true).unwrap();
        let tol = 1e-3;
        let s = sample_polyscrew(sb.refined(), 4, &timing, tol).unwrap();
        let mut worst = 0.0f64;
        for w in s.windows(2) {
            for j in 1..8 {
                let f = j as f64 / 8.0;
                let t = w[0].time + f * (w[1].time - w[0].time);
                let truth = sb.pose_at(timing.parameter(t).0);
                let (d, a) = linear_deviation(&w[0].pose, &w[1].pose, f, &truth);
                worst = worst.max(d).max(a);
            }
        }
        assert!(worst <= tol, "worst deviation {worst}");
    }

    #[test]
    fn bad_tolerance_and_fps_are_named() {
        let p = helix();
        let t = Timing::uniform(4, true);
        for tol in [0.0, -1.0, f64::NAN] {
            let e = sample_polyscrew(&p, 4, &t, tol).unwrap_err();
            assert_eq!(e.path(), "tolerance");
        }
        assert_eq!(sample_fixed_rate(&p, &t, 0.0).unwrap_err().path(), "fps");
        let wrong = Timing::uniform(4, false);
        assert_eq!(sample_motion(&p, &wrong, 1e-3).unwrap_err().path(), "times");
    }

    #[test]
    fn generic_sampler_meets_tolerance() {
        let p = helix();
        let t = Timing::uniform(4, true);
        let s = sample_motion(&p, &t, 1e-3).unwrap();
        for w in s.windows(2) {
            let tm = 0.5 * (w[0].time + w[1].time);
            let (d, _) = linear_deviation(&w[0].pose, &w[1].pose, 0.5, &p.pose_at(tm));
            assert!(d <= 1e-3);
        }
        let f = sample_fixed_rate(&p, &t, 30.0).unwrap();
        assert_eq!(f.len(), 121);
    }
}
