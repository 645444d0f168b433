//! The screw's arithmetic (docs/math/screw.md §4), written once over [`Real`] lanes: [`crate::Screw`] runs it
//! on one `f64`, the batch routines of `screw::batch` on several screws at a time.
//!
//! Only the regular case lives here ([`regular_span`], [`regular_at`] say `None` otherwise); the
//! rare cases that need a decision (no rotation, a half turn, arguments outside the fast
//! trigonometric range, non-finite values) are left to [`crate::Screw`]'s careful route.
//!
//! With `D = b ∘ a⁻¹` (rotation by `θ` about unit `n`, translation `t_D`), `d = n·t_D` and
//! `u = t_D − d n`, the screw is
//!
//! ```text
//! q(t) = cos(tθ/2) q₀ + sin(tθ/2) (n, 0) q₀
//! O(t) = O₀ + t d n + sin(tθ/2) cos(tθ/2) E + sin²(tθ/2) (n × E),
//!        E = cot(θ/2) u + n × (2 O₀ − t_D)
//! ```
//!
//! which is docs/math/screw.md §4's `O(t) = Rot(n, tθ) O₀ + t d n + [sin(tθ/2)/sin(θ/2)] Rot(n, (t−1)θ/2) u`
//! with `Rot(n, tθ) O₀` and the `u` term expanded by the half-angle identities: everything that
//! depends only on the span folds into `E`, and an evaluation needs no division.

use crate::lanes::trig;
use crate::lanes::{Real, Q, V3};

/// Half-turn detection: when the relative quaternion has `|w| ≤ HALF_TURN_EPSILON` the rotation
/// is a half turn (π within ~2e-12 rad) and two minimal screws exist; the deterministic tie-break
/// of [`crate::Screw::between`] picks one.
pub const HALF_TURN_EPSILON: f64 = 1e-12;

/// Sine of the half angle at or below which the relative rotation counts as none (angles below
/// `2·10⁻¹⁵⁰` rad; the rotation part of such a screw moves no unit vector by a representable
/// amount, and its translation is kept exactly). Below it `cot(θ/2)` could overflow.
pub(crate) const MIN_ROTATION_SINE: f64 = 1e-150;

/// The relative displacement `D = b ∘ a⁻¹` of two poses, before any decision.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Relative<R> {
    /// `sin(θ/2) n`: the vector part of the relative rotation, taken with `w ≥ 0`.
    pub v: V3<R>,
    /// `cos(θ/2) ≥ 0`.
    pub w: R,
    /// `|v| = sin(θ/2)`.
    pub s: R,
    /// `t_D = O_b − R_D O_a`.
    pub translation: V3<R>,
}

/// The relative displacement from pose `(oa, qa)` to pose `(ob, qb)`.
///
/// The relative rotation is taken the short way round (`w ≥ 0`) by multiplying by `±1` rather
/// than branching on the sign of `w`, which is a coin toss for unrelated poses.
#[inline(always)]
pub(crate) fn relative<R: Real>(oa: V3<R>, qa: Q<R>, ob: V3<R>, qb: Q<R>) -> Relative<R> {
    let qd = qb.mul(qa.conjugate());
    let qd = qd.scale(qd.w.sign_one());
    let v = qd.xyz();
    Relative {
        v,
        w: qd.w,
        s: v.dot(v).sqrt(),
        translation: ob - qd.rotate(oa),
    }
}

/// A span with a rotation, in the regular case, ready for evaluation.
#[derive(Clone, Copy, Debug)]
pub(crate) struct RegularSpan<R> {
    /// Start origin `O₀`.
    pub oa: V3<R>,
    /// Start rotation `q₀`.
    pub qa: Q<R>,
    /// The half angle `θ/2`.
    pub half_angle: R,
    /// `sin(θ/2)`.
    pub s: R,
    /// `cos(θ/2)`.
    pub w: R,
    /// The evaluation coefficients.
    pub coefficients: Coefficients<R>,
}

