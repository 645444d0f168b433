// The playground's WebAssembly modules and the code it fetches only when first used.
//
// The first frame needs only the renderer: the WebGPU module the <screw-bender> figure uses
// (pkg-webgpu/: the motion, the WebGPU renderer, OBJ and glTF objects), or where WebGPU has no
// usable adapter (or ?backend=webgl2) the WebGL2 one (pkg-gl/); element/modules.js names them.
// The analysis views, file import and export, the comparison methods and the teaching functions
// are in a third module (pkg-full/: no renderer), fetched with the dock, the first import or
// export of a file, or a lesson that measures a motion or has measured poses. Its
// Motion and the renderer module's are separate instances: the renderer module's Motion gets
// the methods only the analysis module has (motionMetrics, methodSample, compareMethods,
// quaternionSpline, keyframeTracks) once that module has loaded, each run on the analysis
// module's copy of the motion (the same document and options, so the same results bit for bit).
//
// Every later fetch can fail (offline, a server without the file): lazy() turns the failure
// into an Error naming what could not load, and the next use tries again.
import { loadMain, loadGl } from '../element/modules.js';

/**
 * The renderer module, initialised: the WebGPU one, or the WebGL2 one when `webgl2` is set or
 * WebGPU offers no usable adapter. Resolves to {wasm, gl}: `gl` says the module draws WebGL2.
 */
export async function renderModule(webgl2 = false) {
  let adapter = null;
  if (!webgl2 && navigator.gpu) {
    try {
      adapter = await navigator.gpu.requestAdapter();
    } catch {
      adapter = null;
    }
  }
  return webgl2 || !adapter ? { wasm: await glModule(), gl: true } : { wasm: await init(loadMain()), gl: false };
}

/** The WebGL2 renderer module, initialised (also the fallback where WebGPU fails to start). */
export const glModule = lazy('the WebGL2 renderer', () => init(loadGl()));

async function init(imported) {
  const m = await imported;
  await m.default();
  return m;
}

/**
 * Opens the Share & embed dialog (editor/share-dialog.js, fetched when first opened: a first
 * visit does not download it); a failed fetch is a message in the banner.
 * @param {import('../app.js').App} app
 * @param {Element | null} opener  where the focus goes back when the dialog closes
 */
export function openShare(app, opener = document.activeElement) {
  shareDialog().then(
    (m) => m.openShareDialog(app, opener),
    (e) => app.parts.notices.show(e.message),
  );
}
const shareDialog = lazy('the share dialog', (a) => import(a ? `./share-dialog.js?retry=${a}` : './share-dialog.js'));

/**
 * Adds the stylesheet at `url` to the page and resolves once it has loaded: for the styles of
 * code fetched when first used, which a first visit does not download either. A stylesheet
 * that fails to load is taken out again (so that a retry adds it anew) and rejects.
 * @param {URL} url
 * @returns {Promise<void>}
 */
export function stylesheet(url) {
  return new Promise((resolve, reject) => {
    const link = document.createElement('link');
    link.rel = 'stylesheet';
    link.href = url.href;
    link.onload = () => resolve();
    link.onerror = () => {
      link.remove();
      reject(new Error(`${url.pathname.split('/').pop()} did not load`));
    };
    document.head.append(link);
  });
}

/**
 * A loader of `what` (named in the error message): `load(attempt)` runs once and its promise is
 * kept; a failure is thrown as an Error naming `what` and forgotten, so the next call tries again
 * (with the next `attempt`: 0, 1, …).
 */
export function lazy(what, load) {
  let pending = null;
  let attempt = 0;
  return () => {
    pending ??= load(attempt++).catch((e) => {
      pending = null;
      throw new Error(`Could not load ${what} (${e?.message ?? e})`);
    });
    return pending;
  };
}

/**
 * The analysis module (pkg-full/), initialised, with its Motion methods forwarded from the
 * renderer module's Motion class `RenderMotion`.
 */
export function analysisModule(RenderMotion) {
  return loadAnalysis().then((m) => {
    forwardMotionMethods(RenderMotion, m.Motion);
    analysisLoaded = m;
    return m;
  });
}

/** The analysis module once analysisModule has resolved, else null (for code that must not wait). */
export const loadedAnalysis = () => analysisLoaded;
let analysisLoaded = null;

// A module whose fetch failed stays failed under its URL (the browser keeps it in its module
// map), so a retry asks for it under another one.
const loadAnalysis = lazy('the analysis functions', (attempt) =>
  // @ts-ignore: scripts/serve.sh builds the module; the type check runs with or without it.
  init(attempt ? import(`../../pkg-full/screwbender.js?retry=${attempt}`) : import('../../pkg-full/screwbender.js')),
);

/** The analysis module's copy of the last motion asked for, while its document and options stay. */
let copy = null;

function copyOf(motion, Motion) {
  const json = motion.toJson();
  const options = motion.options();
  const key = `${json}\n${JSON.stringify(options)}`;
  if (copy?.source !== motion || copy.key !== key) {
    // Through JSON.parse (exact), not fromJson: the wasm module reads JSON numbers by a fast
    // path that can land one unit in the last place off, and the copy must be the motion itself.
    const made = new Motion(JSON.parse(json), options);
    copy?.motion.free();
    copy = { source: motion, key, motion: made };
  }
  return copy.motion;
}

/** Adds to RenderMotion's prototype each method that only the analysis module's Motion has. */
function forwardMotionMethods(RenderMotion, Motion) {
  const own = RenderMotion.prototype;
  if (forwarded.has(own)) return;
  forwarded.add(own);
  for (const [name, d] of Object.entries(Object.getOwnPropertyDescriptors(Motion.prototype))) {
    if (name in own || typeof d.value !== 'function') continue;
    Object.defineProperty(own, name, {
      configurable: true,
      writable: true,
      value(...args) {
        return copyOf(this, Motion)[name](...args);
      },
    });
  }
}

const forwarded = new WeakSet();
