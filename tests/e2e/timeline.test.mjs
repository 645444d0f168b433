// e2e-backends: webgpu (computed on the CPU, the same on either backend: once)
// End-to-end: the timeline in seconds. The motion's key times drive 3-D playback (the pose at
// time t is u = p(t), reached at the key times); key markers on the timeline retime by mouse drag
// and keys (one undo step per drag; a move past a neighbouring key is refused with a message and
// changes nothing); key velocities edited in the Timing view hold in the playback; bad
// velocities are refused; times and velocities survive a reload (autosave) and a share link, and
// older sessions with the page's view.times still load; on a phone the markers are touch targets.
// The pictures of the timeline for the docs are scripts/docs-shots.mjs's.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { BACKEND, DESKTOP, openPage, playgroundPage, waitFrames } from './lib.mjs';

let play;
let page;
let problems;

before(async () => {
  ({ play, page, problems } = await playgroundPage());
  page.on('pageerror', (e) => process.env.DEBUG_STACK && console.log('STACK', e.stack));
});

after(async () => {
  await play?.close();
});

const sb = (f, arg) => page.evaluate(f, arg);
const TIMES = [0, 1, 3, 4, 6, 7, 9];
const times = () => sb(() => window.screwbender.app.times());
const json = () => sb(() => window.screwbender.app.motion.toJson());
const banner = () => sb(() => (document.getElementById('banner').hidden ? '' : document.querySelector('#banner .msg').textContent));

/** The L cycle (6 poses) with the key times TIMES, nothing else changed. */
async function timed() {
  await sb(() => {
    const { app } = window.screwbender;
    app.run('loadPreset', 'l_cycle_rotated');
    if (app.view.dock) app.parts.dockHost.open('');
    document.getElementById('banner').hidden = true;
  });
  assert.equal(await sb((t) => {
    const { app } = window.screwbender;
    const shown = app.errors.length;
    app.run('setTimes', t);
    return app.errors.slice(shown).join(' ');
  }, TIMES), '', 'setTimes applied without a message');
  assert.deepEqual(await times(), TIMES);
  await waitFrames(page, 1);
}

/** The page position of key marker i's centre, and the timeline's pixels per second. */
async function marker(i) {
  return sb((k) => {
    const m = document.querySelector(`#keys .key-marker[data-key="${k}"]`).getBoundingClientRect();
    const keys = document.getElementById('keys');
    const inset = parseFloat(getComputedStyle(keys).getPropertyValue('--key-inset')) || 0;
    const t = window.screwbender.app.keyTimes();
    const width = keys.getBoundingClientRect().width - 2 * inset;
    return { x: m.left + m.width / 2, y: m.top + m.height / 2, perSecond: width / (t[t.length - 1] - t[0]) };
  }, i);
}

/** Drags with real mouse events from `from` by dx pixels in `steps` moves. */
async function drag(from, dx, steps = 10) {
  await page.mouse.move(from.x, from.y);
  await page.mouse.down();
  for (let k = 1; k <= steps; k++) await page.mouse.move(from.x + (dx * k) / steps, from.y);
  await page.mouse.up();
  await waitFrames(page, 1);
}

