// e2e-backends: webgpu (the first visit's light WebGPU module)
// End-to-end: a first visit. A short hint says how to start and stays dismissed; the preset
// chooser lists every preset by a human name with the paper's figure as a subtitle and its
// one-line description, none cut off; WebGPU without an adapter is told as neutral information.
// Nothing written is lost: two tabs each keep their work, offered again after both closed; in a
// sandboxed frame without storage the page says once, in words, that work is not kept.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { BACKEND, DESKTOP, ROOT, openPage, startPlayground, waitFrames } from './lib.mjs';

const ARTIFACTS = path.join(ROOT, 'artifacts', `e2e-${BACKEND}`);
let play;

before(async () => {
  fs.mkdirSync(ARTIFACTS, { recursive: true });
  play = await startPlayground();
});

after(async () => {
  await play?.close();
});

test(`${BACKEND}: the first-visit hint shows once and stays dismissed`, async () => {
  const { page, problems } = await openPage(play.context, play.url, BACKEND);
  const hint = page.locator('#hint');
  assert.ok(await hint.isVisible(), 'no hint on a first visit');
  assert.match(await hint.textContent(), /white handle/);
  await hint.locator('.close').click();
  assert.ok(!(await hint.isVisible()));
  await page.reload();
  await page.evaluate(() => window.screwbender.ready);
  assert.ok(!(await hint.isVisible()), 'the dismissed hint came back');
  assert.deepEqual(problems, []);
  await page.close();
});

test(`${BACKEND}: the preset chooser: human names, figure subtitles, descriptions, nothing cut off`, async () => {
  const { page, problems } = await openPage(play.context, play.url, BACKEND);
  const opener = page.locator('#panel button', { hasText: 'Preset:' });
  await opener.click();
  const dlg = page.locator('#presets');
  assert.ok(await dlg.isVisible());
  const scenes = await page.evaluate(() => window.screwbender.app.scenes.map((s) => ({ id: s.id, label: s.label, figure: s.figure, description: s.description })));
  const items = await page.evaluate(() =>
    [...document.querySelectorAll('#presets .preset')].map((b) => {
      const part = (c) => b.querySelector(c);
      // Cut off: text wider than its box, or clipped by an ellipsis.
      const clipped = [...b.querySelectorAll('span')].some((s) => s.scrollWidth > s.clientWidth + 1);
      return { id: b.dataset.id, name: part('.name').textContent, sub: part('.sub').textContent, desc: part('.desc').textContent, clipped };
    }),
  );
  assert.equal(items.length, scenes.length);
  for (const [k, s] of scenes.entries()) {
    const it = items[k];
    assert.equal(it.id, s.id);
    assert.ok(!it.name.includes('_') && !/^[A-C]\d/.test(it.name), `${s.id}: "${it.name}" is no human name`);
    assert.equal(it.sub, `${s.label} · ${s.figure}`);
    assert.equal(it.desc, s.description);
    assert.ok(!it.clipped, `${s.id}: text cut off`);
  }
  // The human names are all different.
  assert.equal(new Set(items.map((i) => i.name)).size, items.length);
  await page.screenshot({ path: path.join(ARTIFACTS, 'preset-chooser.png') });
  // Keyboard: the current preset has the focus; Esc closes and gives the focus back.
  assert.equal(await page.evaluate(() => document.activeElement.dataset.id), 'l_cycle_rotated');
  await page.keyboard.press('Escape');
  assert.ok(!(await dlg.isVisible()));
  assert.equal(await page.evaluate(() => document.activeElement.textContent.startsWith('Preset:')), true);
  // A click loads the preset; the title card names it.
  await opener.click();
  await page.locator('#presets .preset[data-id=pendulum]').click();
  await waitFrames(page, 1);
  assert.ok(!(await dlg.isVisible()));
  assert.equal(await page.evaluate(() => window.screwbender.app.view.scene), 'pendulum');
  assert.equal(await page.locator('#scene-title').textContent(), 'Pendulum');
  assert.match(await page.locator('#scene-fig').textContent(), /^A5 · Fig\. 6/);
  assert.deepEqual(problems, []);
  await page.close();
});

test(`${BACKEND}: WebGPU without an adapter is neutral information`, async () => {
  const context = await play.browser.newContext({ viewport: DESKTOP });
  // A browser whose WebGPU finds no adapter (as on many machines without a GPU driver for it).
  await context.addInitScript(() => {
    Object.defineProperty(navigator, 'gpu', {
      configurable: true,
      value: { requestAdapter: async () => null, getPreferredCanvasFormat: () => 'bgra8unorm', wgslLanguageFeatures: new Set() },
    });
  });
  const page = await context.newPage();
  await page.goto(play.url);
  await page.evaluate(() => window.screwbender.ready);
  assert.equal(await page.evaluate(() => window.screwbender.backend()), 'WebGL2');
  const banner = page.locator('#banner');
  assert.ok(await banner.isVisible());
  assert.match(await banner.textContent(), /no usable adapter/);
  assert.equal(await banner.getAttribute('class'), 'banner info');
  await context.close();
});

