//! The crate's one error type.
//!
//! Errors carry the *path* of the offending element (`poses[3].rotation`, `levels`, …) so a user
//! reading the message knows what to fix. Pure math never fails and returns values; only calls that
//! take user input (parsing, validation, option values, size limits) return [`Result`].

use std::fmt;

/// Everything that can go wrong when ScrewBender is given bad input.
///
/// The `Display` form is one line: `<path>: <what is wrong>`, e.g.
/// `poses[3].rotation: zero quaternion`. Paths are built with [`Error::within`] as the error travels
/// outwards through nested inputs.
#[non_exhaustive]
#[derive(Debug, Clone, PartialEq)]
pub enum Error {
    /// A number is NaN or infinite.
    NonFinite {
        /// Path of the offending element.
        at: String,
    },
    /// A quaternion with all four components zero (it encodes no rotation).
    ZeroQuaternion {
        /// Path of the offending element.
        at: String,
    },
    /// A quaternion whose norm is further from 1 than [`crate::UNIT_QUATERNION_TOLERANCE`].
    NonUnitQuaternion {
        /// Path of the offending element.
        at: String,
        /// The norm that was found.
        norm: f64,
    },
    /// A basis `I, J, K` that is not orthonormal within [`crate::ORTHONORMAL_TOLERANCE`].
    NotOrthonormal {
        /// Path of the offending element.
        at: String,
        /// Largest entry of `|RᵀR − I|`.
        deviation: f64,
    },
    /// An orthonormal basis with determinant −1 (a reflection, not a rotation).
    LeftHanded {
        /// Path of the offending element.
        at: String,
    },
    /// Fewer poses than the operation needs.
    TooFewPoses {
        /// Path of the offending element.
        at: String,
        /// How many were given.
        found: usize,
        /// How many are needed.
        min: usize,
    },
    /// The result would exceed [`crate::MAX_REFINED_POSES`] poses (the memory guard).
    TooManyPoses {
        /// Path of the offending element (usually `levels`).
        at: String,
        /// How many poses the request would produce (saturating).
        requested: usize,
        /// The limit.
        max: usize,
    },
    /// An option value that is not one of the allowed names.
    UnknownValue {
        /// Path of the offending element.
        at: String,
        /// What was given.
        value: String,
        /// The allowed values, human readable.
        expected: &'static str,
    },
    /// A value of the right type outside its allowed range (an index, a level count, …).
    OutOfRange {
        /// Path of the offending element.
        at: String,
        /// What was given.
        value: String,
        /// The allowed range, human readable.
        expected: String,
    },
    /// An operation that the chosen options do not support.
    Unsupported {
        /// Path of the offending element.
        at: String,
        /// Why it is not supported.
        reason: String,
    },
    /// Malformed input text (JSON syntax, wrong types, missing fields).
    Parse {
        /// Path of the offending element (may be empty for a syntax error).
        at: String,
        /// The parser's message, including line and column where known.
        message: String,
    },
}

impl Error {
    /// The path of the offending element, e.g. `poses[3].rotation` (empty for the whole input).
    pub fn path(&self) -> &str {
        match self {
            Error::NonFinite { at }
            | Error::ZeroQuaternion { at }
            | Error::NonUnitQuaternion { at, .. }
            | Error::NotOrthonormal { at, .. }
            | Error::LeftHanded { at }
            | Error::TooFewPoses { at, .. }
            | Error::TooManyPoses { at, .. }
            | Error::UnknownValue { at, .. }
            | Error::OutOfRange { at, .. }
            | Error::Unsupported { at, .. }
            | Error::Parse { at, .. } => at,
        }
    }

    fn path_mut(&mut self) -> &mut String {
        match self {
            Error::NonFinite { at }
            | Error::ZeroQuaternion { at }
            | Error::NonUnitQuaternion { at, .. }
            | Error::NotOrthonormal { at, .. }
            | Error::LeftHanded { at }
            | Error::TooFewPoses { at, .. }
            | Error::TooManyPoses { at, .. }
            | Error::UnknownValue { at, .. }
            | Error::OutOfRange { at, .. }
            | Error::Unsupported { at, .. }
            | Error::Parse { at, .. } => at,
        }
    }

    /// Prefixes the path with the name of the enclosing element.
    ///
    /// `Error::ZeroQuaternion { at: "rotation".into() }.within("poses[3]")` has path
    /// `poses[3].rotation`; an index child (`[2]`) is joined without a dot.
    pub fn within(mut self, parent: &str) -> Self {
        let at = self.path_mut();
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
        let at = self.path();
        if !at.is_empty() {
            write!(f, "{at}: ")?;
        }
        match self {
            Error::NonFinite { .. } => write!(f, "not a finite number (NaN or infinity)"),
            Error::ZeroQuaternion { .. } => write!(f, "zero quaternion"),
            Error::NonUnitQuaternion { norm, .. } => write!(
                f,
                "quaternion norm {norm} is not 1 (accepted: within {} of 1, then normalised)",
                crate::UNIT_QUATERNION_TOLERANCE
            ),
            Error::NotOrthonormal { deviation, .. } => write!(
                f,
                "basis is not orthonormal (largest |RᵀR − I| entry {deviation:.3e}, accepted up to {:.0e})",
                crate::ORTHONORMAL_TOLERANCE
            ),
            Error::LeftHanded { .. } => {
                write!(f, "basis is left-handed (det = −1); a pose needs a right-handed frame")
            }
            Error::TooFewPoses { found, min, .. } => {
                write!(f, "{found} pose(s) given, at least {min} needed")
            }
            Error::TooManyPoses { requested, max, .. } => write!(
                f,
                "the result would have {requested} poses, more than the limit of {max}"
            ),
            Error::UnknownValue {
                value, expected, ..
            } => write!(f, "unknown value '{value}' (expected {expected})"),
            Error::OutOfRange {
                value, expected, ..
            } => write!(f, "{value} is out of range (expected {expected})"),
            Error::Unsupported { reason, .. } => write!(f, "{reason}"),
            Error::Parse { message, .. } => write!(f, "{message}"),
        }
    }
}

impl std::error::Error for Error {}

/// Checks that every component is finite, naming `at` otherwise.
pub(crate) fn check_finite(values: &[f64], at: &str) -> Result<(), Error> {
    if values.iter().all(|v| v.is_finite()) {
        Ok(())
    } else {
        Err(Error::NonFinite { at: at.to_string() })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paths_nest_with_dots_and_brackets() {
        let e = Error::ZeroQuaternion {
            at: "rotation".into(),
        }
        .within("[3]")
        .within("poses");
        assert_eq!(e.path(), "poses[3].rotation");
        assert_eq!(e.to_string(), "poses[3].rotation: zero quaternion");
    }

    #[test]
    fn empty_path_takes_parent() {
        let e = Error::NonFinite { at: String::new() }.within("origin");
        assert_eq!(
            e.to_string(),
            "origin: not a finite number (NaN or infinity)"
        );
    }
}
