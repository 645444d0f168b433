//! Rigid poses: an origin and a unit rotation.

use glam::{DMat3, DMat4, DQuat, DVec3};

use crate::error::{check_finite, Error, ErrorKind};

/// How far from 1 the norm of a user-given quaternion may be; within it the quaternion is
/// normalised, beyond it [`Pose::from_wxyz`] returns [`ErrorKind::NonUnitQuaternion`](crate::ErrorKind::NonUnitQuaternion).
///
/// `1e-3` accepts quaternions typed by hand with three decimals (`[0.707, 0, 0, 0.707]` has norm
/// 0.99985) and rejects anything that is clearly not meant to be a rotation.
pub const UNIT_QUATERNION_TOLERANCE: f64 = 1e-3;

/// Largest accepted entry of `|RᵀR − I|` for a user-given basis `I, J, K` (see
/// [`Pose::from_basis`]); within it the basis is projected to the nearest rotation.
///
/// `1e-4` accepts bases printed with five or six decimals.
pub const ORTHONORMAL_TOLERANCE: f64 = 1e-4;

/// Largest accepted magnitude of a user-given origin coordinate: `1e100`.
///
/// Far beyond any physical scene (an `f64` resolves a millimetre only up to about `1e12`), and
/// small enough that squared lengths and subdivision weights never overflow (`(1e100)² = 1e200`):
/// every accepted pose gives finite results. Larger coordinates are refused with
/// [`ErrorKind::OutOfRange`](crate::ErrorKind::OutOfRange) naming `origin`.
pub const MAX_COORDINATE: f64 = 1e100;

/// Checks a user-given origin: finite, each coordinate within [`MAX_COORDINATE`].
fn check_origin(origin: &[f64; 3]) -> Result<(), Error> {
    check_finite(origin, "origin")?;
    match origin.iter().find(|v| v.abs() > MAX_COORDINATE) {
        Some(v) => Err(Error::new(
            "origin",
            ErrorKind::OutOfRange {
                value: format!("{v:e}"),
                expected: format!("coordinates within ±{MAX_COORDINATE:e}"),
            },
        )),
        None => Ok(()),
    }
}

/// A rigid pose `L = [O, I, J, K]`: the origin `O` and the rotation whose matrix has columns
/// `I, J, K` (images of the local x, y, z axes).
///
/// As a transform it maps local to world coordinates: `p_world = O + R p_local`.
/// `rotation` is always a unit quaternion; `q` and `−q` are the same pose, so poses are compared
/// with [`Pose::approx_eq`] / [`Pose::distance`], never by raw components.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pose {
    /// The origin `O` (world coordinates).
    pub origin: DVec3,
    /// The rotation, a unit quaternion (glam's Hamilton convention).
    pub rotation: DQuat,
}

impl Default for Pose {
    fn default() -> Self {
        Pose::IDENTITY
    }
}

impl Pose {
    /// The world frame itself.
    pub const IDENTITY: Pose = Pose {
        origin: DVec3::ZERO,
        rotation: DQuat::IDENTITY,
    };

    /// A pose from an origin and a rotation that the caller guarantees to be a unit quaternion.
    ///
    /// For untrusted input use [`Pose::from_wxyz`] or [`Pose::from_basis`].
    pub const fn new(origin: DVec3, rotation: DQuat) -> Pose {
        Pose { origin, rotation }
    }

    /// A pure translation.
    pub const fn from_translation(origin: DVec3) -> Pose {
        Pose::new(origin, DQuat::IDENTITY)
    }

    /// A rotation by `angle` radians about the unit `axis`, right-hand rule, at the world origin.
    pub fn from_axis_angle(axis: DVec3, angle: f64) -> Pose {
        Pose::new(DVec3::ZERO, DQuat::from_axis_angle(axis, angle))
    }