/// The span from `(oa, qa)` to `(ob, qb)` (in every lane), or `None` when any lane is a rare
/// case: no rotation (which includes identical rotations, whose relative rotation is exactly
/// zero), a rotation within [`HALF_TURN_EPSILON`] of a half turn, or non-finite values. In the
/// regular case the screw needs no decision, and the result is that of [`crate::Screw::between`]
/// bit for bit.
#[inline(always)]
pub(crate) fn regular_span<R: Real>(
    oa: V3<R>,
    qa: Q<R>,
    ob: V3<R>,
    qb: Q<R>,
) -> Option<RegularSpan<R>> {
    regular_span_with::<R, false>(oa, qa, ob, qb, true)
}

/// [`regular_span`], its `half_angle` left 0 unless `angle`: a midpoint needs only `sin(θ/2)`
/// and `cos(θ/2)` ([`regular_midpoint`]), and the arctangent is the longest step of the chain.
/// (Inlined natively, a constant `angle` removes the arctangent or the test; in wasm's one
/// out-of-line copy of the batch's span it is a predictable branch.) With `GROUPS` (the batches)
/// the arctangent is [`trig::atan2_kernel_lanes`], which skips the kernel's two steps for a group
/// of short spans; the one-`f64` route keeps [`trig::atan2_kernel`], where one call's angle says
/// nothing about the next (the bench's random pairs ran slower with the test:
/// docs/speed/code-notes.md). Both give
/// the same bits.
#[inline(always)]
#[allow(
    clippy::manual_map,
    reason = "a closure is not always inlined, and out of line it loses the lanes' target features"
)]
pub(crate) fn regular_span_with<R: Real, const GROUPS: bool>(
    oa: V3<R>,
    qa: Q<R>,
    ob: V3<R>,
    qb: Q<R>,
    angle: bool,
) -> Option<RegularSpan<R>> {
    match regular_relative::<R, GROUPS>(oa, qa, ob, qb) {
        Some(rel) => Some(span_start::<R, GROUPS>(oa, qa, rel, angle).complete()),
        None => None,
    }
}

/// The relative displacement from `(oa, qa)` to `(ob, qb)` (in every lane), or `None` when any
/// lane is a rare case (see [`regular_span`]): [`regular_span_with`] up to its decision.
///
/// With `GROUPS` (the batches), natively, the four tests make one branch: the lanes' four
/// comparisons are combined first (in mask registers with AVX-512), so a group pays one
/// predictable branch. The one-`f64` route and wasm32 keep four branches, each taken only on a
/// rare case: there the combining work sits on the call's critical path and costs more than the
/// branches it saves (docs/speed/one-call-screw.md).
#[inline(always)]
pub(crate) fn regular_relative<R: Real, const GROUPS: bool>(
    oa: V3<R>,
    qa: Q<R>,
    ob: V3<R>,
    qb: Q<R>,
) -> Option<Relative<R>> {
    let rel = relative(oa, qa, ob, qb);
    let regular = if GROUPS && !cfg!(target_arch = "wasm32") {
        rel.s.all(|s| s > MIN_ROTATION_SINE && s < f64::INFINITY)
            & rel.w.all(|w| w > HALF_TURN_EPSILON && w < f64::INFINITY)
    } else {
        rel.s.all(|s| s > MIN_ROTATION_SINE)
            && rel.w.all(|w| w > HALF_TURN_EPSILON)
            && rel.s.all(|s| s < f64::INFINITY)
            && rel.w.all(|w| w < f64::INFINITY)
    };
    if regular {
        Some(rel)
    } else {
        None
    }
}

/// A regular span up to its sweep `E`: [`regular_span_with`] after its decision, but for the two
/// products that need nothing else ([`SpanStart::complete`]). The batch of full screws computes
/// the two parts in different stages of its pipeline (`screw::batch`), so that fewer values
/// wait between the stages.
#[derive(Clone, Copy, Debug)]
pub(crate) struct SpanStart<R> {
    oa: V3<R>,
    qa: Q<R>,
    half_angle: R,
    s: R,
    w: R,
    axis: V3<R>,
    slide: R,
    perp: V3<R>,
    sweep: V3<R>,
}

