//! Smoothness and fidelity metrics for any [`Motion`] built from the same control poses: velocity
//! and acceleration jumps at knots, integrated squared accelerations, interpolation error,
//! dependence on the local frame, and exact preservation of screw motions (line, circle, helix).
//!
//! Derivatives come from [`Motion::kinematics`] where the method has them in closed form,
//! otherwise from one-sided finite differences of [`Motion::pose_at`] (steps
//! [`FD_VELOCITY_STEP`], [`FD_ACCELERATION_STEP`]). Their noise floor is about `1e-9` for
//! velocities and `1e-6` for accelerations (relative to the scene scale): jumps below that are
//! zero. ScrewBender motions are measured by differences of their refined poses instead (see
//! [`Derivatives::Sampled`]): their analytic kinematics describe the refined polyscrew, whose
//! twist is constant on each refined span, not the smooth limit motion.
//!
//! The integrals `∫|a|²` and `∫|α|²` integrate what the derivatives show inside the pieces; for a
//! C⁰ motion (polyscrew, SLERP polyline, C⁰ Chaudhry–Cameron) they leave out the impulses at the
//! velocity jumps, which the jump columns report instead.

use glam::{DQuat, DVec3};
use serde::Serialize;

use super::convergence::{converged_metrics, Converged, ConvergedMetrics, Limit};
use super::registry::{Method, COMPARISON_LEVELS};
use crate::error::{Error, ErrorKind};
use crate::motion::{Kinematics, Motion};
use crate::pose::Pose;
use crate::screw::Screw;

/// Offset `δ` for one-sided values of *analytic* kinematics at a knot: the left value is
/// `2k(u−δ) − k(u−2δ)` (linear extrapolation, error `O(δ²)`), the right one likewise, so no
/// method relies on how it breaks ties exactly at a knot.
pub const KNOT_OFFSET: f64 = 1e-6;

/// Step of the second-order one-sided finite difference of positions and rotations used for
/// velocities when a method has no analytic kinematics: `(3x(u) − 4x(u−h) + x(u−2h))/(2h)`
/// (truncation `h²|x'''|/3 ≈ 3e-9|x'''|`, round-off about `1e-12` at unit scale).
pub const FD_VELOCITY_STEP: f64 = 1e-4;

/// Step of the second-order one-sided finite difference for accelerations,
/// `(2x(u) − 5x(u−h) + 4x(u−2h) − x(u−3h))/h²` (truncation `11h²|x''''|/12 ≈ 2e-7|x''''|`,
/// round-off about `1e-8` per unit of scene scale).
pub const FD_ACCELERATION_STEP: f64 = 5e-4;

/// Default number of sub-intervals per knot interval for the integrals (4-point Gauss–Legendre
/// on each). 160 is a multiple of 32 (ScrewBender's refined spans at 5 levels) and of 5 (the
/// Ramamoorthi–Barr refinement segments), so no piece boundary falls inside a sub-interval.
pub const DEFAULT_QUADRATURE_SUBINTERVALS: usize = 160;

/// Default number of samples per knot interval for the frame-dependence and preservation errors.
pub const DEFAULT_SAMPLES_PER_SPAN: usize = 64;

/// Builds a method's motion from poses and the closed flag (e.g. `|p, c| method.build(p, c)`).
pub type MotionBuilder<'a> = dyn Fn(&[Pose], bool) -> Result<Box<dyn Motion>, Error> + 'a;

/// Upper bound on sub-intervals per knot interval and on sampled parameters (options beyond it
/// are clamped: a guard against runaway time).
pub const MAX_METRIC_SAMPLES: usize = 1_000_000;

/// Which side of a parameter a derivative is taken from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Side {
    /// From values at and before `u`.
    Left,
    /// From values at and after `u`.
    Right,
    /// Symmetric (inside a smooth piece).
    Central,
}

