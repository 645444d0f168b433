//! The tests' random numbers: splitmix64, the same on every target.

use glam::{DQuat, DVec3};
use screwbender::Pose;

/// A small deterministic generator (splitmix64) so property tests are reproducible and run the
/// same natively and in the browser. Failing cases print their seed and index.
pub struct Rng(u64);

impl Rng {
    /// A generator from a seed.
    pub fn new(seed: u64) -> Rng {
        Rng(seed)
    }
    /// The state, from which [`Rng::new`] continues the same stream.
    pub fn state(&self) -> u64 {
        self.0
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
    /// A pair of poses for a screw between them: a random start (origin in `[-5, 5]³`), the end
    /// shifted by up to 3 per axis and rotated by the case `kind` names, the rare cases of the
    /// screw kernel first: `0` no rotation, `1` the same rotation with the opposite sign, `2` a
    /// half turn, `3` the same pose, `4` a rotation of 1e-9 rad; any other `kind` a random
    /// rotation.
    pub fn screw_pair(&mut self, kind: u64) -> (Pose, Pose) {
        let a = self.pose(5.0);
        let shift = DVec3::new(
            self.range(-3.0, 3.0),
            self.range(-3.0, 3.0),
            self.range(-3.0, 3.0),
        );
        let b = match kind {
            0 => Pose::new(a.origin + shift, a.rotation),
            1 => Pose::new(a.origin + shift, -a.rotation),
            2 => Pose::new(
                a.origin + shift,
                DQuat::from_axis_angle(self.direction(), std::f64::consts::PI) * a.rotation,
            ),
            3 => a,
            4 => Pose::new(
                a.origin + shift,
                DQuat::from_axis_angle(self.direction(), 1e-9) * a.rotation,
            ),
            _ => Pose::new(a.origin + shift, self.rotation()),
        };
        (a, b)
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
