//! Comparison methods from the literature, all behind the crate's [`Motion`] trait, and
//! the metrics that compare them.
//!
//! | method | type | smoothness | interpolates | source |
//! |---|---|---|---|---|
//! | [`Polyscrew`](crate::Polyscrew) | screws between poses (ScLERP polyline) | C⁰ | yes | ScrewBender §3 |
//! | [`ScrewBender`](crate::ScrewBender) | screw subdivision | limit C¹/C² | 4-point | ScrewBender |
//! | [`SlerpPolyline`] | SLERP + linear origins | C⁰ | yes | classical |
//! | [`DecoupledSmooth`] | Squad + Catmull–Rom origins | C¹ | yes | Shoemake |
//! | [`KimKimShin`] | cumulative B-spline quaternions + B-spline origins | C² | no (ends only) | Kim, Kim & Shin 1995 |
//! | [`Se3BSpline`] | cumulative cubic B-spline on SE(3), approximating or interpolating | C² | variant | Lovegrove et al. 2013; Sommer et al. 2020 |
//! | [`SplitBSpline`] | cumulative cubic B-spline on R³ × SO(3) (approximating: the same motion as [`KimKimShin`]), or interpolating | C² | variant | the same, split |
//! | [`RamamoorthiBarr`] | covariant-acceleration-optimal Hermite quaternion spline + Catmull–Rom origins | C¹ | yes | Ramamoorthi & Barr |
//! | [`RationalMotion`] | rational quadratic / quartic rigid-triangle motion | C⁰ / C¹ | yes | Chaudhry & Cameron |
//! | [`BarrBaseline`] | the same objective as Ramamoorthi–Barr on dense discrete frames (small inputs) | C⁰ (dense) | yes | Barr, Currin, Gabriel & Hughes |
//!
//! [`Method`] names them all (`polyscrew`, `bspline`, `fourpoint`, `jarek`, `slerp`, `decoupled`,
//! `kks`, `se3bspline`, `se3interp`, `splitinterp`, `rb`, `cc0`, `cc1`) and builds each from control poses with pose `i` at `u = i`; the
//! metrics ([`compare_methods`], [`MetricsTable`]) measure velocity/acceleration jumps at the
//! knots, integrated squared accelerations, interpolation error, dependence on the local frame
//! and exact reproduction of line, circle and helix motions.
//!
//! ```
//! use glam::{DQuat, DVec3};
//! use screwbender::methods::{compare_methods, Method, MetricsOptions};
//! use screwbender::{Motion, Pose};
//!
//! let poses: Vec<Pose> = (0..5)
//!     .map(|i| Pose::new(DVec3::new(i as f64, (i % 2) as f64, 0.0), DQuat::from_rotation_z(0.4 * i as f64)))
//!     .collect();
//! let rb = Method::Rb.build(&poses, false)?;
//! assert!(rb.pose_at(2.0).approx_eq(&poses[2], 1e-12));
//! let table = compare_methods(&poses, false, &[Method::Jarek, Method::Kks], &MetricsOptions::default())?;
//! assert_eq!(table.rows.len(), 2);
//! // Screw subdivision does not depend on the choice of the local frame; decoupled methods do.
//! assert!(table.rows[0].frame_dependence.unwrap() < 1e-12);
//! assert!(table.rows[1].frame_dependence.unwrap() > 1e-3);
//! # Ok::<(), screwbender::Error>(())
//! ```
//!
//! Conventions are the crate's: poses map local to world, quaternions are `[w, x, y, z]` at the
//! boundaries (glam's [`glam::DQuat`] inside), parameters in coarse units (or the data times for
//! [`RationalMotion`] and [`RamamoorthiBarr`]). Quaternions that are merely points of R⁴ (spline
//! control points, the non-unit values of the Ramamoorthi–Barr curve) are also stored in
//! [`glam::DQuat`], using only its vector-space operations. Every fallible constructor validates
//! its input and returns an [`Error`](crate::Error) naming the offending element; evaluation never
//! panics (NaN parameters give NaN poses).

