//! Decoupled smoothing (paper Fig. 9 V1 / Fig. 8 V2, docs/math/properties.md §1 and docs/math/decoupled-methods.md §1): the origin and the
//! rotation of a pose interpolated separately, so that the same [`Subdivision`] code that runs
//! the screw schemes runs a decoupled variant — and the frame-(in)dependence comparison of the
//! teaching view.
//!
//! [`DecoupledPose::blend`] is `(O_a + t (O_b − O_a), slerp(q_a, t, q_b))`: the origin by the
//! point rule of docs/math/point-rules.md and the rotation by the screw between the rotation-only poses (a
//! rotation about an axis through the world origin, i.e. the shorter-arc slerp, extrapolated for
//! `t` outside `[0, 1]`, with the screw's half-turn tie-break). Unlike the screw rules, the result
//! depends on which body point is chosen as the local origin.

use glam::DVec3;

use crate::error::Error;
use crate::pose::Pose;
use crate::screw::Screw;
use crate::subdivision::blend::Blend;
use crate::subdivision::Subdivision;

/// A pose whose origin and rotation are interpolated independently (see the module docs).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DecoupledPose(pub Pose);

impl Blend for DecoupledPose {
    /// Start origin, origin difference, and the screw between the rotation-only poses.
    type Span = (DVec3, DVec3, Screw);

    #[inline]
    fn span(a: &Self, b: &Self) -> Self::Span {
        let ra = Pose::new(DVec3::ZERO, a.0.rotation);
        let rb = Pose::new(DVec3::ZERO, b.0.rotation);
        (
            a.0.origin,
            b.0.origin - a.0.origin,
            Screw::between(&ra, &rb),
        )
    }

    #[inline]
    fn span_at(span: &Self::Span, t: f64) -> Self {
        DecoupledPose(Pose::new(span.0 + span.1 * t, span.2.at(t).rotation))
    }
}

/// Subdivides `poses` with origins and rotations decoupled ([`DecoupledPose`]), with the same
/// scheme, rules and levels as the screw subdivision; fails like [`Subdivision::apply`].
pub fn subdivide_decoupled(
    poses: &[Pose],
    closed: bool,
    sub: &Subdivision,
) -> Result<Vec<Pose>, Error> {
    let input: Vec<DecoupledPose> = poses.iter().map(|p| DecoupledPose(*p)).collect();
    Ok(sub
        .apply(&input, closed)?
        .into_iter()
        .map(|d| d.0)
        .collect())
}

/// The control poses re-expressed with their local origin moved to the body point `c` (local
/// coordinates): `P ∘ translate(c)`. The object does not move; only the frame used to describe
/// it changes (docs/math/properties.md §1 with `C = translate(c)`).
pub fn move_local_origin(poses: &[Pose], c: DVec3) -> Vec<Pose> {
    let t = Pose::from_translation(c);
    poses.iter().map(|p| p.compose(&t)).collect()
}

/// Trajectories of the same physical body points under the screw and the decoupled subdivision,
/// with the local origin at `c`, and how far each moved compared with `c = 0`.
#[derive(Clone, Debug, PartialEq)]
pub struct FrameComparison {
    /// Screw scheme: `points.len()` trajectories of `len` positions each, point after point.
    pub screw: Vec<DVec3>,
    /// Decoupled scheme, same layout.
    pub decoupled: Vec<DVec3>,
    /// Positions per trajectory (the refined pose count).
    pub len: usize,
    /// Largest distance between a screw trajectory point with the origin at `c` and at `0`.
    pub screw_deviation: f64,
    /// The same for the decoupled scheme.
    pub decoupled_deviation: f64,
}

/// Subdivides `poses` by screws and decoupled, once as given and once re-expressed with the local
/// origin at `c` ([`move_local_origin`]), and traces the body points `points` (given in the
/// original local frame, so in the moved frame they are `p − c`).
///
/// The screw scheme is independent of the local frame (docs/math/properties.md §1): its deviation is round-off
/// (`~1e-15` times the scene size). The decoupled scheme is not: moving the origin changes which
/// point follows the point rule exactly. Fails like [`Subdivision::apply`].
pub fn compare_frames(
    poses: &[Pose],
    closed: bool,
    sub: &Subdivision,
    c: DVec3,
    points: &[DVec3],
) -> Result<FrameComparison, Error> {
    let moved = move_local_origin(poses, c);
    let screw_base = sub.apply(poses, closed)?;
    let screw_moved = sub.apply(&moved, closed)?;
    let dec_base = subdivide_decoupled(poses, closed, sub)?;
    let dec_moved = subdivide_decoupled(&moved, closed, sub)?;
    let len = screw_base.len();
    let mut out = FrameComparison {
        screw: Vec::with_capacity(len * points.len()),
        decoupled: Vec::with_capacity(len * points.len()),
        len,
        screw_deviation: 0.0,
        decoupled_deviation: 0.0,
    };
    for p in points {
        for j in 0..len {
            let s = screw_moved[j].transform_point(*p - c);
            let d = dec_moved[j].transform_point(*p - c);
            out.screw_deviation = out
                .screw_deviation
                .max((s - screw_base[j].transform_point(*p)).length());
            out.decoupled_deviation = out
                .decoupled_deviation
                .max((d - dec_base[j].transform_point(*p)).length());
            out.screw.push(s);
            out.decoupled.push(d);
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DQuat;

    #[test]
    fn pure_translations_follow_the_point_rule() {
        let a = DecoupledPose(Pose::from_translation(DVec3::new(1.0, 2.0, 3.0)));
        let b = DecoupledPose(Pose::from_translation(DVec3::new(3.0, 2.0, 1.0)));
        let m = DecoupledPose::blend(&a, 1.5, &b);
        assert!((m.0.origin - DVec3::new(4.0, 2.0, 0.0)).length() < 1e-15);
    }

    #[test]
    fn rotation_is_slerp_origin_is_lerp() {
        let a = DecoupledPose(Pose::new(DVec3::new(3.0, 0.0, 0.0), DQuat::IDENTITY));
        let b = DecoupledPose(Pose::new(
            DVec3::new(0.0, 3.0, 0.0),
            DQuat::from_rotation_z(std::f64::consts::FRAC_PI_2),
        ));
        let m = DecoupledPose::midpoint(&a, &b);
        assert!((m.0.origin - DVec3::new(1.5, 1.5, 0.0)).length() < 1e-15);
        let expected = DQuat::from_rotation_z(std::f64::consts::FRAC_PI_4);
        assert!(m.0.rotation.dot(expected).abs() > 1.0 - 1e-15);
    }
}
