//! The one-call `screw(a, t, b)` (compiled for AVX2 where the processor has it) against the
//! two-step route `Screw::between(a, b).at(t)` (compiled for the baseline processor), bit for
//! bit: the same operations in the same order, whatever instructions encode them. Random pairs
//! mixed with the rare cases (no rotation, identical and opposite-sign rotations, half turns,
//! fractions beyond the fast sine range).

use screwbender::{screw, Screw};
use testkit::{pose_bits as bits, Rng};

#[test]
fn one_call_screw_is_the_two_step_screw_bit_for_bit() {
    let mut rng = Rng::new(0x0DD_CA11);
    for i in 0..20_000 {
        let (a, b) = rng.screw_pair(i % 13);
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
