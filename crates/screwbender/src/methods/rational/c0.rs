//! The C⁰ Chaudhry–Cameron motion (docs/math/rational-motion.md §5): linear quaternion interpolation per
//! segment, rational quadratic trajectories with the common denominator `w = |Q(t)|²`.

use glam::{DQuat, DVec3};

use super::segment::Segment;
use crate::methods::triangle::TriangleSample;

/// The segments of the C⁰ motion through `samples` with the sign-fixed unit quaternions `quats`.
///
/// On segment `i` (docs/math/rational-motion.md §5.2, §5.3): `Q(τ) = (1−τ)Q_i + τQ_{i+1}`, weights `(1, ω_i, 1)` with
/// `ω_i = Q_i·Q_{i+1} ≥ 0`, and the translation `a(t)` rational quadratic with the same weights,
/// end points `a_i`, `a_{i+1}` and start tangent the chord slope `d¹_i = (a_{i+1} − a_i)/h_i`
/// (docs/math/rational-motion.md §5.3 \[choice\]). Its middle control point is stored homogeneously,
/// `ω_i c₁ = ω_i a_i + h_i d¹_i / 2 = ω_i a_i + (a_{i+1} − a_i)/2`, so `ω_i = 0` (a relative half
/// turn between consecutive samples) is harmless.
pub(crate) fn segments(samples: &[TriangleSample], quats: &[DQuat]) -> Vec<Segment> {
    (0..samples.len() - 1)
        .map(|i| {
            let (s0, s1) = (&samples[i], &samples[i + 1]);
            let (q0, q1) = (quats[i], quats[i + 1]);
            let omega = q0.dot(q1);
            let weights = [q0.length_squared(), omega, q1.length_squared(), 0.0, 0.0];
            let numer = [
                s0.a * weights[0],
                s0.a * omega + (s1.a - s0.a) * 0.5,
                s1.a * weights[2],
                DVec3::ZERO,
                DVec3::ZERO,
            ];
            Segment {
                t0: s0.t,
                t1: s1.t,
                quats: [q0, q1, DQuat::IDENTITY],
                weights,
                numer,
                degree: 2,
            }
        })
        .collect()
}
