// e2e-backends: webgpu webgl2 (PNG pictures and the theme's colours are read back from each backend's canvas)
// End-to-end: pictures out of the playground (editor/media.js) — a real PNG download at 1× and
// 2× (size, non-blank pixels, a transparent background; the videos are video-export.test.mjs),
// what a PNG leaves out — and the dark theme as drawn (toggle, prefers-color-scheme on a first
// visit). Each result here is pixels of the backend's drawing, so the file runs on both backends;
// the View menu's behaviour that no drawing decides (camera presets, the orthographic projection
// and picking, the menu's layout, refused requests) is view-menu.test.mjs, once.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import { BACKEND, DESKTOP, downloadFrom, openPage, openViewMenu, playgroundPage, waitFrames } from './lib.mjs';

let play;
let page;
let problems;
/** A blank page (no content security policy) where downloaded files are decoded. */
let blank;

before(async () => {
  ({ play, page, problems } = await playgroundPage({ acceptDownloads: true }));
  blank = await play.context.newPage();
  await page.bringToFront();
  await page.evaluate(() => window.screwbender.app.run('loadPreset', 'l_cycle_rotated'));
  // The first-visit hint moves with the layout; it is not what these tests are about.
  await page.evaluate(() => document.querySelector('#hint .close')?.click());
  await waitFrames(page, 2);
});

after(async () => {
  await play?.close();
});

/** The light and dark backgrounds as displayed (www/js/figure/slots.js BACKGROUND), 0..255. */
const LIGHT = [232, 236, 241];
const DARK = [27, 31, 39];
/** Per-channel tolerance on a background pixel (8-bit rounding, the encoders). */
const BG_TOL = 4;

/** Runs `action` and returns the download it causes (null when none came within `ms`). */
const downloadOf = (action, ms) => downloadFrom(page, action, ms);

const openMenu = () => openViewMenu(page);

/** Clicks `item` in the View menu. */
async function menuClick(item) {
  await openMenu();
  await page.click(item);
}

/** Width and height from a PNG's IHDR chunk (throws when the signature is not PNG's). */
function pngSize(bytes) {
  assert.deepEqual([...bytes.subarray(0, 8)], [0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a], 'PNG signature');
  assert.equal(bytes.subarray(12, 16).toString('latin1'), 'IHDR');
  return { width: bytes.readUInt32BE(16), height: bytes.readUInt32BE(20) };
}

/**
 * Decodes a PNG in the page: the fraction of pixels differing from `bg` (sum of channel
 * differences > 30), the alpha of the corner pixel and the fraction of opaque pixels.
 */
function decodePng(bytes, bg) {
  return blank.evaluate(async ({ b64, bg }) => {
    const blob = new Blob([Uint8Array.from(atob(b64), (ch) => ch.charCodeAt(0))]);
    const bmp = await createImageBitmap(blob, { premultiplyAlpha: 'none', colorSpaceConversion: 'none' });
    const c = document.createElement('canvas');
    c.width = bmp.width;
    c.height = bmp.height;
    const g = c.getContext('2d');
    g.drawImage(bmp, 0, 0);
    const d = g.getImageData(0, 0, c.width, c.height).data;
    let differ = 0;
    let opaque = 0;
    for (let i = 0; i < d.length; i += 4) {
      if (Math.abs(d[i] - bg[0]) + Math.abs(d[i + 1] - bg[1]) + Math.abs(d[i + 2] - bg[2]) > 30) differ++;
      if (d[i + 3] === 255) opaque++;
    }
    const n = d.length / 4;
    return { differ: differ / n, opaque: opaque / n, corner: [...d.subarray(0, 4)] };
  }, { b64: Buffer.from(bytes).toString('base64'), bg });
}

const drawingBuffer = () => page.evaluate(() => window.screwbender.app.viewer.pixelSize());
const readBytes = async (download) => fs.readFileSync(await download.path());

