#!/usr/bin/env node
// The figure's weight beside <model-viewer>'s, measured the same way in one run: two pages, each
// showing one motion from a file, opened in headless Chromium (the e2e tests' browser and flags),
// each in a fresh context (a first visit), and every file each downloaded until it was idle
// counted at its gzip -9 size (scripts/downloads.mjs).
//
//   our page:          the npm package's viewer entry (PKG/viewer.js) and
//                      <screw-bender src="motion.json">, read-only;
//   <model-viewer>'s:  npm `@google/model-viewer`'s one-file build (dist/model-viewer.min.js,
//                      three.js inside, the file its documentation has a page load) and
//                      <model-viewer src="motion.glb" autoplay>;
// the same motion in both: preset l_cycle_rotated, its document as JSON for ours, and exported by
// the package's own `screwbender/full` module as glTF binary (its object's mesh and the motion
// as a glTF animation, which <model-viewer> plays) for <model-viewer>.
//
// Prints each page's files and total and the ratio of ours to <model-viewer>'s, and fails when
// ours is the larger (or when a page fetched something that failed, or from another origin: then
// the comparison would not be of what a visitor gets).
//
//   node scripts/figure-vs-model-viewer.mjs [PKG]   # PKG: the built npm package (default pkg/)
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { launch, serveDir } from '../tests/e2e/lib.mjs';
import { fileSizes, watchRequests } from './downloads.mjs';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const PRESET = 'l_cycle_rotated';
const pkg = path.resolve(process.argv[2] ?? path.join(ROOT, 'pkg'));
const modelViewer = path.join(ROOT, 'node_modules/@google/model-viewer');

/** The two pages and their files in a fresh folder; returns its path. */
async function makeSite() {
  for (const f of ['viewer.js', 'full/screwbender.js', 'full/screwbender_bg.wasm']) {
    if (!fs.existsSync(path.join(pkg, f))) throw new Error(`${pkg}/${f} is missing: build the package first (scripts/build-pkg.sh)`);
  }
  const mvBuild = path.join(modelViewer, 'dist/model-viewer.min.js');
  if (!fs.existsSync(mvBuild)) throw new Error(`${mvBuild} is missing: run npm ci (it is a devDependency)`);
  const site = fs.mkdtempSync(path.join(os.tmpdir(), 'figure-vs-model-viewer-'));
  // The package as a site serves it, beside the pages.
  fs.symlinkSync(pkg, path.join(site, 'pkg'));
  fs.copyFileSync(mvBuild, path.join(site, 'model-viewer.min.js'));
  const full = await import(path.join(pkg, 'full/screwbender.js'));
  full.initSync({ module: fs.readFileSync(path.join(pkg, 'full/screwbender_bg.wasm')) });
  const motion = full.Motion.fromPreset(PRESET);
  fs.writeFileSync(path.join(site, 'motion.json'), motion.toJson());
  const glb = motion.exportFile({ format: 'glb' });
  fs.writeFileSync(path.join(site, 'motion.glb'), glb.data);
  motion.free();
  const page = (title, body) =>
    `<!doctype html>\n<html lang="en"><head><meta charset="utf-8"><title>${title}</title></head>\n<body style="margin:0">\n${body}\n</body></html>\n`;
  fs.writeFileSync(
    path.join(site, 'screw-bender.html'),
    page('<screw-bender>', '<script type="module" src="pkg/viewer.js"></script>\n<screw-bender src="motion.json" autoplay alt="A bar along an L-shaped cycle of poses" style="display:block;width:640px;height:400px"></screw-bender>'),
  );
  fs.writeFileSync(
    path.join(site, 'model-viewer.html'),
    page('<model-viewer>', '<script type="module" src="model-viewer.min.js"></script>\n<model-viewer src="motion.glb" autoplay alt="A bar along an L-shaped cycle of poses" style="display:block;width:640px;height:400px"></model-viewer>'),
  );
  return site;
}

