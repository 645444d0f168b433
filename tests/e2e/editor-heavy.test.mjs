// e2e-backends: webgpu (slow frames on the default backend: the reduced strobe)
// End-to-end: a heavy session (10,000 strobe copies × 8 levels) stays responsive. stats() gives
// the real interval between drawn frames (requestAnimationFrame to requestAnimationFrame) beside
// the CPU time; during an orbit or a pose drag whose frames exceed the budget a reduced strobe is
// drawn, and the full one comes back on release; sessions keep the full count throughout.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { BACKEND, DESKTOP, playgroundPage, waitFrames } from './lib.mjs';

/** The budget of www/js/editor/responsive.js. */
const BUDGET_MS = 50;
let play;
let page;
let problems;

before(async () => {
  ({ play, page, problems } = await playgroundPage());
  await page.evaluate(() => (document.getElementById('hint').hidden = true));
});

after(async () => {
  await play?.close();
});

const sb = (f, arg) => page.evaluate(f, arg);
const state = () =>
  sb(() => {
    const app = window.screwbender.app;
    return { strobe: app.view.strobe, saved: window.screwbender.session().view.strobe, stats: window.screwbender.stats(), reduced: app.parts.responsive.reduced };
  });

async function heavy() {
  await sb(() => {
    const app = window.screwbender.app;
    app.parts.session.openPreset('l_cycle_rotated');
    app.updateView({ strobe: 10000 });
    app.motion.setOptions({ levels: 8 });
    app.changed();
    app.select(-1);
  });
  await waitFrames(page, 2);
}

/**
 * A gesture with real mouse events from `from`: press, `moves` moves of (dx, dy) with a drawn
 * frame after each, checking the state after each; then release. Returns the states seen.
 */
async function gesture(from, dx, dy, moves = 6) {
  const seen = [];
  await page.mouse.move(from.x, from.y);
  await page.mouse.down();
  for (let k = 1; k <= moves; k++) {
    await page.mouse.move(from.x + dx * k, from.y + dy * k);
    await waitFrames(page, 1);
    seen.push(await state());
  }
  await page.mouse.up();
  await waitFrames(page, 1);
  return seen;
}

test(`${BACKEND}: 10k × 8: an orbit draws a reduced strobe while frames are slow, the full one after`, async () => {
  await heavy();
  assert.equal((await state()).strobe, 10000);
  // Empty space at the lower left of the view.
  const seen = await gesture({ x: 150, y: DESKTOP.height - 100 }, 12, -4);
  const last = seen[seen.length - 1];
  const interval = last.stats.frameIntervalMs;
  assert.ok(Number.isFinite(interval) && interval > 0, `no frame interval: ${JSON.stringify(last.stats)}`);
  // The CPU time of a frame is part of the interval between frames.
  assert.ok(interval >= last.stats.frameMs * 0.5, `interval ${interval} < CPU time ${last.stats.frameMs}`);
  const slow = seen.slice(0, 3).some((s) => s.stats.frameIntervalMs > BUDGET_MS);
  if (slow) {
    const r = seen.find((s) => s.reduced);
    assert.ok(r, `frames of ${seen.map((s) => Math.round(s.stats.frameIntervalMs)).join(', ')} ms but no reduction`);
    // At most a quarter of the full count (responsive.js reduces by at least 4×), never below 16.
    assert.ok(r.strobe <= 10000 / 4 && r.strobe >= 16, `reduced to ${r.strobe}`);
    // How much faster the frames got is a measurement, not a property: logged, not asserted
    // (this machine's speed drifts with its load).
    console.log(`# orbit frame intervals (ms): ${seen.map((s) => Math.round(s.stats.frameIntervalMs)).join(', ')}; reduced to ${r.strobe}`);
  } else assert.ok(seen.every((s) => !s.reduced), 'reduced although frames were within the budget');
  // Sessions keep the full count throughout.
  assert.ok(seen.every((s) => s.saved === 10000), `saved ${seen.map((s) => s.saved)}`);
  const after = await state();
  assert.equal(after.strobe, 10000, 'the full strobe did not come back');
  assert.equal(after.reduced, false);
  assert.match(await page.locator('#stats').textContent(), /10,000 strobe/);
});

test(`${BACKEND}: 10k × 8: a pose drag under load moves the pose exactly and restores the strobe`, async () => {
  await heavy();
  const p0 = Array.from(await sb(() => window.screwbender.poses()));
  const h = await sb(() => window.screwbender.handleOnPage(4));
  const seen = await gesture(h, 8, 5);
  const p1 = Array.from(await sb(() => window.screwbender.poses()));
  assert.ok(Math.hypot(p1[28] - p0[28], p1[29] - p0[29], p1[30] - p0[30]) > 0.05, 'pose 4 did not move');
  for (const k of [0, 1, 2, 3, 5]) assert.deepEqual(p1.slice(7 * k, 7 * k + 7), p0.slice(7 * k, 7 * k + 7), `pose ${k} moved`);
  // The drawn motion after release is the full subdivision of the final poses.
  const check = await sb(() => {
    const app = window.screwbender.app;
    const Motion = app.motion.constructor;
    const m = Motion.fromPoses(app.motion.poses(), app.motion.closed, app.motion.options());
    const a = m.subdivide();
    const b = window.screwbender.refined();
    m.free();
    let worst = 0;
    for (let i = 0; i < a.length; i++) worst = Math.max(worst, Math.abs(a[i] - b[i]));
    return { worst, n: a.length === b.length };
  });
  assert.ok(check.n && check.worst === 0, `refined differs by ${check.worst}`);
  if (seen.slice(0, 3).some((s) => s.stats.frameIntervalMs > BUDGET_MS)) assert.ok(seen.some((s) => s.reduced), 'slow drag frames but no reduction');
  assert.ok(seen.every((s) => s.saved === 10000));
  assert.equal((await state()).strobe, 10000);
  // One undo step takes the whole drag back, reductions and all.
  await page.locator('#view').focus();
  await page.keyboard.press('Control+z');
  assert.deepEqual(Array.from(await sb(() => window.screwbender.poses())), p0);
  assert.equal((await state()).strobe, 10000);
  assert.deepEqual(await sb(() => window.screwbender.errors()), []);
  assert.deepEqual(problems, []);
});