test('PNG at 1×: a real download of the drawing buffer, named after the preset, not blank', async () => {
  const { w, h } = await drawingBuffer();
  const d = await downloadOf(() => menuClick('#m-png'));
  assert.ok(d, 'a download');
  assert.match(d.suggestedFilename(), /^[a-z0-9-]+\.png$/);
  const bytes = await readBytes(d);
  assert.deepEqual(pngSize(bytes), { width: w, height: h });
  const px = await decodePng(bytes, LIGHT);
  assert.ok(px.differ > 0.02, `drawn content: ${(px.differ * 100).toFixed(2)} % of the pixels differ from the background`);
  assert.equal(px.opaque, 1, 'an opaque picture');
  for (let k = 0; k < 3; k++) assert.ok(Math.abs(px.corner[k] - LIGHT[k]) <= BG_TOL, `background corner ${px.corner}`);
  // The view is drawn at its own size again afterwards.
  const canvas = await page.evaluate(() => [window.screwbender.app.viewer.canvas.width, window.screwbender.app.viewer.canvas.height]);
  assert.deepEqual(canvas, [w, h]);
});

test('PNG at 2×: drawn at twice the size (not scaled up), transparent background on request', async () => {
  const { w, h } = await drawingBuffer();
  await openMenu();
  await page.check('#m-png-2x');
  await page.check('#m-png-transparent');
  const d = await downloadOf(() => page.click('#m-png'));
  assert.match(d.suggestedFilename(), /@2x\.png$/);
  const bytes = await readBytes(d);
  assert.deepEqual(pngSize(bytes), { width: 2 * w, height: 2 * h });
  const px = await decodePng(bytes, [0, 0, 0]);
  assert.equal(px.corner[3], 0, `transparent background at the corner: ${px.corner}`);
  assert.ok(px.opaque > 0.01, `opaque content: ${(px.opaque * 100).toFixed(2)} %`);
  assert.ok(px.opaque < 0.9, 'the background is not opaque');
  // A 2× picture really has more detail than a scaled-up 1× one: edges at pixel steps of 1, not 2.
  const singleSteps = await blank.evaluate(async (b64) => {
    const bmp = await createImageBitmap(new Blob([Uint8Array.from(atob(b64), (ch) => ch.charCodeAt(0))]));
    const c = new OffscreenCanvas(bmp.width, bmp.height);
    const g = c.getContext('2d');
    g.drawImage(bmp, 0, 0);
    const d = g.getImageData(0, 0, c.width, c.height).data;
    // Pixels that differ from both horizontal neighbours' pair partner: impossible in a 2× upscale.
    let odd = 0;
    for (let y = 0; y < c.height; y += 7) {
      for (let x = 0; x + 1 < c.width; x += 2) {
        const i = (y * c.width + x) * 4;
        if (Math.abs(d[i + 3] - d[i + 7]) > 60) odd++;
      }
    }
    return odd;
  }, Buffer.from(bytes).toString('base64'));
  assert.ok(singleSteps > 20, `edges between the pixels of a pair: ${singleSteps}`);
  await openMenu();
  await page.check('#m-png-1x');
  await page.uncheck('#m-png-transparent');
  await page.keyboard.press('Escape');
});

/**
 * The view's canvas as drawn now (one frame drawn and read in the same task, as the PNG export
 * does; a page screenshot of a WebGPU canvas can take minutes on a loaded machine): the colours
 * at `spots` ([x, y] drawing-buffer pixels; when null, up to 20 points of the middle showing
 * `bg` are found).
 */
