// e2e-backends: webgpu (computed on the CPU, the same on either backend: once)
// End-to-end: the teaching surfaces tell the truth and stay out of the way.
//
//   E2E_BACKEND=webgpu|webgl2 node --test tests/e2e/teaching-truth.test.mjs
//
// The methods table's converged metrics on the L cycle (4-point and Catmull–Rom + Squad C¹,
// SLERP + linear's jumps in closed form and its accelerations impulses); Ease in / out's zero
// velocity at both ends, one undo away (the lesson card clear of the step's highlight, the open
// dock and the selected pose's handle at every size: lesson-layout.test.mjs); lessons by id
// (?lesson=screw), the summary and the why of a wrong answer; the phone's
// panel folded after a preset pick and the tour; the first-visit hint gone after an orbit; the
// toolbar's states readable at 4.5:1. Screenshots: artifacts/e2e-<backend>/truth-*.png.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { BACKEND, DESKTOP, mouseDrag, openPage, playgroundPage, waitFrames } from './lib.mjs';

let play;
let page;
let problems;

before(async () => {
  ({ play, page, problems } = await playgroundPage());
});

after(async () => {
  await play?.close();
});

const sb = (f, arg) => page.evaluate(f, arg);
const SIZES = [[1280, 800], [390, 844], [844, 390]];

test(`${BACKEND}: the methods table on the L cycle: C¹ jumps are 0, SLERP + linear's are its closed form and its accelerations impulses`, async () => {
  await page.setViewportSize(DESKTOP);
  const r = await sb(async () => {
    const { app } = window.screwbender;
    app.run('loadPreset', 'l_cycle_rotated');
    await window.screwbender.openView('methods');
    app.dock.current.select(['fourpoint', 'decoupled', 'slerp']);
    window.screwbender.flushViews();
    const rows = [...document.querySelectorAll('#dock section[data-view=methods] table.metrics tr')];
    const cells = Object.fromEntries(rows.slice(1).map((tr) => [tr.cells[0].textContent, [...tr.cells].slice(3).map((c) => ({ text: c.textContent, limit: c.dataset.limit }))]));
    // SLERP + linear in closed form: on span i the body point p moves with (o_{i+1} − o_i) + ω_i × R_i p.
    const m = app.motion;
    const n = m.poseCount;
    const P = Array.from({ length: n }, (_, i) => m.pose(i));
    const qmul = (a, b) => [a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3], a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2], a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1], a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]];
    const conj = (q) => [q[0], -q[1], -q[2], -q[3]];
    const rot = (q, v) => qmul(qmul(q, [0, ...v]), conj(q)).slice(1);
    const rotvec = (q) => {
      let d = q[0] < 0 ? q.map((x) => -x) : q;
      const s = Math.hypot(d[1], d[2], d[3]);
      const ang = 2 * Math.atan2(s, d[0]);
      return s < 1e-15 ? [0, 0, 0] : [d[1], d[2], d[3]].map((x) => (x / s) * ang);
    };
    const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
    const span = (i) => {
      const a = P[i % n];
      const b = P[(i + 1) % n];
      return { d: b.origin.map((x, k) => x - a.origin[k]), w: rotvec(qmul(b.rotation, conj(a.rotation))) };
    };
    let vj = 0;
    let wj = 0;
    for (let i = 0; i < n; i++) {
      const L = span(i + n - 1);
      const R = span(i);
      wj = Math.max(wj, Math.hypot(...R.w.map((x, k) => x - L.w[k])));
      for (const p of app.viewer.bodyPoints().slice(0, 2)) {
        const rp = rot(P[i].rotation, p);
        const vl = L.d.map((x, k) => x + cross(L.w, rp)[k]);
        const vr = R.d.map((x, k) => x + cross(R.w, rp)[k]);
        vj = Math.max(vj, Math.hypot(...vr.map((x, k) => x - vl[k])));
      }
    }
    const table = app.dock.current.lastTable;
    return { cells, vj, wj, slerp: table.rows[2], text: document.querySelector('#dock section[data-view=methods]').textContent };
  });
  for (const row of ['velocity jump', 'angular velocity jump']) {
    assert.equal(r.cells[row][0].text, '0', `4-point ${row}`);
    assert.equal(r.cells[row][0].limit, 'zero');
    assert.equal(r.cells[row][1].text, '0', `Catmull–Rom + Squad ${row}`);
    assert.equal(r.cells[row][2].limit, 'value');
  }
  assert.ok(Math.abs(r.slerp.velocity_jump.value - r.vj) <= 1e-6 * r.vj, `SLERP velocity jump ${r.slerp.velocity_jump.value} vs ${r.vj}`);
  assert.ok(Math.abs(r.slerp.angular_velocity_jump.value - r.wj) <= 1e-6 * r.wj, `SLERP angular velocity jump ${r.slerp.angular_velocity_jump.value} vs ${r.wj}`);
  // The cell shows that value, rounded to the digits its error allows.
  assert.ok(Math.abs(Number(r.cells['velocity jump'][2].text) - r.vj) <= 5e-3 * r.vj, `SLERP cell ${r.cells['velocity jump'][2].text} vs ${r.vj}`);
  for (const row of ['acceleration jump', 'angular accel. jump', '∫|α|²', '∫|a|² (first point)']) {
    assert.equal(r.cells[row][2].limit, 'impulse', `SLERP ${row}`);
    assert.equal(r.cells[row][2].text, '∞ (impulse)');
    assert.notEqual(r.cells[row][0].limit, 'impulse', `4-point ${row} is not an impulse`);
  }
  // Finite values: the 4-point's integrals are real numbers, not 0.
  assert.ok(Number(r.cells['∫|α|²'][0].text) > 1, `4-point ∫|α|² ${r.cells['∫|α|²'][0].text}`);
  assert.doesNotMatch(r.text, /screwbender compare|lower is better for every/);
  assert.deepEqual(problems, []);
});

