//! The named list of motion methods compared by the metrics, the CLI and the page.

use std::fmt;
use std::str::FromStr;

use super::catmull_rom_squad::DecoupledSmooth;
use super::kim_kim_shin::KimKimShin;
use super::lie_spline::{Se3BSpline, SplitBSpline};
use super::ramamoorthi_barr::barr::{BarrBaseline, BarrOptions};
use super::ramamoorthi_barr::optimizer::{RamamoorthiBarr, RbOptions};
use super::rational::{Continuity, EndCondition, RationalMotion};
use super::slerp_polyline::SlerpPolyline;
use super::triangle::ReferenceTriangle;
use crate::error::{Error, ErrorKind};
use crate::motion::Motion;
use crate::polyscrew::Polyscrew;
use crate::pose::Pose;
use crate::screwbender::ScrewBender;
use crate::subdivision::scheme::{Rules, Scheme};
use crate::subdivision::Subdivision;

/// Subdivision levels of the ScrewBender methods in the comparison (`2⁵ = 32` refined spans per
/// control span).
pub const COMPARISON_LEVELS: u32 = 5;

/// The continuity class of a method's motion ([`Method::smoothness`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Smoothness {
    /// Continuous poses; the velocity jumps at the knots.
    C0,
    /// Continuous velocity; the acceleration jumps at the knots.
    C1,
    /// Continuous acceleration.
    C2,
}

/// A motion method, built from control poses with pose `i` at parameter `u = i`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Method {
    /// Screws between consecutive poses ([`Polyscrew`]): the ScLERP polyline.
    Polyscrew,
    /// ScrewBender, cubic B-spline scheme, direct rules, [`COMPARISON_LEVELS`] levels.
    BSpline,
    /// ScrewBender, 4-point scheme, direct rules.
    FourPoint,
    /// ScrewBender, Jarek scheme, direct rules.
    Jarek,
    /// Piecewise SLERP + linear origins ([`SlerpPolyline`]).
    Slerp,
    /// Catmull–Rom origins + Squad rotations ([`DecoupledSmooth`]).
    Decoupled,
    /// Kim–Kim–Shin B-spline quaternion curve + B-spline origins ([`KimKimShin`]).
    Kks,
    /// Cumulative cubic B-spline on SE(3) with the poses as control poses ([`Se3BSpline`],
    /// approximating).
    Se3BSpline,
    /// Cumulative cubic B-spline on SE(3) through the poses ([`Se3BSpline::interpolating`]; only
    /// when named).
    Se3Interp,
    /// Cumulative cubic B-spline on R³ × SO(3), origins and rotations apart, through the poses
    /// ([`SplitBSpline::interpolating`]; only when named). (The approximating one is
    /// [`Method::Kks`]: the same motion.)
    SplitInterp,
    /// Ramamoorthi–Barr quaternion spline + Catmull–Rom origins ([`RamamoorthiBarr`], default
    /// options, free end velocities).
    Rb,
    /// Chaudhry–Cameron C⁰ ([`RationalMotion`], scene B1 reference triangle).
    Cc0,
    /// Chaudhry–Cameron C¹ with end condition (18) (open sequences only).
    Cc1,
    /// The discrete baseline of Barr et al. ([`BarrBaseline`]): Ramamoorthi–Barr's objective on
    /// dense frames ([`BarrOptions::for_keys`]) (open sequences of at
    /// most about 40 poses; only when named, never among [`Method::applicable`]).
    Barr,
}

impl Method {
    /// Every method, in table order.
    pub const ALL: [Method; 14] = [
        Method::Polyscrew,
        Method::BSpline,
        Method::FourPoint,
        Method::Jarek,
        Method::Slerp,
        Method::Decoupled,
        Method::Kks,
        Method::Se3BSpline,
        Method::Se3Interp,
        Method::SplitInterp,
        Method::Rb,
        Method::Cc0,
        Method::Cc1,
        Method::Barr,
    ];

