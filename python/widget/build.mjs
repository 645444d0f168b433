// Bundles the notebook figure (figure.js) into screwbender/static/figure.js with esbuild (the
// root node_modules): one ES module holding the viewer's sources, its stylesheet, the bunny
// preset's mesh and the figure's two WebAssembly renderer modules (WebGPU, and WebGL2 where
// WebGPU has no adapter; only the one the browser draws with is instantiated), so
// that a notebook, a JupyterLab, VS Code or an exported HTML page needs no server, no CDN and
// no network.
//
// The assets are inlined by esbuild's loaders in assets.js, which tells the figure where they are
// (www/js/assets.js's configure()); the sources of www/js are bundled as they are.
//
// It also writes screwbender/static/loader.js (loader.js minified), the ES module of each figure
// widget, which imports the bundle from the kernel's one asset model.
//
//   node python/widget/build.mjs   # from www/pkg-webgpu/ and www/pkg-gl/ (scripts/serve.sh builds them)
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { createRequire } from 'node:module';

const HERE = path.dirname(fileURLToPath(import.meta.url));
const ROOT = path.resolve(HERE, '../..');
const require = createRequire(path.join(ROOT, 'package.json'));
const esbuild = require('esbuild');

const www = path.join(ROOT, 'www');
const wasm = path.join(www, 'pkg-webgpu/screwbender_bg.wasm');
const wasmGl = path.join(www, 'pkg-gl/screwbender_bg.wasm');
for (const f of [wasm, wasmGl]) if (!fs.existsSync(f)) throw new Error(`${f} is missing: build the playground's wasm (scripts/serve.sh) first`);
const out = path.join(ROOT, 'python/screwbender/static/figure.js');

const result = await esbuild.build({
  entryPoints: [path.join(HERE, 'figure.js')],
  bundle: true,
  format: 'esm',
  minify: true,
  target: 'es2022',
  loader: { '.wasm': 'binary', '.css': 'text', '.obj': 'dataurl' },
  outfile: out,
  metafile: true,
  logLevel: 'warning',
  legalComments: 'none',
});
const text = fs.readFileSync(out, 'utf8');
// import.meta is left only in default paths that configure() replaced (the glue's own .wasm,
// the page's module folders, stylesheet and mesh): `new URL(…, import.meta.url)`, evaluated
// only when nothing was configured. Any other use is a path the bundle cannot resolve.
const rest = text.replace(/new URL\([^()]*,import\.meta\.url\)/g, '');
if (rest.includes('import.meta')) throw new Error(`${out}: uses import.meta (a path the bundle cannot resolve)`);
// Each figure's own ES module: the small loader that imports the bundle from the shared asset model.
const loader = path.join(ROOT, 'python/screwbender/static/loader.js');
await esbuild.build({ entryPoints: [path.join(HERE, 'loader.js')], format: 'esm', minify: true, target: 'es2022', outfile: loader, logLevel: 'warning' });
const wasmBytes = fs.statSync(wasm).size + fs.statSync(wasmGl).size;
console.log(`${path.relative(ROOT, out)}: ${(fs.statSync(out).size / 1e6).toFixed(2)} MB (wasm ${(wasmBytes / 1e6).toFixed(2)} MB before base64)`);
void result;