/// Where the metrics take derivatives from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Derivatives {
    /// [`Motion::kinematics`] when the motion has it, otherwise [`finite_difference`].
    Auto,
    /// Differences of poses sampled `step` apart ([`sampled_difference`] with both steps equal),
    /// ignoring analytic kinematics. Used for ScrewBender motions with `step = 2^−levels`, the
    /// refined span: their analytic kinematics are those of the refined polyscrew (constant
    /// twist on each refined span, so zero angular acceleration inside spans and a velocity jump
    /// at every refined knot), whereas differences of the refined poses approximate the smooth
    /// limit motion the subdivision converges to — the discrete derivatives plotted in the
    /// paper's Fig. 8 (V1) / 7 (V2).
    Sampled(f64),
}

/// Options of the metrics.
#[derive(Clone, Debug, PartialEq)]
pub struct MetricsOptions {
    /// Body points (local coordinates) whose trajectories are measured; default `(0,0,0)` and
    /// `(2,0,0)` (the two ends of the bar of scenes A1–A3).
    pub body_points: Vec<DVec3>,
    /// The change of local frame `C` for the frame-independence test (poses `P_i ∘ C`).
    pub frame_change: Pose,
    /// Sub-intervals per knot interval for the integrals.
    pub quadrature_subintervals: usize,
    /// Samples per knot interval for the sampled maximum errors.
    pub samples_per_span: usize,
    /// Whether [`evaluate`] measures the ScrewBender methods by differences of their refined
    /// poses ([`Derivatives::Sampled`] with the refined span length; default `true`) rather than
    /// by the analytic kinematics of the refined polyscrew.
    pub refined_differences: bool,
}

impl Default for MetricsOptions {
    fn default() -> Self {
        MetricsOptions {
            body_points: vec![DVec3::ZERO, DVec3::new(2.0, 0.0, 0.0)],
            frame_change: Pose::new(
                DVec3::new(0.3, -0.5, 0.2),
                DQuat::from_axis_angle(DVec3::new(1.0, 2.0, 3.0).normalize(), 0.7),
            ),
            quadrature_subintervals: DEFAULT_QUADRATURE_SUBINTERVALS,
            samples_per_span: DEFAULT_SAMPLES_PER_SPAN,
            refined_differences: true,
        }
    }
}

/// The kinematics of body point `local` at `u` from the given side: analytic when the motion has
/// them (extrapolated from `u ∓ δ`, [`KNOT_OFFSET`], for one-sided values), otherwise finite
/// differences.
pub fn kinematics_at(motion: &dyn Motion, u: f64, local: DVec3, side: Side) -> Kinematics {
    let sign = match side {
        Side::Left => -1.0,
        Side::Right => 1.0,
        Side::Central => 0.0,
    };
    if let Some(k) = motion.kinematics_at(u, local) {
        if sign == 0.0 {
            return k;
        }
        let d = sign * KNOT_OFFSET;
        if let (Some(a), Some(b)) = (
            motion.kinematics_at(u + d, local),
            motion.kinematics_at(u + 2.0 * d, local),
        ) {
            let lin = |x: DVec3, y: DVec3| x * 2.0 - y;
            return Kinematics {
                position: motion.pose_at(u).transform_point(local),
                velocity: lin(a.velocity, b.velocity),
                acceleration: lin(a.acceleration, b.acceleration),
                angular_velocity: lin(a.angular_velocity, b.angular_velocity),
                angular_acceleration: lin(a.angular_acceleration, b.angular_acceleration),
            };
        }
    }
    finite_difference(motion, u, local, side)
}

/// Kinematics by second-order finite differences of `pose_at` (see [`FD_VELOCITY_STEP`],
/// [`FD_ACCELERATION_STEP`]). Rotations are differentiated as quaternions aligned with `q(u)`:
/// `ω = 2 vec(q' q*)`, `α = 2 vec(q'' q*)`.
pub fn finite_difference(motion: &dyn Motion, u: f64, local: DVec3, side: Side) -> Kinematics {
    sampled_difference(
        motion,
        u,
        local,
        side,
        FD_VELOCITY_STEP,
        FD_ACCELERATION_STEP,
    )
}

