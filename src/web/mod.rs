//! The WebAssembly / JavaScript API (compiled for `wasm32` only).
