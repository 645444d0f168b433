//! Many screws at once, several at a time on SIMD lanes (see `lanes` for why): eight or four on
//! x86-64 with AVX-512 or AVX2, two elsewhere ([`run_widest`]).
//!
//! Every routine here gives *bit for bit* what the one-at-a-time [`Screw`] calls give: the lanes
//! run the same kernel (`screw::kernel`) with the same operations in the same order. A group that
//! holds a rare case (no rotation, a half turn, an argument outside the fast sine range, a
//! non-finite value) is handed to the scalar route, which decides those cases.

use crate::lanes::{run_widest, LanesOp, Width, Q, V3};
use crate::pose::Pose;
use crate::screw::kernel::{self as kernel, RegularSpan};
use crate::screw::Screw;

/// `N` poses, lane `k` holding pose `k` (lanes of the kind of `proto`).
#[inline(always)]
fn load<L: Width<N>, const N: usize>(proto: L, p: [&Pose; N]) -> (V3<L>, Q<L>) {
    // By rows of four numbers, which AVX-512 transposes in whole registers (`Width::rows4`),
    // fewer instructions than a `gather` per coordinate (docs/speed/one-call-screw.md). The origin's
    // row carries the rotation's x as a fourth entry, not used, so that the row is the pose's
    // first four numbers (one load where the layout allows).
    let [ox, oy, oz, _] = proto.rows4(|k| {
        let (o, q) = (p[k].origin, p[k].rotation);
        [o.x, o.y, o.z, q.x]
    });
    let [qx, qy, qz, qw] = proto.rows4(|k| p[k].rotation.to_array());
    (V3::new(ox, oy, oz), Q::new(qx, qy, qz, qw))
}

/// Appends the `N` poses held in the lanes to `out`.
#[inline(always)]
fn push<L: Width<N>, const N: usize>(out: &mut Vec<Pose>, (o, q): (V3<L>, Q<L>)) {
    // The poses built in an array, then one copy: one capacity check and one length update
    // per group instead of per pose (a `push` per lane stored and reloaded the length each
    // time, a chain through memory; `extend` over an iterator went through a `fold` that was
    // not inlined, so it ran outside the code compiled for the detected features).
    //
    // Every caller in this file reserves room for all it appends, so the vector never grows
    // here. That is checked by a path that does not return, rather than left to the copy, whose
    // growth path is a call: every number read from the lanes would be live across that call,
    // and V8 keeps such values on the stack, spilling a third of the sampling loop's
    // instructions. An abort, not a panic, in release builds: it is reachable only by a mistake in
    // this file, and a panic's message would be carried by the size-budgeted math module.
    if out.capacity() - out.len() < N {
        if cfg!(debug_assertions) {
            panic!("no room reserved for the lanes");
        }
        std::process::abort();
    }
    let poses: [Pose; N] = std::array::from_fn(|k| {
        Pose::new(
            glam::DVec3::new(o.x.lane(k), o.y.lane(k), o.z.lane(k)),
            glam::DQuat::from_xyzw(q.x.lane(k), q.y.lane(k), q.z.lane(k), q.w.lane(k)),
        )
    });
    out.extend_from_slice(&poses);
}

/// `N` items from `item(i)`, `i = first..first + N`, written in place.
#[inline(always)]
fn group<T: Copy, const N: usize>(first: usize, empty: T, item: impl Fn(usize) -> T) -> [T; N] {
    let mut group = [empty; N];
    for (k, slot) in group.iter_mut().enumerate() {
        *slot = item(first + k);
    }
    group
}

/// The spans `a[k] → b[k]` in the regular case (see [`kernel::regular_span_with`]; `angle`:
/// whether the half angle is needed, not for midpoints).
///
/// Inlined natively (the lanes then stay in registers across the calls, and the code is
/// compiled for the features [`run_widest`] detected); out of line on wasm32 with SIMD, where
/// the callers are instantiated once per closure type and an inlined copy in each would add
/// kilobytes to the module (whose size is budgeted).
#[cfg_attr(target_arch = "wasm32", inline(never))]
#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
fn span_lanes<L: Width<N>, const N: usize>(
    proto: L,
    a: [&Pose; N],
    b: [&Pose; N],
    angle: bool,
) -> Option<RegularSpan<L>> {
    let (oa, qa) = load(proto, a);
    let (ob, qb) = load(proto, b);
    kernel::regular_span_with::<L, true>(oa, qa, ob, qb, angle)
}

