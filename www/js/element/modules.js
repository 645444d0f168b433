// The figure's WebAssembly modules where the page's layout puts them: the WebGPU-only renderer
// module (pkg-webgpu/), the WebGL2 one (pkg-gl/), imported only when WebGPU has no usable
// adapter, and one with file import (pkg-full/), imported only for a glTF or CSV `src` when the
// renderer module has none. The playground (editor/modules.js) starts from the same first two.
// A build that puts them elsewhere says where with assets.js's configure() (the npm package's
// entry, with literal import paths that bundlers follow); these are resolved from this file's
// URL at run time, so a bundler leaves them alone.

/** `path` from this file's folder (where the page's www/js/element/ is). */
const at = (path) => new URL(path, import.meta.url).href;

/** Imports the main module (wasm-bindgen glue; its default export initialises the wasm). */
export const loadMain = () => import(/* @vite-ignore */ /* webpackIgnore: true */ at('../../pkg-webgpu/screwbender.js'));

/** Imports the WebGL2 module. */
export const loadGl = () => import(/* @vite-ignore */ /* webpackIgnore: true */ at('../../pkg-gl/screwbender.js'));

/** Imports a module with file import (`importMotionFile`), for renderer modules built without it. */
export const loadFiles = () => import(/* @vite-ignore */ /* webpackIgnore: true */ at('../../pkg-full/screwbender.js'));
