//! Chaudhry & Cameron, *Smooth Rational Motion of a Rigid Triangle in R³* (docs/math/rational-motion.md):
//! the fitted motion, its evaluation, kinematics and rational Bézier export.

use glam::{DMat3, DQuat, DVec3};
use serde::Serialize;

mod c0;
mod c1;
mod segment;

use crate::error::{Error, ErrorKind};
use crate::methods::algebra::{angular_rates, canonical_signs, normalised, unnormalised_matrix};
use crate::methods::triangle::{
    rotation_between, validate_samples, ReferenceTriangle, TriangleSample,
};
use crate::motion::{Kinematics, Motion};
use crate::pose::Pose;
use segment::Segment;
pub use segment::{EndCondition, MIN_DENOMINATOR};

/// The [`RationalMotion::growth`] above which the C¹ motion is reported as poor: a middle control
/// point more than this many chord lengths off its chord bends the segment far outside the data
/// (smooth data stay below 1; docs/math/rational-motion.md §6.1).
pub const GROWTH_WARNING: f64 = 10.0;

/// Smoothness of the Chaudhry–Cameron motion.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum Continuity {
    /// Piecewise linear quaternions, rational quadratic trajectories (docs/math/rational-motion.md §5).
    C0,
    /// Quadratic quaternion spline, rational quartic trajectories (docs/math/rational-motion.md §6).
    C1(EndCondition),
}

/// The Chaudhry–Cameron rational motion of a rigid body (docs/math/rational-motion.md §3–§7).
///
/// Built from triangle samples ([`RationalMotion::fit`]) or from poses
/// ([`RationalMotion::from_poses`], through a [`ReferenceTriangle`]). Rotations are recovered per
/// sample (docs/math/rational-motion.md §4.5), signs fixed by eq. (9), interpolated by a C⁰ linear or C¹ quadratic quaternion
/// spline; every body point then moves on a piecewise rational curve (degree 2/2 or 4/4) with the
/// common denominator `w(t) = |Q(t)|²`, and the triangle stays exactly rigid because
/// `R(t) = M(Q)/|Q|²` is a rotation for every `Q ≠ 0`.
///
/// As a [`Motion`]: the parameter is the data time `t`, the knots are the sample times, and the
/// pose at `t` is `(a(t), R(t)) ∘ B`, where `B` places the body relative to vertex `a` at `t_0`
/// (the identity for triangle input: local coordinates are world coordinates relative to `a_0`
/// at `t_0`). Open motions extrapolate their end segments outside `[t_0, t_n]`.
#[derive(Clone, Debug, PartialEq)]
pub struct RationalMotion {
    continuity: Continuity,
    samples: Vec<TriangleSample>,
    quats: Vec<DQuat>,
    segments: Vec<Segment>,
    body: Pose,
    closed: bool,
}

/// One segment of the rational Bézier form of the motion, as plain arrays (docs/math/rational-motion.md §5.2, §6.2).
///
/// The curve `k` (`a`, `x` or `y`) on this segment is `C(τ) = Σ P_k B_k^N(τ) / Σ ω_k B_k^N(τ)` with
/// `τ = (t − t_start)/(t_end − t_start)`, `N = degree`, weights `ω_k` and **homogeneous** control
/// points `P_k = ω_k c_k` (so a zero weight — a relative half turn between consecutive C⁰ samples —
/// needs no point at infinity); the affine control point is `c_k = P_k / ω_k` when `ω_k ≠ 0`.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct RationalBezierSegment {
    /// Start time of the segment.
    pub t_start: f64,
    /// End time of the segment.
    pub t_end: f64,
    /// 2 (C⁰) or 4 (C¹).
    pub degree: usize,
    /// The `degree + 1` weights `ω_k`; `ω_0 = ω_N = 1`.
    pub weights: Vec<f64>,
    /// Quaternion Bézier control points `[w, x, y, z]`: `Q_i, Q_{i+1}` (C⁰) or `Q_i, M_i, Q_{i+1}`
    /// (C¹).
    pub quaternions: Vec<[f64; 4]>,
    /// Homogeneous control points of the trajectory of vertex `a` (the translation curve).
    pub a: Vec<[f64; 3]>,
    /// Homogeneous control points of the trajectory of vertex `x`.
    pub x: Vec<[f64; 3]>,
    /// Homogeneous control points of the trajectory of vertex `y`.
    pub y: Vec<[f64; 3]>,
}

