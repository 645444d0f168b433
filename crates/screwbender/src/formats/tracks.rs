//! A motion document sampled in time, the way the glTF export samples it, and as keyframe
//! tracks for an animation library such as three.js (`VectorKeyframeTrack` for the positions,
//! `QuaternionKeyframeTrack` for the rotations).
//!
//! [`sample_document`] is the one sampling path of the exports: the key times and velocities of
//! the document (or given times) make the [`Timing`]; adaptive sampling bounds a linear
//! keyframe player's error at the object's points ([`Deviation::Body`], docs/math/sampling.md
//! §3), fixed-rate sampling takes uniform frames. [`keyframe_tracks`] stores the samples as
//! `f32` arrays: times from 0, positions `x, y, z`, rotations `x, y, z, w` (the order of glTF and
//! three.js, not the project's `[w, x, y, z]`) with consecutive signs made consistent.

use glam::DQuat;

use crate::error::{Error, ErrorKind};
use crate::formats::document::MotionDocument;
use crate::formats::sampling::{
    sample_fixed_rate, sample_polyscrew_within, Deviation, Sample, DEFAULT_TOLERANCE,
};
use crate::motion::Motion;
use crate::polyscrew::Polyscrew;
use crate::pose::Pose;
use crate::screwbender::ScrewBender;
use crate::subdivision::Subdivision;
use crate::timing::Timing;

/// How the motion is sampled in time.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SamplingMode {
    /// Adaptive keyframes: linear interpolation between them stays within this distance (scene
    /// units) of the true motion at the object's points (see [`sample_polyscrew_within`]).
    Adaptive(f64),
    /// A fixed frame rate (frames per second).
    FixedRate(f64),
}

impl Default for SamplingMode {
    fn default() -> Self {
        SamplingMode::Adaptive(DEFAULT_TOLERANCE)
    }
}

/// The samples of [`sample_document`] and what was sampled.
#[derive(Clone, Debug, PartialEq)]
pub struct DocumentSamples {
    /// The keyframes, times in seconds on the timing's clock (the first at the first key time).
    pub samples: Vec<Sample>,
    /// The timing used (the document's key times and velocities, or the given times).
    pub timing: Timing,
    /// The sampled motion's name (e.g. `screwbender 4-point ×5 (direct)`).
    pub motion_name: String,
}

/// The timing of `doc`: control pose `i` at `times[i]` (`n` times for an open motion, `n + 1`
/// for a cycle; `None`: the document's own, one second per span when it has none), the
/// document's key velocities applying either way. Errors name `times` or `velocities`.
fn document_timing(doc: &MotionDocument, times: Option<&[f64]>) -> Result<Timing, Error> {
    match times {
        Some(times) => Timing::for_keys(
            Some(times.to_vec()),
            doc.velocities.as_deref(),
            doc.poses.len(),
            doc.closed,
        ),
        None => doc.timing(),
    }
}

/// The motion of `doc` subdivided by `sub`: its refined polyscrew (level 0: the control poses'
/// own), what [`sample_polyscrew_within`] takes, and the subdivided motion itself from level 1.
fn refine(
    doc: &MotionDocument,
    sub: Subdivision,
) -> Result<(Option<ScrewBender>, Polyscrew), Error> {
    if sub.levels == 0 {
        Ok((None, Polyscrew::new(doc.poses.clone(), doc.closed)?))
    } else {
        let sb = ScrewBender::new(doc.poses.clone(), doc.closed, sub)?;
        let polyscrew = sb.refined().clone();
        Ok((Some(sb), polyscrew))
    }
}

/// The number of coarse spans of `doc` (a cycle's closing span included).
fn coarse_spans(doc: &MotionDocument) -> usize {
    let n = doc.poses.len();
    if doc.closed {
        n
    } else {
        n.saturating_sub(1)
    }
}

