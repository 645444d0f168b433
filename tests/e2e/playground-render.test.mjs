// e2e-backends: webgpu webgl2 (the backend the page starts and reports, and the pixels it draws)
// End-to-end: the playground as drawn on each backend: it starts on the expected backend (WebGL2
// forced with ?backend=webgl2) without console errors and says so, its view is not blank, and
// every preset draws its trajectories and red control poses. Pictures of the view go to
// artifacts/e2e-<backend>/. Editing, which no backend decides, is playground.test.mjs.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { BACKEND, DESKTOP, ROOT, EXPECTED_BACKEND as EXPECTED, canvasStats, playgroundPage, waitFrames } from './lib.mjs';

const ARTIFACTS = path.join(ROOT, 'artifacts', `e2e-${BACKEND}`);

let play;
let page;
let problems;

before(async () => {
  fs.mkdirSync(ARTIFACTS, { recursive: true });
  ({ play, page, problems } = await playgroundPage({ viewport: DESKTOP }));
});

after(async () => {
  await play?.close();
});

const sb = (f, arg) => page.evaluate(f, arg);

/** Shows `preset`, nothing selected, framed whole. */
const show = (preset) =>
  sb((id) => {
    const { app } = window.screwbender;
    app.run('loadPreset', id);
    app.select(-1);
    app.parts.viewpoint.fit();
  }, preset);

test(`${BACKEND}: page loads without console errors and reports the backend`, async () => {
  assert.equal(await sb(() => window.screwbender.backend()), EXPECTED);
  assert.match(await page.locator('#backend').textContent(), new RegExp(EXPECTED));
  assert.deepEqual(problems, []);
  assert.deepEqual(await sb(() => window.screwbender.errors()), []);
});

test(`${BACKEND}: the canvas is not blank`, async () => {
  const s = await canvasStats(page);
  fs.writeFileSync(path.join(ARTIFACTS, 'start.png'), s.png);
  assert.ok(s.nonBackground > 0.05, `only ${(s.nonBackground * 100).toFixed(1)}% of pixels drawn`);
  assert.ok(s.red > 0.002, `red control poses missing (${s.red})`);
  assert.ok(s.colours > 40, `too few colours (${s.colours})`);
});

test(`${BACKEND}: every preset renders (pictures of the view in artifacts/)`, async () => {
  const ids = await sb(() => window.screwbender.app.scenes.map((s) => s.id));
  assert.equal(ids.length, 14); // A1–A11 without A4 (the planar polygons), B1, C1–C3
  for (const id of ids) {
    await show(id);
    await waitFrames(page, 2);
    const s = await canvasStats(page);
    fs.writeFileSync(path.join(ARTIFACTS, `${id}.png`), s.png);
    assert.ok(s.nonBackground > 0.03, `${id}: only ${(s.nonBackground * 100).toFixed(1)}% drawn`);
    assert.ok(s.red > 0.0005, `${id}: no red control poses`);
  }
  assert.deepEqual(problems, []);
});
