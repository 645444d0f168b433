//! The C¹ piecewise cubic Hermite quaternion spline of Ramamoorthi & Barr, its objective
//! (covariant acceleration plus a unit-length penalty) with analytic gradient, and the
//! Euler–Lagrange error used to place variable frames (docs/math/quaternion-splines.md §2–§5).
//!
//! The spline lives in R⁴ (its values are not unit quaternions); the rotation it describes is
//! `q/|q|`. Quaternion-valued 4-vectors are stored in [`DQuat`] (see `methods::algebra`).

use glam::DQuat;

use crate::error::{check_finite, Error, ErrorKind};
use crate::lanes::pair::P;
use crate::methods::gauss::gauss_legendre;
use crate::methods::polynomial::HERMITE_POWER;

/// Largest number of segments per keyframe interval and of samples accepted by
/// [`HermiteQuatSpline::segment_deviations`] and [`HermiteQuatSpline::unit_deviation`] (larger
/// requests are clamped: a guard against runaway memory and time).
pub const MAX_SPLINE_SAMPLES: usize = 10_000_000;

/// Two frame times closer than this fraction of the local keyframe spacing are the same time
/// (used when excluding candidate segment starts that already carry a frame, docs/math/quaternion-splines.md §4 step 4).
pub const FRAME_TIME_TOLERANCE: f64 = 1e-9;

/// One frame of the spline: time, position and velocity in R⁴, and which of them the optimiser
/// may change.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame {
    /// Frame time `τ_f`.
    pub t: f64,
    /// Position `p_f ∈ R⁴` (a keyframe quaternion, or a free point for a variable frame).
    pub p: DQuat,
    /// Velocity `m_f = dq/dt ∈ R⁴`.
    pub m: DQuat,
    /// Whether `p` is a free variable (variable frames only).
    pub pos_free: bool,
    /// Whether `m` is a free variable.
    pub vel_free: bool,
    /// Whether this frame is a keyframe (its position is data).
    pub keyframe: bool,
}

/// The integrand `F` and its partial derivatives (docs/math/quaternion-splines.md §2, §4.2) at one point:
///
/// ```text
/// F = |q''|² − (q·q'')²/|q|² + α(1 − |q|²)²
/// ∂F/∂q = 2(q T² − q'' T) + 4α(|q|² − 1) q,   ∂F/∂q'' = 2(q'' − q T),   T = q·q''/|q|²
/// ```
pub fn integrand(q: DQuat, q2: DQuat, alpha: f64) -> (f64, DQuat, DQuat) {
    let a = q.dot(q2);
    let b = q.length_squared();
    let t = a / b;
    let f = q2.length_squared() - a * t + alpha * (1.0 - b) * (1.0 - b);
    let dq = (q * (t * t) - q2 * t) * 2.0 + q * (4.0 * alpha * (b - 1.0));
    let dq2 = (q2 - q * t) * 2.0;
    (f, dq, dq2)
}

/// A point of R⁴ as the pairs `[x, y]` and `[z, w]`: a piece's coefficients in power form and
/// the gradient's moments, combined per piece (half the instructions on wasm SIMD).
#[derive(Clone, Copy)]
struct Q4 {
    lo: P,
    hi: P,
}

impl Q4 {
    #[inline(always)]
    fn from(q: DQuat) -> Q4 {
        Q4 {
            lo: P::new(q.x, q.y),
            hi: P::new(q.z, q.w),
        }
    }

    #[inline(always)]
    fn to_array(self) -> [f64; 4] {
        let [x, y] = self.lo.lanes();
        let [z, w] = self.hi.lanes();
        [x, y, z, w]
    }

    #[inline(always)]
    fn scale(self, s: f64) -> Q4 {
        let s = P::splat(s);
        Q4 {
            lo: self.lo.mul(s),
            hi: self.hi.mul(s),
        }
    }

    #[inline(always)]
    fn add(self, o: Q4) -> Q4 {
        Q4 {
            lo: self.lo.add(o.lo),
            hi: self.hi.add(o.hi),
        }
    }

    #[inline(always)]
    fn sub(self, o: Q4) -> Q4 {
        Q4 {
            lo: self.lo.sub(o.lo),
            hi: self.hi.sub(o.hi),
        }
    }
}

/// Two points of R⁴, one per lane: component `i` of both in `c[i]` (`x, y, z, w`). The
/// objective's inner loop evaluates two quadrature nodes at once in this layout, so that its dot
/// products and its division are lane by lane too (nothing is added across lanes until a piece
/// is summed).
#[derive(Clone, Copy)]
struct Q4x2 {
    c: [P; 4],
}

impl Q4x2 {
    #[inline(always)]
    fn zero() -> Q4x2 {
        Q4x2 {
            c: [P::splat(0.0); 4],
        }
    }

