//! Split&Tweak subdivision of cyclic and open sequences (docs/math/subdivision.md, docs/math/open-sequences.md), generic over [`Blend`], so
//! the same rules refine poses (by screws) and points (by affine combinations, docs/math/point-rules.md).
//!
//! Slot convention everywhere: `out[2i]` is the image of input `i` (the *old* slot), `out[2i+1]`
//! the *new* pose between inputs `i` and `i+1`. All outputs of one step are computed from that
//! step's input (simultaneous update).

pub(crate) mod blend;
pub(crate) mod componentwise;
pub(crate) mod scheme;
pub(crate) mod split_tweak;
#[cfg(not(target_arch = "wasm32"))]
mod tiles;
pub(crate) mod warnings;

use crate::error::{Error, ErrorKind};
use blend::Blend;
use scheme::{Rules, Scheme, MAX_J_PARAMETER};

/// The largest number of elements a subdivision may produce or hold in between (the memory
/// guard): `2²⁰ = 1 048 576` poses, about 59 MB. Asking for more returns
/// [`ErrorKind::TooManyPoses`] before anything is allocated.
pub const MAX_REFINED_POSES: usize = 1 << 20;

/// A complete subdivision request: scheme, rule set and number of levels. The default is the
/// subdivision of a new motion in every front end: 4-point, direct rules, 5 levels
/// ([`crate::frontend::DEFAULT_LEVELS`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Subdivision {
    /// The scheme (or J_s parameter).
    pub scheme: Scheme,
    /// The rule set (paper version).
    pub rules: Rules,
    /// Number of subdivision steps; `0` leaves the input as it is.
    pub levels: u32,
}

impl Default for Subdivision {
    fn default() -> Self {
        Subdivision::new(
            Scheme::default(),
            Rules::default(),
            crate::frontend::DEFAULT_LEVELS,
        )
    }
}

impl Subdivision {
    /// A request with the given scheme, rules and levels.
    pub fn new(scheme: Scheme, rules: Rules, levels: u32) -> Subdivision {
        Subdivision {
            scheme,
            rules,
            levels,
        }
    }

    /// Checks the options themselves (not the input): the J_s family exists only with the direct
    /// rules, and its parameter must be finite and within [`MAX_J_PARAMETER`].
    pub fn validate(&self) -> Result<(), Error> {
        if let Scheme::J(s) = self.scheme {
            if !s.is_finite() {
                return Err(Error::new("s", ErrorKind::NonFinite));
            }
            if s.abs() > MAX_J_PARAMETER {
                return Err(Error::new(
                    "s",
                    ErrorKind::OutOfRange {
                        value: if s.abs() < 1e21 {
                            s.to_string()
                        } else {
                            format!("{s:e}")
                        },
                        expected: format!("-{MAX_J_PARAMETER} to {MAX_J_PARAMETER}"),
                    },
                ));
            }
            if self.rules == Rules::SplitThenTweak {
                return Err(Error::new(
                    "rules",
                    ErrorKind::Unsupported {
                        reason: "the J_s family is defined with the direct rules only".into(),
                    },
                ));
            }
        }
        Ok(())
    }

    /// How many elements [`Subdivision::apply`] returns for `n` inputs, or the memory-guard
    /// error (which also covers the intermediate sequence of an open input).
    pub fn output_len(&self, n: usize, closed: bool) -> Result<usize, Error> {
        let min = 2;
        if n < min {
            return Err(Error::new(
                "poses",
                ErrorKind::TooFewPoses { found: n, min },
            ));
        }
        let working = if closed {
            n
        } else {
            n + 2 * self.scheme.half_width()
        };
        let too_many = |requested: usize| {
            Error::new(
                "levels",
                ErrorKind::TooManyPoses {
                    requested,
                    max: MAX_REFINED_POSES,
                },
            )
        };
        let factor = 1usize.checked_shl(self.levels).filter(|_| self.levels < 64);
        let peak = factor.and_then(|f| working.checked_mul(f));
        match peak {
            Some(p) if p <= MAX_REFINED_POSES => {
                let f = factor.unwrap_or(1);
                Ok(if closed { p } else { (n - 1) * f + 1 })
            }
            Some(p) => Err(too_many(p)),
            None => Err(too_many(usize::MAX)),
        }
    }