/// The poses at `t` of regular spans (see [`kernel::regular_at`]). Inlined or not as
/// [`span_lanes`].
#[cfg_attr(target_arch = "wasm32", inline(never))]
#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
fn at_lanes<L: Width<N>, const N: usize>(span: &RegularSpan<L>, t: L) -> Option<(V3<L>, Q<L>)> {
    kernel::regular_at(span, t)
}

/// The native batch of full screws: three groups in flight ([`pipeline::whole_groups`]).
#[cfg(not(target_arch = "wasm32"))]
#[allow(
    clippy::manual_map,
    reason = "a closure is not always inlined, and out of line it loses the lanes' target features"
)]
mod pipeline {
    use super::*;

    /// A group of full screws after the first stage of [`screws`]' pipeline: the index of its first
    /// screw, its start poses and relative displacements (`None` when a lane is a rare case), its
    /// fractions.
    type Started<L, const N: usize> = (usize, Option<(V3<L>, Q<L>, kernel::Relative<L>)>, [f64; N]);

    /// A group after the second stage: its spans up to their sweeps.
    type Spanned<L, const N: usize> = (usize, Option<kernel::SpanStart<L>>, [f64; N]);

    /// Appends the screws `item(0..k)` of the whole groups of `N` among `item(0..n)`; returns `k`.
    ///
    /// Natively three groups are in flight, each in its own stage, so the processor finds
    /// independent work beside each group's long chain (the square root, the arctangent's
    /// division and series, then the sine and cosine), where one group at a time left it waiting.
    /// The stages run oldest
    /// group first in program order (the last stage of the group started two turns ago, then the
    /// second of the previous one, then the new group's loads): the processor then gives its
    /// ports to the oldest work first, which is also the work whose inputs have waited longest,
    /// and the new group's square root, last, no longer holds up retirement (every order is
    /// measured in docs/speed/one-call-screw.md).
    #[inline(always)]
    pub(super) fn whole_groups<'p, L: Width<N>, const N: usize>(
        proto: L,
        n: usize,
        item: &impl Fn(usize) -> (&'p Pose, f64, &'p Pose),
        out: &mut Vec<Pose>,
    ) -> usize {
        let mut started: Option<Started<L, N>> = None;
        let mut spanned: Option<Spanned<L, N>> = None;
        let mut i = 0;
        while i + N <= n {
            if let Some(group) = spanned.take() {
                finish_group(proto, group, item, out);
            }
            let next = match started.take() {
                Some(group) => Some(span_group(group)),
                None => None,
            };
            let now = start_group(proto, i, item);
            spanned = next;
            started = Some(now);
            i += N;
        }
        if let Some(group) = spanned {
            finish_group(proto, group, item, out);
        }
        if let Some(group) = started {
            finish_group(proto, span_group(group), item, out);
        }
        i
    }

    /// The first stage of [`screws`]' pipeline for the group `item(i..i + N)`: its poses loaded
    /// into lanes, their relative displacements and the decision whether the group is regular.
    #[inline(always)]
    fn start_group<'p, L: Width<N>, const N: usize>(
        proto: L,
        i: usize,
        item: &impl Fn(usize) -> (&'p Pose, f64, &'p Pose),
    ) -> Started<L, N> {
        let group: [_; N] = group(i, (&Pose::IDENTITY, 0.0, &Pose::IDENTITY), item);
        let (oa, qa) = load(proto, group.map(|g| g.0));
        let (ob, qb) = load(proto, group.map(|g| g.2));
        let relative = match kernel::regular_relative::<L, true>(oa, qa, ob, qb) {
            Some(rel) => Some((oa, qa, rel)),
            None => None,
        };
        (i, relative, group.map(|g| g.1))
    }

    /// The second stage: the spans up to their sweeps, with their half angles.
    #[inline(always)]
    fn span_group<L: Width<N>, const N: usize>((i, started, t): Started<L, N>) -> Spanned<L, N> {
        let span = match started {
            Some((oa, qa, rel)) => Some(kernel::span_start::<L, true>(oa, qa, rel, true)),
            None => None,
        };
        (i, span, t)
    }

    /// The last stage: the spans completed and evaluated at their fractions, the poses appended to
    /// `out`; a group with a rare case (or a fraction outside the fast sine range) through the
    /// scalar route.
    #[inline(always)]
    fn finish_group<'p, L: Width<N>, const N: usize>(
        proto: L,
        (i, span, t): Spanned<L, N>,
        item: &impl Fn(usize) -> (&'p Pose, f64, &'p Pose),
        out: &mut Vec<Pose>,
    ) {
        let lanes = match span {
            Some(span) => kernel::regular_at(&span.complete(), proto.gather(|k| t[k])),
            None => None,
        };
        match lanes {
            Some(lanes) => push(out, lanes),
            None => (i..i + N).for_each(|i| {
                let (a, t, b) = item(i);
                out.push(scalar_screw(a, t, b));
            }),
        }
    }
}