/** After Ease in / out: the times and velocities in use, du/dt of the timing map at its first, middle and last sample, and the banner. */
const easeState = () =>
  sb(async () => {
    const { app } = window.screwbender;
    const { timingMap } = await app.analysis();
    const m = app.motion;
    const d = timingMap(app.keyTimes(), m.poseCount, m.closed, 400, app.velocities() ?? undefined);
    return { times: app.keyTimes(), velocities: app.velocities(), first: d[2], last: d[d.length - 1], mid: d[3 * 200 + 2], banner: document.querySelector('#banner .msg').textContent };
  });

test(`${BACKEND}: Ease in / out gives du/dt = 0 at both ends, keeps the times, says so, and one undo takes it back`, async () => {
  await page.setViewportSize(DESKTOP);
  await sb(async () => {
    const { app } = window.screwbender;
    app.run('loadPreset', 'cylinder5');
    app.run('setTimes', [0, 1, 3, 4, 6, 7]);
    await window.screwbender.openView('timing');
    window.screwbender.flushViews();
  });
  await page.locator('#dock section[data-view=timing] button', { hasText: 'Ease in / out' }).click();
  const r = await easeState();
  assert.deepEqual(r.times, [0, 1, 3, 4, 6, 7], 'the times stay');
  // The samples of a cycle's map end one step before its end time: du/dt falls towards 0 there.
  assert.ok(Math.abs(r.first) < 1e-12 && Math.abs(r.last) < 0.1 * r.mid, `du/dt at the ends: ${r.first}, ${r.last} (middle ${r.mid})`);
  assert.ok(r.mid > 0.1, `it moves in between: du/dt ${r.mid}`);
  // A cycle starts and ends at pose 0.
  assert.deepEqual(r.velocities, [0, null, null, null, null]);
  assert.match(r.banner, /Ease in \/ out: velocity 0 at pose 0 \(start and end of the cycle\); times unchanged\. Undo/);
  await page.locator('#t-undo').click();
  assert.equal(await sb(() => window.screwbender.app.velocities()), null, 'one undo gives the free velocities back');
  assert.deepEqual(await sb(() => window.screwbender.app.keyTimes()), [0, 1, 3, 4, 6, 7]);
  // An open motion: both end poses.
  await sb(() => {
    window.screwbender.app.run('setClosed', false);
    window.screwbender.flushViews();
  });
  await page.locator('#dock section[data-view=timing] button', { hasText: 'Ease in / out' }).click();
  const open = await easeState();
  assert.deepEqual(open.velocities, [0, null, null, null, 0]);
  assert.ok(Math.abs(open.first) < 1e-12 && Math.abs(open.last) < 1e-12, `open: du/dt at the ends ${open.first}, ${open.last}`);
  assert.match(open.banner, /velocity 0 at poses 0 and 4/);
  assert.deepEqual(problems, []);
});

