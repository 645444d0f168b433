//! Option values: the subdivision options shared by `subdivide`, `eval` and `export`, and the
//! checks that turn an option's text into a number, a list or a level count with a message
//! naming the option.

use std::ffi::OsStr;

use clap::builder::TypedValueParser;
use clap::error::ErrorKind;
use screwbender::{Rules, Scheme, Subdivision};

use crate::failure::Failure;

/// `--scheme`, `--s`, `--rules`, `--levels` and `--open`, as given: [`Self::subdivision`] is
/// the one place they become a [`Subdivision`], so that the names, the defaults and the
/// messages stay those of the core.
#[derive(clap::Args)]
#[command(next_help_heading = "Subdivision options")]
pub struct SubdivisionArgs {
    /// Subdivision scheme: bspline, fourpoint or jarek (default: fourpoint)
    #[arg(long, value_name = "SCHEME", allow_hyphen_values = true)]
    scheme: Option<String>,
    /// Use the J_s family with parameter S instead of --scheme (S=0 4-point, S=0.5 Jarek, S=1
    /// B-spline; direct rules only)
    #[arg(long, value_name = "S", value_parser = Finite, allow_hyphen_values = true)]
    s: Option<f64>,
    /// Rule set: the revised paper's direct rules (direct, the default) or the first version's
    /// split-then-tweak rules (split-then-tweak, also: split)
    #[arg(long, value_name = "RULES", allow_hyphen_values = true)]
    rules: Option<String>,
    /// Subdivision steps (default 5; eval: 0 = plain polyscrew)
    #[arg(long, value_name = "N", allow_hyphen_values = true)]
    levels: Option<String>,
    /// Treat the poses as an open sequence (overrides the document's 'closed')
    #[arg(long)]
    pub open: bool,
}

impl SubdivisionArgs {
    /// The subdivision asked for (`--s` selects the J_s family), with `default_levels` when
    /// `--levels` was not given.
    pub fn subdivision(&self, default_levels: u32) -> Result<Subdivision, Failure> {
        let scheme = self
            .scheme
            .as_deref()
            .map(str::parse::<Scheme>)
            .transpose()?;
        let rules = self.rules.as_deref().map(str::parse::<Rules>).transpose()?;
        let levels = self.levels.as_deref().map(levels).transpose()?;
        let scheme = match (scheme, self.s) {
            (Some(_), Some(_)) => {
                return Err(Failure(
                    "give either --scheme or --s (the J_s family), not both".into(),
                ))
            }
            (_, Some(s)) => Scheme::J(s),
            (Some(scheme), None) => scheme,
            (None, None) => Scheme::default(),
        };
        Ok(Subdivision::new(
            scheme,
            rules.unwrap_or_default(),
            levels.unwrap_or(default_levels),
        ))
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

/// A level count (a whole number ≥ 0).
pub fn levels(text: &str) -> Result<u32, Failure> {
    text.parse::<u32>().map_err(|_| {
        Failure(format!(
            "--levels: '{text}' is not a level count (expected a whole number ≥ 0)"
        ))
    })
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
