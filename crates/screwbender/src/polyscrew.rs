//! Polyscrews: poses joined by screws (docs/math/polyscrew.md).

use std::sync::{Mutex, OnceLock, PoisonError};

use glam::DVec3;

use crate::closure::Closure;
use crate::error::{Error, ErrorKind};
use crate::motion::{Kinematics, Motion};
use crate::pose::{unit_to_rounding, Pose, UNIT_QUATERNION_TOLERANCE};
use crate::screw::Screw;

/// A sequence of poses joined by screws: on span `i` the motion is `screw(P_i, t, P_{i+1})`.
///
/// Cyclic (`closed`) polyscrews have `n` spans including `P_{n−1} → P_0`; open ones have `m − 1`.
/// Each span's screw is computed once, on first use (all spans in one batch): a polyscrew whose
/// poses alone are read (a refined motion handed out as poses) never pays for its 216-byte
/// screws. The motion parameter `u` is in coarse units:
/// span `i` covers `u ∈ [i·h, (i+1)·h]` where `h` is the span length (`1` for a control polyscrew,
/// `2^−ℓ` for one refined by `ℓ` levels of subdivision), so refined and control motions share one
/// parameter.
pub struct Polyscrew {
    poses: Vec<Pose>,
    closed: bool,
    /// The span screws, computed on first use ([`Polyscrew::spans`]).
    spans: OnceLock<Vec<Screw>>,
    /// The memory of span screws made stale by [`Polyscrew::refill`], reused when they are
    /// computed again.
    spare: Mutex<Vec<Screw>>,
    span_length: f64,
}

impl Clone for Polyscrew {
    fn clone(&self) -> Self {
        Polyscrew {
            poses: self.poses.clone(),
            closed: self.closed,
            spans: self.spans.clone(),
            spare: Mutex::new(Vec::new()),
            span_length: self.span_length,
        }
    }
}

/// Equal poses, closedness, span length and span screws (computed if they were not yet).
impl PartialEq for Polyscrew {
    fn eq(&self, other: &Self) -> bool {
        self.poses == other.poses
            && self.closed == other.closed
            && self.span_length == other.span_length
            && self.spans() == other.spans()
    }
}

impl std::fmt::Debug for Polyscrew {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Polyscrew")
            .field("poses", &self.poses)
            .field("closed", &self.closed)
            .field("spans", &self.spans())
            .field("span_length", &self.span_length)
            .finish()
    }
}

impl Polyscrew {
    /// A polyscrew through `poses` with span length 1 (pose `i` at `u = i`).
    ///
    /// Needs at least 2 poses, all finite with unit rotations (within
    /// [`UNIT_QUATERNION_TOLERANCE`]; they are renormalised).
    pub fn new(poses: Vec<Pose>, closure: impl Into<Closure>) -> Result<Polyscrew, Error> {
        Polyscrew::with_span_length(poses, closure.into().is_closed(), 1.0)
    }

    /// A polyscrew whose spans each cover `span_length` coarse units (must be positive and
    /// finite).
    pub fn with_span_length(
        mut poses: Vec<Pose>,
        closed: bool,
        span_length: f64,
    ) -> Result<Polyscrew, Error> {
        if poses.len() < 2 {
            return Err(Error::new(
                "poses",
                ErrorKind::TooFewPoses {
                    found: poses.len(),
                    min: 2,
                },
            ));
        }
        if !(span_length.is_finite() && span_length > 0.0) {
            return Err(Error::new(
                "span_length",
                ErrorKind::OutOfRange {
                    value: span_length.to_string(),
                    expected: "a positive finite number".into(),
                },
            ));
        }
        check_poses(&mut poses)?;
        Ok(Polyscrew {
            poses,
            closed,
            spans: OnceLock::new(),
            spare: Mutex::new(Vec::new()),
            span_length,
        })
    }

