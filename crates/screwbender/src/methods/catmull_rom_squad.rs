//! The decoupled smooth method: Catmull–Rom positions and a Squad quaternion spline (Shoemake),
//! with sign canonicalisation.

use glam::{DQuat, DVec3};

use super::algebra::{align, qexp, qlog, slerp_raw};
use super::positions::CatmullRom;
use super::slerp_polyline::{locate_uniform, validated_poses};
use crate::error::Error;
use crate::motion::Motion;
use crate::pose::Pose;

/// Origins by uniform [`CatmullRom`] interpolation, rotations by Squad:
///
/// ```text
/// squad(q_i, q_{i+1}, s_i, s_{i+1}, f) = slerp(slerp(q_i, q_{i+1}, f), slerp(s_i, s_{i+1}, f), 2f(1−f))
/// s_i = q_i exp(−(log(q_i⁻¹ q_{i+1}) + log(q_i⁻¹ q_{i−1})) / 4)
/// ```
///
/// Signs are canonicalised: every neighbour is taken on the shorter arc from `q_i` (`±q`), so a
/// closed cycle whose quaternions return to `−q_0` is handled. Open ends use `s_0 = q_0`,
/// `s_{n−1} = q_{n−1}` (equivalent to reflected phantom keys). The orientation is C¹ at the
/// poses (uniform parameter), the origins C¹; both are interpolating. Position and orientation
/// are interpolated independently: the motion depends on the choice of the local origin.
#[derive(Clone, Debug, PartialEq)]
pub struct DecoupledSmooth {
    poses: Vec<Pose>,
    inner: Vec<DQuat>,
    positions: CatmullRom,
    closed: bool,
}

impl DecoupledSmooth {
    /// The motion through `poses` (pose `i` at `u = i`). Needs at least 2 valid poses.
    pub fn new(poses: &[Pose], closed: bool) -> Result<DecoupledSmooth, Error> {
        let poses = validated_poses(poses, closed)?;
        let n = poses.len();
        let q: Vec<DQuat> = poses.iter().map(|p| p.rotation).collect();
        let inner = (0..n)
            .map(|i| {
                let has_prev = closed || i > 0;
                let has_next = closed || i + 1 < n;
                if !(has_prev && has_next) {
                    return q[i];
                }
                let qi = q[i];
                let prev = align(qi, q[(i + n - 1) % n]);
                let next = align(qi, q[(i + 1) % n]);
                let inv = qi.conjugate();
                let t = (qlog(inv * next) + qlog(inv * prev)) * -0.25;
                (qi * qexp(t)).normalize()
            })
            .collect();
        let times: Vec<f64> = (0..n + usize::from(closed)).map(|i| i as f64).collect();
        let origins: Vec<DVec3> = poses.iter().map(|p| p.origin).collect();
        Ok(DecoupledSmooth {
            positions: CatmullRom::new(&times, &origins, closed)?,
            poses,
            inner,
            closed,
        })
    }

    fn spans(&self) -> usize {
        self.poses.len() - usize::from(!self.closed)
    }

    /// The rotation at `u` (Squad).
    pub fn rotation(&self, u: f64) -> DQuat {
        let (i, f) = locate_uniform(u, self.spans(), self.closed);
        let j = (i + 1) % self.poses.len();
        let (qi, si) = (self.poses[i].rotation, self.inner[i]);
        let (mut qj, mut sj) = (self.poses[j].rotation, self.inner[j]);
        if qi.dot(qj) < 0.0 {
            qj = -qj;
            sj = -sj;
        }
        slerp_raw(
            slerp_raw(qi, qj, f),
            slerp_raw(si, sj, f),
            2.0 * f * (1.0 - f),
        )
        .normalize()
    }
}

impl Motion for DecoupledSmooth {
    fn name(&self) -> String {
        "decoupled catmull-rom + squad".into()
    }

    fn domain(&self) -> (f64, f64) {
        (0.0, self.spans() as f64)
    }

    fn is_closed(&self) -> bool {
        self.closed
    }

    fn pose_at(&self, u: f64) -> Pose {
        Pose::new(self.positions.eval(u).0, self.rotation(u))
    }

    fn knots(&self) -> Vec<f64> {
        (0..self.poses.len()).map(|i| i as f64).collect()
    }
}
