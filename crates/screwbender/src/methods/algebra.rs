//! Quaternion algebra shared by the comparison methods: the unnormalised rotation matrix `M(Q)`
//! and its polarisation (Chaudhry & Cameron), quaternion exp/log, slerp without sign flip, sign
//! alignment, and the angular velocity/acceleration of a possibly non-unit quaternion curve.
//!
//! Quaternions that are merely points of R⁴ (spline control points, non-unit curve values) are
//! stored in glam's [`DQuat`] as well: its `+`, `−`, scalar `*` and `dot` are the R⁴ operations,
//! and `*` between two quaternions is the Hamilton product.

use glam::{DMat3, DQuat, DVec3};

/// Below this angle (radians) [`slerp_raw`] and [`qlog`] switch to their first-order forms
/// (linear interpolation resp. `log q ≈ vec(q)`), whose error is below `1e-16` relative there.
pub const SMALL_ANGLE: f64 = 1e-8;

/// The unnormalised rotation matrix `M(Q) = |Q|² R(Q/|Q|)` (docs/math/rational-motion.md §2): each entry a
/// quadratic form in `Q`, so `M(Q) v = vec(Q (0, v) Q*)`.
pub fn unnormalised_matrix(q: DQuat) -> DMat3 {
    let (q0, q1, q2, q3) = (q.w, q.x, q.y, q.z);
    DMat3::from_cols(
        DVec3::new(
            q0 * q0 + q1 * q1 - q2 * q2 - q3 * q3,
            2.0 * (q1 * q2 + q0 * q3),
            2.0 * (q1 * q3 - q0 * q2),
        ),
        DVec3::new(
            2.0 * (q1 * q2 - q0 * q3),
            q0 * q0 - q1 * q1 + q2 * q2 - q3 * q3,
            2.0 * (q2 * q3 + q0 * q1),
        ),
        DVec3::new(
            2.0 * (q1 * q3 + q0 * q2),
            2.0 * (q2 * q3 - q0 * q1),
            q0 * q0 - q1 * q1 - q2 * q2 + q3 * q3,
        ),
    )
}

/// The polarised (symmetric bilinear) form `Ms(P, Q) = (M(P+Q) − M(P−Q))/4`, with `Ms(Q, Q) = M(Q)`
/// (docs/math/rational-motion.md §2): `Ms(P, Q) v = vec(P (0,v) Q* + Q (0,v) P*)/2`.
pub fn polar_matrix(p: DQuat, q: DQuat) -> DMat3 {
    (unnormalised_matrix(p + q) - unnormalised_matrix(p - q)) * 0.25
}

/// `exp` of the pure quaternion `(0, v)`: `(cos|v|, sin|v| v/|v|)`, the rotation by `2|v|` about
/// `v` (half-angle convention of Kim–Kim–Shin and of Squad).
pub fn qexp(v: DVec3) -> DQuat {
    let a = v.length();
    if a < SMALL_ANGLE {
        return DQuat::from_xyzw(v.x, v.y, v.z, 1.0).normalize();
    }
    let s = a.sin() / a;
    DQuat::from_xyzw(v.x * s, v.y * s, v.z * s, a.cos())
}

/// `log` of a unit quaternion, the inverse of [`qexp`]: a vector of length `θ/2 ∈ [0, π]`
/// (`q` and `−q` have different logarithms; align signs first).
pub fn qlog(q: DQuat) -> DVec3 {
    let v = q.xyz();
    let s = v.length();
    if s < SMALL_ANGLE {
        // atan2(s, w)/s → 1/w for s → 0; w ≈ ±1 here.
        return v / q.w;
    }
    v * (s.atan2(q.w) / s)
}

/// Spherical linear interpolation of unit quaternions *without* choosing the shorter arc (Squad's
/// inner interpolation needs the raw great-circle arc); falls back to normalised linear
/// interpolation when the angle is below [`SMALL_ANGLE`].
pub fn slerp_raw(a: DQuat, b: DQuat, t: f64) -> DQuat {
    let d = a.dot(b).clamp(-1.0, 1.0);
    let theta = d.acos();
    if theta < SMALL_ANGLE {
        return (a * (1.0 - t) + b * t).normalize();
    }
    let s = theta.sin();
    a * (((1.0 - t) * theta).sin() / s) + b * ((t * theta).sin() / s)
}

/// `b` or `−b`, whichever has a non-negative dot product with `a` (the same rotation, on the
/// shorter arc from `a`).
pub fn align(a: DQuat, b: DQuat) -> DQuat {
    if a.dot(b) < 0.0 {
        -b
    } else {
        b
    }
}

