//! Subdivision options as JavaScript sees them: `{scheme, s, rules, levels}` with string names.
//! `j` is still read as the deprecated name of `s`.

use serde::{Deserialize, Serialize};
use wasm_bindgen::JsValue;

use super::convert::{check_keys, check_object, fields_of, from_js, is_absent, plain};
use screwbender::{Error, ErrorKind, Rules, Scheme, Subdivision};

/// Subdivision levels of a new `Motion` when the options do not say: 5 (each control span
/// becomes 32 screws).
pub const DEFAULT_LEVELS: u32 = 5;

/// The scheme names accepted from JavaScript: the core's names plus `j` for the J_s family.
const SCHEME_NAMES: &str = "bspline, fourpoint, jarek, j";

/// The subdivision of a new `Motion`: 4-point, direct rules, [`DEFAULT_LEVELS`].
pub(crate) fn default_subdivision() -> Subdivision {
    Subdivision::new(Scheme::FourPoint, Rules::Direct, DEFAULT_LEVELS)
}

/// A `Partial<SubdivisionOptions>` object before validation.
#[derive(Deserialize, Default)]
struct OptionsInput {
    scheme: Option<String>,
    s: Option<f64>,
    /// Deprecated name of `s`.
    j: Option<f64>,
    rules: Option<String>,
    levels: Option<f64>,
}

/// `SubdivisionOptions` as returned to JavaScript.
#[derive(Serialize)]
pub(crate) struct OptionsOutput {
    scheme: &'static str,
    s: f64,
    rules: &'static str,
    levels: u32,
}

/// The JavaScript name of a scheme (`j` for every member of the J_s family).
pub(crate) fn scheme_name(scheme: &Scheme) -> &'static str {
    match scheme {
        Scheme::BSpline => "bspline",
        Scheme::FourPoint => "fourpoint",
        Scheme::Jarek => "jarek",
        Scheme::J(_) => "j",
    }
}

/// The JavaScript name of a rule set.
pub(crate) fn rules_name(rules: &Rules) -> &'static str {
    match rules {
        Rules::Direct => "direct",
        Rules::SplitThenTweak => "split",
    }
}

/// The options of `sub` as a plain object.
pub(crate) fn to_output(sub: &Subdivision) -> OptionsOutput {
    OptionsOutput {
        scheme: scheme_name(&sub.scheme),
        s: sub.scheme.s(),
        rules: rules_name(&sub.rules),
        levels: sub.levels,
    }
}

/// Parses a scheme name; `j` (the J_s family) takes the parameter `s`.
pub(crate) fn parse_scheme(name: &str, s: f64) -> Result<Scheme, Error> {
    if name.eq_ignore_ascii_case("j") {
        return Ok(Scheme::J(s));
    }
    name.parse().map_err(|e: Error| match e.kind() {
        ErrorKind::UnknownValue { value, .. } => Error::new(
            e.path(),
            ErrorKind::UnknownValue {
                value: value.clone(),
                expected: SCHEME_NAMES,
            },
        ),
        _ => e,
    })
}

/// A levels value: a whole number ≥ 0 (values beyond `u32` saturate, and the memory guard then
/// rejects them).
pub(crate) fn parse_levels(v: f64) -> Result<u32, Error> {
    if v.fract() == 0.0 && v >= 0.0 {
        Ok(v.min(u32::MAX as f64) as u32)
    } else {
        Err(Error::new(
            "levels",
            ErrorKind::OutOfRange {
                value: super::convert::js_number(v),
                expected: "a whole number ≥ 0".into(),
            },
        ))
    }
}

/// Checks a J_s parameter given on its own (`setS`) or next to a scheme name; `at` is the name
/// it was given under (`s`, or the deprecated `j`), which errors use.
pub(crate) fn check_s(s: f64, at: &str) -> Result<f64, Error> {
    if !s.is_finite() {
        Err(Error::new(at, ErrorKind::NonFinite))
    } else if s.abs() > screwbender::MAX_J_PARAMETER {
        Err(Error::new(
            at,
            ErrorKind::OutOfRange {
                value: super::convert::js_number(s),
                expected: format!("-{0} to {0}", screwbender::MAX_J_PARAMETER),
            },
        ))
    } else {
        Ok(s)
    }
}

/// The J_s parameter of an options object and the name it came under: `s`, or the deprecated
/// `j`; both are fine when they agree, and an error naming both when they do not.
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

/// `sub` with the options in `value` (a `Partial<SubdivisionOptions>`; `undefined` changes
/// nothing) applied. Does not check the memory guard (that needs the poses).
pub(crate) fn apply(sub: Subdivision, value: &JsValue) -> Result<Subdivision, Error> {
    if is_absent(value) {
        return Ok(sub);
    }
    let value = &plain(value, "")?;
    check_object(value, "", "options", "{scheme?, s?, rules?, levels?}")?;
    let input: OptionsInput = from_js(value, "", "options")?;
    check_keys(value, fields_of::<OptionsInput>(), "", "options")?;
    let mut out = sub;
    let given = given_s(&input)?;
    match (&input.scheme, given) {
        (Some(name), _) => {
            let scheme = parse_scheme(name, given.map_or(sub.scheme.s(), |(s, _)| s))?;
            if let (Some((s, at)), false) = (given, matches!(scheme, Scheme::J(_))) {
                if s != scheme.s() {
                    return Err(Error::new(at, ErrorKind::Unsupported { reason: format!(
                            "{at} = {s} contradicts scheme '{}' (whose J_s parameter is {}); use scheme 'j' for other values",
                            scheme_name(&scheme),
                            scheme.s()
                        ) }));
                }
            }
            out.scheme = scheme;
        }
        (None, Some((s, _))) => out.scheme = Scheme::J(s),
        (None, None) => {}
    }
    if let Some(rules) = &input.rules {
        out.rules = rules.parse()?;
    }
    if let Some(levels) = input.levels {
        out.levels = parse_levels(levels)?;
    }
    out.validate()?;
    Ok(out)
}