test(`${BACKEND}: ?lesson=screw opens lesson 1 by its id; a wrong answer says why; Finish shows the summary and the next lesson`, async () => {
  const context = await play.browser.newContext({ viewport: DESKTOP });
  try {
    const { page: p, problems: pp } = await openPage(context, play.url, BACKEND, { path: `${BACKEND === 'webgl2' ? '&' : '?'}lesson=screw` });
    await p.evaluate(() => window.screwbender.lessons.then((L) => L.ready));
    assert.equal(await p.evaluate(() => window.screwbender.lessons.then((L) => L.lesson?.id)), 'screw');
    // The last step's question: a wrong answer, checked with the real buttons.
    const last = await p.evaluate(() => window.screwbender.lessons.then((L) => {
      L.go(L.lesson.steps.length - 1);
      return L.lesson.steps.length;
    }));
    await p.locator('#lesson .choices label').nth(0).click();
    await p.locator('#lesson button.check').click();
    assert.match(await p.locator('#lesson .feedback').textContent(), /Not this one: lerp \+ slerp moves the chosen origin on a straight line/);
    await p.locator('#lesson .choices label').nth(1).click();
    await p.locator('#lesson button.check').click();
    assert.match(await p.locator('#lesson .feedback').textContent(), /Correct|right/i);
    await p.locator('#lesson button.next').click();
    await p.locator('#lesson.summary').waitFor();
    const text = await p.locator('#lesson').textContent();
    assert.match(text, /Lesson complete/);
    assert.match(text, /Exercises solved: \d of \d\./);
    assert.match(text, /Try next: Continuous, but the velocity jumps/);
    await p.locator('#lesson button.start-next').click();
    await p.waitForFunction(() => window.screwbender.lessons.then((L) => L.lesson?.id === 'polyscrew'));
    assert.equal(last > 2, true);
    assert.deepEqual(pp, []);
  } finally {
    await context.close();
  }
});

test(`${BACKEND}: on a phone the panel folds after a preset pick and at the end of the tour`, async () => {
  const context = await play.browser.newContext({ viewport: { width: 390, height: 844 }, hasTouch: true });
  try {
    const { page: p, problems: pp } = await openPage(context, play.url, BACKEND);
    await p.evaluate(() => window.screwbender.app.ui.gui.open());
    await p.locator('#panel').getByText(/^Preset: /).click();
    await p.locator('#presets .preset').nth(2).click();
    await waitFrames(p, 2);
    const r = await p.evaluate(() => {
      const gui = window.screwbender.app.ui.gui;
      const panel = document.getElementById('panel').getBoundingClientRect();
      const view = document.querySelector('#view').getBoundingClientRect();
      return { closed: gui._closed, panelBottom: panel.bottom, viewMid: view.top + view.height / 2 };
    });
    assert.equal(r.closed, true, 'the panel folded');
    assert.ok(r.panelBottom < r.viewMid, `the folded panel (bottom ${r.panelBottom}) leaves the 3-D view uncovered`);
    // The tour opens the panel to point into it; its end folds it.
    await p.evaluate(() => window.screwbender.lessons.then((L) => L.open('tour', { resume: false })));
    await p.evaluate(() => window.screwbender.app.ui.gui.open());
    await p.evaluate(() => window.screwbender.lessons.then((L) => L.go(L.lesson.steps.length)));
    assert.equal(await p.evaluate(() => window.screwbender.app.ui.gui._closed), true, 'the panel folded at the end of the tour');
    assert.deepEqual(pp, []);
  } finally {
    await context.close();
  }
});