/// Kinematics by the same second-order difference formulas as [`finite_difference`] with
/// explicit steps `hv` (velocities) and `ha` (accelerations).
pub fn sampled_difference(
    motion: &dyn Motion,
    u: f64,
    local: DVec3,
    side: Side,
    hv: f64,
    ha: f64,
) -> Kinematics {
    let p0 = motion.pose_at(u);
    let q0 = p0.rotation;
    let sample = |s: f64| {
        let p = motion.pose_at(s);
        let q = if p.rotation.dot(q0) < 0.0 {
            -p.rotation
        } else {
            p.rotation
        };
        (p.transform_point(local), q)
    };
    let (x0, _) = (p0.transform_point(local), q0);
    let (velocity, q1) = match side {
        Side::Central => {
            let h = hv;
            let (xp, qp) = sample(u + h);
            let (xm, qm) = sample(u - h);
            ((xp - xm) / (2.0 * h), (qp - qm) * (0.5 / h))
        }
        _ => {
            let s = if side == Side::Left { -1.0 } else { 1.0 };
            let h = hv;
            let (x1, r1) = sample(u + s * h);
            let (x2, r2) = sample(u + 2.0 * s * h);
            let k = s / (2.0 * h);
            (
                (x1 * 4.0 - x0 * 3.0 - x2) * k,
                (r1 * 4.0 - q0 * 3.0 - r2) * k,
            )
        }
    };
    let (acceleration, q2) = match side {
        Side::Central => {
            let h = ha;
            let (xp, qp) = sample(u + h);
            let (xm, qm) = sample(u - h);
            let k = 1.0 / (h * h);
            ((xp - x0 * 2.0 + xm) * k, (qp - q0 * 2.0 + qm) * k)
        }
        _ => {
            let s = if side == Side::Left { -1.0 } else { 1.0 };
            let h = ha;
            let (x1, r1) = sample(u + s * h);
            let (x2, r2) = sample(u + 2.0 * s * h);
            let (x3, r3) = sample(u + 3.0 * s * h);
            let k = 1.0 / (h * h);
            (
                (x0 * 2.0 - x1 * 5.0 + x2 * 4.0 - x3) * k,
                (q0 * 2.0 - r1 * 5.0 + r2 * 4.0 - r3) * k,
            )
        }
    };
    let qc = q0.conjugate();
    Kinematics {
        position: x0,
        velocity,
        acceleration,
        angular_velocity: (q1 * qc).xyz() * 2.0,
        angular_acceleration: (q2 * qc).xyz() * 2.0,
    }
}

/// The smoothness metrics of one motion measured at one step along its own derivative route
/// ([`single_step_metrics`]): analytic kinematics where the method has them, finite
/// differences otherwise, differences of the refined poses for ScrewBender motions. Kept for
/// diagnosis beside the converged values of a [`MetricsRow`]; not comparable across methods,
/// since the routes and steps differ (a ScrewBender motion's refined-pose differences show a
/// velocity jump of the order of its refined span, a finite difference only its own rounding).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SingleStepMetrics {
    /// Where the derivatives come from: `"analytic"`, `"finite differences, …"` or
    /// `"pose differences, step h"` (see [`Derivatives`]).
    pub derivatives: String,
    /// Largest jump `|v(u⁺) − v(u⁻)|` of a body point's velocity at the knots (interior knots
    /// for open motions), per parameter unit.
    pub velocity_jump: f64,
    /// Largest jump of the angular velocity at the knots (radians per parameter unit).
    pub angular_velocity_jump: f64,
    /// Largest jump of a body point's acceleration at the knots.
    pub acceleration_jump: f64,
    /// Largest jump of the angular acceleration at the knots.
    pub angular_acceleration_jump: f64,
    /// `∫ |x''(u)|² du` over the domain, one entry per body point (impulses at velocity jumps
    /// left out).
    pub acceleration_energy: Vec<f64>,
    /// `∫ |α(u)|² du`, the integrated squared angular acceleration; for unit quaternions
    /// `|q'' \ q|² = |α|²/4`, so this is 4× Ramamoorthi–Barr's covariant acceleration.
    pub angular_acceleration_energy: f64,
}

