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
    (
        V3::new(
            proto.gather(|k| p[k].origin.x),
            proto.gather(|k| p[k].origin.y),
            proto.gather(|k| p[k].origin.z),
        ),
        Q::new(
            proto.gather(|k| p[k].rotation.x),
            proto.gather(|k| p[k].rotation.y),
            proto.gather(|k| p[k].rotation.z),
            proto.gather(|k| p[k].rotation.w),
        ),
    )
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
    // and V8 keeps such values on the stack (70 of the 197 instructions per group of four of its
    // code for a subdivision's sampling loop, 39 of 123 without the call; the subdivisions run
    // 0.96–0.98× as long). An abort, not a panic, in release builds: it is reachable only by a
    // mistake in this file, and the panic's message costs the math module 30 bytes.
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

/// Appends `screw(a[k], t[k], b[k])` for every lane to `out`, through the scalar route when the
/// group holds a rare case. (Out of line on wasm32, where each batch's closure type would
/// otherwise get its own copy; inlined natively as [`span_lanes`].)
#[cfg_attr(target_arch = "wasm32", inline(never))]
#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
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

/// Appends `screw(a[k], ½, b[k])` for every lane to `out` (see [`screw_group`]).
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
            let mut i = 0;
            while i + N <= n {
                let group: [_; N] = group(i, (&Pose::IDENTITY, 0.0, &Pose::IDENTITY), &item);
                let (a, t, b) = (group.map(|g| g.0), group.map(|g| g.1), group.map(|g| g.2));
                screw_group(proto, a, t, b, out);
                i += N;
            }
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