test(`${BACKEND}: timed playback reaches the key poses at the key times; the footer shows t and u`, async () => {
  // Uniform timing: pose i at i s, u = t exactly (as before the timeline was in seconds).
  await sb(() => window.screwbender.app.run('loadPreset', 'l_cycle_rotated'));
  for (const t of [0, 0.5, 2.25, 5.75]) {
    const ph = await sb((x) => (window.screwbender.app.viewer.seekTime(x), window.screwbender.app.viewer.playhead()), t);
    assert.equal(ph.t, t);
    assert.equal(ph.u, t, `uniform: u at t = ${t}`);
  }
  await timed();
  // Seeked to each key time, the view shows that key's pose (to 1e-9 in u; the cycle's last
  // time is pose 0 again).
  for (let i = 0; i < TIMES.length; i++) {
    const ph = await sb((x) => (window.screwbender.app.viewer.seekTime(x), window.screwbender.app.viewer.playhead()), TIMES[i]);
    assert.ok(Math.abs(ph.u - (i % 6)) < 1e-9, `u = ${ph.u} at t = ${TIMES[i]}, want ${i % 6}`);
  }
  // Between keys the pose is the retimed one: halfway through the long span 1 → 3 s, not u = 1.5
  // of the uniform timing but p(2) of the motion's own map.
  const mid = await sb(() => {
    const { app } = window.screwbender;
    app.viewer.seekTime(2);
    return { ph: app.viewer.playhead(), p: app.motion.parameterAt(2), text: document.getElementById('time').textContent };
  });
  assert.equal(mid.ph.u, mid.p);
  assert.ok(mid.ph.u > 1 && mid.ph.u < 2);
  assert.equal(mid.text, `t = 2.00 s · u = ${mid.p.toFixed(2)}`);
  // The scrubber runs in seconds: its middle is t = 4.5 s.
  await page.locator('#scrub').fill('500');
  const scrubbed = await sb(() => window.screwbender.app.viewer.playhead());
  assert.ok(Math.abs(scrubbed.t - 4.5) < 1e-9, `scrubbed to t = ${scrubbed.t}`);
  // Playing advances t in seconds, and the pose shown is always p(t) (no duration asserted).
  const start = await sb(() => {
    window.screwbender.app.viewer.seekTime(0.2);
    window.screwbender.app.viewer.setPlaying(true);
    return window.screwbender.app.viewer.playhead().t;
  });
  await page.waitForFunction((t0) => window.screwbender.app.viewer.playhead().t > t0 + 0.05, start, { timeout: 60000 });
  const during = await sb(() => {
    const { app } = window.screwbender;
    const ph = app.viewer.playhead();
    app.viewer.setPlaying(false);
    return { ph, p: app.motion.parameterAt(ph.t) };
  });
  assert.equal(during.ph.u, during.p, `playing: u = ${during.ph.u} at t = ${during.ph.t}`);
  assert.deepEqual(problems, []);
});

test(`${BACKEND}: a key marker dragged with the mouse retimes the key as one undo step`, async () => {
  await timed();
  const m = await marker(2);
  const undoBefore = await sb(() => window.screwbender.app.history.undoStack.length);
  // Half a second later (between its neighbours at 1 s and 4 s).
  await drag(m, 0.5 * m.perSecond);
  const after = await times();
  // Within a pixel and a half of the pointer's path (drags snap to 0.01 s).
  const tol = 1.5 / m.perSecond + 0.01;
  assert.ok(Math.abs(after[2] - 3.5) <= tol, `pose 2 moved to ${after[2]} s, want 3.5 ± ${tol}`);
  assert.deepEqual(after.filter((_, i) => i !== 2), TIMES.filter((_, i) => i !== 2));
  assert.equal(await sb(() => window.screwbender.app.history.undoStack.length), undoBefore + 1, 'one undo step per drag');
  // The playback follows: at the new key time the view shows pose 2.
  const ph = await sb((t) => (window.screwbender.app.viewer.seekTime(t), window.screwbender.app.viewer.playhead()), after[2]);
  assert.ok(Math.abs(ph.u - 2) < 1e-9, `u = ${ph.u} at the dragged key`);
  // The marker's accessible value follows.
  assert.equal(await page.locator('#keys .key-marker[data-key="2"]').getAttribute('aria-valuenow'), String(after[2]));
  await sb(() => window.screwbender.app.parts.session.undo());
  assert.deepEqual(await times(), TIMES);
  await sb(() => window.screwbender.app.parts.session.redo());
  assert.deepEqual(await times(), after);
  assert.deepEqual(problems, []);
});

