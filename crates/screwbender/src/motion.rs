//! The [`Motion`] trait: what every motion (polyscrew, subdivided polyscrew, comparison method)
//! offers, so the CLI, the page and the metrics treat them alike.

use glam::DVec3;

use crate::pose::Pose;

/// Position, velocity and acceleration of one body point, plus the body's angular velocity and
/// angular acceleration, all in world coordinates and per unit of the motion parameter.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Kinematics {
    /// World position of the body point.
    pub position: DVec3,
    /// Its velocity `dx/du`.
    pub velocity: DVec3,
    /// Its acceleration `d²x/du²`.
    pub acceleration: DVec3,
    /// The body's angular velocity `ω` (world frame; `|ω|` in radians per parameter unit).
    pub angular_velocity: DVec3,
    /// The body's angular acceleration `dω/du`.
    pub angular_acceleration: DVec3,
}

impl Kinematics {
    /// The same kinematics per unit of time under a retiming `u = p(t)` with `u' = du/dt` and
    /// `u'' = d²u/dt²` (chain rule: `v_t = v_u u'`, `a_t = a_u u'² + v_u u''`, likewise for `ω`
    /// and `α`); see [`crate::Timing::parameter_derivatives`].
    pub fn retimed(&self, du: f64, ddu: f64) -> Kinematics {
        Kinematics {
            position: self.position,
            velocity: self.velocity * du,
            acceleration: self.acceleration * (du * du) + self.velocity * ddu,
            angular_velocity: self.angular_velocity * du,
            angular_acceleration: self.angular_acceleration * (du * du)
                + self.angular_velocity * ddu,
        }
    }
}

/// A rigid motion: a pose for every parameter value in its domain.
///
/// Parameters are in *coarse units*: control pose `i` sits at `u = i` unless the method says
/// otherwise (see [`Motion::knots`]).
pub trait Motion {
    /// A short human-readable name of the method (`"polyscrew"`, `"screwbender fourpoint"`, …).
    fn name(&self) -> String;

    /// The parameter interval `[start, end]`. A closed motion is periodic with period
    /// `end − start` and `pose_at(end) = pose_at(start)`.
    fn domain(&self) -> (f64, f64);

    /// Whether the motion is a cycle.
    fn is_closed(&self) -> bool;

    /// The pose at parameter `u`. Closed motions wrap `u` into the domain; open motions
    /// extrapolate their end pieces outside it.
    fn pose_at(&self, u: f64) -> Pose;

    /// The parameters of the control poses (where interpolating methods pass through them and
    /// where velocity jumps are measured).
    fn knots(&self) -> Vec<f64>;

    /// Analytic kinematics of the body point with local coordinates `local` at `u`, when the
    /// method has them in closed form. At a knot the right-hand (next piece's) value is returned.
    fn kinematics_at(&self, _u: f64, _local: DVec3) -> Option<Kinematics> {
        None
    }

    /// Former name of [`Motion::kinematics_at`], kept for one release (every API of the project
    /// calls it `kinematics_at`).
    #[deprecated(since = "0.2.0", note = "renamed to `kinematics_at`")]
    fn kinematics(&self, u: f64, local: DVec3) -> Option<Kinematics> {
        self.kinematics_at(u, local)
    }

    /// `count` poses at uniformly spaced parameters: over `[start, end)` for a closed motion (the
    /// end repeats the start) and over `[start, end]` inclusive for an open one.
    fn sample(&self, count: usize) -> Vec<Pose> {
        let (a, b) = self.domain();
        let denom = if self.is_closed() {
            count as f64
        } else {
            count.saturating_sub(1).max(1) as f64
        };
        (0..count)
            .map(|k| self.pose_at(a + (b - a) * k as f64 / denom))
            .collect()
    }
}