test(`${BACKEND}: the first-visit hint goes after the first orbit`, async () => {
  const context = await play.browser.newContext({ viewport: { width: 844, height: 390 } });
  try {
    const { page: p, problems: pp } = await openPage(context, play.url, BACKEND);
    const hint = p.locator('#hint');
    assert.ok(await hint.isVisible(), 'the hint shows on a first visit');
    // An orbit: a drag over empty background near the top right of the view.
    const v = await p.evaluate(() => {
      const r = document.querySelector('#view').getBoundingClientRect();
      return { x: r.left + r.width * 0.55, y: r.top + r.height * 0.18 };
    });
    await mouseDrag(p, v, 80, 30);
    assert.ok(!(await hint.isVisible()), 'the hint left after the orbit');
    await p.reload();
    await p.evaluate(() => window.screwbender.ready);
    assert.ok(!(await hint.isVisible()), 'and stays away');
    assert.deepEqual(pp, []);
  } finally {
    await context.close();
  }
});

test(`${BACKEND}: every toolbar state (off, on, hover on either, disabled) reads at 4.5:1 or more`, async () => {
  // A window tall enough for the buttons' names (shorter ones put them in the tooltips).
  await page.setViewportSize({ width: 1440, height: 900 });
  await sb(() => {
    const { app } = window.screwbender;
    app.run('loadPreset', 'cylinder5');
    app.select(-1);
    app.setMode('translate');
  });
  /** Contrast of the label of button `sel` against what is under it (its background over the toolbar's over the page's). */
  const contrast = (sel) =>
    sb((s) => {
      const b = document.querySelector(s);
      const rgba = (c) => (c.match(/[\d.]+/g) ?? []).map(Number);
      const over = (top, bottom) => {
        const a = top[3] ?? 1;
        return [0, 1, 2].map((k) => top[k] * a + bottom[k] * (1 - a));
      };
      let bg = [232, 236, 241];
      const chain = [];
      for (let e = b; e; e = e.parentElement) chain.unshift(e);
      for (const e of chain) {
        const c = rgba(getComputedStyle(e).backgroundColor);
        if (c.length >= 3 && (c[3] ?? 1) > 0) bg = over(c, bg);
      }
      const lum = (c) => {
        const l = c.map((v) => {
          const x = v / 255;
          return x <= 0.04045 ? x / 12.92 : ((x + 0.055) / 1.055) ** 2.4;
        });
        return 0.2126 * l[0] + 0.7152 * l[1] + 0.0722 * l[2];
      };
      const span = b.querySelector('span');
      const st = getComputedStyle(span ?? b);
      const fg = over(rgba(st.color), bg);
      const opacity = Number(getComputedStyle(b).opacity);
      const shown = over([...fg, opacity], bg);
      const [L1, L2] = [lum(shown), lum(bg)].sort((x, y) => y - x);
      return (L1 + 0.05) / (L2 + 0.05);
    }, sel);
  const cases = [];
  cases.push(['off (Rotate)', await contrast('#t-rotate')]);
  cases.push(['on (Move)', await contrast('#t-translate')]);
  await page.hover('#t-translate');
  cases.push(['on, hovered (Move)', await contrast('#t-translate')]);
  await page.hover('#t-rotate');
  cases.push(['off, hovered (Rotate)', await contrast('#t-rotate')]);
  assert.equal(await page.locator('#t-redo').isDisabled(), true);
  cases.push(['disabled (Redo)', await contrast('#t-redo')]);
  for (const [what, c] of cases) assert.ok(c >= 4.5, `${what}: contrast ${c.toFixed(2)}:1`);
  assert.deepEqual(problems, []);
});

