//! Large subdivisions by tiles, so that the finest levels stay in the processor's caches
//! (docs/math/local-update.md §4).
//!
//! Refined whole, every level of a large cycle streams its input and its output through main
//! memory: at 2²⁰ refined poses (59 MB) the last four levels move about 200 MB, and a refined pose
//! costs more than at 2¹² (docs/speed/code-notes.md). But a refined pose reads only coarse poses less than
//! `k + 1` coarse spans away (`k`, the scheme's half-width: 1 for the B-spline, 2 for the
//! others), so at most `k` spans away, as coarse poses sit at whole spans; and a window refined as
//! if it were a cycle performs, for the poses that never read across its artificial closing span,
//! the same operations in the same order as the whole cycle (the local update's argument, §3). So
//! a large cycle is refined whole down to [`TILE_LEVELS`] levels above the finest, and the rest
//! tile by tile: [`TILE_SPANS`] coarse spans with `k` more on each side, refined in buffers that
//! fit the cache, and the tile's own refined poses copied out. The result is the same bit for bit
//! (the tests below: one span less on each side already changes bits).
//!
//! Native targets only: on wasm32 the subdivisions the page and the npm module make are small,
//! and the code would add to the math module, whose size is budgeted.

use super::blend::Blend;
use super::{Subdivision, SubdivisionBuffers};

/// The levels refined tile by tile: a tile's finest level holds `2⁶ = 64` refined poses per coarse
/// span.
const TILE_LEVELS: u32 = 6;

/// Coarse spans per tile: with the B-spline's halo of 1 span on each side 1.6 % more work, with
/// the other schemes' 2, 3 %; a tile's two buffers at its finest level hold about
/// `2 · (128 + 5) · 64` poses, 0.9 MB (Zen 4's second-level cache: 1 MB).
const TILE_SPANS: usize = 128;

/// Refined sizes from which a subdivision goes by tiles (3.5 MB of poses; below, the levels of a
/// whole cycle fit the caches).
const TILED_FROM: usize = 1 << 16;

/// Whether a cycle of `len` poses refined by `sub` goes by tiles.
pub(super) fn tiled(sub: &Subdivision, len: usize) -> bool {
    sub.levels > TILE_LEVELS && (len << sub.levels) >= TILED_FROM
}

/// Refines the cycle `current` in place by `sub.levels` steps, the last [`TILE_LEVELS`] tile by
/// tile (for cycles that [`tiled`] accepts).
pub(super) fn refine_cycle_tiled<T: Blend>(
    sub: &Subdivision,
    current: &mut Vec<T>,
    buffers: &mut SubdivisionBuffers<T>,
) {
    let coarse_levels = Subdivision {
        levels: sub.levels - TILE_LEVELS,
        ..*sub
    };
    let fine_levels = Subdivision {
        levels: TILE_LEVELS,
        ..*sub
    };
    let f = 1usize << TILE_LEVELS;
    let size = current.len() << sub.levels;
    // The coarse levels in a buffer of their own (a 64th of the result), so that `current`
    // keeps its memory for the refined poses: refined in `current`, the levels' swaps with
    // `next` would leave a caller's output buffer and the working buffer both at full size.
    buffers.coarse.clear();
    buffers.coarse.extend_from_slice(current);
    coarse_levels.refine_levels(&mut buffers.coarse, &mut buffers.next, &mut buffers.scratch);
    current.clear();
    current.reserve(size);
    let coarse = &buffers.coarse;
    let n = coarse.len();
    let halo = sub.scheme.half_width();
    let mut first = 0;
    while first < n {
        let spans = TILE_SPANS.min(n - first);
        // Coarse poses first − k … first + spans + k (cyclically): every pose the tile's refined
        // poses read, none across the window's closing span.
        let window = &mut buffers.window;
        window.clear();
        window.extend((0..spans + 2 * halo + 1).map(|i| coarse[(first + n - halo + i) % n]));
        fine_levels.refine_levels(window, &mut buffers.next, &mut buffers.scratch);
        current.extend_from_slice(&window[halo * f..(halo + spans) * f]);
        first += spans;
    }
}

