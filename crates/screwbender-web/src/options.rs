//! Subdivision options as JavaScript gives them: `{scheme, s, rules, levels}` with string ids,
//! resolved by the core's front-end rules ([`screwbender::frontend::options`]), which the CLI and
//! Python share. `j` is still read as the deprecated name of `s`.

use serde::{Deserialize, Serialize};
use wasm_bindgen::JsValue;

use super::convert::{check_keys, check_object, fields_of, from_js, is_absent, plain};
use screwbender::frontend::{self, OptionsInput};
use screwbender::{Error, Subdivision};

pub use screwbender::frontend::{default_subdivision, parse_levels, rules_name, scheme_name};

/// A `Partial<SubdivisionOptions>` object before validation.
#[derive(Deserialize, Default)]
struct OptionsObject {
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

/// The options of `sub` as a plain object.
pub(crate) fn to_output(sub: &Subdivision) -> OptionsOutput {
    OptionsOutput {
        scheme: scheme_name(&sub.scheme),
        s: sub.scheme.s(),
        rules: rules_name(&sub.rules),
        levels: sub.levels,
    }
}

/// Parses a scheme id over the current J_s parameter `s` (`j` keeps it).
pub(crate) fn parse_scheme(name: &str, s: f64) -> Result<screwbender::Scheme, Error> {
    let base = Subdivision::new(screwbender::Scheme::J(s), Default::default(), 0);
    let input = OptionsInput {
        scheme: Some(name),
        ..OptionsInput::default()
    };
    frontend::resolve(base, &input).map(|sub| sub.scheme)
}

/// Checks a J_s parameter given on its own (`setS`) under the name `at`.
pub(crate) fn check_s(s: f64, at: &str) -> Result<f64, Error> {
    let input = if at == "j" {
        OptionsInput {
            j: Some(s),
            ..OptionsInput::default()
        }
    } else {
        OptionsInput {
            s: Some(s),
            ..OptionsInput::default()
        }
    };
    frontend::resolve(Subdivision::default(), &input).map(|_| s)
}

/// `sub` with the options in `value` (a `Partial<SubdivisionOptions>`; `undefined` changes
/// nothing) applied. Does not check the memory guard (that needs the poses).
pub(crate) fn apply(sub: Subdivision, value: &JsValue) -> Result<Subdivision, Error> {
    if is_absent(value) {
        return Ok(sub);
    }
    let value = &plain(value, "")?;
    check_object(value, "", "options", "{scheme?, s?, rules?, levels?}")?;
    let input: OptionsObject = from_js(value, "", "options")?;
    check_keys(value, fields_of::<OptionsObject>(), "", "options")?;
    frontend::resolve(
        sub,
        &OptionsInput {
            scheme: input.scheme.as_deref(),
            s: input.s,
            j: input.j,
            rules: input.rules.as_deref(),
            levels: input.levels,
        },
    )
}
