//! A small limited-memory BFGS minimiser with a strong-Wolfe line search (Nocedal & Wright,
//! *Numerical Optimization*, Algorithms 7.4, 3.5 and 3.6).
//!
//! Written here rather than taken from a crate: the objective of the quaternion spline has at
//! most a few hundred variables, needs nothing but `Vec<f64>`, and must run unchanged (and
//! deterministically, without a clock) in the browser.

use crate::lanes::pair::P;

/// Options of [`minimize`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LbfgsOptions {
    /// Number of stored correction pairs `(s, y)`.
    pub memory: usize,
    /// Iteration cap (each iteration is one line search).
    pub max_iterations: usize,
    /// Stop when `|∇f|_∞ ≤ gradient_tolerance · max(1, |f|)`.
    pub gradient_tolerance: f64,
    /// Stop when `(f_k − f_{k+1}) ≤ value_tolerance · max(1, |f_k|, |f_{k+1}|)`.
    pub value_tolerance: f64,
}

/// Default memory of [`LbfgsOptions`] (docs/math/quaternion-splines.md §4.2 gives 10–20).
pub const DEFAULT_LBFGS_MEMORY: usize = 20;
/// Default gradient tolerance (docs/math/quaternion-splines.md §4.2: `|∇OBJ|_∞ < 1e-10·max(1, OBJ)`).
pub const DEFAULT_GRADIENT_TOLERANCE: f64 = 1e-10;
/// Default relative decrease tolerance (docs/math/quaternion-splines.md §4.2: relative `OBJ` change `< 1e-12`).
pub const DEFAULT_VALUE_TOLERANCE: f64 = 1e-12;

/// Armijo (sufficient decrease) constant of the line search.
const WOLFE_C1: f64 = 1e-4;
/// Curvature constant of the strong Wolfe conditions (0.9 is standard for quasi-Newton).
const WOLFE_C2: f64 = 0.9;
/// Guard against division by zero (a zero gradient norm, a zero curvature `sᵀy`): values below
/// this are treated as zero.
const TINY: f64 = 1e-300;
/// The line search's bracket is resolved when its width is below this fraction of the step.
const BRACKET_TOLERANCE: f64 = 1e-16;
/// Largest number of trial steps in one line search.
const MAX_LINE_SEARCH_STEPS: usize = 40;

impl Default for LbfgsOptions {
    fn default() -> Self {
        LbfgsOptions {
            memory: DEFAULT_LBFGS_MEMORY,
            max_iterations: 10_000,
            gradient_tolerance: DEFAULT_GRADIENT_TOLERANCE,
            value_tolerance: DEFAULT_VALUE_TOLERANCE,
        }
    }
}

/// Why [`minimize`] stopped.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LbfgsStop {
    /// The gradient test passed.
    Gradient,
    /// The relative decrease test passed.
    Value,
    /// The iteration cap was reached.
    MaxIterations,
    /// No step satisfying the Wolfe conditions was found even along steepest descent (usually
    /// the minimum is resolved to round-off).
    LineSearch,
    /// The objective or gradient at the start point is not finite.
    NonFinite,
}

/// Outcome of [`minimize`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LbfgsReport {
    /// Final objective value.
    pub value: f64,
    /// Final `|∇f|_∞`.
    pub gradient_norm: f64,
    /// Iterations performed.
    pub iterations: usize,
    /// Objective/gradient evaluations.
    pub evaluations: usize,
    /// Why it stopped.
    pub stop: LbfgsStop,
}

/// `aᵀb` over the common length, with four partial sums (elements `4i + r` go to sum `r`, then
/// `(s₀ + s₁) + (s₂ + s₃)`, then the remaining elements in order): four independent chains of
/// additions instead of one, which is what bounds the two-loop recursion's time (its dot
/// products depend on each other and are as long as the variables).
fn dot(a: &[f64], b: &[f64]) -> f64 {
    let n = a.len().min(b.len());
    let (a, b) = (&a[..n], &b[..n]);
    // Partial sums 0, 1 in `lo`, 2, 3 in `hi`.
    let (mut lo, mut hi) = (P::splat(0.0), P::splat(0.0));
    let (a4, b4) = (a.chunks_exact(4), b.chunks_exact(4));
    let (ra, rb) = (a4.remainder(), b4.remainder());
    for (x, y) in a4.zip(b4) {
        lo = lo.add(P::new(x[0], x[1]).mul(P::new(y[0], y[1])));
        hi = hi.add(P::new(x[2], x[3]).mul(P::new(y[2], y[3])));
    }
    let ([s0, s1], [s2, s3]) = (lo.lanes(), hi.lanes());
    let mut total = (s0 + s1) + (s2 + s3);
    for (x, y) in ra.iter().zip(rb) {
        total += x * y;
    }
    total
}

