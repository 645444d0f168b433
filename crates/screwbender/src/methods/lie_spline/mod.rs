//! Uniform cumulative cubic B-splines on a Lie group of poses (Lovegrove, Patron-Perez & Sibley,
//! *Spline Fusion*, BMVC 2013; Sommer, Usenko, Schubert, Demmel & Cremers, *Efficient Derivative
//! Computation for Cumulative B-Splines on Lie Groups*, CVPR 2020): the spline of robotics and
//! computer vision, on SE(3) ([`Se3BSpline`]) or on R³ × SO(3) ([`SplitBSpline`]).
//!
//! On span `j` (`u = j + f`, `f ∈ [0, 1)`), with control poses `C_k`,
//!
//! ```text
//! T(u) = C_{j−1} · exp(λ₁(f) Ω_j) · exp(λ₂(f) Ω_{j+1}) · exp(λ₃(f) Ω_{j+2}),   Ω_k = log(C_{k−1}⁻¹ C_k),
//! λ₁ = (5 + 3f − 3f² + f³)/6,   λ₂ = (1 + 3f + 3f² − 2f³)/6,   λ₃ = f³/6
//! ```
//!
//! (the cumulative cubic basis). Its body velocity, acceleration and jerk come in closed form from
//! Sommer et al.'s recursion over the three factors `A_i = exp(λ_i Ω_i)`, O(order) per
//! evaluation:
//!
//! ```text
//! ξ⁽ⁱ⁾ = Ad(A_i⁻¹) ξ⁽ⁱ⁻¹⁾ + λ̇_i Ω_i
//! ξ̇⁽ⁱ⁾ = Ad(A_i⁻¹) ξ̇⁽ⁱ⁻¹⁾ + λ̇_i [ξ⁽ⁱ⁾, Ω_i] + λ̈_i Ω_i
//! ξ̈⁽ⁱ⁾ = Ad(A_i⁻¹) ξ̈⁽ⁱ⁻¹⁾ + λ̇_i [Ad(A_i⁻¹) ξ̇⁽ⁱ⁻¹⁾, Ω_i] + λ̈_i [ξ⁽ⁱ⁾, Ω_i] + λ̇_i [ξ̇⁽ⁱ⁾, Ω_i] + λ⃛_i Ω_i
//! ```
//!
//! starting from zero (`d/du (A⁻¹ X A) = [A⁻¹ X A, λ̇ Ω] + A⁻¹ Ẋ A`). The motion is C² (the
//! cumulative basis is that of the uniform cubic B-spline).
//!
//! * **Approximating** ([`LieBSpline::new`]): the given poses are the control poses, as for the
//!   ScrewBender B-spline; the motion passes near, not through, them.
//! * **Interpolating** ([`LieBSpline::interpolating`]): control poses solved so that `T(i)` is
//!   pose `i`. At a knot `T(i) = C_i · E_i` with `E_i = exp(−Ω_i/6) exp(Ω_{i+1}/6)`, so the
//!   iteration `C_i ← C_i · exp(α log(C_i⁻¹ P_i E_i⁻¹))` (all `i` at once, `α = 1.5`) has the
//!   solution as its fixed point; for poses close to each other it is the over-relaxed Jacobi
//!   iteration of the linear B-spline system `(C_{i−1} + 4C_i + C_{i+1})/6 = P_i`, which
//!   contracts by 1/2 per step. The control poses of an interpolating spline lie beyond the poses
//!   (they overshoot them), and each piece turns by less than half a turn (`log` is the minimal
//!   one): where the solution would need two neighbouring control poses half a turn or more apart
//!   — a cycle whose poses turn by about 100° or more from one to the next, such as the closing
//!   span of the `l_cycle_rotated` preset — the iteration cannot converge, and an error says so
//!   (nothing is built).
//! * **Open sequences** get one phantom control pose at each end, reflected along the end span
//!   (`C_{−1} = C_0 exp(−Ω_1)`, `C_n = C_{n−1} exp(Ω_{n−1})`): then `Ω_0 = Ω_1`, and the motion
//!   starts exactly at pose 0 and ends at the last pose over `[0, n − 1]` (the choice of
//!   Kim–Kim–Shin's open ends, carried to the group). Closed sequences wrap with period `n`.
//!
//! On SE(3) every piece is a screw, and the motion does not depend on the choice of the local
//! frame nor of the world frame (conjugating every control pose conjugates every factor). On
//! R³ × SO(3) the rotations are Kim–Kim–Shin's quaternion curve and the origins the cubic
//! B-spline of the control origins, with the same phantom ends: the approximating split spline
//! *is* the motion of [`KimKimShin`](super::KimKimShin) (method `kks`), here with analytic
//! derivatives; a body point off the local origin does not follow a helix.
//!
//! Written here rather than taken from a crate: no maintained Rust crate offers cumulative Lie
//! group B-splines with their derivative recursion on f64 poses (Sophus and basalt are C++), and
//! the group operations reuse the crate's own screw ([`group`]).

