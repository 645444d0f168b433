// e2e-backends: webgpu (computed on the CPU, the same on either backend: once)
// End-to-end tests of the teaching views of the analysis dock (www/js/dock/axes.js, steps.js,
// polygon.js, frame.js) in headless Chromium:
//
//   E2E_BACKEND=webgpu|webgl2 node --test tests/e2e/teaching.test.mjs
//
// Each view opens, follows an edit of the motion (or a real mouse drag), and logs no console
// error; the polygon view reproduces the L-polygon numbers of docs/math/point-rules.md §5 through
// the wasm export in the page. Screenshots go to artifacts/e2e-<backend>/teach-<view>.png.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { waitFrames, playgroundPage, ROOT, BACKEND } from './lib.mjs';

const ARTIFACTS = path.join(ROOT, 'artifacts', `e2e-${BACKEND}`);

let play;
let page;
let problems;

before(async () => {
  fs.mkdirSync(ARTIFACTS, { recursive: true });
  ({ play, page, problems } = await playgroundPage());
});

after(async () => {
  await play?.close();
});

const sb = (f, arg) => page.evaluate(f, arg);

async function preset(id) {
  await sb((p) => {
    window.screwbender.app.run('loadPreset', p);
    window.screwbender.app.select(-1);
  }, id);
  await waitFrames(page, 1);
}

async function open(id) {
  // The first view opened fetches the dock, its views and the analysis module: wait for it.
  await sb(async (v) => {
    await window.screwbender.openView(v);
    window.screwbender.flushViews();
  }, id);
  await waitFrames(page, 1);
}

/** Moves control pose 1 by (dx, dy, 0) as one undoable edit and runs the view's update. */
async function editPose(dx, dy) {
  await sb(([x, y]) => {
    const app = window.screwbender.app;
    const p = app.motion.pose(1);
    app.parts.session.edit(() => app.motion.setPose(1, { origin: [p.origin[0] + x, p.origin[1] + y, p.origin[2]], rotation: p.rotation }));
    window.screwbender.flushViews();
  }, [dx, dy]);
  await waitFrames(page, 1);
}

async function shot(name) {
  await page.screenshot({ path: path.join(ARTIFACTS, `teach-${name}.png`) });
}

function noProblems() {
  assert.deepEqual(problems, []);
}

test(`${BACKEND}: screw axes view lists every span and follows edits and drags`, async () => {
  await preset('l_cycle_rotated');
  await open('axes');
  const rows = () => sb(() => document.querySelectorAll('.view-axes tbody tr').length);
  assert.equal(await rows(), 6);
  const spanInfo = () => sb(() => window.screwbender.app.dock.current.state.screws.map((s) => [s.kind, s.angle, s.slide]));
  const before = await spanInfo();
  // The table agrees with Motion.spanScrews() at the control level.
  const direct = await sb(() => window.screwbender.app.motion.spanScrews().map((s) => [s.kind, s.angle, s.slide]));
  assert.deepEqual(before, direct);
  // An edit changes the spans next to pose 1.
  await editPose(0.5, 1);
  const after1 = await spanInfo();
  assert.notDeepEqual(after1, before);
  // A real mouse drag of pose 2 updates the table live (the view is live).
  const h = await sb(() => window.screwbender.handleOnPage(2));
  await page.mouse.move(h.x, h.y);
  await page.mouse.down();
  await page.mouse.move(h.x + 30, h.y + 20, { steps: 4 });
  // Chromium delivers mouse moves with the next frame, which SwiftShader may draw late: wait for
  // the table to change (or the timeout) rather than sample it once.
  const followed = await page
    .waitForFunction(
      (was) => {
        window.screwbender.flushViews();
        const now = window.screwbender.app.dock.current.state.screws.map((s) => [s.kind, s.angle, s.slide]);
        return JSON.stringify(now) !== was;
      },
      JSON.stringify(after1),
      { timeout: 10000 },
    )
    .then(() => true, () => false);
  await page.mouse.up();
  assert.ok(followed, 'the table did not follow the drag');
  // Hovering a row highlights the span and shows its label.
  await page.locator('.view-axes tbody tr').nth(3).hover();
  await page
    .waitForFunction(() => window.screwbender.app.dock.current.state.hover === 3, null, { timeout: 10000 })
    .catch(() => {});
  assert.equal(await sb(() => window.screwbender.app.dock.current.state.hover), 3);
  assert.equal(await sb(() => document.querySelector('.axes-label').hidden), false);
  assert.match(await page.locator('.axes-label').textContent(), /°, slide/);
  // Hovering an axis in the 3-D view highlights its row.
  await page.mouse.move(5, 790);
  await sb(() => window.screwbender.app.dock.current.highlight(-1));
  const target = await sb(() => {
    const app = window.screwbender.app;
    const ends = app.dock.current.state.ends;
    const dock = document.getElementById('dock').getBoundingClientRect();
    for (let i = 0; i < ends.length; i++) {
      if (!ends[i]) continue;
      const mid = ends[i][0].map((v, a) => (v + ends[i][1][a]) / 2);
      const p = app.viewer.toPage(mid);
      if (p && p.x > dock.right + 10 && p.x < 1000 && p.y > 150 && p.y < 740) return { i, ...p };
    }
    return null;
  });
  assert.ok(target, 'no axis visible outside the dock');
  await page.mouse.move(target.x, target.y);
  await page
    .waitForFunction((i) => window.screwbender.app.dock.current.state.hover === i, target.i, { timeout: 10000 })
    .catch(() => {});
  assert.equal(await sb(() => window.screwbender.app.dock.current.state.hover), target.i);
  assert.equal(await sb((i) => document.querySelectorAll('.view-axes tbody tr')[i].classList.contains('hi'), target.i), true);
  await page.mouse.move(5, 790);
  // A refined level has 2^level times as many spans.
  await page.locator('.view-axes select.level').selectOption('2');
  await sb(() => window.screwbender.flushViews());
  assert.equal(await rows(), 24);
  await page.locator('.view-axes select.level').selectOption('0');
  await page.locator('.view-axes tbody tr').nth(3).hover();
  await waitFrames(page, 2);
  await shot('axes');
  noProblems();
});

