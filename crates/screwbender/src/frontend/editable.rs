//! The editable motion every binding wraps: a motion document and its subdivision options,
//! changed only by validated updates, and the smooth motion they define, refined on first use
//! and kept until an edit makes it stale.
//!
//! The JavaScript class `Motion` and the Python class `Motion` each convert their arguments and
//! results and otherwise call this, so that an edit is accepted, refused and worded the same way
//! in both, and a refinement is reused in both for as long as it is valid.
//!
//! Every edit builds the next state, validates it completely ([`MotionDocument::check_with`]:
//! the poses, the timing, the options and the memory guard [`crate::MAX_REFINED_POSES`]) and
//! only then stores it: after an error the motion keeps its exact previous state.

use crate::error::{Error, ErrorKind};
use crate::formats::document::MotionDocument;
use crate::pose::Pose;
use crate::screw::screw;
use crate::screwbender::ScrewBender;
use crate::subdivision::{Subdivision, SubdivisionBuffers};

use super::options::{resolve, OptionsInput};

/// A motion document and subdivision options that are always valid together, with their
/// refinement cached until the next edit.
#[derive(Debug)]
pub struct EditableMotion {
    doc: MotionDocument,
    subdivision: Subdivision,
    /// The refined motion with its span screws, built on first use.
    motion: Option<ScrewBender>,
    /// The refined poses alone ([`EditableMotion::refined_poses`] before any evaluation needs
    /// the screws, which cost more than the poses).
    poses: Option<Vec<Pose>>,
    /// The refined motion an edit made stale: the next one is rebuilt in its memory
    /// ([`ScrewBender::rebuild`]), as a subdivision into fresh memory pays a page fault per 4 KB.
    spare_motion: Option<ScrewBender>,
    /// The memory of refined poses an edit made stale, for the next refinement of the poses.
    spare_poses: Vec<Pose>,
    /// The subdivision's working sequences, kept from one subdivision to the next.
    buffers: SubdivisionBuffers<Pose>,
}

impl Clone for EditableMotion {
    /// An independent copy with the same state and refinement; the spare memory stays here.
    fn clone(&self) -> Self {
        EditableMotion {
            doc: self.doc.clone(),
            subdivision: self.subdivision,
            motion: self.motion.clone(),
            poses: self.poses.clone(),
            spare_motion: None,
            spare_poses: Vec::new(),
            buffers: SubdivisionBuffers::new(),
        }
    }
}

/// `i` as an index into `len` items, or an error at `index` naming the range.
fn check_index(i: usize, len: usize) -> Result<usize, Error> {
    if i < len {
        Ok(i)
    } else {
        Err(Error::new(
            "index",
            ErrorKind::OutOfRange {
                value: i.to_string(),
                expected: match len {
                    0 => "no index (the sequence is empty)".to_string(),
                    _ => format!("an integer from 0 to {}", len - 1),
                },
            },
        ))
    }
}

impl EditableMotion {
    /// A motion of `doc` subdivided by `subdivision`, if they are valid together.
    pub fn new(doc: MotionDocument, subdivision: Subdivision) -> Result<EditableMotion, Error> {
        doc.check_with(&subdivision)?;
        Ok(EditableMotion {
            doc,
            subdivision,
            motion: None,
            poses: None,
            spare_motion: None,
            spare_poses: Vec::new(),
            buffers: SubdivisionBuffers::new(),
        })
    }

    /// The motion document: control poses, closedness, name and key timing.
    pub fn document(&self) -> &MotionDocument {
        &self.doc
    }

    /// The subdivision options.
    pub fn subdivision(&self) -> Subdivision {
        self.subdivision
    }

    /// The parameter interval `(0, n)` of a cycle of `n` poses, `(0, m − 1)` of an open one.
    pub fn domain(&self) -> (f64, f64) {
        let n = self.doc.poses.len();
        let spans = if self.doc.closed { n } else { n - 1 };
        (0.0, spans as f64)
    }

    /// How many refined poses the options make of the control poses.
    pub fn refined_count(&self) -> Result<usize, Error> {
        self.subdivision
            .output_len(self.doc.poses.len(), self.doc.closed)
    }

    /// Where the options give a poor result without an error, one sentence each.
    pub fn warnings(&self) -> Vec<String> {
        self.subdivision
            .warnings(&self.doc.poses, self.doc.closed)
            .iter()
            .map(ToString::to_string)
            .collect()
    }

    /// Whether the refinement of the current state is cached (nothing to compute on the next
    /// evaluation).
    pub fn is_refined(&self) -> bool {
        self.motion.is_some() || self.poses.is_some()
    }

    /// Applies `change` to a copy of the document and options, validates the copy and only then
    /// stores it (and forgets the refinement); on error nothing changes.
    pub fn update(
        &mut self,
        change: impl FnOnce(&mut MotionDocument, &mut Subdivision) -> Result<(), Error>,
    ) -> Result<(), Error> {
        let mut doc = self.doc.clone();
        let mut subdivision = self.subdivision;
        change(&mut doc, &mut subdivision)?;
        doc.check_with(&subdivision)?;
        self.doc = doc;
        self.subdivision = subdivision;
        self.invalidate();
        Ok(())
    }

    /// Forgets the refinement, keeping its memory for the next one.
    fn invalidate(&mut self) {
        if let Some(stale) = self.motion.take() {
            self.spare_motion = Some(stale);
        }
        if let Some(stale) = self.poses.take() {
            self.spare_poses = stale;
        }
    }

