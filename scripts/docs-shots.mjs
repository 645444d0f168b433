// Makes the committed pictures of docs/screenshots/ (embedded by README.md, www/README.md and the
// docs) from declared scenes, so that the e2e tests take no picture that nothing checks.
//
//   node scripts/docs-shots.mjs                        # every scene into docs/screenshots/
//   node scripts/docs-shots.mjs analysis-1280 course-320
//   node scripts/docs-shots.mjs --out /tmp/shots       # elsewhere, to compare before committing
//   node scripts/docs-shots.mjs --backend webgl2       # drawn through WebGL2 (default WebGPU)
//   node scripts/docs-shots.mjs --list                 # the scenes' names
//
// It serves www/ as built (./scripts/serve.sh, BUILD_ONLY=1) and uses the e2e tests' Chromium
// launcher (tests/e2e/lib.mjs). A scene is {name, viewport, phone?, path?, preset?, theme?, view?,
// actions?, keepFocus?, fullPage?}: `path` is a page under www/ (the playground when absent);
// `phone` means a touch screen at twice the pixels; `preset`, `theme` and `view` (an analysis view
// of the dock) are set through the playground's App; `actions(page, scene)` does the rest; the
// focus is dropped before the picture unless `keepFocus`. Each scene gets a
// fresh browser context (nothing saved by one scene reaches the next). The pictures of the
// lessons are the lesson tests' (tests/e2e/lessons.test.mjs), not made here.
import fs from 'node:fs';
import path from 'node:path';
import { ROOT, launch, openPage, serveWww, waitFrames } from '../tests/e2e/lib.mjs';

const LAPTOP = { width: 1280, height: 800 };
const PHONE = { width: 390, height: 844 };

/** The L cycle's key times of the timeline pictures, in seconds. */
const TIMELINE_TIMES = [0, 1, 3, 4, 6, 7, 9];

/** Hides the notice, the toast and the first-visit hint: a picture shows the page, not them. */
const quiet = (page) =>
  page.evaluate(() => {
    for (const id of ['banner', 'toast']) document.getElementById(id).hidden = true;
    document.querySelector('#hint .close')?.click();
  });

/** Opens the toolbar's View menu. */
const viewMenu = (page) => page.click('#t-view');

/** A CSV of `n` poses sampling a cycle (a full turn about z while bobbing), first pose repeated last. */
function denseCsv(n) {
  const rows = ['x,y,z,qw,qx,qy,qz'];
  for (let i = 0; i <= n; i++) {
    const a = (i / n) * 2 * Math.PI;
    rows.push(`${3 * Math.cos(a)},${3 * Math.sin(a)},${0.5 * Math.sin(2 * a)},${Math.cos(a / 2)},0,0,${Math.sin(a / 2)}`);
  }
  return Buffer.from(rows.join('\n'));
}

/** The L cycle on TIMELINE_TIMES with one key velocity, the Timing view at 3.5 s. */
async function timedLCycle(page) {
  await page.evaluate(async (times) => {
    const { app } = window.screwbender;
    app.run('setTimes', times);
    app.run('setVelocities', [null, 0.25, null, null, null, null]);
    await app.parts.dockHost.open('timing');
    app.viewer.seekTime(3.5);
  }, TIMELINE_TIMES);
  await page.evaluate(() => window.screwbender.flushViews());
}

/** Starts every figure of a page of <screw-bender> elements and waits for them. */
const startFigures = (page) =>
  page.evaluate(() => Promise.all([...document.querySelectorAll('screw-bender')].map((e) => {
    e.setAttribute('loading', 'eager');
    return e.ready;
  })));

/** Scrolls figure `id` to the middle of the window and lets it draw. */
async function centre(page, id) {
  await page.evaluate((i) => document.getElementById(i).scrollIntoView({ block: 'center' }), id);
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
}

