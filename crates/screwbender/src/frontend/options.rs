//! Subdivision options as every front end receives them: a scheme id, the J_s parameter `s`, a
//! rule-set id and a level count, each optional, applied over a current [`Subdivision`].
//!
//! The rules, once for all front ends:
//! * `scheme` is `bspline`, `fourpoint`, `jarek` or `j` (the J_s family, parameter `s`); the
//!   core's other spellings of a scheme are accepted too ([`Scheme`]'s `FromStr`).
//! * `s` alone selects the J_s family. With a named scheme it must agree with that scheme's own
//!   parameter (`bspline` is `s = 1`); with `j` it is the parameter (absent: the current one).
//! * `rules` is `direct` or `split` (display: "split-then-tweak (V1)"); [`Rules`]'s `FromStr`
//!   also takes `split-then-tweak`.
//! * `levels` is a whole number from 0 to [`MAX_LEVELS`]; absent, a new motion has
//!   [`DEFAULT_LEVELS`].

use crate::error::{Error, ErrorKind};
use crate::subdivision::scheme::{Rules, Scheme, MAX_J_PARAMETER};
use crate::subdivision::{Subdivision, MAX_REFINED_POSES};

/// Subdivision levels of a new motion when the options do not say: each control span becomes
/// `2⁵ = 32` screws, smooth to the eye at any size a figure is drawn.
pub const DEFAULT_LEVELS: u32 = 5;

/// The most levels any front end accepts: the fewest poses a motion has (two, as a cycle)
/// refined this many times fill the memory guard ([`MAX_REFINED_POSES`]), so one level more can
/// never be refined, whatever the input.
pub const MAX_LEVELS: u32 = MAX_REFINED_POSES.trailing_zeros() - 1;

/// The scheme ids, for messages.
pub const SCHEME_NAMES: &str = "bspline, fourpoint, jarek, j";

/// The subdivision of a new motion: 4-point, direct rules, [`DEFAULT_LEVELS`]
/// (= [`Subdivision::default`]).
pub fn default_subdivision() -> Subdivision {
    Subdivision::default()
}

/// Options as given, before validation; `None` keeps the current value.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct OptionsInput<'a> {
    /// A scheme id ([`SCHEME_NAMES`]).
    pub scheme: Option<&'a str>,
    /// The J_s parameter.
    pub s: Option<f64>,
    /// The deprecated name of `s` (JavaScript only, for one release): both may be given when
    /// they agree.
    pub j: Option<f64>,
    /// A rule-set id (`direct`, `split`).
    pub rules: Option<&'a str>,
    /// A level count (a whole number, given as a number).
    pub levels: Option<f64>,
}

/// The id of a scheme (`j` for every member of the J_s family; its parameter is `s`).
pub fn scheme_name(scheme: &Scheme) -> &'static str {
    match scheme {
        Scheme::BSpline => "bspline",
        Scheme::FourPoint => "fourpoint",
        Scheme::Jarek => "jarek",
        Scheme::J(_) => "j",
    }
}

/// The id of a rule set, as files, options and every API write it.
pub fn rules_name(rules: &Rules) -> &'static str {
    match rules {
        Rules::Direct => "direct",
        Rules::SplitThenTweak => "split",
    }
}

/// The display name of a rule set, for menus and captions.
pub fn rules_display(rules: &Rules) -> &'static str {
    match rules {
        Rules::Direct => "direct (V2)",
        Rules::SplitThenTweak => "split-then-tweak (V1)",
    }
}

/// A number as a message shows it: as JavaScript writes it for the values a user types
/// (`Infinity`, not Rust's `inf`), and no `1e300` written out in full.
fn shown(v: f64) -> String {
    if v.is_infinite() {
        if v > 0.0 { "Infinity" } else { "-Infinity" }.into()
    } else if v.is_nan() || v.abs() < 1e21 {
        v.to_string()
    } else {
        format!("{v:e}")
    }
}

