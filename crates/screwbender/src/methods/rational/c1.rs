//! The C¹ Chaudhry–Cameron motion (docs/math/rational-motion.md §6): a quadratic quaternion spline from
//! the consistency equations with end condition (18) or (19), rational quartic trajectories.

use glam::{DQuat, DVec3};

use super::segment::{EndCondition, Segment};
use crate::methods::polynomial::Vector;
use crate::methods::triangle::TriangleSample;

/// Middle Bézier control points `M_0 … M_{n−1}` of the C¹ quadratic spline through
/// `values[0..=n]` with knot spacings `h` (docs/math/rational-motion.md §6.1, eqs. 14–19), generic so that the same
/// recursion serves the quaternions and the translation spline `A(t)` of docs/math/rational-motion.md §6.3.
///
/// The consistency equations `h_{i−1} M_i + h_i M_{i−1} = (h_i + h_{i−1}) V_i` are solved by the
/// explicit recursion of the chosen end condition:
/// (18) `M_0 = (V_0 + V_1)/2`, `M_i = V_i + (h_i/h_{i−1})(V_i − M_{i−1})`;
/// (19) `M_{n−1} = (V_{n−1} + V_n)/2`, `M_{i−1} = V_i + (h_{i−1}/h_i)(V_i − M_i)`.
/// Errors are amplified by `h_i/h_{i−1}` per step and never damped (docs/math/rational-motion.md §6.1).
pub(crate) fn quadratic_spline_middles<T: Vector>(
    values: &[T],
    h: &[f64],
    end: EndCondition,
) -> Vec<T> {
    let n = values.len().saturating_sub(1);
    if n == 0 {
        return Vec::new();
    }
    let mut m = vec![values[0]; n];
    match end {
        EndCondition::ZeroCurvatureStart => {
            m[0] = (values[0] + values[1]) * 0.5;
            for i in 1..n {
                m[i] = values[i] + (values[i] - m[i - 1]) * (h[i] / h[i - 1]);
            }
        }
        EndCondition::ZeroCurvatureEnd => {
            m[n - 1] = (values[n - 1] + values[n]) * 0.5;
            for i in (1..n).rev() {
                m[i - 1] = values[i] + (values[i] - m[i]) * (h[i - 1] / h[i]);
            }
        }
    }
    m
}

/// The segments of the C¹ motion (docs/math/rational-motion.md §6.2, §6.3).
///
/// Quaternions: `Q(τ) = (1−τ)²Q_i + 2τ(1−τ)M_i + τ²Q_{i+1}`; weights
/// `(1, Q_i·M_i, (2/3)|M_i|² + (1/3)Q_i·Q_{i+1}, M_i·Q_{i+1}, 1)`. Translation: the rational
/// quartic with these weights and the homogeneous control points
///
/// ```text
/// ω₀c₀ = a_i,   ω₁c₁ = ω₁a_i + h d¹_i/4,
/// ω₂c₂ = ω₂a_i + (4ω₁ − 1) h d¹_i/6 + h² d²_i/12,
/// ω₃c₃ = ω₃a_{i+1} − h d¹_{i+1}/4,   ω₄c₄ = a_{i+1}
/// ```
///
/// where `d¹`, `d²` are the derivatives of the C¹ quadratic spline `A(t)` of the points `a_i` with
/// the same end condition (docs/math/rational-motion.md §6.3 \[choice\]); a motion without rotation gives exactly `A(t)`.
pub(crate) fn segments(
    samples: &[TriangleSample],
    quats: &[DQuat],
    end: EndCondition,
) -> Vec<Segment> {
    let n = samples.len() - 1;
    let h: Vec<f64> = (0..n).map(|i| samples[i + 1].t - samples[i].t).collect();
    let mids = quadratic_spline_middles(quats, &h, end);
    let points: Vec<DVec3> = samples.iter().map(|s| s.a).collect();
    let amid = quadratic_spline_middles(&points, &h, end);
    // d¹_i = A'(t_i), d²_i = A'' on segment i.
    let mut d1: Vec<DVec3> = (0..n)
        .map(|i| (amid[i] - points[i]) * (2.0 / h[i]))
        .collect();
    d1.push((points[n] - amid[n - 1]) * (2.0 / h[n - 1]));
    (0..n)
        .map(|i| {
            let (q0, m, q1) = (quats[i], mids[i], quats[i + 1]);
            let w = [
                q0.length_squared(),
                q0.dot(m),
                (2.0 / 3.0) * m.length_squared() + (1.0 / 3.0) * q0.dot(q1),
                m.dot(q1),
                q1.length_squared(),
            ];
            let hi = h[i];
            let (a0, a1) = (points[i], points[i + 1]);
            let d2 = (a0 - amid[i] * 2.0 + a1) * (2.0 / (hi * hi));
            let numer = [
                a0 * w[0],
                a0 * w[1] + d1[i] * (hi / 4.0),
                a0 * w[2] + d1[i] * ((4.0 * w[1] - 1.0) * hi / 6.0) + d2 * (hi * hi / 12.0),
                a1 * w[3] - d1[i + 1] * (hi / 4.0),
                a1 * w[4],
            ];
            Segment {
                t0: samples[i].t,
                t1: samples[i + 1].t,
                quats: [q0, m, q1],
                weights: w,
                numer,
                degree: 4,
            }
        })
        .collect()
}
