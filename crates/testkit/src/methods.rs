//! Helpers of the comparison methods' tests (`methods_*`): a generator of test data and small
//! assertion helpers (no clock, no threads, no files: the same code runs under wasm).

use glam::{DQuat, DVec3};
use screwbender::methods::RbOptions;
use screwbender::Pose;

use crate::rng::Rng;

/// splitmix64: a small deterministic generator for property tests (same on every target).
pub struct SplitMix(pub u64);

impl SplitMix {
    /// Uniform in `[0, 1)`: the same splitmix64 stream as [`Rng::unit`].
    pub fn uniform(&mut self) -> f64 {
        let mut rng = Rng::new(self.0);
        let v = rng.unit();
        self.0 = rng.state();
        v
    }

    /// Uniform in `[a, b)`.
    pub fn range(&mut self, a: f64, b: f64) -> f64 {
        a + (b - a) * self.uniform()
    }

    /// A random unit vector.
    pub fn unit(&mut self) -> DVec3 {
        loop {
            let v = DVec3::new(
                self.range(-1., 1.),
                self.range(-1., 1.),
                self.range(-1., 1.),
            );
            if v.length() > 0.1 && v.length() < 1.0 {
                return v.normalize();
            }
        }
    }

    /// A random pose with origin within `scale` and rotation angle up to `max_angle`.
    pub fn pose(&mut self, scale: f64, max_angle: f64) -> Pose {
        let o = self.unit() * self.range(0.0, scale);
        Pose::new(
            o,
            DQuat::from_axis_angle(self.unit(), self.range(0.0, max_angle)),
        )
    }
}

/// Quaternion from `[w, x, y, z]` without normalisation.
pub fn wxyz(q: [f64; 4]) -> DQuat {
    DQuat::from_xyzw(q[1], q[2], q[3], q[0])
}

/// Asserts that the quaternion `q` equals `[w, x, y, z]` within `tol` per component.
pub fn assert_quat_near(q: DQuat, e: [f64; 4], tol: f64, what: &str) {
    let got = [q.w, q.x, q.y, q.z];
    let ok = got.iter().zip(e).all(|(g, e)| (g - e).abs() <= tol);
    assert!(ok, "{what}: got {got:?}, expected {e:?} (tol {tol:e})");
}

/// Asserts `|a − b|_∞ ≤ tol`.
pub fn assert_vec_near(a: DVec3, b: [f64; 3], tol: f64, what: &str) {
    assert!(
        (a - DVec3::from_array(b)).abs().max_element() <= tol,
        "{what}: got {a:?}, expected {b:?} (tol {tol:e})"
    );
}

/// Asserts a relative difference.
pub fn assert_rel(got: f64, want: f64, tol: f64, what: &str) {
    assert!(
        (got - want).abs() <= tol * want.abs().max(1e-300),
        "{what}: got {got}, expected {want} (relative tol {tol:e})"
    );
}

/// Scene C1's keyframes (`presets.md`, the preset `rb_sphere7`), keyframe `i` at `t = i`.
pub fn sphere7() -> (Vec<f64>, Vec<DQuat>) {
    let scene = screwbender::presets::preset("rb_sphere7").expect("scene C1");
    let q: Vec<DQuat> = scene.poses.iter().map(|p| p.rotation).collect();
    ((0..q.len()).map(|i| i as f64).collect(), q)
}

/// Ramamoorthi–Barr options of scene C1: zero end angular velocities, `frames` variable frames,
/// and no early stop (the table of docs/math/quaternion-splines.md §8 runs all rounds).
pub fn sphere7_options(frames: usize) -> RbOptions {
    RbOptions {
        omega_start: Some(DVec3::ZERO),
        omega_end: Some(DVec3::ZERO),
        variable_frames: frames,
        min_relative_decrease: 0.0,
        ..RbOptions::default()
    }
}

/// The poses of scene A2 `l_cycle_rotated` (presets.md), cyclic: the library's preset.
pub fn l_cycle_rotated() -> Vec<Pose> {
    screwbender::presets::preset("l_cycle_rotated")
        .expect("preset A2 exists")
        .poses
}
