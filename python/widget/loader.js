// The ES module of every `screwbender.Figure` widget (screwbender/static/loader.js): small, so
// that each figure's model initialises at once. The viewer itself (static/figure.js: the
// element, its stylesheet and the renderer's WebAssembly modules) travels once per kernel in
// one shared asset model (`_Assets` in screwbender/_figure.py), which every figure references
// by its `_assets` trait; the first figure of a page imports it, and every figure of the page
// uses that one import (one wasm instance, one WebGPU device).
const VIEWER = Symbol.for('screwbender.figure.viewer');

/** The viewer's `render` (imported from the asset model on first use). */
function viewer(model) {
  globalThis[VIEWER] ??= (async () => {
    // A widget reference ("IPY_MODEL_" and the model id), or the model where a manager unpacked it.
    const ref = model.get('_assets');
    const assets = typeof ref === 'string' ? await model.widget_manager.get_model(ref.replace(/^IPY_MODEL_/, '')) : ref;
    const url = URL.createObjectURL(new Blob([assets.get('code')], { type: 'text/javascript' }));
    try {
      return (await import(url)).default.render;
    } finally {
      URL.revokeObjectURL(url);
    }
  })().catch((e) => {
    // Not kept: the next figure tries again.
    delete globalThis[VIEWER];
    throw e;
  });
  return globalThis[VIEWER];
}

export default {
  async render({ model, el }) {
    const render = await viewer(model);
    return render({ model, el });
  },
};
