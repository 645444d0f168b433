//! Option values: the subdivision options shared by `subdivide`, `eval` and `export`, and the
//! checks that turn an option's text into a number, a list or a level count with a message
//! naming the option.

use std::ffi::OsStr;

use clap::builder::TypedValueParser;
use clap::error::ErrorKind;
use screwbender::frontend::{self, OptionsInput};
use screwbender::Subdivision;

use crate::failure::Failure;

/// `--scheme`, `--s`, `--rules`, `--levels` and `--open`, as given: [`Self::subdivision`] is
/// the one place they become a [`Subdivision`], so that the names, the defaults and the
/// messages stay those of the core.
#[derive(clap::Args)]
#[command(next_help_heading = "Subdivision options")]
pub struct SubdivisionArgs {
    /// Subdivision scheme: bspline, fourpoint, jarek, or j with --s (default: fourpoint)
    #[arg(long, value_name = "SCHEME", allow_hyphen_values = true)]
    scheme: Option<String>,
    /// The J_s family's parameter (S=0 4-point, S=0.5 Jarek, S=1 B-spline; direct rules
    /// only); alone it selects the family, with --scheme it must agree with the scheme
    #[arg(long, value_name = "S", value_parser = Finite, allow_hyphen_values = true)]
    s: Option<f64>,
    /// Rule set: the revised paper's direct rules (direct, the default) or the first version's
    /// split-then-tweak rules (split, also: split-then-tweak)
    #[arg(long, value_name = "RULES", allow_hyphen_values = true)]
    rules: Option<String>,
    /// Subdivision steps, 0 to 19 (default 5; eval: 0 = plain polyscrew)
    #[arg(long, value_name = "N", allow_hyphen_values = true)]
    levels: Option<String>,
    /// Treat the poses as an open sequence (overrides the document's 'closed')
    #[arg(long)]
    pub open: bool,
}

impl SubdivisionArgs {
    /// The subdivision asked for, resolved by the core's front-end rules (the same ids,
    /// defaults, ranges and messages as JavaScript and Python): `--s` alone selects the J_s
    /// family, with `--scheme` it must agree with the scheme; 5 levels unless `--levels`.
    pub fn subdivision(&self) -> Result<Subdivision, Failure> {
        let levels = self
            .levels
            .as_deref()
            .map(frontend::parse_levels_text)
            .transpose()?;
        let input = OptionsInput {
            scheme: self.scheme.as_deref(),
            s: self.s,
            j: None,
            rules: self.rules.as_deref(),
            levels: levels.map(f64::from),
        };
        Ok(frontend::resolve(Subdivision::default(), &input)?)
    }
}

/// Parses an option's value as a finite number, refusing anything else with the message of
/// [`number`] (so a bad `--u` is reported as it is met, before the input is read).
#[derive(Clone, Copy)]
pub struct Finite;

impl TypedValueParser for Finite {
    type Value = f64;

    fn parse_ref(
        &self,
        _cmd: &clap::Command,
        arg: Option<&clap::Arg>,
        value: &OsStr,
    ) -> Result<f64, clap::Error> {
        let name = arg
            .and_then(clap::Arg::get_long)
            .map_or_else(String::new, |long| format!("--{long}"));
        number(&name, &value.to_string_lossy())
            .map_err(|Failure(message)| clap::Error::raw(ErrorKind::ValueValidation, message))
    }
}

/// A finite number given for option `name`.
pub fn number(name: &str, text: &str) -> Result<f64, Failure> {
    match text.parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        _ => Err(Failure(format!("{name}: '{text}' is not a finite number"))),
    }
}

/// A comma-separated list of finite numbers.
pub fn numbers(name: &str, text: &str) -> Result<Vec<f64>, Failure> {
    text.split(',').map(|t| number(name, t.trim())).collect()
}

/// A comma-separated list of key velocities: numbers ≥ 0, or `-` for a free slope
/// (`--velocities -,0.5,-`).
pub fn velocities(name: &str, text: &str) -> Result<Vec<Option<f64>>, Failure> {
    text.split(',')
        .map(|t| match t.trim() {
            "-" => Ok(None),
            t => number(name, t).map(Some),
        })
        .collect()
}