/// `d ← d + c u`, then `vᵀd` summed exactly as [`dot`] does (0 without `v`), in one pass over `d`
/// (all three of the same length).
#[inline(always)]
fn axpy_then_dot(d: &mut [f64], c: f64, u: &[f64], v: Option<&[f64]>) -> f64 {
    let n = d.len().min(u.len());
    let (d, u) = (&mut d[..n], &u[..n]);
    let Some(v) = v else {
        for (di, ui) in d.iter_mut().zip(u) {
            *di += c * ui;
        }
        return 0.0;
    };
    let v = &v[..n];
    let (mut lo, mut hi) = (P::splat(0.0), P::splat(0.0));
    let cc = P::splat(c);
    let mut d4 = d.chunks_exact_mut(4);
    let (u4, v4) = (u.chunks_exact(4), v.chunks_exact(4));
    let (ru, rv) = (u4.remainder(), v4.remainder());
    for ((dc, uc), vc) in (&mut d4).zip(u4).zip(v4) {
        let d0 = P::new(dc[0], dc[1]).add(cc.mul(P::new(uc[0], uc[1])));
        let d1 = P::new(dc[2], dc[3]).add(cc.mul(P::new(uc[2], uc[3])));
        lo = lo.add(P::new(vc[0], vc[1]).mul(d0));
        hi = hi.add(P::new(vc[2], vc[3]).mul(d1));
        let ([a, b], [e, f]) = (d0.lanes(), d1.lanes());
        dc.copy_from_slice(&[a, b, e, f]);
    }
    let ([s0, s1], [s2, s3]) = (lo.lanes(), hi.lanes());
    let mut total = (s0 + s1) + (s2 + s3);
    for ((di, ui), vi) in d4.into_remainder().iter_mut().zip(ru).zip(rv) {
        *di += c * ui;
        total += vi * *di;
    }
    total
}

/// `max |aᵢ|` (0 for none; NaN entries are skipped, as `f64::max` does). A comparison rather than
/// `f64::max`, which is a call to `fmax` on wasm.
fn inf_norm(a: &[f64]) -> f64 {
    a.iter()
        .fold(0.0f64, |m, v| if v.abs() > m { v.abs() } else { m })
}

/// The stored correction pairs `(s, y)` and `ρ = 1/sᵀy` of [`minimize`]: a ring of `m` rows of
/// `n` numbers, pair `j` (0 = oldest) in row `(first + j) mod m`.
struct History {
    n: usize,
    s: Vec<f64>,
    y: Vec<f64>,
    rho: Vec<f64>,
    first: usize,
    len: usize,
}

impl History {
    /// Pair `j` (0 = oldest): `(s, y, ρ)`.
    fn pair(&self, j: usize) -> (&[f64], &[f64], f64) {
        let row = (self.first + j) % self.rho.len();
        let r = row * self.n..(row + 1) * self.n;
        (&self.s[r.clone()], &self.y[r], self.rho[row])
    }

    /// Appends a pair, dropping the oldest when all `m` rows are in use.
    fn push(&mut self, s: &[f64], y: &[f64], rho: f64) {
        let m = self.rho.len();
        let row = (self.first + self.len) % m;
        if self.len == m {
            self.first = (self.first + 1) % m;
        } else {
            self.len += 1;
        }
        let r = row * self.n..(row + 1) * self.n;
        self.s[r.clone()].copy_from_slice(s);
        self.y[r].copy_from_slice(y);
        self.rho[row] = rho;
    }