/// One row of a [`MetricsTable`]: the metrics of one method on one input.
///
/// The smoothness fields ([`MetricsRow::smoothness`], flattened into the row in JSON:
/// `velocity_jump`, `acceleration_energy`, …) are the converged values, measured the same way
/// for every method ([`converged_metrics`]); they are what the CLI's table, `compare --json`,
/// JavaScript's `compareMethods`, Python's `compare_methods` and the page show.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct MetricsRow {
    /// Short method name (e.g. `"jarek"`).
    pub method: String,
    /// The motion's own description ([`Motion::name`]).
    pub motion: String,
    /// Velocity and acceleration jumps at the knots and the integrated squared accelerations,
    /// extrapolated to a vanishing step, each with its limit (a value, zero, an impulse, or
    /// divergent).
    #[serde(flatten)]
    pub smoothness: ConvergedMetrics,
    /// Largest pose distance (origin distance + angle) between control pose `i` and the motion at
    /// knot `i` (zero for interpolating methods).
    pub interpolation_error: f64,
    /// Largest body-point deviation between the motion and the motion built on `P_i ∘ C`, mapped
    /// back by `C⁻¹` (zero for frame-independent methods).
    pub frame_dependence: Option<f64>,
    /// Largest body-point deviation from the exact motion when the input is sampled from a
    /// translation with fixed orientation (open, 6 poses).
    pub line_error: Option<f64>,
    /// The same for a rotation about a fixed axis (open, 6 poses, 50° apart).
    pub circle_error: Option<f64>,
    /// The same for a helical (screw) motion (open, 6 poses).
    pub helix_error: Option<f64>,
    /// Messages for metrics that could not be computed (e.g. the method rejected a test input),
    /// and, starting with `warning: `, where the motion itself is poor ([`Method::warnings`]).
    pub notes: Vec<String>,
    /// The same smoothness metrics at one step along the method's own derivative route: for
    /// diagnosis only (see [`SingleStepMetrics`]).
    pub single_step: SingleStepMetrics,
}

/// A comparison table: one [`MetricsRow`] per method, on the same poses.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct MetricsTable {
    /// Number of control poses.
    pub pose_count: usize,
    /// Whether the input is a cycle.
    pub closed: bool,
    /// The body points (local coordinates) of the trajectory metrics.
    pub body_points: Vec<[f64; 3]>,
    /// The rows.
    pub rows: Vec<MetricsRow>,
    /// Methods left out by [`compare_applicable`] because they do not support this input, with
    /// the reason (`"cc1: …"`).
    pub skipped: Vec<String>,
}

/// The knots where jumps are measured: all of them for a closed motion, the interior ones for an
/// open motion (its ends have only one side).
fn knots_to_test(motion: &dyn Motion) -> Vec<f64> {
    let k = motion.knots();
    if motion.is_closed() {
        k
    } else if k.len() > 2 {
        k[1..k.len() - 1].to_vec()
    } else {
        Vec::new()
    }
}

/// Breakpoints of the integration: the knots plus the domain ends, sorted.
fn intervals(motion: &dyn Motion) -> Vec<f64> {
    let (a, b) = motion.domain();
    let mut pts: Vec<f64> = motion
        .knots()
        .into_iter()
        .filter(|&k| k > a && k < b)
        .collect();
    pts.insert(0, a);
    pts.push(b);
    pts
}

/// 4-point Gauss–Legendre on `[0, 1]`.
const GAUSS4: [(f64, f64); 4] = [
    (0.069_431_844_202_973_71, 0.173_927_422_568_726_93),
    (0.330_009_478_207_571_9, 0.326_072_577_431_273_07),
    (0.669_990_521_792_428_1, 0.326_072_577_431_273_07),
    (0.930_568_155_797_026_3, 0.173_927_422_568_726_93),
];