#[cfg(not(target_arch = "wasm32"))]
use pipeline::whole_groups;

/// [`whole_groups`] on wasm32: one group at a time ([`screw_group`]). The pipeline's stages,
/// each with the kernel inlined, would grow the math module, whose size is budgeted, for an
/// engine that does not reorder instructions across them.
#[cfg(target_arch = "wasm32")]
#[inline(always)]
fn whole_groups<'p, L: Width<N>, const N: usize>(
    proto: L,
    n: usize,
    item: &impl Fn(usize) -> (&'p Pose, f64, &'p Pose),
    out: &mut Vec<Pose>,
) -> usize {
    let mut i = 0;
    while i + N <= n {
        let group: [_; N] = group(i, (&Pose::IDENTITY, 0.0, &Pose::IDENTITY), item);
        let (a, t, b) = (group.map(|g| g.0), group.map(|g| g.1), group.map(|g| g.2));
        screw_group(proto, a, t, b, out);
        i += N;
    }
    i
}

/// Appends `screw(a[k], t[k], b[k])` for every lane to `out`, through the scalar route when the
/// group holds a rare case: wasm32's batch of full screws, one group at a time ([`whole_groups`]).
/// Out of line, where each batch's closure type would otherwise get its own copy, and through
/// [`span_lanes`] and [`at_lanes`], whose one copy serves the other batches too.
#[cfg(target_arch = "wasm32")]
#[inline(never)]
fn screw_group<L: Width<N>, const N: usize>(
    proto: L,
    a: [&Pose; N],
    t: [f64; N],
    b: [&Pose; N],
    out: &mut Vec<Pose>,
) {
    match span_lanes(proto, a, b, true).and_then(|span| at_lanes(&span, proto.gather(|k| t[k]))) {
        Some(lanes) => push(out, lanes),
        None => (0..N).for_each(|k| out.push(scalar_screw(a[k], t[k], b[k]))),
    }
}

/// Appends `screw(a[k], ½, b[k])` for every lane to `out`, through the scalar route when the
/// group holds a rare case. (Out of line on wasm32, where each batch's closure type would
/// otherwise get its own copy; inlined natively as [`span_lanes`].)
#[cfg_attr(target_arch = "wasm32", inline(never))]
#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
fn midpoint_group<L: Width<N>, const N: usize>(
    proto: L,
    a: [&Pose; N],
    b: [&Pose; N],
    out: &mut Vec<Pose>,
) {
    match span_lanes(proto, a, b, false) {
        Some(span) => push(out, kernel::regular_midpoint(&span)),
        None => (0..N).for_each(|k| out.push(scalar_midpoint(a[k], b[k]))),
    }
}

/// The scalar routes, out of line: they are rare, and one copy serves every caller.
#[inline(never)]
fn scalar_screw(a: &Pose, t: f64, b: &Pose) -> Pose {
    super::screw(a, t, b)
}

#[inline(never)]
fn scalar_midpoint(a: &Pose, b: &Pose) -> Pose {
    Screw::midpoint(a, b)
}

/// Appends `screw(a, t, b)` for `(a, t, b) = item(i)`, `i = 0..n`, to `out`.
pub(crate) fn screws<'p>(
    n: usize,
    item: impl Fn(usize) -> (&'p Pose, f64, &'p Pose),
    out: &mut Vec<Pose>,
) {
    struct Screws<'a, F>(usize, F, &'a mut Vec<Pose>);
    impl<'p, F: Fn(usize) -> (&'p Pose, f64, &'p Pose)> LanesOp for Screws<'_, F> {
        type Output = ();
        #[inline(always)]
        fn run<L: Width<N>, const N: usize>(self, proto: L) {
            let Screws(n, item, out) = self;
            out.reserve(n);
            let i = whole_groups(proto, n, &item, out);
            out.extend((i..n).map(|i| {
                let (a, t, b) = item(i);
                scalar_screw(a, t, b)
            }));
        }
    }
    run_widest(Screws(n, item, out));
}