test(`${BACKEND}: split/tweak view steps with buttons and keys and follows the scheme`, async () => {
  await preset('l_cycle_rotated');
  await open('steps');
  const st = () => sb(() => {
    const s = window.screwbender.app.dock.current.state;
    return { index: s.index, caption: s.caption, out: s.step ? Array.from(s.step.output) : [] };
  });
  let s = await st();
  assert.equal(s.index, 0);
  assert.match(s.caption, /Level 0 → 1 · split/);
  await page.locator('.view-steps .next').click();
  s = await st();
  assert.equal(s.index, 1);
  assert.match(s.caption, /tweak \(4-point, direct V2\)/);
  // Level 0's tweak output is the level-1 subdivision of the motion.
  const level1 = await sb(async () => {
    const { Motion } = await window.screwbender.app.analysis();
    const m = window.screwbender.app.motion;
    const r = new Motion(m.toDocument(), { ...m.options(), levels: 1 });
    const out = Array.from(r.subdivide());
    r.free();
    return out;
  });
  assert.equal(s.out.length, level1.length);
  assert.ok(s.out.every((v, i) => Math.abs(Math.abs(v) - Math.abs(level1[i])) < 1e-9));
  // Keys: ] forward, [ back (not while typing in an input).
  await page.locator('body').click({ position: { x: 5, y: 300 } });
  await page.keyboard.press(']');
  assert.equal((await st()).index, 2);
  await page.keyboard.press('.');
  assert.equal((await st()).index, 3);
  await page.keyboard.press('[');
  assert.equal((await st()).index, 2);
  // Changing the rule set shows the V1 helper poses and changes the caption.
  await sb(() => window.screwbender.app.run('setOption', 'rules', 'split'));
  await sb(() => window.screwbender.flushViews());
  await page.keyboard.press(']');
  s = await st();
  assert.match(s.caption, /split & tweak V1/);
  assert.ok((await sb(() => window.screwbender.app.dock.current.state.step.helperSlots.length)) > 0);
  // An edit re-runs the step.
  const beforeEdit = s.out;
  await editPose(1, 0);
  assert.notDeepEqual((await st()).out, beforeEdit);
  await sb(() => window.screwbender.app.run('setOption', 'rules', 'direct'));
  await sb(() => window.screwbender.app.dock.current.goTo(1));
  await waitFrames(page, 2);
  await shot('steps');
  noProblems();
});

