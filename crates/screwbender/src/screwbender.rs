//! The ScrewBender motion: control poses smoothed by screw subdivision.

use glam::DVec3;

use crate::closure::Closure;
use crate::error::{Error, ErrorKind};
use crate::motion::{Kinematics, Motion};
use crate::polyscrew::{check_poses, checked_pose, Polyscrew};
use crate::pose::Pose;
use crate::subdivision::{Subdivision, SubdivisionBuffers};

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
        closure: impl Into<Closure>,
        subdivision: Subdivision,
    ) -> Result<ScrewBender, Error> {
        let closed = closure.into().is_closed();
        // Validate the control poses first so errors name them, not refined poses.
        let control = checked_control(control)?;
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

    /// Makes this the motion [`ScrewBender::new`] builds from the same arguments (bit for
    /// bit), reusing this motion's memory for the refined poses and their screws, and `buffers`
    /// for the subdivision's working sequences (see [`Subdivision::apply_into`]): rebuilding a
    /// motion of the same size or smaller needs no fresh memory besides the control poses.
    ///
    /// On error (too few or bad control poses, bad options, too many refined poses) nothing
    /// changes.
    pub fn rebuild(
        &mut self,
        control: &[Pose],
        closed: bool,
        subdivision: Subdivision,
        buffers: &mut SubdivisionBuffers<Pose>,
    ) -> Result<(), Error> {
        let control = checked_control(control.to_vec())?;
        subdivision.validate()?;
        subdivision.output_len(control.len(), closed)?;
        let h = 0.5f64.powi(subdivision.levels as i32);
        let refilled = self.refined.refill(closed, h, |poses| {
            // Cannot fail: the options and the output length were checked above.
            let done = subdivision.apply_into(&control, closed, poses, buffers);
            debug_assert!(done.is_ok());
        });
        if let Err(e) = refilled {
            // Unreachable for validated poses and options (as in `new`): restore this motion
            // from its own arguments, which gives it back bit for bit.
            *self = ScrewBender::new(self.control.clone(), self.closed, self.subdivision)?;
            return Err(e.within("refined"));
        }
        self.control = control;
        self.closed = closed;
        self.subdivision = subdivision;
        Ok(())
    }

    /// Replaces control pose `i` and re-subdivides only the part of the motion it influences
    /// (2 coarse spans on each side for the B-spline, 3 for the others; see
    /// [`Subdivision::update_local`]): the cost of a drag step does not grow with the number of
    /// control poses. The result equals a full rebuild bit for bit.
    ///
    /// Returns the rewritten refined index range `(start, count)`, read cyclically. On error
    /// (index out of range, non-finite or non-unit pose) nothing changes.
    pub fn set_control_pose(&mut self, i: usize, pose: Pose) -> Result<(usize, usize), Error> {
        self.set_control_pose_by(i, pose, |sub, control, closed, refined| {
            sub.update_local(control, closed, i, refined)
        })
    }

    /// [`ScrewBender::set_control_pose`] with caller-owned working buffers for the
    /// re-subdivided window (see [`Subdivision::update_local_with`]): a drag that keeps them
    /// needs no fresh memory per step. The result is the same bit for bit.
    pub fn set_control_pose_with(
        &mut self,
        i: usize,
        pose: Pose,
        buffers: &mut SubdivisionBuffers<Pose>,
    ) -> Result<(usize, usize), Error> {
        self.set_control_pose_by(i, pose, |sub, control, closed, refined| {
            sub.update_local_with(control, closed, i, refined, buffers)
        })
    }

    /// [`ScrewBender::set_control_pose`] with `update` re-subdividing the window.
    fn set_control_pose_by(
        &mut self,
        i: usize,
        pose: Pose,
        update: impl FnOnce(&Subdivision, &[Pose], bool, &mut [Pose]) -> Result<(usize, usize), Error>,
    ) -> Result<(usize, usize), Error> {
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
        match update(&self.subdivision, &self.control, self.closed, refined) {
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

    fn kinematics_at(&self, u: f64, local: DVec3) -> Option<Kinematics> {
        Some(self.refined.point_kinematics(u, local))
    }
}

/// Control poses checked as [`Polyscrew::new`] checks them (at least 2, each finite and unit),
/// with the same errors.
fn checked_control(mut control: Vec<Pose>) -> Result<Vec<Pose>, Error> {
    if control.len() < 2 {
        return Polyscrew::new(control, false).map(|p| p.poses().to_vec());
    }
    check_poses(&mut control)?;
    Ok(control)
}
