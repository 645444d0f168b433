// The figure's WebAssembly modules. In www/ the playground's module (../../pkg/) has both
// backends, so there is no separate WebGL2 module; the npm package's build (scripts/build-pkg.sh)
// replaces this file: there ../../pkg/ has WebGPU only, and loadGl imports the WebGL2 module,
// fetched only when WebGPU has no usable adapter. The import paths are literal, so bundlers
// follow them.

/** Imports the main module (wasm-bindgen glue; its default export initialises the wasm). */
export const loadMain = () => import('../../pkg/screwbender.js');

/** Imports the WebGL2 module, or null when the main module has both backends. */
export const loadGl = null;