    /// Makes this a polyscrew through the poses `fill` writes into the (cleared) pose buffer,
    /// reusing this polyscrew's memory for the poses and the span screws. The poses are checked
    /// as in [`Polyscrew::with_span_length`]; on error the content of the polyscrew is
    /// unspecified (the caller rebuilds it).
    pub(crate) fn refill(
        &mut self,
        closed: bool,
        span_length: f64,
        fill: impl FnOnce(&mut Vec<Pose>),
    ) -> Result<(), Error> {
        self.poses.clear();
        fill(&mut self.poses);
        if self.poses.len() < 2 || !(span_length.is_finite() && span_length > 0.0) {
            // The same errors as a new polyscrew.
            return Polyscrew::with_span_length(
                std::mem::take(&mut self.poses),
                closed,
                span_length,
            )
            .map(drop);
        }
        check_poses(&mut self.poses)?;
        self.closed = closed;
        self.span_length = span_length;
        if let Some(stale) = self.spans.take() {
            *self.spare.get_mut().unwrap_or_else(PoisonError::into_inner) = stale;
        }
        Ok(())
    }

    /// Mutable access to the poses for in-crate local updates; call
    /// [`Polyscrew::refresh_spans`] for the changed range afterwards.
    pub(crate) fn poses_mut(&mut self) -> &mut [Pose] {
        &mut self.poses
    }

    /// Recomputes the screws of every span touching poses `start .. start + count` (indices
    /// read cyclically for a closed polyscrew).
    pub(crate) fn refresh_spans(&mut self, start: usize, count: usize) {
        let n = self.poses.len();
        // Not computed yet: they will be, from the new poses.
        let Some(screws) = self.spans.get_mut() else {
            return;
        };
        let spans = screws.len();
        if count >= n {
            screws.clear();
            span_screws_into(&self.poses, self.closed, screws);
            return;
        }
        // Spans start−1 … start+count−1 have an end in the range: recomputed in runs of
        // consecutive spans that do not wrap, each run in one batch (bit for bit
        // `Screw::between`).
        let mut fresh = Vec::with_capacity(count + 1);
        let mut k = 0;
        while k <= count {
            let first = (start + n + k - 1) % n;
            if first >= spans {
                k += 1;
                continue;
            }
            // The run ends before the span that wraps round (n − 1 → 0) or at the range's end.
            let len = (count + 1 - k).min(n - 1 - first).max(1).min(spans - first);
            let last = first + len;
            fresh.clear();
            if last < n {
                span_screws_into(&self.poses[first..=last], false, &mut fresh);
            } else {
                // The closing span n − 1 → 0 alone.
                fresh.push(Screw::between(&self.poses[first], &self.poses[0]));
            }
            screws[first..first + len].copy_from_slice(&fresh);
            k += len;
        }
    }

    /// The poses at the span ends (the control poses of a plain polyscrew).
    pub fn poses(&self) -> &[Pose] {
        &self.poses
    }

    /// Whether the last pose is joined back to the first.
    pub fn closed(&self) -> bool {
        self.closed
    }

    /// The number of spans: `n` closed, `n − 1` open.
    fn span_count(&self) -> usize {
        let n = self.poses.len();
        if self.closed {
            n
        } else {
            n - 1
        }
    }

    /// The screws of the spans, `spans()[i]` from pose `i` to pose `i+1` (mod `n` when closed).
    pub fn spans(&self) -> &[Screw] {
        self.spans.get_or_init(|| {
            // In the memory of the last stale screws, if any (bit for bit the same screws).
            let mut spans =
                std::mem::take(&mut *self.spare.lock().unwrap_or_else(PoisonError::into_inner));
            spans.clear();
            span_screws_into(&self.poses, self.closed, &mut spans);
            spans
        })
    }

    /// Coarse parameter units covered by one span.
    pub fn span_length(&self) -> f64 {
        self.span_length
    }

    /// The span index and local fraction `t ∈ [0, 1)` (or beyond, extrapolating the end spans
    /// of an open polyscrew) for coarse parameter `u`.
    pub fn locate(&self, u: f64) -> (usize, f64) {
        let x = u / self.span_length;
        let count = self.span_count();
        if self.closed {
            let x = x.rem_euclid(count as f64);
            // rem_euclid may round up to exactly `count`.
            let i = (x.floor() as usize).min(count - 1);
            (i, x - i as f64)
        } else {
            let i = if x.is_nan() {
                0
            } else {
                x.floor().clamp(0.0, (count - 1) as f64) as usize
            };
            (i, x - i as f64)
        }
    }

    /// The pose at coarse parameter `u` (docs/math/polyscrew.md).
    pub fn pose_at(&self, u: f64) -> Pose {
        let (i, t) = self.locate(u);
        self.spans()[i].at(t)
    }

