//! One subdivision step taken apart for teaching (docs/math/subdivision.md, paper Figs. 3–4): the **split**
//! sequence (every span's screw midpoint inserted) and the **tweak** that turns it into the
//! step's output, generic over [`Blend`] like [`Subdivision`].
//!
//! * With the first version's rules ([`Rules::SplitThenTweak`], docs/math/subdivision.md §3) the tweak is computed here
//!   from the split sequence `Z`, independently of [`Subdivision`], together with the helper
//!   element each tweak moves towards or away from (`m = s(Z_{j−1}, ½, Z_{j+1})` for old slots,
//!   `m = s(Z_{j−2}, ½, Z_{j+2})` for new slots). The integration tests check that the result
//!   equals one [`Subdivision`] step.
//! * With the direct rules ([`Rules::Direct`], docs/math/subdivision.md §2) the output is one
//!   [`Subdivision::step_cyclic`]; the split sequence is still the screw midpoints, and the
//!   "tweak" of slot `j` is the displacement `Z_j → Q_j`. Each moved slot has two helpers, the
//!   inner blends of its rule (e.g. `s(a, 9/8, b)` and `s(d, 9/8, c)` for the 4-point new pose),
//!   whose screw midpoint is the output.
//!
//! Open sequences are refined on the extended cycle of docs/math/open-sequences.md (dummy poses included); each
//! [`SplitTweakStep`] says which part of its output is kept.

use crate::error::Error;
use crate::subdivision::blend::Blend;
use crate::subdivision::scheme::{Rules, Scheme};
use crate::subdivision::{extend_open, Subdivision};

/// One subdivision step of a cycle, split and tweak shown separately.
#[derive(Clone, Debug, PartialEq)]
pub struct SplitTweakStep<T> {
    /// The step's input (a cycle of `n` elements).
    pub input: Vec<T>,
    /// The split sequence `Z` (`2n` elements): `Z_{2i} = P_i`, `Z_{2i+1} = blend(P_i, ½, P_{i+1})`.
    pub split: Vec<T>,
    /// The tweaked sequence `Q` (`2n` elements), equal to one [`Subdivision`] step of `input`.
    pub output: Vec<T>,
    /// Which slots the scheme's tweak moves (`Q_j` differs from `Z_j` by rule, not by accident):
    /// old slots for the B-spline, new slots for the 4-point, both for Jarek and the J_s family.
    pub tweaked: Vec<bool>,
    /// Helper elements as `(j, h)`, drawn faintly in the paper's Fig. 4. Split-then-tweak rules:
    /// one per tweaked slot `j`, the element the tweak moves `Z_j` towards (old slots) or away
    /// from (new slots) along the blend between them. Direct rules: two per tweaked slot, the two
    /// inner blends of the rule, whose midpoint `blend(h₁, ½, h₂)` is `Q_j`.
    pub helpers: Vec<(usize, T)>,
    /// The part of `output` that belongs to the motion, as `(start, len)`: everything for a
    /// cycle; for an open sequence, the refined range that covers `[0, m − 1]` after this step
    /// (docs/math/open-sequences.md §2 step 4), the rest being dummy poses.
    pub kept: (usize, usize),
}

/// The tweak weights `(old, new)` of the split-then-tweak rules (docs/math/subdivision.md §3): how far the old
/// slot moves towards its helper (`½` B-spline, `¼` Jarek) and the blend parameter of the new
/// slot from its helper (`5/4` 4-point, `9/8` Jarek). `None` leaves that slot as split.
fn tweak_weights(scheme: Scheme) -> (Option<f64>, Option<f64>) {
    match scheme {
        Scheme::BSpline => (Some(0.5), None),
        Scheme::FourPoint => (None, Some(5.0 / 4.0)),
        Scheme::Jarek => (Some(0.25), Some(9.0 / 8.0)),
        // The J_s family: old b + s(a − 2b + c)/8 = s/4 towards the helper; new weight 1 + (1 − s)/8.
        Scheme::J(s) => (
            (s != 0.0).then_some(s / 4.0),
            (s != 1.0).then_some(1.0 + (1.0 - s) / 8.0),
        ),
    }
}

/// The split sequence of a cycle: `Z_{2i} = P_i`, `Z_{2i+1} = blend(P_i, ½, P_{i+1})`.
pub fn split<T: Blend>(input: &[T]) -> Vec<T> {
    let n = input.len();
    let mut z = Vec::with_capacity(2 * n);
    for i in 0..n {
        z.push(input[i]);
        z.push(T::midpoint(&input[i], &input[(i + 1) % n]));
    }
    z
}