    /// Subdivides `input` `levels` times.
    ///
    /// Closed (cyclic) input of `n ≥ 2` elements gives `n·2^levels` elements. Open input of
    /// `m ≥ 2` elements is extended by dummy poses extrapolated along the end screws, subdivided as
    /// a cycle and cut back (docs/math/open-sequences.md), giving `(m−1)·2^levels + 1` elements that cover exactly the
    /// original parameter range; motions sampled from one screw are reproduced exactly.
    ///
    /// Natively, a thread keeps the working buffers of its last subdivision (at most 8 MB) for
    /// the next one, which then needs no fresh memory besides its result. To reuse the result's
    /// memory too, and buffers of any size, use [`Subdivision::apply_into`].
    pub fn apply<T: Blend>(&self, input: &[T], closed: bool) -> Result<Vec<T>, Error> {
        self.validate()?;
        self.output_len(input.len(), closed)?;
        let mut buffers = SubdivisionBuffers::kept();
        let mut out = Vec::new();
        self.apply_unchecked(input, closed, &mut out, &mut buffers);
        buffers.keep();
        if !closed {
            // An open result is cut from a longer cycle: hand back only the memory it uses.
            out.shrink_to_fit();
        }
        Ok(out)
    }

    /// [`Subdivision::apply`] into caller-owned memory: `out` is cleared and receives the
    /// result, and `buffers` holds the working sequences. Both keep their capacity, so
    /// subdividing again (the next level count, the next drag release, the next file) needs no
    /// fresh memory once they have grown to the largest size asked for: a subdivision into
    /// fresh memory pays a page fault for every 4 KB it touches, which at 2²⁰ poses costs more
    /// than the screws.
    ///
    /// The result is that of [`Subdivision::apply`] bit for bit. On error (bad options, too few
    /// inputs, too many outputs) `out` is left as it was.
    pub fn apply_into<T: Blend>(
        &self,
        input: &[T],
        closed: bool,
        out: &mut Vec<T>,
        buffers: &mut SubdivisionBuffers<T>,
    ) -> Result<(), Error> {
        self.validate()?;
        self.output_len(input.len(), closed)?;
        self.apply_unchecked(input, closed, out, buffers);
        Ok(())
    }

    /// [`Subdivision::apply_into`] for validated options and an input whose output length
    /// passed [`Subdivision::output_len`].
    fn apply_unchecked<T: Blend>(
        &self,
        input: &[T],
        closed: bool,
        out: &mut Vec<T>,
        buffers: &mut SubdivisionBuffers<T>,
    ) {
        out.clear();
        if closed {
            out.extend_from_slice(input);
            self.refine_cycle(out, buffers);
            return;
        }
        let k = self.scheme.half_width();
        extend_open_into(input, k, out);
        self.refine_cycle(out, buffers);
        let f = 1usize << self.levels;
        let start = k * f;
        let len = (input.len() - 1) * f + 1;
        out.copy_within(start..start + len, 0);
        out.truncate(len);
    }

    /// Re-subdivides only what moving one input changed (docs/math/local-update.md, locality), in place.
    ///
    /// `refined` must be the output of [`Subdivision::apply`] for the same options, closedness and
    /// length, computed before input `moved` changed; `input` holds the new value. Refined poses
    /// within 2 (B-spline) or 3 (other schemes) coarse spans of the moved pose are recomputed from
    /// a window of `4` resp. `6` coarse poses on each side, which is exactly what the full
    /// subdivision reads there, so the result is bit-identical to a full recompute at a cost
    /// independent of the sequence length. Returns the refined index range that was rewritten as
    /// `(start, count)`, to be read cyclically (indices mod `refined.len()`).
    ///
    /// Natively the window's working buffers are kept on the thread as for
    /// [`Subdivision::apply`]; [`Subdivision::update_local_with`] takes them from the caller.
    pub fn update_local<T: Blend>(
        &self,
        input: &[T],
        closed: bool,
        moved: usize,
        refined: &mut [T],
    ) -> Result<(usize, usize), Error> {
        let mut buffers = SubdivisionBuffers::kept();
        let done = self.update_local_with(input, closed, moved, refined, &mut buffers);
        buffers.keep();
        done
    }

