//! Fewer control poses from dense ones (docs/math/formats.md §7): an imported CSV or glTF of
//! sampled poses holds hundreds of keyframes, far more than make sense as control poses.
//! [`reduce_poses`] keeps every k-th pose, or the fewest poses whose polyscrew stays within a
//! tolerance of the dense poses.

use crate::error::{Error, ErrorKind};
use crate::formats::document::MotionDocument;
use crate::formats::sampling::check_tolerance;
use crate::pose::Pose;
use crate::screw::screw;

/// More control poses than this in an imported file are likely samples of a motion rather than
/// hand-placed keys: callers offer to reduce them ([`reduce_poses`]).
pub const MANY_POSES: usize = 64;

/// How [`reduce_poses`] thins a dense pose sequence.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Reduction {
    /// Keep poses `0, k, 2k, …` (and the last pose of an open sequence).
    Every(usize),
    /// Keep the fewest poses (greedily, farthest reach first) such that every dropped pose is
    /// within `tolerance` of the polyscrew through the kept ones: the screw between its kept
    /// neighbours `a < i < b`, at the fraction `(i − a)/(b − a)`. The deviation is the origin's
    /// distance plus `radius` times the rotation angle (the most any body point within `radius`
    /// of the origin moves), in scene units.
    Fit {
        /// Largest deviation (scene units).
        tolerance: f64,
        /// Extent of the body around its local origin (0: the origin only).
        radius: f64,
    },
}

/// The document with fewer poses (see [`Reduction`]); the name, `closed` and, where they fit,
/// the key times (those of the kept poses) are kept; velocities are dropped (they belong to the
/// dense keys). At least 2 poses are always kept (3 for a cycle when the input has them).
///
/// Errors: `every` below 1, a bad tolerance (`tolerance`) or radius (`radius`).
pub fn reduce_poses(doc: &MotionDocument, reduction: Reduction) -> Result<MotionDocument, Error> {
    let n = doc.poses.len();
    let keep: Vec<usize> = match reduction {
        Reduction::Every(k) => {
            if k == 0 {
                return Err(Error::new(
                    "every",
                    ErrorKind::OutOfRange {
                        value: "0".into(),
                        expected: "a whole number ≥ 1".into(),
                    },
                ));
            }
            let mut keep: Vec<usize> = (0..n).step_by(k).collect();
            if !doc.closed && keep.last() != Some(&(n - 1)) {
                keep.push(n - 1);
            }
            keep
        }
        Reduction::Fit { tolerance, radius } => {
            check_tolerance(tolerance)?;
            if !(radius.is_finite() && radius >= 0.0) {
                return Err(Error::new(
                    "radius",
                    ErrorKind::OutOfRange {
                        value: radius.to_string(),
                        expected: "a finite number ≥ 0 (scene units)".into(),
                    },
                ));
            }
            fit(&doc.poses, doc.closed, tolerance, radius)
        }
    };
    let min = if doc.closed { 3.min(n) } else { 2.min(n) };
    let keep = if keep.len() < min {
        (0..min).map(|i| i * n / min).collect()
    } else {
        keep
    };
    let mut out = MotionDocument::new(keep.iter().map(|&i| doc.poses[i]).collect(), doc.closed);
    out.name = doc.name.clone();
    if let Some(times) = &doc.times {
        let mut kept: Vec<f64> = keep.iter().map(|&i| times[i]).collect();
        if doc.closed {
            kept.push(times[n]);
        }
        out.times = Some(kept);
    }
    Ok(out)
}

/// How far pose `p` is from `q`: origin distance plus `radius` × rotation angle.
fn deviation(p: &Pose, q: &Pose, radius: f64) -> f64 {
    p.origin.distance(q.origin) + radius * p.angle_to(q)
}

/// Whether every pose strictly between `a` and `b` (indices into the sequence, `b` may be `n`
/// for a cycle's return to pose 0) is within `tolerance` of the screw from `a` to `b`.
fn span_fits(poses: &[Pose], a: usize, b: usize, tolerance: f64, radius: f64) -> bool {
    let n = poses.len();
    let (pa, pb) = (&poses[a], &poses[b % n]);
    (a + 1..b).all(|i| {
        let s = (i - a) as f64 / (b - a) as f64;
        deviation(&screw(pa, s, pb), &poses[i], radius) <= tolerance
    })
}