function examine(spots, bg) {
  return page.evaluate(({ spots, bg }) => {
    let out;
    window.screwbender.app.viewer.snapshot(1, [null], (canvas) => {
      const g = document.createElement('canvas').getContext('2d', { willReadFrequently: true });
      g.canvas.width = canvas.width;
      g.canvas.height = canvas.height;
      g.drawImage(canvas, 0, 0);
      const { width: w, height: h } = canvas;
      const d = g.getImageData(0, 0, w, h).data;
      const at = (x, y) => [...d.subarray((y * w + x) * 4, (y * w + x) * 4 + 3)];
      if (!spots) {
        spots = [];
        for (let y = Math.round(h / 4); y < (3 * h) / 4 && spots.length < 20; y += 13) {
          for (let x = Math.round(w / 4); x < (3 * w) / 4 && spots.length < 20; x += 17) {
            if (at(x, y).every((v, k) => Math.abs(v - bg[k]) <= 4)) spots.push([x, y]);
          }
        }
      }
      out = { spots, colours: spots.map(([x, y]) => at(x, y)) };
    });
    return out;
  }, { spots, bg });
}

/** Whether the first channels of pixel `a` are within `tol` of colour `b`. */
const near = (a, b, tol) => b.every((x, k) => Math.abs(a[k] - x) <= tol);

test('dark theme: the toggle darkens the page and the canvas, and is kept in the session', async () => {
  await page.evaluate(() => window.screwbender.app.parts.viewpoint.fit());
  await waitFrames(page, 2);
  // Points of the view showing the light background (nothing drawn there, off the chrome).
  const { spots } = await examine(null, LIGHT);
  assert.ok(spots.length >= 10, `background visible at ${spots.length} points`);
  await menuClick('#m-theme');
  await page.keyboard.press('Escape');
  await waitFrames(page, 2);
  assert.equal(await page.evaluate(() => document.documentElement.dataset.theme), 'dark');
  assert.equal(await page.locator('#m-theme').getAttribute('aria-pressed'), 'true');
  const dark = await examine(spots);
  dark.colours.forEach((c, k) => assert.ok(near(c, DARK, BG_TOL), `dark canvas background at ${spots[k]}: ${c}`));
  // The trajectories and the control polygon turn light (readable on the dark background).
  const lines = await page.evaluate(() => {
    const c = window.screwbender.app.viewer.drawing.colors;
    return [c.trajectory, c.polygon];
  });
  for (const c of lines) assert.ok(Math.min(...c) > 0.35, `a light line colour (linear RGB): ${c}`);
  // The page's chrome is dark too.
  assert.equal(await page.evaluate(() => getComputedStyle(document.getElementById('toolbar')).color), 'rgb(230, 233, 239)');
  assert.equal(await page.evaluate(() => window.screwbender.session().view.theme), 'dark');
  // A PNG follows the theme.
  const d = await downloadOf(() => menuClick('#m-png'));
  const corner = (await decodePng(await readBytes(d), DARK)).corner;
  assert.ok(near(corner, DARK, BG_TOL), `dark PNG background: ${corner}`);
  // D toggles back.
  await page.focus('#view');
  await page.keyboard.press('d');
  await waitFrames(page, 2);
  assert.equal(await page.evaluate(() => document.documentElement.dataset.theme), 'light');
  const again = await examine(spots);
  again.colours.forEach((c, k) => assert.ok(near(c, LIGHT, BG_TOL), `light again at ${spots[k]}: ${c}`));
  assert.deepEqual(problems, []);
});

test('prefers-color-scheme: dark gives the dark theme on a first visit', async () => {
  const context = await play.browser.newContext({ viewport: DESKTOP, colorScheme: 'dark' });
  try {
    const { page: p, problems: pp } = await openPage(context, play.url, BACKEND);
    const s = await p.evaluate(() => ({ theme: document.documentElement.dataset.theme, setting: window.screwbender.app.view.theme }));
    assert.deepEqual(s, { theme: 'dark', setting: 'auto' });
    const c = await p.evaluate(() => {
      const { app } = window.screwbender;
      let px;
      app.viewer.snapshot(1, [null], (canvas) => {
        const g = document.createElement('canvas').getContext('2d');
        g.canvas.width = canvas.width;
        g.canvas.height = canvas.height;
        g.drawImage(canvas, 0, 0);
        px = [...g.getImageData(1, 1, 1, 1).data.subarray(0, 3)];
      });
      return px;
    });
    assert.ok(near(c, DARK, BG_TOL), `dark canvas on a first visit: ${c}`);
    // The system turning light again is followed while the setting is 'auto'.
    await p.emulateMedia({ colorScheme: 'light' });
    await p.waitForFunction(() => document.documentElement.dataset.theme === 'light');
    assert.deepEqual(pp, []);
  } finally {
    await context.close();
  }
});

