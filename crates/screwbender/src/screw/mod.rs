//! The screw motion between two poses (docs/math/screw.md; paper §3 "screw").
//!
//! The production route is the closed form of the SE(3) logarithm/exponential (docs/math/screw.md §4): it is
//! exact for every angle in `[0, π]`, including angles down to the last bit, and never forms the
//! ill-conditioned axis point. The paper's own construction (docs/math/screw.md §2, after Rossignac & Kim,
//! with the signed-angle and `O₀ + O₁` corrections) is in [`PaperScrew`], for teaching displays
//! and as a test oracle.

#[cfg(lanes)]
pub(crate) mod batch;
pub(crate) mod kernel;

use glam::{DQuat, DVec3};

use crate::lanes::trig;
use crate::lanes::{Q, V3};
use crate::pose::Pose;

pub use kernel::HALF_TURN_EPSILON;
use kernel::{Coefficients, MIN_ROTATION_SINE};

/// Rotation angles at or below this (radians) are reported as "no rotation" by
/// [`Screw::parameters`] (identity or pure translation). Evaluation does not use it: the closed
/// form stays exact for every non-zero angle.
pub const ANGLE_EPSILON: f64 = 1e-12;

/// Relative length below which a displacement counts as zero when classifying a screw: a
/// translation `t` is "none" when `|t| ≤ LENGTH_EPSILON · max(1, |O₀|, |O₁|)` (scene scale).
pub const LENGTH_EPSILON: f64 = 1e-12;

/// `screw(a, t, b)`: the pose reached after the fraction `t` of the screw motion from `a` to `b`.
///
/// `t = 0` gives `a`, `t = 1` gives `b`; any real `t` is allowed (`t < 0` or `t > 1`
/// extrapolates along the same screw). This evaluates the logarithm each time; to evaluate many
/// `t` on the same pair, build a [`Screw`] once.
///
/// ```
/// use screwbender::{screw, Pose};
/// use glam::{DQuat, DVec3};
/// let a = Pose::IDENTITY;
/// let b = Pose::new(DVec3::new(2.0, 0.0, 1.0), DQuat::from_rotation_z(std::f64::consts::FRAC_PI_2));
/// let mid = screw(&a, 0.5, &b);
/// // docs/math/screw.md §7 example A: a quarter turn about the axis x = y = 1 with lift 1.
/// assert!((mid.origin - DVec3::new(1.0, -(2f64.sqrt() - 1.0), 0.5)).length() < 1e-15);
/// ```
#[inline]
pub fn screw(a: &Pose, t: f64, b: &Pose) -> Pose {
    // Compiled for AVX2 where the processor has it (checked once, then one cached load): the
    // same scalar IEEE operations in the same order (no fused multiply-add is ever formed), so
    // the same bits, in the VEX three-operand encoding, which needs no register copies — fewer
    // instructions per call, so that the processor overlaps more of consecutive calls
    // (docs/speed/one-call-screw.md).
    #[cfg(target_arch = "x86_64")]
    {
        /// `screw_scalar` in `pulp`'s dispatch.
        struct OnSimd<'p>(&'p Pose, f64, &'p Pose);
        impl pulp::WithSimd for OnSimd<'_> {
            type Output = Pose;
            #[inline(always)]
            fn with_simd<S: pulp::Simd>(self, _: S) -> Pose {
                screw_scalar(self.0, self.1, self.2)
            }
        }
        if let Some(simd) = pulp::x86::V3::try_new() {
            return pulp::Simd::vectorize(simd, OnSimd(a, t, b));
        }
    }
    screw_scalar(a, t, b)
}

/// [`screw`] for any processor. (One out-of-line copy elsewhere than x86-64: inlined into
/// every caller of [`screw`] it would be copied many times into the size-budgeted wasm module.)
#[cfg_attr(target_arch = "x86_64", inline(always))]
#[cfg_attr(not(target_arch = "x86_64"), inline(never))]
fn screw_scalar(a: &Pose, t: f64, b: &Pose) -> Pose {
    // The regular case straight through the kernel (the same operations as the two calls
    // below, without a `Screw` in memory between them); the rare cases decide in `Screw`.
    let (oa, qa) = (a.origin.into(), a.rotation.into());
    let regular = kernel::regular_span(oa, qa, b.origin.into(), b.rotation.into())
        .and_then(|span| kernel::regular_at_one(&span, t));
    match regular {
        Some((origin, rotation)) => Pose::new(origin.into(), rotation.into()),
        None => Screw::between(a, b).at(t),
    }
}