test(`${BACKEND}: polygon view reproduces the L-polygon vectors of docs/math/point-rules.md §5 and drags vertices`, async () => {
  await open('polygon');
  // The wasm export, called in the page (docs/math/point-rules.md §5, one step).
  const got = await sb(async () => {
    const { subdividePolygon } = await window.screwbender.app.analysis();
    const L = [0, 0, 6, 0, 6, 2, 2, 2, 2, 6, 0, 6];
    const out = {};
    for (const scheme of ['bspline', 'fourpoint', 'jarek']) {
      for (const rules of ['direct', 'split']) out[`${scheme}/${rules}`] = Array.from(subdividePolygon(L, true, { scheme, rules, levels: 1 }));
    }
    return out;
  });
  const want = {
    bspline: [0.75, 0.75, 3, 0, 5.25, 0.25, 6, 1, 5.5, 1.75, 4, 2, 2.5, 2.5, 2, 4, 1.75, 5.5, 1, 6, 0.25, 5.25, 0, 3],
    fourpoint: [0, 0, 3, -0.5, 6, 0, 6.625, 1, 6, 2, 4, 1.875, 2, 2, 1.875, 4, 2, 6, 1, 6.625, 0, 6, -0.5, 3],
    jarek: [0.375, 0.375, 3, -0.25, 5.625, 0.125, 6.3125, 1, 5.75, 1.875, 4, 1.9375, 2.25, 2.25, 1.9375, 4, 1.875, 5.75, 1, 6.3125, 0.125, 5.625, -0.25, 3],
  };
  for (const [key, values] of Object.entries(got)) {
    const w = want[key.split('/')[0]];
    assert.equal(values.length, w.length, key);
    values.forEach((v, i) => assert.ok(Math.abs(v - w[i]) < 1e-12, `${key}[${i}]: ${v} vs ${w[i]}`));
  }
  // Bad input to the teaching exports throws errors naming the element.
  const errors = await sb(async () => {
    const m = await window.screwbender.app.analysis();
    const msg = (f) => {
      try {
        f();
        return 'no error';
      } catch (e) {
        return e.message;
      }
    };
    const ok = [0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0];
    return [
      msg(() => m.subdividePolygon([0, 0, 1], true, { levels: 1 })),
      msg(() => m.subdividePolygon([0, 0, NaN, 1], true, { levels: 1 })),
      msg(() => m.splitTweakStep([0, 0, 0, 0, 0, 0, 0, ...ok.slice(7)], true, {}, 0)),
      msg(() => m.splitTweakStep(ok, true, {}, 1.5)),
      msg(() => m.compareFrames(ok, true, {}, [0, Infinity, 0], [0, 0, 0])),
      msg(() => m.spanScrewsOf(ok.slice(0, 7), true)),
    ];
  });
  assert.match(errors[0], /^points: .*even number/);
  assert.match(errors[1], /^points\[1\]/);
  assert.match(errors[2], /^poses\[0\]\.rotation: zero quaternion/);
  assert.match(errors[3], /^level/);
  assert.match(errors[4], /^offset/);
  assert.match(errors[5], /poses/);
  // The view shows the same numbers at level 1 on polygon_l.
  await sb(() => window.screwbender.app.dock.current.set('polygon_l', 1));
  const shown = await sb(() => Array.from(window.screwbender.app.dock.current.state.results.fourpoint));
  shown.forEach((v, i) => assert.ok(Math.abs(v - want.fourpoint[i]) < 1e-12));
  // ... and lists them in its numbers table.
  await page.locator('.view-polygon .numbers summary').click();
  const row1 = await page.locator('.view-polygon .numbers tbody tr').nth(1).textContent();
  assert.match(row1, /\(3, 0\)\s*\(3, -0\.5\)\s*\(3, -0\.25\)/);
  // A real drag of vertex 1 moves it and re-subdivides.
  const v1 = await sb(() => window.screwbender.app.dock.current.vertexOnPage(1));
  await page.mouse.move(v1.x, v1.y);
  await page.mouse.down();
  await page.mouse.move(v1.x + 25, v1.y - 15, { steps: 5 });
  await page.mouse.up();
  const moved = await sb(() => {
    const s = window.screwbender.app.dock.current.state;
    return { p: Array.from(s.polys.polygon_l.slice(2, 4)), r: Array.from(s.results.fourpoint) };
  });
  assert.ok(moved.p[0] > 6.2 && moved.p[1] > 0.2, `vertex moved to ${moved.p}`);
  assert.ok(Math.abs(moved.r[4] - moved.p[0]) < 1e-12 && Math.abs(moved.r[5] - moved.p[1]) < 1e-12, '4-point interpolates the dragged vertex');
  // Control-origins mode follows motion edits and is read-only.
  await sb(() => window.screwbender.app.dock.current.set('origins', 3));
  const o1 = await sb(() => Array.from(window.screwbender.app.dock.current.state.points));
  await editPose(0, 2);
  const o2 = await sb(() => Array.from(window.screwbender.app.dock.current.state.points));
  assert.notDeepEqual(o1, o2);
  await sb(() => {
    const v = window.screwbender.app.dock.current;
    v.set('polygon_l', 5);
  });
  await waitFrames(page, 1);
  await shot('polygon');
  noProblems();
});