test(`${BACKEND}: a marker dragged or moved by keys past its neighbour is refused with a message; nothing changes`, async () => {
  await timed();
  const before = await json();
  const undoBefore = await sb(() => window.screwbender.app.history.undoStack.length);
  const m = await marker(2);
  // Pose 2 (3 s) dragged to about 5 s, past pose 3 (4 s).
  await drag(m, 2 * m.perSecond);
  assert.match(await banner(), /Not retimed: pose 2 cannot move to .* at or after pose 3's key \(4 s\).*nothing changed/);
  assert.equal(await json(), before);
  assert.equal(await sb(() => window.screwbender.app.history.undoStack.length), undoBefore);
  assert.equal(await page.locator('#keys .key-marker[data-key="2"]').getAttribute('aria-valuenow'), '3');
  // Keys: a focused marker moves by 0.1 s (Shift: 0.01 s).
  await sb(() => (document.getElementById('banner').hidden = true));
  const key = page.locator('#keys .key-marker[data-key="3"]');
  await key.focus();
  await page.keyboard.press('ArrowRight');
  assert.equal((await times())[3], 4.1);
  await page.keyboard.press('Shift+ArrowLeft');
  assert.equal((await times())[3], 4.09);
  // Towards pose 4 at 6 s: 19 steps reach 5.99 s, the 20th (6.09 s) is refused.
  for (let k = 0; k < 19; k++) await page.keyboard.press('ArrowRight');
  assert.ok(Math.abs((await times())[3] - 5.99) < 1e-9, `${(await times())[3]}`);
  const atEdge = await json();
  await page.keyboard.press('ArrowRight');
  assert.match(await banner(), /Not retimed: pose 3 cannot move to 6\.09 s: at or after pose 4's key \(6 s\)/);
  assert.equal(await json(), atEdge);
  // The first key cannot pass the second either (leftwards from the second).
  await page.locator('#keys .key-marker[data-key="1"]').focus();
  for (let k = 0; k < 9; k++) await page.keyboard.press('ArrowLeft');
  assert.ok(Math.abs((await times())[1] - 0.1) < 1e-9);
  const before0 = await json();
  await page.keyboard.press('ArrowLeft');
  assert.match(await banner(), /pose 1 cannot move to 0 s: at or before pose 0's key \(0 s\)/);
  assert.equal(await json(), before0);
  assert.deepEqual(problems, []);
});

test(`${BACKEND}: a run of arrow presses on one marker is one undo step; idle, blur, another marker or an undo start a new one`, async () => {
  await timed();
  const undoLength = () => sb(() => window.screwbender.app.history.undoStack.length);
  // The time stamp of every arrow keydown on a marker (the page merges by the same stamps).
  await sb(() => {
    window.__markerKeys = [];
    document.getElementById('keys').addEventListener('keydown', (e) => e.key.startsWith('Arrow') && window.__markerKeys.push({ key: e.target.dataset.key, at: e.timeStamp }), true);
  });
  /**
   * The undo steps the presses recorded since `from` should make: a new step at a run's first
   * press and after a gap of a second or more (MERGE_IDLE_MS).
   */
  const expectedSteps = async (from) => {
    const keys = await sb(() => window.__markerKeys);
    let steps = 0;
    for (let k = from; k < keys.length; k++) {
      if (k === from || keys[k].key !== keys[k - 1].key || keys[k].at - keys[k - 1].at >= 1000) steps++;
    }
    return { steps, count: keys.length };
  };
  const m3 = page.locator('#keys .key-marker[data-key="3"]');
  await m3.focus();
  let u0 = await undoLength();
  for (const k of ['ArrowRight', 'ArrowRight', 'ArrowRight', 'Shift+ArrowRight', 'Shift+ArrowRight']) await page.keyboard.press(k);
  assert.ok(Math.abs((await times())[3] - 4.32) < 1e-9, `${(await times())[3]}`);
  let want = await expectedSteps(0);
  assert.equal(want.count, 5);
  assert.equal((await undoLength()) - u0, want.steps, 'a quick run of presses on one marker: one undo step (unless the machine stalled a second)');
  for (let k = 0; k < want.steps; k++) await sb(() => window.screwbender.app.parts.session.undo());
  assert.deepEqual(await times(), TIMES, 'undoing the run gives the times before it');
  await sb(() => window.screwbender.app.parts.session.redo());
  // Another marker (Tab: the next one) starts a step; so does coming back (Shift+Tab).
  await sb(() => (window.__markerKeys = []));
  await m3.focus();
  u0 = await undoLength();
  await page.keyboard.press('ArrowRight');
  await page.keyboard.press('Tab');
  assert.equal(await sb(() => document.activeElement.dataset.key), '4');
  await page.keyboard.press('ArrowLeft');
  await page.keyboard.press('Shift+Tab');
  await page.keyboard.press('ArrowRight');
  want = await expectedSteps(0);
  assert.ok(want.steps === 3, `three runs (${JSON.stringify(await sb(() => window.__markerKeys))})`);
  assert.equal((await undoLength()) - u0, 3, 'marker 3, marker 4, marker 3 again: three undo steps');
  // A second idle starts a new step.
  u0 = await undoLength();
  await page.waitForTimeout(1100);
  await page.keyboard.press('ArrowRight');
  assert.equal((await undoLength()) - u0, 1, 'a press after a second idle: a new step');
  // A blur ends the run.
  u0 = await undoLength();
  await sb(() => document.activeElement.blur());
  await m3.focus();
  await page.keyboard.press('ArrowRight');
  assert.equal((await undoLength()) - u0, 1, 'a press after a blur: a new step');
  // An undo in the middle of a run: the next press is a new step (never folded into a step
  // that is no longer on the stack), and the redo stack is dropped.
  await sb(() => window.screwbender.app.parts.session.undo());
  const undone = await times();
  u0 = await undoLength();
  await page.keyboard.press('ArrowRight');
  assert.equal((await undoLength()) - u0, 1, 'a press after an undo: a new step');
  assert.equal(await sb(() => window.screwbender.app.history.canRedo), false);
  await sb(() => window.screwbender.app.parts.session.undo());
  assert.deepEqual(await times(), undone);
  assert.deepEqual(problems, []);
});

test(`${BACKEND}: phone (390×844, touch): close markers split their 44 px hit areas; a tap or drag goes to the nearest marker`, async () => {
  const ctx = await play.browser.newContext({ viewport: { width: 390, height: 844 }, hasTouch: true, isMobile: true, deviceScaleFactor: 2 });
  try {
    const { page: phone, problems: phoneProblems } = await openPage(ctx, play.url, BACKEND);
    const ev = (f, arg) => phone.evaluate(f, arg);
    await ev(() => {
      const { app } = window.screwbender;
      app.run('loadPreset', 'l_cycle_rotated');
      app.parts.dockHost.open('');
      document.getElementById('banner').hidden = true;
    });
    assert.equal(await ev((t) => {
    const { app } = window.screwbender;
    const shown = app.errors.length;
    app.run('setTimes', t);
    return app.errors.slice(shown).join(' ');
  }, TIMES), '', 'setTimes applied without a message');
    await waitFrames(phone, 1);
    const box = (k) =>
      ev((i) => document.querySelector(`#keys .key-marker[data-key="${i}"]`).getBoundingClientRect().toJSON(), k);
    // Keys 2 and 3 brought close: their centres about 30 px apart (the visible marks, 10 px
    // wide, 20 px apart), less than the 44 px boxes, so the boxes overlap.
    const b0 = await box(0);
    const b6 = await box(6);
    const perSecond = (b6.x - b0.x) / 9;
    const close = [0, 1, 3, Number((3 + 30 / perSecond).toFixed(2)), 6, 7, 9];
    assert.equal(await ev((t) => {
    const { app } = window.screwbender;
    const shown = app.errors.length;
    app.run('setTimes', t);
    return app.errors.slice(shown).join(' ');
  }, close), '', 'setTimes applied without a message');
    await waitFrames(phone, 1);
    const [l, r] = [await box(2), await box(3)];
    assert.ok(l.width >= 44 - 0.5 && l.height >= 44 - 0.5, `marker ${l.width}×${l.height}`);
    const lc = l.x + l.width / 2;
    const rc = r.x + r.width / 2;
    const y = l.y + l.height / 2;
    assert.ok(rc - lc > 24 && rc - lc < 36, `centres ${rc - lc} px apart`);
    assert.ok(r.x < lc + 12 && l.right > rc - 12, 'the boxes overlap where the taps land');
    // The right marker is drawn on top over the overlap: without the split it takes both taps.
    assert.equal(await ev(([x, yy]) => document.elementFromPoint(x, yy).dataset.key, [lc + 12, y]), '3');
    await phone.touchscreen.tap(lc + 12, y);
    assert.equal(await ev(() => document.activeElement.dataset.key), '2', 'a tap 12 px right of the left marker selects the left one');
    await phone.touchscreen.tap(rc - 12, y);
    assert.equal(await ev(() => document.activeElement.dataset.key), '3', 'a tap 12 px left of the right marker selects the right one');
    // A touch drag from 12 px right of the left marker moves the left key by the finger's
    // travel (10 px leftwards; the key does not jump under the finger).
    const cdp = await ctx.newCDPSession(phone);
    const at = (x) => [{ x, y, id: 0 }];
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: at(lc + 12) });
    for (let k = 1; k <= 5; k++) await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: at(lc + 12 - 2 * k) });
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
    await waitFrames(phone, 1);
    const after = await ev(() => window.screwbender.app.times());
    const tol = 1.5 / perSecond + 0.01;
    assert.ok(Math.abs(after[2] - (3 - 10 / perSecond)) <= tol, `left key at ${after[2]} s, want ${3 - 10 / perSecond} ± ${tol}`);
    assert.deepEqual(after.filter((_, i) => i !== 2), close.filter((_, i) => i !== 2), 'only the left key moved');
    // The visible marks stay small: the mark (the ::after triangle) is 10 px wide.
    const mark = await ev(() => getComputedStyle(document.querySelector('#keys .key-marker'), '::after').borderLeftWidth);
    assert.equal(mark, '5px');
    assert.deepEqual(phoneProblems, []);
  } finally {
    await ctx.close();
  }
});