/// The smoothness metrics of `motion` at one step along the route `derivatives` (see
/// [`SingleStepMetrics`]).
pub fn single_step_metrics(
    motion: &dyn Motion,
    derivatives: Derivatives,
    options: &MetricsOptions,
) -> SingleStepMetrics {
    let points = &options.body_points;
    let probe = points.first().copied().unwrap_or(DVec3::ZERO);
    let analytic = motion.kinematics_at(motion.domain().0, probe).is_some();
    let (domain_start, domain_end) = motion.domain();
    let kin = |u: f64, p: DVec3, side: Side| match derivatives {
        Derivatives::Auto => kinematics_at(motion, u, p, side),
        Derivatives::Sampled(h) => {
            // Stay inside the domain of an open motion.
            let side = match side {
                Side::Central if !motion.is_closed() && u - h < domain_start => Side::Right,
                Side::Central if !motion.is_closed() && u + h > domain_end => Side::Left,
                s => s,
            };
            sampled_difference(motion, u, p, side, h, h)
        }
    };
    let node_side = |x: f64| match derivatives {
        Derivatives::Sampled(_) => Side::Central,
        Derivatives::Auto if analytic || (x > 0.25 && x < 0.75) => Side::Central,
        Derivatives::Auto if x < 0.5 => Side::Right,
        Derivatives::Auto => Side::Left,
    };
    let derivative_source = match derivatives {
        Derivatives::Sampled(h) => format!("pose differences, step {h}"),
        Derivatives::Auto if analytic => "analytic".to_string(),
        Derivatives::Auto => {
            format!("finite differences, steps {FD_VELOCITY_STEP}/{FD_ACCELERATION_STEP}")
        }
    };
    let (mut vj, mut wj, mut aj, mut alj) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    for u in knots_to_test(motion) {
        for &p in points {
            let l = kin(u, p, Side::Left);
            let r = kin(u, p, Side::Right);
            vj = vj.max((r.velocity - l.velocity).length());
            aj = aj.max((r.acceleration - l.acceleration).length());
            wj = wj.max((r.angular_velocity - l.angular_velocity).length());
            alj = alj.max((r.angular_acceleration - l.angular_acceleration).length());
        }
    }
    let sub = options.quadrature_subintervals.clamp(1, MAX_METRIC_SAMPLES);
    let mut energy = vec![0.0; points.len()];
    let mut angular = 0.0;
    for w in intervals(motion).windows(2) {
        let len = (w[1] - w[0]) / sub as f64;
        for s in 0..sub {
            let a = w[0] + s as f64 * len;
            for (x, wt) in GAUSS4 {
                let u = a + x * len;
                // Small-step central differences only when the stencil stays inside this
                // sub-interval (no piece boundary inside it).
                let side = node_side(x);
                if points.is_empty() {
                    let k = kin(u, probe, side);
                    angular += wt * len * k.angular_acceleration.length_squared();
                }
                for (j, (e, &p)) in energy.iter_mut().zip(points).enumerate() {
                    let k = kin(u, p, side);
                    *e += wt * len * k.acceleration.length_squared();
                    if j == 0 {
                        angular += wt * len * k.angular_acceleration.length_squared();
                    }
                }
            }
        }
    }
    SingleStepMetrics {
        derivatives: derivative_source,
        velocity_jump: vj,
        angular_velocity_jump: wj,
        acceleration_jump: aj,
        angular_acceleration_jump: alj,
        acceleration_energy: energy,
        angular_acceleration_energy: angular,
    }
}

/// Largest pose distance (origin distance + angle) between control pose `i` and `motion` at its
/// knot `i`.
pub fn interpolation_error(motion: &dyn Motion, poses: &[Pose]) -> f64 {
    poses
        .iter()
        .zip(&motion.knots())
        .map(|(p, &u)| motion.pose_at(u).distance(p))
        .fold(0.0f64, f64::max)
}

/// Largest deviation of the body points between two motions sampled at `samples_per_span`
/// points per knot interval of `a`'s domain; `map` turns `b`'s pose into the one compared.
fn max_deviation(
    a: &dyn Motion,
    b: &dyn Motion,
    map: impl Fn(Pose) -> Pose,
    options: &MetricsOptions,
) -> f64 {
    let (u0, u1) = a.domain();
    let spans = a
        .knots()
        .len()
        .saturating_sub(usize::from(!a.is_closed()))
        .max(1);
    let count = spans
        .saturating_mul(options.samples_per_span.max(1))
        .min(MAX_METRIC_SAMPLES);
    let points: &[DVec3] = if options.body_points.is_empty() {
        &[DVec3::ZERO]
    } else {
        &options.body_points
    };
    let mut worst = 0.0f64;
    for k in 0..=count {
        let u = u0 + (u1 - u0) * k as f64 / count as f64;
        let (pa, pb) = (a.pose_at(u), map(b.pose_at(u)));
        for &p in points {
            let d = (pa.transform_point(p) - pb.transform_point(p)).length();
            // NaN (a broken motion) counts as infinitely wrong.
            worst = if d.is_nan() {
                f64::INFINITY
            } else {
                worst.max(d)
            };
        }
    }
    worst
}