/// The screw from one pose to another, with its logarithm precomputed so that [`Screw::at`] costs
/// one `sin_cos` and a few products.
///
/// With `D = b ∘ a⁻¹` (the world-frame displacement, rotation angle `θ ∈ [0, π]` about unit axis
/// `n`, translation `t_D`): `d = n·t_D` is the slide along the axis and `u = t_D − d n` the
/// translation part perpendicular to it. Then (docs/math/screw.md §4)
///
/// ```text
/// R(t) = Rot(n, tθ) R₀
/// O(t) = Rot(n, tθ) O₀ + t d n + [sin(tθ/2)/sin(θ/2)] Rot(n, (t−1)θ/2) u
/// ```
///
/// Degenerate cases (docs/math/screw.md §5): identical poses give `a` for every `t`; a pure translation moves
/// linearly; tiny angles need no special branch (the ratio of sines is well conditioned for any
/// `θ > 0`). A half turn (`θ = π`) has two minimal screws; the tie-break picks the sense with a
/// positive slide `d`, or, when `|d|` is negligible, the axis whose largest-magnitude component
/// is positive (lowest index on ties).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Screw {
    start: Pose,
    /// `θ/2` (`0` without rotation).
    half_angle: f64,
    sin_half: f64,
    cos_half: f64,
    /// Axis, slide and the evaluation vectors (see `screw::kernel`). Without rotation: axis `+z`
    /// (arbitrary), slide 0, and `perp` holds the whole translation.
    coefficients: Coefficients<f64>,
}

/// The classification and parameters of a screw, for display and teaching (docs/math/screw.md §2, §5).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ScrewKind {
    /// The two poses are the same: the motion stays put.
    Identity,
    /// No rotation: the motion is the translation by `distance` along unit `direction`.
    Translation {
        /// Unit direction `S`.
        direction: DVec3,
        /// Translation length `d > 0`.
        distance: f64,
    },
    /// A true screw: rotation by `angle` about the axis through `foot` with direction `axis`,
    /// combined with a slide `slide` along it.
    General(ScrewParameters),
}

/// The paper's screw parameters `S, r, d, P` in canonical form (`r ∈ (0, π]`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ScrewParameters {
    /// Unit axis direction `S`.
    pub axis: DVec3,
    /// Rotation angle `r` in radians, in `(0, π]`, right-hand rule about `axis`.
    pub angle: f64,
    /// Slide `d` along `axis` (length units).
    pub slide: f64,
    /// The paper's axis point `P = (O₀ + O₁ + (S × O)/tan(r/2)) / 2` (with the `O₀ + O₁`
    /// misprint corrected): the axis point at the height of the midpoint of the two origins.
    pub point: DVec3,
    /// The axis foot point `P⊥`, the axis point closest to the world origin.
    pub foot: DVec3,
    /// The pitch `d / r` (slide per radian).
    pub pitch: f64,
}

impl Screw {
    /// The screw from `a` to `b` (the logarithm of `b ∘ a⁻¹`), with the half-turn tie-break.
    #[inline]
    pub fn between(a: &Pose, b: &Pose) -> Screw {
        let mut s = Screw::between_unmeasured(a, b);
        s.half_angle = half_angle(s.sin_half, s.cos_half);
        s
    }

    /// `screw(a, ½, b)` without any transcendental function: the half-angle of the half-angle
    /// comes from `cos(θ/4) = √((1 + cos(θ/2))/2)`, well conditioned since `θ/2 ≤ π/2`.
    #[inline]
    pub fn midpoint(a: &Pose, b: &Pose) -> Pose {
        // The regular case straight through the kernel (its half angle, unused, is optimised
        // away); the rare cases decide below.
        let (oa, qa) = (a.origin.into(), a.rotation.into());
        if let Some(span) = kernel::regular_span(oa, qa, b.origin.into(), b.rotation.into()) {
            let (origin, rotation) = kernel::regular_midpoint(&span);
            return Pose::new(origin.into(), rotation.into());
        }
        let s = Screw::between_unmeasured(a, b);
        if s.sin_half == 0.0 {
            return s.at_without_rotation(0.5);
        }
        // After a half-turn tie-break cos(θ/2) is a hair below 0; (1 + w)/2 stays near ½.
        let (sa, ca) = kernel::half_of_half(s.sin_half, s.cos_half);
        s.evaluate(0.5, sa, ca)
    }