test(`${BACKEND}: a key velocity edited in the Timing view holds in the playback; bad velocities are refused`, async () => {
  await timed();
  await sb(() => window.screwbender.app.parts.dockHost.open('timing'));
  await sb(() => window.screwbender.flushViews());
  const section = '#dock section[data-view=timing]';
  const vin = page.locator(`${section} input[aria-label^="velocity of pose"]`);
  assert.equal(await vin.count(), 6, 'one velocity per control pose');
  await vin.nth(1).fill('0.25');
  await vin.nth(1).dispatchEvent('change');
  await sb(() => window.screwbender.flushViews());
  assert.deepEqual(await sb(() => window.screwbender.app.velocities()), [null, 0.25, null, null, null, null]);
  // Finite differences of u over t at the key, through the playhead: p is C¹ but p'' may jump
  // at the key, so the central difference is off by O(h) (about 1e-6 for h = 1e-6) plus
  // rounding (1e-16 / h).
  const h = 1e-6;
  const [lo, hi] = await sb((hh) => {
    const { app } = window.screwbender;
    const at = (t) => (app.viewer.seekTime(t), app.viewer.playhead().u);
    return [at(1 - hh), at(1 + hh)];
  }, h);
  const rate = (hi - lo) / (2 * h);
  assert.ok(Math.abs(rate - 0.25) < 1e-5, `du/dt at pose 1 = ${rate}, set 0.25`);
  // Refused, each with a message, changing nothing: negative, and too fast (time would run
  // backwards next to the key).
  const s0 = await sb(() => JSON.stringify(window.screwbender.session()));
  for (const [bad, why] of [['-1', /velocities\[2\]/], ['50', /velocities\[2\].*backwards/]]) {
    await vin.nth(2).fill(bad);
    await vin.nth(2).dispatchEvent('change');
    assert.match(await page.locator(`${section} [role=status]`).textContent(), why, `velocity ${bad}`);
    assert.equal(await vin.nth(2).inputValue(), '', `a refused velocity (${bad}) shows the one in use again`);
    assert.equal(await sb(() => JSON.stringify(window.screwbender.session())), s0);
  }
  // Blank again: free.
  await vin.nth(1).fill('');
  await vin.nth(1).dispatchEvent('change');
  assert.equal(await sb(() => window.screwbender.app.velocities()), null);
  await sb(() => window.screwbender.app.parts.dockHost.open(''));
  assert.deepEqual(problems, []);
});

