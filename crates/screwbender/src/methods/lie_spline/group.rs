//! The two Lie groups of rigid poses that the cumulative B-splines run on: SE(3) (rotation and
//! translation coupled, the screw's group) and R³ × SO(3) (origin and rotation apart), with the
//! few operations the spline and its derivative recursion need.
//!
//! SE(3)'s exponential and logarithm are not written again here: the screw from the identity to
//! a pose `D` *is* `exp(t log D)` (docs/math/screw.md §4), so [`Screw`] supplies them with its
//! care near zero angle and its half-turn tie-break, and [`Screw::twist`] the twist `log D`.
//! R³ × SO(3) uses the quaternion exponential and logarithm of [`super::super::algebra`].

use std::ops::{Add, Mul, Neg, Sub};

use glam::{DQuat, DVec3};

use super::super::algebra::{qexp, qlog};
use crate::pose::Pose;
use crate::screw::Screw;

/// An element of the Lie algebra: a body twist (angular part `ω`, linear part `v`).
///
/// On SE(3), `T⁻¹ dT = [ω]× ⊕ v` in the body frame; on R³ × SO(3), `ω` is the body angular
/// velocity and `v` the origin's velocity in world coordinates.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Twist {
    /// Angular part `ω` (radians per parameter unit).
    pub angular: DVec3,
    /// Linear part `v`.
    pub linear: DVec3,
}

impl Twist {
    /// The zero twist.
    pub const ZERO: Twist = Twist {
        angular: DVec3::ZERO,
        linear: DVec3::ZERO,
    };

    /// A twist from its two parts.
    pub const fn new(angular: DVec3, linear: DVec3) -> Twist {
        Twist { angular, linear }
    }

    /// `|ω| + |v|`, the size used for convergence tests.
    pub fn size(&self) -> f64 {
        self.angular.length() + self.linear.length()
    }
}

impl Add for Twist {
    type Output = Twist;
    fn add(self, o: Twist) -> Twist {
        Twist::new(self.angular + o.angular, self.linear + o.linear)
    }
}

impl Sub for Twist {
    type Output = Twist;
    fn sub(self, o: Twist) -> Twist {
        Twist::new(self.angular - o.angular, self.linear - o.linear)
    }
}

impl Neg for Twist {
    type Output = Twist;
    fn neg(self) -> Twist {
        Twist::new(-self.angular, -self.linear)
    }
}

impl Mul<f64> for Twist {
    type Output = Twist;
    fn mul(self, s: f64) -> Twist {
        Twist::new(self.angular * s, self.linear * s)
    }
}

/// A Lie group of rigid poses, each element stored as a [`Pose`] (origin and unit rotation).
pub trait LieGroup: Clone + std::fmt::Debug {
    /// `log(a⁻¹ b)` precomputed so that [`LieGroup::exp`] is cheap.
    type Segment: Clone + Copy + std::fmt::Debug + PartialEq;

    /// Short name of the group for messages (`"SE(3)"`).
    const NAME: &'static str;

    /// The group product `a · b`.
    fn compose(a: &Pose, b: &Pose) -> Pose;

    /// The group inverse.
    fn inverse(a: &Pose) -> Pose;

    /// The segment from `a` to `b`: `Ω = log(a⁻¹ b)` (minimal rotation, angle in `[0, π]`).
    fn segment(a: &Pose, b: &Pose) -> Self::Segment;

    /// `exp(t Ω)` of a segment.
    fn exp(segment: &Self::Segment, t: f64) -> Pose;

    /// The twist `Ω` of a segment.
    fn twist(segment: &Self::Segment) -> Twist;

    /// `Ad(a⁻¹) x`: a twist carried into the frame of `a` (`a⁻¹ X a`).
    fn ad_inverse(a: &Pose, x: Twist) -> Twist;

    /// The Lie bracket `[x, y]`.
    fn bracket(x: Twist, y: Twist) -> Twist;

    /// The origin's velocity and acceleration in world coordinates, from the pose and its body
    /// twist and the twist's derivative.
    fn origin_rates(pose: &Pose, xi: Twist, dxi: Twist) -> (DVec3, DVec3);
}

/// SE(3): poses composed as rigid transforms ([`Pose::compose`]); the spline's pieces are screws.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Se3;

impl LieGroup for Se3 {
    type Segment = Screw;
    const NAME: &'static str = "SE(3)";

    fn compose(a: &Pose, b: &Pose) -> Pose {
        a.compose(b)
    }

    fn inverse(a: &Pose) -> Pose {
        a.inverse()
    }

    fn segment(a: &Pose, b: &Pose) -> Screw {
        Screw::between(&Pose::IDENTITY, &a.inverse().compose(b))
    }

    fn exp(segment: &Screw, t: f64) -> Pose {
        segment.at(t)
    }

    fn twist(segment: &Screw) -> Twist {
        // The screw starts at the identity, so its world twist is the body twist `log D`.
        let (omega, v0) = segment.twist();
        Twist::new(omega, v0)
    }

