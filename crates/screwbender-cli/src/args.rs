//! Reading a command's arguments: option values, the one positional FILE, numbers, and the
//! subdivision options shared by `subdivide`, `eval` and `export`.

use screwbender::{Rules, Scheme, Subdivision};

use crate::failure::Failure;

/// Walks one command's arguments.
pub struct ArgReader<'a> {
    it: std::slice::Iter<'a, String>,
    /// The positional FILE argument, if one was given.
    pub file: Option<String>,
}

impl<'a> ArgReader<'a> {
    /// A reader over `args` (the command's arguments, without the command name).
    pub fn new(args: &'a [String]) -> ArgReader<'a> {
        ArgReader {
            it: args.iter(),
            file: None,
        }
    }

    /// The next argument.
    pub fn next_arg(&mut self) -> Option<&'a str> {
        self.it.next().map(String::as_str)
    }

    /// The value that must follow option `name`.
    pub fn value(&mut self, name: &str) -> Result<String, Failure> {
        self.it
            .next()
            .cloned()
            .ok_or_else(|| Failure(format!("{name} needs a value")))
    }

    /// An argument no option of the command claimed: an unknown `--option` is an error,
    /// anything else is the FILE (at most one).
    pub fn positional(&mut self, arg: &str) -> Result<(), Failure> {
        if arg.starts_with("--") {
            return Err(Failure(format!("unknown option '{arg}' (try --help)")));
        }
        if self.file.replace(arg.to_string()).is_some() {
            return Err(Failure("more than one input FILE given".into()));
        }
        Ok(())
    }
}

/// `--scheme`, `--s`, `--rules`, `--levels` and `--open`.
#[derive(Default)]
pub struct SubdivisionArgs {
    scheme: Option<Scheme>,
    s: Option<f64>,
    rules: Rules,
    levels: Option<u32>,
    /// `--open` was given (overrides the document's `closed`).
    pub open: bool,
}

impl SubdivisionArgs {
    /// Consumes `flag` (and its value) if it is one of these options; `Ok(false)` otherwise.
    pub fn take(&mut self, flag: &str, args: &mut ArgReader) -> Result<bool, Failure> {
        match flag {
            "--scheme" => self.scheme = Some(args.value(flag)?.parse::<Scheme>()?),
            "--s" => self.s = Some(number(flag, &args.value(flag)?)?),
            "--rules" => self.rules = args.value(flag)?.parse::<Rules>()?,
            "--levels" => self.levels = Some(levels(&args.value(flag)?)?),
            "--open" => self.open = true,
            _ => return Ok(false),
        }
        Ok(true)
    }

    /// The subdivision asked for (`--s` selects the J_s family), with `default_levels` when
    /// `--levels` was not given.
    pub fn subdivision(&self, default_levels: u32) -> Result<Subdivision, Failure> {
        let scheme = match (self.scheme, self.s) {
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
            self.rules,
            self.levels.unwrap_or(default_levels),
        ))
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
