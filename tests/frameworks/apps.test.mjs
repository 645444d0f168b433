// The example apps of examples/ (React 19, Vue 3, Svelte 5), each built by `vite build` against
// the npm package's tarball, served on 127.0.0.1 and driven in headless Chromium with real
// mouse and keyboard: the app's state reaches the figure (attributes and the `document`
// property), the figure's events reach the app's state, figures added and removed (and the one
// made by mount() in a component, unmounted and mounted again) leave exactly the live figures,
// and React's StrictMode double mount (the development build) leaves one figure.
//
//   FRAMEWORK_APPS=DIR E2E_BACKEND=webgpu node --test tests/frameworks/apps.test.mjs
//
// DIR holds react/, vue/, svelte/ with each a dist/ (and react/dist-dev/, built with
// NODE_ENV=development): scripts/test.d/frameworks.sh makes them.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { BACKEND, EXPECTED_BACKEND, launch, serveDir, shotPath } from '../e2e/lib.mjs';

const APPS = process.env.FRAMEWORK_APPS;
if (!APPS) throw new Error('FRAMEWORK_APPS (a folder with react/, vue/, svelte/ built) is not set');
const BUILDS = [
  { name: 'react', dist: 'react/dist' },
  { name: 'react-strictmode-dev', dist: 'react/dist-dev', strict: true },
  { name: 'vue', dist: 'vue/dist' },
  { name: 'svelte', dist: 'svelte/dist' },
];

let browser;
before(async () => {
  browser = await launch(BACKEND);
});
after(async () => {
  await browser?.close();
});

/**
 * Opens a build in a fresh context. Every ResizeObserver and IntersectionObserver is counted
 * while live (made and not disconnected): a started figure holds one of each, a destroyed one none.
 */
async function openApp(build, viewport = { width: 1280, height: 800 }) {
  const dir = path.join(APPS, build.dist);
  assert.ok(fs.existsSync(path.join(dir, 'index.html')), `${dir} is built`);
  const server = await serveDir(dir);
  const context = await browser.newContext({ viewport });
  await context.addInitScript(() => {
    // Canvases made: one per figure made (mount() or the element), started or not.
    window.__canvases = 0;
    const create = Document.prototype.createElement;
    Document.prototype.createElement = function (tag, ...rest) {
      if (String(tag).toLowerCase() === 'canvas') window.__canvases++;
      return create.call(this, tag, ...rest);
    };
    window.__live = 0;
    for (const name of ['ResizeObserver', 'IntersectionObserver']) {
      const Base = window[name];
      window[name] = class extends Base {
        constructor(...args) {
          super(...args);
          this.__on = true;
          window.__live++;
        }
        disconnect() {
          if (this.__on) window.__live--;
          this.__on = false;
          super.disconnect();
        }
      };
    }
  });
  const page = await context.newPage();
  const problems = [];
  // Warnings too (React's development build warns of props it does not understand), but not
  // Chromium's own when WebGPU has no adapter (the WebGL2 runs).
  page.on('console', (m) => {
    if (m.type() === 'error' || (m.type() === 'warning' && m.text() !== 'No available adapters.')) problems.push(`console ${m.type()}: ${m.text()}`);
  });
  page.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
  await page.goto(server.url);
  await page.waitForFunction(() => customElements.get('screw-bender') && document.querySelector('[data-testid=figure]'));
  await figureReady(page);
  return {
    page,
    problems,
    async close() {
      await context.close();
      server.stop();
    },
  };
}

/** Waits until the app's main figure (the element now in the page) shows a motion. */
async function figureReady(page) {
  await page.waitForFunction(async () => {
    const el = document.querySelector('[data-testid=figure]');
    await el.ready;
    return el.motion !== null && el.backend !== null;
  }, null, { timeout: 60000 });
}

const text = (page, id) => page.locator(`[data-testid=${id}]`).first().textContent();
const figure = (page, f) => page.evaluate(f);

/** Figures in the page: <screw-bender> elements and hosts of mount() figures. */
const figureCount = (page) => page.evaluate(() => document.querySelectorAll('screw-bender, .mounted').length);