/// Appends `screw(a, ½, b)` for `(a, b) = pair(i)`, `i = 0..n`, to `out` (as
/// [`Screw::midpoint`]: no transcendental function).
pub(crate) fn midpoints<'p>(
    n: usize,
    pair: impl Fn(usize) -> (&'p Pose, &'p Pose),
    out: &mut Vec<Pose>,
) {
    struct Midpoints<'a, F>(usize, F, &'a mut Vec<Pose>);
    impl<'p, F: Fn(usize) -> (&'p Pose, &'p Pose)> LanesOp for Midpoints<'_, F> {
        type Output = ();
        #[inline(always)]
        fn run<L: Width<N>, const N: usize>(self, proto: L) {
            let Midpoints(n, pair, out) = self;
            out.reserve(n);
            let mut i = 0;
            while i + N <= n {
                let group: [_; N] = group(i, (&Pose::IDENTITY, &Pose::IDENTITY), &pair);
                midpoint_group(proto, group.map(|g| g.0), group.map(|g| g.1), out);
                i += N;
            }
            out.extend((i..n).map(|i| {
                let (a, b) = pair(i);
                scalar_midpoint(a, b)
            }));
        }
    }
    run_widest(Midpoints(n, pair, out));
}

/// For every span `p[i] → p[(i+1) mod n]` of the cycle `p` and every fraction `ts[j]`, sets
/// `out[j][i]` to the span's pose at `ts[j]` (`out[j]` is cleared first). Each span's logarithm
/// is computed once for all the fractions.
pub(crate) fn sample_cycle(p: &[Pose], ts: &[f64], out: &mut [Vec<Pose>]) {
    struct SampleCycle<'a>(&'a [Pose], &'a [f64], &'a mut [Vec<Pose>]);
    impl LanesOp for SampleCycle<'_> {
        type Output = ();
        #[inline(always)]
        fn run<L: Width<N>, const N: usize>(self, proto: L) {
            let SampleCycle(p, ts, out) = self;
            let n = p.len();
            for column in out.iter_mut() {
                column.clear();
                column.reserve(n);
            }
            let next = |i: usize| if i + 1 == n { 0 } else { i + 1 };
            let scalar = |i: usize, out: &mut [Vec<Pose>]| {
                let span = Screw::between(&p[i], &p[next(i)]);
                for (column, &t) in out.iter_mut().zip(ts) {
                    column.push(span.at(t));
                }
            };
            let mut i = 0;
            while i + N <= n {
                let a: [&Pose; N] = std::array::from_fn(|k| &p[i + k]);
                let b = std::array::from_fn(|k| &p[next(i + k)]);
                // Every fraction is checked before any pose is written, so that a rare case
                // sends the whole group to the scalar route.
                let span = span_lanes(proto, a, b, true).filter(|span| {
                    ts.iter()
                        .all(|&t| kernel::regular_at_fits(span, span.s.constant(t)))
                });
                match span {
                    Some(span) => {
                        for (column, &t) in out.iter_mut().zip(ts) {
                            if let Some(lanes) = at_lanes(&span, span.s.constant(t)) {
                                push(column, lanes);
                            }
                        }
                    }
                    None => (i..i + N).for_each(|i| scalar(i, out)),
                }
                i += N;
            }
            (i..n).for_each(|i| scalar(i, out));
        }
    }
    run_widest(SampleCycle(p, ts, out));
}

/// The lanes of `v` as an array.
#[inline(always)]
fn lanes_of<L: Width<N>, const N: usize>(v: L) -> [f64; N] {
    std::array::from_fn(|k| v.lane(k))
}

/// The lanes of three-vectors of lanes, one array per coordinate.
#[inline(always)]
fn v3_lanes<L: Width<N>, const N: usize>(v: &V3<L>) -> [[f64; N]; 3] {
    [lanes_of(v.x), lanes_of(v.y), lanes_of(v.z)]
}

