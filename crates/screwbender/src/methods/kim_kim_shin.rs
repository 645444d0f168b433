//! Kim, Kim & Shin's cumulative B-spline quaternion curve (*A General Construction Scheme for
//! Unit Quaternion Curves with Simple High Order Derivatives*, SIGGRAPH 1995), with uniform cubic
//! B-spline positions.

use glam::{DQuat, DVec3};

use super::algebra::{qexp, qlog};
use super::slerp_polyline::{locate_uniform, validated_poses};
use crate::error::Error;
use crate::motion::Motion;
use crate::pose::Pose;

/// Uniform cubic B-spline motion, decoupled: origins by the cubic B-spline of the control origins,
/// rotations by the cumulative-basis B-spline quaternion curve
///
/// ```text
/// q(u) = q_{j−1} exp(ω_j B̃₁(f)) exp(ω_{j+1} B̃₂(f)) exp(ω_{j+2} B̃₃(f)),   u = j + f,
/// ω_k = log(q_{k−1}⁻¹ q_k)   (shorter arc),
/// B̃₁ = (5 + 3f − 3f² + f³)/6,  B̃₂ = (1 + 3f + 3f² − 2f³)/6,  B̃₃ = f³/6
/// ```
///
/// which is C² on the unit sphere and reduces to the B-spline for rotations about one axis.
/// Approximating, like the ScrewBender B-spline: the motion at `u = i` is near, not at, pose `i`.
/// Open sequences get phantom end keys extrapolated along the end spans (`2P_0 − P_1` and
/// `q_0 q_1⁻¹ q_0`, likewise at the end), so the motion starts at pose 0 and ends at the last
/// pose, over `[0, n − 1]`; closed ones wrap with period `n`.
#[derive(Clone, Debug, PartialEq)]
pub struct KimKimShin {
    /// Control origins with one phantom at each end (open) or as given (closed).
    origins: Vec<DVec3>,
    /// Control rotations, likewise.
    rotations: Vec<DQuat>,
    /// `ω_k = log(q_{k−1}⁻¹ q_k)`, index aligned with `rotations` (`ω_0` unused when open).
    omegas: Vec<DVec3>,
    count: usize,
    closed: bool,
}

fn relative_log(a: DQuat, b: DQuat) -> DVec3 {
    let d = a.conjugate() * b;
    qlog(if d.w < 0.0 { -d } else { d })
}

impl KimKimShin {
    /// The motion from `poses` (control pose `i` near `u = i`). Needs at least 2 valid poses.
    pub fn new(poses: &[Pose], closed: bool) -> Result<KimKimShin, Error> {
        let poses = validated_poses(poses, closed)?;
        let n = poses.len();
        let mut origins: Vec<DVec3> = poses.iter().map(|p| p.origin).collect();
        let mut rotations: Vec<DQuat> = poses.iter().map(|p| p.rotation).collect();
        if !closed {
            let (o0, o1) = (origins[0], origins[1]);
            let (oa, ob) = (origins[n - 2], origins[n - 1]);
            let (q0, q1) = (rotations[0], rotations[1]);
            let (qa, qb) = (rotations[n - 2], rotations[n - 1]);
            origins.insert(0, o0 * 2.0 - o1);
            origins.push(ob * 2.0 - oa);
            rotations.insert(0, (q0 * qexp(-relative_log(q0, q1))).normalize());
            rotations.push((qb * qexp(relative_log(qa, qb))).normalize());
        }
        let m = rotations.len();
        let omegas = (0..m)
            .map(|k| {
                if k == 0 && !closed {
                    DVec3::ZERO
                } else {
                    relative_log(rotations[(k + m - 1) % m], rotations[k])
                }
            })
            .collect();
        Ok(KimKimShin {
            origins,
            rotations,
            omegas,
            count: n,
            closed,
        })
    }

    fn spans(&self) -> usize {
        self.count - usize::from(!self.closed)
    }

    /// Control index of `j + d` (window offset `d ∈ −1..=2`) in the stored arrays.
    fn idx(&self, j: usize, d: isize) -> usize {
        if self.closed {
            let m = self.count as isize;
            (j as isize + d).rem_euclid(m) as usize
        } else {
            // Stored arrays are shifted by the front phantom.
            (j as isize + 1 + d) as usize
        }
    }
}

/// Uniform cubic B-spline basis on one segment.
fn basis(f: f64) -> [f64; 4] {
    let (f2, f3) = (f * f, f * f * f);
    let s = 1.0 - f;
    [
        s * s * s / 6.0,
        (3.0 * f3 - 6.0 * f2 + 4.0) / 6.0,
        (-3.0 * f3 + 3.0 * f2 + 3.0 * f + 1.0) / 6.0,
        f3 / 6.0,
    ]
}

impl Motion for KimKimShin {
    fn name(&self) -> String {
        "kim-kim-shin b-spline".into()
    }

    fn domain(&self) -> (f64, f64) {
        (0.0, self.spans() as f64)
    }

    fn is_closed(&self) -> bool {
        self.closed
    }

    fn pose_at(&self, u: f64) -> Pose {
        let (j, f) = locate_uniform(u, self.spans(), self.closed);
        let b = basis(f);
        let k: [usize; 4] = [
            self.idx(j, -1),
            self.idx(j, 0),
            self.idx(j, 1),
            self.idx(j, 2),
        ];
        let origin = self.origins[k[0]] * b[0]
            + self.origins[k[1]] * b[1]
            + self.origins[k[2]] * b[2]
            + self.origins[k[3]] * b[3];
        let c1 = b[1] + b[2] + b[3];
        let c2 = b[2] + b[3];
        let c3 = b[3];
        let q = self.rotations[k[0]]
            * qexp(self.omegas[k[1]] * c1)
            * qexp(self.omegas[k[2]] * c2)
            * qexp(self.omegas[k[3]] * c3);
        Pose::new(origin, q.normalize())
    }

    fn knots(&self) -> Vec<f64> {
        (0..self.count).map(|i| i as f64).collect()
    }
}