/** Every picture of docs/screenshots/ this script makes (file name without .png). */
const SCENES = [
  { name: 'playground', viewport: LAPTOP, preset: 'l_cycle_rotated' },
  { name: 'theme-light-1280', viewport: LAPTOP, preset: 'l_cycle_rotated', theme: 'light' },
  { name: 'theme-dark-1280', viewport: LAPTOP, preset: 'l_cycle_rotated', theme: 'dark' },
  { name: 'theme-light-390', viewport: PHONE, preset: 'l_cycle_rotated', theme: 'light' },
  { name: 'theme-dark-390', viewport: PHONE, preset: 'l_cycle_rotated', theme: 'dark' },
  {
    name: 'media-menu-dark-1280', viewport: LAPTOP, preset: 'l_cycle_rotated', theme: 'dark',
    actions: async (page) => {
      await page.evaluate(() => window.screwbender.app.updateView({ showPoseNumbers: true }));
      await viewMenu(page);
    },
  },
  { name: 'media-menu-light-390', viewport: PHONE, preset: 'l_cycle_rotated', theme: 'light', actions: viewMenu },
  {
    name: 'media-ortho-top', viewport: LAPTOP, preset: 'l_cycle_rotated',
    actions: async (page) => {
      await viewMenu(page);
      await page.click('#m-ortho');
      await page.click('[data-camera=top]');
      await page.keyboard.press('Escape');
      await page.evaluate(() => window.screwbender.app.parts.viewpoint.fit());
    },
  },
  {
    name: 'media-recording', viewport: LAPTOP, preset: 'l_cycle_rotated',
    actions: async (page) => {
      await viewMenu(page);
      await page.click('#m-video');
      await page.waitForFunction(() => !document.getElementById('rec').hidden && document.getElementById('rec-progress').value > 0, null, { timeout: 120000 });
    },
  },
  {
    name: 'csv-reduce', viewport: LAPTOP, preset: 'l_cycle_rotated',
    actions: async (page) => {
      await page.locator('#any-file').setInputFiles({ name: 'dense.csv', mimeType: 'text/csv', buffer: denseCsv(200) });
      await page.waitForSelector('#reduce-dialog[open]');
    },
  },
  { name: 'analysis-1280', viewport: LAPTOP, preset: 'l_cycle_rotated', view: 'plots' },
  { name: 'analysis-dark-1280', viewport: LAPTOP, preset: 'l_cycle_rotated', theme: 'dark', view: 'plots', actions: (page) => page.evaluate(() => window.screwbender.app.viewer.seekTime(2.5)) },
  { name: 'analysis-390', viewport: PHONE, preset: 'l_cycle_rotated', view: 'plots' },
  { name: 'analysis-dark-390', viewport: PHONE, preset: 'l_cycle_rotated', theme: 'dark', view: 'plots' },
  {
    name: 'analysis-390-plots', viewport: PHONE, preset: 'l_cycle_rotated', view: 'plots',
    actions: (page) => page.locator('#dock .view-plots select.pick').selectOption({ label: 'position x' }),
  },
  {
    name: 'analysis-844x390', viewport: { width: 844, height: 390 }, preset: 'l_cycle_rotated', view: 'plots',
    actions: (page) => page.locator('#dock .view-plots select.pick').selectOption({ label: 'position x' }),
  },
  {
    name: 'timeline-desktop', viewport: LAPTOP, preset: 'l_cycle_rotated', keepFocus: true,
    actions: async (page) => {
      await timedLCycle(page);
      await page.locator('#keys .key-marker[data-key="3"]').focus();
    },
  },
  {
    name: 'timeline-phone', viewport: PHONE, phone: true, preset: 'l_cycle_rotated',
    actions: async (page) => {
      await timedLCycle(page);
      await page.evaluate(() => {
        window.screwbender.app.parts.dockHost.open('');
        window.screwbender.app.parts.viewpoint.fit();
      });
    },
  },
  { name: 'course', viewport: LAPTOP, path: 'examples/course.html', fullPage: true },
  { name: 'course-phone', viewport: PHONE, phone: true, path: 'examples/course.html', fullPage: true },
  { name: 'course-final-1280', viewport: LAPTOP, path: 'examples/course.html', actions: (page) => page.evaluate(() => window.scrollTo(0, document.body.scrollHeight)) },
  { name: 'course-final-390', viewport: PHONE, phone: true, path: 'examples/course.html', actions: (page) => page.evaluate(() => window.scrollTo(0, document.body.scrollHeight)) },
  {
    name: 'course-390-dark', viewport: PHONE, phone: true, path: 'examples/course.html',
    actions: async (page) => {
      await page.evaluate(() => document.querySelectorAll('screw-bender').forEach((e) => e.setAttribute('theme', 'dark')));
      await centre(page, 'fig-fourpoint');
    },
  },
  { name: 'course-320', viewport: { width: 320, height: 640 }, phone: true, path: 'examples/course.html', actions: (page) => centre(page, 'fig-fourpoint') },
  { name: 'three-example', viewport: { width: 1280, height: 800 }, path: 'examples/three.html?t=1.5', fullPage: true },
];

