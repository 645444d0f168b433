//! Sine and cosine for the presets' meshes, the same bits on every target.
//!
//! `f64::sin` and `f64::cos` call the platform's math library: natively the C library's, in
//! WebAssembly a port of musl's. Both are within an ulp, but not the same ulp, and that last bit
//! matters where it decides something discrete: on a convex hull's flat faces it picks which
//! triangulation the hull takes, so the page (wasm) and the command line (native) would write the
//! same morphing shapes with their triangles in another order. The `libm` crate is that musl
//! port in plain Rust, so every target that draws a preset's object computes it from the same
//! numbers.

/// `sin(x)`, bit for bit the same on every target.
pub(crate) fn sin(x: f64) -> f64 {
    libm::sin(x)
}

/// `cos(x)`, bit for bit the same on every target.
pub(crate) fn cos(x: f64) -> f64 {
    libm::cos(x)
}

/// `(sin(x), cos(x))`, bit for bit the same on every target.
pub(crate) fn sin_cos(x: f64) -> (f64, f64) {
    libm::sincos(x)
}