test(`${BACKEND}: the CSV and glTF exports follow the motion's key times and velocities`, async () => {
  await timed();
  assert.equal(await sb(() => {
    const { app } = window.screwbender;
    const shown = app.errors.length;
    app.run('setVelocities', [null, 0.25, null, 2, null, null]);
    return app.errors.slice(shown).join(' ');
  }), '', 'setVelocities applied without a message');
  const out = await sb(async () => {
    const { exportMotion } = await import('./js/editor/files.js');
    const { app } = window.screwbender;
    const csv = await exportMotion(app, 'csv', { tolerance: 1e-4 }, { save: false });
    const rows = new TextDecoder().decode(csv.data).trim().split('\n');
    // Each row's (t, u) against the playback's map u = p(t) (which wraps u = 6 to 0 at 9 s).
    let worst = 0;
    for (const row of rows.slice(1)) {
      const [t, u] = row.split(',').map(Number);
      const d = Math.abs(u - app.motion.parameterAt(t));
      worst = Math.max(worst, Math.min(d, Math.abs(d - 6)));
    }
    const gltf = await exportMotion(app, 'gltf', {}, { save: false });
    const json = JSON.parse(new TextDecoder().decode(gltf.data));
    const input = json.accessors[json.animations[0].samplers[0].input];
    return { header: rows[0], count: rows.length - 1, last: rows[rows.length - 1].split(',').slice(0, 2).map(Number), worst, gltf: [input.min[0], input.max[0]] };
  });
  assert.equal(out.header.slice(0, 4), 't,u,');
  assert.ok(out.count > 100, `${out.count} rows`);
  assert.deepEqual(out.last, [9, 6]);
  // The CSV's parameter column is the retiming with the velocities (to rounding).
  assert.ok(out.worst < 1e-9, `CSV u off p(t) by ${out.worst}`);
  assert.ok(Math.abs(out.gltf[0]) < 1e-6 && Math.abs(out.gltf[1] - 9) < 1e-6, `glTF runs over ${out.gltf}`);
  assert.deepEqual(problems, []);
});

