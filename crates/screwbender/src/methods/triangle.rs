//! Rigid-triangle input of the Chaudhry–Cameron method: samples, validation, and the rotation at
//! each sample recovered from three vertex positions (docs/math/rational-motion.md §4).

use glam::{DQuat, DVec3};

use crate::error::{check_finite, Error, ErrorKind};
use crate::pose::Pose;

/// A triangle whose sine of its smallest-angle measure `|e₁ × e₂| / max(|e₁|, |e₂|)²` is at most
/// this is rejected as degenerate (collinear or coincident vertices): its rotation would be
/// determined only to about `ε / 1e-6` radians by data of relative precision `ε`.
pub const DEGENERATE_TRIANGLE_TOLERANCE: f64 = 1e-6;

/// Largest accepted change of an edge length between the first sample and any other, relative to
/// the longest edge of the first sample. Data printed with six decimals (scene `triangle7`) is
/// rigid to about `2e-6`; beyond `1e-4` the data is not a rigid motion and is rejected.
pub const RIGIDITY_TOLERANCE: f64 = 1e-4;

/// docs/math/rational-motion.md §4.5: when the longest cross product of the basis differences is at most this times the
/// squared scale of the triangle, the rotation is taken as the identity (pure translation).
pub const ROTATION_EPSILON: f64 = 1e-12;

/// One observation of the rigid triangle: the time and the three vertex positions
/// (vertex `a` carries the translation; docs/math/rational-motion.md §1).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TriangleSample {
    /// The time `t_i` (strictly increasing over the samples).
    pub t: f64,
    /// Vertex `a` (the reference point).
    pub a: DVec3,
    /// Vertex `x`.
    pub x: DVec3,
    /// Vertex `y`.
    pub y: DVec3,
}

/// The vertices of the triangle in a body's local frame, used to turn poses into triangle samples.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ReferenceTriangle {
    /// Local coordinates of vertex `a`.
    pub a: DVec3,
    /// Local coordinates of vertex `x`.
    pub x: DVec3,
    /// Local coordinates of vertex `y`.
    pub y: DVec3,
}

impl ReferenceTriangle {
    /// The triangle of scene B1 (`triangle7`): `a = (0,0,0)`, `x = (1,0,0)`, `y = (0.3,0.8,0)`.
    pub const SCENE_B1: ReferenceTriangle = ReferenceTriangle {
        a: DVec3::ZERO,
        x: DVec3::new(1.0, 0.0, 0.0),
        y: DVec3::new(0.3, 0.8, 0.0),
    };
}

impl Default for ReferenceTriangle {
    fn default() -> Self {
        ReferenceTriangle::SCENE_B1
    }
}

impl TriangleSample {
    /// The sample of the triangle `reference` (local coordinates) placed by `pose` at time `t`.
    pub fn from_pose(t: f64, pose: &Pose, reference: &ReferenceTriangle) -> TriangleSample {
        TriangleSample {
            t,
            a: pose.transform_point(reference.a),
            x: pose.transform_point(reference.x),
            y: pose.transform_point(reference.y),
        }
    }

    /// Edge vectors `e₁ = x − a`, `e₂ = y − a`.
    pub fn edges(&self) -> (DVec3, DVec3) {
        (self.x - self.a, self.y - self.a)
    }

    /// The three edge lengths `|x − a|`, `|y − a|`, `|y − x|`.
    pub fn edge_lengths(&self) -> [f64; 3] {
        [
            (self.x - self.a).length(),
            (self.y - self.a).length(),
            (self.y - self.x).length(),
        ]
    }
}

/// Samples of `reference` placed by each pose, at the given times (one per pose).
pub fn samples_from_poses(
    poses: &[Pose],
    times: &[f64],
    reference: &ReferenceTriangle,
) -> Result<Vec<TriangleSample>, Error> {
    if times.len() != poses.len() {
        return Err(Error::new(
            "times",
            ErrorKind::OutOfRange {
                value: format!("{} times", times.len()),
                expected: format!("one time per pose ({})", poses.len()),
            },
        ));
    }
    Ok(poses
        .iter()
        .zip(times)
        .map(|(p, &t)| TriangleSample::from_pose(t, p, reference))
        .collect())
}

