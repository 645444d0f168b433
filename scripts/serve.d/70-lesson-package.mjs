// The playground's files a lesson package holds (run by 70-lesson-package.sh): lists them in
// www/pkg-lesson/files.json for www/js/lessons/package.js, which the page's "Download for an LMS"
// dialog and scripts/lesson-package.mjs both use. Groups (paths relative to www/):
// * page: the page's code (all of www/js: the lesson player reaches most of it, and a list of
//   what one lesson reaches would break silently with the next import), its styles, the
//   first-frame renderer modules (WebGPU, and WebGL2 where WebGPU has no adapter), KaTeX,
//   lil-gui, uPlot, their licences, and the tour (the Lessons menu offers it).
// * analysis: the analysis module, fetched by the analysis views and `metric` checks.
// * bunny: the Stanford bunny's mesh, for the preset that shows it.
// Left out: the video muxer, three.js and reveal.js (the page's video export and the examples),
// the offline figure's template, the npm packages' type files.
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const WWW = path.join(ROOT, 'www');

/** Files under www/`dir` (recursively) whose names match `re`, sorted, relative to www/. */
function walk(dir, re) {
  const out = [];
  for (const e of fs.readdirSync(path.join(WWW, dir), { withFileTypes: true })) {
    const rel = `${dir}/${e.name}`;
    if (e.isDirectory()) out.push(...walk(rel, re));
    else if (re.test(e.name)) out.push(rel);
  }
  return out.sort();
}

/** The wasm-bindgen module of www/`dir`: its glue and its wasm. */
const wasmModule = (dir) => [`${dir}/screwbender.js`, `${dir}/screwbender_bg.wasm`];

const VENDOR = ['LICENSE.md', 'katex.min.mjs', 'katex.LICENSE', 'lil-gui.esm.min.js', 'uPlot.esm.js', 'uPlot.min.css', 'uPlot.LICENSE'].map((f) => `vendor/${f}`);
const groups = {
  page: [...walk('js', /\.js$/), ...walk('css', /\.css$/), ...VENDOR, ...wasmModule('pkg-webgpu'), ...wasmModule('pkg-gl'), 'lessons/tour.json'],
  analysis: wasmModule('pkg-full'),
  bunny: ['vendor/bunny.obj', 'vendor/bunny.NOTICE'],
};
for (const list of Object.values(groups)) {
  for (const f of list) if (!fs.existsSync(path.join(WWW, f))) throw new Error(`70-lesson-package: www/${f} is missing; build the page first (./scripts/serve.sh)`);
}
const cargo = fs.readFileSync(path.join(ROOT, 'Cargo.toml'), 'utf8');
const version = /^version\s*=\s*"([^"]+)"/m.exec(cargo)?.[1] ?? '0.0.0';
fs.mkdirSync(path.join(WWW, 'pkg-lesson'), { recursive: true });
fs.writeFileSync(path.join(WWW, 'pkg-lesson/files.json'), `${JSON.stringify({ version, template: 'index.html', groups }, null, 1)}\n`);
const bytes = (list) => list.reduce((n, f) => n + fs.statSync(path.join(WWW, f)).size, 0);
console.log(`lesson package files: page ${(bytes(groups.page) / 1e6).toFixed(2)} MB, analysis ${(bytes(groups.analysis) / 1e6).toFixed(2)} MB (before compression)`);
