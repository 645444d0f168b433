// e2e-backends: webgpu (what the WebGPU page fetches, and when)
// End-to-end: what the first visit leaves for later. The first frame is drawn from the renderer
// module alone (on WebGPU the figure's WebGPU module, on WebGL2 the WebGL2 one), and until the page
// is idle nothing else comes: no analysis module, no view, no uPlot, no lesson player, no KaTeX,
// no Share dialog. Opening the dock fetches the analysis, with "loading…" in the dock meanwhile;
// the Lessons button fetches the player and KaTeX. Where a fetch fails, a message names what could
// not load, the editor keeps working (edits, undo), and the next try loads it.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { BACKEND, DESKTOP, EXPECTED_BACKEND, startPlayground, waitFrames } from './lib.mjs';

let play;

before(async () => {
  play = await startPlayground();
});

after(async () => {
  await play?.close();
});

/** A first visit (a fresh context: no autosave); `requests` lists the paths it fetched, in order. */
async function open(route) {
  const context = await play.browser.newContext({ viewport: DESKTOP });
  const page = await context.newPage();
  const requests = [];
  const problems = [];
  page.on('pageerror', (e) => problems.push(e.message));
  page.on('request', (r) => requests.push(new URL(r.url()).pathname));
  if (route) await route(page);
  await page.goto(`${play.url}${BACKEND === 'webgl2' ? '?backend=webgl2' : ''}`);
  await page.evaluate(() => window.screwbender.ready);
  await waitFrames(page, 2);
  // Idle: what a visit fetches later than its first frame counts too.
  await page.waitForLoadState('networkidle');
  return { page, requests, problems };
}

const LATER = [
  /^\/pkg-full\//,
  /^\/js\/dock\/(?!index\.js)/,
  /^\/js\/editor\/dock\.js/,
  /uPlot\.(esm\.js|min\.css)$/,
  // The lesson player (all of js/lessons/ but progress.js, which says whether the tour is due), its
  // stylesheet and KaTeX; the Share dialog.
  /^\/js\/lessons\/(?!progress\.js)/,
  /^\/css\/lessons\.css$/,
  /katex/,
  /^\/js\/editor\/share-dialog\.js/,
];

test(`${BACKEND}: the first frame needs the renderer module only; the dock fetches the rest`, async () => {
  const { page, requests, problems } = await open();
  assert.equal(await page.evaluate(() => window.screwbender.backend()), EXPECTED_BACKEND);
  const mine = BACKEND === 'webgl2' ? '/pkg-gl/screwbender_bg.wasm' : '/pkg-webgpu/screwbender_bg.wasm';
  const other = BACKEND === 'webgl2' ? '/pkg-webgpu/' : '/pkg-gl/';
  assert.ok(requests.includes(mine), `${mine} not fetched`);
  assert.ok(!requests.some((p) => p.startsWith(other)), `${other} fetched: ${requests.join(' ')}`);
  for (const re of LATER) assert.ok(!requests.some((p) => re.test(p)), `${re} fetched before the dock was opened`);
  // The dock: one view opened fetches the views and the analysis module; a view works.
  await page.locator('#t-dock').click();
  await page.waitForSelector('#dock .tabs button[data-view="plots"].on');
  assert.ok(requests.some((p) => p.startsWith('/pkg-full/')), 'the analysis module was not fetched');
  const metrics = await page.evaluate(async () => {
    await window.screwbender.openView('metrics');
    window.screwbender.flushViews();
    return document.querySelector('#dock .view-metrics').textContent;
  });
  assert.match(metrics, /\d/);
  // The Lessons button fetches the player, its stylesheet and KaTeX, and shows the menu.
  await page.locator('#t-lessons').click();
  await page.locator('#lessons-menu').waitFor({ state: 'visible' });
  for (const p of ['/js/lessons/player.js', '/css/lessons.css', '/vendor/katex.min.mjs']) assert.ok(requests.includes(p), `${p} not fetched for the Lessons menu`);
  assert.equal(await page.locator('#t-lessons').count(), 1, 'one Lessons button');
  assert.deepEqual(await page.evaluate(() => window.screwbender.errors()), []);
  assert.deepEqual(problems, []);
  await page.context().close();
});

test(`${BACKEND}: the dock shows "loading…" while its modules come`, async () => {
  let release;
  const held = new Promise((r) => (release = r));
  const { page } = await open((p) =>
    p.route('**/pkg-full/screwbender_bg.wasm', async (route) => {
      await held;
      await route.continue();
    }),
  );
  await page.locator('#t-dock').click();
  const note = page.locator('#dock .loading');
  await note.waitFor({ state: 'visible' });
  assert.match(await note.textContent(), /Loading the analysis views/);
  assert.ok(await page.locator('#dock').isVisible());
  release();
  await page.waitForSelector('#dock .tabs button[data-view="plots"].on');
  assert.equal(await note.count(), 0);
  await page.context().close();
});

test(`${BACKEND}: a module that cannot load is named, and the editor works on`, async () => {
  let blocked = true;
  const { page, problems } = await open(async (p) => {
    await p.route('**/pkg-full/**', (route) => (blocked ? route.abort('connectionrefused') : route.continue()));
    await p.route('**/js/lessons/player.js*', (route) => (blocked ? route.abort('connectionrefused') : route.continue()));
  });
  // The lessons could not load: a message, no menu, the page as it was.
  await page.locator('#t-lessons').click();
  await page.waitForFunction(() => window.screwbender.errors().some((e) => /Lessons unavailable/.test(e)));
  assert.equal(await page.evaluate(() => window.screwbender.lessons), null);
  assert.equal(await page.locator('#lessons-menu').count(), 0);
  // The dock could not load: its message names the analysis functions; the dock stays closed.
  await page.locator('#t-dock').click();
  await page.waitForFunction(() => window.screwbender.errors().some((e) => /Could not load the analysis functions/.test(e)));
  const banner = await page.locator('#banner .msg').textContent();
  assert.match(banner, /Could not load the analysis functions .*the editor works on/i);
  assert.ok(!(await page.locator('#dock').isVisible()), 'the dock stayed open');
  assert.equal(await page.evaluate(() => window.screwbender.app.view.dock), '');
  // Edits and undo as ever.
  const before = await page.evaluate(() => Array.from(window.screwbender.poses()));
  await page.evaluate(() => {
    const { app } = window.screwbender;
    app.select(1);
    app.parts.session.edit(() => app.motion.setPose(1, { origin: [0.5, 0.25, 0], rotation: [1, 0, 0, 0] }));
  });
  const moved = await page.evaluate(() => Array.from(window.screwbender.poses()));
  assert.deepEqual(moved.slice(7, 10), [0.5, 0.25, 0]);
  await page.locator('#view').focus();
  await page.keyboard.press('Control+z');
  await page.waitForFunction((b) => JSON.stringify(Array.from(window.screwbender.poses())) === b, JSON.stringify(before));
  await waitFrames(page, 2);
  // The fetches work again: the next tries open the dock and the Lessons menu.
  blocked = false;
  await page.locator('#t-dock').click();
  await page.waitForSelector('#dock .tabs button[data-view="plots"].on');
  await page.locator('#t-lessons').click();
  await page.locator('#lessons-menu').waitFor({ state: 'visible' });
  assert.deepEqual(problems, []);
  await page.context().close();
});