    /// `q` in both lanes.
    #[inline(always)]
    fn splat(q: Q4) -> Q4x2 {
        Q4x2 {
            c: [
                q.lo.first_twice(),
                q.lo.second_twice(),
                q.hi.first_twice(),
                q.hi.second_twice(),
            ],
        }
    }

    /// The two lanes added, as one point.
    #[inline(always)]
    fn lane_sum(self) -> Q4 {
        let [x, y, z, w] = self.c;
        Q4 {
            lo: x.lane_sums(y),
            hi: z.lane_sums(w),
        }
    }

    #[inline(always)]
    fn scale(self, s: P) -> Q4x2 {
        Q4x2 {
            c: self.c.map(|c| c.mul(s)),
        }
    }

    /// `op` component by component.
    #[inline(always)]
    fn zip(self, o: Q4x2, op: impl Fn(P, P) -> P) -> Q4x2 {
        let [a, b, c, d] = self.c;
        let [e, f, g, h] = o.c;
        Q4x2 {
            c: [op(a, e), op(b, f), op(c, g), op(d, h)],
        }
    }

    #[inline(always)]
    fn add(self, o: Q4x2) -> Q4x2 {
        self.zip(o, P::add)
    }

    #[inline(always)]
    fn sub(self, o: Q4x2) -> Q4x2 {
        self.zip(o, P::sub)
    }

    /// `(xx' + zz') + (yy' + ww')` in each lane.
    #[inline(always)]
    fn dot(self, o: Q4x2) -> P {
        let [x, y, z, w] = self.c;
        let [x2, y2, z2, w2] = o.c;
        x.mul(x2).add(z.mul(z2)).add(y.mul(y2).add(w.mul(w2)))
    }
}

/// Two quadrature nodes side by side: their fractions `s` and `w sᵐ` (`m = 0..4`) with their
/// weights `w`, computed once per spline (see [`node_pairs`]).
#[derive(Clone, Copy, Debug, PartialEq)]
struct NodePair {
    s: [f64; 2],
    ws: [[f64; 2]; 4],
}

/// The quadrature nodes two by two; an odd count ends with its last node again at weight 0 (every
/// term it adds is zero, and it is finite wherever the real node is).
fn node_pairs(nodes: &[f64], weights: &[f64]) -> Vec<NodePair> {
    let one = |k: usize, weight: bool| {
        let (s, w) = (nodes[k], if weight { weights[k] } else { 0.0 });
        (s, [w, w * s, w * s * s, w * s * s * s])
    };
    (0..nodes.len().div_ceil(2))
        .map(|i| {
            let (s0, m0) = one(2 * i, true);
            let k1 = (2 * i + 1).min(nodes.len() - 1);
            let (s1, m1) = one(k1, k1 == 2 * i + 1);
            NodePair {
                s: [s0, s1],
                ws: [0, 1, 2, 3].map(|m| [m0[m], m1[m]]),
            }
        })
        .collect()
}

/// `q` and `q''` at local fractions `s` (two nodes) of a piece in power form:
/// `q = (a₀ + a₁s) + s²(a₂ + a₃s)`, `q'' = b₀ + s b₁` (see
/// [`HermiteQuatSpline::piece_power_form`]; the coefficients in both lanes). Estrin's scheme
/// rather than Horner's: two dependent multiply-adds instead of three before the integrand,
/// whose division waits for `q`.
#[inline(always)]
fn values(a: &[Q4x2; 4], b: &[Q4x2; 2], s: P) -> (Q4x2, Q4x2) {
    let q = a[1]
        .scale(s)
        .add(a[0])
        .add(a[3].scale(s).add(a[2]).scale(s.mul(s)));
    let q2 = b[1].scale(s).add(b[0]);
    (q, q2)
}

/// [`integrand`] at two nodes, with its two partial derivatives halved (`½∂F/∂q = q(T² + 2α(|q|²
/// − 1)) − q''T`, `½∂F/∂q'' = q'' − qT`: fewer operations; the gradient is doubled once per
/// piece). `alpha` and `two_alpha` are `α` and `2α` in both lanes.
#[inline(always)]
fn integrand_x2(q: Q4x2, q2: Q4x2, alpha: P, two_alpha: P) -> (P, Q4x2, Q4x2) {
    let one = P::splat(1.0);
    let a = q.dot(q2);
    let b = q.dot(q);
    let t = a.div(b);
    let one_minus_b = one.sub(b);
    let f = q2
        .dot(q2)
        .sub(a.mul(t))
        .add(alpha.mul(one_minus_b).mul(one_minus_b));
    let half_dq = q
        .scale(t.mul(t).add(two_alpha.mul(b.sub(one))))
        .sub(q2.scale(t));
    let half_dq2 = q2.sub(q.scale(t));
    (f, half_dq, half_dq2)
}