/// Samples the motion of `doc` (subdivided by `sub`; level 0 is the plain polyscrew) in time:
/// control pose `i` at `times[i]` (`n` times for an open motion, `n + 1` for a cycle; `None`:
/// the document's own, one second per span when it has none), the document's key velocities
/// applying either way. Adaptive sampling bounds `deviation` (as the glTF export does with
/// [`Deviation::Body`]); fixed-rate sampling ignores it.
///
/// Errors name the element: a time count that does not match the poses or times not increasing
/// (`times`), a bad tolerance or frame rate, a bad radius, more than
/// [`crate::MAX_SAMPLES`] samples.
pub fn sample_document(
    doc: &MotionDocument,
    sub: Subdivision,
    sampling: SamplingMode,
    times: Option<&[f64]>,
    deviation: Deviation,
) -> Result<DocumentSamples, Error> {
    let timing = document_timing(doc, times)?;
    let (sb, polyscrew) = refine(doc, sub)?;
    let motion: Box<dyn Motion> = match sb {
        Some(sb) => Box::new(sb),
        None => Box::new(polyscrew.clone()),
    };
    let samples = match sampling {
        SamplingMode::FixedRate(fps) => sample_fixed_rate(motion.as_ref(), &timing, fps)?,
        SamplingMode::Adaptive(tolerance) => {
            sample_polyscrew_within(&polyscrew, coarse_spans(doc), &timing, tolerance, deviation)?
        }
    };
    Ok(DocumentSamples {
        samples,
        timing,
        motion_name: motion.name(),
    })
}

/// Rotations as `f32` `[x, y, z, w]`, each sign chosen so its dot with the previous one is ≥ 0
/// (a player that slerps between the stored values would otherwise spin the long way on a
/// `q` / `−q` flip).
pub fn consistent_rotations(poses: &[Pose]) -> Vec<[f32; 4]> {
    let mut prev: Option<DQuat> = None;
    poses
        .iter()
        .map(|p| {
            let mut q = p.rotation.normalize();
            if let Some(pq) = prev {
                if pq.dot(q) < 0.0 {
                    q = -q;
                }
            }
            prev = Some(q);
            [q.x as f32, q.y as f32, q.z as f32, q.w as f32]
        })
        .collect()
}

/// Keyframe arrays of a sampled motion, ready for three.js `VectorKeyframeTrack('.position', …)`
/// and `QuaternionKeyframeTrack('.quaternion', …)` (or any player that lerps positions and
/// slerps rotations between keys).
#[derive(Clone, Debug, PartialEq)]
pub struct KeyframeTracks {
    /// Key times in seconds, strictly increasing as `f32`, starting at 0 (the first key time,
    /// [`KeyframeTracks::start_time`], is subtracted).
    pub times: Vec<f32>,
    /// The local origin's position at each key: `x, y, z`.
    pub positions: Vec<f32>,
    /// The rotation at each key as a unit quaternion `x, y, z, w` (three.js and glTF order; the
    /// project's own order is `[w, x, y, z]`), consecutive keys with a non-negative dot.
    pub quaternions: Vec<f32>,
    /// The motion's first key time (seconds), subtracted from [`KeyframeTracks::times`].
    pub start_time: f64,
}