    /// A pose from an origin and a quaternion in the crate's file/API order `[w, x, y, z]`.
    ///
    /// The quaternion must be finite, non-zero and of norm within [`UNIT_QUATERNION_TOLERANCE`]
    /// of 1; it is then normalised. The origin must be finite with coordinates within
    /// [`MAX_COORDINATE`]. Errors name `origin` or `rotation`.
    pub fn from_wxyz(origin: [f64; 3], rotation: [f64; 4]) -> Result<Pose, Error> {
        if let Some(pose) = Pose::from_valid_wxyz(origin, rotation) {
            return Ok(pose);
        }
        check_origin(&origin)?;
        let q = quat_from_wxyz(rotation).map_err(|e| e.within("rotation"))?;
        Ok(Pose::new(DVec3::from_array(origin), q))
    }

    /// [`Pose::from_wxyz`] for valid input, `None` otherwise: the common case without building
    /// a `Result` whose error owns strings, for batches of poses from JavaScript (which spent
    /// most of their validation time on it otherwise).
    #[inline]
    pub fn from_valid_wxyz(origin: [f64; 3], rotation: [f64; 4]) -> Option<Pose> {
        // `!(|v| > max)` would let NaN through; `|v| <= max` is false for NaN.
        let origin_ok = origin
            .iter()
            .fold(true, |ok, v| ok & (v.abs() <= MAX_COORDINATE));
        let q = normalized_quat(rotation).filter(|_| origin_ok)?;
        Some(Pose::new(DVec3::from_array(origin), q))
    }

    /// A pose from an origin and the basis vectors `I, J, K` (images of the local axes).
    ///
    /// The basis must be finite, orthonormal within [`ORTHONORMAL_TOLERANCE`] and right-handed.
    /// It is *not* silently repaired beyond that: use [`Pose::from_basis_orthonormalized`] to
    /// accept any non-degenerate right-handed basis.
    pub fn from_basis(origin: [f64; 3], basis: [[f64; 3]; 3]) -> Result<Pose, Error> {
        check_origin(&origin)?;
        let m = basis_matrix(basis)?;
        let gram = m.transpose() * m;
        let deviation = (gram - DMat3::IDENTITY)
            .to_cols_array()
            .iter()
            .fold(0.0f64, |acc, v| acc.max(v.abs()));
        if deviation > ORTHONORMAL_TOLERANCE {
            return Err(Error::new(
                "basis",
                ErrorKind::NotOrthonormal {
                    deviation,
                    tolerance: ORTHONORMAL_TOLERANCE,
                },
            ));
        }
        if m.determinant() < 0.0 {
            return Err(Error::new("basis", ErrorKind::LeftHanded));
        }
        Ok(Pose::new(DVec3::from_array(origin), quat_from_matrix(&m)))
    }

    /// Like [`Pose::from_basis`], but first re-orthonormalises the basis by Gram–Schmidt
    /// (`I` kept in direction, `J` made orthogonal to it, `K = I × J` sign-checked).
    ///
    /// Fails only for non-finite, degenerate (linearly dependent) or left-handed bases.
    pub fn from_basis_orthonormalized(
        origin: [f64; 3],
        basis: [[f64; 3]; 3],
    ) -> Result<Pose, Error> {
        check_origin(&origin)?;
        let m = basis_matrix(basis)?;
        let det = m.determinant();
        let scale = m.x_axis.length() * m.y_axis.length() * m.z_axis.length();
        // `scale` is a product of lengths of finite vectors: zero for a zero column.
        if scale == 0.0 || det.abs() <= 1e-9 * scale {
            return Err(Error::new(
                "basis",
                ErrorKind::NotOrthonormal {
                    deviation: 1.0,
                    tolerance: ORTHONORMAL_TOLERANCE,
                },
            ));
        }
        if det < 0.0 {
            return Err(Error::new("basis", ErrorKind::LeftHanded));
        }
        let i = m.x_axis.normalize();
        let j = (m.y_axis - i * i.dot(m.y_axis)).normalize();
        let k = i.cross(j);
        let r = DMat3::from_cols(i, j, k);
        Ok(Pose::new(DVec3::from_array(origin), quat_from_matrix(&r)))
    }

    /// The rotation as `[w, x, y, z]`, scalar first (the crate's file and API order).
    pub fn rotation_wxyz(&self) -> [f64; 4] {
        quat_to_wxyz(self.rotation)
    }

