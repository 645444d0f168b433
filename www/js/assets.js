// Where the figure finds what it loads besides its own modules: the WebAssembly modules (the
// renderer module, the WebGL2 one, the one that reads glTF and CSV files), its stylesheet and
// the Stanford bunny of the bunny6 preset. By default each sits where the page's layout puts it
// beside www/js/ (pkg-webgpu/, pkg-gl/, pkg-full/, css/, vendor/), found from this file's URL;
// a build that moves or inlines them says so once, with configure(), before the first figure
// starts: the npm package's entry (its own module folders), the notebook bundle and the
// offline file (modules, stylesheet and mesh inlined).
//
// The defaults are written as `new URL('literal', import.meta.url)` so that bundlers which copy
// such assets (Vite, webpack) find the stylesheet and the mesh; they are evaluated only when
// nothing was configured, since a module run from a blob: or an inline script has no folder.

/**
 * The modules of the figure: each a function that imports a wasm-bindgen module (its default
 * export initialises the wasm). `gl` may be null where `main` has both backends.
 * @typedef {object} ModuleLoaders
 * @property {() => Promise<any>} main
 * @property {(() => Promise<any>) | null} gl
 * @property {() => Promise<any>} files
 */
/**
 * @typedef {object} AssetConfig
 * @property {ModuleLoaders} [modules] the WebAssembly modules
 * @property {string} [stylesheet] the stylesheet's URL (a `data:` URL works)
 * @property {string} [css] the stylesheet's text, put in a <style> (instead of `stylesheet`)
 * @property {string | null} [bunny] the bunny mesh's URL (OBJ text); null: none, the wedge stands in
 */

/** @type {AssetConfig} */
const config = {};

/**
 * Tells the figure where its assets are (any subset; each replaces the default). Call it before
 * the first figure starts, as a build's entry module does.
 * @param {AssetConfig} assets
 */
export function configure(assets) {
  for (const key of Object.keys(assets)) {
    if (!['modules', 'stylesheet', 'css', 'bunny'].includes(key)) throw new TypeError(`configure: unknown asset "${key}" (modules, stylesheet, css, bunny)`);
  }
  Object.assign(config, assets);
}

/** The configured module loaders, or null for the page's own (element/modules.js). */
export const configuredModules = () => config.modules ?? null;

/** The figure's stylesheet as a node for its shadow root: a <link>, or a <style> with its text. */
export function stylesheetNode() {
  if (config.css != null) {
    const style = document.createElement('style');
    style.textContent = config.css;
    return style;
  }
  const link = document.createElement('link');
  link.rel = 'stylesheet';
  link.href = config.stylesheet ?? new URL('../css/screw-bender.css', import.meta.url).href;
  return link;
}

/** The bunny mesh's URL (null: there is none, and the wedge stands in). */
export function bunnyUrl() {
  if (config.bunny !== undefined) return config.bunny;
  return new URL('../vendor/bunny.obj', import.meta.url).href;
}
