// Bundles the notebook figure (figure.js) into screwbender/static/figure.js with esbuild (the
// root node_modules): one ES module holding the viewer's sources, its stylesheet, the bunny
// preset's mesh and the figure's two WebAssembly renderer modules (WebGPU, and WebGL2 where
// WebGPU has no adapter; only the one the browser draws with is instantiated), so
// that a notebook, a JupyterLab, VS Code or an exported HTML page needs no server, no CDN and
// no network.
//
// Three sources of www/js are adapted while bundling (the sources themselves stay as the page
// and the npm package use them): the figure's module loader (element/modules.js) initialises the
// wasm from the inlined bytes instead of fetching `screwbender_bg.wasm` beside the glue; the
// stylesheet link of element/chrome.js becomes a <style> with the CSS text (a bundle has no
// folder to link into); the bunny mesh URL of view/drawing.js becomes a data: URL.
//
// It also writes screwbender/static/loader.js (loader.js minified), the ES module of each figure
// widget, which imports the bundle from the kernel's one asset model.
//
//   node python/widget/build.mjs [WWW_DIR]   # default www/ (pkg-webgpu/ and pkg-gl/, scripts/serve.sh)
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { createRequire } from 'node:module';

const HERE = path.dirname(fileURLToPath(import.meta.url));
const ROOT = path.resolve(HERE, '../..');
const require = createRequire(path.join(ROOT, 'package.json'));
const esbuild = require('esbuild');

const www = path.resolve(process.argv[2] ?? path.join(ROOT, 'www'));
const glue = path.join(www, 'pkg-webgpu/screwbender.js');
const wasm = path.join(www, 'pkg-webgpu/screwbender_bg.wasm');
const glueGl = path.join(www, 'pkg-gl/screwbender.js');
const wasmGl = path.join(www, 'pkg-gl/screwbender_bg.wasm');
for (const f of [glue, wasm, glueGl, wasmGl]) if (!fs.existsSync(f)) throw new Error(`${f} is missing: build the playground's wasm (scripts/serve.sh) first`);
const out = path.join(ROOT, 'python/screwbender/static/figure.js');

/** Replaces `from` by `to` in `text`, failing loudly when the source no longer has it. */
function patch(file, text, from, to) {
  if (!text.includes(from)) throw new Error(`${file}: '${from}' not found (the source changed: update build.mjs)`);
  return text.replace(from, to);
}

const adapt = {
  name: 'screwbender-figure',
  setup(build) {
    build.onResolve({ filter: /^screwbender-figure:/ }, (a) => ({ path: a.path, namespace: 'figure' }));
    build.onLoad({ filter: /^screwbender-figure:modules$/, namespace: 'figure' }, () => ({
      resolveDir: HERE,
      loader: 'js',
      contents: `
        import init, * as glue from ${JSON.stringify(glue)};
        import initGl, * as glueGl from ${JSON.stringify(glueGl)};
        import bytes from ${JSON.stringify(wasm)};
        import bytesGl from ${JSON.stringify(wasmGl)};
        export const loadMain = async () => ({ ...glue, default: () => init({ module_or_path: bytes }) });
        export const loadGl = async () => ({ ...glueGl, default: () => initGl({ module_or_path: bytesGl }) });
        export const loadFiles = () => Promise.reject(new Error('both modules read files themselves'));`,
    }));
    build.onLoad({ filter: /element[\\/]wasm\.js$/ }, (a) => {
      const text = fs.readFileSync(a.path, 'utf8');
      return { loader: 'js', contents: patch(a.path, text, "from './modules.js'", "from 'screwbender-figure:modules'") };
    });
    build.onLoad({ filter: /element[\\/]chrome\.js$/ }, (a) => {
      let text = fs.readFileSync(a.path, 'utf8');
      const css = fs.readFileSync(path.join(ROOT, 'www/css/screw-bender.css'), 'utf8');
      text = patch(a.path, text, "const link = document.createElement('link');", "const link = document.createElement('style');");
      text = patch(a.path, text, "link.rel = 'stylesheet';", `link.textContent = ${JSON.stringify(css)};`);
      text = patch(a.path, text, "link.href = new URL('../../css/screw-bender.css', import.meta.url).href;", '');
      return { loader: 'js', contents: text };
    });
    build.onLoad({ filter: /view[\\/]drawing\.js$/ }, (a) => {
      const text = fs.readFileSync(a.path, 'utf8');
      const obj = fs.readFileSync(path.join(ROOT, 'www/vendor/bunny.obj'));
      const url = `data:text/plain;base64,${obj.toString('base64')}`;
      return { loader: 'js', contents: patch(a.path, text, "new URL('../../vendor/bunny.obj', import.meta.url)", JSON.stringify(url)) };
    });
  },
};

const result = await esbuild.build({
  entryPoints: [path.join(HERE, 'figure.js')],
  bundle: true,
  format: 'esm',
  minify: true,
  target: 'es2022',
  loader: { '.wasm': 'binary' },
  plugins: [adapt],
  outfile: out,
  metafile: true,
  logLevel: 'warning',
  legalComments: 'none',
});
const text = fs.readFileSync(out, 'utf8');
// The glue's default path to its .wasm (used only when init gets no bytes, which never happens
// here) is the one use of import.meta left: any other is a path the bundle cannot resolve.
const rest = text.replaceAll('new URL("screwbender_bg.wasm",import.meta.url)', '');
if (rest.includes('import.meta')) throw new Error(`${out}: uses import.meta (a path the bundle cannot resolve)`);
// Each figure's own ES module: the small loader that imports the bundle from the shared asset model.
const loader = path.join(ROOT, 'python/screwbender/static/loader.js');
await esbuild.build({ entryPoints: [path.join(HERE, 'loader.js')], format: 'esm', minify: true, target: 'es2022', outfile: loader, logLevel: 'warning' });
const wasmBytes = fs.statSync(wasm).size + fs.statSync(wasmGl).size;
console.log(`${path.relative(ROOT, out)}: ${(fs.statSync(out).size / 1e6).toFixed(2)} MB (wasm ${(wasmBytes / 1e6).toFixed(2)} MB before base64)`);
void result;