    /// [`Subdivision::update_local`] with caller-owned working buffers (a drag keeps them from
    /// one step to the next, so a step needs no fresh memory). The result is the same bit for
    /// bit.
    pub fn update_local_with<T: Blend>(
        &self,
        input: &[T],
        closed: bool,
        moved: usize,
        refined: &mut [T],
        buffers: &mut SubdivisionBuffers<T>,
    ) -> Result<(usize, usize), Error> {
        self.validate()?;
        let len = self.output_len(input.len(), closed)?;
        if refined.len() != len || moved >= input.len() {
            return Err(Error::new(
                if moved >= input.len() {
                    "moved"
                } else {
                    "refined"
                },
                ErrorKind::OutOfRange {
                    value: if moved >= input.len() {
                        moved
                    } else {
                        refined.len()
                    }
                    .to_string(),
                    expected: format!("{} refined poses and an input index", len),
                },
            ));
        }
        // Influence radius r (2 or 3 coarse spans) and window half-width K = 2r: the kept outputs
        // at distance < r from the moved pose read inputs at distance < 2r, all inside the window.
        let r = self.scheme.half_width() + 1;
        let k_ext = self.scheme.half_width();
        let whole = |this: &Self, refined: &mut [T]| -> Result<(usize, usize), Error> {
            let all = this.apply(input, closed)?;
            refined.copy_from_slice(&all);
            Ok((0, refined.len()))
        };
        // Open ends: moving one of the two end poses on each side also moves the dummy poses.
        if !closed && (moved < 2 || moved + 2 >= input.len()) {
            return whole(self, refined);
        }
        let working: Vec<T>;
        let (cycle, centre): (&[T], usize) = if closed {
            (input, moved)
        } else {
            working = extend_open(input, k_ext);
            (&working, moved + k_ext)
        };
        let n = cycle.len();
        let half = 2 * r;
        if 2 * half + 1 >= n {
            return whole(self, refined);
        }
        let window: Vec<T> = (0..=2 * half)
            .map(|i| cycle[(centre + n - half + i) % n])
            .collect();
        let mut local = window;
        self.refine_cycle(&mut local, buffers);
        let f = 1usize << self.levels;
        let total = n * f;
        let offset = if closed { 0 } else { k_ext * f };
        let first = (half - r) * f + 1;
        let last = (half + r) * f - 1;
        let mut start = None;
        let mut count = 0;
        for (q, value) in local.iter().enumerate().take(last + 1).skip(first) {
            let global = ((centre + n - half) * f + q) % total;
            if closed {
                refined[global] = *value;
            } else if global >= offset && global - offset < len {
                refined[global - offset] = *value;
            } else {
                continue;
            }
            let index = if closed { global } else { global - offset };
            start.get_or_insert(index);
            count += 1;
        }
        Ok((start.unwrap_or(0), count))
    }

    /// One step on a cycle (ignoring `levels`): `out` is cleared and receives `2·input.len()`
    /// elements. Fails for invalid options or fewer than 2 inputs.
    pub fn step_cyclic<T: Blend>(&self, input: &[T], out: &mut Vec<T>) -> Result<(), Error> {
        self.validate()?;
        Subdivision { levels: 1, ..*self }.output_len(input.len(), true)?;
        self.step_unchecked(input, out, &mut Scratch::default());
        Ok(())
    }

    fn step_unchecked<T: Blend>(&self, input: &[T], out: &mut Vec<T>, scratch: &mut Scratch<T>) {
        out.clear();
        match self.rules {
            Rules::Direct => direct_step(input, self.scheme, out, scratch),
            Rules::SplitThenTweak => split_tweak_step(input, self.scheme, out, scratch),
        }
    }

    /// Refines the cycle `current` in place by `levels` steps, working in `buffers` (large
    /// cycles natively by tiles, `tiles.rs`: the same bits).
    fn refine_cycle<T: Blend>(&self, current: &mut Vec<T>, buffers: &mut SubdivisionBuffers<T>) {
        #[cfg(not(target_arch = "wasm32"))]
        if tiles::tiled(self, current.len()) {
            return tiles::refine_cycle_tiled(self, current, buffers);
        }
        self.refine_levels(current, &mut buffers.next, &mut buffers.scratch);
    }