/** Waits until the live observers are those of `figures` started figures (and stay so a while). */
async function expectLive(page, figures, label) {
  try {
    await page.waitForFunction((n) => window.__live === 2 * n, figures, { timeout: 60000 });
  } catch {
    assert.fail(`${label}: ${await page.evaluate(() => window.__live)} live observers, expected ${2 * figures} (${figures} figures)`);
  }
  await page.waitForTimeout(200);
  assert.equal(await page.evaluate(() => window.__live), 2 * figures, `${label}: live observers stay at ${2 * figures}`);
}

for (const build of BUILDS) {
  test(`${build.name}: the app's state reaches the figure (attributes and the document property)`, async () => {
    const app = await openApp(build);
    const { page } = app;
    try {
      assert.equal(await figure(page, () => document.querySelector('[data-testid=figure]').backend), EXPECTED_BACKEND);
      const levels = () => figure(page, () => document.querySelector('[data-testid=figure]').motion?.options().levels);
      assert.equal(await levels(), 3, 'levels={3} reached the figure');
      await page.click('[data-testid=levels-up]');
      await page.waitForFunction(() => document.querySelector('[data-testid=figure]').motion?.options().levels === 4);
      const posesOf = () => figure(page, () => Array.from(document.querySelector('[data-testid=figure]').motion.poses()));
      const lcycle = await posesOf();
      await page.selectOption('[data-testid=preset]', 'circle4');
      await page.waitForFunction(() => document.querySelector('[data-testid=figure]').getAttribute('scene') === 'circle4');
      await page.waitForFunction((n) => document.querySelector('[data-testid=figure]').motion?.poses().length !== n, lcycle.length);
      assert.equal(await levels(), 4, 'the levels stay');
      // An object-valued prop goes to the element's `document` property (not an attribute).
      await page.click('[data-testid=document]');
      await page.waitForFunction(() => document.querySelector('[data-testid=figure]').motion?.poseCount === 2, null, { timeout: 30000 });
      await figureReady(page);
      const doc = await figure(page, () => {
        const el = document.querySelector('[data-testid=figure]');
        return { attribute: el.getAttribute('document'), poses: Array.from(el.motion.poses()), levels: el.motion.options().levels, msg: el.shadowRoot.querySelector('.msg').hidden };
      });
      assert.equal(doc.attribute, null, 'document is set as a property');
      assert.deepEqual(doc.poses.slice(7, 10), [3, 1, 1], 'the second pose of the document');
      assert.equal(doc.levels, 4);
      assert.equal(doc.msg, true, 'no message in the figure');
      await page.selectOption('[data-testid=preset]', 'l_cycle_rotated');
      await page.waitForFunction((n) => document.querySelector('[data-testid=figure]').motion?.poses().length === n, lcycle.length, { timeout: 30000 });
      assert.deepEqual(await posesOf(), lcycle, 'back to the preset');
      assert.equal(await figureCount(page), 2, 'one main figure and the mount() one');
      await page.screenshot({ path: shotPath(`frameworks/${build.name}.png`) });
      assert.deepEqual(app.problems, []);
    } finally {
      await app.close();
    }
  });

  test(`${build.name}: the figure's events reach the app's state (time, select, change; play and pause where the element has them)`, async () => {
    const app = await openApp(build);
    const { page } = app;
    try {
      await page.click('[data-testid=seek]');
      await page.waitForFunction(() => document.querySelector('[data-testid=time]').textContent === '1.00');
      assert.ok(Number(await text(page, 'time-events')) >= 1);
      // The figure's own play button (in its shadow tree), clicked with the mouse.
      const play = page.locator('[data-testid=figure] .play');
      await play.click();
      const t0 = await text(page, 'time');
      await page.waitForFunction((t) => document.querySelector('[data-testid=time]').textContent !== t, t0, { timeout: 20000 });
      const media = await figure(page, () => 'paused' in document.querySelector('[data-testid=figure]'));
      if (media) await page.waitForFunction(() => document.querySelector('[data-testid=playing]').textContent === 'true');
      await play.click();
      if (media) await page.waitForFunction(() => document.querySelector('[data-testid=playing]').textContent === 'false');
      await page.waitForTimeout(300);
      const stopped = await text(page, 'time');
      await page.waitForTimeout(500);
      assert.equal(await text(page, 'time'), stopped, 'the time stands once paused');
      // A real key in the focused figure selects pose 0.
      await page.locator('[data-testid=figure] canvas').focus();
      await page.keyboard.press('ArrowRight');
      await page.waitForFunction(() => document.querySelector('[data-testid=selected]').textContent === '0');
      // A real drag of pose 1: select and change reach the app.
      const h = await figure(page, () => {
        const el = document.querySelector('[data-testid=figure]');
        el.scrollIntoView({ block: 'center' });
        return el.viewer.screenOfPose(1);
      });
      await page.waitForTimeout(100);
      const h2 = await figure(page, () => document.querySelector('[data-testid=figure]').viewer.screenOfPose(1));
      await page.mouse.move(h2.x, h2.y);
      await page.mouse.down();
      for (let k = 1; k <= 8; k++) await page.mouse.move(h2.x + 5 * k, h2.y - 4 * k);
      await page.mouse.up();
      await page.waitForFunction(() => Number(document.querySelector('[data-testid=changes]').textContent) >= 1, null, { timeout: 10000 });
      assert.equal(await text(page, 'moved'), '1', `pose 1 moved (its handle at ${JSON.stringify(h)})`);
      assert.equal(await text(page, 'selected'), '1');
      assert.deepEqual(app.problems, []);
    } finally {
      await app.close();
    }
  });

  test(`${build.name}: figures added and removed, the mount() figure unmounted and mounted again: exactly the live figures, flat heap${build.strict ? ' (StrictMode double mount)' : ''}`, async () => {
    const app = await openApp(build);
    const { page } = app;
    try {
      // The main figure and the mount() one; StrictMode ran the latter's effect twice (a figure
      // made, destroyed and made again), which leaves one.
      await expectLive(page, 2, 'at the start');
      assert.equal(await page.evaluate(() => window.__canvases), build.strict ? 3 : 2, 'figures made at the start');
      const canvases = await figure(page, () => document.querySelector('[data-testid=mounted]').shadowRoot.querySelectorAll('canvas').length);
      assert.equal(canvases, 1, 'one canvas in the mount() figure');
      const cdp = await page.context().newCDPSession(page);
      const heap = async () => {
        await cdp.send('HeapProfiler.collectGarbage');
        return (await cdp.send('Runtime.getHeapUsage')).usedSize;
      };
      const round = async (r) => {
        for (let k = 0; k < 3; k++) await page.click('[data-testid=add]');
        assert.equal(await figureCount(page), 5, `round ${r}: three figures added`);
        await expectLive(page, 5, `round ${r}, added`);
        for (let k = 0; k < 3; k++) await page.click('[data-testid=remove]');
        await page.click('[data-testid=toggle-mounted]');
        assert.equal(await figureCount(page), 1, `round ${r}: removed`);
        await expectLive(page, 1, `round ${r}, removed`);
        await page.click('[data-testid=toggle-mounted]');
        await expectLive(page, 2, `round ${r}, the mount() figure back`);
      };
      await round(0);
      await round(1);
      const heap1 = await heap();
      for (let r = 2; r < 6; r++) await round(r);
      const heap2 = await heap();
      // Twelve leaked figures (their viewers, models and motions) would add far more.
      assert.ok(heap2 < heap1 * 1.3 + 1e6, `JS heap ${heap1} -> ${heap2}`);
      assert.deepEqual(app.problems, []);
    } finally {
      await app.close();
    }
  });
}

test('the phone layout of each app (390×844): figures fit the width', async () => {
  for (const build of BUILDS.filter((b) => !b.strict)) {
    const app = await openApp(build, { width: 390, height: 844 });
    try {
      const w = await app.page.evaluate(() => ({ fig: document.querySelector('[data-testid=figure]').getBoundingClientRect().width, page: document.documentElement.scrollWidth }));
      assert.ok(w.fig <= 390 && w.page <= 390, `${build.name}: figure ${w.fig} px, page ${w.page} px wide`);
      await app.page.screenshot({ path: shotPath(`frameworks/${build.name}-phone.png`) });
      assert.deepEqual(app.problems, []);
    } finally {
      await app.close();
    }
  }
});