test(`${BACKEND}: times and velocities survive a reload and a share link; old sessions' view.times load`, async () => {
  await timed();
  assert.equal(await sb(() => {
    const { app } = window.screwbender;
    const shown = app.errors.length;
    app.run('setVelocities', [null, 0.5, null, null, null, null]);
    return app.errors.slice(shown).join(' ');
  }), '', 'setVelocities applied without a message');
  const want = await json();
  const link = await sb(() => window.screwbender.app.parts.session.shareLink());
  // Reload: the autosave restores the motion with its timing.
  await sb(() => window.screwbender.app.parts.session.autosave());
  await page.reload();
  await sb(() => window.screwbender.ready);
  assert.equal(await json(), want);
  assert.deepEqual(await times(), TIMES);
  // The share link, in a fresh page of its own (its own storage is the context's: cleared first).
  const ctx = await play.browser.newContext({ viewport: DESKTOP });
  try {
    const { page: other, problems: otherProblems } = await openPage(ctx, play.url, BACKEND, { path: link.slice(link.indexOf('#')) });
    assert.equal(await other.evaluate(() => window.screwbender.app.motion.toJson()), want);
    // An older session: the times in view.times, the document without them.
    const old = await sb(async () => {
      const { encodeHash } = await import('./js/share-link.js');
      const s = window.screwbender.session();
      delete s.document.times;
      delete s.document.velocities;
      s.view.times = [0, 2, 3, 4, 5, 6, 8];
      return encodeHash(s);
    });
    // Given to the open page (as if pasted into its address bar: a hashchange, no load).
    await other.evaluate((h) => {
      location.hash = `#s=${h}`;
    }, old);
    await other.waitForFunction(() => window.screwbender.app.times()?.[1] === 2);
    assert.deepEqual(await other.evaluate(() => window.screwbender.app.times()), [0, 2, 3, 4, 5, 6, 8]);
    assert.equal(await other.evaluate(() => 'times' in window.screwbender.session().view), false, 'view.times is not saved again');
    assert.deepEqual(otherProblems, []);
  } finally {
    await ctx.close();
  }
  assert.deepEqual(problems, []);
});