    fn ad_inverse(a: &Pose, x: Twist) -> Twist {
        // a⁻¹ (ω, v) a = (Rᵀω, Rᵀ(v − p × ω)).
        let rt = a.rotation.conjugate();
        Twist::new(rt * x.angular, rt * (x.linear - a.origin.cross(x.angular)))
    }

    fn bracket(x: Twist, y: Twist) -> Twist {
        Twist::new(
            x.angular.cross(y.angular),
            x.angular.cross(y.linear) - y.angular.cross(x.linear),
        )
    }

    fn origin_rates(pose: &Pose, xi: Twist, dxi: Twist) -> (DVec3, DVec3) {
        // Ȯ = R v, Ö = R (ω × v + v̇).
        let r = pose.rotation;
        (
            r * xi.linear,
            r * (xi.angular.cross(xi.linear) + dxi.linear),
        )
    }
}

/// R³ × SO(3): origins added, rotations multiplied, independently (the "split" spline).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SplitSe3;

/// A segment of R³ × SO(3): the origin difference and the rotation vector of `q_a⁻¹ q_b`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SplitSegment {
    translation: DVec3,
    rotation: DVec3,
}

impl LieGroup for SplitSe3 {
    type Segment = SplitSegment;
    const NAME: &'static str = "R³ × SO(3)";

    fn compose(a: &Pose, b: &Pose) -> Pose {
        Pose::new(a.origin + b.origin, (a.rotation * b.rotation).normalize())
    }

    fn inverse(a: &Pose) -> Pose {
        Pose::new(-a.origin, a.rotation.conjugate())
    }

    fn segment(a: &Pose, b: &Pose) -> SplitSegment {
        let d = a.rotation.conjugate() * b.rotation;
        let d = if d.w < 0.0 { -d } else { d };
        SplitSegment {
            translation: b.origin - a.origin,
            // qlog is the half-angle vector.
            rotation: qlog(d) * 2.0,
        }
    }

    fn exp(segment: &SplitSegment, t: f64) -> Pose {
        let q: DQuat = qexp(segment.rotation * (0.5 * t));
        Pose::new(segment.translation * t, q)
    }

    fn twist(segment: &SplitSegment) -> Twist {
        Twist::new(segment.rotation, segment.translation)
    }

    fn ad_inverse(a: &Pose, x: Twist) -> Twist {
        Twist::new(a.rotation.conjugate() * x.angular, x.linear)
    }

    fn bracket(x: Twist, y: Twist) -> Twist {
        Twist::new(x.angular.cross(y.angular), DVec3::ZERO)
    }

    fn origin_rates(_pose: &Pose, xi: Twist, dxi: Twist) -> (DVec3, DVec3) {
        (xi.linear, dxi.linear)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pose(o: [f64; 3], axis: [f64; 3], angle: f64) -> Pose {
        Pose::new(
            DVec3::from_array(o),
            DQuat::from_axis_angle(DVec3::from_array(axis).normalize(), angle),
        )
    }

    fn round_trip<G: LieGroup>() {
        let a = pose([0.3, -1.0, 2.0], [1.0, 2.0, -0.5], 0.7);
        for b in [
            pose([1.3, 0.4, -0.2], [-0.3, 1.0, 0.2], 2.9),
            pose([0.3, -1.0, 2.0], [1.0, 2.0, -0.5], 0.7 + 1e-11),
            a,
        ] {
            let s = G::segment(&a, &b);
            let end = G::compose(&a, &G::exp(&s, 1.0));
            assert!(end.approx_eq(&b, 1e-13), "{} {end:?} {b:?}", G::NAME);
            let back = G::compose(&G::inverse(&a), &a);
            assert!(back.approx_eq(&Pose::IDENTITY, 1e-15));
        }
    }

    #[test]
    fn exp_of_segment_reaches_its_end() {
        round_trip::<Se3>();
        round_trip::<SplitSe3>();
    }

    /// `Ad(a⁻¹) log D = log(a⁻¹ D a)`: the adjoint carries twists as conjugation carries poses.
    fn adjoint_is_conjugation<G: LieGroup>() {
        let a = pose([0.3, -1.0, 2.0], [1.0, 2.0, -0.5], 0.7);
        let d = pose([1.3, 0.4, -0.2], [-0.3, 1.0, 0.2], 1.9);
        let conjugated = G::compose(&G::compose(&G::inverse(&a), &d), &a);
        let direct = G::twist(&G::segment(&Pose::IDENTITY, &conjugated));
        let ad = G::ad_inverse(&a, G::twist(&G::segment(&Pose::IDENTITY, &d)));
        assert!(
            (direct - ad).size() < 1e-14,
            "{}: {direct:?} vs {ad:?}",
            G::NAME
        );
    }

    #[test]
    fn adjoint_matches_conjugation() {
        adjoint_is_conjugation::<Se3>();
        adjoint_is_conjugation::<SplitSe3>();
    }
}
