// The figure's WebAssembly modules: the WebGPU-only renderer module (pkg-webgpu/), the WebGL2
// one (pkg-gl/), imported only when WebGPU has no usable adapter, and one with file import
// (pkg-full/), imported only for a glTF or CSV `src` when the renderer module has none. The
// playground (editor/modules.js) starts from the same first two. The npm package's build
// (scripts/build-pkg.sh) replaces this file with its own paths. The import paths are literal, so
// bundlers follow them.

/** Imports the main module (wasm-bindgen glue; its default export initialises the wasm). */
// @ts-ignore: scripts/serve.sh builds the module; the type check runs with or without it.
export const loadMain = () => import('../../pkg-webgpu/screwbender.js');

/** Imports the WebGL2 module (null where the main module has both backends). */
// @ts-ignore: scripts/serve.sh builds the module; the type check runs with or without it.
export const loadGl = () => import('../../pkg-gl/screwbender.js');

/** Imports a module with file import (`importMotionFile`), for renderer modules built without it. */
// @ts-ignore: scripts/serve.sh builds the module; the type check runs with or without it.
export const loadFiles = () => import('../../pkg-full/screwbender.js');