pub mod group;

use glam::DVec3;

use super::slerp_polyline::{locate_uniform, validated_poses};
use crate::error::{Error, ErrorKind};
use crate::motion::{Kinematics, Motion};
use crate::pose::Pose;
use group::{LieGroup, Se3, SplitSe3, Twist};

/// The cumulative cubic B-spline on SE(3).
pub type Se3BSpline = LieBSpline<Se3>;

/// The cumulative cubic B-spline on R³ × SO(3).
pub type SplitBSpline = LieBSpline<SplitSe3>;

/// Most iterations of [`LieBSpline::interpolating`] before it reports failure.
pub const MAX_INTERPOLATION_ITERATIONS: usize = 200;

/// [`LieBSpline::interpolating`] stops when every `T(i)` is within this distance
/// ([`Pose::distance`]) of pose `i`, times `max(1, largest |origin|)`.
pub const INTERPOLATION_TOLERANCE: f64 = 1e-13;

/// The relaxation factor `α` of the interpolation iteration (1.5: contraction 1/2 per step in
/// the linear limit, against 2/3 without relaxation).
const RELAXATION: f64 = 1.5;

/// The cumulative cubic basis `λ₁, λ₂, λ₃` at `f` and its first three derivatives.
fn cumulative_basis(f: f64) -> [[f64; 3]; 4] {
    let (f2, f3) = (f * f, f * f * f);
    let g = 1.0 - f;
    [
        [
            (5.0 + 3.0 * f - 3.0 * f2 + f3) / 6.0,
            (1.0 + 3.0 * f + 3.0 * f2 - 2.0 * f3) / 6.0,
            f3 / 6.0,
        ],
        [0.5 * g * g, 0.5 + f - f2, 0.5 * f2],
        [f - 1.0, 1.0 - 2.0 * f, f],
        [1.0, -2.0, 1.0],
    ]
}

/// A uniform cumulative cubic B-spline on the Lie group `G` (see the module documentation).
#[derive(Clone, Debug, PartialEq)]
pub struct LieBSpline<G: LieGroup> {
    /// Control poses: with one phantom at each end (open) or as given (closed).
    controls: Vec<Pose>,
    /// `segments[k] = log(C_{k−1}⁻¹ C_k)`, index aligned with `controls` (`k = 0` wraps when
    /// closed, unused when open).
    segments: Vec<G::Segment>,
    /// Number of given poses.
    count: usize,
    closed: bool,
    interpolating: bool,
}

/// A pose of the spline with its body velocity, acceleration and jerk ([`LieBSpline::derivatives`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BodyDerivatives {
    /// The pose `T(u)`.
    pub pose: Pose,
    /// The body twist `T⁻¹ dT/du` (on R³ × SO(3): body angular velocity, world origin velocity).
    pub velocity: Twist,
    /// Its derivative.
    pub acceleration: Twist,
    /// Its second derivative.
    pub jerk: Twist,
}

impl<G: LieGroup> LieBSpline<G> {
    /// The approximating spline with `poses` as control poses (control pose `i` near `u = i`).
    /// Needs at least 2 valid poses.
    pub fn new(poses: &[Pose], closed: bool) -> Result<LieBSpline<G>, Error> {
        let poses = validated_poses(poses, closed)?;
        Ok(LieBSpline::from_controls(&poses, closed, false))
    }

