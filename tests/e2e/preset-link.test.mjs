// e2e-backends: webgpu (the address and the state, the same on either backend: once)
// End-to-end: `index.html?preset=<id>` opens that preset as a pick in the preset chooser does;
// over an autosaved session it is one undo step; an unknown id gives a notice and the default.
// Each case opens the link in a fresh browser context (no autosave) unless it says otherwise.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { BACKEND, DESKTOP, openPage, startPlayground, waitFrames } from './lib.mjs';

let play;

before(async () => {
  play = await startPlayground();
});

after(async () => {
  await play?.close();
});

/** Opens the playground at `query` in a new context (or `context`); returns {page, problems, context}. */
async function open(query, context = null) {
  const ctx = context ?? (await play.browser.newContext({ viewport: DESKTOP }));
  const { page, problems } = await openPage(ctx, play.url, BACKEND, { path: query });
  return { page, problems, context: ctx };
}

/** What the page shows of its preset: the state, the panel's button, the chooser's current card. */
async function presetShown(page) {
  const state = await page.evaluate(() => ({
    scene: window.screwbender.app.view.scene,
    object: window.screwbender.app.view.object,
    name: window.screwbender.app.motion.name,
    search: location.search,
  }));
  const button = page.locator('#panel button', { hasText: 'Preset:' });
  const label = (await button.textContent()).trim();
  await button.click();
  const current = await page.evaluate(() => document.querySelector('#presets .preset.on')?.dataset.id ?? null);
  await page.keyboard.press('Escape');
  return { ...state, label, current };
}

test(`${BACKEND}: ?preset=bunny6 opens the bunny preset with the Stanford bunny drawn`, async () => {
  const { page, problems, context } = await open('?preset=bunny6');
  try {
    const shown = await presetShown(page);
    assert.deepEqual(shown, {
      scene: 'bunny6',
      object: 'scene',
      name: 'bunny6',
      // The parameter has done its work: a reload keeps the edits made since.
      search: '',
      label: 'Preset: Inconsistent rotations …',
      current: 'bunny6',
    });
    assert.equal(await page.locator('#scene-title').textContent(), 'Inconsistent rotations');
    // The poses are the preset's, as Motion.fromPreset gives them.
    const same = await page.evaluate(() => {
      const m = window.screwbender.app.wasm.Motion.fromPreset('bunny6');
      const want = [...m.poses()];
      m.free();
      const got = [...window.screwbender.poses()];
      return got.length === want.length && got.every((x, i) => x === want[i]);
    });
    assert.ok(same, 'the preset\'s control poses');
    // The scanned bunny replaces the wedge once its file is in.
    await page.waitForFunction(() => window.screwbender.app.viewer.drawing.bunnyTriangles > 1000, null, { timeout: 60000 });
    await waitFrames(page, 1);
    assert.deepEqual(await page.evaluate(() => window.screwbender.errors()), []);
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});

test(`${BACKEND}: over an autosaved session, ?preset= is one undo step`, async () => {
  const first = await open('');
  try {
    await first.page.evaluate(() => window.screwbender.app.run('loadPreset', 'pendulum'));
    await first.page.evaluate(() => window.screwbender.app.parts.session.autosave());
    await first.page.close();
    const { page, problems } = await open('?preset=cylinder5', first.context);
    assert.equal(await page.evaluate(() => window.screwbender.app.view.scene), 'cylinder5');
    await page.locator('#view').focus();
    await page.keyboard.press('Control+z');
    await page.waitForFunction(() => window.screwbender.app.view.scene === 'pendulum');
    assert.deepEqual(problems, []);
  } finally {
    await first.context.close();
  }
});

test(`${BACKEND}: an unknown ?preset= says so in the notice area and opens the default preset`, async () => {
  const { page, problems, context } = await open('?preset=no_such_preset&tour=0');
  try {
    const banner = page.locator('#banner');
    await banner.waitFor({ state: 'visible' });
    const text = await banner.locator('.msg').textContent();
    assert.match(text, /preset "no_such_preset", which does not exist/);
    assert.match(text, /showing L cycle, rotated poses/);
    assert.ok(await page.evaluate(() => window.screwbender.errors().some((e) => e.includes('no_such_preset'))));
    const shown = await presetShown(page);
    assert.equal(shown.scene, 'l_cycle_rotated');
    assert.equal(shown.current, 'l_cycle_rotated');
    // Only the preset parameter leaves the address.
    assert.equal(shown.search, '?tour=0');
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});
