//! The one place where JavaScript values meet the core's types, by concern: scalar arguments
//! (`values`), lists of numbers and typed arrays (`typed_arrays`), the serde bridge with element
//! paths in its errors (`bridge`), pose and kinematics layouts (`layouts`) and screw parameters
//! (`screw_info`).
//!
//! Every function here returns the core [`Error`] (with the path of the bad element), so the
//! callers can validate everything before they mutate anything.
//!
//! ## Typed-array layouts
//!
//! * **Poses** ([`POSE_STRIDE`] = 7 `f64` per pose, `Float64Array`):
//!   `[ox, oy, oz, qw, qx, qy, qz]` — the origin, then the unit quaternion scalar first.
//! * **Matrices** ([`MATRIX_STRIDE`] = 16 `f32` per pose, `Float32Array`): the 4×4 homogeneous
//!   local-to-world matrix in column-major order (`m[12..15]` is the origin), ready for WebGL /
//!   WebGPU instance buffers and `DOMMatrix.fromFloat32Array`.
//! * **Kinematics samples** ([`KINEMATICS_STRIDE`] = 16 `f64` per sample, `Float64Array`):
//!   `[u, px, py, pz, vx, vy, vz, ax, ay, az, wx, wy, wz, αx, αy, αz]` — the parameter, the body
//!   point's position, velocity and acceleration, the body's angular velocity and angular
//!   acceleration (all world frame, per coarse parameter unit).

mod bridge;
mod layouts;
mod screw_info;
mod typed_arrays;
mod values;

pub(crate) use bridge::*;
pub(crate) use layouts::*;
pub use layouts::{KINEMATICS_STRIDE, MATRIX_STRIDE, POSE_STRIDE};
pub(crate) use screw_info::*;
pub(crate) use typed_arrays::*;
pub(crate) use values::*;
