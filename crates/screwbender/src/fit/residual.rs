//! How far a fitted motion is from the measured poses: the residual of one sample that the solver
//! minimises, and the report of all of them that the user reads.

use glam::DVec3;

use crate::methods::qlog;
use crate::pose::Pose;

/// The residual of a fitted pose against a measured one: the origin's offset (3 entries) and the
/// rotation vector of `R_measured⁻¹ R_fitted` times `radius` (3 entries), both in scene units.
pub(crate) fn residual(fitted: &Pose, measured: &Pose, radius: f64) -> [f64; 6] {
    let d = fitted.origin - measured.origin;
    let r = rotation_vector(measured, fitted) * radius;
    [d.x, d.y, d.z, r.x, r.y, r.z]
}

/// The rotation vector (axis × angle, angle in `[0, π]`) that turns `a`'s rotation into `b`'s,
/// in `a`'s frame.
pub(crate) fn rotation_vector(a: &Pose, b: &Pose) -> DVec3 {
    let q = a.rotation.conjugate() * b.rotation;
    let q = if q.w < 0.0 { -q } else { q };
    // qlog is the half-angle vector.
    qlog(q) * 2.0
}

/// `pose · exp(δ)` on R³ × SO(3) in the body frame: `δ = [ω, v]` turns the pose by the rotation
/// vector `ω` and moves its origin by `v` along its own axes. The solver's coordinates around
/// each control pose.
pub(crate) fn retract(pose: &Pose, delta: &[f64]) -> Pose {
    let w = DVec3::new(delta[0], delta[1], delta[2]);
    let v = DVec3::new(delta[3], delta[4], delta[5]);
    Pose::new(
        pose.origin + pose.rotation * v,
        (pose.rotation * crate::methods::qexp(w * 0.5)).normalize(),
    )
}

/// The residuals of a fit ([`fit_poses`](super::fit_poses)): how far the fitted motion is from
/// each measured pose at its time, over all samples (outliers included).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FitReport {
    /// Number of control poses of the fitted motion.
    pub controls: usize,
    /// Number of measured poses.
    pub samples: usize,
    /// Root mean square of the origins' distances (scene units).
    pub rms_position: f64,
    /// Largest origin distance (scene units).
    pub max_position: f64,
    /// Root mean square of the rotation angles between fitted and measured poses (radians).
    pub rms_angle: f64,
    /// Largest rotation angle (radians).
    pub max_angle: f64,
    /// Root mean square of the deviation `distance + radius · angle` (scene units), the measure
    /// of a tolerance ([`ControlCount::Tolerance`](super::ControlCount::Tolerance)) and of
    /// `reduce_poses`.
    pub rms_deviation: f64,
    /// Largest deviation (scene units).
    pub max_deviation: f64,
    /// Gauss–Newton iterations taken (both stages when a robust loss is used).
    pub iterations: usize,
}

impl FitReport {
    /// The report of fitted poses `fitted[i]` against `measured[i]`.
    pub(crate) fn measure(
        fitted: impl Iterator<Item = Pose>,
        measured: &[Pose],
        radius: f64,
        controls: usize,
        iterations: usize,
    ) -> FitReport {
        let (mut p2, mut pmax, mut a2, mut amax, mut d2, mut dmax) =
            (0.0, 0.0f64, 0.0, 0.0f64, 0.0, 0.0f64);
        for (f, m) in fitted.zip(measured) {
            let p = f.origin.distance(m.origin);
            let a = rotation_vector(m, &f).length();
            let d = p + radius * a;
            p2 += p * p;
            a2 += a * a;
            d2 += d * d;
            pmax = pmax.max(p);
            amax = amax.max(a);
            dmax = dmax.max(d);
        }
        let n = measured.len().max(1) as f64;
        FitReport {
            controls,
            samples: measured.len(),
            rms_position: (p2 / n).sqrt(),
            max_position: pmax,
            rms_angle: (a2 / n).sqrt(),
            max_angle: amax,
            rms_deviation: (d2 / n).sqrt(),
            max_deviation: dmax,
            iterations,
        }
    }
}