/** Makes the picture of `scene` into `out` with a browser `browser` for `backend` served at `url`. */
async function shoot(browser, url, backend, scene, out) {
  const context = await browser.newContext({
    viewport: scene.viewport,
    ...(scene.phone ? { hasTouch: true, isMobile: true, deviceScaleFactor: 2 } : {}),
  });
  try {
    let page;
    if (scene.path) {
      page = await context.newPage();
      const q = backend === 'webgl2' ? `${scene.path.includes('?') ? '&' : '?'}backend=webgl2` : '';
      await page.goto(`${url}${scene.path}${q}`);
      if (await page.evaluate(() => !!document.querySelector('screw-bender'))) {
        await page.waitForFunction(() => customElements.get('screw-bender'));
        await startFigures(page);
        // The figures' autoplay stops, so that every run shows the same moment.
        await page.evaluate(() => document.querySelectorAll('screw-bender').forEach((e) => e.pause()));
      }
    } else {
      ({ page } = await openPage(context, url, backend));
      await page.evaluate(({ preset, theme, view }) => {
        const { app } = window.screwbender;
        if (preset) app.run('loadPreset', preset);
        if (theme) app.updateView({ theme });
        if (view) window.screwbender.openView(view);
      }, { preset: scene.preset, theme: scene.theme, view: scene.view });
      if (scene.view) await page.evaluate(() => window.screwbender.flushViews());
      await quiet(page);
    }
    await scene.actions?.(page, scene);
    // No focus ring in a picture unless the scene shows where the focus is.
    if (!scene.keepFocus) await page.evaluate(() => /** @type {HTMLElement} */ (document.activeElement)?.blur());
    if (!scene.path) await waitFrames(page, 2);
    const file = path.join(out, `${scene.name}.png`);
    await page.screenshot({ path: file, fullPage: !!scene.fullPage });
    return file;
  } finally {
    await context.close();
  }
}

async function main() {
  const args = process.argv.slice(2);
  const option = (name, fallback) => {
    const i = args.indexOf(name);
    if (i < 0) return fallback;
    const [, value] = args.splice(i, 2);
    if (!value) throw new Error(`${name} needs a value`);
    return value;
  };
  if (args.includes('--list')) {
    for (const s of SCENES) console.log(s.name);
    return;
  }
  const out = path.resolve(option('--out', path.join(ROOT, 'docs/screenshots')));
  const backend = option('--backend', 'webgpu');
  if (!['webgpu', 'webgl2'].includes(backend)) throw new Error(`--backend ${backend}: webgpu or webgl2`);
  const unknown = args.filter((n) => !SCENES.some((s) => s.name === n));
  if (unknown.length) throw new Error(`no scene named ${unknown.join(', ')} (--list names them)`);
  const scenes = args.length ? SCENES.filter((s) => args.includes(s.name)) : SCENES;
  fs.mkdirSync(out, { recursive: true });
  const { url, stop } = await serveWww();
  const browser = await launch(backend);
  const failed = [];
  try {
    for (const scene of scenes) {
      try {
        console.log(`docs-shots: ${path.relative(process.cwd(), await shoot(browser, url, backend, scene, out))}`);
      } catch (e) {
        console.error(`docs-shots: ${scene.name}: ${e.message.split('\n')[0]}`);
        failed.push(scene.name);
      }
    }
  } finally {
    await browser.close();
    stop();
  }
  if (failed.length) throw new Error(`${failed.length} of ${scenes.length} scenes failed: ${failed.join(' ')}`);
}

main().catch((e) => {
  console.error(`docs-shots: ${e.message}`);
  process.exit(1);
});