mod algebra;
mod catmull_rom_squad;
mod convergence;
mod gauss;
mod kim_kim_shin;
mod lbfgs;
mod lie_spline;
mod metrics;
mod polynomial;
mod positions;
mod ramamoorthi_barr;
mod rational;
mod registry;
mod slerp_polyline;
mod triangle;

#[allow(unused_imports)] // for the links in the docs above
use crate::motion::Motion;

// Methods and their registry.
pub use catmull_rom_squad::DecoupledSmooth;
pub use kim_kim_shin::KimKimShin;
pub use lie_spline::group::{LieGroup, Se3, SplitSe3, SplitSegment, Twist};
pub use lie_spline::{
    BodyDerivatives, LieBSpline, Se3BSpline, SplitBSpline, INTERPOLATION_TOLERANCE,
    MAX_INTERPOLATION_ITERATIONS,
};
pub use registry::{Method, Smoothness, COMPARISON_LEVELS};
pub use slerp_polyline::SlerpPolyline;

// Chaudhry & Cameron.
pub use rational::{
    triangle_samples, Continuity, EndCondition, RationalBezierExport, RationalBezierSegment,
    RationalMotion, GROWTH_WARNING, MIN_DENOMINATOR, TRIANGLE_STRIDE,
};
pub use triangle::{
    rotation_between, samples_from_poses, validate_samples, ReferenceTriangle, TriangleSample,
    DEGENERATE_TRIANGLE_TOLERANCE, RIGIDITY_TOLERANCE, ROTATION_EPSILON,
};

// Ramamoorthi & Barr, and the discrete baseline of Barr et al.
pub use ramamoorthi_barr::barr::{
    fit_barr, BarrBaseline, BarrFit, BarrOptions, BARR_RELATIVE_DECREASE,
    DEFAULT_BARR_FRAMES_PER_INTERVAL, MAX_BARR_FRAMES,
};
pub use ramamoorthi_barr::optimizer::{
    fit_quaternion_spline, initial_spline, optimise_spline, Insertion, RamamoorthiBarr, RbFit,
    RbOptions, RbStage, DEFAULT_ALPHA, DEFAULT_GAUSS_NODES, DEFAULT_MIN_RELATIVE_DECREASE,
    DEFAULT_SEGMENTS_PER_INTERVAL, DEFAULT_VARIABLE_FRAMES, MAX_RB_FRAMES,
};
pub use ramamoorthi_barr::spline::{
    euler_lagrange, integrand, EulerLagrange, Frame, HermiteQuatSpline, FRAME_TIME_TOLERANCE,
    MAX_SPLINE_SAMPLES,
};

// Metrics.
pub use convergence::{converged_metrics, Converged, ConvergedMetrics, Limit, CONVERGENCE_LEVELS};
pub use metrics::{
    compare_applicable, compare_methods, evaluate, finite_difference, frame_dependence,
    interpolation_error, kinematics_at, preservation_errors, preservation_inputs,
    sampled_difference, single_step_metrics, Derivatives, MetricsOptions, MetricsRow, MetricsTable,
    MotionBuilder, Side, SingleStepMetrics, DEFAULT_QUADRATURE_SUBINTERVALS,
    DEFAULT_SAMPLES_PER_SPAN, FD_ACCELERATION_STEP, FD_VELOCITY_STEP, KNOT_OFFSET,
    MAX_METRIC_SAMPLES, PRESERVATION_POSES,
};

// Building blocks.
pub use algebra::{
    angular_rates, canonical_signs, polar_matrix, qexp, qlog, slerp_raw, unnormalised_matrix,
    SMALL_ANGLE,
};
pub use gauss::{gauss_legendre, MAX_GAUSS_NODES};
pub use lbfgs::{
    minimize, LbfgsOptions, LbfgsReport, LbfgsStop, DEFAULT_GRADIENT_TOLERANCE,
    DEFAULT_LBFGS_MEMORY, DEFAULT_VALUE_TOLERANCE,
};
pub use polynomial::{bezier, bezier_d2, hermite_basis, hermite_d3, Vector};
pub use positions::CatmullRom;