/// The quaternions with signs chosen so that consecutive dot products are non-negative (the sign
/// rule of Chaudhry & Cameron eq. 9 and of Ramamoorthi & Barr, docs/math/quaternion-splines.md §1): the first is kept.
pub fn canonical_signs(qs: &[DQuat]) -> Vec<DQuat> {
    let mut out: Vec<DQuat> = Vec::with_capacity(qs.len());
    for &q in qs {
        let q = match out.last() {
            Some(&prev) => align(prev, q),
            None => q,
        };
        out.push(q);
    }
    out
}

/// Rotation (as a unit quaternion) of a non-zero, possibly non-unit quaternion: `Q/|Q|`.
/// A zero quaternion gives the identity (callers guarantee `|Q| > 0`).
pub fn normalised(q: DQuat) -> DQuat {
    let n = q.length();
    if n > 0.0 && n.is_finite() {
        q / n
    } else {
        DQuat::IDENTITY
    }
}

/// World-frame angular velocity and angular acceleration of the rotation `Q(t)/|Q(t)|` from a
/// possibly non-unit curve `Q` and its first two derivatives:
///
/// ```text
/// ω = 2 vec(Q' Q*) / |Q|²
/// α = dω/dt = 2 vec(Q'' Q*) / |Q|² − ω · 2 (Q·Q') / |Q|²      (vec(Q' Q'*) = 0)
/// ```
pub fn angular_rates(q: DQuat, q1: DQuat, q2: DQuat) -> (DVec3, DVec3) {
    let b = q.length_squared();
    if b.is_nan() || b <= 0.0 {
        return (DVec3::ZERO, DVec3::ZERO);
    }
    let qc = q.conjugate();
    let omega = (q1 * qc).xyz() * (2.0 / b);
    let alpha = (q2 * qc).xyz() * (2.0 / b) - omega * (2.0 * q.dot(q1) / b);
    (omega, alpha)
}

/// Unit quaternion curve derivative from a world-frame angular velocity: `Q' = ½ (0, ω) Q`.
pub fn velocity_from_omega(omega: DVec3, q: DQuat) -> DQuat {
    DQuat::from_xyzw(omega.x, omega.y, omega.z, 0.0) * q * 0.5
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn matrix_is_sandwich_and_polarisation() {
        let p = DQuat::from_xyzw(0.3, -0.2, 0.5, 0.9);
        let q = DQuat::from_xyzw(-0.7, 0.1, 0.4, 0.2);
        let v = DVec3::new(0.4, -1.3, 0.8);
        let vq = DQuat::from_xyzw(v.x, v.y, v.z, 0.0);
        let direct = (p * vq * p.conjugate()).xyz();
        assert!((unnormalised_matrix(p) * v - direct).length() < 1e-15);
        let sym = ((p * vq * q.conjugate() + q * vq * p.conjugate()) * 0.5).xyz();
        assert!((polar_matrix(p, q) * v - sym).length() < 1e-15);
        let r = DMat3::from_quat(p.normalize());
        let m = unnormalised_matrix(p) * (1.0 / p.length_squared());
        assert!((r - m).to_cols_array().iter().all(|e| e.abs() < 1e-15));
    }

    #[test]
    fn exp_log_round_trip() {
        for v in [
            DVec3::new(0.3, -0.2, 1.1),
            DVec3::new(1e-10, 0.0, 2e-10),
            DVec3::ZERO,
            DVec3::new(0.0, 3.0, 0.0),
        ] {
            let q = qexp(v);
            assert!((q.length() - 1.0).abs() < 1e-15);
            assert!((qlog(q) - v).length() < 1e-14, "{v}");
        }
    }

    #[test]
    fn rates_of_a_scaled_uniform_rotation() {
        // Q(t) = s(t) exp(t n θ/2) with a varying scale: ω = θ n, α = 0.
        let n = DVec3::new(1.0, 2.0, -2.0) / 3.0;
        let theta = 0.8;
        let t = 0.4;
        let u = qexp(n * (theta * t / 2.0));
        let (s, s1, s2) = (1.0 + t * t, 2.0 * t, 2.0);
        let nq = DQuat::from_xyzw(n.x, n.y, n.z, 0.0) * (theta / 2.0);
        let u1 = nq * u;
        let u2 = nq * nq * u;
        let q = u * s;
        let q1 = u1 * s + u * s1;
        let q2 = u2 * s + u1 * (2.0 * s1) + u * s2;
        let (w, a) = angular_rates(q, q1, q2);
        assert!((w - n * theta).length() < 1e-15);
        assert!(a.length() < 1e-15);
    }
}
