//! Sine, cosine and angles for the presets' meshes, the same bits on every target.
//!
//! `f64::sin`, `f64::cos` and `f64::acos` (which glam's `angle_between` calls) use the
//! platform's math library: natively the C library's, in WebAssembly a port of musl's. Both are
//! within an ulp, but not the same ulp, and that last bit matters: on a convex hull's flat faces
//! it picks which triangulation the hull takes, and in the morph's vertex normals it shows in
//! the file, so the page (wasm) and the command line (native) would write the same morphing
//! shapes with other bytes. The `libm` crate is that musl port in plain Rust, so every target
//! that draws a preset's object computes it from the same numbers. In WebAssembly the standard
//! library's functions already are that port (the compiler's built-in copy of `libm`), so they
//! are called there instead of a second copy, which the figure's download would carry twice.

use glam::DVec3;

/// `sin(x)`, bit for bit the same on every target.
pub(crate) fn sin(x: f64) -> f64 {
    #[cfg(target_arch = "wasm32")]
    return x.sin();
    #[cfg(not(target_arch = "wasm32"))]
    return libm::sin(x);
}

/// `cos(x)`, bit for bit the same on every target.
pub(crate) fn cos(x: f64) -> f64 {
    #[cfg(target_arch = "wasm32")]
    return x.cos();
    #[cfg(not(target_arch = "wasm32"))]
    return libm::cos(x);
}

/// `(sin(x), cos(x))`, bit for bit the same on every target.
pub(crate) fn sin_cos(x: f64) -> (f64, f64) {
    (sin(x), cos(x))
}

/// The angle between `a` and `b` in radians (glam's `DVec3::angle_between`, with `acos` bit
/// for bit the same on every target).
pub(crate) fn angle_between(a: DVec3, b: DVec3) -> f64 {
    let cosine = (a.dot(b) / (a.length_squared() * b.length_squared()).sqrt()).clamp(-1.0, 1.0);
    #[cfg(target_arch = "wasm32")]
    return cosine.acos();
    #[cfg(not(target_arch = "wasm32"))]
    return libm::acos(cosine);
}