/// Checks the samples (docs/math/rational-motion.md §1, §4): at least `min` of them, finite, strictly increasing times
/// (equal consecutive times are rejected as duplicate keyframes), a non-degenerate first
/// triangle (see [`DEGENERATE_TRIANGLE_TOLERANCE`]) and edge lengths equal to the first
/// sample's within [`RIGIDITY_TOLERANCE`]. Errors name `samples[i]` (and the field).
pub fn validate_samples(samples: &[TriangleSample], min: usize) -> Result<(), Error> {
    if samples.len() < min {
        return Err(Error::new(
            "samples",
            ErrorKind::TooFewPoses {
                found: samples.len(),
                min,
            },
        ));
    }
    for (i, s) in samples.iter().enumerate() {
        let at = |field: &str| format!("samples[{i}].{field}");
        check_finite(&[s.t], &at("t"))?;
        check_finite(&s.a.to_array(), &at("a"))?;
        check_finite(&s.x.to_array(), &at("x"))?;
        check_finite(&s.y.to_array(), &at("y"))?;
        if i > 0 && s.t <= samples[i - 1].t {
            return Err(Error::new(at("t"), ErrorKind::OutOfRange { value: s.t.to_string(), expected: format!(
                    "a time after samples[{}].t = {} (times must increase strictly; duplicate keyframes are not allowed)",
                    i - 1,
                    samples[i - 1].t
                ) }));
        }
    }
    let first = &samples[0];
    let (e1, e2) = first.edges();
    let scale = e1.length().max(e2.length());
    let area = e1.cross(e2).length();
    if scale.is_nan() || scale <= 0.0 || area <= DEGENERATE_TRIANGLE_TOLERANCE * scale * scale {
        return Err(Error::new("samples[0]", ErrorKind::Unsupported { reason: format!(
                "degenerate triangle (collinear or coincident vertices: |e1 × e2| = {area:.3e}, longest edge {scale:.3e})"
            ) }));
    }
    let ref_len = first.edge_lengths();
    let longest = ref_len.iter().fold(0.0f64, |m, &l| m.max(l));
    for (i, s) in samples.iter().enumerate().skip(1) {
        let len = s.edge_lengths();
        let dev = (0..3).fold(0.0f64, |m, k| m.max((len[k] - ref_len[k]).abs()));
        if dev > RIGIDITY_TOLERANCE * longest {
            return Err(Error::new(format!("samples[{i}]"), ErrorKind::OutOfRange { value: format!("edge lengths {len:?}"), expected: format!(
                    "the edge lengths of samples[0] {ref_len:?} within {RIGIDITY_TOLERANCE} relative (a rigid triangle)"
                ) }));
        }
    }
    Ok(())
}