impl<R: Real> SpanStart<R> {
    /// The span.
    #[inline(always)]
    pub(crate) fn complete(self) -> RegularSpan<R> {
        let SpanStart {
            oa,
            qa,
            half_angle,
            s,
            w,
            axis,
            slide,
            perp,
            sweep,
        } = self;
        RegularSpan {
            oa,
            qa,
            half_angle,
            s,
            w,
            coefficients: complete_coefficients(qa, axis, slide, perp, sweep),
        }
    }
}

/// The start of the span from `(oa, qa)` whose relative displacement `rel` is regular (see
/// [`regular_relative`]; `angle` and `GROUPS` as in [`regular_span_with`]).
#[inline(always)]
pub(crate) fn span_start<R: Real, const GROUPS: bool>(
    oa: V3<R>,
    qa: Q<R>,
    rel: Relative<R>,
    angle: bool,
) -> SpanStart<R> {
    let inv_s = rel.s.constant(1.0) / rel.s;
    let axis = rel.v.scale(inv_s);
    let slide = axis.dot(rel.translation);
    let (perp, sweep) = perp_and_sweep(oa, axis, slide, rel.w * inv_s, rel.translation);
    SpanStart {
        oa,
        qa,
        half_angle: if !angle {
            rel.s.constant(0.0)
        } else if GROUPS {
            trig::atan2_kernel_lanes(rel.s, rel.w)
        } else {
            trig::atan2_kernel(rel.s, rel.w)
        },
        s: rel.s,
        w: rel.w,
        axis,
        slide,
        perp,
        sweep,
    }
}

/// The pose at `t` of a regular span, or `None` when `t·θ/2` is outside the fast sine range in
/// any lane (the result is that of [`crate::Screw::at`] bit for bit).
#[inline(always)]
pub(crate) fn regular_at<R: Real>(span: &RegularSpan<R>, t: R) -> Option<(V3<R>, Q<R>)> {
    regular_at_by::<R, false>(span, t)
}

/// [`regular_at`] on one `f64`, bit for bit, through [`trig::sin_cos_kernel_one`] (a
/// predictable branch around the sine's argument reduction).
#[inline(always)]
pub(crate) fn regular_at_one(span: &RegularSpan<f64>, t: f64) -> Option<(V3<f64>, Q<f64>)> {
    regular_at_by::<f64, true>(span, t)
}

/// [`regular_at`], the sine and cosine of `t·θ/2` by [`trig::sin_cos_kernel_one`] if `ONE`
/// (both give the same bits). A constant rather than the function passed as a value: the
/// function item's `FnOnce` shim is not always inlined, and out of line it runs without the
/// target features the batches were compiled for.
#[inline(always)]
fn regular_at_by<R: Real, const ONE: bool>(span: &RegularSpan<R>, t: R) -> Option<(V3<R>, Q<R>)> {
    if !regular_at_fits(span, t) {
        return None;
    }
    let x = t * span.half_angle;
    let (sa, ca) = if ONE {
        trig::sin_cos_kernel_one(x)
    } else {
        trig::sin_cos_kernel_lanes(x)
    };
    Some(evaluate(span.oa, span.qa, &span.coefficients, t, sa, ca))
}

/// Whether [`regular_at`] evaluates the span at `t` (`t·θ/2` in the fast sine range in every
/// lane), so that callers can check all their fractions before producing any result.
#[inline(always)]
pub(crate) fn regular_at_fits<R: Real>(span: &RegularSpan<R>, t: R) -> bool {
    (t * span.half_angle).all(trig::in_sin_cos_range)
}