impl RationalBezierSegment {
    /// Evaluates one of this segment's curves (`&self.a`, `&self.x` or `&self.y`) at local `τ`
    /// (entries beyond `degree + 1` are ignored).
    pub fn evaluate(&self, homogeneous: &[[f64; 3]], tau: f64) -> DVec3 {
        let n = self.degree;
        let mut num = DVec3::ZERO;
        let mut den = 0.0;
        for (k, (p, w)) in homogeneous
            .iter()
            .zip(&self.weights)
            .enumerate()
            .take(n + 1)
        {
            let b = binomial(n, k) * tau.powi(k as i32) * (1.0 - tau).powi((n - k) as i32);
            num += DVec3::from_array(*p) * b;
            den += w * b;
        }
        num / den
    }

    /// The affine control point `c_k = P_k / ω_k` of a curve, or `None` when `ω_k = 0`.
    pub fn control_point(&self, homogeneous: &[[f64; 3]], k: usize) -> Option<DVec3> {
        let w = *self.weights.get(k)?;
        let p = homogeneous.get(k)?;
        (w != 0.0).then(|| DVec3::from_array(*p) / w)
    }
}

/// The rational Bézier form of a whole [`RationalMotion`].
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct RationalBezierExport {
    /// `"C0"`, `"C1 (18)"` or `"C1 (19)"`.
    pub continuity: String,
    /// Vertex positions at `t_0` (`a_0, x_0, y_0`).
    pub reference: [[f64; 3]; 3],
    /// One entry per segment `[t_i, t_{i+1}]`.
    pub segments: Vec<RationalBezierSegment>,
}

fn binomial(n: usize, k: usize) -> f64 {
    if k > n {
        return 0.0;
    }
    (0..k).fold(1.0, |acc, j| acc * (n - j) as f64 / (j + 1) as f64)
}

impl RationalMotion {
    /// Fits the motion to triangle samples (open sequence).
    ///
    /// Needs at least 2 samples, validated by [`super::validate_samples`]: finite, strictly
    /// increasing times, a non-degenerate rigid triangle. The C¹ version fails with
    /// [`ErrorKind::Unsupported`](crate::ErrorKind::Unsupported) when its denominator drops below [`MIN_DENOMINATOR`].
    pub fn fit(
        samples: &[TriangleSample],
        continuity: Continuity,
    ) -> Result<RationalMotion, Error> {
        validate_samples(samples, 2)?;
        let reference = samples[0];
        let quats = canonical_signs(
            &samples
                .iter()
                .map(|s| rotation_between(&reference, s))
                .collect::<Vec<_>>(),
        );
        let segments = match continuity {
            Continuity::C0 => c0::segments(samples, &quats),
            Continuity::C1(end) => c1::segments(samples, &quats, end),
        };
        if let Continuity::C1(_) = continuity {
            for (i, s) in segments.iter().enumerate() {
                let m = s.min_denominator();
                if m.is_nan() || m < MIN_DENOMINATOR {
                    return Err(Error::new("samples", ErrorKind::Unsupported { reason: format!(
                            "the C1 quaternion spline nearly vanishes on segment {i} (min |Q|² = {m:.3e} < {MIN_DENOMINATOR:e}): the data are too irregular for the end-condition recursion; use C0 or resample"
                        ) }));
                }
            }
        }
        Ok(RationalMotion {
            continuity,
            samples: samples.to_vec(),
            quats,
            segments,
            body: Pose::IDENTITY,
            closed: false,
        })
    }

    /// A closed (periodic) C⁰ motion: the samples followed by the first sample again at
    /// `closing_time` (after the last sample's time). Only [`Continuity::C0`] has a periodic form:
    /// the C¹ consistency equations of a cycle are singular for an even number of uniformly
    /// spaced samples, and the paper's end conditions (18)/(19) need ends.
    pub fn fit_closed(
        samples: &[TriangleSample],
        closing_time: f64,
        continuity: Continuity,
    ) -> Result<RationalMotion, Error> {
        if continuity != Continuity::C0 {
            return Err(Error::new("continuity", ErrorKind::Unsupported { reason: "the C1 Chaudhry–Cameron motion needs an open sequence (end conditions (18)/(19)); closed motions are C0 only".into() }));
        }
        let mut all = samples.to_vec();
        if let Some(first) = samples.first() {
            all.push(TriangleSample {
                t: closing_time,
                ..*first
            });
        }
        validate_samples(&all, 3).map_err(|e| {
            if e.path() == format!("samples[{}].t", samples.len()) {
                Error::new(
                    "closing_time",
                    ErrorKind::OutOfRange {
                        value: closing_time.to_string(),
                        expected: "a finite time after the last sample".into(),
                    },
                )
            } else {
                e
            }
        })?;
        let mut m = RationalMotion::fit(&all, continuity)?;
        m.closed = true;
        Ok(m)
    }

