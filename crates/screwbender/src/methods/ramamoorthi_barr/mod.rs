//! Ramamoorthi & Barr's quaternion splines in one room: the C¹ Hermite spline on the unit sphere
//! and its covariant-acceleration objective (`spline`), the optimiser that inserts variable
//! frames and minimises it (`optimizer`), and the discrete baseline of Barr et al. that it is
//! compared with (`barr`). Notes: docs/math/quaternion-splines.md.

pub(crate) mod barr;
pub(crate) mod optimizer;
pub(crate) mod spline;