    /// The basis vectors `I, J, K` (columns of the rotation matrix).
    pub fn basis(&self) -> [DVec3; 3] {
        let m = DMat3::from_quat(self.rotation);
        [m.x_axis, m.y_axis, m.z_axis]
    }

    /// The 4×4 homogeneous matrix (column-major in glam) mapping local to world coordinates.
    pub fn to_matrix(&self) -> DMat4 {
        DMat4::from_rotation_translation(self.rotation, self.origin)
    }

    /// Composition `self ∘ other` as transforms: first `other`, then `self`.
    ///
    /// `(A∘B).R = A.R B.R`, `(A∘B).O = A.R B.O + A.O`. With `other` a change of local frame `C`,
    /// `A∘C` is the same placement described in another local frame.
    pub fn compose(&self, other: &Pose) -> Pose {
        Pose::new(
            self.rotation * other.origin + self.origin,
            renormalize(self.rotation * other.rotation),
        )
    }

    /// The inverse transform: `A⁻¹ = (Aᵀ.R, −A.Rᵀ A.O)`.
    pub fn inverse(&self) -> Pose {
        let r = self.rotation.conjugate();
        Pose::new(-(r * self.origin), r)
    }

    /// Maps a point from local to world coordinates: `O + R p`.
    pub fn transform_point(&self, p: DVec3) -> DVec3 {
        self.rotation * p + self.origin
    }

    /// Maps a direction from local to world coordinates: `R v`.
    pub fn transform_vector(&self, v: DVec3) -> DVec3 {
        self.rotation * v
    }

    /// Rotation angle between the two frames in radians, in `[0, π]` (independent of quaternion
    /// signs).
    pub fn angle_to(&self, other: &Pose) -> f64 {
        let d = self.rotation.conjugate() * other.rotation;
        let v = DVec3::new(d.x, d.y, d.z).length();
        2.0 * v.atan2(d.w.abs())
    }

    /// A distance between poses: `|O₁ − O₀| + angle(R₀, R₁)` (length units plus radians).
    ///
    /// It is zero exactly when the poses are equal and ignores the quaternion sign.
    pub fn distance(&self, other: &Pose) -> f64 {
        (self.origin - other.origin).length() + self.angle_to(other)
    }

    /// Whether both the origin distance and the rotation angle are at most `tol`.
    pub fn approx_eq(&self, other: &Pose, tol: f64) -> bool {
        (self.origin - other.origin).length() <= tol && self.angle_to(other) <= tol
    }

    /// Whether every component is finite.
    pub fn is_finite(&self) -> bool {
        self.origin.is_finite() && self.rotation.is_finite()
    }
}

/// Converts `[w, x, y, z]` to a unit quaternion, validating it (see [`Pose::from_wxyz`]).
pub fn quat_from_wxyz(q: [f64; 4]) -> Result<DQuat, Error> {
    if let Some(unit) = normalized_quat(q) {
        return Ok(unit);
    }
    // Only errors are left: say which.
    check_finite(&q, "")?;
    let norm = q.iter().map(|c| c * c).sum::<f64>().sqrt();
    if norm == 0.0 {
        return Err(Error::new(String::new(), ErrorKind::ZeroQuaternion));
    }
    Err(Error::new(
        String::new(),
        ErrorKind::NonUnitQuaternion {
            norm,
            tolerance: UNIT_QUATERNION_TOLERANCE,
        },
    ))
}

/// `[w, x, y, z]` normalised, or `None` when it is not finite or its norm is not within
/// [`UNIT_QUATERNION_TOLERANCE`] of 1 (zero included).
#[inline]
fn normalized_quat(q: [f64; 4]) -> Option<DQuat> {
    let [w, x, y, z] = q;
    let norm_squared = w * w + x * x + y * y + z * z;
    // Quaternions already unit to rounding pass through untouched, so reading back a pose this
    // crate wrote (a saved session, an exported document) gives the same bits, and validating
    // twice changes nothing (the rule of `checked_pose`). NaN, from any non-finite component,
    // fails every comparison below.
    if unit_to_rounding(norm_squared) {
        return Some(DQuat::from_xyzw(x, y, z, w));
    }
    let norm = norm_squared.sqrt();
    let off = (norm - 1.0).abs();
    if off.is_nan() || off > UNIT_QUATERNION_TOLERANCE {
        return None;
    }
    Some(DQuat::from_xyzw(x / norm, y / norm, z / norm, w / norm))
}

