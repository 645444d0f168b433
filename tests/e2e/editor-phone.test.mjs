// e2e-backends: webgpu (computed on the CPU, the same on either backend: once)
// End-to-end: the playground on a phone, upright (390 × 844) and on its side (844 × 390), with
// touch emulation: every control on screen and at least 44 px, taps on the toolbar and on a
// pose handle, pinch zoom and two-finger pan with real touch events, the snap toggle, help for
// touch. Screenshots land in artifacts/e2e-<backend>/phone-*.png.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { startPlayground, openPage, waitFrames, ROOT, BACKEND } from './lib.mjs';

const ARTIFACTS = path.join(ROOT, 'artifacts', `e2e-${BACKEND}`);
const LAYOUTS = { portrait: { width: 390, height: 844 }, landscape: { width: 844, height: 390 } };
let play;

before(async () => {
  fs.mkdirSync(ARTIFACTS, { recursive: true });
  play = await startPlayground();
});

after(async () => {
  await play?.close();
});

async function phonePage(viewport) {
  const context = await play.browser.newContext({ viewport, hasTouch: true, isMobile: true, deviceScaleFactor: 2 });
  const { page, problems } = await openPage(context, play.url, BACKEND);
  return { context, page, problems };
}

/** Every visible control: its label, box and (for checkboxes) the box of the label around it. */
const controls = (page, scope) =>
  page.evaluate((sel) => {
    const out = [];
    for (const e of document.querySelectorAll(`${sel} button, ${sel} input, ${sel} select, ${sel} [tabindex]`)) {
      if (e.type === 'hidden' || e.type === 'file' || !e.getClientRects().length) continue;
      if (getComputedStyle(e).visibility === 'hidden') continue;
      const target = e.type === 'checkbox' ? (e.closest('label') ?? e) : e;
      const r = target.getBoundingClientRect();
      if (r.width === 0 || r.height === 0) continue;
      const name = e.id || e.getAttribute('aria-label') || e.textContent.trim().slice(0, 30) || e.tagName;
      out.push({ name, x: r.left, y: r.top, w: r.width, h: r.height, r: r.right, b: r.bottom });
    }
    return out;
  }, scope);

function onScreen(list, { width, height }, what) {
  const off = list.filter((c) => c.x < -0.5 || c.y < -0.5 || c.r > width + 0.5 || c.b > height + 0.5);
  assert.deepEqual(off.map((c) => `${c.name} ${Math.round(c.x)},${Math.round(c.y)}–${Math.round(c.r)},${Math.round(c.b)}`), [], `${what}: off screen`);
}

/**
 * The controls of `scope` that another element covers at their centre (a tap would miss them);
 * controls scrolled out of the scrolling box `clip` (if given) are not counted.
 */
const covered = (page, scope, clip) =>
  page.evaluate(([sel, clipSel]) => {
    const out = [];
    const box = clipSel ? document.querySelector(clipSel).getBoundingClientRect() : null;
    for (const e of document.querySelectorAll(`${sel} button, ${sel} input, ${sel} select`)) {
      if (!e.getClientRects().length) continue;
      const r = e.getBoundingClientRect();
      const [cx, cy] = [r.left + r.width / 2, r.top + r.height / 2];
      if (box && (cy < box.top || cy > box.bottom || cx < box.left || cx > box.right)) continue;
      const hit = document.elementFromPoint(cx, cy);
      if (!hit || !(e.contains(hit) || hit.contains(e) || hit.closest('label')?.contains(e))) out.push(`${e.id || e.textContent.trim() || e.tagName} under ${hit?.id || hit?.className || hit?.tagName}`);
    }
    return out;
  }, [scope, clip]);

function bigEnough(list, what) {
  const small = list.filter((c) => c.w < 44 - 0.5 || c.h < 44 - 0.5);
  assert.deepEqual(small.map((c) => `${c.name} ${c.w.toFixed(0)}×${c.h.toFixed(0)}`), [], `${what}: touch targets under 44 px`);
}

/** Distance of the camera from its target, and the target. */
const cam = (page) => page.evaluate(() => ({ d: window.screwbender.app.viewer.camera.distance, t: [...window.screwbender.app.viewer.camera.target] }));