/// The unit quaternion of the rotation that carries the triangle `reference` (its edges
/// relative to vertex `a`) to `sample`, by the robust Gibbs-vector construction of docs/math/rational-motion.md §4.5.
///
/// With `e₁ = x − a`, `e₂ = y − a`, `e₃ = e₁ × e₂` before (`…,0`) and after (`…,i`),
/// `Δ_k = e_{k,i} − e_{k,0}`, `Σ_k = e_{k,i} + e_{k,0}`: among the pairs `(1,2), (2,3), (3,1)` pick
/// the one maximising `|Δ_k × Δ_l|`; then `Q ∝ (Δ_k · Σ_l, Δ_k × Δ_l)`. No rotation (longest cross
/// product at most [`ROTATION_EPSILON`] times the squared scale) gives the identity; half turns
/// (`Q.w = 0`) and rotation axes in the triangle's plane need no special branch. The result has
/// `w ≥ 0` (angle in `[0, π]`); apply the sign rule of eq. (9) afterwards.
pub fn rotation_between(reference: &TriangleSample, sample: &TriangleSample) -> DQuat {
    let (e10, e20) = reference.edges();
    let (e1i, e2i) = sample.edges();
    let e30 = e10.cross(e20);
    let e3i = e1i.cross(e2i);
    let delta = [e1i - e10, e2i - e20, e3i - e30];
    let sum = [e1i + e10, e2i + e20, e3i + e30];
    // e3 has units of length², so its differences are compared after scaling by 1/scale.
    let scale = e10.length().max(e20.length());
    if scale.is_nan() || scale <= 0.0 {
        return DQuat::IDENTITY;
    }
    let inv = 1.0 / scale;
    let d = [delta[0], delta[1], delta[2] * inv];
    let s = [sum[0], sum[1], sum[2] * inv];
    let mut best = (0usize, 1usize, d[0].cross(d[1]));
    for (k, l) in [(1usize, 2usize), (2, 0)] {
        let c = d[k].cross(d[l]);
        if c.length_squared() > best.2.length_squared() {
            best = (k, l, c);
        }
    }
    let (k, l, c) = best;
    if c.length() <= ROTATION_EPSILON * scale * scale {
        return DQuat::IDENTITY;
    }
    let w = d[k].dot(s[l]);
    let q = DQuat::from_xyzw(c.x, c.y, c.z, w).normalize();
    if q.w < 0.0 {
        -q
    } else {
        q
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn place(q: DQuat, o: DVec3) -> TriangleSample {
        TriangleSample::from_pose(0.0, &Pose::new(o, q), &ReferenceTriangle::SCENE_B1)
    }

    #[test]
    fn recovers_special_rotations() {
        let r0 = place(DQuat::IDENTITY, DVec3::ZERO);
        let axis_in_plane = DVec3::new(1.0, 1.0, 0.0).normalize();
        for q in [
            DQuat::IDENTITY,
            DQuat::from_axis_angle(axis_in_plane, std::f64::consts::FRAC_PI_2),
            DQuat::from_axis_angle(DVec3::X, 0.7), // edge a–x fixed
            DQuat::from_axis_angle(DVec3::Z, std::f64::consts::PI),
            DQuat::from_axis_angle(DVec3::new(0.3, -1.0, 0.2).normalize(), std::f64::consts::PI),
            DQuat::from_axis_angle(DVec3::new(1.0, 2.0, 3.0).normalize(), 1e-9),
        ] {
            let s = place(q, DVec3::new(1.0, -2.0, 0.5));
            let back = rotation_between(&r0, &s);
            assert!(back.dot(q).abs() > 1.0 - 1e-15, "{q} → {back}");
        }
    }

    #[test]
    fn validation_names_samples() {
        let good: Vec<_> = (0..3)
            .map(|i| {
                let mut s = place(DQuat::from_rotation_z(0.3 * i as f64), DVec3::X * i as f64);
                s.t = i as f64;
                s
            })
            .collect();
        assert!(validate_samples(&good, 2).is_ok());
        assert!(matches!(
            validate_samples(&good[..1], 2)
                .as_ref()
                .map_err(|e| e.kind()),
            Err(ErrorKind::TooFewPoses { .. })
        ));
        let mut bad = good.clone();
        bad[2].t = 1.0;
        assert_eq!(
            validate_samples(&bad, 2).unwrap_err().path(),
            "samples[2].t"
        );
        let mut bad = good.clone();
        bad[1].y += DVec3::new(0.0, 0.01, 0.0);
        assert_eq!(validate_samples(&bad, 2).unwrap_err().path(), "samples[1]");
        let mut bad = good.clone();
        bad[0].y = bad[0].a + (bad[0].x - bad[0].a) * 2.0;
        assert_eq!(validate_samples(&bad, 2).unwrap_err().path(), "samples[0]");
        let mut bad = good;
        bad[1].x.z = f64::NAN;
        assert_eq!(
            validate_samples(&bad, 2).unwrap_err().path(),
            "samples[1].x"
        );
    }
}
