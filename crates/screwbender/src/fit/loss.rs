//! Robust losses: how much a sample's residual counts, so that a few wild samples (outliers of
//! a motion capture) do not drag the fitted motion towards them.
//!
//! With `s` a sample's residual length and `δ` the scale, the loss `ρ(s²)` replaces `s²`:
//!
//! ```text
//! none:    ρ = s²
//! Huber:   ρ = s²              (s ≤ δ),   2δs − δ²        (s > δ)
//! Cauchy:  ρ = δ² ln(1 + s²/δ²)
//! ```
//!
//! Gauss–Newton minimises them by reweighting (each sample's rows weighted by `ρ′(s²)`, Triggs
//! et al., *Bundle Adjustment — A Modern Synthesis*, §4.3).

use crate::error::{Error, ErrorKind};

/// The robust loss of a fit (see the module documentation).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RobustLoss {
    /// Plain least squares.
    None,
    /// Quadratic up to the scale, linear beyond: outliers count by their distance, not its square.
    Huber,
    /// Logarithmic beyond the scale: far outliers count almost nothing.
    Cauchy,
}

impl RobustLoss {
    /// The ids of the losses, as the command line, JavaScript and Python spell them.
    pub const NAMES: &'static str = "none, huber, cauchy";

    /// The loss named `name` (`none`, `huber` or `cauchy`); errors name `robust`.
    pub fn from_name(name: &str) -> Result<RobustLoss, Error> {
        match name {
            "none" => Ok(RobustLoss::None),
            "huber" => Ok(RobustLoss::Huber),
            "cauchy" => Ok(RobustLoss::Cauchy),
            _ => Err(Error::new(
                "robust",
                ErrorKind::UnknownValue {
                    value: name.into(),
                    expected: RobustLoss::NAMES,
                },
            )),
        }
    }

    /// The id of the loss.
    pub fn name(self) -> &'static str {
        match self {
            RobustLoss::None => "none",
            RobustLoss::Huber => "huber",
            RobustLoss::Cauchy => "cauchy",
        }
    }

    /// `ρ(s²)` at scale `delta` (> 0).
    pub(crate) fn rho(self, s2: f64, delta: f64) -> f64 {
        match self {
            RobustLoss::None => s2,
            RobustLoss::Huber => {
                let s = s2.sqrt();
                if s <= delta {
                    s2
                } else {
                    2.0 * delta * s - delta * delta
                }
            }
            RobustLoss::Cauchy => delta * delta * (s2 / (delta * delta)).ln_1p(),
        }
    }

    /// The weight `ρ′(s²)` of a sample's rows in the normal equations.
    pub(crate) fn weight(self, s2: f64, delta: f64) -> f64 {
        match self {
            RobustLoss::None => 1.0,
            RobustLoss::Huber => {
                let s = s2.sqrt();
                if s <= delta {
                    1.0
                } else {
                    delta / s
                }
            }
            RobustLoss::Cauchy => 1.0 / (1.0 + s2 / (delta * delta)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn weights_are_the_derivatives_of_the_losses() {
        for loss in [RobustLoss::None, RobustLoss::Huber, RobustLoss::Cauchy] {
            assert_eq!(RobustLoss::from_name(loss.name()), Ok(loss));
            for s2 in [0.01, 0.5, 2.0, 30.0] {
                let h = 1e-6;
                let d = (loss.rho(s2 + h, 0.8) - loss.rho(s2 - h, 0.8)) / (2.0 * h);
                assert!((d - loss.weight(s2, 0.8)).abs() < 1e-8, "{loss:?} at {s2}");
            }
        }
        assert_eq!(RobustLoss::from_name("l1").unwrap_err().path(), "robust");
    }
}