/// One step of the cycle `input` with split and tweak separated (see the module docs).
///
/// Fails like [`Subdivision::step_cyclic`]: fewer than 2 elements, or invalid options (the J_s
/// family with the split-then-tweak rules).
pub fn split_tweak_step<T: Blend>(
    input: &[T],
    scheme: Scheme,
    rules: Rules,
) -> Result<SplitTweakStep<T>, Error> {
    let sub = Subdivision::new(scheme, rules, 1);
    let mut direct = Vec::new();
    // Validates the options and the length.
    sub.step_cyclic(input, &mut direct)?;
    let z = split(input);
    let m = z.len();
    let (old_w, new_w) = tweak_weights(scheme);
    let tweaked: Vec<bool> = (0..m)
        .map(|j| {
            if j % 2 == 0 {
                old_w.is_some()
            } else {
                new_w.is_some()
            }
        })
        .collect();
    let (output, helpers) = match rules {
        Rules::Direct => (direct, direct_helpers(input, scheme)),
        Rules::SplitThenTweak => {
            let zz = |j: usize| &z[j % m];
            let mut out = Vec::with_capacity(m);
            let mut helpers = Vec::new();
            for (j, zj) in z.iter().enumerate() {
                let q = if j % 2 == 0 {
                    match old_w {
                        Some(w) => {
                            let h = T::midpoint(zz(j + m - 1), zz(j + 1));
                            helpers.push((j, h));
                            T::blend(zj, w, &h)
                        }
                        None => *zj,
                    }
                } else {
                    match new_w {
                        Some(w) => {
                            let h = T::midpoint(zz(j + m - 2), zz(j + 2));
                            helpers.push((j, h));
                            T::blend(&h, w, zj)
                        }
                        None => *zj,
                    }
                };
                out.push(q);
            }
            (out, helpers)
        }
    };
    Ok(SplitTweakStep {
        input: input.to_vec(),
        split: z,
        output,
        tweaked,
        helpers,
        kept: (0, m),
    })
}

/// The inner blends of the direct rules (docs/math/subdivision.md §2) for every moved slot: `(j, h₁)`, `(j, h₂)`
/// with `Q_j = blend(h₁, ½, h₂)`. With `a, b, c, d = P_{i−1}, P_i, P_{i+1}, P_{i+2}`: old slot
/// `2i` from `s(b, σ, a)`, `s(b, σ, c)` (`σ = s/4`: ¼ B-spline, ⅛ Jarek); new slot `2i+1` from
/// `s(a, w, b)`, `s(d, w, c)` (`w = 1 + (1 − s)/8`: 9/8 4-point, 17/16 Jarek).
fn direct_helpers<T: Blend>(p: &[T], scheme: Scheme) -> Vec<(usize, T)> {
    let n = p.len();
    let s = scheme.s();
    let w = 1.0 + (1.0 - s) / 8.0;
    let mut out = Vec::new();
    for i in 0..n {
        let (a, b, c, d) = (&p[(i + n - 1) % n], &p[i], &p[(i + 1) % n], &p[(i + 2) % n]);
        if s != 0.0 {
            out.push((2 * i, T::blend(b, s / 4.0, a)));
            out.push((2 * i, T::blend(b, s / 4.0, c)));
        }
        if s != 1.0 {
            out.push((2 * i + 1, T::blend(a, w, b)));
            out.push((2 * i + 1, T::blend(d, w, c)));
        }
    }
    out
}

/// Steps `0 .. sub.levels` of the subdivision of `input` (a cycle when `closed`), each taken
/// apart by [`split_tweak_step`]; step `ℓ` maps level `ℓ` to level `ℓ + 1`, and the output of the
/// last step is [`Subdivision::apply`]'s result (for an open sequence, its `kept` part).
///
/// An open sequence of `m` elements is first extended by `k` dummy elements at each end
/// (docs/math/open-sequences.md §2, `k` the scheme's half-width), so every step works on a cycle; `kept` is then
/// `(k·2^{ℓ+1}, (m−1)·2^{ℓ+1} + 1)`. Fails like [`Subdivision::apply`] (too few elements,
/// invalid options, the memory guard).
pub fn split_tweak_levels<T: Blend>(
    input: &[T],
    closed: bool,
    sub: Subdivision,
) -> Result<Vec<SplitTweakStep<T>>, Error> {
    sub.validate()?;
    sub.output_len(input.len(), closed)?;
    let k = sub.scheme.half_width();
    let mut current = if closed {
        input.to_vec()
    } else {
        extend_open(input, k)
    };
    let mut steps = Vec::with_capacity(sub.levels as usize);
    for level in 0..sub.levels {
        let mut step = split_tweak_step(&current, sub.scheme, sub.rules)?;
        if !closed {
            let f = 1usize << (level + 1);
            step.kept = (k * f, (input.len() - 1) * f + 1);
        }
        current = step.output.clone();
        steps.push(step);
    }
    Ok(steps)
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec2;

    #[test]
    fn split_inserts_midpoints() {
        let p = [DVec2::ZERO, DVec2::new(2.0, 0.0), DVec2::new(2.0, 2.0)];
        let z = split(&p);
        assert_eq!(z.len(), 6);
        assert_eq!(z[1], DVec2::new(1.0, 0.0));
        assert_eq!(z[5], DVec2::new(1.0, 1.0));
    }

    #[test]
    fn four_point_tweaks_new_slots_only() {
        let p = [
            DVec2::ZERO,
            DVec2::new(1.0, 0.0),
            DVec2::new(2.0, 0.0),
            DVec2::new(3.0, 3.0),
        ];
        let s = split_tweak_step(&p, Scheme::FourPoint, Rules::SplitThenTweak).unwrap();
        assert_eq!(
            s.tweaked,
            [false, true, false, true, false, true, false, true]
        );
        // docs/math/subdivision.md §3.3 numeric example: the new point between B and C.
        assert!((s.output[3] - DVec2::new(1.5, -0.1875)).length() < 1e-12);
        assert_eq!(s.helpers.len(), 4);
    }
}