/// Greedy farthest reach: from each kept pose, the farthest next pose whose span fits (found by
/// doubling, then bisection between the last fitting and the first failing reach).
fn fit(poses: &[Pose], closed: bool, tolerance: f64, radius: f64) -> Vec<usize> {
    let n = poses.len();
    let end = if closed { n } else { n - 1 };
    let mut keep = vec![0];
    let mut a = 0;
    while a < end {
        let fits = |b: usize| span_fits(poses, a, b, tolerance, radius);
        let (mut good, mut step) = (a + 1, 2);
        let mut bad = None;
        while good < end {
            let b = (a + step).min(end);
            if fits(b) {
                good = b;
                step *= 2;
            } else {
                bad = Some(b);
                break;
            }
        }
        if let Some(mut bad) = bad {
            while bad - good > 1 {
                let mid = (good + bad) / 2;
                if fits(mid) {
                    good = mid;
                } else {
                    bad = mid;
                }
            }
        }
        if good < n {
            keep.push(good);
        }
        a = good;
    }
    keep
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::{DQuat, DVec3};

    fn dense(count: usize) -> Vec<Pose> {
        (0..count)
            .map(|i| {
                let a = i as f64 / count as f64 * std::f64::consts::TAU;
                Pose::new(
                    DVec3::new(2.0 * a.cos(), 2.0 * a.sin(), 0.1 * a),
                    DQuat::from_rotation_z(a),
                )
            })
            .collect()
    }

    #[test]
    fn every_k_keeps_the_ends_of_an_open_sequence() {
        let mut doc = MotionDocument::new(dense(10), false);
        doc.times = Some((0..10).map(f64::from).collect());
        let r = reduce_poses(&doc, Reduction::Every(4)).unwrap();
        assert_eq!(r.poses.len(), 4); // 0, 4, 8, 9
        assert_eq!(r.times, Some(vec![0.0, 4.0, 8.0, 9.0]));
        r.timing().unwrap();
        assert_eq!(
            reduce_poses(&doc, Reduction::Every(0)).unwrap_err().path(),
            "every"
        );
    }

    #[test]
    fn a_fit_keeps_every_dropped_pose_within_the_tolerance() {
        // A helix sampled densely is one screw: a fit needs few poses; a bumpy one needs more.
        let doc = MotionDocument::new(dense(400), false);
        let tol = 1e-3;
        let r = reduce_poses(
            &doc,
            Reduction::Fit {
                tolerance: tol,
                radius: 1.0,
            },
        )
        .unwrap();
        assert!(r.poses.len() < 40, "{} poses kept", r.poses.len());
        let mut bumpy = dense(400);
        for (i, p) in bumpy.iter_mut().enumerate() {
            p.origin.z += 0.05 * (i as f64 * 0.2).sin();
        }
        let doc = MotionDocument::new(bumpy.clone(), true);
        let r = reduce_poses(
            &doc,
            Reduction::Fit {
                tolerance: tol,
                radius: 1.0,
            },
        )
        .unwrap();
        assert!(
            r.poses.len() > 10 && r.poses.len() < 400,
            "{}",
            r.poses.len()
        );
        // Every dense pose lies within the tolerance of the kept polyscrew.
        let idx: Vec<usize> = r
            .poses
            .iter()
            .map(|p| bumpy.iter().position(|q| q == p).unwrap())
            .collect();
        for w in 0..idx.len() {
            let (a, b) = (idx[w], if w + 1 < idx.len() { idx[w + 1] } else { 400 });
            assert!(span_fits(&bumpy, a, b, tol, 1.0), "span {a}..{b}");
        }
        assert!(!span_fits(&bumpy, 0, 200, tol, 1.0));
        let e = reduce_poses(
            &doc,
            Reduction::Fit {
                tolerance: 0.0,
                radius: 1.0,
            },
        )
        .unwrap_err();
        assert_eq!(e.path(), "tolerance");
    }
}