test(`${BACKEND}: frame view: screw trajectories ignore the local origin, decoupled ones do not`, async () => {
  await preset('l_cycle_rotated');
  await open('frame');
  const res = () => sb(() => {
    const s = window.screwbender.app.dock.current.state;
    return { ds: s.result.screwDeviation, dd: s.result.decoupledDeviation, radial: s.radial };
  });
  let r = await res();
  assert.equal(r.ds, 0);
  assert.equal(r.dd, 0);
  // Move the slider for c_x with the keyboard (a real input event).
  const slider = page.locator('.view-frame .sliders input').first();
  await slider.focus();
  for (let k = 0; k < 20; k++) await page.keyboard.press('ArrowRight');
  r = await res();
  assert.ok(r.ds < 1e-9, `screw deviation ${r.ds}`);
  assert.ok(r.dd > 1e-2, `decoupled deviation ${r.dd}`);
  assert.match(await page.locator('.view-frame .ds').textContent(), /e-1[0-9]|^0$/);
  // An edit keeps the property.
  await editPose(0.3, -0.4);
  r = await res();
  assert.ok(r.ds < 1e-9 && r.dd > 1e-2);
  // circle4: the screw scheme keeps the circle exactly, decoupled cuts the corners.
  await page.locator('.view-frame .circle').click();
  await sb(() => window.screwbender.flushViews());
  await sb(() => window.screwbender.app.dock.current.setOffset([0, 0, 0]));
  r = await res();
  assert.ok(r.radial.screw < 1e-9, `screw radial ${r.radial.screw}`);
  assert.ok(Math.abs(r.radial.decoupled - (3 - 2.65165)) < 0.01, `decoupled radial ${r.radial.decoupled}`);
  await sb(() => window.screwbender.app.dock.current.setOffset([1.5, 0, 0]));
  r = await res();
  assert.ok(r.ds < 1e-9 && r.dd > 0.1);
  await sb(() => window.screwbender.app.parts.viewpoint.fit());
  await waitFrames(page, 2);
  await shot('frame');
  noProblems();
});

test(`${BACKEND}: every preset in every teaching view (open, 2-pose, J_s, V1 rules): no errors`, async () => {
  const ids = await sb(() => window.screwbender.app.scenes.map((s) => s.id));
  for (const id of ids) {
    await preset(id);
    for (const view of ['axes', 'steps', 'polygon', 'frame']) {
      await open(view);
      if (view === 'axes') {
        await page.locator('.view-axes select.level').selectOption('1');
        await sb(() => window.screwbender.flushViews());
        await page.locator('.view-axes select.level').selectOption('0');
      }
      if (view === 'steps') await sb(() => window.screwbender.app.dock.current.goTo(5));
      if (view === 'polygon') await sb(() => window.screwbender.app.dock.current.set('origins', 2));
    }
  }
  await preset('bunny6');
  for (const options of [{ scheme: 'j', j: 0.3 }, { scheme: 'jarek', rules: 'split' }, { scheme: 'bspline', rules: 'split' }]) {
    await sb((o) => window.screwbender.app.parts.session.edit(() => window.screwbender.app.motion.setOptions(o)), options);
    for (const view of ['axes', 'steps', 'frame']) {
      await open(view);
      if (view === 'steps') await sb(() => window.screwbender.app.dock.current.goTo(3));
    }
  }
  assert.deepEqual(await sb(() => window.screwbender.errors()), []);
  noProblems();
});

test(`${BACKEND}: hiding a teaching view clears its overlays; no banner errors`, async () => {
  for (const id of ['axes', 'steps', 'polygon', 'frame']) await open(id);
  await sb(() => window.screwbender.openView(''));
  await waitFrames(page, 1);
  assert.deepEqual(await sb(() => window.screwbender.errors()), []);
  noProblems();
});