    /// Forgets every pair.
    fn clear(&mut self) {
        self.first = 0;
        self.len = 0;
    }
}

/// Minimises `f` from `x` (overwritten with the result). `f(x, g)` returns the value and writes
/// the gradient into `g`. Never panics; non-finite trial values shrink the step.
pub fn minimize<F>(mut f: F, x: &mut [f64], options: &LbfgsOptions) -> LbfgsReport
where
    F: FnMut(&[f64], &mut [f64]) -> f64,
{
    let n = x.len();
    let mut g = vec![0.0; n];
    let mut fx = f(x, &mut g);
    let mut evaluations = 1;
    let report = |value, g: &[f64], iterations, evaluations, stop| LbfgsReport {
        value,
        gradient_norm: inf_norm(g),
        iterations,
        evaluations,
        stop,
    };
    if n == 0 {
        return report(fx, &g, 0, evaluations, LbfgsStop::Gradient);
    }
    if !fx.is_finite() || !g.iter().all(|v| v.is_finite()) {
        return report(fx, &g, 0, evaluations, LbfgsStop::NonFinite);
    }
    let m = options.memory.max(1);
    // The last `m` correction pairs, oldest first from row `first` of a ring of `m` rows of `n`
    // (allocated once: nothing is allocated per iteration).
    let mut history = History {
        n,
        s: vec![0.0; m * n],
        y: vec![0.0; m * n],
        rho: vec![0.0; m],
        first: 0,
        len: 0,
    };
    let mut d = vec![0.0; n];
    let mut alpha_buf = vec![0.0; m];
    let mut x_new = vec![0.0; n];
    let mut g_new = vec![0.0; n];
    let mut s = vec![0.0; n];
    let mut y = vec![0.0; n];
    for iter in 0..options.max_iterations {
        if inf_norm(&g) <= options.gradient_tolerance * fx.abs().max(1.0) {
            return report(fx, &g, iter, evaluations, LbfgsStop::Gradient);
        }
        // Two-loop recursion: d = −H g. Each update of d is one pass with the dot product that
        // the next step needs (`axpy_then_dot`: the same sums as `dot` after the update).
        d.copy_from_slice(&g);
        let k = history.len;
        if k > 0 {
            let mut sd = dot(history.pair(k - 1).0, &d);
            for j in (0..k).rev() {
                let (_, yj, rho) = history.pair(j);
                let a = rho * sd;
                alpha_buf[j] = a;
                // d − a y, as d + (−a) y (the same bits).
                let next = (j > 0).then(|| history.pair(j - 1).0);
                sd = axpy_then_dot(&mut d, -a, yj, next);
            }
        }
        let gamma = if k > 0 {
            let (sk, yk, _) = history.pair(k - 1);
            dot(sk, yk) / dot(yk, yk)
        } else {
            1.0 / dot(&g, &g).sqrt().max(TINY)
        };
        for di in d.iter_mut() {
            *di *= gamma;
        }
        if k > 0 {
            let mut yd = dot(history.pair(0).1, &d);
            for (j, &aj) in alpha_buf.iter().enumerate().take(k) {
                let (sj, _, rho) = history.pair(j);
                let b = rho * yd;
                let next = (j + 1 < k).then(|| history.pair(j + 1).1);
                yd = axpy_then_dot(&mut d, aj - b, sj, next);
            }
        }
        for di in d.iter_mut() {
            *di = -*di;
        }
        let mut dg = dot(&d, &g);
        if dg.is_nan() || dg >= 0.0 {
            // Not a descent direction (lost curvature information): restart along −g.
            history.clear();
            let scale = 1.0 / dot(&g, &g).sqrt().max(TINY);
            for (di, gi) in d.iter_mut().zip(&g) {
                *di = -gi * scale;
            }
            dg = dot(&d, &g);
        }
        let step = line_search(
            &mut f,
            x,
            fx,
            dg,
            &d,
            &mut x_new,
            &mut g_new,
            &mut evaluations,
        );
        let Some(f_new) = step else {
            if history.len == 0 {
                return report(fx, &g, iter, evaluations, LbfgsStop::LineSearch);
            }
            // Retry once from steepest descent.
            history.clear();
            continue;
        };
        for ((si, a), b) in s.iter_mut().zip(&x_new).zip(x.iter()) {
            *si = a - b;
        }
        for ((yi, a), b) in y.iter_mut().zip(&g_new).zip(&g) {
            *yi = a - b;
        }
        let sy = dot(&s, &y);
        let decrease = fx - f_new;
        x.copy_from_slice(&x_new);
        g.copy_from_slice(&g_new);
        let f_old = fx;
        fx = f_new;
        if sy > TINY {
            history.push(&s, &y, 1.0 / sy);
        }
        if decrease <= options.value_tolerance * f_old.abs().max(fx.abs()).max(1.0) {
            return report(fx, &g, iter + 1, evaluations, LbfgsStop::Value);
        }
    }
    report(
        fx,
        &g,
        options.max_iterations,
        evaluations,
        LbfgsStop::MaxIterations,
    )
}