    /// The interpolating spline: control poses solved so that the motion is at pose `i` at
    /// `u = i` (within [`INTERPOLATION_TOLERANCE`]). Errors name `poses` when the iteration does
    /// not converge in [`MAX_INTERPOLATION_ITERATIONS`] steps (poses turning too far between
    /// neighbours).
    pub fn interpolating(poses: &[Pose], closed: bool) -> Result<LieBSpline<G>, Error> {
        let poses = validated_poses(poses, closed)?;
        let n = poses.len();
        let scale = poses
            .iter()
            .fold(1.0f64, |m, p| m.max(p.origin.abs().max_element()));
        let tolerance = INTERPOLATION_TOLERANCE * scale;
        // Open sequences: the ends pass through their poses by construction (see above).
        let free = if closed { 0..n } else { 1..n.saturating_sub(1) };
        let mut controls = poses.clone();
        let mut worst = f64::INFINITY;
        for _ in 0..MAX_INTERPOLATION_ITERATIONS {
            let spline = LieBSpline::<G>::from_controls(&controls, closed, true);
            worst = 0.0f64;
            let mut next = controls.clone();
            for i in free.clone() {
                let at = spline.pose_at(i as f64);
                let d = at.distance(&poses[i]);
                worst = if d.is_nan() {
                    f64::INFINITY
                } else {
                    worst.max(d)
                };
                let c = &controls[i];
                let e = G::compose(&G::inverse(c), &at);
                let target = G::compose(&poses[i], &G::inverse(&e));
                next[i] = G::compose(c, &G::exp(&G::segment(c, &target), RELAXATION));
            }
            if worst <= tolerance {
                return Ok(spline);
            }
            if !worst.is_finite() {
                break;
            }
            controls = next;
        }
        Err(Error::new(
            "poses",
            ErrorKind::Unsupported {
                reason: format!(
                    "the interpolating {} B-spline found no control poses through these poses \
                     ({MAX_INTERPOLATION_ITERATIONS} iterations left a distance of {worst:.3e}): \
                     a solution needs neighbouring control poses half a turn or more apart; add \
                     poses between those that turn most",
                    G::NAME
                ),
            },
        ))
    }

    fn from_controls(poses: &[Pose], closed: bool, interpolating: bool) -> LieBSpline<G> {
        let n = poses.len();
        let mut controls = poses.to_vec();
        if !closed {
            let first = G::segment(&poses[0], &poses[1]);
            let last = G::segment(&poses[n - 2], &poses[n - 1]);
            controls.insert(0, G::compose(&poses[0], &G::exp(&first, -1.0)));
            controls.push(G::compose(&poses[n - 1], &G::exp(&last, 1.0)));
        }
        let m = controls.len();
        let segments = (0..m)
            .map(|k| G::segment(&controls[(k + m - 1) % m], &controls[k]))
            .collect();
        LieBSpline {
            controls,
            segments,
            count: n,
            closed,
            interpolating,
        }
    }

    /// The control poses (for an open spline without the two phantoms).
    pub fn control_poses(&self) -> &[Pose] {
        if self.closed {
            &self.controls
        } else {
            &self.controls[1..self.controls.len() - 1]
        }
    }

    /// Replaces control pose `i` (an index into [`LieBSpline::control_poses`]) and updates only
    /// what depends on it: the up to three segments around it and, near an open end, the phantom
    /// control pose reflected from it. The result equals [`LieBSpline::new`] on the changed
    /// poses; fitting perturbs one control pose at a time, so a rebuild would cost O(n) where
    /// this costs O(1). `pose` must be a valid pose (unit rotation, finite).
    pub(crate) fn set_control_pose(&mut self, i: usize, pose: Pose) {
        let n = self.count;
        let m = self.controls.len();
        let stored = if self.closed { i } else { i + 1 };
        self.controls[stored] = pose;
        let mut touched = [stored, (stored + 1) % m, usize::MAX, usize::MAX];
        if !self.closed {
            if i <= 1 {
                let first = G::segment(&self.controls[1], &self.controls[2]);
                self.controls[0] = G::compose(&self.controls[1], &G::exp(&first, -1.0));
                touched[2] = 1;
            }
            if i + 2 >= n {
                let last = G::segment(&self.controls[n - 1], &self.controls[n]);
                self.controls[n + 1] = G::compose(&self.controls[n], &G::exp(&last, 1.0));
                touched[3] = m - 1;
            }
        }
        for k in touched.into_iter().filter(|&k| k < m) {
            self.segments[k] = G::segment(&self.controls[(k + m - 1) % m], &self.controls[k]);
        }
        // Segment 0 (the wrap) is read only by closed splines; an open one keeps it as built.
        if !self.closed {
            self.segments[0] = G::segment(&self.controls[m - 1], &self.controls[0]);
        }
    }