/// Whether a quaternion of squared norm `norm_squared` is unit to rounding (its norm within
/// about 4 ε of 1), so that validation keeps it as it is. Decided on the squared norm, without
/// a square root: this is the common case of every pose read, in batches of thousands from
/// JavaScript. False for NaN.
#[inline]
pub(crate) fn unit_to_rounding(norm_squared: f64) -> bool {
    (norm_squared - 1.0).abs() <= 8.0 * f64::EPSILON
}

/// The quaternion as `[w, x, y, z]` — the one place where glam's `x, y, z, w` storage order is
/// converted to the crate's scalar-first order.
pub fn quat_to_wxyz(q: DQuat) -> [f64; 4] {
    [q.w, q.x, q.y, q.z]
}

fn basis_matrix(basis: [[f64; 3]; 3]) -> Result<DMat3, Error> {
    for (k, v) in basis.iter().enumerate() {
        check_finite(v, &format!("basis[{k}]"))?;
    }
    Ok(DMat3::from_cols(
        DVec3::from_array(basis[0]),
        DVec3::from_array(basis[1]),
        DVec3::from_array(basis[2]),
    ))
}

/// Rotation matrix → unit quaternion by Shepperd's method (largest pivot first, so it is accurate
/// for every angle including π), normalised, with `w ≥ 0`.
pub(crate) fn quat_from_matrix(m: &DMat3) -> DQuat {
    let (m00, m11, m22) = (m.x_axis.x, m.y_axis.y, m.z_axis.z);
    // m.col(c).row(r) = m[r][c]; name entries as rXY = row X column Y.
    let (r01, r02) = (m.y_axis.x, m.z_axis.x);
    let (r10, r12) = (m.x_axis.y, m.z_axis.y);
    let (r20, r21) = (m.x_axis.z, m.y_axis.z);
    let tr = m00 + m11 + m22;
    let q = if tr >= m00 && tr >= m11 && tr >= m22 {
        let w = 0.5 * (1.0 + tr).sqrt();
        let s = 0.25 / w;
        DQuat::from_xyzw((r21 - r12) * s, (r02 - r20) * s, (r10 - r01) * s, w)
    } else if m00 >= m11 && m00 >= m22 {
        let x = 0.5 * (1.0 + 2.0 * m00 - tr).sqrt();
        let s = 0.25 / x;
        DQuat::from_xyzw(x, (r01 + r10) * s, (r02 + r20) * s, (r21 - r12) * s)
    } else if m11 >= m22 {
        let y = 0.5 * (1.0 + 2.0 * m11 - tr).sqrt();
        let s = 0.25 / y;
        DQuat::from_xyzw((r01 + r10) * s, y, (r12 + r21) * s, (r02 - r20) * s)
    } else {
        let z = 0.5 * (1.0 + 2.0 * m22 - tr).sqrt();
        let s = 0.25 / z;
        DQuat::from_xyzw((r02 + r20) * s, (r12 + r21) * s, z, (r10 - r01) * s)
    };
    let q = q.normalize();
    if q.w < 0.0 {
        -q
    } else {
        q
    }
}