    /// Everything of [`Screw::between`] but `half_angle`, which is left NaN when there is a
    /// rotation (the caller fills it in, or evaluates only where the angle's sine and cosine
    /// suffice).
    ///
    /// The branches (identical rotations, no rotation, half turns) go the same way for almost
    /// every pair, so they cost nothing when predicted.
    #[inline]
    fn between_unmeasured(a: &Pose, b: &Pose) -> Screw {
        let (oa, qa) = (a.origin.into(), a.rotation.into());
        let rel = kernel::relative(oa, qa, b.origin.into(), b.rotation.into());
        // Identical rotations (either sign) give an exactly zero relative rotation, so identical
        // poses reproduce `a` bit for bit at every t instead of up to rounding.
        let same_rotation = a.rotation == b.rotation || a.rotation == -b.rotation;
        if same_rotation || rel.s <= MIN_ROTATION_SINE {
            return Screw::translation(a, b, same_rotation, rel.translation.into());
        }
        let inv_s = 1.0 / rel.s;
        let mut axis = rel.v.scale(inv_s);
        let mut slide = axis.dot(rel.translation);
        let mut w = rel.w;
        if w <= HALF_TURN_EPSILON && half_turn_prefers_flip(axis.into(), slide, a, b) {
            // The same rotation seen from the other side: θ' = 2π − θ about −n (exact, so the
            // end pose stays b even when θ is a hair below π).
            w = -w;
            axis = V3::new(-axis.x, -axis.y, -axis.z);
            slide = -slide;
        }
        // The relative rotation is a product of unit quaternions, unit to rounding: its parts
        // are the half angle's sine and cosine without renormalising (the evaluated rotation is
        // renormalised).
        Screw {
            start: *a,
            half_angle: f64::NAN,
            sin_half: rel.s,
            cos_half: w,
            coefficients: kernel::coefficients(oa, qa, axis, slide, w * inv_s, rel.translation),
        }
    }

    /// The screw without rotation: `O(t) = O₀ + t t_D`, `q(t) = q₀`.
    #[cold]
    fn translation(a: &Pose, b: &Pose, same_rotation: bool, translation: DVec3) -> Screw {
        // With identical rotations the difference of the origins is exact (no rotation of O₀
        // by a relative rotation that is the identity only up to rounding).
        let perp = if same_rotation {
            b.origin - a.origin
        } else {
            translation
        };
        let zero = V3::new(0.0, 0.0, 0.0);
        Screw {
            start: *a,
            half_angle: 0.0,
            sin_half: 0.0,
            cos_half: 1.0,
            coefficients: Coefficients {
                axis: V3::new(0.0, 0.0, 1.0),
                slide: 0.0,
                perp: perp.into(),
                sweep: zero,
                sweep_normal: zero,
                axis_rotation: Q::new(0.0, 0.0, 0.0, 0.0),
            },
        }
    }

    /// The start pose `a`.
    pub fn start(&self) -> &Pose {
        &self.start
    }

    /// The rotation angle `θ ∈ [0, π]` (slightly above π only after a half-turn tie-break).
    pub fn angle(&self) -> f64 {
        2.0 * self.half_angle
    }

    /// The pose at fraction `t` of the screw (any real `t`).
    ///
    /// With `s = sin(tθ/2)`, `c = cos(tθ/2)`: `q(t) = c q₀ + s (n, 0) q₀` and
    /// `O(t) = O₀ + t d n + s c E + s² (n × E)`, where `E = cot(θ/2) u + n × (2 O₀ − t_D)` is
    /// fixed by the span. (Expand `Rot(n, tθ) O₀` and the `u` term of docs/math/screw.md §4 with the
    /// half-angle identities; the `O₀` and `u` parts fold into the one vector `E`.)
    #[inline]
    pub fn at(&self, t: f64) -> Pose {
        if self.sin_half == 0.0 {
            return self.at_without_rotation(t);
        }
        let (sa, ca) = trig::sin_cos(t * self.half_angle);
        self.evaluate(t, sa, ca)
    }

    /// [`Screw::at`] for a screw without rotation.
    #[inline]
    fn at_without_rotation(&self, t: f64) -> Pose {
        let translation: DVec3 = self.coefficients.perp.into();
        Pose::new(self.start.origin + t * translation, self.start.rotation)
    }