    /// The motion through `poses` at `times` (one per pose; for a closed motion one more: the
    /// time at which the cycle returns to the first pose), using the triangle `reference` placed
    /// by each pose as the data. The resulting motion reproduces the poses themselves at the
    /// sample times (not only the triangle): body point `p` (local) moves as
    /// `a(t) + R(t)(P_0 p − a_0)`.
    pub fn from_poses(
        poses: &[Pose],
        times: &[f64],
        closed: bool,
        continuity: Continuity,
        reference: &ReferenceTriangle,
    ) -> Result<RationalMotion, Error> {
        for (i, p) in poses.iter().enumerate() {
            if !p.is_finite() {
                return Err(Error::new(format!("poses[{i}]"), ErrorKind::NonFinite));
            }
        }
        let (pose_times, closing) = if closed {
            if times.len() != poses.len() + 1 {
                return Err(Error::new(
                    "times",
                    ErrorKind::OutOfRange {
                        value: format!("{} times", times.len()),
                        expected: format!(
                            "{} (one per pose plus the closing time)",
                            poses.len() + 1
                        ),
                    },
                ));
            }
            (&times[..poses.len()], times.last().copied())
        } else {
            (times, None)
        };
        let samples = super::triangle::samples_from_poses(poses, pose_times, reference)?;
        let mut m = match closing {
            Some(tc) => RationalMotion::fit_closed(&samples, tc, continuity)?,
            None => RationalMotion::fit(&samples, continuity)?,
        };
        // B = (a_0, I)⁻¹ ∘ P_0: the body relative to vertex a at t_0.
        let p0 = poses[0];
        m.body = Pose::new(p0.origin - m.samples[0].a, p0.rotation);
        Ok(m)
    }

    /// The continuity this motion was fitted with.
    pub fn continuity(&self) -> Continuity {
        self.continuity
    }

    /// The sample quaternions `Q_i` after the sign rule (eq. 9), `Q_0 = 1`.
    pub fn quaternions(&self) -> &[DQuat] {
        &self.quats
    }

    /// The C¹ middle control quaternions `M_i` (empty for C⁰).
    pub fn middles(&self) -> Vec<DQuat> {
        match self.continuity {
            Continuity::C0 => Vec::new(),
            Continuity::C1(_) => self.segments.iter().map(|s| s.quats[1]).collect(),
        }
    }

    /// The three vertices `[a(t), x(t), y(t)]` of the triangle the motion was fitted to (for a
    /// motion from poses: the reference triangle placed by the poses) at time `t`:
    /// `v(t) = a(t) + R(t)(v_0 − a_0)` (docs/math/rational-motion.md §3).
    pub fn vertices(&self, t: f64) -> [DVec3; 3] {
        let first = &self.samples[0];
        let a = self.translation(t);
        let r = self.rotation(t);
        [a, a + r * (first.x - first.a), a + r * (first.y - first.a)]
    }

    /// How far the C¹ end-condition recursion has carried the middle control points from the
    /// data (docs/math/rational-motion.md §6.1, caution): the largest distance of a middle
    /// control point `M_i` (quaternions) or `Â_i` (translation spline) from the midpoint of its
    /// segment's chord, relative to the longest chord of the same curve; the larger of the two.
    ///
    /// Smooth data keep it near `h·curvature/4` (well below 1); the recursion amplifies any
    /// misfit by `h_i/h_{i−1}` per step and never damps it, so on long or irregular sequences it
    /// grows without bound. `0` for C⁰ (no recursion) and for data on a straight line.
    pub fn growth(&self) -> f64 {
        let Continuity::C1(end) = self.continuity else {
            return 0.0;
        };
        let n = self.samples.len() - 1;
        let h: Vec<f64> = (0..n)
            .map(|i| self.samples[i + 1].t - self.samples[i].t)
            .collect();
        fn relative<T: crate::methods::polynomial::Vector>(
            values: &[T],
            mids: &[T],
            norm: impl Fn(T) -> f64,
        ) -> f64 {
            let chord = values
                .windows(2)
                .map(|w| norm(w[1] - w[0]))
                .fold(0.0, f64::max);
            let off = mids
                .iter()
                .enumerate()
                .map(|(i, &m)| norm(m - (values[i] + values[i + 1]) * 0.5))
                .fold(0.0, f64::max);
            if chord > 0.0 {
                off / chord
            } else {
                0.0
            }
        }
        let mq = c1::quadratic_spline_middles(&self.quats, &h, end);
        let points: Vec<DVec3> = self.samples.iter().map(|s| s.a).collect();
        let ma = c1::quadratic_spline_middles(&points, &h, end);
        relative(&self.quats, &mq, DQuat::length).max(relative(&points, &ma, DVec3::length))
    }

