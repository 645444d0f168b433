//! The crate's one error type: the path of the offending element, and what is wrong with it.
//!
//! Errors carry the *path* of the offending element (`poses[3].rotation`, `levels`, …) so a user
//! reading the message knows what to fix. Pure math never fails and returns values; only calls that
//! take user input (parsing, validation, option values, size limits) return [`Result`].
//!
//! This module is plain data and imports nothing of the crate: a kind that needs a tolerance in
//! its message carries it.

use std::fmt;

/// Everything that can go wrong when ScrewBender is given bad input: where ([`Error::path`]) and
/// what ([`Error::kind`]).
///
/// The `Display` form is one line: `<path>: <what is wrong>`, e.g.
/// `poses[3].rotation: zero quaternion`. Paths are built with [`Error::within`] as the error
/// travels outwards through nested inputs.
#[derive(Debug, Clone, PartialEq)]
pub struct Error {
    path: String,
    kind: ErrorKind,
}

/// What is wrong with the element an [`Error`] names.
#[non_exhaustive]
#[derive(Debug, Clone, PartialEq)]
pub enum ErrorKind {
    /// A number is NaN or infinite.
    NonFinite,
    /// A quaternion with all four components zero (it encodes no rotation).
    ZeroQuaternion,
    /// A quaternion whose norm is further from 1 than `tolerance`
    /// ([`crate::UNIT_QUATERNION_TOLERANCE`]).
    NonUnitQuaternion {
        /// The norm that was found.
        norm: f64,
        /// How far from 1 a norm is accepted (and then normalised).
        tolerance: f64,
    },
    /// A basis `I, J, K` that is not orthonormal within `tolerance`
    /// ([`crate::ORTHONORMAL_TOLERANCE`]).
    NotOrthonormal {
        /// Largest entry of `|RᵀR − I|`.
        deviation: f64,
        /// The largest deviation accepted.
        tolerance: f64,
    },
    /// An orthonormal basis with determinant −1 (a reflection, not a rotation).
    LeftHanded,
    /// Fewer poses than the operation needs.
    TooFewPoses {
        /// How many were given.
        found: usize,
        /// How many are needed.
        min: usize,
    },
    /// The result would exceed [`crate::MAX_REFINED_POSES`] poses (the memory guard).
    TooManyPoses {
        /// How many poses the request would produce (saturating).
        requested: usize,
        /// The limit.
        max: usize,
    },
    /// An option value that is not one of the allowed names.
    UnknownValue {
        /// What was given.
        value: String,
        /// The allowed values, human readable.
        expected: &'static str,
    },
    /// A value of the right type outside its allowed range (an index, a level count, …).
    OutOfRange {
        /// What was given.
        value: String,
        /// The allowed range, human readable.
        expected: String,
    },
    /// An operation that the chosen options do not support.
    Unsupported {
        /// Why it is not supported.
        reason: String,
    },
    /// Malformed input text (JSON syntax, wrong types, missing fields).
    Parse {
        /// The parser's message, including line and column where known.
        message: String,
    },
}

impl Error {
    /// An error of `kind` at the element `path` (empty for the whole input).
    pub fn new(path: impl Into<String>, kind: ErrorKind) -> Error {
        Error {
            path: path.into(),
            kind,
        }
    }

    /// The path of the offending element, e.g. `poses[3].rotation` (empty for the whole input).
    pub fn path(&self) -> &str {
        &self.path
    }

    /// What is wrong with the element.
    pub fn kind(&self) -> &ErrorKind {
        &self.kind
    }

    /// Prefixes the path with the name of the enclosing element.
    ///
    /// `Error::new("rotation", ErrorKind::ZeroQuaternion).within("poses[3]")` has path
    /// `poses[3].rotation`; an index child (`[2]`) is joined without a dot.
    pub fn within(mut self, parent: &str) -> Self {
        let at = &mut self.path;
        *at = if at.is_empty() {
            parent.to_string()
        } else if parent.is_empty() {
            std::mem::take(at)
        } else if at.starts_with('[') {
            format!("{parent}{at}")
        } else {
            format!("{parent}.{at}")
        };
        self
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if !self.path.is_empty() {
            write!(f, "{}: ", self.path)?;
        }
        write!(f, "{}", self.kind)
    }
}

impl fmt::Display for ErrorKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ErrorKind::NonFinite => write!(f, "not a finite number (NaN or infinity)"),
            ErrorKind::ZeroQuaternion => write!(f, "zero quaternion"),
            ErrorKind::NonUnitQuaternion { norm, tolerance } => write!(
                f,
                "quaternion norm {norm} is not 1 (accepted: within {tolerance} of 1, then normalised)"
            ),
            ErrorKind::NotOrthonormal {
                deviation,
                tolerance,
            } => write!(
                f,
                "basis is not orthonormal (largest |RᵀR − I| entry {deviation:.3e}, accepted up to {tolerance:.0e})"
            ),
            ErrorKind::LeftHanded => {
                write!(f, "basis is left-handed (det = −1); a pose needs a right-handed frame")
            }
            ErrorKind::TooFewPoses { found, min } => {
                write!(f, "{found} pose(s) given, at least {min} needed")
            }
            ErrorKind::TooManyPoses { requested, max } => write!(
                f,
                "the result would have {requested} poses, more than the limit of {max}"
            ),
            ErrorKind::UnknownValue { value, expected } => {
                write!(f, "unknown value '{value}' (expected {expected})")
            }
            ErrorKind::OutOfRange { value, expected } => {
                write!(f, "{value} is out of range (expected {expected})")
            }
            ErrorKind::Unsupported { reason } => write!(f, "{reason}"),
            ErrorKind::Parse { message } => write!(f, "{message}"),
        }
    }
}

impl std::error::Error for Error {}

/// Checks that every component is finite, naming `at` otherwise.
pub(crate) fn check_finite(values: &[f64], at: &str) -> Result<(), Error> {
    if values.iter().all(|v| v.is_finite()) {
        Ok(())
    } else {
        Err(Error::new(at, ErrorKind::NonFinite))
    }
}

/// Checks an input's size before it is parsed: at most `max` bytes, naming `at` otherwise.
pub(crate) fn check_size(len: usize, max: usize, at: &str) -> Result<(), Error> {
    if len <= max {
        Ok(())
    } else {
        Err(Error::new(
            at,
            ErrorKind::OutOfRange {
                value: format!("{len} bytes"),
                expected: format!("at most {max} bytes"),
            },
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paths_nest_with_dots_and_brackets() {
        let e = Error::new("rotation", ErrorKind::ZeroQuaternion)
            .within("[3]")
            .within("poses");
        assert_eq!(e.path(), "poses[3].rotation");
        assert_eq!(e.to_string(), "poses[3].rotation: zero quaternion");
    }

    #[test]
    fn empty_path_takes_parent() {
        let e = Error::new("", ErrorKind::NonFinite).within("origin");
        assert_eq!(
            e.to_string(),
            "origin: not a finite number (NaN or infinity)"
        );
    }

    #[test]
    fn tolerances_travel_in_the_kind() {
        let e = Error::new(
            "q",
            ErrorKind::NonUnitQuaternion {
                norm: 2.0,
                tolerance: 1e-3,
            },
        );
        assert_eq!(
            e.to_string(),
            "q: quaternion norm 2 is not 1 (accepted: within 0.001 of 1, then normalised)"
        );
    }
}
