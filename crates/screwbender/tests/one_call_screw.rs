//! The one-call `screw(a, t, b)` (compiled for AVX2 where the processor has it) against the
//! two-step route `Screw::between(a, b).at(t)` (compiled for the baseline processor), bit for
//! bit: the same operations in the same order, whatever instructions encode them. Random pairs
//! mixed with the rare cases (no rotation, identical and opposite-sign rotations, half turns,
//! fractions beyond the fast sine range).

use glam::{DQuat, DVec3};
use screwbender::{screw, Pose, Screw};
use testkit::Rng;

fn bits(p: &Pose) -> [u64; 7] {
    let (o, q) = (p.origin, p.rotation);
    [o.x, o.y, o.z, q.x, q.y, q.z, q.w].map(f64::to_bits)
}

#[test]
fn one_call_screw_is_the_two_step_screw_bit_for_bit() {
    let mut rng = Rng::new(0x0DD_CA11);
    for i in 0..20_000 {
        let a = Pose::new(
            DVec3::new(
                rng.range(-5.0, 5.0),
                rng.range(-5.0, 5.0),
                rng.range(-5.0, 5.0),
            ),
            rng.rotation(),
        );
        let shift = DVec3::new(
            rng.range(-3.0, 3.0),
            rng.range(-3.0, 3.0),
            rng.range(-3.0, 3.0),
        );
        let rotation = match i % 13 {
            0 => a.rotation,
            1 => -a.rotation,
            2 => DQuat::from_axis_angle(rng.direction(), std::f64::consts::PI) * a.rotation,
            3 => DQuat::from_axis_angle(rng.direction(), 1e-9) * a.rotation,
            _ => rng.rotation(),
        };
        let b = Pose::new(a.origin + shift, rotation);
        let t = match i % 7 {
            0 => 0.0,
            1 => 1.0,
            2 => 3e10,
            _ => rng.range(-2.0, 3.0),
        };
        let got = screw(&a, t, &b);
        assert_eq!(
            bits(&got),
            bits(&Screw::between(&a, &b).at(t)),
            "pair {i}, t = {t}"
        );
        // A real pose: unit rotation, finite origin.
        assert!((got.rotation.length() - 1.0).abs() < 1e-12, "pair {i}");
        assert!(got.origin.is_finite(), "pair {i}");
    }
}
