//! Sets `cfg(lanes)` where the screw batches run several screws at a time on SIMD lanes
//! (`src/screw/batch.rs`): every native target, and wasm32 only when built with `simd128`
//! (without SIMD the interleaved lanes gained nothing there and would only add code to the
//! size-budgeted module; docs/speed/code-notes.md).
//! `cfg(portable_lanes)` marks where the portable `Lanes` type is used: everywhere but wasm32
//! with `simd128`, which has its own (`src/lanes/wasm.rs`).

fn main() {
    println!("cargo::rustc-check-cfg=cfg(lanes)");
    println!("cargo::rustc-check-cfg=cfg(portable_lanes)");
    let wasm = std::env::var("CARGO_CFG_TARGET_ARCH").unwrap_or_default() == "wasm32";
    let simd128 = std::env::var("CARGO_CFG_TARGET_FEATURE")
        .unwrap_or_default()
        .split(',')
        .any(|f| f == "simd128");
    if !wasm || simd128 {
        println!("cargo::rustc-cfg=lanes");
    }
    if !wasm {
        println!("cargo::rustc-cfg=portable_lanes");
    }
}
