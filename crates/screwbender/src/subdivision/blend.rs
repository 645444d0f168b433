//! The one operation every subdivision rule is built from: `blend(a, t, b)`.
//!
//! For points it is the affine combination `a + t (b − a)`; for poses it is `screw(a, t, b)`
//! (docs/math/subdivision.md §1: "every affine combination is replaced by a nesting of screw calls"). Writing the rules
//! once, generically, makes the point (polygon) versions of docs/math/point-rules.md *the same code* as the pose
//! versions, so the reduction of every pose rule to its point rule holds by construction.

use glam::{DVec2, DVec3};

use crate::pose::Pose;
#[cfg(lanes)]
use crate::screw::batch;
use crate::screw::Screw;

/// A space with an interpolation `blend(a, t, b)` defined for every real `t`, where `t = 0` gives
/// `a` and `t = 1` gives `b`.
///
/// `Span` caches whatever depends only on `(a, b)` (for poses, the screw logarithm), so a rule
/// that evaluates the same pair at several `t` pays for the logarithm once. (`'static`: a
/// subdivision keeps its working buffers on its thread for the next one, whatever their
/// element type.)
pub trait Blend: Copy + 'static {
    /// The precomputed interpolant between two elements.
    type Span: Copy;
    /// Precomputes the interpolant from `a` to `b`.
    fn span(a: &Self, b: &Self) -> Self::Span;
    /// Evaluates a precomputed interpolant at `t` (any real number).
    fn span_at(span: &Self::Span, t: f64) -> Self;
    /// `blend(a, t, b)` without caching.
    #[inline]
    fn blend(a: &Self, t: f64, b: &Self) -> Self {
        Self::span_at(&Self::span(a, b), t)
    }
    /// `blend(a, ½, b)`, which a space may compute more cheaply (the outer blend of every
    /// subdivision rule is a midpoint).
    #[inline]
    fn midpoint(a: &Self, b: &Self) -> Self {
        Self::blend(a, 0.5, b)
    }

    /// Appends `midpoint(x, y)` for `(x, y) = pair(i)`, `i = 0..n`, to `out`. A space may
    /// compute several at once (poses do, on SIMD lanes); the results are those of
    /// [`Blend::midpoint`]. `pair` hands out references, so that a batch reads its inputs where
    /// they are instead of copying them.
    fn midpoints<'a>(n: usize, pair: impl Fn(usize) -> (&'a Self, &'a Self), out: &mut Vec<Self>)
    where
        Self: 'a,
    {
        out.extend((0..n).map(|i| {
            let (x, y) = pair(i);
            Self::midpoint(x, y)
        }));
    }

    /// Appends `blend(x, t, y)` for `(x, t, y) = item(i)`, `i = 0..n`, to `out` (several at once
    /// where the space can; the results are those of [`Blend::blend`]).
    fn blends<'a>(n: usize, item: impl Fn(usize) -> (&'a Self, f64, &'a Self), out: &mut Vec<Self>)
    where
        Self: 'a,
    {
        out.extend((0..n).map(|i| {
            let (x, t, y) = item(i);
            Self::blend(x, t, y)
        }));
    }

    /// For every span `p[i] → p[(i+1) mod n]` of the cycle `p` and every fraction `ts[j]`, sets
    /// `out[j][i]` to the span's value at `ts[j]` (each `out[j]` is cleared first): all the
    /// evaluations of one subdivision step, each span's interpolant computed once.
    fn sample_cycle(p: &[Self], ts: &[f64], out: &mut [Vec<Self>]) {
        for column in out.iter_mut() {
            column.clear();
        }
        let n = p.len();
        for i in 0..n {
            let span = Self::span(&p[i], &p[(i + 1) % n]);
            for (column, &t) in out.iter_mut().zip(ts) {
                column.push(Self::span_at(&span, t));
            }
        }
    }
}

/// Poses blend by screws. Their batch methods run several screws at a time on SIMD lanes
/// (`screw::batch`: eight with AVX-512, four with AVX2 or wasm SIMD, two with SSE2 or NEON) where
/// that pays: natively, and on wasm32 built with `simd128`. Plain wasm32 has no SIMD, the
/// interleaved lanes gained nothing there (docs/speed/code-notes.md), and their code would only
/// add to the module, so it keeps the one-at-a-time defaults.
impl Blend for Pose {
    type Span = Screw;
    #[inline]
    fn span(a: &Self, b: &Self) -> Screw {
        Screw::between(a, b)
    }
    #[inline]
    fn span_at(span: &Screw, t: f64) -> Self {
        span.at(t)
    }
    #[inline]
    fn blend(a: &Self, t: f64, b: &Self) -> Self {
        crate::screw::screw(a, t, b)
    }
    #[inline]
    fn midpoint(a: &Self, b: &Self) -> Self {
        Screw::midpoint(a, b)
    }
    #[cfg(lanes)]
    fn midpoints<'a>(n: usize, pair: impl Fn(usize) -> (&'a Self, &'a Self), out: &mut Vec<Self>) {
        batch::midpoints(n, pair, out);
    }
    #[cfg(lanes)]
    fn blends<'a>(
        n: usize,
        item: impl Fn(usize) -> (&'a Self, f64, &'a Self),
        out: &mut Vec<Self>,
    ) {
        batch::screws(n, item, out);
    }
    #[cfg(lanes)]
    fn sample_cycle(p: &[Self], ts: &[f64], out: &mut [Vec<Self>]) {
        batch::sample_cycle(p, ts, out);
    }
}

macro_rules! affine_blend {
    ($($ty:ty),*) => {$(
        impl Blend for $ty {
            type Span = ($ty, $ty);
            #[inline]
            fn span(a: &Self, b: &Self) -> ($ty, $ty) {
                (*a, *b - *a)
            }
            #[inline]
            fn span_at(span: &($ty, $ty), t: f64) -> Self {
                span.0 + span.1 * t
            }
        }
    )*};
}

affine_blend!(f64, DVec2, DVec3);