/// The Euler–Lagrange residual of the objective and the intermediate `T, T', T''`
/// (docs/math/quaternion-splines.md §5, eqs. 7–9 with the two corrections marked there).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EulerLagrange {
    /// `EL = 2(U + V'' + W)` as a 4-vector.
    pub el: DQuat,
    /// `T = q·q''/|q|²`.
    pub t: f64,
    /// `T'`.
    pub t1: f64,
    /// `T''`.
    pub t2: f64,
}

impl EulerLagrange {
    /// `|EL|`.
    pub fn norm(&self) -> f64 {
        self.el.length()
    }
}

/// The Euler–Lagrange residual from `q` and its first four derivatives (`q'''' = 0` on cubic
/// pieces; kept general for the great-circle check):
///
/// ```text
/// U = q T² − q'' T,  W = 2α(|q|² − 1) q,  V'' = q'''' − (q'' T + 2 q' T' + q T'')
/// T'  = (d12 + d03)/d00 − 2 d01 d02/d00²
/// T'' = (2 d13 + d22 + d04)/d00 − 4 d01 (d12 + d03)/d00² − 2 d02 (d02 + d11)/d00² + 8 d01² d02/d00³
/// ```
///
/// with `d_jk = q^(j) · q^(k)`.
pub fn euler_lagrange(
    q: DQuat,
    q1: DQuat,
    q2: DQuat,
    q3: DQuat,
    q4: DQuat,
    alpha: f64,
) -> EulerLagrange {
    let d00 = q.dot(q);
    let d01 = q.dot(q1);
    let d02 = q.dot(q2);
    let d03 = q.dot(q3);
    let d04 = q.dot(q4);
    let d11 = q1.dot(q1);
    let d12 = q1.dot(q2);
    let d13 = q1.dot(q3);
    let d22 = q2.dot(q2);
    let t = d02 / d00;
    let t1 = (d12 + d03) / d00 - 2.0 * d01 * d02 / (d00 * d00);
    let t2 = (2.0 * d13 + d22 + d04) / d00
        - 4.0 * d01 * (d12 + d03) / (d00 * d00)
        - 2.0 * d02 * (d02 + d11) / (d00 * d00)
        + 8.0 * d01 * d01 * d02 / (d00 * d00 * d00);
    let u = q * (t * t) - q2 * t;
    let vpp = q4 - (q2 * t + q1 * (2.0 * t1) + q * t2);
    let w = q * (2.0 * alpha * (d00 - 1.0));
    EulerLagrange {
        el: (u + vpp + w) * 2.0,
        t,
        t1,
        t2,
    }
}

/// A C¹ piecewise cubic Hermite curve in R⁴ through a sorted list of frames, open or closed, with
/// the objective of Ramamoorthi & Barr.
///
/// Piece `j` joins frame `j` to frame `j + 1` (for a closed spline the last piece joins the last
/// frame to frame 0 at the period end, multiplied by `wrap_sign = ±1`: the curve may return to
/// `−Q_0`, the same rotation, so the R⁴ curve is periodic or anti-periodic; the objective is
/// invariant under `q → −q`).
#[derive(Clone, Debug, PartialEq)]
pub struct HermiteQuatSpline {
    frames: Vec<Frame>,
    closed: bool,
    end: f64,
    wrap_sign: f64,
    alpha: f64,
    nodes: Vec<f64>,
    weights: Vec<f64>,
    /// The nodes two by two with `w sᵐ` (`m = 0..4`), computed once: the objective evaluates two
    /// nodes at once, and its gradient is summed as these moments of `∂F/∂q` and `∂F/∂q''`.
    node_pairs: Vec<NodePair>,
    /// Per frame, the offsets of its position and velocity in the variables
    /// ([`HermiteQuatSpline::variables`]), [`NO_SLOT`] when not free; kept with the frames.
    slots: Vec<[usize; 2]>,
}

/// A frame's position or velocity that is not a free variable (see `HermiteQuatSpline::slots`).
const NO_SLOT: usize = usize::MAX;

/// The offsets of every frame's free position and velocity in the variables.
fn variable_slots(frames: &[Frame]) -> Vec<[usize; 2]> {
    let mut k = 0;
    frames
        .iter()
        .map(|f| {
            let mut slot = [NO_SLOT; 2];
            for (s, free) in slot.iter_mut().zip([f.pos_free, f.vel_free]) {
                if free {
                    *s = k;
                    k += 4;
                }
            }
            slot
        })
        .collect()
}

/// One piece's data: control values and timing.
#[derive(Clone, Copy, Debug)]
struct Piece {
    f0: usize,
    f1: usize,
    p0: DQuat,
    m0: DQuat,
    p1: DQuat,
    m1: DQuat,
    t0: f64,
    dt: f64,
    sign: f64,
}