/// A level count: a whole number from 0 to [`MAX_LEVELS`], at `levels`.
pub fn parse_levels(v: f64) -> Result<u32, Error> {
    if v.fract() == 0.0 && (0.0..=MAX_LEVELS as f64).contains(&v) {
        Ok(v as u32)
    } else {
        Err(Error::new(
            "levels",
            ErrorKind::OutOfRange {
                value: shown(v),
                expected: format!(
                    "a whole number from 0 to {MAX_LEVELS}; more levels never fit the limit of \
                     {MAX_REFINED_POSES} refined poses"
                ),
            },
        ))
    }
}

/// A level count given as text (a command-line value): a number, then [`parse_levels`].
pub fn parse_levels_text(text: &str) -> Result<u32, Error> {
    match text.trim().parse::<f64>() {
        Ok(v) if !v.is_nan() => parse_levels(v),
        _ => Err(Error::new(
            "levels",
            ErrorKind::Parse {
                message: format!("'{text}' is not a level count (expected a whole number)"),
            },
        )),
    }
}

/// Checks a J_s parameter given under the name `at` (`s`, or the deprecated `j`).
fn check_s(s: f64, at: &str) -> Result<f64, Error> {
    if !s.is_finite() {
        Err(Error::new(at, ErrorKind::NonFinite))
    } else if s.abs() > MAX_J_PARAMETER {
        Err(Error::new(
            at,
            ErrorKind::OutOfRange {
                value: shown(s),
                expected: format!("-{MAX_J_PARAMETER} to {MAX_J_PARAMETER}"),
            },
        ))
    } else {
        Ok(s)
    }
}

/// The J_s parameter of `input` and the name it came under; an error naming both when `s` and
/// the deprecated `j` disagree.
fn given_s(input: &OptionsInput) -> Result<Option<(f64, &'static str)>, Error> {
    let s = input.s.map(|v| check_s(v, "s")).transpose()?;
    let j = input.j.map(|v| check_s(v, "j")).transpose()?;
    match (s, j) {
        (Some(s), Some(j)) if s != j => Err(Error::new(
            "s",
            ErrorKind::Unsupported {
                reason: format!(
                    "s = {s} and j = {j} disagree (j is the deprecated name of s; give s only)"
                ),
            },
        )),
        (Some(s), _) => Ok(Some((s, "s"))),
        (None, Some(j)) => Ok(Some((j, "j"))),
        (None, None) => Ok(None),
    }
}

/// Parses a scheme id; `j` (the J_s family) takes the parameter `s`.
fn parse_scheme(name: &str, s: f64) -> Result<Scheme, Error> {
    if name.trim().eq_ignore_ascii_case("j") {
        return Ok(Scheme::J(s));
    }
    name.parse().map_err(|e: Error| match e.kind() {
        ErrorKind::UnknownValue { value, .. } => Error::new(
            "scheme",
            ErrorKind::UnknownValue {
                value: value.clone(),
                expected: SCHEME_NAMES,
            },
        ),
        _ => e,
    })
}

/// `base` with the options of `input` applied (see the module doc), validated
/// ([`Subdivision::validate`]; the memory guard needs the poses and is checked where they are).
pub fn resolve(base: Subdivision, input: &OptionsInput) -> Result<Subdivision, Error> {
    let mut out = base;
    let given = given_s(input)?;
    match (input.scheme, given) {
        (Some(name), _) => {
            let scheme = parse_scheme(name, given.map_or(base.scheme.s(), |(s, _)| s))?;
            if let (Some((s, at)), false) = (given, matches!(scheme, Scheme::J(_))) {
                if s != scheme.s() {
                    return Err(Error::new(
                        at,
                        ErrorKind::Unsupported {
                            reason: format!(
                                "{at} = {s} contradicts scheme '{}' (whose J_s parameter is {}); \
                                 use scheme 'j' for other values",
                                scheme_name(&scheme),
                                scheme.s()
                            ),
                        },
                    ));
                }
            }
            out.scheme = scheme;
        }
        (None, Some((s, _))) => out.scheme = Scheme::J(s),
        (None, None) => {}
    }
    if let Some(rules) = input.rules {
        out.rules = rules.parse()?;
    }
    if let Some(levels) = input.levels {
        out.levels = parse_levels(levels)?;
    }
    out.validate()?;
    Ok(out)
}
