// The offline figure's template (run by 60-offline.sh): www/pkg-offline/figure.html and its size
// in www/pkg-offline/figure.json. The playground's share dialog (www/js/editor/share-dialog.js)
// fills in the figure (a <screw-bender> with a share payload) and the title, and downloads it.
//
// The file is made of:
// * the element's ES modules (www/js/element/screw-bender.js and what it imports, the wasm-bindgen
//   glue among them) bundled by esbuild into one inline module script, unchanged. A module run
//   first (OFFLINE_ASSETS) tells the figure where its assets are (www/js/assets.js's
//   configure()): the renderer modules from the page's inline bytes, the stylesheet as a data:
//   URL, the Stanford bunny from the page (the dialog adds it only when the figure shows it).
// * the two renderer modules of the figure (WebGPU, and WebGL2 where WebGPU has no adapter),
//   each gzip-compressed (DecompressionStream unpacks it) and base64-encoded in a
//   <script type="application/octet-stream"> element, which the browser never runs; only the one
//   the browser draws with is unpacked.
// * a Content-Security-Policy that lets the page load nothing from any network (default-src
//   'none'; the scripts by their hashes; fetch only of data: URLs).
import crypto from 'node:crypto';
import fs from 'node:fs';
import path from 'node:path';
import zlib from 'node:zlib';
import { fileURLToPath } from 'node:url';
import * as esbuild from 'esbuild';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const WWW = path.join(ROOT, 'www');
const OUT = path.join(WWW, 'pkg-offline');
const WASM = path.join(WWW, 'pkg-webgpu/screwbender_bg.wasm');
const WASM_GL = path.join(WWW, 'pkg-gl/screwbender_bg.wasm');

/** Where the dialog puts the figure, the title and the bunny (each once in the template). */
const SLOTS = { figure: '<!--screwbender:figure-->', title: '<!--screwbender:title-->', bunny: '<!--screwbender:bunny-->' };

const css = fs.readFileSync(path.join(WWW, 'css/screw-bender.css'), 'utf8');
const cssUrl = `data:text/css;base64,${Buffer.from(css).toString('base64')}`;

const OFFLINE_ASSETS = `
import { configure } from './js/assets.js';
import * as glue from './pkg-webgpu/screwbender.js';
import * as glueGl from './pkg-gl/screwbender.js';

/** A wasm module's bytes from the page: base64 of gzip (scripts/serve.d/60-offline.mjs). */
async function wasmBytes(id) {
  const text = document.getElementById(id).textContent.trim();
  const packed = await fetch('data:application/gzip;base64,' + text);
  return new Response(packed.body.pipeThrough(new DecompressionStream('gzip'))).arrayBuffer();
}

/** A module whose default export initialises it from the page's bytes of element \`id\`. */
async function inline(g, id) {
  const module_or_path = await wasmBytes(id);
  return { ...g, default: () => g.default({ module_or_path }) };
}

const bunny = document.getElementById('screwbender-bunny');
configure({
  modules: {
    main: () => inline(glue, 'screwbender-wasm'),
    gl: () => inline(glueGl, 'screwbender-wasm-gl'),
    // Both inline modules read glTF and CSV themselves, and the page fetches no other module.
    files: () => Promise.reject(new Error('no file import module offline')),
  },
  stylesheet: ${JSON.stringify(cssUrl)},
  // No bunny in the page: none, and the wedge stands in.
  bunny: bunny ? 'data:text/plain;charset=utf-8,' + encodeURIComponent(bunny.textContent) : null,
});
`;

/** The entry: the assets first (evaluated before the element defines itself), then the element. */
const offline = {
  name: 'offline',
  setup(build) {
    build.onResolve({ filter: /^offline:assets$/ }, () => ({ path: 'assets', namespace: 'offline' }));
    build.onLoad({ filter: /.*/, namespace: 'offline' }, () => ({ contents: OFFLINE_ASSETS, loader: 'js', resolveDir: WWW }));
  },
};

const result = await esbuild.build({
  stdin: { contents: "import 'offline:assets';\nimport './js/element/screw-bender.js';\n", resolveDir: WWW, loader: 'js' },
  bundle: true,
  minify: true,
  format: 'esm',
  platform: 'browser',
  write: false,
  legalComments: 'none',
  logLevel: 'warning',
  plugins: [offline],
});
// Inline script text must not close its element early.
const js = result.outputFiles[0].text.replace(/<\/(script)/gi, '<\\/$1');

const wasm = fs.readFileSync(WASM);
const packed = zlib.gzipSync(wasm, { level: 9 }).toString('base64');
const wasmGl = fs.readFileSync(WASM_GL);
const packedGl = zlib.gzipSync(wasmGl, { level: 9 }).toString('base64');

const style = 'html,body{margin:0;height:100%}body{display:flex;flex-direction:column;background:#e8ecf1;font:14px/1.4 system-ui,-apple-system,"Segoe UI",sans-serif}screw-bender{flex:1 1 auto;min-height:0;aspect-ratio:auto}@media (prefers-color-scheme:dark){body{background:#1b1f27;color:#e6e9ef}}';
const hash = (s) => `'sha256-${crypto.createHash('sha256').update(s).digest('base64')}'`;
const csp = [
  "default-src 'none'",
  `script-src ${hash(js)} 'wasm-unsafe-eval'`,
  `style-src ${hash(style)} data:`,
  'connect-src data:',
  'img-src data: blob:',
  "base-uri 'none'",
  "form-action 'none'",
].join('; ');

const html = `<!doctype html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta http-equiv="Content-Security-Policy" content="${csp}">
<meta name="viewport" content="width=device-width, initial-scale=1">
<meta name="generator" content="ScrewBender playground (offline figure)">
<title>${SLOTS.title}</title>
<style>${style}</style>
</head>
<body>
${SLOTS.figure}
${SLOTS.bunny}
<script type="application/octet-stream" id="screwbender-wasm">${packed}</script>
<script type="application/octet-stream" id="screwbender-wasm-gl">${packedGl}</script>
<script type="module">${js}</script>
</body>
</html>
`;
fs.mkdirSync(OUT, { recursive: true });
fs.writeFileSync(path.join(OUT, 'figure.html'), html);
fs.writeFileSync(path.join(OUT, 'figure.json'), `${JSON.stringify({ bytes: Buffer.byteLength(html), wasmBytes: wasm.length + wasmGl.length, scriptBytes: js.length })}\n`);
console.log(`offline figure template: ${(Buffer.byteLength(html) / 1e6).toFixed(2)} MB (wasm ${((wasm.length + wasmGl.length) / 1e6).toFixed(2)} MB → ${((packed.length + packedGl.length) / 1e6).toFixed(2)} MB base64 of gzip, script ${(js.length / 1e3).toFixed(0)} KB)`);