    /// Replaces the document (the options are kept).
    pub fn set_document(&mut self, doc: MotionDocument) -> Result<(), Error> {
        self.update(|d, _| {
            *d = doc;
            Ok(())
        })
    }

    /// Sets or clears the document's display name.
    pub fn set_name(&mut self, name: Option<String>) -> Result<(), Error> {
        self.update(|d, _| {
            d.name = name;
            Ok(())
        })
    }

    /// Makes the motion a cycle (`true`) or an open sequence (`false`).
    pub fn set_closed(&mut self, closed: bool) -> Result<(), Error> {
        self.update(|d, _| {
            d.set_closed(closed);
            Ok(())
        })
    }

    /// Replaces every control pose.
    pub fn set_poses(&mut self, poses: Vec<Pose>) -> Result<(), Error> {
        self.update(|d, _| {
            d.poses = poses;
            Ok(())
        })
    }

    /// Sets the key times (`None`: uniform), keeping the key velocities; errors name `times`
    /// or `times[i]`.
    pub fn set_times(&mut self, times: Option<Vec<f64>>) -> Result<(), Error> {
        self.update(|d, _| d.set_timing(times, d.velocities.clone()))
    }

    /// Sets the key velocities (`None`: all free), keeping the key times; errors name
    /// `velocities` or `velocities[i]`.
    pub fn set_velocities(&mut self, velocities: Option<Vec<Option<f64>>>) -> Result<(), Error> {
        self.update(|d, _| d.set_timing(d.times.clone(), velocities))
    }

    /// Replaces the subdivision options.
    pub fn set_subdivision(&mut self, subdivision: Subdivision) -> Result<(), Error> {
        self.update(|_, s| {
            *s = subdivision;
            Ok(())
        })
    }

    /// Applies options as a front end receives them ([`resolve`]) over the current ones.
    pub fn set_options(&mut self, input: &OptionsInput) -> Result<(), Error> {
        let next = resolve(self.subdivision, input)?;
        self.set_subdivision(next)
    }

    /// Replaces control pose `i`. A drag calls this every frame, so a cached refined motion is
    /// kept and only the window the pose influences is subdivided again (bit for bit a rebuild;
    /// [`ScrewBender::set_control_pose_with`]).
    pub fn set_pose(&mut self, i: usize, pose: Pose) -> Result<(), Error> {
        let i = check_index(i, self.doc.poses.len())?;
        let mut doc = self.doc.clone();
        doc.poses[i] = pose;
        doc.check_with(&self.subdivision)?;
        if let Some(motion) = self.motion.as_mut() {
            motion.set_control_pose_with(i, pose, &mut self.buffers)?;
        }
        if let Some(stale) = self.poses.take() {
            self.spare_poses = stale;
        }
        self.doc = doc;
        Ok(())
    }

    /// Inserts a pose between control poses `i` and `i + 1` and returns its index, `i + 1`.
    /// Without `pose`, inserts the screw midpoint `screw(P_i, ½, P_{i+1})` (a cycle's last pose
    /// is followed by its first; an open motion's last pose has no successor).
    pub fn insert_pose(&mut self, i: usize, pose: Option<Pose>) -> Result<usize, Error> {
        let n = self.doc.poses.len();
        let i = match pose {
            Some(_) => check_index(i, n)?,
            None => check_index(i, if self.doc.closed { n } else { n - 1 })?,
        };
        self.update(|d, _| {
            let new = match pose {
                Some(p) => p,
                None => screw(&d.poses[i], 0.5, &d.poses[(i + 1) % n]),
            };
            d.insert_pose(i + 1, new);
            Ok(())
        })?;
        Ok(i + 1)
    }

    /// Removes control pose `i` (a motion keeps at least 2 poses).
    pub fn remove_pose(&mut self, i: usize) -> Result<(), Error> {
        let i = check_index(i, self.doc.poses.len())?;
        self.update(|d, _| {
            d.remove_pose(i);
            Ok(())
        })
    }

    /// The refined motion with its span screws, subdivided first if an edit made it stale.
    pub fn refined(&mut self) -> Result<&ScrewBender, Error> {
        if self.motion.is_none() {
            let (doc, sub) = (&self.doc, self.subdivision);
            let motion = match self.spare_motion.take() {
                Some(mut motion) => {
                    motion.rebuild(&doc.poses, doc.closed, sub, &mut self.buffers)?;
                    motion
                }
                None => ScrewBender::new(doc.poses.clone(), doc.closed, sub)?,
            };
            if let Some(poses) = self.poses.take() {
                self.spare_poses = poses;
            }
            self.motion = Some(motion);
        }
        match &self.motion {
            Some(motion) => Ok(motion),
            None => unreachable!("the refined motion was stored above"),
        }
    }

    /// The refined poses (those of [`EditableMotion::refined`] bit for bit), subdivided first if
    /// an edit made them stale; without the span screws when the motion has not been evaluated.
    pub fn refined_poses(&mut self) -> Result<&[Pose], Error> {
        if self.motion.is_none() && self.poses.is_none() {
            let mut poses = std::mem::take(&mut self.spare_poses);
            self.subdivision.apply_into(
                &self.doc.poses,
                self.doc.closed,
                &mut poses,
                &mut self.buffers,
            )?;
            self.poses = Some(poses);
        }
        match (&self.motion, &self.poses) {
            (Some(motion), _) => Ok(motion.refined().poses()),
            (None, Some(poses)) => Ok(poses),
            (None, None) => unreachable!("the refined poses were stored above"),
        }
    }
}