test(`${BACKEND}: the Top view frames the poses below the header, above the timeline and clear of the panel`, async () => {
  for (const [w, h] of SIZES) {
    await page.setViewportSize({ width: w, height: h });
    // A frame after the resize: the view knows its new size before the Top view frames the poses.
    await waitFrames(page, 1);
    await sb(() => {
      const { app } = window.screwbender;
      app.run('loadPreset', 'l_cycle_rotated');
      app.select(-1);
      app.ui.gui.open();
    });
    if (w < 760 || h < 500) await sb(() => window.screwbender.app.ui.gui.close());
    await page.focus('#view');
    await page.keyboard.press('Shift+T');
    await waitFrames(page, 2);
    const g = await sb(async () => {
      const { app } = window.screwbender;
      const { toPage } = await import('./js/figure/picking.js');
      // The body points' trajectories (what the view draws of the motion), 120 samples each.
      const traj = [];
      for (const b of app.viewer.bodyPoints()) {
        const d = app.motion.timedKinematics(120, b);
        for (let k = 0; k < 120; k++) traj.push(toPage(app.viewer, [d[16 * k + 1], d[16 * k + 2], d[16 * k + 3]]));
      }
      const rect = (id) => {
        const e = document.getElementById(id);
        if (!e || e.hidden) return null;
        const r = e.getBoundingClientRect();
        return r.width > 0 ? { left: r.left, top: r.top, right: r.right, bottom: r.bottom } : null;
      };
      return {
        pts: [...Array.from({ length: app.motion.poseCount }, (_, k) => app.viewer.screenOfPose(k)), ...traj],
        title: rect('title'),
        hint: rect('hint'),
        timeline: rect('timeline'),
        panel: rect('panel'),
        toolbar: rect('toolbar'),
      };
    });
    for (const [k, p] of g.pts.entries()) {
      const inside = (r) => r && p.x >= r.left && p.x <= r.right && p.y >= r.top && p.y <= r.bottom;
      const what = k < 6 ? `pose ${k}` : `trajectory sample ${k - 6}`;
      for (const id of ['title', 'hint', 'timeline', 'panel', 'toolbar']) assert.ok(!inside(g[id]), `${w}x${h}: ${what} at (${p.x.toFixed(0)}, ${p.y.toFixed(0)}) is under #${id}`);
      assert.ok(p.y > 0 && p.y < h && p.x > 0 && p.x < w, `${w}x${h}: ${what} on screen`);
    }
  }
  await page.setViewportSize(DESKTOP);
  assert.deepEqual(problems, []);
});

test(`${BACKEND}: a preset is framed clear of the panel and the dock: pose 2's rotate gizmo of the tumbling cylinder stays between them`, async () => {
  // A page of its own: the framing starts from a first visit's view, not from the views the
  // tests above left.
  const context = await play.browser.newContext({ viewport: DESKTOP });
  try {
    const { page: p, problems: pp } = await openPage(context, play.url, BACKEND);
    await p.evaluate(async () => {
      const { app } = window.screwbender;
      app.ui.gui.open();
      await window.screwbender.openView('axes');
      window.screwbender.flushViews();
      app.run('loadPreset', 'cylinder5');
      app.select(2);
      app.setMode('rotate');
    });
    await waitFrames(p, 2);
    const g = await p.evaluate(() => {
      const { app } = window.screwbender;
      const c = app.viewer.screenOfPose(2);
      const radius = Math.max(...['ring-x', 'ring-y', 'ring-z'].map((n) => {
        const q = app.viewer.screenOfGizmo(n);
        return Math.hypot(q.x - c.x, q.y - c.y);
      }));
      const panel = document.getElementById('panel').getBoundingClientRect();
      const dock = document.getElementById('dock').getBoundingClientRect();
      return { c, radius, panelLeft: panel.left, panelBottom: panel.bottom, dockRight: dock.right };
    });
    assert.ok(g.c.x - g.radius > g.dockRight, `the rings reach x = ${(g.c.x - g.radius).toFixed(0)}, the dock ends at ${g.dockRight}`);
    // Where the panel reaches down beside the rings, they stay left of it.
    if (g.panelBottom > g.c.y - g.radius) assert.ok(g.c.x + g.radius < g.panelLeft, `the rings reach x = ${(g.c.x + g.radius).toFixed(0)}, the panel starts at ${g.panelLeft}`);
    assert.deepEqual(pp, []);
  } finally {
    await context.close();
  }
  assert.deepEqual(problems, []);
});
