//! Arithmetic on one `f64` or on several side by side (SIMD lanes), so that the screw kernel is
//! written once and runs either on one screw or on several independent screws at a time.
//!
//! Why several at a time: one screw is a long chain of dependent operations (a square root, two
//! divisions, an arctangent and a sine/cosine in a row), so a single evaluation leaves most of
//! the processor idle. Independent screws side by side fill it, and each lane operation is one
//! SIMD instruction for all of them (SSE2, NEON and wasm SIMD hold two `f64`, AVX four).
//! Batches of screws (the subdivision's spans, `screwPairs` in JavaScript) go through
//! [`run_widest`]; a single call uses `f64`.
//!
//! The folder, from the bottom up: `real.rs` holds the common types ([`Real`], [`Width`],
//! [`LanesOp`]); the backends implement them: `portable.rs` (`Lanes<N>`: SSE2, NEON),
//! `avx.rs` (four lanes, AVX2), `avx512.rs` (eight lanes) and `wasm.rs` (wasm SIMD, two and
//! four lanes); `dispatch.rs` picks the widest at run time; `vectors.rs` has the 3-vectors and
//! quaternions of lanes; `trig.rs` the branch-free elementary functions on them.

#[cfg(all(lanes, target_arch = "x86_64"))]
mod avx;
#[cfg(all(lanes, target_arch = "x86_64"))]
mod avx512;
#[cfg(lanes)]
mod dispatch;
pub(crate) mod pair;
#[cfg(portable_lanes)]
mod portable;
mod real;
pub(crate) mod trig;
mod vectors;
#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
mod wasm;