    /// The pose at `t` given `sa = sin(tθ/2)` and `ca = cos(tθ/2)` (rotating case only).
    #[inline]
    fn evaluate(&self, t: f64, sa: f64, ca: f64) -> Pose {
        let a = &self.start;
        let (origin, rotation) = kernel::evaluate(
            a.origin.into(),
            a.rotation.into(),
            &self.coefficients,
            t,
            sa,
            ca,
        );
        Pose::new(origin.into(), rotation.into())
    }

    /// The world-frame twist of the screw per unit `t`: angular velocity `ω = θ n` and the
    /// velocity `v₀` of the (possibly virtual) body point at the world origin.
    ///
    /// Every body point at world position `x` moves with velocity `ω × x + v₀` and acceleration
    /// `ω × (ω × x + v₀)`, the same at every `t` of the span (the twist is constant along a
    /// screw). `v₀ = d n + (θ/2)(cot(θ/2) u − n × u)`, well conditioned for all `θ`.
    pub fn twist(&self) -> (DVec3, DVec3) {
        let (axis, perp): (DVec3, DVec3) =
            (self.coefficients.axis.into(), self.coefficients.perp.into());
        if self.sin_half == 0.0 {
            return (DVec3::ZERO, perp);
        }
        let h = self.half_angle;
        let omega = (2.0 * h) * axis;
        // (θ/2)·cot(θ/2) = h·cos/sin, written so that it tends to 1 as h → 0.
        let hcot = h / self.sin_half * self.cos_half;
        let v0 = self.coefficients.slide * axis + hcot * perp - h * axis.cross(perp);
        (omega, v0)
    }

    /// The canonical parameters for display (docs/math/screw.md §2 steps 6–8, §5 degenerate cases).
    pub fn parameters(&self) -> ScrewKind {
        let a = &self.start;
        let scale = 1f64.max(a.origin.length()).max(self.end().origin.length());
        let theta = self.angle();
        let (axis, slide, perp): (DVec3, f64, DVec3) = (
            self.coefficients.axis.into(),
            self.coefficients.slide,
            self.coefficients.perp.into(),
        );
        if theta <= ANGLE_EPSILON || self.sin_half == 0.0 {
            let translation = slide * axis + perp;
            let len = translation.length();
            if len <= LENGTH_EPSILON * scale {
                return ScrewKind::Identity;
            }
            return ScrewKind::Translation {
                direction: translation / len,
                distance: len,
            };
        }
        // After a half-turn tie-break θ may exceed π by at most ~4e-12 (it is exactly the same
        // rotation seen from the chosen side): report the canonical π with the chosen axis.
        let angle = theta.min(std::f64::consts::PI);
        // Foot point relative to the axis through the world origin: P⊥ = (u + (n×u)/tan(θ/2))/2.
        let cot_half = (0.5 * angle).cos() / (0.5 * angle).sin();
        let foot = 0.5 * (perp + axis.cross(perp) * cot_half);
        let mid = 0.5 * (a.origin + self.end().origin);
        let point = foot + axis * axis.dot(mid);
        ScrewKind::General(ScrewParameters {
            axis,
            angle,
            slide,
            point,
            foot,
            pitch: slide / angle,
        })
    }

    /// The end pose (`at(1)`).
    pub fn end(&self) -> Pose {
        self.at(1.0)
    }
}

/// The half angle `atan2(s, c)` in `[0, π/2]` for `s > 0`, `c ≥ 0` (in `(π/2, π/2 + 10⁻¹²]`
/// after a half-turn tie-break, where `c` is a hair below zero).
#[inline]
fn half_angle(s: f64, c: f64) -> f64 {
    if c >= 0.0 {
        trig::atan2_quadrant(s, c)
    } else {
        s.atan2(c)
    }
}

/// The half-turn tie-break of docs/math/screw.md §5: `true` when the screw should use `−n`.
fn half_turn_prefers_flip(axis: DVec3, slide: f64, a: &Pose, b: &Pose) -> bool {
    let scale = 1f64.max(a.origin.length()).max(b.origin.length());
    if slide.abs() > LENGTH_EPSILON * scale {
        return slide < 0.0;
    }
    let c = axis.to_array();
    let mut k = 0;
    for i in 1..3 {
        if c[i].abs() > c[k].abs() {
            k = i;
        }
    }
    c[k] < 0.0
}

/// Which cross product of basis differences the paper's construction picked (docs/math/screw.md §2 step 2).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BasisPair {
    /// `(I₁ − I₀) × (J₁ − J₀)`, leading vector `I`.
    IJ,
    /// `(J₁ − J₀) × (K₁ − K₀)`, leading vector `J`.
    JK,
    /// `(K₁ − K₀) × (I₁ − I₀)`, leading vector `K`.
    KI,
}

