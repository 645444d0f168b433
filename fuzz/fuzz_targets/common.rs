//! Shared input shapes and checks of the fuzz targets.
#![allow(dead_code)]

use arbitrary::Arbitrary;
use screwbender::Pose;

/// Every accepted origin is within this (the validators refuse larger coordinates), so every
/// result must be finite.
pub const FINITE_CHECK_SCALE: f64 = screwbender::MAX_COORDINATE;

/// A pose drawn so that the interesting regions are likely: scales 1e-12..1e12, rotations at
/// and near 0 and π, raw (non-unit, zero, non-finite) quaternions through the validator.
#[derive(Arbitrary, Debug, Clone)]
pub struct PoseIn {
    mantissa: [i32; 3],
    exponent: i8,
    kind: u8,
    axis: [i16; 3],
    small: u8,
    raw_origin: [f64; 3],
    raw_q: [f64; 4],
}

impl PoseIn {
    /// The `[origin, wxyz]` pair, to be validated by `Pose::from_wxyz`.
    pub fn raw(&self) -> ([f64; 3], [f64; 4]) {
        let scale = 10f64.powi(i32::from(self.exponent % 13));
        let origin = if self.kind >= 200 {
            self.raw_origin
        } else {
            self.mantissa
                .map(|m| f64::from(m) / f64::from(i32::MAX) * scale)
        };
        let axis = self.axis.map(f64::from);
        let len = (axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]).sqrt();
        let axis = if len == 0.0 {
            [0.0, 0.0, 1.0]
        } else {
            axis.map(|a| a / len)
        };
        let eps = 10f64.powi(-i32::from(self.small % 17));
        let angle = match self.kind % 6 {
            0 => 0.0,
            1 => eps,
            2 => std::f64::consts::PI - eps,
            3 => std::f64::consts::PI,
            4 => f64::from(self.small) * (std::f64::consts::TAU / 255.0),
            _ => return (origin, self.raw_q),
        };
        let (s, c) = (0.5 * angle).sin_cos();
        (origin, [c, axis[0] * s, axis[1] * s, axis[2] * s])
    }

    /// The validated pose, or `None` when the validator refused it (which must not panic).
    pub fn pose(&self) -> Option<Pose> {
        let (o, q) = self.raw();
        let direct = Pose::from_wxyz(o, q);
        if direct.is_ok() {
            return direct.ok();
        }
        // Normalise raw quaternions so that arbitrary rotations get through too.
        let n = (q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]).sqrt();
        if n.is_finite() && n > 1e-150 {
            Pose::from_wxyz(o, q.map(|c| c / n)).ok()
        } else {
            None
        }
    }
}

/// Largest origin coordinate magnitude.
pub fn scale_of(poses: &[Pose]) -> f64 {
    poses
        .iter()
        .map(|p| p.origin.abs().max_element())
        .fold(0.0, f64::max)
}

/// Asserts a finite pose with a unit rotation (to `1e-12`).
#[track_caller]
pub fn assert_sane(p: &Pose, what: &str) {
    assert!(p.is_finite(), "{what}: non-finite pose {p:?}");
    let n = p.rotation.length();
    assert!(
        (n - 1.0).abs() <= 1e-12,
        "{what}: rotation norm {n} in {p:?}"
    );
}
