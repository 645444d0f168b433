// The WebAssembly side that all figures of a page share: one module instance (the main module, or
// the WebGL2 one when WebGPU has no usable adapter), the files module where a glTF or CSV `src`
// needs one, and one queue in which figures open their renderers. The modules are those that
// assets.js's configure() names, else the page's own (modules.js).
import { configuredModules } from '../assets.js';
import * as pageModules from './modules.js';

/** The module loaders in use: {main, gl, files}. */
function loaders() {
  return configuredModules() ?? { main: pageModules.loadMain, gl: pageModules.loadGl, files: pageModules.loadFiles };
}

let wasmReady = null;
let glReady = null;
/**
 * The one wasm module instance all figures share (initialised on first use): the main module,
 * or the WebGL2 module when there is one and WebGPU offers no usable adapter. A figure that asks
 * for WebGL2 (`webgl2`) gets the WebGL2 module where there is one, shared by such figures, since
 * the WebGPU-only module cannot draw with WebGL2.
 */
export function loadWasm({ webgl2 = false } = {}) {
  const { main: loadMain, gl: loadGl } = loaders();
  if (webgl2 && loadGl) {
    glReady ??= (async () => {
      const m = await loadGl();
      await m.default();
      return m;
    })();
    return glReady;
  }
  wasmReady ??= (async () => {
    let adapter = null;
    if (loadGl && navigator.gpu) {
      try {
        adapter = await navigator.gpu.requestAdapter();
      } catch {
        adapter = null;
      }
    }
    const m = await (loadGl && !adapter ? loadGl() : loadMain());
    await m.default();
    return m;
  })();
  return wasmReady;
}

let filesReady = null;
/**
 * The module with file import (`importMotionFile`), initialised on first use, for a glTF or CSV
 * `src` when the renderer module has none; loaded again after a failure.
 */
export function loadFiles() {
  filesReady ??= loaders().files()
    .then(async (m) => {
      await m.default();
      return m;
    })
    .catch((e) => {
      filesReady = null;
      throw e;
    });
  return filesReady;
}

/** Figures open their renderers one after another, so the first one's WebGPU device is shared. */
let startChain = Promise.resolve();
export function serially(f) {
  const run = startChain.then(f, f);
  startChain = run.catch(() => {});
  return run;
}