/// Strong-Wolfe line search along `d` from `x` (value `f0`, slope `dg0 < 0`). On success the
/// accepted point and gradient are in `x_new`, `g_new` and its value is returned.
#[allow(clippy::too_many_arguments)]
fn line_search<F>(
    f: &mut F,
    x: &[f64],
    f0: f64,
    dg0: f64,
    d: &[f64],
    x_new: &mut [f64],
    g_new: &mut [f64],
    evaluations: &mut usize,
) -> Option<f64>
where
    F: FnMut(&[f64], &mut [f64]) -> f64,
{
    let mut eval = |a: f64, x_new: &mut [f64], g_new: &mut [f64]| -> (f64, f64) {
        for ((xn, xi), di) in x_new.iter_mut().zip(x).zip(d) {
            *xn = xi + a * di;
        }
        *evaluations += 1;
        let v = f(x_new, g_new);
        if v.is_finite() && g_new.iter().all(|g| g.is_finite()) {
            (v, dot(g_new, d))
        } else {
            (f64::INFINITY, f64::NAN)
        }
    };
    let (mut a_prev, mut f_prev, mut dg_prev) = (0.0, f0, dg0);
    let mut a = 1.0;
    for i in 0..MAX_LINE_SEARCH_STEPS {
        let (fa, dga) = eval(a, x_new, g_new);
        if !fa.is_finite() {
            // Overshot into a region where the objective blows up: back off.
            a = 0.5 * (a_prev + a);
            continue;
        }
        if fa > f0 + WOLFE_C1 * a * dg0 || (i > 0 && fa >= f_prev) {
            return zoom(
                &mut eval, f0, dg0, a_prev, f_prev, dg_prev, a, fa, dga, x_new, g_new,
            );
        }
        if dga.abs() <= -WOLFE_C2 * dg0 {
            return Some(fa);
        }
        if dga >= 0.0 {
            return zoom(
                &mut eval, f0, dg0, a, fa, dga, a_prev, f_prev, dg_prev, x_new, g_new,
            );
        }
        a_prev = a;
        f_prev = fa;
        dg_prev = dga;
        a *= 2.0;
    }
    None
}

/// Minimiser of the cubic through `(a, fa, ga)` and `(b, fb, gb)`, safeguarded into the
/// middle 80 % of the bracket (bisection when the cubic is unusable).
#[allow(clippy::too_many_arguments)]
fn cubic_step(a: f64, fa: f64, ga: f64, b: f64, fb: f64, gb: f64) -> f64 {
    let (lo, hi) = if a < b { (a, b) } else { (b, a) };
    let margin = 0.1 * (hi - lo);
    let d1 = ga + gb - 3.0 * (fa - fb) / (a - b);
    let disc = d1 * d1 - ga * gb;
    let mid = 0.5 * (a + b);
    if disc.is_nan() || disc < 0.0 || !ga.is_finite() || !gb.is_finite() {
        return mid;
    }
    let d2 = (b - a).signum() * disc.sqrt();
    let t = b - (b - a) * (gb + d2 - d1) / (gb - ga + 2.0 * d2);
    if t.is_finite() && t > lo + margin && t < hi - margin {
        t
    } else {
        mid
    }
}