impl HermiteQuatSpline {
    /// A spline from frames sorted by strictly increasing, finite times, with the penalty weight
    /// `alpha ≥ 0` in the frames' time units and an `n`-point Gauss–Legendre rule per piece
    /// (`n` clamped to `1 ..= 64`). For a closed spline `end` is the period end (after the last
    /// frame) and `wrap_sign` the sign of frame 0 at the period end; for an open one they are
    /// ignored. Needs at least 2 frames (open) or 1 (closed); errors name `frames[i]`, `end` or
    /// `alpha`.
    pub fn new(
        frames: Vec<Frame>,
        closed: bool,
        end: f64,
        wrap_sign: f64,
        alpha: f64,
        gauss_nodes: usize,
    ) -> Result<HermiteQuatSpline, Error> {
        let min = if closed { 1 } else { 2 };
        if frames.len() < min {
            return Err(Error::new(
                "frames",
                ErrorKind::TooFewPoses {
                    found: frames.len(),
                    min,
                },
            ));
        }
        for (i, f) in frames.iter().enumerate() {
            check_finite(&[f.t], &format!("frames[{i}].t"))?;
            check_finite(&f.p.to_array(), &format!("frames[{i}].p"))?;
            check_finite(&f.m.to_array(), &format!("frames[{i}].m"))?;
            if i > 0 && f.t <= frames[i - 1].t {
                return Err(Error::new(
                    format!("frames[{i}].t"),
                    ErrorKind::OutOfRange {
                        value: f.t.to_string(),
                        expected: format!("a time after frames[{}].t = {}", i - 1, frames[i - 1].t),
                    },
                ));
            }
        }
        let last = frames[frames.len() - 1].t;
        if closed && (end.is_nan() || end <= last || end.is_infinite()) {
            return Err(Error::new(
                "end",
                ErrorKind::OutOfRange {
                    value: end.to_string(),
                    expected: format!("a finite period end after the last frame time {last}"),
                },
            ));
        }
        if alpha.is_nan() || alpha < 0.0 || alpha.is_infinite() {
            return Err(Error::new(
                "alpha",
                ErrorKind::OutOfRange {
                    value: alpha.to_string(),
                    expected: "a finite number ≥ 0".into(),
                },
            ));
        }
        let (nodes, weights) = gauss_legendre(gauss_nodes);
        let node_pairs = node_pairs(&nodes, &weights);
        let slots = variable_slots(&frames);
        let end = if closed {
            end
        } else {
            frames.last().map_or(0.0, |f| f.t)
        };
        Ok(HermiteQuatSpline {
            frames,
            closed,
            end,
            wrap_sign: if wrap_sign < 0.0 { -1.0 } else { 1.0 },
            alpha,
            nodes,
            weights,
            node_pairs,
            slots,
        })
    }

    /// The frames, sorted by time.
    pub fn frames(&self) -> &[Frame] {
        &self.frames
    }

    /// Whether the spline is a cycle.
    pub fn is_closed(&self) -> bool {
        self.closed
    }

    /// The parameter interval `[first frame time, end]`.
    pub fn domain(&self) -> (f64, f64) {
        (self.frames.first().map_or(0.0, |f| f.t), self.end)
    }

    /// The penalty weight `α` in the spline's own time units.
    pub fn alpha(&self) -> f64 {
        self.alpha
    }

    /// Sets the penalty weight (in the spline's time units); a negative or non-finite value is
    /// ignored.
    pub fn set_alpha(&mut self, alpha: f64) {
        if alpha.is_finite() && alpha >= 0.0 {
            self.alpha = alpha;
        }
    }

    /// The number of cubic pieces.
    pub fn piece_count(&self) -> usize {
        if self.closed {
            self.frames.len()
        } else {
            self.frames.len().saturating_sub(1)
        }
    }

    fn piece(&self, j: usize) -> Piece {
        let f0 = j;
        let last = j + 1 == self.frames.len();
        let f1 = if last { 0 } else { j + 1 };
        let (a, b) = (&self.frames[f0], &self.frames[f1]);
        let (t1, sign) = if last {
            (self.end, self.wrap_sign)
        } else {
            (b.t, 1.0)
        };
        Piece {
            f0,
            f1,
            p0: a.p,
            m0: a.m,
            p1: b.p * sign,
            m1: b.m * sign,
            t0: a.t,
            dt: t1 - a.t,
            sign,
        }
    }

    /// Wraps `t` into the period (closed) and finds its piece and local fraction `s`.
    fn locate(&self, t: f64) -> (usize, f64) {
        let (t0, t1) = self.domain();
        let t = if self.closed && t.is_finite() && t1 > t0 {
            t0 + (t - t0).rem_euclid(t1 - t0)
        } else {
            t
        };
        let count = self.piece_count().max(1);
        let j = self
            .frames
            .partition_point(|f| f.t <= t)
            .saturating_sub(1)
            .min(count - 1);
        let p = self.piece(j);
        (j, (t - p.t0) / p.dt)
    }

