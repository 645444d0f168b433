//! Subdivision options: which scheme, which rule set, how many levels.

use std::fmt;
use std::str::FromStr;

use crate::error::{Error, ErrorKind};

/// Largest accepted `|s|` of the J_s family ([`Scheme::J`]): `4`.
///
/// The family's useful range is `[0, 1]` (4-point to B-spline); beyond a few units the old-vertex
/// rule `b + s(a − 2b + c)/8` amplifies differences by about `|s|/2` per level, so a huge `s`
/// overflows to infinities within the level cap. `±4` keeps the growth below `3²⁰ ≈ 3.5·10⁹`.
pub const MAX_J_PARAMETER: f64 = 4.0;

/// A subdivision scheme (docs/math/point-rules.md, docs/math/subdivision.md).
///
/// The three named schemes are the paper's; [`Scheme::J`] is the Rossignac–Schaefer J-spline
/// family applied to screws, which contains them: `J(0)` = 4-point, `J(0.5)` = Jarek,
/// `J(1)` = B-spline.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub enum Scheme {
    /// Cubic B-spline (approximating, limit C² on points).
    BSpline,
    /// Dyn–Levin–Gregory 4-point with `w = 1/16` (interpolating, limit C¹ on points).
    #[default]
    FourPoint,
    /// Jarek: the average of the B-spline and 4-point rules.
    Jarek,
    /// The J_s family with real parameter `s` (direct rules only). On points: old
    /// `b + s(a − 2b + c)/8`, new `(b + c)/2 − (1 − s)(a − b − c + d)/16`.
    J(f64),
}

impl Scheme {
    /// The names accepted by [`Scheme::from_str`] (for messages and UIs).
    pub const NAMES: &'static str = "bspline, fourpoint, jarek";

    /// Half-width `k` of the rule's stencil in coarse spans (docs/math/open-sequences.md): 1 for the B-spline, 2 for
    /// the others. Open sequences are extended by `k` dummy poses at each end.
    pub fn half_width(&self) -> usize {
        match self {
            Scheme::BSpline => 1,
            _ => 2,
        }
    }

    /// The J_s parameter `s` of this scheme: `1` B-spline, `0` 4-point, `½` Jarek.
    pub fn s(&self) -> f64 {
        match *self {
            Scheme::BSpline => 1.0,
            Scheme::FourPoint => 0.0,
            Scheme::Jarek => 0.5,
            Scheme::J(s) => s,
        }
    }

    /// The J_s parameter under its former name.
    #[deprecated(note = "use `Scheme::s`: the J_s parameter is called `s` everywhere")]
    pub fn j_parameter(&self) -> f64 {
        self.s()
    }

    /// Whether the refined motion passes through the control poses (`Q_{2i} = P_i`).
    pub fn interpolates(&self) -> bool {
        self.s() == 0.0
    }
}

impl fmt::Display for Scheme {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Scheme::BSpline => f.write_str("bspline"),
            Scheme::FourPoint => f.write_str("fourpoint"),
            Scheme::Jarek => f.write_str("jarek"),
            Scheme::J(s) => write!(f, "j({s})"),
        }
    }
}

impl FromStr for Scheme {
    type Err = Error;
    /// Parses `bspline`, `fourpoint` (also `4point`, `4-point`), `jarek` (case-insensitive).
    fn from_str(s: &str) -> Result<Self, Error> {
        match s.to_ascii_lowercase().as_str() {
            "bspline" | "b-spline" => Ok(Scheme::BSpline),
            "fourpoint" | "4point" | "4-point" | "four-point" => Ok(Scheme::FourPoint),
            "jarek" => Ok(Scheme::Jarek),
            _ => Err(Error::new(
                "scheme",
                ErrorKind::UnknownValue {
                    value: s.to_string(),
                    expected: Scheme::NAMES,
                },
            )),
        }
    }
}

/// Which version of the paper's rules (docs/math/subdivision.md).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Rules {
    /// The revised paper's direct rules on the coarse poses (docs/math/subdivision.md §2). Default.
    #[default]
    Direct,
    /// The first version: split (insert screw midpoints), then tweak the split sequence
    /// (docs/math/subdivision.md §3, with the 4-point/Jarek argument-order misprint corrected).
    /// Its id in files and options is `split`.
    SplitThenTweak,
}

impl Rules {
    /// The names accepted by [`Rules::from_str`].
    pub const NAMES: &'static str = "direct, split (also split-then-tweak)";

    /// Former name of [`Rules::SplitThenTweak`], kept for one release: "Split&Tweak" names the
    /// whole framework, of which both rule sets are part.
    #[deprecated(since = "0.2.0", note = "renamed to `Rules::SplitThenTweak`")]
    #[allow(non_upper_case_globals)]
    pub const SplitTweak: Rules = Rules::SplitThenTweak;
}

impl fmt::Display for Rules {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Rules::Direct => "direct",
            Rules::SplitThenTweak => "split",
        })
    }
}

impl FromStr for Rules {
    type Err = Error;
    /// Parses `direct` (also `v2`) or `split-then-tweak` (also `split`, `split-tweak`, `v1`),
    /// case-insensitive.
    fn from_str(s: &str) -> Result<Self, Error> {
        match s.to_ascii_lowercase().as_str() {
            "direct" | "v2" => Ok(Rules::Direct),
            "split-then-tweak" | "split" | "split-tweak" | "splittweak" | "v1" => {
                Ok(Rules::SplitThenTweak)
            }
            _ => Err(Error::new(
                "rules",
                ErrorKind::UnknownValue {
                    value: s.to_string(),
                    expected: Rules::NAMES,
                },
            )),
        }
    }
}