/** Two fingers from a1, b1 to a2, b2 in `steps` moves (CDP touch events: real pointer events in the page). */
async function twoFingers(page, a1, b1, a2, b2, steps = 8) {
  const cdp = await page.context().newCDPSession(page);
  const at = (k) => [0, 1].map((f) => {
    const [p, q] = f === 0 ? [a1, a2] : [b1, b2];
    return { x: p.x + ((q.x - p.x) * k) / steps, y: p.y + ((q.y - p.y) * k) / steps, id: f };
  });
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: at(0) });
  for (let k = 1; k <= steps; k++) await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: at(k) });
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
  await cdp.detach();
  await waitFrames(page, 1);
}

for (const [layout, viewport] of Object.entries(LAYOUTS)) {
  test(`${BACKEND}: phone ${layout} ${viewport.width}×${viewport.height}: everything on screen, touch targets ≥ 44 px`, async () => {
    const { context, page, problems } = await phonePage(viewport);
    try {
      // The camera-independent chrome, as it opens.
      for (const scope of ['#toolbar', '#timeline', '#panel']) {
        const list = await controls(page, scope);
        assert.ok(list.length > 0, `nothing in ${scope}`);
        onScreen(list, viewport, scope);
        bigEnough(list, scope);
      }
      for (const scope of ['#toolbar', '#timeline']) assert.deepEqual(await covered(page, scope), [], `${scope} covered`);
      const title = await page.locator('#title').boundingBox();
      const panelHead = await page.locator('#panel .lil-gui.lil-root > .lil-title').boundingBox();
      const overlap = (a, b) => a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
      assert.ok(!overlap(title, panelHead), 'the folded panel header overlaps the title card');
      const toolbar = await page.locator('#toolbar').boundingBox();
      const timeline = await page.locator('#timeline').boundingBox();
      assert.ok(!overlap(toolbar, timeline), 'toolbar and timeline overlap');
      await page.screenshot({ path: path.join(ARTIFACTS, `phone-${layout}.png`) });
      // The panel opened (tap on its title): its controls are as wide as the screen allows and big enough.
      await page.locator('#panel .lil-gui.lil-root > .lil-title').tap();
      await page.evaluate(() => window.screwbender.app.ui.gui.folders[0].open());
      assert.equal(await page.evaluate(() => window.screwbender.app.ui.gui._closed), false, 'a tap on the title did not open the panel');
      // lil-gui opens a folder over animation frames: wait until its controls are laid out (a
      // loaded software renderer can delay those frames) before measuring them.
      let panel = await controls(page, '#panel');
      for (let k = 0; k < 100 && panel.length < 8; k++) {
        await page.waitForTimeout(50);
        panel = await controls(page, '#panel');
      }
      assert.ok(panel.length >= 8, `${panel.length} controls in the open panel`);
      const pbox = await page.locator('#panel').boundingBox();
      onScreen([{ name: '#panel', x: pbox.x, y: pbox.y, r: pbox.x + pbox.width, b: pbox.y + pbox.height }], viewport, 'panel');
      onScreen(panel.map((c) => ({ ...c, y: Math.max(c.y, 0), b: Math.min(c.b, pbox.y + pbox.height) })), viewport, 'panel controls');
      bigEnough(panel, 'open panel');
      // Nothing (the first-visit hint, say) lies over the open panel.
      assert.deepEqual(await covered(page, '#panel .lil-gui.lil-root > .lil-children > .lil-gui:first-child', '#panel'), [], 'panel controls covered');
      await page.screenshot({ path: path.join(ARTIFACTS, `phone-${layout}-panel.png`) });
      await page.locator('#panel .lil-gui.lil-root > .lil-title').tap();
      // The help: touch gestures described, a close button in reach.
      await page.locator('#t-help').tap();
      assert.ok(await page.locator('#help .touch-help').isVisible(), 'no touch help');
      assert.match(await page.locator('#help .touch-help').textContent(), /pinch/);
      const close = await controls(page, '#help');
      onScreen(close, viewport, 'help');
      bigEnough(close, 'help');
      await page.locator('#help .help-close').tap();
      assert.ok(!(await page.locator('#help').isVisible()));
      // The analysis dock fits too.
      await page.locator('#t-dock').tap();
      await page.evaluate(() => window.screwbender.flushViews());
      const dock = await page.locator('#dock').boundingBox();
      onScreen([{ name: '#dock', x: dock.x, y: dock.y, r: dock.x + dock.width, b: dock.y + dock.height }], viewport, 'dock');
      bigEnough(await controls(page, '#dock .head'), 'dock tabs');
      assert.deepEqual(await covered(page, '#dock .head'), [], 'dock tabs covered');
      assert.deepEqual(await covered(page, '#toolbar'), [], 'toolbar covered by the dock');
      await page.screenshot({ path: path.join(ARTIFACTS, `phone-${layout}-dock.png`) });
      await page.locator('#t-dock').tap();
      assert.deepEqual(problems, []);
    } finally {
      await context.close();
    }
  });
}

