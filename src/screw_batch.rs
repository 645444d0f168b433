//! Many screws at once, two at a time on [`F2`] lanes (see `lanes` for why).
//!
//! Every routine here gives *bit for bit* what the one-at-a-time [`Screw`] calls give: the lanes
//! run the same kernel (`screw_kernel`) with the same operations in the same order. A pair that
//! holds a rare case (no rotation, a half turn, an argument outside the fast sine range, a
//! non-finite value) is handed to the scalar route, which decides those cases.

use crate::lanes::{Real, F2, Q, V3};
use crate::pose::Pose;
use crate::screw::Screw;
use crate::screw_kernel::{self as kernel, RegularSpan};

/// Two poses, lane `k` holding pose `k`.
#[inline(always)]
fn load(a: &Pose, b: &Pose) -> (V3<F2>, Q<F2>) {
    let (o, p, q, r) = (a.origin, b.origin, a.rotation, b.rotation);
    (
        V3::new(F2([o.x, p.x]), F2([o.y, p.y]), F2([o.z, p.z])),
        Q::new(
            F2([q.x, r.x]),
            F2([q.y, r.y]),
            F2([q.z, r.z]),
            F2([q.w, r.w]),
        ),
    )
}

/// The two poses held in the lanes.
#[inline(always)]
fn store(o: V3<F2>, q: Q<F2>) -> [Pose; 2] {
    let lane = |k: usize| {
        Pose::new(
            glam::DVec3::new(o.x.0[k], o.y.0[k], o.z.0[k]),
            glam::DQuat::from_xyzw(q.x.0[k], q.y.0[k], q.z.0[k], q.w.0[k]),
        )
    };
    [lane(0), lane(1)]
}

/// The spans `a[k] → b[k]` in the regular case (see [`kernel::regular_span`]).
///
/// Inlined natively (the lanes then stay in registers across the calls); out of line on
/// wasm32 with SIMD, where the callers are instantiated once per closure type and an inlined
/// copy in each would add kilobytes to the module (whose size is budgeted).
#[cfg_attr(target_arch = "wasm32", inline(never))]
#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
fn span_pair(a: [&Pose; 2], b: [&Pose; 2]) -> Option<RegularSpan<F2>> {
    let (oa, qa) = load(a[0], a[1]);
    let (ob, qb) = load(b[0], b[1]);
    kernel::regular_span(oa, qa, ob, qb)
}

/// The poses at `t` of a regular span pair (see [`kernel::regular_at`]). Inlined or not as
/// [`span_pair`].
#[cfg_attr(target_arch = "wasm32", inline(never))]
#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
fn at_pair(span: &RegularSpan<F2>, t: F2) -> Option<[Pose; 2]> {
    let (o, q) = kernel::regular_at(span, t)?;
    Some(store(o, q))
}

/// Appends `screw(a, t, b)` for `(a, t, b) = item(i)`, `i = 0..n`, to `out`.
pub(crate) fn screws(n: usize, item: impl Fn(usize) -> (Pose, f64, Pose), out: &mut Vec<Pose>) {
    out.reserve(n);
    let mut i = 0;
    while i + 1 < n {
        let ((a0, t0, b0), (a1, t1, b1)) = (item(i), item(i + 1));
        let pair = screw_pair([&a0, &a1], F2([t0, t1]), [&b0, &b1])
            .unwrap_or_else(|| [scalar_screw(&a0, t0, &b0), scalar_screw(&a1, t1, &b1)]);
        out.extend_from_slice(&pair);
        i += 2;
    }
    if i < n {
        let (a, t, b) = item(i);
        out.push(scalar_screw(&a, t, &b));
    }
}

/// `screw(a[k], t[k], b[k])` for both lanes, or `None` for a rare case.
#[inline(never)]
fn screw_pair(a: [&Pose; 2], t: F2, b: [&Pose; 2]) -> Option<[Pose; 2]> {
    at_pair(&span_pair(a, b)?, t)
}

