//! Helpers shared by the integration tests (native and wasm32 alike: no clocks, files or threads).
#![allow(dead_code)]

#[cfg(not(target_arch = "wasm32"))]
pub mod cli;
#[cfg(target_arch = "wasm32")]
pub mod js;

use glam::{DQuat, DVec2, DVec3};
use screwbender::{Pose, Scheme};

/// A pose from an origin and a `[w, x, y, z]` quaternion that may be rounded (normalised here).
pub fn pose(o: [f64; 3], q: [f64; 4]) -> Pose {
    Pose::new(
        DVec3::from_array(o),
        DQuat::from_xyzw(q[1], q[2], q[3], q[0]).normalize(),
    )
}

/// Asserts that two poses agree: origins within `tol` and rotations within `tol` radians
/// (quaternion sign ignored). Prints both poses on failure.
#[track_caller]
pub fn assert_pose_near(got: &Pose, want: &Pose, tol: f64, what: &str) {
    let dx = (got.origin - want.origin).length();
    let da = got.angle_to(want);
    assert!(
        dx <= tol && da <= tol,
        "{what}: poses differ (|Δo| = {dx:.3e}, angle = {da:.3e}, tol {tol:.1e})\n  got  {:?} {:?}\n  want {:?} {:?}",
        got.origin,
        got.rotation_wxyz(),
        want.origin,
        want.rotation_wxyz()
    );
}

/// Asserts two vectors agree to `tol`.
#[track_caller]
pub fn assert_vec_near(got: DVec3, want: DVec3, tol: f64, what: &str) {
    let d = (got - want).length();
    assert!(
        d <= tol,
        "{what}: |Δ| = {d:.3e} > {tol:.1e}\n  got  {got:?}\n  want {want:?}"
    );
}

/// The largest pose error between two equally long sequences.
pub fn max_pose_error(a: &[Pose], b: &[Pose]) -> f64 {
    assert_eq!(a.len(), b.len(), "sequence lengths differ");
    a.iter()
        .zip(b)
        .map(|(p, q)| (p.origin - q.origin).length() + p.angle_to(q))
        .fold(0.0, f64::max)
}

/// A small deterministic generator (splitmix64) so property tests are reproducible and run the
/// same natively and in the browser. Failing cases print their seed and index.
pub struct Rng(u64);

impl Rng {
    /// A generator from a seed.
    pub fn new(seed: u64) -> Rng {
        Rng(seed)
    }
    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform in `[0, 1)`.
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }
    /// Uniform in `[lo, hi)`.
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }
    /// A uniformly random unit vector.
    pub fn direction(&mut self) -> DVec3 {
        loop {
            let v = DVec3::new(
                self.range(-1.0, 1.0),
                self.range(-1.0, 1.0),
                self.range(-1.0, 1.0),
            );
            let l = v.length();
            if l > 0.1 && l <= 1.0 {
                return v / l;
            }
        }
    }
    /// A uniformly random rotation.
    pub fn rotation(&mut self) -> DQuat {
        loop {
            let q = DQuat::from_xyzw(
                self.range(-1.0, 1.0),
                self.range(-1.0, 1.0),
                self.range(-1.0, 1.0),
                self.range(-1.0, 1.0),
            );
            let l = q.length();
            if l > 0.1 && l <= 1.0 {
                return q / l;
            }
        }
    }
    /// A random pose with origin in `[-scale, scale]³`.
    pub fn pose(&mut self, scale: f64) -> Pose {
        let o = DVec3::new(
            self.range(-scale, scale),
            self.range(-scale, scale),
            self.range(-scale, scale),
        );
        Pose::new(o, self.rotation())
    }
    /// A pose displaced from `p` by a random screw of angle at most `max_angle`.
    pub fn pose_near(&mut self, p: &Pose, max_angle: f64, step: f64) -> Pose {
        let rot = DQuat::from_axis_angle(self.direction(), self.range(0.0, max_angle));
        let move_ = self.direction() * self.range(0.0, step);
        Pose::new(p.origin + move_, (rot * p.rotation).normalize())
    }
    /// A smooth-ish random cycle: consecutive poses differ by at most `max_angle` radians.
    pub fn cycle(&mut self, n: usize, max_angle: f64) -> Vec<Pose> {
        let mut poses = vec![self.pose(3.0)];
        for _ in 1..n {
            let next = self.pose_near(poses.last().unwrap(), max_angle, 3.0);
            poses.push(next);
        }
        poses
    }
}

/// Spec §4 (`screwbender.md`): one subdivision step of the L polygon (scene A4 `polygon_l`) by
/// each point scheme, the same for both rule sets.
pub fn l_polygon_one_step() -> Vec<(Scheme, Vec<DVec2>)> {
    let points =
        |pts: &[[f64; 2]]| -> Vec<DVec2> { pts.iter().map(|p| DVec2::from_array(*p)).collect() };
    vec![
        (
            Scheme::BSpline,
            points(&[
                [0.75, 0.75],
                [3.0, 0.0],
                [5.25, 0.25],
                [6.0, 1.0],
                [5.5, 1.75],
                [4.0, 2.0],
                [2.5, 2.5],
                [2.0, 4.0],
                [1.75, 5.5],
                [1.0, 6.0],
                [0.25, 5.25],
                [0.0, 3.0],
            ]),
        ),
        (
            Scheme::FourPoint,
            points(&[
                [0.0, 0.0],
                [3.0, -0.5],
                [6.0, 0.0],
                [6.625, 1.0],
                [6.0, 2.0],
                [4.0, 1.875],
                [2.0, 2.0],
                [1.875, 4.0],
                [2.0, 6.0],
                [1.0, 6.625],
                [0.0, 6.0],
                [-0.5, 3.0],
            ]),
        ),
        (
            Scheme::Jarek,
            points(&[
                [0.375, 0.375],
                [3.0, -0.25],
                [5.625, 0.125],
                [6.3125, 1.0],
                [5.75, 1.875],
                [4.0, 1.9375],
                [2.25, 2.25],
                [1.9375, 4.0],
                [1.875, 5.75],
                [1.0, 6.3125],
                [0.125, 5.625],
                [-0.25, 3.0],
            ]),
        ),
    ]
}