#[allow(clippy::too_many_arguments)]
fn zoom<E>(
    eval: &mut E,
    f0: f64,
    dg0: f64,
    mut lo: f64,
    mut f_lo: f64,
    mut dg_lo: f64,
    mut hi: f64,
    mut f_hi: f64,
    mut dg_hi: f64,
    x_new: &mut [f64],
    g_new: &mut [f64],
) -> Option<f64>
where
    E: FnMut(f64, &mut [f64], &mut [f64]) -> (f64, f64),
{
    for _ in 0..MAX_LINE_SEARCH_STEPS {
        let a = cubic_step(lo, f_lo, dg_lo, hi, f_hi, dg_hi);
        let (fa, dga) = eval(a, x_new, g_new);
        if !fa.is_finite() || fa > f0 + WOLFE_C1 * a * dg0 || fa >= f_lo {
            hi = a;
            f_hi = fa;
            dg_hi = dga;
        } else {
            if dga.abs() <= -WOLFE_C2 * dg0 {
                return Some(fa);
            }
            if dga * (hi - lo) >= 0.0 {
                hi = lo;
                f_hi = f_lo;
                dg_hi = dg_lo;
            }
            lo = a;
            f_lo = fa;
            dg_lo = dga;
        }
        if (hi - lo).abs() <= BRACKET_TOLERANCE * lo.abs().max(TINY) {
            break;
        }
    }
    // Accept the best sufficient-decrease point found, if it improves on the start.
    if lo > 0.0 && f_lo < f0 {
        let (fa, _) = eval(lo, x_new, g_new);
        if fa.is_finite() {
            return Some(fa);
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn minimises_rosenbrock() {
        let mut x = vec![-1.2, 1.0, -1.2, 1.0];
        let r = minimize(
            |x, g| {
                let mut f = 0.0;
                g.iter_mut().for_each(|v| *v = 0.0);
                for i in 0..x.len() - 1 {
                    let (a, b) = (x[i], x[i + 1]);
                    f += 100.0 * (b - a * a).powi(2) + (1.0 - a).powi(2);
                    g[i] += -400.0 * a * (b - a * a) - 2.0 * (1.0 - a);
                    g[i + 1] += 200.0 * (b - a * a);
                }
                f
            },
            &mut x,
            &LbfgsOptions::default(),
        );
        assert!(x.iter().all(|v| (v - 1.0).abs() < 1e-7), "{x:?} {r:?}");
        assert!(r.value < 1e-14);
    }

    #[test]
    fn quadratic_and_edge_cases() {
        // Ill-conditioned quadratic.
        let diag = [1.0, 10.0, 1e3, 1e5];
        let mut x = vec![1.0; 4];
        let r = minimize(
            |x, g| {
                let mut f = 0.0;
                for i in 0..4 {
                    f += 0.5 * diag[i] * (x[i] - i as f64).powi(2);
                    g[i] = diag[i] * (x[i] - i as f64);
                }
                f
            },
            &mut x,
            &LbfgsOptions::default(),
        );
        assert!(
            x.iter()
                .enumerate()
                .all(|(i, v)| (v - i as f64).abs() < 1e-8),
            "{r:?}"
        );
        // No variables.
        let r = minimize(|_, _| 3.0, &mut [], &LbfgsOptions::default());
        assert_eq!((r.value, r.stop), (3.0, LbfgsStop::Gradient));
        // Non-finite start.
        let r = minimize(
            |_, g| {
                g[0] = 0.0;
                f64::NAN
            },
            &mut [0.0],
            &LbfgsOptions::default(),
        );
        assert_eq!(r.stop, LbfgsStop::NonFinite);
        // Blows up away from the start: backs off instead of failing.
        let mut x = vec![0.5];
        let r = minimize(
            |x, g| {
                if x[0] >= 1.0 {
                    g[0] = f64::NAN;
                    return f64::INFINITY;
                }
                g[0] = -1.0 / (1.0 - x[0]) + 2.0 * x[0];
                -(1.0 - x[0]).ln() + x[0] * x[0]
            },
            &mut x,
            &LbfgsOptions::default(),
        );
        assert!(r.value.is_finite() && x[0] < 1.0, "{r:?} {x:?}");
    }
}