/// Frame-independence error: build the method on `P_i ∘ C` and compare `pose'(u) ∘ C⁻¹` with
/// `pose(u)` on the body points (zero when the motion does not depend on the choice of the
/// local frame).
pub fn frame_dependence(
    build: &MotionBuilder<'_>,
    motion: &dyn Motion,
    poses: &[Pose],
    closed: bool,
    options: &MetricsOptions,
) -> Result<f64, Error> {
    let c = options.frame_change;
    let moved: Vec<Pose> = poses.iter().map(|p| p.compose(&c)).collect();
    let other = build(&moved, closed)?;
    let cinv = c.inverse();
    Ok(max_deviation(
        motion,
        other.as_ref(),
        |p| p.compose(&cinv),
        options,
    ))
}

/// A constant-twist motion sampled at `u = 0 … count−1`, for the preservation tests.
#[derive(Clone, Copy, Debug)]
struct ScrewTest(Screw);

impl Motion for ScrewTest {
    fn name(&self) -> String {
        "exact screw".into()
    }
    fn domain(&self) -> (f64, f64) {
        (0.0, (PRESERVATION_POSES - 1) as f64)
    }
    fn is_closed(&self) -> bool {
        false
    }
    fn pose_at(&self, u: f64) -> Pose {
        self.0.at(u)
    }
    fn knots(&self) -> Vec<f64> {
        (0..PRESERVATION_POSES).map(|i| i as f64).collect()
    }
}

/// Number of poses of the line, circle and helix inputs of the preservation test.
pub const PRESERVATION_POSES: usize = 6;