/// The motion of `doc` as keyframe tracks, sampled adaptively as the glTF export samples it
/// (what [`sample_document`] gives with [`SamplingMode::Adaptive`] and [`Deviation::Body`]: the
/// same keys): a player that lerps the positions and slerps the rotations stays within
/// `tolerance` of the motion at every body point within `radius` of the local origin. Control
/// pose `i` at `times[i]` (`None`: the document's own), the key velocities applying.
///
/// Errors: those of [`sample_document`]; key times that are no longer strictly increasing once
/// stored as `f32` (`samples[i]`).
pub fn keyframe_tracks(
    doc: &MotionDocument,
    sub: Subdivision,
    tolerance: f64,
    times: Option<&[f64]>,
    radius: f64,
) -> Result<KeyframeTracks, Error> {
    let timing = document_timing(doc, times)?;
    let (_, polyscrew) = refine(doc, sub)?;
    let samples = sample_polyscrew_within(
        &polyscrew,
        coarse_spans(doc),
        &timing,
        tolerance,
        Deviation::Body { radius },
    )?;
    let start_time = timing.knots()[0];
    let times: Vec<f32> = samples
        .iter()
        .map(|s| (s.time - start_time) as f32)
        .collect();
    if let Some(i) = times
        .windows(2)
        .position(|w| w[1] <= w[0] || !w[1].is_finite())
    {
        return Err(Error::new(
            format!("samples[{}]", i + 1),
            ErrorKind::OutOfRange {
                value: format!("time {}", samples[i + 1].time - start_time),
                expected: "times strictly increasing in f32 (samples too dense)".into(),
            },
        ));
    }
    let poses: Vec<Pose> = samples.iter().map(|s| s.pose).collect();
    Ok(KeyframeTracks {
        times,
        positions: poses
            .iter()
            .flat_map(|p| p.origin.to_array().map(|x| x as f32))
            .collect(),
        quaternions: consistent_rotations(&poses).into_iter().flatten().collect(),
        start_time,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::subdivision::scheme::{Rules, Scheme};
    use glam::DVec3;

    fn doc(closed: bool) -> MotionDocument {
        let poses = vec![
            Pose {
                origin: DVec3::ZERO,
                rotation: DQuat::IDENTITY,
            },
            Pose {
                origin: DVec3::new(1.0, 0.5, 0.0),
                rotation: DQuat::from_rotation_z(2.5),
            },
            Pose {
                origin: DVec3::new(2.0, -0.5, 1.0),
                rotation: DQuat::from_rotation_x(-2.0),
            },
            Pose {
                origin: DVec3::new(0.5, 1.0, 2.0),
                rotation: DQuat::from_rotation_y(3.0),
            },
        ];
        MotionDocument::new(poses, closed)
    }

    #[test]
    fn tracks_hold_the_samples_in_f32_with_consistent_signs() {
        for closed in [false, true] {
            let d = doc(closed);
            let sub = Subdivision::new(Scheme::FourPoint, Rules::Direct, 3);
            let deviation = Deviation::Body { radius: 0.7 };
            // The export's sampling (sample_document, as export_motion calls it): the same keys.
            let sampled =
                sample_document(&d, sub, SamplingMode::Adaptive(1e-4), None, deviation).unwrap();
            let t = keyframe_tracks(&d, sub, 1e-4, None, 0.7).unwrap();
            let k = sampled.samples.len();
            assert!(k > 8, "{k} samples");
            assert_eq!(
                (t.times.len(), t.positions.len(), t.quaternions.len()),
                (k, 3 * k, 4 * k)
            );
            assert_eq!(t.times[0], 0.0);
            assert!(t.times.windows(2).all(|w| w[1] > w[0]));
            for (i, s) in sampled.samples.iter().enumerate() {
                assert_eq!(
                    t.times[i],
                    (s.time - sampled.samples[0].time) as f32,
                    "key {i}"
                );
                let p = DVec3::new(
                    t.positions[3 * i] as f64,
                    t.positions[3 * i + 1] as f64,
                    t.positions[3 * i + 2] as f64,
                );
                assert!(p.distance(s.pose.origin) <= 1e-6 * (1.0 + s.pose.origin.length()));
                let q = DQuat::from_xyzw(
                    t.quaternions[4 * i] as f64,
                    t.quaternions[4 * i + 1] as f64,
                    t.quaternions[4 * i + 2] as f64,
                    t.quaternions[4 * i + 3] as f64,
                );
                assert!((q.length() - 1.0).abs() <= 1e-6);
                // The same rotation (either sign), within f32 rounding.
                assert!(
                    q.dot(s.pose.rotation.normalize()).abs() >= 1.0 - 1e-6,
                    "key {i}"
                );
                if i > 0 {
                    let prev = &t.quaternions[4 * (i - 1)..4 * i];
                    let dot: f32 = prev
                        .iter()
                        .zip(&t.quaternions[4 * i..4 * i + 4])
                        .map(|(a, b)| a * b)
                        .sum();
                    assert!(dot >= 0.0, "keys {} and {i}: dot {dot}", i - 1);
                }
            }
        }
    }

    #[test]
    fn times_start_at_zero_and_bad_settings_are_named() {
        let d = doc(false);
        let sub = Subdivision::new(Scheme::FourPoint, Rules::Direct, 3);
        let t = keyframe_tracks(&d, sub, 1e-3, Some(&[2.0, 3.0, 5.0, 6.0]), 1.0).unwrap();
        assert_eq!(t.start_time, 2.0);
        assert_eq!(t.times[0], 0.0);
        assert!((t.times[t.times.len() - 1] - 4.0).abs() <= 1e-6);
        let err = |r: Result<KeyframeTracks, Error>| r.unwrap_err().to_string();
        assert!(err(keyframe_tracks(&d, sub, f64::NAN, None, 1.0)).contains("tolerance"));
        assert!(err(keyframe_tracks(&d, sub, 1e-3, None, -1.0)).contains("radius"));
        assert!(err(keyframe_tracks(&d, sub, 1e-3, Some(&[0.0, 1.0]), 1.0)).contains("times"));
        assert!(err(keyframe_tracks(
            &d,
            sub,
            1e-3,
            Some(&[0.0, 2.0, 1.0, 3.0]),
            1.0
        ))
        .contains("times"));
    }
}