    /// Refines the cycle `current` in place by `levels` steps, the whole cycle at each level,
    /// working in `next` and `scratch`.
    fn refine_levels<T: Blend>(
        &self,
        current: &mut Vec<T>,
        next: &mut Vec<T>,
        scratch: &mut Scratch<T>,
    ) {
        // Both buffers at their final size from the start: each level then writes in place
        // instead of growing (and copying) the one it is swapped with.
        let size = current.len() << self.levels;
        current.reserve(size.saturating_sub(current.len()));
        next.clear();
        next.reserve(size);
        scratch.reserve(size / 2);
        for _ in 0..self.levels {
            self.step_unchecked(current, next, scratch);
            std::mem::swap(current, next);
        }
    }
}

/// The working buffers of a subdivision besides its result: the sequence of the step being
/// computed, and the steps' temporaries. Pass the same buffers to every
/// [`Subdivision::apply_into`] to subdivide without fresh memory.
///
/// [`Subdivision::apply`] uses buffers of its own: natively, the last subdivision's are kept on
/// its thread for the next one (up to 8 MB): at the finest levels they are hundreds of
/// kilobytes, which the system allocator hands back to the operating system when they are
/// freed, and taking them again cost page faults — a tenth of the time of a subdivision of 32
/// poses by 6 levels. (Not on wasm32, whose memory is never handed back: there keeping them
/// would only add code to the module.)
pub struct SubdivisionBuffers<T> {
    next: Vec<T>,
    scratch: Scratch<T>,
    /// A tiled subdivision's coarse cycle and the window of its current tile (`tiles.rs`).
    #[cfg(not(target_arch = "wasm32"))]
    coarse: Vec<T>,
    #[cfg(not(target_arch = "wasm32"))]
    window: Vec<T>,
}

impl<T> Default for SubdivisionBuffers<T> {
    fn default() -> Self {
        SubdivisionBuffers::new()
    }
}

impl<T> std::fmt::Debug for SubdivisionBuffers<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("SubdivisionBuffers")
            .field("elements", &self.elements())
            .finish()
    }
}

impl<T> SubdivisionBuffers<T> {
    /// Empty buffers (they grow on first use).
    pub fn new() -> SubdivisionBuffers<T> {
        SubdivisionBuffers {
            next: Vec::new(),
            scratch: Scratch::with_capacity(0),
            #[cfg(not(target_arch = "wasm32"))]
            coarse: Vec::new(),
            #[cfg(not(target_arch = "wasm32"))]
            window: Vec::new(),
        }
    }

    /// The number of elements the buffers have room for, all together.
    fn elements(&self) -> usize {
        #[cfg(not(target_arch = "wasm32"))]
        let tiles = self.coarse.capacity() + self.window.capacity();
        #[cfg(target_arch = "wasm32")]
        let tiles = 0;
        tiles
            + self.next.capacity()
            + self.scratch.left.capacity()
            + self.scratch.right.capacity()
            + self
                .scratch
                .samples
                .iter()
                .map(Vec::capacity)
                .sum::<usize>()
    }
}

/// The most bytes of working buffers kept between subdivisions, per thread.
#[cfg(not(target_arch = "wasm32"))]
const SPARE_BYTES: usize = 8 << 20;

#[cfg(not(target_arch = "wasm32"))]
thread_local! {
    /// The working buffers of the last subdivision on this thread, whatever it subdivided.
    static SPARE: std::cell::Cell<Option<Box<dyn std::any::Any>>> =
        const { std::cell::Cell::new(None) };
}

impl<T: Blend> SubdivisionBuffers<T> {
    /// The buffers kept on this thread (if they hold `T`), or new ones. (Taken, not borrowed:
    /// a subdivision inside a [`Blend`] implementation finds none and makes its own.)
    fn kept() -> SubdivisionBuffers<T> {
        #[cfg(not(target_arch = "wasm32"))]
        if let Some(kept) = SPARE
            .with(|spare| spare.take())
            .and_then(|kept| kept.downcast::<SubdivisionBuffers<T>>().ok())
        {
            return *kept;
        }
        SubdivisionBuffers::new()
    }