    /// `q, q', q'', q'''` at time `t` (closed splines wrap; open ones extrapolate their end
    /// pieces). Exactly at a frame the next piece is used.
    pub fn eval(&self, t: f64) -> [DQuat; 4] {
        let (j, s) = self.locate(t);
        self.eval_piece(j, s)
    }

    fn eval_piece(&self, j: usize, s: f64) -> [DQuat; 4] {
        let p = self.piece(j);
        crate::methods::polynomial::hermite_d3(p.p0, p.m0, p.p1, p.m1, p.dt, s)
    }

    /// The number of free variables (4 per free position or velocity).
    pub fn variable_count(&self) -> usize {
        self.frames
            .iter()
            .map(|f| 4 * (f.pos_free as usize + f.vel_free as usize))
            .sum()
    }

    /// The free variables, frame by frame: position (if free) then velocity (if free), each as
    /// glam's `x, y, z, w`.
    pub fn variables(&self) -> Vec<f64> {
        let mut x = Vec::with_capacity(self.variable_count());
        for f in &self.frames {
            if f.pos_free {
                x.extend_from_slice(&f.p.to_array());
            }
            if f.vel_free {
                x.extend_from_slice(&f.m.to_array());
            }
        }
        x
    }

    /// Sets the free variables (layout of [`HermiteQuatSpline::variables`]); extra or missing
    /// entries are ignored.
    pub fn set_variables(&mut self, x: &[f64]) {
        let mut it = x.chunks_exact(4);
        for f in &mut self.frames {
            if f.pos_free {
                if let Some(c) = it.next() {
                    f.p = DQuat::from_slice(c);
                }
            }
            if f.vel_free {
                if let Some(c) = it.next() {
                    f.m = DQuat::from_slice(c);
                }
            }
        }
    }

    /// The objective `OBJ = ∫ F dt` (docs/math/quaternion-splines.md §2, eq. 3) by Gauss–Legendre quadrature on every piece.
    pub fn objective(&self) -> f64 {
        self.objective_impl(None, self.alpha)
    }

    /// The covariant-acceleration part alone, `∫ |q'' \ q|² dt` (the objective with `α = 0`).
    pub fn covariant_acceleration(&self) -> f64 {
        self.objective_impl(None, 0.0)
    }

    /// The objective and its gradient with respect to the free variables (docs/math/quaternion-splines.md §4.2), written
    /// into `gradient` (length [`HermiteQuatSpline::variable_count`]).
    pub fn objective_and_gradient(&self, gradient: &mut [f64]) -> f64 {
        self.objective_impl(Some(gradient), self.alpha)
    }

    /// `∫ F dt` with penalty weight `alpha`, and with `gradient` its gradient with respect to the
    /// free variables (docs/math/quaternion-splines.md §4.2), by Gauss–Legendre quadrature on
    /// every piece. Each piece is evaluated in power form, and its gradient summed as six moments
    /// of `∂F/∂q` and `∂F/∂q''` (instead of four sums over the Hermite basis); the result is
    /// added straight into `gradient` (only the slots of free variables are written). Allocates
    /// nothing: the nodes' moments `w sᵐ` and the variables' slots are kept by the spline.
    fn objective_impl(&self, gradient: Option<&mut [f64]>, alpha: f64) -> f64 {
        let Some(out) = gradient else {
            let mut total = 0.0;
            for j in 0..self.piece_count() {
                let (p, a, b, _) = self.piece_power_form(j);
                total += p.dt * self.piece_sums::<false>(&a, &b, alpha).0;
            }
            return total;
        };
        // The slot of each free variable that fits in `out` (others are left alone), zeroed.
        let len = out.len();
        let slot = |k: usize| (k != NO_SLOT && k + 4 <= len).then_some(k);
        for s in self.slots.iter().flatten().filter_map(|&k| slot(k)) {
            out[s..s + 4].fill(0.0);
        }
        let mut total = 0.0;
        for j in 0..self.piece_count() {
            let (p, a, b, inv2) = self.piece_power_form(j);
            let (sum, mq, mq2) = self.piece_sums::<true>(&a, &b, alpha);
            total += p.dt * sum;
            // ∂/∂c_k = Σ w (∂F/∂q H_k(s) + ∂F/∂q'' H_k''(s)/Δ²) with the Hermite basis H_k
            // (docs/math/quaternion-splines.md §3) expanded in powers of s.
            let combine = |h: [f64; 4], h2: [f64; 2]| {
                let v = mq[0]
                    .scale(h[0])
                    .add(mq[1].scale(h[1]))
                    .add(mq[2].scale(h[2]))
                    .add(mq[3].scale(h[3]));
                v.add(mq2[0].scale(h2[0]).add(mq2[1].scale(h2[1])).scale(inv2))
            };
            // H_k'' = 2c₂ + 6c₃ s (small integers: exact).
            let g = HERMITE_POWER.map(|c| combine(c, [2.0 * c[2], 6.0 * c[3]]));
            let d = p.dt;
            let (fa, fb) = (self.slots[p.f0], self.slots[p.f1]);
            let to = [fa[0], fa[1], fb[0], fb[1]];
            // Twice the moments' combination (the integrand gave half derivatives).
            let scale = [d, d * d, d * p.sign, d * d * p.sign].map(|x| 2.0 * x);
            for k in 0..4 {
                if let Some(s) = slot(to[k]) {
                    let v = g[k].scale(scale[k]).to_array();
                    for (o, v) in out[s..s + 4].iter_mut().zip(v) {
                        *o += v;
                    }
                }
            }
        }
        total
    }

