//! Sets `cfg(lanes)` where the screw batches run two screws at a time on SIMD lanes
//! (`src/screw_batch.rs`): every native target, and wasm32 only when built with `simd128`
//! (without SIMD the interleaved lanes gained nothing there and would add 6 KB to the module).

fn main() {
    println!("cargo::rustc-check-cfg=cfg(lanes)");
    let arch = std::env::var("CARGO_CFG_TARGET_ARCH").unwrap_or_default();
    let features = std::env::var("CARGO_CFG_TARGET_FEATURE").unwrap_or_default();
    if arch != "wasm32" || features.split(',').any(|f| f == "simd128") {
        println!("cargo::rustc-cfg=lanes");
    }
}