    /// Keeps the buffers for the next subdivision on this thread, unless they are too large.
    fn keep(self) {
        #[cfg(not(target_arch = "wasm32"))]
        if self.elements() * std::mem::size_of::<T>() <= SPARE_BYTES {
            SPARE.with(|spare| spare.set(Some(Box::new(self))));
        }
    }
}

/// Buffers reused from one subdivision step to the next (a step's temporaries at the finest
/// levels are hundreds of kilobytes: allocating them afresh each step costs page faults).
struct Scratch<T> {
    samples: Vec<Vec<T>>,
    left: Vec<T>,
    right: Vec<T>,
}

impl<T> Default for Scratch<T> {
    fn default() -> Self {
        Scratch::with_capacity(0)
    }
}

impl<T> Scratch<T> {
    /// Buffers for steps of up to `n` inputs, allocated once: growing them level by level
    /// would copy each one at every level.
    fn with_capacity(n: usize) -> Self {
        let mut scratch = Scratch {
            samples: Vec::new(),
            left: Vec::new(),
            right: Vec::new(),
        };
        scratch.reserve(n);
        scratch
    }

    /// Makes room for steps of up to `n` inputs.
    fn reserve(&mut self, n: usize) {
        self.left.clear();
        self.left.reserve(n);
        // The split rules' midpoints: one per output pose for Jarek.
        self.right.clear();
        self.right.reserve(2 * n);
        for column in &mut self.samples {
            column.clear();
            column.reserve(n);
        }
    }
}

/// docs/math/open-sequences.md §2 steps 1–2: `P_{−j} = blend(P₀, −j, P₁)`, `P_{m−1+j} = blend(P_{m−2}, 1+j, P_{m−1})`
/// for `j = 1..k`, in order `P_{−k} … P_{m−1+k}`.
pub(crate) fn extend_open<T: Blend>(input: &[T], k: usize) -> Vec<T> {
    let mut e = Vec::with_capacity(input.len() + 2 * k);
    extend_open_into(input, k, &mut e);
    e
}

/// [`extend_open`], appended to `e`.
fn extend_open_into<T: Blend>(input: &[T], k: usize, e: &mut Vec<T>) {
    let m = input.len();
    let first = T::span(&input[0], &input[1]);
    let last = T::span(&input[m - 2], &input[m - 1]);
    e.reserve(m + 2 * k);
    e.extend((1..=k).rev().map(|j| T::span_at(&first, -(j as f64))));
    e.extend_from_slice(input);
    e.extend((1..=k).map(|j| T::span_at(&last, 1.0 + j as f64)));
}

/// The direct rules (docs/math/subdivision.md §2) and the J_s family. `L_i` is the span `P_i → P_{i+1}`; reversed
/// arguments use `blend(b, t, a) = blend(a, 1 − t, b)`:
///
/// - old pose: `s(s(b, s/4, a), ½, s(b, s/4, c))` = `mid(L_{i−1}(1 − s/4), L_i(s/4))`, or `P_i`
///   itself for `s = 0` (4-point);
/// - new pose: `s(s(a, w, b), ½, s(d, w, c))` = `mid(L_{i−1}(w), L_{i+1}(1 − w))` with
///   `w = 1 + (1 − s)/8`, or `L_i(½)` for the B-spline (`s = 1`, where the rule collapses).
///
/// So B-spline: `L(¾), L(¼), L(½)`; 4-point: `L(9/8), L(−1/8)`; Jarek: `L(7/8), L(1/8),
/// L(17/16), L(−1/16)`. Every span is sampled at those fractions in one batch (its logarithm
/// computed once), then the midpoints are taken in a second batch.
// Never inlined (as `split_tweak_step`): called once per level, so the call costs nothing, and
// every caller (`refine_cycle`, `step_cyclic`, the teaching steps) shares one copy per `T`
// instead of inlining its own into the size-budgeted npm module.
#[inline(never)]
fn direct_step<T: Blend>(p: &[T], scheme: Scheme, out: &mut Vec<T>, scratch: &mut Scratch<T>) {
    let n = p.len();
    let s = scheme.s();
    let prev = |i: usize| if i == 0 { n - 1 } else { i - 1 };
    let next = |i: usize| if i + 1 == n { 0 } else { i + 1 };
    let bspline = scheme == Scheme::BSpline;
    let w = 1.0 + (1.0 - s) / 8.0;
    let mut ts = Vec::with_capacity(4);
    if s != 0.0 {
        ts.extend([1.0 - s / 4.0, s / 4.0]);
    }
    if bspline {
        ts.push(0.5);
    } else {
        ts.extend([w, 1.0 - w]);
    }
    let Scratch {
        samples,
        left: olds,
        right: news,
    } = scratch;
    let capacity = olds.capacity().max(n);
    samples.resize_with(ts.len(), || Vec::with_capacity(capacity));
    let samples = &mut samples[..ts.len()];
    T::sample_cycle(p, &ts, samples);
    let samples = &*samples;
    let old_pair = |i: usize| (&samples[0][prev(i)], &samples[1][i]);
    let new_pair = |i: usize| {
        let (left, right) = (&samples[ts.len() - 2], &samples[ts.len() - 1]);
        (&left[prev(i)], &right[next(i)])
    };
    out.reserve(2 * n);
    if bspline {
        olds.clear();
        T::midpoints(n, old_pair, olds);
        interleave(olds, &samples[2], out);
    } else if s == 0.0 {
        news.clear();
        T::midpoints(n, new_pair, news);
        interleave(p, news, out);
    } else {
        // Old and new poses are both midpoints: one batch, written in output order. (One
        // copy path for both parities keeps the closure small enough to be inlined.)
        let pair = |j: usize| {
            let (i, new) = (j / 2, j % 2);
            let (left, right) = (&samples[2 * new], &samples[2 * new + 1]);
            (&left[prev(i)], &right[if new == 1 { next(i) } else { i }])
        };
        T::midpoints(2 * n, pair, out);
    }
}

