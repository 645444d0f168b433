//! The batched full screws (`Pose::blends`, several at a time on SIMD lanes) against
//! `screw(a, t, b)` one at a time, bit for bit: random pairs mixed with the rare cases (no
//! rotation, identical and opposite-sign rotations, half turns, fractions beyond the fast sine
//! range), every batch length around the lane widths (the groups and the scalar tail), appended
//! after poses already in the output.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use glam::{DQuat, DVec3};
use screwbender::{screw, Blend, Pose};
use testkit::{pose_bits as bits, Rng};

#[test]
fn batched_screws_are_the_one_at_a_time_screws_bit_for_bit() {
    let mut rng = Rng::new(0x05EE_D0B1_E4D5);
    for n in (0..=40).chain([255, 1000]) {
        // One rare pair in about ten (so most groups are regular and some are not).
        let pairs: Vec<(Pose, Pose)> = (0..n)
            .map(|_| {
                let kind = rng.next_u64() % 48;
                rng.screw_pair(kind)
            })
            .collect();
        let ts: Vec<f64> = (0..n)
            .map(|i| match i % 11 {
                0 => 0.0,
                1 => 1.0,
                2 => 0.5,
                // Beyond the fast sine range for any angle above 1e-5 rad.
                3 => 3e10,
                _ => rng.range(-2.0, 3.0),
            })
            .collect();
        // Appended after what is in the output already, which stays as it was.
        let before = Pose::new(DVec3::new(1.0, 2.0, 3.0), DQuat::IDENTITY);
        let mut out = vec![before; 3];
        Pose::blends(n, |i| (&pairs[i].0, ts[i], &pairs[i].1), &mut out);
        assert_eq!(out.len(), n + 3, "n = {n}");
        for p in &out[..3] {
            assert_eq!(bits(p), bits(&before), "n = {n}: earlier output changed");
        }
        for (i, got) in out[3..].iter().enumerate() {
            let (a, b) = &pairs[i];
            let want = screw(a, ts[i], b);
            assert_eq!(bits(got), bits(&want), "n = {n}, pair {i}, t = {}", ts[i]);
            // A real screw (not a default or a copy): unit rotation, finite origin.
            assert!(
                (got.rotation.length() - 1.0).abs() < 1e-12,
                "n = {n}, pair {i}"
            );
            assert!(got.origin.is_finite(), "n = {n}, pair {i}");
        }
    }
}