    /// The accepted names, for messages.
    pub const NAMES: &'static str = "polyscrew, bspline, fourpoint, jarek, slerp, decoupled, kks, \
                                     se3bspline, se3interp, splitinterp, rb, cc0, cc1, barr";

    /// The short name (as accepted by [`Method::from_str`]).
    pub fn name(self) -> &'static str {
        match self {
            Method::Polyscrew => "polyscrew",
            Method::BSpline => "bspline",
            Method::FourPoint => "fourpoint",
            Method::Jarek => "jarek",
            Method::Slerp => "slerp",
            Method::Decoupled => "decoupled",
            Method::Kks => "kks",
            Method::Se3BSpline => "se3bspline",
            Method::Se3Interp => "se3interp",
            Method::SplitInterp => "splitinterp",
            Method::Rb => "rb",
            Method::Cc0 => "cc0",
            Method::Cc1 => "cc1",
            Method::Barr => "barr",
        }
    }

    /// The method's continuity class on generic poses, which its converged metrics show: C⁰,
    /// velocity jumps at the knots (the discrete baseline of Barr et al. joins its dense frames
    /// by SLERP, so it jumps slightly at each of them); C¹, no velocity jump; C², no
    /// acceleration jump either. Jarek is classed by what is proven of it, at least C¹.
    pub fn smoothness(self) -> Smoothness {
        match self {
            Method::Polyscrew | Method::Slerp | Method::Cc0 | Method::Barr => Smoothness::C0,
            Method::FourPoint | Method::Jarek | Method::Decoupled | Method::Rb | Method::Cc1 => {
                Smoothness::C1
            }
            Method::BSpline
            | Method::Kks
            | Method::Se3BSpline
            | Method::Se3Interp
            | Method::SplitInterp => Smoothness::C2,
        }
    }

    /// Whether the method has a closed (cyclic) form. The C¹ Chaudhry–Cameron motion and the
    /// discrete baseline of Barr et al. have not.
    pub fn supports_closed(self) -> bool {
        !matches!(self, Method::Cc1 | Method::Barr)
    }

    /// Whether the method is compared only when named, never among [`Method::applicable`]: the
    /// discrete baseline of Barr et al. (costly, for small inputs) and the interpolating Lie-group
    /// B-splines (which have no solution where poses turn far between neighbours, see
    /// [`Se3BSpline::interpolating`]).
    pub fn only_when_named(self) -> bool {
        matches!(self, Method::Barr | Method::Se3Interp | Method::SplitInterp)
    }

    /// The methods that apply to a closed or open input, in table order, without those compared
    /// [`Method::only_when_named`].
    pub fn applicable(closed: bool) -> Vec<Method> {
        Method::ALL
            .into_iter()
            .filter(|m| !m.only_when_named() && (!closed || m.supports_closed()))
            .collect()
    }

    /// Sentences for where this method's motion through `poses` is poor though it was built
    /// without error: the C¹ Chaudhry–Cameron recursion running away on long sequences
    /// ([`RationalMotion::warning`]); empty for every other method, and when the method rejects
    /// the input (its error says why).
    pub fn warnings(self, poses: &[Pose], closed: bool) -> Vec<String> {
        let continuity = match self {
            Method::Cc1 => Continuity::C1(EndCondition::ZeroCurvatureStart),
            _ => return Vec::new(),
        };
        let times: Vec<f64> = (0..poses.len() + usize::from(closed))
            .map(|i| i as f64)
            .collect();
        RationalMotion::from_poses(
            poses,
            &times,
            closed,
            continuity,
            &ReferenceTriangle::SCENE_B1,
        )
        .ok()
        .and_then(|m| m.warning())
        .into_iter()
        .collect()
    }

    /// Builds the motion through `poses` (pose `i` at `u = i`; a closed motion has period `n`).
    pub fn build(self, poses: &[Pose], closed: bool) -> Result<Box<dyn Motion>, Error> {
        self.build_at(poses, closed, COMPARISON_LEVELS)
    }

    /// Whether the method is a ScrewBender subdivision motion (its refinement depends on the
    /// levels of [`Method::build_at`]).
    pub fn is_subdivision(self) -> bool {
        matches!(self, Method::BSpline | Method::FourPoint | Method::Jarek)
    }

    /// [`Method::build`] with the ScrewBender methods refined `levels` times (the other methods
    /// ignore `levels`).
    pub fn build_at(
        self,
        poses: &[Pose],
        closed: bool,
        levels: u32,
    ) -> Result<Box<dyn Motion>, Error> {
        let sb = |scheme| -> Result<Box<dyn Motion>, Error> {
            let s = Subdivision::new(scheme, Rules::Direct, levels);
            Ok(Box::new(ScrewBender::new(poses.to_vec(), closed, s)?))
        };
        let times: Vec<f64> = (0..poses.len() + usize::from(closed))
            .map(|i| i as f64)
            .collect();
        let cc = |c| -> Result<Box<dyn Motion>, Error> {
            // Validate the poses first so that errors name them.
            super::slerp_polyline::validated_poses(poses, closed)?;
            Ok(Box::new(RationalMotion::from_poses(
                poses,
                &times,
                closed,
                c,
                &ReferenceTriangle::SCENE_B1,
            )?))
        };
        match self {
            Method::Polyscrew => Ok(Box::new(Polyscrew::new(poses.to_vec(), closed)?)),
            Method::BSpline => sb(Scheme::BSpline),
            Method::FourPoint => sb(Scheme::FourPoint),
            Method::Jarek => sb(Scheme::Jarek),
            Method::Slerp => Ok(Box::new(SlerpPolyline::new(poses, closed)?)),
            Method::Decoupled => Ok(Box::new(DecoupledSmooth::new(poses, closed)?)),
            Method::Kks => Ok(Box::new(KimKimShin::new(poses, closed)?)),
            Method::Se3BSpline => Ok(Box::new(Se3BSpline::new(poses, closed)?)),
            Method::Se3Interp => Ok(Box::new(Se3BSpline::interpolating(poses, closed)?)),
            Method::SplitInterp => Ok(Box::new(SplitBSpline::interpolating(poses, closed)?)),
            Method::Rb => {
                super::slerp_polyline::validated_poses(poses, closed)?;
                Ok(Box::new(RamamoorthiBarr::from_poses(
                    poses,
                    &times,
                    closed,
                    &RbOptions::default(),
                )?))
            }
            Method::Cc0 => cc(Continuity::C0),
            Method::Cc1 => cc(Continuity::C1(EndCondition::ZeroCurvatureStart)),
            Method::Barr => {
                let poses = super::slerp_polyline::validated_poses(poses, closed)?;
                if closed {
                    return Err(Error::new(
                        "closed",
                        ErrorKind::Unsupported {
                            reason: "the discrete baseline of Barr et al. is built for open \
                                     sequences only"
                                .into(),
                        },
                    ));
                }
                let options = BarrOptions::for_keys(poses.len());
                Ok(Box::new(BarrBaseline::from_poses(
                    &poses, &times, &options,
                )?))
            }
        }
    }
}

impl fmt::Display for Method {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Method {
    type Err = Error;
    /// Parses one of [`Method::NAMES`] (case-insensitive, surrounding spaces ignored).
    fn from_str(s: &str) -> Result<Method, Error> {
        let t = s.trim().to_ascii_lowercase();
        Method::ALL
            .into_iter()
            .find(|m| m.name() == t)
            .ok_or_else(|| {
                Error::new(
                    "methods",
                    ErrorKind::UnknownValue {
                        value: s.to_string(),
                        expected: Method::NAMES,
                    },
                )
            })
    }
}