test(`${BACKEND}: the strobe slider is logarithmic; the count field takes exact numbers`, async () => {
  const { page, problems } = await openPage(play.context, play.url, BACKEND);
  const slider = page.locator('#panel .log-slider .lil-slider');
  const box = await slider.boundingBox();
  for (const f of [0.25, 0.5, 0.75]) {
    const x = box.x + f * box.width;
    await page.mouse.click(x, box.y + box.height / 2);
    const got = await page.evaluate(() => window.screwbender.app.view.strobe);
    // lil-gui maps the pointer to [left, right] linearly, then to 10^value; the page sees
    // whole pixels, so the value is within a pixel's worth (a factor 10^(4 / width)).
    const [lo, hi] = [-1, 1].map((d) => 10 ** (4 * ((x + d - box.x) / box.width)));
    assert.ok(got >= Math.floor(lo) && got <= Math.ceil(hi), `at ${f}: strobe ${got}, want ${lo.toFixed(1)}–${hi.toFixed(1)}`);
  }
  // A quarter of the slider spans 1–10: 2 % of it is about 1.2, not 168 as on a linear slider.
  const count = page.locator('#panel .lil-controller', { hasText: 'Strobe count' }).locator('input');
  await count.fill('37');
  await count.press('Enter');
  assert.equal(await page.evaluate(() => window.screwbender.app.view.strobe), 37);
  assert.deepEqual(problems, []);
  await page.close();
});

/** The control poses of `page`, rounded (as JSON, to compare). */
const posesOf = (page) => page.evaluate(() => JSON.stringify(Array.from(window.screwbender.poses(), (v) => Math.round(v * 1e6) / 1e6)));

test(`${BACKEND}: two tabs: the work of each is kept, and offered again after both are closed`, async () => {
  const context = await play.browser.newContext({ viewport: DESKTOP });
  try {
    const a = await openPage(context, play.url, BACKEND);
    await a.page.evaluate(() => window.screwbender.app.run('loadPreset', 'pendulum'));
    const b = await openPage(context, play.url, BACKEND);
    await b.page.evaluate(() => window.screwbender.app.run('loadPreset', 'circle4'));
    const [workA, workB] = [await posesOf(a.page), await posesOf(b.page)];
    assert.notEqual(workA, workB);
    // Tab A closes first, tab B last: B's work is the latest, A's must not be lost.
    // As a browser closes a tab: its unload handlers run (page.close does not wait for them).
    const close = (p) => Promise.all([p.waitForEvent('close'), p.close({ runBeforeUnload: true })]);
    await close(a.page);
    await close(b.page);
    const c = await openPage(context, play.url, BACKEND);
    assert.equal(await posesOf(c.page), workB, 'a new tab starts from the latest work');
    const offer = c.page.locator('#drafts li');
    assert.equal(await offer.count(), 1, 'the other tab\'s work is offered');
    assert.match(await offer.textContent(), /pendulum|poses/i);
    await offer.locator('button', { hasText: 'Open' }).click();
    assert.equal(await posesOf(c.page), workA, 'the offered draft holds tab A\'s work');
    // Opening it is an edit: the work shown before is one Undo away.
    await c.page.evaluate(() => window.screwbender.app.parts.session.undo());
    assert.equal(await posesOf(c.page), workB);
    assert.ok(!(await c.page.locator('#drafts').isVisible()), 'the list closes once its drafts are taken');
    assert.deepEqual([...a.problems, ...b.problems, ...c.problems], []);
  } finally {
    await context.close();
  }
});

test(`${BACKEND}: a sandboxed frame without storage says once, in words, that work is not kept`, async () => {
  const context = await play.browser.newContext({ viewport: DESKTOP });
  try {
    const page = await context.newPage();
    await page.setContent(`<iframe sandbox="allow-scripts" src="${play.url}" style="width:1000px;height:700px;border:0"></iframe>`);
    const frame = await (await page.waitForSelector('iframe')).contentFrame();
    await frame.waitForFunction(() => window.screwbender?.ready);
    await frame.evaluate(() => window.screwbender.ready);
    // Edits autosave: each would have failed before.
    await frame.evaluate(() => {
      const { app } = window.screwbender;
      app.run('loadPreset', 'pendulum');
      app.run('setOption', 'levels', 3);
      app.run('setOption', 'levels', 4);
    });
    const seen = await frame.evaluate(() => ({
      text: document.body.innerText,
      notices: [...document.querySelectorAll('#drafts:not([hidden])')].map((e) => e.textContent),
      errors: window.screwbender.errors(),
    }));
    assert.equal(seen.notices.length, 1, 'one notice');
    assert.match(seen.notices[0], /cannot keep your work/);
    assert.match(seen.notices[0], /Share link/);
    assert.match(seen.notices[0], /Export/);
    assert.doesNotMatch(seen.text, /Failed to read|localStorage|SecurityError/);
    assert.deepEqual(seen.errors.filter((e) => /Failed to read|localStorage|autosave/i.test(e)), []);
    assert.equal(seen.errors.filter((e) => /cannot keep your work/.test(e)).length, 1, 'said once');
  } finally {
    await context.close();
  }
});
