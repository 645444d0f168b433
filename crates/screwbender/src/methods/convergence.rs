//! Converged smoothness metrics, measured the same way for every method: the motion is sampled on
//! the grid `u = k·h` for three steps `h = 2^−L` ([`CONVERGENCE_LEVELS`]; a ScrewBender motion is
//! refined `L` times, so the samples are its refined poses), derivatives are the same one-sided
//! (at knots) and central (for the integrals) differences of those samples for all methods, and
//! the three estimates are extrapolated to `h → 0`.
//!
//! Why not the analytic kinematics where a method has them: the ScrewBender motions would then
//! be measured on their refined polyscrew (constant twist per refined span) and the others on
//! their exact derivatives, two different things; a table that puts them side by side must take
//! both through the same route and step, and say what the limit is.
//!
//! Each metric comes out as a [`Converged`]: a value (extrapolated, with an error bound from the
//! two extrapolations), zero (the estimates shrink with the step, as for a jump of a C¹ motion),
//! an impulse (the acceleration of a motion whose velocity jumps is a Dirac impulse at the
//! knots: its acceleration jump is undefined and `∫|a|²` infinite, the size reported is that of
//! the velocity jump) or divergent (the estimates grow as the step shrinks).

use glam::{DQuat, DVec3};
use serde::Serialize;

use super::registry::Method;
use crate::error::Error;
use crate::motion::Motion;
use crate::pose::Pose;

/// The three subdivision levels `L` whose steps `2^−L` the converged metrics use, coarsest first.
pub const CONVERGENCE_LEVELS: [u32; 3] = [7, 8, 9];

/// An estimate counts as zero below this fraction of the motion's typical speed (rounding of the
/// differences at the finest step).
const ZERO_RELATIVE: f64 = 1e-7;
/// A jump whose extrapolated limit is below this fraction of its coarsest estimate, with the
/// estimates shrinking step by step, tends to zero.
const SHRINK_FRACTION: f64 = 0.05;
/// Estimates that grow by more than this factor at each halving diverge.
const GROWTH: f64 = 1.2;

/// What a converged metric tends to as the step shrinks.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Limit {
    /// A finite value ([`Converged::value`], error bound [`Converged::error`]).
    Value,
    /// Zero: the estimates shrink with the step (e.g. the velocity jump of a C¹ motion).
    Zero,
    /// An impulse: the velocity (or angular velocity) jumps at the knots, so the acceleration
    /// there is a Dirac impulse; [`Converged::value`] is the size of that velocity jump.
    Impulse,
    /// The estimates grow as the step shrinks (the derivative does not exist).
    Diverges,
}

/// One converged metric.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Converged {
    /// What the metric tends to.
    pub limit: Limit,
    /// The extrapolated value (0 for [`Limit::Zero`], the finest estimate for
    /// [`Limit::Diverges`], the velocity jump's size for [`Limit::Impulse`]).
    pub value: f64,
    /// The size of the extrapolation's correction to the finest estimate: a bound on the error
    /// of `value` (Aitken's extrapolation of the three estimates).
    pub error: f64,
    /// The raw estimates at the steps of [`ConvergedMetrics::steps`], coarsest first.
    pub estimates: [f64; 3],
}

/// The converged smoothness metrics of one method (see the module doc).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ConvergedMetrics {
    /// The steps `h = 2^−L` of the three estimates, in parameter units.
    pub steps: [f64; 3],
    /// Largest jump of a body point's velocity at the knots.
    pub velocity_jump: Converged,
    /// Largest jump of the angular velocity at the knots.
    pub angular_velocity_jump: Converged,
    /// Largest jump of a body point's acceleration at the knots.
    pub acceleration_jump: Converged,
    /// Largest jump of the angular acceleration at the knots.
    pub angular_acceleration_jump: Converged,
    /// `∫|a|² du`, one per body point.
    pub acceleration_energy: Vec<Converged>,
    /// `∫|α|² du`.
    pub angular_acceleration_energy: Converged,
}

/// The raw estimates at one step.
struct Estimate {
    velocity_jump: f64,
    angular_velocity_jump: f64,
    acceleration_jump: f64,
    angular_acceleration_jump: f64,
    acceleration_energy: Vec<f64>,
    angular_acceleration_energy: f64,
    /// Largest speed of a body point at the knots (the scale of "zero").
    speed: f64,
    /// Largest angular speed at the knots.
    angular_speed: f64,
}