/// `screw(a, ½, b)` for both lanes, or `None` for a rare case.
#[inline(never)]
fn midpoint_pair(a: [&Pose; 2], b: [&Pose; 2]) -> Option<[Pose; 2]> {
    let (o, q) = kernel::regular_midpoint(&span_pair(a, b)?);
    Some(store(o, q))
}

/// The scalar routes, out of line: they are rare, and one copy serves every caller.
#[inline(never)]
fn scalar_screw(a: &Pose, t: f64, b: &Pose) -> Pose {
    crate::screw(a, t, b)
}

#[inline(never)]
fn scalar_midpoint(a: &Pose, b: &Pose) -> Pose {
    Screw::midpoint(a, b)
}

/// Appends `screw(a, ½, b)` for `(a, b) = pair(i)`, `i = 0..n`, to `out` (as
/// [`Screw::midpoint`]: no transcendental function).
pub(crate) fn midpoints(n: usize, pair: impl Fn(usize) -> (Pose, Pose), out: &mut Vec<Pose>) {
    out.reserve(n);
    let mut i = 0;
    while i + 1 < n {
        let ((a0, b0), (a1, b1)) = (pair(i), pair(i + 1));
        let pair = midpoint_pair([&a0, &a1], [&b0, &b1])
            .unwrap_or_else(|| [scalar_midpoint(&a0, &b0), scalar_midpoint(&a1, &b1)]);
        out.extend_from_slice(&pair);
        i += 2;
    }
    if i < n {
        let (a, b) = pair(i);
        out.push(scalar_midpoint(&a, &b));
    }
}

/// For every span `p[i] → p[(i+1) mod n]` of the cycle `p` and every fraction `ts[j]`, sets
/// `out[j][i]` to the span's pose at `ts[j]` (`out[j]` is cleared first). Each span's logarithm
/// is computed once for all the fractions.
pub(crate) fn sample_cycle(p: &[Pose], ts: &[f64], out: &mut [Vec<Pose>]) {
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
    while i + 1 < n {
        let lanes = if ts.len() <= MAX_SAMPLES {
            span_pair([&p[i], &p[i + 1]], [&p[i + 1], &p[next(i + 1)]]).and_then(|span| {
                let mut poses = [[Pose::IDENTITY; 2]; MAX_SAMPLES];
                for (slot, &t) in poses.iter_mut().zip(ts) {
                    *slot = at_pair(&span, F2::splat(t))?;
                }
                Some(poses)
            })
        } else {
            None
        };
        match lanes {
            Some(poses) => {
                for (column, pair) in out.iter_mut().zip(poses) {
                    column.extend_from_slice(&pair);
                }
            }
            _ => {
                scalar(i, out);
                scalar(i + 1, out);
            }
        }
        i += 2;
    }
    if i < n {
        scalar(i, out);
    }
}

/// The most fractions [`sample_cycle`] evaluates in lanes per span (a subdivision step needs
/// at most four); more go through the scalar route.
const MAX_SAMPLES: usize = 4;

#[cfg(test)]
mod tests {
    use super::*;
    use glam::{DQuat, DVec3};

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
        let p = poses();
        let n = p.len();
        let ts = [-1.0 / 16.0, 0.3, 9.0 / 8.0, 2.5e5];
        for &t in &ts {
            let mut got = Vec::new();
            screws(n, |i| (p[i], t, p[(i * 7 + 3) % n]), &mut got);
            for (i, g) in got.iter().enumerate() {
                let want = crate::screw(&p[i], t, &p[(i * 7 + 3) % n]);
                assert!(same_bits(g, &want), "screw {i} at {t}: {g:?} vs {want:?}");
            }
        }
        let mut mids = Vec::new();
        midpoints(n, |i| (p[i], p[(i + 1) % n]), &mut mids);
        for (i, m) in mids.iter().enumerate() {
            assert!(
                same_bits(m, &Screw::midpoint(&p[i], &p[(i + 1) % n])),
                "{i}"
            );
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