/** The fraction of pixels where two PNGs of the same size differ (sum of channel differences > 30). */
function pngDiff(a, b) {
  return blank.evaluate(async ([a64, b64]) => {
    const px = async (s) => {
      const bmp = await createImageBitmap(new Blob([Uint8Array.from(atob(s), (ch) => ch.charCodeAt(0))]));
      const c = document.createElement('canvas');
      c.width = bmp.width;
      c.height = bmp.height;
      const g = c.getContext('2d');
      g.drawImage(bmp, 0, 0);
      return g.getImageData(0, 0, c.width, c.height).data;
    };
    const [p, q] = [await px(a64), await px(b64)];
    if (p.length !== q.length) return 1;
    let n = 0;
    for (let i = 0; i < p.length; i += 4) if (Math.abs(p[i] - q[i]) + Math.abs(p[i + 1] - q[i + 1]) + Math.abs(p[i + 2] - q[i + 2]) > 30) n++;
    return n / (p.length / 4);
  }, [Buffer.from(a).toString('base64'), Buffer.from(b).toString('base64')]);
}

test('PNG leaves out the gizmo and the selection by default, keeps the pose numbers, and says so in the menu', async () => {
  await page.evaluate(() => {
    const app = window.screwbender.app;
    app.run('loadPreset', 'cylinder5');
    app.updateView({ showPoseNumbers: true });
    app.setMode?.('rotate');
  });
  await waitFrames(page, 2);
  await openMenu();
  assert.match(await page.locator('#m-picture-note').textContent(), /leave out the gizmo and the selection .* keep the pose numbers/);
  const png = async () => readBytes(await downloadOf(() => menuClick('#m-png')));
  await page.evaluate(() => window.screwbender.app.select(-1));
  await waitFrames(page, 2);
  const none = await png();
  await page.evaluate(() => window.screwbender.app.select(2));
  await waitFrames(page, 2);
  const selected = await png();
  // The selection (and its gizmo) is still on screen afterwards.
  assert.equal(await page.evaluate(() => window.screwbender.app.selected), 2);
  await openMenu();
  await page.check('#m-png-selection');
  const withGizmo = await png();
  await openMenu();
  await page.uncheck('#m-png-selection');
  const same = await pngDiff(none, selected);
  const gizmo = await pngDiff(none, withGizmo);
  assert.ok(same < 1e-4, `the default PNG with pose 2 selected differs from the unselected one at ${(same * 100).toFixed(3)} % of its pixels`);
  assert.ok(gizmo > 2e-3, `ticked, the gizmo is in the picture (${(gizmo * 100).toFixed(3)} % of the pixels)`);
  // The pose numbers are drawn in: without them the picture differs.
  await page.evaluate(() => {
    const app = window.screwbender.app;
    app.select(-1);
    app.updateView({ showPoseNumbers: false });
    app.parts.labels.place();
  });
  await waitFrames(page, 2);
  const bare = await png();
  const numbers = await pngDiff(none, bare);
  assert.ok(numbers > 1e-4, `the pose numbers are in the picture (${(numbers * 100).toFixed(4)} % of the pixels)`);
  await page.evaluate(() => {
    window.screwbender.app.updateView({ showPoseNumbers: true });
    window.screwbender.app.run('loadPreset', 'l_cycle_rotated');
  });
  assert.deepEqual(problems, []);
});