test(`${BACKEND}: phone: taps select and edit; pinch zooms; two fingers pan; the snap toggle snaps drags`, async () => {
  const { context, page, problems } = await phonePage(LAYOUTS.portrait);
  try {
    // A tap on a handle selects its pose; toolbar taps change the mode and the snap.
    const h = await page.evaluate(() => window.screwbender.handleOnPage(2));
    await page.touchscreen.tap(h.x, h.y);
    assert.equal(await page.evaluate(() => window.screwbender.selected()), 2);
    await page.locator('#t-rotate').tap();
    assert.equal(await page.evaluate(() => window.screwbender.app.mode), 'rotate');
    await page.locator('#t-translate').tap();
    await page.locator('#t-snap').tap();
    assert.equal(await page.evaluate(() => window.screwbender.app.view.snap), true);
    assert.equal(await page.locator('#t-snap').getAttribute('aria-pressed'), 'true');
    // A one-finger drag of the x arrow with the snap toggle on moves by whole snapping steps.
    const x0 = (await page.evaluate(() => Array.from(window.screwbender.poses())))[14];
    const a = await page.evaluate(() => window.screwbender.gizmoOnPage('axis-x'));
    const o = await page.evaluate(() => window.screwbender.handleOnPage(2));
    // Along the arrow as drawn on the screen.
    const len = Math.hypot(a.x - o.x, a.y - o.y);
    const dir = { x: (a.x - o.x) / len, y: (a.y - o.y) / len };
    const cdp = await context.newCDPSession(page);
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: [{ x: a.x, y: a.y, id: 0 }] });
    for (let k = 1; k <= 10; k++) await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: [{ x: a.x + 6 * k * dir.x, y: a.y + 6 * k * dir.y, id: 0 }] });
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
    await waitFrames(page, 1);
    const x1 = (await page.evaluate(() => Array.from(window.screwbender.poses())))[14];
    const steps = (x1 - x0) / 0.25;
    assert.ok(Math.abs(x1 - x0) >= 0.25 - 1e-12, `the drag moved x by ${x1 - x0}`);
    assert.ok(Math.abs(steps - Math.round(steps)) < 1e-9, `snapped move ${x1 - x0} is not whole 0.25 steps`);
    // Pinch out: the camera comes closer; the target stays (fingers symmetric about a point).
    const c = { x: 195, y: 420 };
    const c0 = await cam(page);
    await twoFingers(page, { x: c.x - 40, y: c.y }, { x: c.x + 40, y: c.y }, { x: c.x - 120, y: c.y }, { x: c.x + 120, y: c.y });
    const c1 = await cam(page);
    assert.ok(c1.d < c0.d * 0.6, `pinch: distance ${c0.d} -> ${c1.d}`);
    // Two fingers moved together pan: the target moves, the distance stays.
    await twoFingers(page, { x: 150, y: 400 }, { x: 240, y: 400 }, { x: 150, y: 300 }, { x: 240, y: 300 });
    const c2 = await cam(page);
    assert.ok(Math.abs(c2.d - c1.d) < 1e-9 * c1.d, `pan changed the distance ${c1.d} -> ${c2.d}`);
    assert.ok(Math.hypot(...c2.t.map((v, k) => v - c1.t[k])) > 0.05, 'two-finger pan did not move the target');
    await page.screenshot({ path: path.join(ARTIFACTS, 'phone-portrait-edited.png') });
    assert.deepEqual(problems, []);
  } finally {
    await context.close();
  }
});