/// Appends the screws of the `N` regular spans of `span`, starting at `starts`, to `out`: the
/// fields [`Screw::between`] fills in, bit for bit (in the regular case its half angle is the
/// same `atan2` kernel, and nothing else is decided).
#[inline(always)]
fn push_screws<L: Width<N>, const N: usize>(
    span: &RegularSpan<L>,
    starts: &[Pose],
    out: &mut Vec<Screw>,
) {
    // Every lane read out once, coordinate by coordinate, before any screw is written.
    let c = &span.coefficients;
    let (half_angle, sin_half, cos_half) = (
        lanes_of(span.half_angle),
        lanes_of(span.s),
        lanes_of(span.w),
    );
    let (axis, slide, perp) = (v3_lanes(&c.axis), lanes_of(c.slide), v3_lanes(&c.perp));
    let (sweep, sweep_normal) = (v3_lanes(&c.sweep), v3_lanes(&c.sweep_normal));
    let q = &c.axis_rotation;
    let rotation = [lanes_of(q.x), lanes_of(q.y), lanes_of(q.z), lanes_of(q.w)];
    let v3 = |v: &[[f64; N]; 3], k: usize| V3::new(v[0][k], v[1][k], v[2][k]);
    let starts: &[Pose; N] = starts.try_into().expect("one start per lane");
    let (origins, rotations) = (
        starts.map(|p| p.origin.to_array()),
        starts.map(|p| p.rotation.to_array()),
    );
    for k in 0..N {
        out.push(Screw {
            start: Pose::new(origins[k].into(), glam::DQuat::from_array(rotations[k])),
            half_angle: half_angle[k],
            sin_half: sin_half[k],
            cos_half: cos_half[k],
            coefficients: kernel::Coefficients {
                axis: v3(&axis, k),
                slide: slide[k],
                perp: v3(&perp, k),
                sweep: v3(&sweep, k),
                sweep_normal: v3(&sweep_normal, k),
                axis_rotation: Q::new(
                    rotation[0][k],
                    rotation[1][k],
                    rotation[2][k],
                    rotation[3][k],
                ),
            },
        });
    }
}

/// Appends the screw of every span `p[i] → p[i+1]` of the sequence `p` (and `p[n−1] → p[0]`
/// when `closed`) to `out`: [`Screw::between`] for each, bit for bit, several spans at a time.
pub(crate) fn span_screws(p: &[Pose], closed: bool, out: &mut Vec<Screw>) {
    struct SpanScrews<'a>(&'a [Pose], bool, &'a mut Vec<Screw>);
    impl LanesOp for SpanScrews<'_> {
        type Output = ();
        #[inline(always)]
        fn run<L: Width<N>, const N: usize>(self, proto: L) {
            let SpanScrews(p, closed, out) = self;
            let n = p.len();
            let count = match (n, closed) {
                (0, _) => 0,
                (_, true) => n,
                (_, false) => n - 1,
            };
            out.reserve(count);
            let next = |i: usize| if i + 1 == n { 0 } else { i + 1 };
            let mut i = 0;
            while i + N <= count {
                let a: [&Pose; N] = std::array::from_fn(|k| &p[i + k]);
                let b = std::array::from_fn(|k| &p[next(i + k)]);
                match span_lanes(proto, a, b, true) {
                    Some(span) => push_screws(&span, &p[i..i + N], out),
                    None => (0..N).for_each(|k| out.push(scalar_span(a[k], b[k]))),
                }
                i += N;
            }
            out.extend((i..count).map(|i| scalar_span(&p[i], &p[next(i)])));
        }
    }
    run_widest(SpanScrews(p, closed, out));
}

#[inline(never)]
fn scalar_span(a: &Pose, b: &Pose) -> Screw {
    Screw::between(a, b)
}

/// Run natively and, on wasm32, by wasm-bindgen-test (in Node): each platform's lanes.
#[cfg(test)]
mod tests {
    use super::*;
    use glam::{DQuat, DVec3};
    #[cfg(target_arch = "wasm32")]
    use wasm_bindgen_test::wasm_bindgen_test as test;

    /// Poses including every rare case next to regular ones: identical, opposite-sign and
    /// nearly identical rotations, half turns, pure translations.
    fn poses() -> Vec<Pose> {
        let mut state = 0x2545_F491_4F6C_DD1Du64;
        let mut unit = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut out = Vec::new();
        for k in 0..61 {
            let axis = DVec3::new(unit() - 0.5, unit() - 0.5, unit() - 0.5).normalize();
            let angle = match k % 7 {
                0 => 0.0,
                1 => std::f64::consts::PI,
                2 => 1e-200,
                _ => 6.0 * unit(),
            };
            let o = DVec3::new(unit(), unit(), unit()) * 10.0 - 5.0;
            out.push(Pose::new(o, DQuat::from_axis_angle(axis, angle)));
            if k % 5 == 0 {
                // Same rotation, negated sign, and a pure translation of it.
                let last = *out.last().unwrap();
                out.push(Pose::new(last.origin + DVec3::X, -last.rotation));
            }
        }
        out
    }

