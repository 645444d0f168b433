//! The one operation every subdivision rule is built from: `blend(a, t, b)`.
//!
//! For points it is the affine combination `a + t (b − a)`; for poses it is `screw(a, t, b)`
//! (spec §5: "every affine combination is replaced by a nesting of screw calls"). Writing the rules
//! once, generically, makes the point (polygon) versions of spec §4 *the same code* as the pose
//! versions, so the reduction of every pose rule to its point rule holds by construction.

use glam::{DVec2, DVec3};

use crate::pose::Pose;
use crate::screw::Screw;

/// A space with an interpolation `blend(a, t, b)` defined for every real `t`, where `t = 0` gives
/// `a` and `t = 1` gives `b`.
///
/// `Span` caches whatever depends only on `(a, b)` (for poses, the screw logarithm), so a rule
/// that evaluates the same pair at several `t` pays for the logarithm once.
pub trait Blend: Copy {
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
}

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
    fn midpoint(a: &Self, b: &Self) -> Self {
        Screw::midpoint(a, b)
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