#[cfg(lanes)]
pub(crate) use dispatch::run_widest;
#[cfg(all(test, lanes))]
pub(crate) use dispatch::tests::with_max_width;
#[cfg(all(test, portable_lanes))]
use portable::Lanes;
pub(crate) use real::Real;
#[cfg(lanes)]
pub(crate) use real::{LanesOp, Width};
pub(crate) use vectors::{Q, V3};

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    /// Every lane operation of `proto`'s kind gives, lane by lane, the bits of the one-lane
    /// operation: NaN, infinities, signed zeros, subnormals and the quadrant bit tricks
    /// included.
    pub(crate) fn lanes_match_one_lane<L: Width<N>, const N: usize>(proto: L) {
        let values = [
            1.5,
            -2.0,
            0.25,
            3.0,
            0.0,
            -0.0,
            1e-300,
            -1e300,
            f64::NAN,
            f64::INFINITY,
            7.0,
            0.1,
            2.5,
            -0.75,
            5e-324,
            -f64::INFINITY,
        ];
        let same = |got: L, want: [f64; N], what: &str| {
            for (k, w) in want.iter().enumerate() {
                assert_eq!(
                    got.lane(k).to_bits(),
                    w.to_bits(),
                    "{what}, lane {k} of {N}"
                );
            }
        };
        for start in 0..values.len() {
            let x: [f64; N] = std::array::from_fn(|k| values[(start + k) % values.len()]);
            let y: [f64; N] = std::array::from_fn(|k| values[(start + 3 * k + 5) % values.len()]);
            let (a, b) = (proto.gather(|k| x[k]), proto.gather(|k| y[k]));
            let each = |f: fn(f64, f64) -> f64| std::array::from_fn(|k| f(x[k], y[k]));
            same(a, x, "gather");
            let rows = proto.rows4(|k| [x[k], y[k], -x[k], x[k] * y[k]]);
            same(rows[0], x, "rows4, first entry");
            same(rows[1], y, "rows4, second entry");
            same(rows[2], x.map(|p| -p), "rows4, third entry");
            same(rows[3], each(|p, q| p * q), "rows4, fourth entry");
            same(a + b, each(|p, q| p + q), "add");
            same(a - b, each(|p, q| p - q), "sub");
            same(a * b, each(|p, q| p * q), "mul");
            same(a / b, each(|p, q| p / q), "div");
            same(-a, x.map(|p| -p), "neg");
            same(a.sqrt(), x.map(f64::sqrt), "sqrt");
            same(a.min(b), each(Real::min), "min");
            same(a.max(b), each(Real::max), "max");
            same(a.sign_one(), x.map(Real::sign_one), "sign_one");
            same(proto.constant(x[0]), [x[0]; N], "constant");
            // gt_step is specified for non-negative finite operands.
            let (fx, fy) = (x.map(finite_abs), y.map(finite_abs));
            let (fa, fb) = (proto.gather(|k| fx[k]), proto.gather(|k| fy[k]));
            let steps = std::array::from_fn(|k| Real::gt_step(fx[k], fy[k]));
            same(fa.gt_step(fb), steps, "gt_step");
            assert_eq!(a.all(|v| !v.is_nan()), x.iter().all(|v| !v.is_nan()), "all");
            let q: [f64; N] =
                std::array::from_fn(|k| 6755399441055744.0 + ((start + k) % 8) as f64);
            let (gs, gc) = Real::quadrant(proto.gather(|k| q[k]), a, b);
            let want: [(f64, f64); N] = std::array::from_fn(|k| Real::quadrant(q[k], x[k], y[k]));
            same(gs, want.map(|w| w.0), "quadrant sine");
            same(gc, want.map(|w| w.1), "quadrant cosine");
        }
    }

    fn finite_abs(v: f64) -> f64 {
        if v.is_finite() {
            v.abs()
        } else {
            1.0
        }
    }

    #[test]
    fn steps_and_signs() {
        assert_eq!(2.0.gt_step(1.0), 1.0);
        assert_eq!(1.0.gt_step(2.0), 0.0);
        assert_eq!(1.0.gt_step(1.0), 0.0);
        assert_eq!(0.0.gt_step(0.0), 0.0);
        assert_eq!(1e-300.gt_step(0.0), 1.0);
        assert_eq!((-0.0f64).sign_one(), -1.0);
        assert_eq!(0.0f64.sign_one(), 1.0);
        assert_eq!(Real::min(1.0, f64::NAN).to_bits(), f64::NAN.to_bits());
        assert_eq!(Real::max(2.0, 1.0), 2.0);
    }

    #[cfg(portable_lanes)]
    #[test]
    fn two_lanes_match_one_lane() {
        lanes_match_one_lane(Lanes([0.0; 2]));
    }

    #[cfg(all(lanes, target_arch = "x86_64"))]
    #[test]
    fn avx_lanes_match_one_lane() {
        // Run only where the processor has the instructions; where it lacks them the test
        // passes without testing those lanes, so it says so in the log (written to the
        // process's stderr directly: the test harness keeps a passing test's `eprintln!`).
        use std::io::Write;
        let missing = |what: &str| {
            let _ = writeln!(
                std::io::stderr(),
                "avx_lanes_match_one_lane: NOT TESTED here, the processor lacks {what}"
            );
        };
        match avx::Avx4::detect() {
            Some(proto) => lanes_match_one_lane(proto),
            None => missing("AVX2 (x86-64-v3): the 4-lane AVX path"),
        }
        match avx512::Avx8::detect() {
            Some(proto) => lanes_match_one_lane(proto),
            None => missing("AVX-512 (x86-64-v4): the 8-lane AVX-512 path"),
        }
    }

    #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
    #[wasm_bindgen_test::wasm_bindgen_test]
    fn wasm_lanes_match_one_lane() {
        lanes_match_one_lane(wasm::Wasm2::zero());
        lanes_match_one_lane(wasm::Wasm4::zero());
    }

    #[test]
    fn product_with_the_conjugate_has_an_exactly_zero_vector_part() {
        let mut x = 0.123_456_789f64;
        for _ in 0..1000 {
            x = (x * 3.7 + 0.31).fract();
            let q = Q::new(x - 0.5, 0.3 - x * x, x * 0.7 - 0.2, 0.9 - x).scale(0.8);
            for r in [q, q.scale(-1.0)] {
                let p = r.mul(q.conjugate());
                assert_eq!([p.x, p.y, p.z], [0.0; 3], "{q:?}");
            }
        }
    }
}