#[cfg(test)]
mod tests {
    use super::super::scheme::{Rules, Scheme};
    use super::super::{extend_open, Scratch};
    use super::*;
    use crate::pose::Pose;
    use glam::{DQuat, DVec2, DVec3};

    /// `n` poses that turn by up to about 100° from one to the next, about varied axes.
    fn poses(n: usize) -> Vec<Pose> {
        (0..n)
            .map(|i| {
                let x = i as f64;
                let axis = DVec3::new((1.3 * x).sin(), (0.7 * x).cos(), 0.5 + 0.1 * x.sin());
                Pose::new(
                    DVec3::new(x.cos() * 3.0, (2.1 * x).sin(), 0.2 * x),
                    DQuat::from_axis_angle(axis.normalize(), 1.7 * x),
                )
            })
            .collect()
    }

    /// The cycle refined whole at every level: what the tiles must give bit for bit.
    fn whole<T: Blend>(sub: &Subdivision, cycle: &[T]) -> Vec<T> {
        let mut current = cycle.to_vec();
        sub.refine_levels(&mut current, &mut Vec::new(), &mut Scratch::default());
        current
    }

    fn same_bits<T: Blend + std::fmt::Debug + PartialEq>(tiled: &[T], whole: &[T], what: &str) {
        assert_eq!(tiled.len(), whole.len(), "{what}: lengths");
        if let Some(i) = (0..whole.len()).find(|&i| tiled[i] != whole[i]) {
            panic!(
                "{what}: refined pose {i} of {} differs: {:?} against {:?}",
                whole.len(),
                tiled[i],
                whole[i]
            );
        }
    }

    #[test]
    fn tiles_give_the_whole_cycle_bit_for_bit() {
        // (poses, levels): whole tiles only (9 · 2⁷ coarse poses), and a partial last tile
        // (300 · 2² = 1200 = 9 · 128 + 48).
        for (n, levels) in [(9, 13), (300, 8)] {
            let input = poses(n);
            let cases = [
                (Scheme::BSpline, Rules::Direct),
                (Scheme::FourPoint, Rules::Direct),
                (Scheme::Jarek, Rules::Direct),
                (Scheme::J(0.3), Rules::Direct),
                (Scheme::BSpline, Rules::SplitThenTweak),
                (Scheme::FourPoint, Rules::SplitThenTweak),
                (Scheme::Jarek, Rules::SplitThenTweak),
            ];
            for (scheme, rules) in cases {
                let sub = Subdivision::new(scheme, rules, levels);
                let what = format!("{scheme:?} {rules:?}, {n} poses × {levels} levels");
                assert!(tiled(&sub, n), "{what}: not tiled");
                let mut buffers = SubdivisionBuffers::new();
                let mut out = Vec::new();
                sub.apply_into(&input, true, &mut out, &mut buffers)
                    .unwrap();
                same_bits(&out, &whole(&sub, &input), &format!("{what}, closed"));
                // Again in the same buffers, open: the extended sequence, cropped.
                sub.apply_into(&input, false, &mut out, &mut buffers)
                    .unwrap();
                let k = scheme.half_width();
                let f = 1usize << levels;
                let extended = whole(&sub, &extend_open(&input, k));
                let want = &extended[k * f..k * f + (n - 1) * f + 1];
                same_bits(&out, want, &format!("{what}, open"));
            }
        }
    }

    #[test]
    fn tiles_serve_points_too() {
        let points: Vec<DVec2> = (0..500)
            .map(|i| DVec2::new((i as f64 * 0.37).sin(), (i as f64 * 0.11).cos()))
            .collect();
        let sub = Subdivision::new(Scheme::Jarek, Rules::SplitThenTweak, 8);
        assert!(tiled(&sub, points.len()));
        same_bits(
            &sub.apply(&points, true).unwrap(),
            &whole(&sub, &points),
            "points",
        );
    }

    #[test]
    fn small_or_shallow_subdivisions_are_not_tiled() {
        let four = |levels| Subdivision::new(Scheme::FourPoint, Rules::Direct, levels);
        assert!(!tiled(&four(6), 5000), "no levels left above the tiles");
        assert!(!tiled(&four(12), 8), "2¹⁵ refined poses");
        assert!(tiled(&four(13), 8));
    }
}