/// The paper's construction of the screw parameters (docs/math/screw.md §2), step by step, for teaching.
///
/// Corrected as in docs/math/screw.md §2.1 and §2.2: the angle is *signed* (an unsigned angle is wrong about half the
/// time) and `P` uses `O₀ + O₁` (both versions of the paper misprint `O₁ + O₂`).
/// Its accuracy degrades like `ε/θ` for small angles; use [`Screw`] in production.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PaperScrew {
    /// The cross product that was the longest (ties: lowest index), or `None` without rotation.
    pub pair: Option<BasisPair>,
    /// `S` before canonicalisation (the normalised cross product).
    pub raw_axis: DVec3,
    /// The signed angle from `S × A₀` to `S × A₁` about `S`, in `(−π, π]`, before
    /// canonicalisation.
    pub raw_angle: f64,
    /// The canonical kind and parameters (`r ≥ 0`).
    pub kind: ScrewKind,
    start: Pose,
}

/// Length of the longest cross product below which the paper's construction sees no rotation.
pub const PAPER_CROSS_EPSILON: f64 = 1e-24;

impl PaperScrew {
    /// Runs the paper's construction on two poses.
    pub fn between(a: &Pose, b: &Pose) -> PaperScrew {
        let [i0, j0, k0] = a.basis();
        let [i1, j1, k1] = b.basis();
        let (di, dj, dk) = (i1 - i0, j1 - j0, k1 - k0);
        let o = b.origin - a.origin;
        let cands = [
            (di.cross(dj), i0, i1, BasisPair::IJ),
            (dj.cross(dk), j0, j1, BasisPair::JK),
            (dk.cross(di), k0, k1, BasisPair::KI),
        ];
        let mut best = 0;
        for k in 1..3 {
            if cands[k].0.length() > cands[best].0.length() {
                best = k;
            }
        }
        let (c, a0, a1, pair) = cands[best];
        let len = c.length();
        if len <= PAPER_CROSS_EPSILON {
            let dist = o.length();
            let kind = if dist == 0.0 {
                ScrewKind::Identity
            } else {
                ScrewKind::Translation {
                    direction: o / dist,
                    distance: dist,
                }
            };
            return PaperScrew {
                pair: None,
                raw_axis: DVec3::Z,
                raw_angle: 0.0,
                kind,
                start: *a,
            };
        }
        let raw_axis = c / len;
        let (u0, u1) = (raw_axis.cross(a0), raw_axis.cross(a1));
        let raw_angle = raw_axis.dot(u0.cross(u1)).atan2(u0.dot(u1));
        let (axis, angle) = if raw_angle < 0.0 {
            (-raw_axis, -raw_angle)
        } else {
            (raw_axis, raw_angle)
        };
        let slide = o.dot(axis);
        let point = 0.5 * (a.origin + b.origin + axis.cross(o) / (0.5 * angle).tan());
        let foot = point - axis * point.dot(axis);
        PaperScrew {
            pair: Some(pair),
            raw_axis,
            raw_angle,
            kind: ScrewKind::General(ScrewParameters {
                axis,
                angle,
                slide,
                point,
                foot,
                pitch: slide / angle,
            }),
            start: *a,
        }
    }

    /// The pose at fraction `t`: `R(t) = Rot(S, t r) R₀`, `O(t) = P + Rot(S, t r)(O₀ − P) + t d S`
    /// (docs/math/screw.md §3).
    pub fn at(&self, t: f64) -> Pose {
        let a = &self.start;
        match self.kind {
            ScrewKind::Identity => *a,
            ScrewKind::Translation {
                direction,
                distance,
            } => Pose::new(a.origin + t * distance * direction, a.rotation),
            ScrewKind::General(p) => {
                let rt = DQuat::from_axis_angle(p.axis, t * p.angle);
                Pose::new(
                    p.point + rt * (a.origin - p.point) + t * p.slide * p.axis,
                    (rt * a.rotation).normalize(),
                )
            }
        }
    }
}

/// `screw(a, t, b)` by the paper's construction (docs/math/screw.md §2–§3): a test oracle for `θ ≳ 1e-3`.
pub fn screw_paper(a: &Pose, t: f64, b: &Pose) -> Pose {
    PaperScrew::between(a, b).at(t)
}