/// Samples of one body point's trajectory and the rotations on the grid.
fn estimate(motion: &dyn Motion, levels: u32, points: &[DVec3]) -> Estimate {
    let (a, b) = motion.domain();
    let closed = motion.is_closed();
    let per_span = 1usize << levels;
    let knots = motion.knots();
    let spans = knots.len().saturating_sub(usize::from(!closed)).max(1);
    let n = spans * per_span;
    let h = (b - a) / n as f64;
    // Open: samples 0..=n; closed: 0..n with wrap-around.
    let count = if closed { n } else { n + 1 };
    let poses: Vec<Pose> = (0..count)
        .map(|k| motion.pose_at(a + k as f64 * h))
        .collect();
    let at = |k: isize| -> Option<&Pose> {
        if closed {
            Some(&poses[k.rem_euclid(n as isize) as usize])
        } else if k >= 0 && (k as usize) < count {
            Some(&poses[k as usize])
        } else {
            None
        }
    };
    // Rotations aligned with q_k before differencing (q and −q are the same rotation).
    let align = |q: DQuat, r: DQuat| if q.dot(r) < 0.0 { -q } else { q };
    let omega = |dq: DQuat, q: DQuat| (dq * q.conjugate()).xyz() * 2.0;
    // One-sided values at sample k towards side s (±1): velocity and acceleration of point p
    // (None: p is the rotation), second order.
    let one_sided = |k: isize, s: isize, p: Option<DVec3>| -> Option<(DVec3, DVec3)> {
        let p0 = at(k)?;
        let (p1, p2, p3) = (at(k + s)?, at(k + 2 * s)?, at(k + 3 * s)?);
        let sf = s as f64;
        match p {
            Some(p) => {
                let x = |q: &Pose| q.transform_point(p);
                let (x0, x1, x2, x3) = (x(p0), x(p1), x(p2), x(p3));
                let v = (x1 * 4.0 - x0 * 3.0 - x2) * (sf / (2.0 * h));
                let acc = (x0 * 2.0 - x1 * 5.0 + x2 * 4.0 - x3) / (h * h);
                Some((v, acc))
            }
            None => {
                let q0 = p0.rotation;
                let (q1, q2, q3) = (
                    align(p1.rotation, q0),
                    align(p2.rotation, q0),
                    align(p3.rotation, q0),
                );
                let dq = (q1 * 4.0 - q0 * 3.0 - q2) * (sf / (2.0 * h));
                let ddq = (q0 * 2.0 - q1 * 5.0 + q2 * 4.0 - q3) * (1.0 / (h * h));
                Some((omega(dq, q0), omega(ddq, q0)))
            }
        }
    };
    let tested: Vec<isize> = (0..knots.len())
        .filter(|&i| closed || (i > 0 && i + 1 < knots.len()))
        .map(|i| (i * per_span) as isize)
        .collect();
    let mut e = Estimate {
        velocity_jump: 0.0,
        angular_velocity_jump: 0.0,
        acceleration_jump: 0.0,
        angular_acceleration_jump: 0.0,
        acceleration_energy: vec![0.0; points.len()],
        angular_acceleration_energy: 0.0,
        speed: 0.0,
        angular_speed: 0.0,
    };
    for &k in &tested {
        for &p in points {
            if let (Some(l), Some(r)) = (one_sided(k, -1, Some(p)), one_sided(k, 1, Some(p))) {
                e.velocity_jump = e.velocity_jump.max((r.0 - l.0).length());
                e.acceleration_jump = e.acceleration_jump.max((r.1 - l.1).length());
                e.speed = e.speed.max(l.0.length()).max(r.0.length());
            }
        }
        if let (Some(l), Some(r)) = (one_sided(k, -1, None), one_sided(k, 1, None)) {
            e.angular_velocity_jump = e.angular_velocity_jump.max((r.0 - l.0).length());
            e.angular_acceleration_jump = e.angular_acceleration_jump.max((r.1 - l.1).length());
            e.angular_speed = e.angular_speed.max(l.0.length()).max(r.0.length());
        }
    }
    // Integrals: central second differences at every sample with both neighbours, trapezoid
    // weights (the ends of an open motion get half a step each, from their one-sided values).
    for k in 0..count as isize {
        let (Some(m), Some(p0), Some(pp)) = (at(k - 1), at(k), at(k + 1)) else {
            continue;
        };
        let w = h;
        for (j, &pt) in points.iter().enumerate() {
            let acc = (pp.transform_point(pt) - p0.transform_point(pt) * 2.0
                + m.transform_point(pt))
                / (h * h);
            e.acceleration_energy[j] += w * acc.length_squared();
        }
        let q0 = p0.rotation;
        let ddq = (align(pp.rotation, q0) - q0 * 2.0 + align(m.rotation, q0)) * (1.0 / (h * h));
        e.angular_acceleration_energy += w * omega(ddq, q0).length_squared();
    }
    if !closed {
        for k in [0isize, count as isize - 1] {
            let s = if k == 0 { 1 } else { -1 };
            for (j, &pt) in points.iter().enumerate() {
                if let Some((_, acc)) = one_sided(k, s, Some(pt)) {
                    e.acceleration_energy[j] += 0.5 * h * acc.length_squared();
                }
            }
            if let Some((_, alpha)) = one_sided(k, s, None) {
                e.angular_acceleration_energy += 0.5 * h * alpha.length_squared();
            }
        }
    }
    e
}