/// The midpoint (`t = ½`) of a regular span, without a transcendental function (as
/// [`crate::Screw::midpoint`], bit for bit).
#[inline(always)]
pub(crate) fn regular_midpoint<R: Real>(span: &RegularSpan<R>) -> (V3<R>, Q<R>) {
    let (sa, ca) = half_of_half(span.s, span.w);
    evaluate(
        span.oa,
        span.qa,
        &span.coefficients,
        span.s.constant(0.5),
        sa,
        ca,
    )
}

/// What an evaluation needs of a span with a rotation (see the module documentation).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Coefficients<R> {
    /// Unit axis `n`.
    pub axis: V3<R>,
    /// Slide `d`.
    pub slide: R,
    /// `u = t_D − d n`.
    pub perp: V3<R>,
    /// `E`.
    pub sweep: V3<R>,
    /// `n × E`.
    pub sweep_normal: V3<R>,
    /// `(n, 0) q₀`.
    pub axis_rotation: Q<R>,
}

/// The coefficients of the span from `(oa, qa)` with unit axis `axis`, slide `slide`, half-angle
/// cotangent `cot_half` and translation `t_D`.
#[inline(always)]
pub(crate) fn coefficients<R: Real>(
    oa: V3<R>,
    qa: Q<R>,
    axis: V3<R>,
    slide: R,
    cot_half: R,
    translation: V3<R>,
) -> Coefficients<R> {
    let (perp, sweep) = perp_and_sweep(oa, axis, slide, cot_half, translation);
    complete_coefficients(qa, axis, slide, perp, sweep)
}

/// `u` and `E` (see the module documentation) of the span from origin `oa` with unit axis
/// `axis`, slide `slide`, half-angle cotangent `cot_half` and translation `t_D`.
#[inline(always)]
fn perp_and_sweep<R: Real>(
    oa: V3<R>,
    axis: V3<R>,
    slide: R,
    cot_half: R,
    translation: V3<R>,
) -> (V3<R>, V3<R>) {
    let perp = translation - axis.scale(slide);
    let sweep = perp.scale(cot_half) + axis.cross(oa.scale(cot_half.constant(2.0)) - translation);
    (perp, sweep)
}

/// The coefficients from the start rotation `qa`, the axis, the slide, `u` and `E`: the two
/// products left (`n × E` and `(n, 0) q₀`).
#[inline(always)]
fn complete_coefficients<R: Real>(
    qa: Q<R>,
    axis: V3<R>,
    slide: R,
    perp: V3<R>,
    sweep: V3<R>,
) -> Coefficients<R> {
    Coefficients {
        axis,
        slide,
        perp,
        sweep,
        sweep_normal: axis.cross(sweep),
        axis_rotation: qa.premul_vector(axis),
    }
}

/// The pose at `t` of the span from `(oa, qa)`, given `sa = sin(tθ/2)` and `ca = cos(tθ/2)`.
/// The rotation is renormalised (one Newton step), so that errors do not build up over
/// subdivision levels.
#[inline(always)]
pub(crate) fn evaluate<R: Real>(
    oa: V3<R>,
    qa: Q<R>,
    c: &Coefficients<R>,
    t: R,
    sa: R,
    ca: R,
) -> (V3<R>, Q<R>) {
    let (sc, ss) = (sa * ca, sa * sa);
    let origin = oa + c.axis.scale(t * c.slide) + c.sweep.scale(sc) + c.sweep_normal.scale(ss);
    let q = qa.scale(ca).add(c.axis_rotation.scale(sa));
    (origin, q.renormalized())
}

/// `sin(θ/4)` and `cos(θ/4)` from `sin(θ/2) = s` and `cos(θ/2) = w ≥ 0`, without a
/// transcendental function: `cos(θ/4) = √((1 + w)/2)` is well conditioned since `θ/2 ≤ π/2`.
#[inline(always)]
pub(crate) fn half_of_half<R: Real>(s: R, w: R) -> (R, R) {
    let ca = (w.constant(0.5) * (w.constant(1.0) + w)).sqrt();
    (s / (ca + ca), ca)
}