/// Renormalises a quaternion that is unit up to rounding (keeps composition chains from
/// drifting away from unit length), with the screw kernel's Newton step.
#[inline]
pub(crate) fn renormalize(q: DQuat) -> DQuat {
    crate::lanes::Q::from(q).renormalized().into()
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn wxyz_round_trip_and_normalisation() {
        let p = Pose::from_wxyz([1.0, 2.0, 3.0], [0.707, 0.0, 0.0, 0.707]).unwrap();
        let [w, x, y, z] = p.rotation_wxyz();
        assert!((w * w + x * x + y * y + z * z - 1.0).abs() < 1e-15);
        assert!((w - z).abs() < 1e-15 && x == 0.0 && y == 0.0);
    }

    #[test]
    fn bad_quaternions_are_named() {
        let e = Pose::from_wxyz([0.0; 3], [0.0; 4]).unwrap_err();
        assert_eq!(e.to_string(), "rotation: zero quaternion");
        let e = Pose::from_wxyz([0.0; 3], [2.0, 0.0, 0.0, 0.0]).unwrap_err();
        assert!(
            matches!(e.kind(), ErrorKind::NonUnitQuaternion { norm, .. } if e.path() == "rotation" && *norm == 2.0)
        );
        let e = Pose::from_wxyz([f64::NAN, 0.0, 0.0], [1.0, 0.0, 0.0, 0.0]).unwrap_err();
        assert_eq!(e.path(), "origin");
        let e = Pose::from_wxyz([0.0; 3], [1.0, f64::INFINITY, 0.0, 0.0]).unwrap_err();
        assert_eq!(e.path(), "rotation");
    }

    #[test]
    fn basis_validation() {
        let rz = [[0.0, 1.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, 1.0]];
        let p = Pose::from_basis([0.0; 3], rz).unwrap();
        let expect = DQuat::from_rotation_z(PI / 2.0);
        assert!(p.rotation.dot(expect).abs() > 1.0 - 1e-15);
        let left = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, -1.0]];
        assert!(matches!(
            Pose::from_basis([0.0; 3], left)
                .as_ref()
                .map_err(|e| e.kind()),
            Err(ErrorKind::LeftHanded)
        ));
        let skew = [[1.0, 0.1, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
        assert!(matches!(
            Pose::from_basis([0.0; 3], skew)
                .as_ref()
                .map_err(|e| e.kind()),
            Err(ErrorKind::NotOrthonormal { .. })
        ));
        let fixed = Pose::from_basis_orthonormalized([0.0; 3], skew).unwrap();
        let [i, _, _] = fixed.basis();
        assert!((i - DVec3::new(1.0, 0.1, 0.0).normalize()).length() < 1e-15);
        let flat = [[1.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 0.0, 1.0]];
        assert!(Pose::from_basis_orthonormalized([0.0; 3], flat).is_err());
    }

    #[test]
    fn shepperd_near_pi() {
        for axis in [
            DVec3::X,
            DVec3::Y,
            DVec3::Z,
            DVec3::new(1.0, -2.0, 0.5).normalize(),
        ] {
            for angle in [0.0, 1e-9, 1.0, PI - 1e-9, PI] {
                let q = DQuat::from_axis_angle(axis, angle);
                let back = quat_from_matrix(&DMat3::from_quat(q));
                assert!(back.dot(q).abs() > 1.0 - 1e-15, "{axis} {angle}");
            }
        }
    }

    #[test]
    fn compose_inverse_transform() {
        let a = Pose::new(DVec3::new(1.0, 2.0, 3.0), DQuat::from_rotation_y(0.7));
        let b = Pose::new(DVec3::new(-1.0, 0.5, 2.0), DQuat::from_rotation_x(-1.2));
        let p = DVec3::new(0.3, -0.4, 0.9);
        let ab = a.compose(&b);
        assert!((ab.transform_point(p) - a.transform_point(b.transform_point(p))).length() < 1e-14);
        assert!(a.compose(&a.inverse()).approx_eq(&Pose::IDENTITY, 1e-15));
        let m = ab.to_matrix();
        assert!((m.transform_point3(p) - ab.transform_point(p)).length() < 1e-14);
        assert!((a.transform_vector(p) - a.rotation * p).length() == 0.0);
    }

    #[test]
    fn distance_ignores_quaternion_sign() {
        let a = Pose::new(DVec3::X, DQuat::from_rotation_z(0.3));
        let b = Pose::new(DVec3::X, -a.rotation);
        assert!(a.distance(&b) < 1e-15);
        assert!(a.approx_eq(&b, 1e-15));
        let c = Pose::new(DVec3::Y, DQuat::from_rotation_z(0.8));
        assert!((a.distance(&c) - (2f64.sqrt() + 0.5)).abs() < 1e-14);
    }
}