/// The limit of three estimates at halving steps. Their differences `d₁ = e₀ − e₁`,
/// `d₂ = e₁ − e₂` shrink by `ρ = d₁/d₂` per halving (2 for an error linear in the step, as the
/// one-sided differences at a 4-point knot; 4 for a quadratic one, as on a smooth curve), so the
/// limit is `e₂ − d₂/(ρ − 1)` (Aitken's extrapolation) with that correction as the error bound;
/// where the differences do not shrink geometrically the finest estimate stands, with the larger
/// difference as its error. Zero when a jump's estimates shrink towards it (or are below
/// `zero`), divergent when they grow at every halving.
fn limit(estimates: [f64; 3], zero: f64, jump: bool) -> Converged {
    let [e0, e1, e2] = estimates;
    let (d1, d2) = (e0 - e1, e1 - e2);
    let (value, error) = if d2 == 0.0 {
        (e2, d1.abs())
    } else {
        let rho = d1 / d2;
        if (1.5..=32.0).contains(&rho) {
            let c = d2 / (rho - 1.0);
            (e2 - c, c.abs())
        } else {
            (e2, d1.abs().max(d2.abs()))
        }
    };
    let out = |limit, value| Converged {
        limit,
        value,
        error,
        estimates,
    };
    if !estimates.iter().all(|v| v.is_finite()) {
        return out(Limit::Diverges, f64::INFINITY);
    }
    if e2 <= zero {
        return out(Limit::Zero, 0.0);
    }
    if e2 > GROWTH * e1 && e1 > GROWTH * e0 {
        return out(Limit::Diverges, e2);
    }
    let shrinking = e2 < e1 && e1 < e0;
    if jump && shrinking && (value <= SHRINK_FRACTION * e0 || value <= zero) {
        return out(Limit::Zero, 0.0);
    }
    out(Limit::Value, value.max(0.0))
}

/// The converged metrics of `method` on `poses` (see the module doc); `points` are the body
/// points in local coordinates (at least one is used: the origin when empty).
pub fn converged_metrics(
    method: Method,
    poses: &[Pose],
    closed: bool,
    points: &[DVec3],
) -> Result<ConvergedMetrics, Error> {
    let points: Vec<DVec3> = if points.is_empty() {
        vec![DVec3::ZERO]
    } else {
        points.to_vec()
    };
    let fixed = if method.is_subdivision() {
        None
    } else {
        Some(method.build(poses, closed)?)
    };
    let mut est = Vec::with_capacity(3);
    for &levels in &CONVERGENCE_LEVELS {
        let e = match &fixed {
            Some(m) => estimate(m.as_ref(), levels, &points),
            None => estimate(
                method.build_at(poses, closed, levels)?.as_ref(),
                levels,
                &points,
            ),
        };
        est.push(e);
    }
    let steps = CONVERGENCE_LEVELS.map(|l| 0.5f64.powi(l as i32));
    let three = |f: &dyn Fn(&Estimate) -> f64| [f(&est[0]), f(&est[1]), f(&est[2])];
    let speed = est.iter().map(|e| e.speed).fold(1e-12, f64::max);
    let angular_speed = est
        .iter()
        .map(|e| e.angular_speed.max(e.speed))
        .fold(1e-12, f64::max);
    let velocity_jump = limit(three(&|e| e.velocity_jump), ZERO_RELATIVE * speed, true);
    let angular_velocity_jump = limit(
        three(&|e| e.angular_velocity_jump),
        ZERO_RELATIVE * angular_speed,
        true,
    );
    // Accelerations: the scale of "zero" is speed per parameter unit, over the finest step.
    let acc_zero = ZERO_RELATIVE * speed / steps[2];
    let alpha_zero = ZERO_RELATIVE * angular_speed / steps[2];
    let impulse = |jump: &Converged, c: Converged| {
        if jump.limit == Limit::Value {
            Converged {
                limit: Limit::Impulse,
                value: jump.value,
                ..c
            }
        } else {
            c
        }
    };
    let acceleration_jump = impulse(
        &velocity_jump,
        limit(three(&|e| e.acceleration_jump), acc_zero, true),
    );
    let angular_acceleration_jump = impulse(
        &angular_velocity_jump,
        limit(three(&|e| e.angular_acceleration_jump), alpha_zero, true),
    );
    let acceleration_energy = (0..points.len())
        .map(|j| {
            impulse(
                &velocity_jump,
                limit(
                    three(&|e| e.acceleration_energy[j]),
                    acc_zero * acc_zero,
                    false,
                ),
            )
        })
        .collect();
    let angular_acceleration_energy = impulse(
        &angular_velocity_jump,
        limit(
            three(&|e| e.angular_acceleration_energy),
            alpha_zero * alpha_zero,
            false,
        ),
    );
    Ok(ConvergedMetrics {
        steps,
        velocity_jump,
        angular_velocity_jump,
        acceleration_jump,
        angular_acceleration_jump,
        acceleration_energy,
        angular_acceleration_energy,
    })
}
