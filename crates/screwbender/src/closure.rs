//! Whether a sequence of poses closes into a cycle: a vocabulary type of its own, so that a call
//! reads `ScrewBender::new(poses, Closure::Closed, rules)` instead of a bare `true`.

/// Whether a sequence of poses is a cycle (its last pose joined back to its first by a screw) or
/// open (docs/math/conventions.md §2.1).
///
/// Constructors take `impl Into<Closure>`, so a `bool` (`true` = closed) still converts; new code
/// names the variant.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Closure {
    /// A cycle: `n` poses, `n` spans, domain `[0, n)`.
    #[default]
    Closed,
    /// An open sequence: `m` poses, `m − 1` spans, domain `[0, m − 1]`.
    Open,
}

impl Closure {
    /// `true` for [`Closure::Closed`].
    pub fn is_closed(self) -> bool {
        self == Closure::Closed
    }
}

impl From<bool> for Closure {
    /// `true` is [`Closure::Closed`], `false` [`Closure::Open`].
    fn from(closed: bool) -> Closure {
        if closed {
            Closure::Closed
        } else {
            Closure::Open
        }
    }
}
