// e2e-backends: webgpu (the camera's numbers, the same on either backend: once)
// End-to-end: the <screw-bender> snippet of Share & embed frames the figure as the playground
// is framed: after an orbit, a pan and a zoom with the real mouse, the snippet's `camera`
// attribute ("yaw pitch distance tx ty tz") gives the figure in a blank page the page's yaw,
// pitch, distance and target to 1e-9. The attribute's other forms and its bad values are
// checked on the same page.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { BACKEND, playgroundPage, waitFrames } from './lib.mjs';

let play;
let page;
let problems;

before(async () => {
  ({ play, page, problems } = await playgroundPage());
  await page.evaluate(() => document.querySelector('#hint .close')?.click());
});

after(async () => {
  await play?.close();
});

/** The playground's camera. */
const pageCamera = () => page.evaluate(() => window.screwbender.app.viewer.camera.toJSON());

/** Serves `html` at `name` on the test server's origin. */
async function hostPage(name, html) {
  const url = `${play.url}${name}`;
  await play.context.route(url, (route) => route.fulfill({ status: 200, contentType: 'text/html; charset=utf-8', body: html }));
  return url;
}

/** A blank page with `body`; returns the page, once its first figure is ready, and its problems. */
async function figurePage(name, body) {
  const url = await hostPage(name, `<!doctype html><html lang="en"><head><meta charset="utf-8"><title>Figure</title></head><body>${body}</body></html>`);
  const p = await play.context.newPage();
  const pp = [];
  p.on('pageerror', (e) => pp.push(e.message));
  p.on('console', (m) => m.type() === 'error' && pp.push(m.text()));
  await p.goto(url);
  await p.waitForFunction(() => customElements.get('screw-bender'));
  await p.evaluate(() => document.querySelector('screw-bender').ready.catch(() => {}));
  return { p, pp };
}

const figureCamera = (p) => p.evaluate(() => document.querySelector('screw-bender').viewer.camera.toJSON());

function assertCamera(got, want, tol = 1e-9) {
  for (const k of ['yaw', 'pitch', 'distance']) assert.ok(Math.abs(got[k] - want[k]) <= tol, `${k}: ${got[k]} vs ${want[k]}`);
  for (let i = 0; i < 3; i++) assert.ok(Math.abs(got.target[i] - want.target[i]) <= tol, `target[${i}]: ${got.target[i]} vs ${want.target[i]}`);
}

test(`${BACKEND}: after an orbit, a pan and a zoom, the snippet's figure has the page's camera to 1e-9`, async () => {
  const canvas = page.locator('#view');
  const box = await canvas.boundingBox();
  // Away from the motion in the middle, so that the presses turn the view, not a pose.
  const at = { x: box.x + box.width * 0.12, y: box.y + box.height * 0.8 };
  const before = await pageCamera();
  // Orbit: Alt-drag (the primary button without Alt may pick a pose).
  await page.keyboard.down('Alt');
  await page.mouse.move(at.x, at.y);
  await page.mouse.down();
  for (let k = 1; k <= 6; k++) await page.mouse.move(at.x + 13 * k, at.y - 5 * k);
  await page.mouse.up();
  await page.keyboard.up('Alt');
  // Pan: a right-button drag.
  await page.mouse.move(at.x, at.y);
  await page.mouse.down({ button: 'right' });
  for (let k = 1; k <= 6; k++) await page.mouse.move(at.x + 17 * k, at.y - 9 * k);
  await page.mouse.up({ button: 'right' });
  // Zoom: the wheel.
  await page.mouse.move(at.x, at.y);
  await page.mouse.wheel(0, -240);
  await waitFrames(page, 2);
  const cam = await pageCamera();
  for (const k of ['yaw', 'pitch', 'distance']) assert.notEqual(cam[k], before[k], `${k} changed by the mouse`);
  assert.ok(cam.target.some((x, i) => Math.abs(x - before.target[i]) > 1e-3), 'the pan moved the target');

  // Share & embed, as a keyboard user opens it: the File folder's button, then Enter.
  await page.evaluate(() => window.screwbender.app.ui.gui.folders.find((f) => f._title === 'File').open());
  const button = page.locator('#panel button', { hasText: 'Share & embed…' });
  await button.focus();
  await page.keyboard.press('Enter');
  await page.locator('#share').waitFor({ state: 'visible' });
  const snippet = await page.inputValue('#share-element');
  await page.keyboard.press('Escape');
  const attr = snippet.match(/ camera="([^"]*)"/);
  assert.ok(attr, `a camera attribute in ${snippet.slice(0, 300)}`);
  assert.equal(attr[1].trim().split(/\s+/).length, 6, `yaw pitch distance tx ty tz: "${attr[1]}"`);

  const { p, pp } = await figurePage('snippet-camera.html', `<h1>Lecture</h1>\n${snippet}\n`);
  try {
    assertCamera(await figureCamera(p), cam);
    assert.equal(await p.evaluate(() => document.querySelector('screw-bender').shadowRoot.querySelector('.msg')?.textContent ?? ''), '');
    assert.deepEqual(pp, []);
  } finally {
    await p.close();
  }
  assert.deepEqual(problems, []);
});

test(`${BACKEND}: camera takes "yaw pitch distance" and "yaw pitch distance tx ty tz"; other counts are errors`, async () => {
  const script = await page.evaluate(() => new URL('js/element/screw-bender.js', location.href).href);
  const figure = (camera) => `<screw-bender preset="pendulum" loading="eager" camera="${camera}"></screw-bender>`;
  const deg = Math.PI / 180;
  const { p, pp } = await figurePage('camera-forms.html', `<script type="module" src="${script}"></script>\n${figure('30 20 9 1 -2 0.5')}`);
  try {
    assertCamera(await figureCamera(p), { yaw: 30 * deg, pitch: 20 * deg, distance: 9, target: [1, -2, 0.5] });
    // Three numbers: turned and set back, around the target the figure frames itself.
    await p.evaluate(() => document.querySelector('screw-bender').setAttribute('camera', '-40 10 7'));
    const three = await figureCamera(p);
    assertCamera(three, { yaw: -40 * deg, pitch: 10 * deg, distance: 7, target: three.target });
    assert.notDeepEqual(three.target, [1, -2, 0.5], 'the three-number form frames the motion again');
    // Four, five or seven numbers, or a non-finite one: the element's error, the camera kept.
    for (const bad of ['10 10 5 1', '10 10 5 1 2', '10 10 5 1 2 3 4', '10 10 5 1 NaN 3', '10 10 -5 1 2 3']) {
      const result = await p.evaluate((v) => {
        const el = document.querySelector('screw-bender');
        const errors = [];
        el.addEventListener('error', (e) => errors.push(e.detail), { once: true });
        el.setAttribute('camera', v);
        return { errors, camera: el.viewer.camera.toJSON() };
      }, bad);
      assert.equal(result.errors.length, 1, `camera="${bad}" is an error`);
      assert.equal(result.errors[0].attribute, 'camera');
      assertCamera(result.camera, three);
    }
    assert.deepEqual(pp, []);
  } finally {
    await p.close();
  }
});