    fn same_bits(a: &Pose, b: &Pose) -> bool {
        a.origin.to_array().map(f64::to_bits) == b.origin.to_array().map(f64::to_bits)
            && a.rotation.to_array().map(f64::to_bits) == b.rotation.to_array().map(f64::to_bits)
    }

    #[test]
    fn lanes_reproduce_the_scalar_route_bit_for_bit() {
        // Every width this machine has: the widest, then capped to four and to two lanes.
        for width in [usize::MAX, 4, 2] {
            crate::lanes::with_max_width(width, same_as_scalar);
        }
    }

    #[test]
    fn a_rare_group_in_every_stage_of_the_pipeline() {
        // Regular pairs, but for one rare pair (no rotation) or one fraction outside the fast
        // sine range at index `rare`: whichever stage its group is in when the others pass,
        // every screw comes out as one at a time, in order.
        let p = poses();
        let regular: Vec<usize> = (0..p.len())
            .filter(|&i| {
                let span = Screw::between(&p[i], &p[(i + 1) % p.len()]);
                span.sin_half > 1e-3 && span.cos_half > 1e-3
            })
            .collect();
        assert!(regular.len() > 20);
        let still = Pose::new(DVec3::new(1.0, 2.0, 3.0), DQuat::from_rotation_z(0.4));
        for width in [usize::MAX, 4, 2] {
            crate::lanes::with_max_width(width, || {
                for n in [8, 16, 17, 24, 40, 51] {
                    for rare in 0..n {
                        for kind in 0..2 {
                            let pair = |i: usize| {
                                let j = regular[i % regular.len()];
                                match (i == rare, kind) {
                                    (true, 0) => (&still, 0.3, &still),
                                    (true, _) => (&p[j], 3e10, &p[(j + 1) % p.len()]),
                                    _ => (&p[j], 0.3, &p[(j + 1) % p.len()]),
                                }
                            };
                            let mut got = Vec::new();
                            screws(n, pair, &mut got);
                            assert_eq!(got.len(), n);
                            for (i, g) in got.iter().enumerate() {
                                let (a, t, b) = pair(i);
                                let want = crate::screw::screw(a, t, b);
                                assert!(same_bits(g, &want), "n {n}, rare {rare}, screw {i}");
                            }
                        }
                    }
                }
            });
        }
    }

    fn same_as_scalar() {
        let p = poses();
        let n = p.len();
        let ts = [-1.0 / 16.0, 0.3, 9.0 / 8.0, 2.5e5];
        for &t in &ts {
            let mut got = Vec::new();
            screws(n, |i| (&p[i], t, &p[(i * 7 + 3) % n]), &mut got);
            for (i, g) in got.iter().enumerate() {
                let want = crate::screw::screw(&p[i], t, &p[(i * 7 + 3) % n]);
                assert!(same_bits(g, &want), "screw {i} at {t}: {g:?} vs {want:?}");
            }
        }
        let mut mids = Vec::new();
        midpoints(n, |i| (&p[i], &p[(i + 1) % n]), &mut mids);
        for (i, m) in mids.iter().enumerate() {
            assert!(
                same_bits(m, &Screw::midpoint(&p[i], &p[(i + 1) % n])),
                "{i}"
            );
        }
        for closed in [true, false] {
            let mut spans = Vec::new();
            span_screws(&p, closed, &mut spans);
            assert_eq!(spans.len(), if closed { n } else { n - 1 });
            for (i, got) in spans.iter().enumerate() {
                let want = Screw::between(&p[i], &p[(i + 1) % n]);
                // Compared by bits (`==` would pass 0.0 for -0.0 and fail on equal NaNs).
                assert_eq!(format!("{got:?}"), format!("{want:?}"), "span {i}");
                assert!(same_bits(&got.at(0.3), &want.at(0.3)), "span {i}");
            }
        }
        let mut columns = vec![Vec::new(); 3];
        sample_cycle(&p, &ts[..3], &mut columns);
        for (j, column) in columns.iter().enumerate() {
            assert_eq!(column.len(), n);
            for (i, g) in column.iter().enumerate() {
                let want = Screw::between(&p[i], &p[(i + 1) % n]).at(ts[j]);
                assert!(same_bits(g, &want), "span {i} at {}", ts[j]);
            }
        }
    }
}
