// e2e-backends: webgpu webgl2 (the mesh is uploaded and drawn by each renderer)
// The paper's bunny example (preset bunny6) shows the Stanford bunny (crates/screwbender/assets/
// bunny.obj, from the npm package `bunny`; its bunny.NOTICE) instead of the wedge that stood in:
// the committed mesh is the package's, the page serves that same file (the build copies it into
// www/vendor/), and the page uploads it for the preset's object. Screenshots go to
// artifacts/e2e-<backend>/ at 1280×800 and 390×844.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { createRequire } from 'node:module';
import { BACKEND, DESKTOP, ROOT, canvasStats, playgroundPage, waitFrames } from './lib.mjs';

const ARTIFACTS = path.join(ROOT, `artifacts/e2e-${BACKEND}`);
let play;
let page;
let problems;

before(async () => {
  fs.mkdirSync(ARTIFACTS, { recursive: true });
  ({ play, page, problems } = await playgroundPage());
});

after(async () => {
  await play?.close();
});

const sb = (f, arg) => page.evaluate(f, arg);

test('the committed OBJ is the npm package’s Stanford bunny, z up, and the page serves it', async () => {
  const bunny = createRequire(import.meta.url)(path.join(ROOT, 'node_modules/bunny'));
  const text = fs.readFileSync(path.join(ROOT, 'crates/screwbender/assets/bunny.obj'), 'utf8');
  assert.equal(await sb(() => fetch('vendor/bunny.obj').then((r) => r.text())), text, 'the served mesh is the crate’s');
  const v = text.split('\n').filter((l) => l.startsWith('v ')).map((l) => l.slice(2).split(' ').map(Number));
  const f = text.split('\n').filter((l) => l.startsWith('f ')).map((l) => l.slice(2).split(' ').map(Number));
  assert.equal(v.length, bunny.positions.length);
  assert.equal(f.length, bunny.cells.length);
  bunny.positions.forEach(([x, y, z], i) => assert.deepEqual(v[i], [x, -z || 0, y].map((c) => c + 0), `v ${i}`));
  bunny.cells.forEach((c, i) => assert.deepEqual(f[i], c.map((k) => k + 1), `f ${i}`));
  assert.ok(fs.readFileSync(path.join(ROOT, 'crates/screwbender/assets/bunny.NOTICE'), 'utf8').includes('Stanford 3D Scanning Repository'));
});

test(`${BACKEND}: the bunny preset's object is the Stanford bunny mesh`, async () => {
  await sb(() => window.screwbender.app.run('loadPreset', 'l_cycle_rotated'));
  await waitFrames(page, 2);
  const before = await canvasStats(page);
  await sb(() => window.screwbender.app.run('loadPreset', 'bunny6'));
  // The mesh is fetched once, then uploaded for the strobe, control and animated copies.
  await page.waitForFunction(() => window.screwbender.app.viewer.drawing.bunnyTriangles > 0, null, { timeout: 10000 });
  const triangles = await sb(() => window.screwbender.app.viewer.drawing.bunnyTriangles);
  assert.equal(triangles, 3674);
  await waitFrames(page, 3);
  const after = await canvasStats(page);
  assert.notDeepEqual(after, before);
  await page.screenshot({ path: path.join(ARTIFACTS, 'bunny6.png') });
  // Another preset and back: the wedge is not shown in between, the bunny comes back at once.
  await sb(() => window.screwbender.app.run('loadPreset', 'circle4'));
  await sb(() => window.screwbender.app.run('loadPreset', 'bunny6'));
  assert.equal(await sb(() => window.screwbender.app.viewer.drawing.bunnyTriangles), 3674);
  await page.setViewportSize({ width: 390, height: 844 });
  await waitFrames(page, 3);
  await page.screenshot({ path: path.join(ARTIFACTS, 'bunny6-phone.png') });
  await page.setViewportSize(DESKTOP);
  assert.deepEqual(problems, []);
  assert.deepEqual(await sb(() => window.screwbender.errors()), []);
});