    /// A sentence when [`RationalMotion::growth`] exceeds [`GROWTH_WARNING`]: the C¹ recursion
    /// has run away from the data and the motion is poor (large accelerations between samples)
    /// though nothing failed; `None` otherwise.
    pub fn warning(&self) -> Option<String> {
        let g = self.growth();
        (g > GROWTH_WARNING).then(|| {
            format!(
                "the C1 end-condition recursion grows without damping over {} samples: a middle \
                 control point lies {g:.3e} chord lengths off its chord (over {GROWTH_WARNING}), \
                 so the motion swings far between samples; use C0, fewer samples, or the other \
                 end condition",
                self.samples.len()
            )
        })
    }

    /// The samples the motion was fitted to (for a closed motion including the closing sample).
    pub fn samples(&self) -> &[TriangleSample] {
        &self.samples
    }

    fn locate(&self, t: f64) -> (usize, f64) {
        let t0 = self.samples[0].t;
        let tn = self.samples[self.samples.len() - 1].t;
        let t = if self.closed && t.is_finite() {
            t0 + (t - t0).rem_euclid(tn - t0)
        } else {
            t
        };
        let n = self.segments.len();
        let i = self.segments.partition_point(|s| s.t1 <= t).min(n - 1);
        let s = &self.segments[i];
        (i, (t - s.t0) / (s.t1 - s.t0))
    }

    /// The quaternion curve `Q(t)` (not normalised; `|Q(t_i)| = 1`).
    pub fn quaternion(&self, t: f64) -> DQuat {
        let (i, tau) = self.locate(t);
        self.segments[i].quat(tau).0
    }

    /// The rotation `R(t) = M(Q)/|Q|²` since `t_0`.
    pub fn rotation(&self, t: f64) -> DMat3 {
        let q = self.quaternion(t);
        unnormalised_matrix(q) * (1.0 / q.length_squared())
    }

    /// The translation curve `a(t)` (trajectory of vertex `a`).
    pub fn translation(&self, t: f64) -> DVec3 {
        let (i, tau) = self.locate(t);
        let ((n, _, _), (w, _, _)) = self.segments[i].homogeneous(tau);
        n / w
    }

    /// Position at `t` of the body point whose world position at `t_0` is `p0`:
    /// `a(t) + R(t)(p0 − a_0)`.
    pub fn point(&self, p0: DVec3, t: f64) -> DVec3 {
        let (i, tau) = self.locate(t);
        let s = &self.segments[i];
        let ((n, _, _), (w, _, _)) = s.homogeneous(tau);
        let q = s.quat(tau).0;
        n / w + normalised(q) * (p0 - self.samples[0].a)
    }

    /// The smallest denominator `min w(t)` over all segments (`1` for C⁰ data up to `(1+ω)/2`).
    pub fn min_denominator(&self) -> f64 {
        self.segments
            .iter()
            .fold(f64::INFINITY, |m, s| m.min(s.min_denominator()))
    }

    /// The rational Bézier form: per segment the weights, quaternion control points and the
    /// homogeneous control points of the three vertex curves (docs/math/rational-motion.md §5.2, §6.2).
    pub fn bezier(&self) -> RationalBezierExport {
        let r = &self.samples[0];
        let (e1, e2) = r.edges();
        let segments = self
            .segments
            .iter()
            .map(|s| {
                let k = s.degree + 1;
                let mats = s.matrix_coefficients();
                let curve = |v: DVec3| -> Vec<[f64; 3]> {
                    (0..k)
                        .map(|j| (s.numer[j] + mats[j] * v).to_array())
                        .collect()
                };
                let quats: Vec<[f64; 4]> = if s.degree == 2 {
                    vec![wxyz(s.quats[0]), wxyz(s.quats[1])]
                } else {
                    s.quats.iter().map(|&q| wxyz(q)).collect()
                };
                RationalBezierSegment {
                    t_start: s.t0,
                    t_end: s.t1,
                    degree: s.degree,
                    weights: s.weights[..k].to_vec(),
                    quaternions: quats,
                    a: s.numer[..k].iter().map(|p| p.to_array()).collect(),
                    x: curve(e1),
                    y: curve(e2),
                }
            })
            .collect();
        RationalBezierExport {
            continuity: match self.continuity {
                Continuity::C0 => "C0".into(),
                Continuity::C1(EndCondition::ZeroCurvatureStart) => "C1 (18)".into(),
                Continuity::C1(EndCondition::ZeroCurvatureEnd) => "C1 (19)".into(),
            },
            reference: [r.a.to_array(), r.x.to_array(), r.y.to_array()],
            segments,
        }
    }
}