test(`${BACKEND}: a <screw-bender> figure seeks in seconds of its motion's key times; its time event gives t and u`, async () => {
  const fig = await play.context.newPage();
  const figProblems = [];
  fig.on('pageerror', (e) => figProblems.push(`pageerror: ${e.message}`));
  fig.on('console', (m) => m.type() === 'error' && figProblems.push(`console: ${m.text()}`));
  try {
    await fig.goto(`${play.url}examples/course.html`);
    await fig.waitForFunction(() => customElements.get('screw-bender'));
    await fig.evaluate(() => {
      const el = document.getElementById('fig-fourpoint');
      el.scrollIntoView({ block: 'center' });
      return el.ready;
    });
    await fig.evaluate((t) => {
      const el = document.getElementById('fig-fourpoint');
      el.document = { ...el.document, times: t };
    }, TIMES);
    await fig.waitForFunction((n) => document.getElementById('fig-fourpoint').document?.times?.length === n, TIMES.length, { timeout: 30000 });
    const details = await fig.evaluate((t) => {
      const el = document.getElementById('fig-fourpoint');
      const seen = [];
      el.addEventListener('time', (e) => seen.push(e.detail));
      for (const x of t) el.seek(x);
      el.seek(2);
      return seen;
    }, TIMES);
    assert.equal(details.length, TIMES.length + 1, 'one time event per seek');
    TIMES.forEach((t, i) => {
      const d = details[i];
      // The cycle's last time is its first pose again (t wraps to the start of the period).
      assert.equal(d.t, i < 6 ? t : 0);
      assert.ok(Math.abs(d.u - (i % 6)) < 1e-9, `figure: u = ${d.u} at t = ${t}`);
      assert.deepEqual([d.start, d.end], [0, 9]);
    });
    assert.ok(details[7].u > 1 && details[7].u < 2, `u = ${details[7].u} at 2 s (between poses 1 and 2)`);
    assert.deepEqual(figProblems, []);
  } finally {
    await fig.close();
  }
});

test(`${BACKEND}: on a phone, a shared timed motion's key markers are touch targets of 44 px, on screen`, async () => {
  await timed();
  await sb(async () => {
    const { app } = window.screwbender;
    app.run('setVelocities', [null, 0.25, null, null, null, null]);
    await app.parts.dockHost.open('timing');
    app.viewer.seekTime(3.5);
  });
  const link = await sb(() => window.screwbender.app.parts.session.shareLink());
  const ctx = await play.browser.newContext({ viewport: { width: 390, height: 844 }, hasTouch: true, isMobile: true, deviceScaleFactor: 2 });
  try {
    const { page: phone, problems: phoneProblems } = await openPage(ctx, play.url, BACKEND, { path: link.slice(link.indexOf('#')) });
    await phone.evaluate(() => window.screwbender.app.parts.dockHost.open(''));
    // Every marker is a touch target of at least 44 px, on screen.
    const boxes = await phone.evaluate(() => [...document.querySelectorAll('#keys .key-marker')].map((m) => m.getBoundingClientRect().toJSON()));
    assert.equal(boxes.length, 7);
    for (const b of boxes) {
      assert.ok(b.width >= 44 - 0.5 && b.height >= 44 - 0.5, `marker ${b.width}×${b.height}`);
      assert.ok(b.left >= -0.5 && b.right <= 390.5 && b.top >= -0.5 && b.bottom <= 844.5, `marker off screen: ${JSON.stringify(b)}`);
    }
    assert.deepEqual(phoneProblems, []);
  } finally {
    await ctx.close();
  }
  assert.deepEqual(problems, []);
});
