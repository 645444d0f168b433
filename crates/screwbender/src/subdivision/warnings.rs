//! Warnings where a subdivision's result is silently poor (docs/math/subdivision.md §4, validity).
//!
//! The first version's split-then-tweak rules place the new pose of span `i` (4-point) or tweak
//! it (Jarek) with the screw between the split midpoints of spans `i − 1` and `i + 1`. That screw
//! turns at most half a turn, the short way round; when the poses between those midpoints turn by
//! half a turn or more, the rule blends towards a pose on the wrong side and the result leaves the
//! data's path (3 poses on a circle of radius 5: off by 3.8 units with the 4-point rule, 1.6
//! with Jarek; 4 poses 90° apart make every such screw exactly a half turn, whose direction
//! rounding decides). The direct rules and the B-spline never read a screw that wide.

use std::fmt;

use super::scheme::{Rules, Scheme};
use super::Subdivision;
use crate::pose::Pose;

/// How far (radians) below half a turn a tweak screw's turn still counts as a half turn: the
/// rounding of the angles of a few spans summed, far below any turn a user would set apart.
pub const HALF_TURN_TOLERANCE: f64 = 1e-9;

/// A subdivision result that is poor without any error being raised.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Warning {
    /// A split-then-tweak rule reads a screw whose poses turn by half a turn or more.
    WideTweak {
        /// The scheme whose rule fails (4-point or Jarek).
        scheme: Scheme,
        /// The span (between poses `span` and `span + 1`) whose new pose goes wrong.
        span: usize,
        /// The rotation, in radians, along the poses between the split midpoints of the spans
        /// before and after `span` (half of each plus all of `span`): `≥ π − HALF_TURN_TOLERANCE`.
        turn: f64,
    },
}

impl fmt::Display for Warning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Warning::WideTweak { scheme, span, turn } => write!(
                f,
                "span {span}: the split-then-tweak {} rule reads a screw across spans that \
                 turn by {:.1}° in total (180° or more), so the new pose of span {span} takes \
                 the short way round and the result is poor; use the direct rules or add poses",
                match scheme {
                    Scheme::FourPoint => "4-point",
                    Scheme::Jarek => "Jarek",
                    _ => "tweak",
                },
                turn.to_degrees()
            ),
        }
    }
}

impl Subdivision {
    /// The warnings for subdividing `poses` (cyclic when `closed`) with these options: empty
    /// unless the result is poor without an error being raised.
    ///
    /// With the split-then-tweak rules and a scheme that tweaks new poses (4-point, Jarek),
    /// every span whose tweak screw spans poses turning by half a turn or more (the half of the
    /// span before, the span, the half of the span after) is named, in order. An open sequence
    /// counts its extension beyond each end (docs/math/open-sequences.md §2), whose spans repeat
    /// the end spans; a span of the extension that fails is reported as the end span it
    /// continues. No levels (nothing subdivided), fewer than 2 poses, or invalid options, give no
    /// warnings (the subdivision
    /// itself reports those).
    pub fn warnings(&self, poses: &[Pose], closed: bool) -> Vec<Warning> {
        let n = poses.len();
        if self.levels == 0
            || self.rules != Rules::SplitThenTweak
            || self.validate().is_err()
            || n < 2
        {
            return Vec::new();
        }
        // The rules that tweak new poses: every scheme but the B-spline (which tweaks old poses
        // only, by screws across one span).
        if self.scheme.s() == 1.0 {
            return Vec::new();
        }
        let spans = if closed { n } else { n - 1 };
        // The turn of span `j`; for an open sequence, `j` beyond the ends continues the end span.
        let turn = |j: isize| -> f64 {
            let j = if closed {
                j.rem_euclid(n as isize) as usize
            } else {
                j.clamp(0, spans as isize - 1) as usize
            };
            poses[j].angle_to(&poses[(j + 1) % n])
        };
        // For an open sequence, the extension's spans next to the ends also get new poses whose
        // errors the following levels carry into the kept spans.
        let (first, last) = if closed {
            (0, spans as isize - 1)
        } else {
            (-1, spans as isize)
        };
        let mut out: Vec<Warning> = Vec::new();
        for j in first..=last {
            let total = 0.5 * turn(j - 1) + turn(j) + 0.5 * turn(j + 1);
            if total < std::f64::consts::PI - HALF_TURN_TOLERANCE {
                continue;
            }
            let span = j.clamp(0, spans as isize - 1) as usize;
            match out.last_mut() {
                Some(Warning::WideTweak {
                    span: previous,
                    turn: worst,
                    ..
                }) if *previous == span => *worst = worst.max(total),
                _ => out.push(Warning::WideTweak {
                    scheme: self.scheme,
                    span,
                    turn: total,
                }),
            }
        }
        out
    }
}