/// Numbers per key of a raw triangle sequence: `t, a_x, a_y, a_z, x_x, x_y, x_z, y_x, y_y, y_z`.
pub const TRIANGLE_STRIDE: usize = 10;

/// A raw triangle sequence (docs/math/rational-motion.md §1) from flat numbers, [`TRIANGLE_STRIDE`]
/// per key: the time, then the three vertices `a`, `x`, `y`. The length must be a multiple of the
/// stride; the samples are not validated here ([`RationalMotion::fit`] does, naming
/// `samples[i]`).
pub fn triangle_samples(data: &[f64]) -> Result<Vec<TriangleSample>, Error> {
    if data.len() % TRIANGLE_STRIDE != 0 {
        return Err(Error::new(
            "samples",
            ErrorKind::OutOfRange {
                value: format!("{} numbers", data.len()),
                expected: format!(
                    "a multiple of {TRIANGLE_STRIDE} (t and the vertices a, x, y of each key)"
                ),
            },
        ));
    }
    let v = |c: &[f64]| DVec3::new(c[0], c[1], c[2]);
    Ok(data
        .chunks_exact(TRIANGLE_STRIDE)
        .map(|c| TriangleSample {
            t: c[0],
            a: v(&c[1..4]),
            x: v(&c[4..7]),
            y: v(&c[7..10]),
        })
        .collect())
}

fn wxyz(q: DQuat) -> [f64; 4] {
    [q.w, q.x, q.y, q.z]
}

impl Motion for RationalMotion {
    fn name(&self) -> String {
        match self.continuity {
            Continuity::C0 => "chaudhry-cameron C0".into(),
            Continuity::C1(EndCondition::ZeroCurvatureStart) => "chaudhry-cameron C1 (18)".into(),
            Continuity::C1(EndCondition::ZeroCurvatureEnd) => "chaudhry-cameron C1 (19)".into(),
        }
    }

    fn domain(&self) -> (f64, f64) {
        (self.samples[0].t, self.samples[self.samples.len() - 1].t)
    }

    fn is_closed(&self) -> bool {
        self.closed
    }

    fn pose_at(&self, t: f64) -> Pose {
        let (i, tau) = self.locate(t);
        let s = &self.segments[i];
        let ((n, _, _), (w, _, _)) = s.homogeneous(tau);
        let r = normalised(s.quat(tau).0);
        Pose::new(n / w, r).compose(&self.body)
    }

    fn knots(&self) -> Vec<f64> {
        let k = if self.closed {
            self.samples.len() - 1
        } else {
            self.samples.len()
        };
        self.samples[..k].iter().map(|s| s.t).collect()
    }

    /// Closed form: `ω = 2 vec(Q'Q*)/|Q|²`, `α` from `Q''` (see [`super::angular_rates`]); the
    /// translation by the quotient rule on `N/w`; a body point at `r = x − a` from `a` moves with
    /// `a' + ω × r` and accelerates with `a'' + α × r + ω × (ω × r)`.
    fn kinematics_at(&self, t: f64, local: DVec3) -> Option<Kinematics> {
        let (i, tau) = self.locate(t);
        let s = &self.segments[i];
        let h = s.t1 - s.t0;
        let (q, q1, q2) = s.quat(tau);
        let (omega, alpha) = angular_rates(q, q1 / h, q2 / (h * h));
        let ((n, n1, n2), (w, w1, w2)) = s.homogeneous(tau);
        let a = n / w;
        let a1 = (n1 - a * w1) / w;
        let a2 = (n2 - a1 * (2.0 * w1) - a * w2) / w;
        let (a1, a2) = (a1 / h, a2 / (h * h));
        let pose = Pose::new(a, normalised(q)).compose(&self.body);
        let x = pose.transform_point(local);
        let r = x - a;
        let velocity = a1 + omega.cross(r);
        Some(Kinematics {
            position: x,
            velocity,
            acceleration: a2 + alpha.cross(r) + omega.cross(omega.cross(r)),
            angular_velocity: omega,
            angular_acceleration: alpha,
        })
    }
}

impl Default for Continuity {
    fn default() -> Self {
        Continuity::C1(EndCondition::default())
    }
}