    /// Over the nodes of one piece in power form (`a`, `b` of
    /// [`HermiteQuatSpline::piece_power_form`]): `Σ w F`, and with `MOMENTS` the moments
    /// `Σ w sᵐ ½∂F/∂q` (`m = 0..4`) and `Σ w sᵐ ½∂F/∂q''` (`m = 0, 1`). Nodes go two at a time
    /// ([`NodePair`]): each lane sums every other node, and the two lanes are added at the end.
    #[inline(always)]
    fn piece_sums<const MOMENTS: bool>(
        &self,
        a: &[Q4; 4],
        b: &[Q4; 2],
        alpha: f64,
    ) -> (f64, [Q4; 4], [Q4; 2]) {
        let (a, b) = (a.map(Q4x2::splat), b.map(Q4x2::splat));
        let (two_alpha, alpha) = (P::splat(2.0 * alpha), P::splat(alpha));
        // The integrand at a node pair: `w F`, the half derivatives and the moments' weights.
        let at = |n: &NodePair| {
            let (q, q2) = values(&a, &b, P::new(n.s[0], n.s[1]));
            let (f, hdq, hdq2) = integrand_x2(q, q2, alpha, two_alpha);
            let ws = n.ws.map(|[u, v]| P::new(u, v));
            (ws[0].mul(f), hdq, hdq2, ws)
        };
        // The sums start from the first pair's terms rather than from zero: V8 keeps most of
        // the 25 sums in memory, and zeroing them costs a load and a store each per piece.
        let mut pairs = self.node_pairs.iter();
        let Some(first) = pairs.next() else {
            let zero = Q4x2::zero().lane_sum();
            return (0.0, [zero; 4], [zero; 2]);
        };
        let (mut sum, hdq, hdq2, ws) = at(first);
        let mut mq = [0, 1, 2, 3].map(|m| hdq.scale(ws[m]));
        let mut mq2 = [0, 1].map(|m| hdq2.scale(ws[m]));
        for n in pairs {
            let (wf, hdq, hdq2, ws) = at(n);
            sum = sum.add(wf);
            if MOMENTS {
                for m in 0..4 {
                    mq[m] = mq[m].add(hdq.scale(ws[m]));
                }
                for m in 0..2 {
                    mq2[m] = mq2[m].add(hdq2.scale(ws[m]));
                }
            }
        }
        let [s0, s1] = sum.lanes();
        (s0 + s1, mq.map(Q4x2::lane_sum), mq2.map(Q4x2::lane_sum))
    }

    /// Piece `j` and its cubic in powers of the local fraction `s`: `q = a₀ + a₁s + a₂s² + a₃s³`
    /// from the Hermite form `H₀p₀ + H₁Δm₀ + H₂p₁ + H₃Δm₁` (docs/math/quaternion-splines.md §3),
    /// `q''/Δ²`'s coefficients `b₀ = 2a₂/Δ²`, `b₁ = 6a₃/Δ²` (time derivatives), and `1/Δ²` itself
    /// (the gradient scales by it too).
    #[inline(always)]
    fn piece_power_form(&self, j: usize) -> (Piece, [Q4; 4], [Q4; 2], f64) {
        let p = self.piece(j);
        let [p0, dm0, p1, dm1] = [p.p0, p.m0 * p.dt, p.p1, p.m1 * p.dt].map(Q4::from);
        let a2 = p1.sub(p0).scale(3.0).sub(dm0.scale(2.0)).sub(dm1);
        let a3 = p0.sub(p1).scale(2.0).add(dm0).add(dm1);
        let inv2 = 1.0 / (p.dt * p.dt);
        (
            p,
            [p0, dm0, a2, a3],
            [a2.scale(2.0 * inv2), a3.scale(6.0 * inv2)],
            inv2,
        )
    }