/// The three exact motions of the preservation test, as the screw from pose 0 to pose 1:
/// a line (translation, fixed tilted orientation), a circle (50° per step about a vertical axis
/// through `(1, 2, 0)`, object at radius 3) and a helix (45° per step about a tilted axis with a
/// slide of 0.6).
pub fn preservation_inputs() -> [(&'static str, Screw); 3] {
    let tilt = DQuat::from_axis_angle(DVec3::new(0.3, -1.0, 0.5).normalize(), 0.8);
    let start = Pose::new(DVec3::new(1.0, -2.0, 0.5), tilt);
    let line = Pose::new(start.origin + DVec3::new(1.5, 0.5, -0.25), tilt);
    let centre = DVec3::new(1.0, 2.0, 0.0);
    let rot = |axis: DVec3, angle: f64, slide: f64, p: Pose| {
        let r = DQuat::from_axis_angle(axis, angle);
        Pose::new(
            centre + r * (p.origin - centre) + axis * slide,
            r * p.rotation,
        )
    };
    let c0 = Pose::new(centre + DVec3::new(3.0, 0.0, 0.5), tilt);
    let circle = rot(DVec3::Z, 50f64.to_radians(), 0.0, c0);
    let axis = DVec3::new(0.2, 0.3, 1.0).normalize();
    let helix = rot(axis, 45f64.to_radians(), 0.6, c0);
    [
        ("line", Screw::between(&start, &line)),
        ("circle", Screw::between(&c0, &circle)),
        ("helix", Screw::between(&c0, &helix)),
    ]
}

/// Exact-preservation errors `[line, circle, helix]`: the method is built on
/// [`PRESERVATION_POSES`] poses sampled from each exact motion (open) and compared with it on
/// the body points over the whole domain.
pub fn preservation_errors(
    build: &MotionBuilder<'_>,
    options: &MetricsOptions,
) -> [Result<f64, Error>; 3] {
    preservation_inputs().map(|(_, screw)| {
        let exact = ScrewTest(screw);
        let poses: Vec<Pose> = exact.knots().iter().map(|&u| screw.at(u)).collect();
        let m = build(&poses, false)?;
        Ok(max_deviation(&exact, m.as_ref(), |p| p, options))
    })
}

/// All metrics of one method: builds it on `poses`, measures it (converged, and at one step
/// along its own route), and rebuilds it for the frame-independence and preservation tests.
/// Errors only when the method rejects `poses` themselves; a rejected test input leaves that
/// metric `None` with a note.
pub fn evaluate(
    method: Method,
    poses: &[Pose],
    closed: bool,
    options: &MetricsOptions,
) -> Result<MetricsRow, Error> {
    let motion = method.build(poses, closed)?;
    let derivatives = match method {
        Method::BSpline | Method::FourPoint | Method::Jarek if options.refined_differences => {
            Derivatives::Sampled(0.5f64.powi(COMPARISON_LEVELS as i32))
        }
        _ => Derivatives::Auto,
    };
    let smoothness = converged_metrics(method, poses, closed, &options.body_points)
        .map_err(|e| e.within("converged metrics"))?;
    let mut row = MetricsRow {
        method: method.name().to_string(),
        motion: motion.name(),
        smoothness,
        interpolation_error: interpolation_error(motion.as_ref(), poses),
        frame_dependence: None,
        line_error: None,
        circle_error: None,
        helix_error: None,
        notes: Vec::new(),
        single_step: single_step_metrics(motion.as_ref(), derivatives, options),
    };
    for w in method.warnings(poses, closed) {
        row.notes.push(format!("warning: {w}"));
    }
    let build = |p: &[Pose], c: bool| method.build(p, c);
    match frame_dependence(&build, motion.as_ref(), poses, closed, options) {
        Ok(v) => row.frame_dependence = Some(v),
        Err(e) => row.notes.push(format!("frame test: {e}")),
    }
    let names = ["line", "circle", "helix"];
    for (k, r) in preservation_errors(&build, options).into_iter().enumerate() {
        match r {
            Ok(v) => match k {
                0 => row.line_error = Some(v),
                1 => row.circle_error = Some(v),
                _ => row.helix_error = Some(v),
            },
            Err(e) => row.notes.push(format!("{} test: {e}", names[k])),
        }
    }
    Ok(row)
}

/// The comparison table of `methods` on `poses` (see [`evaluate`]).
pub fn compare_methods(
    poses: &[Pose],
    closed: bool,
    methods: &[Method],
    options: &MetricsOptions,
) -> Result<MetricsTable, Error> {
    let rows = methods
        .iter()
        .map(|&m| evaluate(m, poses, closed, options).map_err(|e| e.within(m.name())))
        .collect::<Result<Vec<_>, Error>>()?;
    Ok(MetricsTable {
        pose_count: poses.len(),
        closed,
        body_points: options.body_points.iter().map(|p| p.to_array()).collect(),
        rows,
        skipped: Vec::new(),
    })
}

/// The comparison table of every method that applies to the input ([`Method::applicable`]); a
/// method that rejects these poses as unsupported (e.g. the C¹ Chaudhry–Cameron motion when its
/// denominator would vanish) is listed in [`MetricsTable::skipped`] instead of failing the whole
/// table. Invalid poses still give an error.
pub fn compare_applicable(
    poses: &[Pose],
    closed: bool,
    options: &MetricsOptions,
) -> Result<MetricsTable, Error> {
    let mut table = compare_methods(poses, closed, &[], options)?;
    for m in Method::applicable(closed) {
        match evaluate(m, poses, closed, options) {
            Ok(row) => table.rows.push(row),
            Err(e) if matches!(e.kind(), ErrorKind::Unsupported { .. }) => {
                table.skipped.push(format!("{m}: {e}"))
            }
            Err(e) => return Err(e.within(m.name())),
        }
    }
    Ok(table)
}

fn fmt_num(v: f64) -> String {
    if v == 0.0 {
        "0".into()
    } else {
        format!("{v:.2e}")
    }
}

fn fmt_opt(v: Option<f64>) -> String {
    v.map_or_else(|| "-".into(), fmt_num)
}

/// A converged metric as a table cell: its value, `0`, `impulse(s)` for a jump carried by an
/// impulse of size `s` (the velocity jump), `∞` for an integral over an impulse, `diverges`.
fn fmt_converged(c: &Converged, integral: bool) -> String {
    match c.limit {
        Limit::Value => fmt_num(c.value),
        Limit::Zero => "0".into(),
        Limit::Impulse if integral => "∞".into(),
        Limit::Impulse => format!("impulse({})", fmt_num(c.value)),
        Limit::Diverges => "diverges".into(),
    }
}

impl MetricsTable {
    /// The table as aligned plain-text columns, with a legend.
    pub fn to_text(&self) -> String {
        let mut header: Vec<String> = ["method", "|Δv|", "|Δω|", "|Δa|", "|Δα|"]
            .iter()
            .map(|s| s.to_string())
            .collect();
        for p in &self.body_points {
            header.push(format!("∫|a|²({},{},{})", p[0], p[1], p[2]));
        }
        for h in ["∫|α|²", "interp", "frame", "line", "circle", "helix"] {
            header.push(h.into());
        }
        let mut rows: Vec<Vec<String>> = vec![header];
        for r in &self.rows {
            let c = &r.smoothness;
            let mut line = vec![
                r.method.clone(),
                fmt_converged(&c.velocity_jump, false),
                fmt_converged(&c.angular_velocity_jump, false),
                fmt_converged(&c.acceleration_jump, false),
                fmt_converged(&c.angular_acceleration_jump, false),
            ];
            line.extend(c.acceleration_energy.iter().map(|e| fmt_converged(e, true)));
            line.push(fmt_converged(&c.angular_acceleration_energy, true));
            line.push(fmt_num(r.interpolation_error));
            for v in [
                r.frame_dependence,
                r.line_error,
                r.circle_error,
                r.helix_error,
            ] {
                line.push(fmt_opt(v));
            }
            rows.push(line);
        }
        let cols = rows.iter().map(|r| r.len()).max().unwrap_or(0);
        let width: Vec<usize> = (0..cols)
            .map(|c| {
                rows.iter()
                    .filter_map(|r| r.get(c))
                    .map(|s| s.chars().count())
                    .max()
                    .unwrap_or(0)
            })
            .collect();
        let mut out = format!(
            "{} {} poses; body points {:?}\n",
            self.pose_count,
            if self.closed { "closed" } else { "open" },
            self.body_points
        );
        for r in &rows {
            let cells: Vec<String> = r
                .iter()
                .enumerate()
                .map(|(c, s)| {
                    let pad = width[c] - s.chars().count();
                    if c == 0 {
                        format!("{s}{}", " ".repeat(pad))
                    } else {
                        format!("{}{s}", " ".repeat(pad))
                    }
                })
                .collect();
            out.push_str(cells.join("  ").trim_end());
            out.push('\n');
        }
        for r in &self.rows {
            for n in &r.notes {
                out.push_str(&format!("note ({}): {n}\n", r.method));
            }
        }
        for s in &self.skipped {
            out.push_str(&format!("skipped {s}\n"));
        }
        out.push_str(
            "|Δv| |Δω| |Δa| |Δα|: largest jumps at the knots (body points; per parameter unit)\n\
             ∫|a|²: integrated squared acceleration of a body point; ∫|α|²: of the angular velocity\n\
             interp: largest distance to the control poses at their knots (length + radians)\n\
             frame: change of the trajectories when the local frame moves (built on P_i∘C)\n\
             line/circle/helix: largest deviation from an exact screw motion sampled at 6 poses\n\
             smoothness columns: every method sampled alike at steps 2^-7, 2^-8, 2^-9 and\n\
             extrapolated to a vanishing step; impulse(s): the velocity jumps by s, so the\n\
             acceleration there is an impulse (no finite jump; its integral is ∞)\n",
        );
        out
    }

    /// The table as JSON (see the field docs of [`MetricsTable`] and [`MetricsRow`]).
    #[cfg(feature = "json")]
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
    }
}
