//! What the keyframe imports (CSV, glTF) share: their size limit, and how a repeated last pose
//! marks a cycle.

use crate::pose::Pose;

/// Largest keyframe file accepted (CSV, glTF, GLB, a glTF buffer): 64 MiB. Larger input is
/// refused before parsing.
pub(crate) const MAX_KEYFRAME_FILE_BYTES: usize = 64 << 20;

/// A last keyframe this close to the first (origin distance, and rotation angle in radians)
/// marks a cycle. Loose enough for `f32` storage of scene-sized coordinates.
pub const REPEAT_TOLERANCE: f64 = 1e-5;

/// Whether the last of more than two poses repeats the first within [`REPEAT_TOLERANCE`] (the
/// file then describes a cycle and the repeat is dropped).
pub(crate) fn last_repeats_first(poses: &[Pose]) -> bool {
    match poses {
        [a, .., b] if poses.len() > 2 => {
            a.origin.distance(b.origin) <= REPEAT_TOLERANCE && a.angle_to(b) <= REPEAT_TOLERANCE
        }
        _ => false,
    }
}
