//! The ScrewBender motion: control poses smoothed by screw subdivision.

use glam::DVec3;

use crate::error::{Error, ErrorKind};
use crate::motion::{Kinematics, Motion};
use crate::polyscrew::{checked_pose, Polyscrew};
use crate::pose::Pose;
use crate::subdivision::Subdivision;

/// A control polyscrew refined by [`Subdivision`]: the paper's smooth motion.
///
/// The refined polyscrew has span length `2^−levels`, so control pose `i` stays at parameter
/// `u = i` (coarse units) for every level, and open motions cover exactly `[0, m − 1]`.
#[derive(Clone, Debug, PartialEq)]
pub struct ScrewBender {
    control: Vec<Pose>,
    closed: bool,
    subdivision: Subdivision,
    refined: Polyscrew,
}

impl ScrewBender {
    /// Subdivides `control` (at least 2 poses) with `subdivision`.
    pub fn new(
        control: Vec<Pose>,
        closed: bool,
        subdivision: Subdivision,
    ) -> Result<ScrewBender, Error> {
        // Validate the control poses first so errors name them, not refined poses.
        let control = Polyscrew::new(control, closed)?.poses().to_vec();
        let poses = subdivision.apply(&control, closed)?;
        let h = 0.5f64.powi(subdivision.levels as i32);
        // Unreachable for validated poses and options (they cannot overflow); named if it happens.
        let refined =
            Polyscrew::with_span_length(poses, closed, h).map_err(|e| e.within("refined"))?;
        Ok(ScrewBender {
            control,
            closed,
            subdivision,
            refined,
        })
    }

    /// Replaces control pose `i` and re-subdivides only the part of the motion it influences
    /// (2 coarse spans on each side for the B-spline, 3 for the others; see
    /// [`Subdivision::update_local`]): the cost of a drag step does not grow with the number of
    /// control poses. The result equals a full rebuild bit for bit.
    ///
    /// Returns the rewritten refined index range `(start, count)`, read cyclically. On error
    /// (index out of range, non-finite or non-unit pose) nothing changes.
    pub fn set_control_pose(&mut self, i: usize, pose: Pose) -> Result<(usize, usize), Error> {
        if i >= self.control.len() {
            return Err(Error::new(
                "index",
                ErrorKind::OutOfRange {
                    value: i.to_string(),
                    expected: format!("0 to {}", self.control.len() - 1),
                },
            ));
        }
        let pose = checked_pose(&pose).map_err(|e| e.within("pose"))?;
        let old = std::mem::replace(&mut self.control[i], pose);
        let refined = self.refined.poses_mut();
        match self
            .subdivision
            .update_local(&self.control, self.closed, i, refined)
        {
            Ok((start, count)) => {
                self.refined.refresh_spans(start, count);
                Ok((start, count))
            }
            Err(e) => {
                self.control[i] = old;
                Err(e)
            }
        }
    }

    /// The control poses.
    pub fn control(&self) -> &[Pose] {
        &self.control
    }

    /// The subdivision options.
    pub fn subdivision(&self) -> &Subdivision {
        &self.subdivision
    }

    /// The refined polyscrew (its poses are the subdivided poses).
    pub fn refined(&self) -> &Polyscrew {
        &self.refined
    }
}

impl Motion for ScrewBender {
    fn name(&self) -> String {
        let s = &self.subdivision;
        format!("screwbender {} {} L{}", s.scheme, s.rules, s.levels)
    }

    fn domain(&self) -> (f64, f64) {
        self.refined.domain()
    }

    fn is_closed(&self) -> bool {
        self.closed
    }

    fn pose_at(&self, u: f64) -> Pose {
        self.refined.pose_at(u)
    }

    fn knots(&self) -> Vec<f64> {
        (0..self.control.len()).map(|i| i as f64).collect()
    }

    fn kinematics(&self, u: f64, local: DVec3) -> Option<Kinematics> {
        Some(self.refined.point_kinematics(u, local))
    }
}
