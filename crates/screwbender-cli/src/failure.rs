//! How a command fails: one message for standard error, exit status 2.

use screwbender::Error;

/// A failure of the command: a message for standard error (exit status 2).
pub struct Failure(pub String);

impl From<Error> for Failure {
    fn from(e: Error) -> Self {
        Failure(e.to_string())
    }
}