    /// Whether the control poses were solved to pass through the given poses.
    pub fn is_interpolating(&self) -> bool {
        self.interpolating
    }

    fn spans(&self) -> usize {
        self.count - usize::from(!self.closed)
    }

    /// The span and fraction of `u`, and the stored indices of its four control poses.
    fn window(&self, u: f64) -> (f64, [usize; 4]) {
        let (j, f) = locate_uniform(u, self.spans(), self.closed);
        let idx = |d: isize| -> usize {
            if self.closed {
                (j as isize + d).rem_euclid(self.count as isize) as usize
            } else {
                (j as isize + 1 + d) as usize
            }
        };
        (f, [idx(-1), idx(0), idx(1), idx(2)])
    }

    /// The pose at `u` with its body velocity, acceleration and jerk per parameter unit
    /// (Sommer et al.'s recursion, see the module documentation).
    pub fn derivatives(&self, u: f64) -> BodyDerivatives {
        let (f, k) = self.window(u);
        let b = cumulative_basis(f);
        let mut pose = self.controls[k[0]];
        let (mut xi, mut dxi, mut ddxi) = (Twist::ZERO, Twist::ZERO, Twist::ZERO);
        for i in 0..3 {
            let segment = &self.segments[k[i + 1]];
            let a = G::exp(segment, b[0][i]);
            let omega = G::twist(segment);
            let (l1, l2, l3) = (b[1][i], b[2][i], b[3][i]);
            let carried_dxi = G::ad_inverse(&a, dxi);
            xi = G::ad_inverse(&a, xi) + omega * l1;
            let next_dxi = carried_dxi + G::bracket(xi, omega) * l1 + omega * l2;
            ddxi = G::ad_inverse(&a, ddxi)
                + G::bracket(carried_dxi, omega) * l1
                + G::bracket(xi, omega) * l2
                + G::bracket(next_dxi, omega) * l1
                + omega * l3;
            dxi = next_dxi;
            pose = G::compose(&pose, &a);
        }
        BodyDerivatives {
            pose,
            velocity: xi,
            acceleration: dxi,
            jerk: ddxi,
        }
    }
}

impl<G: LieGroup> Motion for LieBSpline<G> {
    fn name(&self) -> String {
        let kind = if self.interpolating {
            ", interpolating"
        } else {
            ""
        };
        format!("{} cumulative b-spline{kind}", G::NAME)
    }

    fn domain(&self) -> (f64, f64) {
        (0.0, self.spans() as f64)
    }

    fn is_closed(&self) -> bool {
        self.closed
    }

    fn pose_at(&self, u: f64) -> Pose {
        let (f, k) = self.window(u);
        let b = cumulative_basis(f)[0];
        let mut pose = self.controls[k[0]];
        for i in 0..3 {
            pose = G::compose(&pose, &G::exp(&self.segments[k[i + 1]], b[i]));
        }
        pose
    }

    fn knots(&self) -> Vec<f64> {
        (0..self.count).map(|i| i as f64).collect()
    }

    fn kinematics_at(&self, u: f64, local: DVec3) -> Option<Kinematics> {
        let d = self.derivatives(u);
        let r = d.pose.rotation;
        let (w, dw) = (d.velocity.angular, d.acceleration.angular);
        let (o1, o2) = G::origin_rates(&d.pose, d.velocity, d.acceleration);
        Some(Kinematics {
            position: d.pose.transform_point(local),
            velocity: o1 + r * w.cross(local),
            acceleration: o2 + r * (dw.cross(local) + w.cross(w.cross(local))),
            angular_velocity: r * w,
            angular_acceleration: r * dw,
        })
    }
}
