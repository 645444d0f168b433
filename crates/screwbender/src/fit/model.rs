//! The two motions a fit produces, behind the two things the solver asks of them: the pose at a
//! parameter, and one control pose replaced in place. The Jacobian perturbs one control pose at
//! a time, so both replace it locally (the subdivision re-runs only the window the pose reaches,
//! the Lie spline recomputes the segments beside it) rather than rebuilding the whole motion.

use crate::closure::Closure;
use crate::error::{Error, ErrorKind};
use crate::methods::Se3BSpline;
use crate::motion::Motion;
use crate::pose::Pose;
use crate::screwbender::ScrewBender;
use crate::subdivision::scheme::{Rules, Scheme};
use crate::subdivision::Subdivision;

/// Subdivision levels of the fitted ScrewBender motion while fitting: the refined polyscrew
/// then has 64 spans per control span, and its poses differ from the limit motion's by far
/// less than any measurement noise.
pub const FIT_LEVELS: u32 = 6;

/// Which smooth motion [`fit_poses`](super::fit_poses) fits: both are cubic B-splines whose
/// control pose `k` sits at `u = k`, each sample touching four control poses.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FitMethod {
    /// ScrewBender's cubic B-spline scheme with the direct rules (open sequence), evaluated on
    /// its polyscrew refined [`FIT_LEVELS`] times.
    ScrewBender,
    /// The cumulative cubic B-spline on SE(3) (registry id `se3bspline`).
    Se3BSpline,
}

impl FitMethod {
    /// The ids of the methods, as the command line, JavaScript and Python spell them.
    pub const NAMES: &'static str = "screwbender, se3bspline";

    /// The method named `name` (`screwbender` or `se3bspline`); errors name `method`.
    pub fn from_name(name: &str) -> Result<FitMethod, Error> {
        match name {
            "screwbender" => Ok(FitMethod::ScrewBender),
            "se3bspline" => Ok(FitMethod::Se3BSpline),
            _ => Err(Error::new(
                "method",
                ErrorKind::UnknownValue {
                    value: name.into(),
                    expected: FitMethod::NAMES,
                },
            )),
        }
    }

    /// The id of the method (`screwbender` or `se3bspline`).
    pub fn name(self) -> &'static str {
        match self {
            FitMethod::ScrewBender => "screwbender",
            FitMethod::Se3BSpline => "se3bspline",
        }
    }
}

/// A motion being fitted.
#[derive(Clone, Debug)]
pub(crate) enum Model {
    ScrewBender(ScrewBender),
    Se3(Se3BSpline),
}

impl Model {
    /// The open motion of `method` with `controls` as its control poses (at least 2).
    pub(crate) fn build(method: FitMethod, controls: &[Pose]) -> Result<Model, Error> {
        Ok(match method {
            FitMethod::ScrewBender => Model::ScrewBender(ScrewBender::new(
                controls.to_vec(),
                Closure::Open,
                Subdivision::new(Scheme::BSpline, Rules::Direct, FIT_LEVELS),
            )?),
            FitMethod::Se3BSpline => Model::Se3(Se3BSpline::new(controls, false)?),
        })
    }

    /// The pose at `u` (control pose `k` near `u = k`).
    pub(crate) fn pose_at(&self, u: f64) -> Pose {
        match self {
            Model::ScrewBender(m) => m.pose_at(u),
            Model::Se3(m) => m.pose_at(u),
        }
    }

    /// Replaces control pose `k` by the valid pose `pose`.
    pub(crate) fn set_control_pose(&mut self, k: usize, pose: Pose) {
        match self {
            Model::ScrewBender(m) => {
                // A unit, finite pose at an index in range: the update cannot fail.
                let _ = m.set_control_pose(k, pose);
            }
            Model::Se3(m) => m.set_control_pose(k, pose),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::{DQuat, DVec3};

    fn controls(n: usize) -> Vec<Pose> {
        (0..n)
            .map(|i| {
                let a = i as f64 * 0.6;
                Pose::new(
                    DVec3::new(3.0 * a.cos(), 2.0 * a.sin(), 0.3 * a),
                    DQuat::from_axis_angle(DVec3::new(0.3, 1.0, 0.5).normalize(), a),
                )
            })
            .collect()
    }

    /// The solver evaluates only the spans `k − 2 … k + 1` after moving control pose `k`: the
    /// local replacement must equal a rebuild there, and leave every other span unchanged.
    #[test]
    fn a_replaced_control_pose_reaches_only_its_spans_and_equals_a_rebuild() {
        let n = 9;
        let moved = Pose::new(
            DVec3::new(0.4, -1.0, 2.0),
            DQuat::from_axis_angle(DVec3::X, 0.4),
        );
        for method in [FitMethod::ScrewBender, FitMethod::Se3BSpline] {
            for k in [0, 1, 4, n - 2, n - 1] {
                let c = controls(n);
                let base = Model::build(method, &c).unwrap();
                let mut local = base.clone();
                local.set_control_pose(k, moved);
                let mut changed = c.clone();
                changed[k] = moved;
                let rebuilt = Model::build(method, &changed).unwrap();
                for step in 0..=((n - 1) * 16) {
                    let u = step as f64 / 16.0;
                    let (a, b) = (local.pose_at(u), rebuilt.pose_at(u));
                    assert!(a.approx_eq(&b, 1e-12), "{method:?} k={k} u={u}");
                    let span = (u.floor() as usize).min(n - 2);
                    if span + 2 < k || span > k + 1 {
                        assert_eq!(a, base.pose_at(u), "{method:?} k={k} u={u} moved");
                    }
                }
            }
        }
    }

    #[test]
    fn methods_are_named_by_their_ids() {
        for m in [FitMethod::ScrewBender, FitMethod::Se3BSpline] {
            assert_eq!(FitMethod::from_name(m.name()), Ok(m));
        }
        assert_eq!(FitMethod::from_name("slerp").unwrap_err().path(), "method");
    }
}