/// Appends `evens[0], odds[0], evens[1], odds[1], …` to `out`.
fn interleave<T: Copy>(evens: &[T], odds: &[T], out: &mut Vec<T>) {
    let n = evens.len().min(odds.len());
    // A mapped range has a known length: one reservation, no capacity check per element.
    out.extend((0..2 * n).map(|j| {
        if j % 2 == 0 {
            evens[j / 2]
        } else {
            odds[j / 2]
        }
    }));
}

/// The first version's rules (docs/math/subdivision.md §3): split, then tweak the split sequence `Z`, all right-hand
/// sides reading `Z`. The 4-point and Jarek new-pose tweaks use the corrected argument order
/// `s(s(Z_{j−2}, ½, Z_{j+2}), 5/4 resp. 9/8, Z_j)`.
// Never inlined: see `direct_step`.
#[inline(never)]
fn split_tweak_step<T: Blend>(p: &[T], scheme: Scheme, out: &mut Vec<T>, scratch: &mut Scratch<T>) {
    let n = p.len();
    let prev = |i: usize| if i == 0 { n - 1 } else { i - 1 };
    let next = |i: usize| if i + 1 == n { 0 } else { i + 1 };
    let Scratch {
        samples,
        left: split,
        right: mids,
    } = scratch;
    // The split sequence Z: the old poses `Z_{2i} = p[i]` and the split midpoints
    // `Z_{2i+1} = split[i]`.
    split.clear();
    T::midpoints(n, |i| (&p[i], &p[next(i)]), split);
    let split: &[T] = split;
    // (old-pose weight, new-pose weight): how far each tweak goes. The J_s family has no
    // split-tweak form (options are validated before a step runs); its named members map here.
    let s = scheme.s();
    let (old_w, new_w) = if s == 1.0 {
        (Some(0.5), None)
    } else if s == 0.0 {
        (None, Some(5.0 / 4.0))
    } else {
        (Some(0.25), Some(9.0 / 8.0))
    };
    // The tweaked old and new poses, each in its own batches (in `Z`'s indices the two read
    // different neighbours; one batch over both parities had to decide per pose, and its
    // closures were too large to be inlined into the lanes).
    let capacity = split.len();
    samples.resize_with(2, || Vec::with_capacity(capacity));
    let [olds, news] = &mut samples[..] else {
        unreachable!("two sample buffers")
    };
    mids.clear();
    if let Some(w) = old_w {
        // Q_{2i} = s(Z_{2i}, w, s(Z_{2i−1}, ½, Z_{2i+1})).
        T::midpoints(n, |i| (&split[prev(i)], &split[i]), mids);
        olds.clear();
        T::blends(n, |i| (&p[i], w, &mids[i]), olds);
    }
    let first_new = mids.len();
    if let Some(w) = new_w {
        // Q_{2i+1} = s(s(Z_{2i−1}, ½, Z_{2i+3}), w, Z_{2i+1}).
        T::midpoints(n, |i| (&split[prev(i)], &split[next(i)]), mids);
        news.clear();
        T::blends(n, |i| (&mids[first_new + i], w, &split[i]), news);
    }
    let evens: &[T] = if old_w.is_some() { olds } else { p };
    let odds: &[T] = if new_w.is_some() { news } else { split };
    out.reserve(2 * n);
    interleave(evens, odds, out);
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec2;

    #[test]
    fn memory_guard_counts_open_extension() {
        let s = Subdivision::new(Scheme::FourPoint, Rules::Direct, 18);
        assert_eq!(s.output_len(4, true).unwrap(), 4 << 18);
        // open: 4 + 2·2 = 8 working poses · 2^18 = 2^21 > limit
        assert!(matches!(
            s.output_len(4, false).as_ref().map_err(|e| e.kind()),
            Err(ErrorKind::TooManyPoses { .. })
        ));
        let huge = Subdivision::new(Scheme::BSpline, Rules::Direct, 200);
        assert!(matches!(
            huge.output_len(3, true).as_ref().map_err(|e| e.kind()),
            Err(ErrorKind::TooManyPoses {
                requested: usize::MAX,
                ..
            })
        ));
        assert!(matches!(
            s.output_len(1, true).as_ref().map_err(|e| e.kind()),
            Err(ErrorKind::TooFewPoses {
                found: 1,
                min: 2,
                ..
            })
        ));
    }

    #[test]
    fn j_with_split_rules_is_rejected() {
        let s = Subdivision::new(Scheme::J(0.3), Rules::SplitThenTweak, 1);
        let pts = [DVec2::ZERO, DVec2::X, DVec2::Y];
        assert!(matches!(
            s.apply(&pts, true).as_ref().map_err(|e| e.kind()),
            Err(ErrorKind::Unsupported { .. })
        ));
        let s = Subdivision::new(Scheme::J(f64::NAN), Rules::Direct, 1);
        assert!(matches!(
            s.apply(&pts, true).as_ref().map_err(|e| e.kind()),
            Err(ErrorKind::NonFinite)
        ));
    }

    #[test]
    fn kept_buffers_do_not_change_results() {
        // Every subdivision after the first on a thread reuses the last one's buffers, whatever
        // their element type and size: the results must not depend on what ran before.
        let points: Vec<DVec2> = (0..7)
            .map(|i| DVec2::new((i as f64).cos(), (i * i) as f64 * 0.1))
            .collect();
        let reals = [0.0, 1.0, 4.0, 2.0];
        let runs = move |levels| {
            let mut results = Vec::new();
            for rules in [Rules::Direct, Rules::SplitThenTweak] {
                for scheme in [Scheme::BSpline, Scheme::FourPoint, Scheme::Jarek] {
                    let s = Subdivision::new(scheme, rules, levels);
                    let refined = s.apply(&points, true).unwrap();
                    assert_eq!(s.apply(&reals, false).unwrap().len(), 3 * (1 << levels) + 1);
                    results.push(refined);
                }
            }
            results
        };
        let first = runs(5);
        runs(1);
        runs(8);
        assert_eq!(runs(5), first);
        // A new thread starts without kept buffers.
        let fresh = std::thread::spawn(move || runs(5)).join().unwrap();
        assert_eq!(fresh, first);
    }

    #[test]
    fn open_output_covers_the_range() {
        let pts: Vec<DVec2> = (0..5).map(|i| DVec2::new(i as f64, 0.0)).collect();
        for scheme in [Scheme::BSpline, Scheme::FourPoint, Scheme::Jarek] {
            let out = Subdivision::new(scheme, Rules::Direct, 3)
                .apply(&pts, false)
                .unwrap();
            assert_eq!(out.len(), 4 * 8 + 1);
            for (j, q) in out.iter().enumerate() {
                assert!(
                    (q.x - j as f64 / 8.0).abs() < 1e-14 && q.y == 0.0,
                    "{scheme} {j}"
                );
            }
        }
    }
}
