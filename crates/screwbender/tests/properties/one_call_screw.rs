//! The one-call `screw(a, t, b)` (compiled for AVX2 where the processor has it) against the
//! two-step route `Screw::between(a, b).at(t)` (compiled for the baseline processor), bit for
//! bit: the same operations in the same order, whatever instructions encode them. Random pairs
//! mixed with the rare cases (no rotation, identical and opposite-sign rotations, half turns,
//! fractions beyond the fast sine range).

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use screwbender::{screw, Screw};
use testkit::{pose_bits as bits, Rng};

#[test]
fn one_call_screw_is_the_two_step_screw_bit_for_bit() {
    say_if_the_avx2_route_is_untested();
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

/// Without AVX2 and FMA (x86-64-v3) the one-call screw takes the baseline route too, and the test
/// compares that route with itself: the log says so (on the process's stderr directly, which the
/// test harness does not keep back for a passing test).
fn say_if_the_avx2_route_is_untested() {
    #[cfg(target_arch = "x86_64")]
    {
        if !(std::is_x86_feature_detected!("avx2") && std::is_x86_feature_detected!("fma")) {
            use std::io::Write;
            let _ = writeln!(
                std::io::stderr(),
                "one_call_screw_is_the_two_step_screw_bit_for_bit: the AVX2 route is NOT TESTED \
                 here, the processor lacks AVX2 and FMA (x86-64-v3)"
            );
        }
    }
}
