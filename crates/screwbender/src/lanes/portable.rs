//! The portable lanes: `N` plain `f64`s that the compiler packs into SIMD registers where it
//! can (two lanes on SSE2 and NEON). Used everywhere but wasm32 with `simd128`, which has its own
//! (`wasm.rs`).

use std::ops::{Add, Div, Mul, Neg, Sub};

use super::real::{quadrant_lane, Real, Width};

/// `N` `f64` lanes, computed together: one SIMD instruction per operation where the compiler
/// packs them into registers (two lanes on SSE2 and NEON), independent instruction streams
/// otherwise.
#[cfg(portable_lanes)]
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(transparent)]
pub(crate) struct Lanes<const N: usize>(pub [f64; N]);

// stack traffic keep the compiler from packing the lanes into SIMD registers).
#[cfg(portable_lanes)]
macro_rules! lanes_of_width {
    ($n:literal: $($k:literal)*) => {
        impl Width<$n> for Lanes<$n> {
            #[inline(always)]
            fn gather(self, f: impl Fn(usize) -> f64) -> Self {
                Lanes([$(f($k)),*])
            }
            #[inline(always)]
            fn lane(self, k: usize) -> f64 {
                self.0[k]
            }
        }

        impl Lanes<$n> {
            /// Applies `f` to each lane.
            #[inline(always)]
            fn map(self, f: impl Fn(f64) -> f64) -> Self {
                Lanes([$(f(self.0[$k])),*])
            }
            /// Applies `f` lane by lane to two operands.
            #[inline(always)]
            fn zip(self, other: Self, f: impl Fn(f64, f64) -> f64) -> Self {
                Lanes([$(f(self.0[$k], other.0[$k])),*])
            }
        }

        impl Add for Lanes<$n> {
            type Output = Self;
            #[inline(always)]
            fn add(self, o: Self) -> Self {
                self.zip(o, |a, b| a + b)
            }
        }
        impl Sub for Lanes<$n> {
            type Output = Self;
            #[inline(always)]
            fn sub(self, o: Self) -> Self {
                self.zip(o, |a, b| a - b)
            }
        }
        impl Mul for Lanes<$n> {
            type Output = Self;
            #[inline(always)]
            fn mul(self, o: Self) -> Self {
                self.zip(o, |a, b| a * b)
            }
        }
        impl Div for Lanes<$n> {
            type Output = Self;
            #[inline(always)]
            fn div(self, o: Self) -> Self {
                self.zip(o, |a, b| a / b)
            }
        }
        impl Neg for Lanes<$n> {
            type Output = Self;
            #[inline(always)]
            fn neg(self) -> Self {
                self.map(|a| -a)
            }
        }

        impl Real for Lanes<$n> {
            #[inline(always)]
            fn constant(self, v: f64) -> Self {
                Lanes([v; $n])
            }
            // Every lane is tested (no early exit): one branch on the combined answer.
            #[inline(always)]
            fn all(self, f: impl Fn(f64) -> bool) -> bool {
                true $(& f(self.0[$k]))*
            }
            #[inline(always)]
            fn sqrt(self) -> Self {
                self.map(f64::sqrt)
            }
            #[inline(always)]
            fn min(self, other: Self) -> Self {
                self.zip(other, <f64 as Real>::min)
            }
            #[inline(always)]
            fn max(self, other: Self) -> Self {
                self.zip(other, <f64 as Real>::max)
            }
            #[inline(always)]
            fn sign_one(self) -> Self {
                self.map(<f64 as Real>::sign_one)
            }
            #[inline(always)]
            fn gt_step(self, other: Self) -> Self {
                self.zip(other, <f64 as Real>::gt_step)
            }
            #[inline(always)]
            fn quadrant(rounded: Self, s: Self, c: Self) -> (Self, Self) {
                let lanes = [$(quadrant_lane(rounded.0[$k], s.0[$k], c.0[$k])),*];
                (Lanes([$(lanes[$k].0),*]), Lanes([$(lanes[$k].1),*]))
            }
        }
    };
}
#[cfg(portable_lanes)]
lanes_of_width!(2: 0 1);