/** Opens `file` of the site at `url` and waits until `shown` resolves in it and it is idle. */
async function measure(browser, url, site, file, shown) {
  const context = await browser.newContext({ viewport: { width: 800, height: 500 } });
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  const requests = watchRequests(page);
  await page.goto(`${url}${file}`);
  await page.evaluate(shown);
  const { done, open, failed } = await requests.untilIdle();
  await context.close();
  // A request the page cancelled itself (net::ERR_ABORTED) is no failure of the site: on a busy
  // machine <model-viewer>'s request for its model is sometimes reported so although the model
  // loaded. The page asked for that file, so it counts as downloaded (once, if another request
  // for it finished); any other failure is a broken page.
  const cancelled = failed.filter((f) => f.error === 'net::ERR_ABORTED' && !done.includes(f.url)).map((f) => f.url);
  const broken = failed.filter((f) => f.error !== 'net::ERR_ABORTED');
  const origin = new URL(url).origin;
  const fetched = [...done, ...open, ...cancelled];
  const elsewhere = fetched.filter((u) => !u.startsWith(origin) && !/^(data|blob):/.test(u));
  const problems = [...errors.map((e) => `page error: ${e}`), ...broken.map((f) => `failed: ${f.url} (${f.error})`), ...elsewhere.map((u) => `another origin: ${u}`)];
  if (problems.length) throw new Error(`${file}: ${problems.join('; ')}`);
  for (const u of cancelled) console.log(`${file}: ${u} was cancelled by the page (net::ERR_ABORTED); counted as downloaded`);
  const sizeOf = fileSizes(site);
  const files = fetched.filter((u) => u.startsWith(origin)).map(sizeOf);
  return { files, total: files.reduce((s, f) => s + f.gzip, 0) };
}

async function main() {
  const site = await makeSite();
  const server = await serveDir(site);
  const browser = await launch('webgpu', { softwarePage: false });
  let ours;
  let theirs;
  try {
    // Ours: its `ready` resolves once the motion is loaded and the renderer has started.
    ours = await measure(browser, server.url, site, 'screw-bender.html', async () => {
      await customElements.whenDefined('screw-bender');
      await document.querySelector('screw-bender').ready;
    });
    // <model-viewer>: `loaded` once the model is in, `modelIsVisible` once it is drawn.
    theirs = await measure(browser, server.url, site, 'model-viewer.html', async () => {
      await customElements.whenDefined('model-viewer');
      const mv = document.querySelector('model-viewer');
      if (!mv.loaded) await new Promise((resolve, reject) => {
        mv.addEventListener('load', resolve, { once: true });
        mv.addEventListener('error', (e) => reject(new Error(`model-viewer: ${e.detail?.type ?? 'error'}`)), { once: true });
      });
    });
  } finally {
    await browser.close();
    server.stop();
    fs.rmSync(site, { recursive: true, force: true });
  }
  const version = JSON.parse(fs.readFileSync(path.join(modelViewer, 'package.json'), 'utf8')).version;
  for (const [name, m] of [['<screw-bender> (read-only, WebGPU)', ours], [`<model-viewer> ${version}`, theirs]]) {
    console.log(`${name}: ${m.total} bytes gzip in ${m.files.length} files`);
    for (const f of [...m.files].sort((a, b) => b.gzip - a.gzip)) console.log(`${String(f.gzip).padStart(10)} ${String(f.raw).padStart(10)}  ${f.path}`);
  }
  const ratio = ours.total / theirs.total;
  console.log(`figure / model-viewer: ${ours.total} / ${theirs.total} = ${ratio.toFixed(3)}`);
  if (ratio > 1) {
    console.error(`the read-only figure downloads more than <model-viewer> showing the same motion (${ratio.toFixed(3)} times as much)`);
    process.exit(1);
  }
}

main().catch((e) => {
  console.error(e.message);
  process.exit(1);
});
