//! The decoupled polyline: piecewise SLERP of the rotations and linear interpolation of the
//! origins (the classical "interpolate position and orientation separately" baseline).

use glam::{DQuat, DVec3};

use super::algebra::align;
use crate::error::Error;
use crate::motion::{Kinematics, Motion};
use crate::polyscrew::Polyscrew;
use crate::pose::Pose;

/// Validates poses like [`Polyscrew::new`] (at least 2, finite, unit rotations within
/// [`crate::UNIT_QUATERNION_TOLERANCE`], renormalised) and returns them.
pub(crate) fn validated_poses(poses: &[Pose], closed: bool) -> Result<Vec<Pose>, Error> {
    Ok(Polyscrew::new(poses.to_vec(), closed)?.poses().to_vec())
}

/// Span index and fraction for a uniformly parameterised motion with `spans` spans (pose `i` at
/// `u = i`): closed motions wrap, open ones extrapolate their end spans.
pub(crate) fn locate_uniform(u: f64, spans: usize, closed: bool) -> (usize, f64) {
    let n = spans as f64;
    if closed {
        let x = if u.is_finite() { u.rem_euclid(n) } else { u };
        let i = if x.is_finite() {
            (x.floor() as usize).min(spans - 1)
        } else {
            0
        };
        (i, x - i as f64)
    } else {
        let i = if u.is_nan() {
            0
        } else {
            u.floor().clamp(0.0, n - 1.0) as usize
        };
        (i, u - i as f64)
    }
}

/// Piecewise SLERP with linear translation: on span `i`, `R(f) = slerp(R_i, R_{i+1}, f)` on the
/// shorter arc and `O(f) = (1−f) O_i + f O_{i+1}` — decoupled, so unlike the polyscrew a body
/// point off the origin does not move on a helix, and the result depends on the choice of the
/// local origin. C⁰ at the poses.
#[derive(Clone, Debug, PartialEq)]
pub struct SlerpPolyline {
    poses: Vec<Pose>,
    closed: bool,
}

impl SlerpPolyline {
    /// The motion through `poses` (pose `i` at `u = i`). Needs at least 2 valid poses.
    pub fn new(poses: &[Pose], closed: bool) -> Result<SlerpPolyline, Error> {
        Ok(SlerpPolyline {
            poses: validated_poses(poses, closed)?,
            closed,
        })
    }

    fn spans(&self) -> usize {
        self.poses.len() - usize::from(!self.closed)
    }

    fn span(&self, i: usize) -> (Pose, Pose) {
        let a = self.poses[i];
        let mut b = self.poses[(i + 1) % self.poses.len()];
        b.rotation = align(a.rotation, b.rotation);
        (a, b)
    }
}

impl Motion for SlerpPolyline {
    fn name(&self) -> String {
        "slerp polyline".into()
    }

    fn domain(&self) -> (f64, f64) {
        (0.0, self.spans() as f64)
    }

    fn is_closed(&self) -> bool {
        self.closed
    }

    fn pose_at(&self, u: f64) -> Pose {
        let (i, f) = locate_uniform(u, self.spans(), self.closed);
        let (a, b) = self.span(i);
        Pose::new(
            a.origin.lerp(b.origin, f),
            slerp_extrapolating(a.rotation, b.rotation, f),
        )
    }

    fn knots(&self) -> Vec<f64> {
        (0..self.poses.len()).map(|i| i as f64).collect()
    }

    /// On a span the world angular velocity is the constant rotation vector `ω` of
    /// `R_{i+1} R_iᵀ`, the origin velocity the chord `O_{i+1} − O_i`; a body point at `r = x − O`
    /// moves with `O' + ω × r` and accelerates with `ω × (ω × r)`.
    fn kinematics_at(&self, u: f64, local: DVec3) -> Option<Kinematics> {
        let (i, f) = locate_uniform(u, self.spans(), self.closed);
        let (a, b) = self.span(i);
        let omega = (b.rotation * a.rotation.conjugate()).to_scaled_axis();
        let q = slerp_extrapolating(a.rotation, b.rotation, f);
        let r = q * local;
        let v0 = b.origin - a.origin;
        Some(Kinematics {
            position: a.origin.lerp(b.origin, f) + r,
            velocity: v0 + omega.cross(r),
            acceleration: omega.cross(omega.cross(r)),
            angular_velocity: omega,
            angular_acceleration: DVec3::ZERO,
        })
    }
}

/// `a (a⁻¹ b)^f` for any real `f` (glam's slerp is exact for `f` outside `[0, 1]` too, but
/// written out here so extrapolation is explicit): the rotation vector of `b a⁻¹`, scaled.
fn slerp_extrapolating(a: DQuat, b: DQuat, f: f64) -> DQuat {
    let d = b * a.conjugate();
    (DQuat::from_scaled_axis(d.to_scaled_axis() * f) * a).normalize()
}