    /// The Euler–Lagrange residual at `t` (inside a piece; at a frame the next piece is used).
    pub fn euler_lagrange_at(&self, t: f64) -> EulerLagrange {
        let [q, q1, q2, q3] = self.eval(t);
        euler_lagrange(
            q,
            q1,
            q2,
            q3,
            DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0),
            self.alpha,
        )
    }

    /// `DEV(t_n) = (1/Δt) ∫_{t_n}^{t_n+Δt} |EL| dt` (docs/math/quaternion-splines.md §4, eq. 4) for every segment: each keyframe
    /// interval `[k_i, k_{i+1}]` (`key_times` sorted, for a closed spline ending with the period
    /// end) split into `per_interval` equal segments; integrals split at frames inside a segment.
    /// Returns `(segment start, DEV)` pairs.
    pub fn segment_deviations(&self, key_times: &[f64], per_interval: usize) -> Vec<(f64, f64)> {
        let per = per_interval.clamp(1, MAX_SPLINE_SAMPLES);
        let segments = key_times.len().saturating_sub(1).saturating_mul(per);
        let mut out = Vec::with_capacity(segments.min(1 << 16));
        for w in key_times.windows(2) {
            let dt = (w[1] - w[0]) / per as f64;
            for s in 0..per {
                let ta = w[0] + s as f64 * dt;
                let tb = ta + dt;
                // Cut at the frames strictly inside the segment (frames are sorted).
                let inside = self.frames.iter().map(|f| f.t).filter(|&t| {
                    t > ta + FRAME_TIME_TOLERANCE * dt && t < tb - FRAME_TIME_TOLERANCE * dt
                });
                let mut total = 0.0;
                let mut c0 = ta;
                for c1 in inside.chain(std::iter::once(tb)) {
                    self.add_el_integral(c0, c1, &mut total);
                    c0 = c1;
                }
                out.push((ta, total / dt));
            }
        }
        out
    }

    /// Adds `∫_{c0}^{c1} |EL| dt` by Gauss–Legendre quadrature on the piece containing both ends
    /// to `total`, node by node.
    fn add_el_integral(&self, c0: f64, c1: f64, total: &mut f64) {
        let (j, _) = self.locate(0.5 * (c0 + c1));
        let p = self.piece(j);
        let len = c1 - c0;
        for (&x, &wt) in self.nodes.iter().zip(&self.weights) {
            let t = c0 + len * x;
            // Local fraction on piece j (the cut lies inside the piece).
            let s = (t - p.t0) / p.dt;
            let [q, q1, q2, q3] =
                crate::methods::polynomial::hermite_d3(p.p0, p.m0, p.p1, p.m1, p.dt, s);
            let el = euler_lagrange(
                q,
                q1,
                q2,
                q3,
                DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0),
                self.alpha,
            );
            *total += len * wt * el.norm();
        }
    }

    /// Inserts a variable frame at `t` initialised from the current curve (`p = q(t)`,
    /// `m = q'(t)`), which leaves the curve unchanged (docs/math/quaternion-splines.md §4 step 4). Returns its index, or
    /// `None` when `t` is outside the domain or already a frame time.
    pub fn insert_frame(&mut self, t: f64) -> Option<usize> {
        let (t0, t1) = self.domain();
        if !(t > t0 && t < t1) {
            return None;
        }
        let [q, q1, _, _] = self.eval(t);
        let idx = self.frames.partition_point(|f| f.t < t);
        let scale = (t1 - t0).max(f64::MIN_POSITIVE);
        let clash = |i: usize| {
            self.frames
                .get(i)
                .is_some_and(|f| (f.t - t).abs() <= FRAME_TIME_TOLERANCE * scale)
        };
        if clash(idx) || (idx > 0 && clash(idx - 1)) {
            return None;
        }
        self.frames.insert(
            idx,
            Frame {
                t,
                p: q,
                m: q1,
                pos_free: true,
                vel_free: true,
                keyframe: false,
            },
        );
        self.slots = variable_slots(&self.frames);
        Some(idx)
    }

    /// `(max, mean)` of `| |q(t)| − 1 |` over `samples` uniformly spaced times of the domain
    /// (end points included; at least 2).
    pub fn unit_deviation(&self, samples: usize) -> (f64, f64) {
        let n = samples.clamp(2, MAX_SPLINE_SAMPLES);
        let (t0, t1) = self.domain();
        let mut max = 0.0f64;
        let mut sum = 0.0;
        for k in 0..n {
            let t = t0 + (t1 - t0) * k as f64 / (n - 1) as f64;
            let d = (self.eval(t)[0].length() - 1.0).abs();
            max = max.max(d);
            sum += d;
        }
        (max, sum / n as f64)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::methods::polynomial::hermite_basis;

    /// The objective and gradient computed the plain way, on [`DQuat`] with the Hermite basis at
    /// every node and the gradient summed per frame (how they were computed before the power
    /// form and the moments).
    fn reference(s: &HermiteQuatSpline, alpha: f64) -> (f64, Vec<f64>) {
        let frames = s.frames.len();
        let zero = DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0);
        let (mut gp, mut gm) = (vec![zero; frames], vec![zero; frames]);
        let basis: Vec<[[f64; 4]; 4]> = s.nodes.iter().map(|&x| hermite_basis(x)).collect();
        let mut total = 0.0;
        for j in 0..s.piece_count() {
            let p = s.piece(j);
            let c = [p.p0, p.m0 * p.dt, p.p1, p.m1 * p.dt];
            let inv2 = 1.0 / (p.dt * p.dt);
            let mut sum = 0.0;
            let mut g = [zero; 4];
            for (h, &w) in basis.iter().zip(&s.weights) {
                let q = c[0] * h[0][0] + c[1] * h[0][1] + c[2] * h[0][2] + c[3] * h[0][3];
                let q2 = (c[0] * h[2][0] + c[1] * h[2][1] + c[2] * h[2][2] + c[3] * h[2][3]) * inv2;
                let (f, fq, fq2) = integrand(q, q2, alpha);
                sum += w * f;
                for k in 0..4 {
                    g[k] += (fq * h[0][k] + fq2 * (h[2][k] * inv2)) * w;
                }
            }
            total += p.dt * sum;
            let d = p.dt;
            gp[p.f0] += g[0] * d;
            gm[p.f0] += g[1] * (d * d);
            gp[p.f1] += g[2] * (d * p.sign);
            gm[p.f1] += g[3] * (d * d * p.sign);
        }
        let mut out = Vec::new();
        for (f, (dp, dm)) in s.frames.iter().zip(gp.iter().zip(&gm)) {
            for (free, v) in [(f.pos_free, dp), (f.vel_free, dm)] {
                if free {
                    out.extend_from_slice(&v.to_array());
                }
            }
        }
        (total, out)
    }

    /// The objective in power form with the gradient as moments agrees with the plain sum over
    /// the Hermite basis to round-off (relative).
    const OBJ_TOL: f64 = 1e-13;
    /// The gradient, relative to its largest entry (and at least 1).
    const GRAD_TOL: f64 = 1e-11;

    #[test]
    fn objective_matches_the_plain_computation() {
        let mut worst = [0.0f64; 2];
        let mut seed = 0x2545_f491_4f6c_dd1du64;
        let mut rand = move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
        };
        for case in 0..40 {
            let closed = case % 2 == 1;
            let count = 1 + case % 5 + usize::from(!closed);
            let mut t = 0.0;
            let frames: Vec<Frame> = (0..count)
                .map(|i| {
                    t += 0.3 + rand().abs();
                    let q = DQuat::from_xyzw(rand(), rand(), rand(), rand());
                    Frame {
                        t,
                        p: q,
                        m: DQuat::from_xyzw(rand(), rand(), rand(), rand()) * 3.0,
                        pos_free: (i + case) % 3 == 0,
                        vel_free: (i + case) % 4 != 1,
                        keyframe: false,
                    }
                })
                .collect();
            let end = t + 0.5;
            let sign = if case % 4 == 1 { -1.0 } else { 1.0 };
            let alpha = 10.0 * rand().abs();
            let mut s =
                HermiteQuatSpline::new(frames, closed, end, sign, alpha, 1 + case % 12).unwrap();
            if case % 3 == 2 {
                // A variable frame inserted later (new free variables in the middle).
                let (a, b) = s.domain();
                assert!(s.insert_frame(a + 0.37 * (b - a)).is_some(), "case {case}");
            }
            let (want, want_g) = reference(&s, alpha);
            let mut g = vec![f64::NAN; s.variable_count() + 3];
            let got = s.objective_and_gradient(&mut g);
            let rel = |a: f64, b: f64| (a - b).abs() / b.abs().max(f64::MIN_POSITIVE);
            worst[0] = worst[0].max(rel(got, want));
            assert!(rel(got, want) <= OBJ_TOL, "case {case}: {got} vs {want}");
            assert_eq!(s.objective().to_bits(), got.to_bits(), "case {case}");
            let (ca, ca_want) = (s.covariant_acceleration(), reference(&s, 0.0).0);
            assert!(
                rel(ca, ca_want) <= OBJ_TOL,
                "case {case}: {ca} vs {ca_want}"
            );
            assert_eq!(want_g.len(), s.variable_count());
            let scale = want_g.iter().fold(1.0f64, |m, v| m.max(v.abs()));
            for (i, (a, b)) in g.iter().zip(&want_g).enumerate() {
                worst[1] = worst[1].max((a - b).abs() / scale);
                assert!(
                    (a - b).abs() <= GRAD_TOL * scale,
                    "case {case}, ∂/∂x[{i}]: {a} vs {b}"
                );
            }
            // Entries past the variables are left alone.
            assert!(g[want_g.len()..].iter().all(|v| v.is_nan()), "case {case}");
        }
        println!(
            "largest differences: objective {:e} (relative), gradient {:e}",
            worst[0], worst[1]
        );
    }
}