    /// Closed-form kinematics of the body point `local` at `u`, per coarse parameter unit.
    ///
    /// Along each span the twist is constant (`ω = θn/h`, `v₀`/h for span length `h`), so the
    /// velocity is `ω × x + v₀`, the acceleration `ω × (ω × x + v₀)` and the angular acceleration
    /// zero. At a span boundary the value of the span that starts there is returned.
    pub fn point_kinematics(&self, u: f64, local: DVec3) -> Kinematics {
        let (i, t) = self.locate(u);
        self.span_kinematics(i, t, local)
    }

    /// Kinematics on span `i` at local fraction `t` (see [`Polyscrew::point_kinematics`]); with
    /// `t = 1` this is the left-hand value at the span's end.
    pub fn span_kinematics(&self, i: usize, t: f64, local: DVec3) -> Kinematics {
        let span = &self.spans()[i];
        let x = span.at(t).transform_point(local);
        let (omega, v0) = span.twist();
        let inv_h = 1.0 / self.span_length;
        let (omega, v0) = (omega * inv_h, v0 * inv_h);
        let velocity = omega.cross(x) + v0;
        Kinematics {
            position: x,
            velocity,
            acceleration: omega.cross(velocity),
            angular_velocity: omega,
            angular_acceleration: DVec3::ZERO,
        }
    }
}

/// A pose checked for use in a motion: finite, rotation unit within
/// [`UNIT_QUATERNION_TOLERANCE`] (then renormalised).
pub(crate) fn checked_pose(p: &Pose) -> Result<Pose, Error> {
    if !p.is_finite() {
        return Err(Error::new(String::new(), ErrorKind::NonFinite));
    }
    // Rotations already unit to rounding pass through untouched, so validating twice changes
    // nothing (a rebuilt motion is bit-identical to an edited one).
    if unit_to_rounding(p.rotation.length_squared()) {
        return Ok(*p);
    }
    let norm = p.rotation.length();
    if (norm - 1.0).abs() > UNIT_QUATERNION_TOLERANCE {
        return Err(Error::new(
            "rotation",
            ErrorKind::NonUnitQuaternion {
                norm,
                tolerance: UNIT_QUATERNION_TOLERANCE,
            },
        ));
    }
    let rotation = p.rotation / norm;
    Ok(Pose::new(p.origin, rotation))
}

/// Checks every pose for use in a motion ([`checked_pose`]), naming the first bad one.
pub(crate) fn check_poses(poses: &mut [Pose]) -> Result<(), Error> {
    for (i, p) in poses.iter_mut().enumerate() {
        // The common case inline (a refined motion checks thousands): finite and unit to
        // rounding, which `checked_pose` passes through untouched.
        if p.origin.is_finite() && unit_to_rounding(p.rotation.length_squared()) {
            continue;
        }
        *p = checked_pose(p).map_err(|e| e.within(&format!("poses[{i}]")))?;
    }
    Ok(())
}

/// Appends the screw of every span of a pose sequence to `out`: several at a time on SIMD
/// lanes where the build has them, bit for bit [`Screw::between`] of each span.
pub(crate) fn span_screws_into(poses: &[Pose], closed: bool, out: &mut Vec<Screw>) {
    #[cfg(lanes)]
    crate::screw::batch::span_screws(poses, closed, out);
    #[cfg(not(lanes))]
    {
        let n = poses.len();
        let count = if closed { n } else { n.saturating_sub(1) };
        out.extend((0..count).map(|i| Screw::between(&poses[i], &poses[(i + 1) % n])));
    }
}

impl Motion for Polyscrew {
    fn name(&self) -> String {
        "polyscrew".into()
    }

    fn domain(&self) -> (f64, f64) {
        (0.0, self.span_count() as f64 * self.span_length)
    }

    fn is_closed(&self) -> bool {
        self.closed
    }

    fn pose_at(&self, u: f64) -> Pose {
        Polyscrew::pose_at(self, u)
    }

    fn knots(&self) -> Vec<f64> {
        (0..self.poses.len())
            .map(|i| i as f64 * self.span_length)
            .collect()
    }

    fn kinematics_at(&self, u: f64, local: DVec3) -> Option<Kinematics> {
        Some(self.point_kinematics(u, local))
    }
}
