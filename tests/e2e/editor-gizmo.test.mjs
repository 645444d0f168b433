// e2e-backends: webgpu (computed on the CPU, the same on either backend: once)
// End-to-end: the gizmo with real mouse events. Snapping lands on the absolute grid and on
// absolute angles; parts seen edge-on are hidden (not drawn, not grabbable); dragging a handle
// moves its pose in the world plane facing the view, which is highlighted, never in depth;
// presses again on handles that overlap cycle through their poses.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { playgroundPage, waitFrames, mouseDrag, BACKEND } from './lib.mjs';

let play;
let page;
let problems;

before(async () => {
  ({ play, page, problems } = await playgroundPage());
  // The first-visit hint is not what these tests are about.
  await page.evaluate(() => (document.getElementById('hint').hidden = true));
});

after(async () => {
  await play?.close();
});

const sb = (f, arg) => page.evaluate(f, arg);
const pose = async (i) => Array.from(await sb(() => window.screwbender.poses())).slice(7 * i, 7 * i + 7);
const onGrid = (x, step) => Math.abs(x / step - Math.round(x / step)) < 1e-9;

/** Loads `preset`, puts pose i at `origin` with `rotation`, selects it, sets the mode and snap. */
async function setup({ preset = 'l_cycle_rotated', i = 2, origin, rotation, mode = 'translate', snap = false, camera }) {
  await sb(
    ({ preset, i, origin, rotation, mode, snap, camera }) => {
      const app = window.screwbender.app;
      app.parts.session.openPreset(preset);
      if (origin || rotation) {
        const p = app.motion.pose(i);
        app.motion.setPose(i, { origin: origin ?? p.origin, rotation: rotation ?? p.rotation });
      }
      app.updateView({ snap });
      if (camera) Object.assign(app.viewer.camera, camera);
      app.viewer.cameraMoved();
      app.changed(false);
      app.setMode(mode);
      app.select(i);
    },
    { preset, i, origin, rotation, mode, snap, camera },
  );
  await waitFrames(page, 2);
}

test(`${BACKEND}: snapped moves land on the absolute 0.25 grid`, async () => {
  await setup({ origin: [7.721, 2.13, 0.07], snap: true });
  const a = await sb(() => window.screwbender.gizmoOnPage('axis-x'));
  const o = await sb(() => window.screwbender.handleOnPage(2));
  const len = Math.hypot(a.x - o.x, a.y - o.y);
  await mouseDrag(page, a, (60 * (a.x - o.x)) / len, (60 * (a.y - o.y)) / len);
  const p = await pose(2);
  assert.ok(Math.abs(p[0] - 7.721) > 0.2, `x did not move: ${p[0]}`);
  assert.ok(onGrid(p[0], 0.25), `x = ${p[0]} is off the grid (it kept the start's offset: 7.721 -> 8.221)`);
  assert.deepEqual(p.slice(1, 3), [2.13, 0.07], 'an x drag keeps y and z');
});

test(`${BACKEND}: snapped turns land on absolute 15° angles`, async () => {
  const t = (7 * Math.PI) / 360;
  await setup({ rotation: [Math.cos(t), 0, 0, Math.sin(t)], mode: 'rotate', snap: true });
  const r = await sb(() => window.screwbender.gizmoOnPage('ring-z'));
  await mouseDrag(page, r, 40, 30);
  const q = (await pose(2)).slice(3);
  // A turn about z keeps the rotation about z alone; its angle is a multiple of 15°.
  assert.ok(Math.abs(q[1]) < 1e-12 && Math.abs(q[2]) < 1e-12, `not about z: ${q}`);
  const deg = (2 * Math.atan2(q[3], q[0]) * 180) / Math.PI;
  assert.ok(Math.abs(deg - 7) > 5, `did not turn: ${deg}°`);
  assert.ok(onGrid(deg, 15), `angle ${deg}° is not a multiple of 15°`);
});

test(`${BACKEND}: parts seen edge-on are hidden`, async () => {
  // Looking straight down: the z arrow points at the eye, the x and y squares are seen edge-on.
  await setup({ camera: { pitch: Math.PI / 2 - 1e-3 } });
  const visible = await sb(() => ['axis-x', 'axis-y', 'axis-z', 'plane-x', 'plane-y', 'plane-z'].filter((p) => window.screwbender.gizmoOnPage(p)));
  assert.deepEqual(visible, ['axis-x', 'axis-y', 'plane-z']);
  // From the side (looking along y at the horizon): the y arrow and the x and z squares go.
  await setup({ camera: { pitch: 0, yaw: Math.PI / 2 } });
  const side = await sb(() => ['axis-x', 'axis-y', 'axis-z', 'plane-x', 'plane-y', 'plane-z'].filter((p) => window.screwbender.gizmoOnPage(p)));
  assert.deepEqual(side, ['axis-x', 'axis-z', 'plane-y']);
  // A press where the hidden x square would be grabs no plane.
  const hit = await sb(() => {
    const app = window.screwbender.app;
    const c = app.motion.pose(2).origin;
    const s = app.viewer.toPage([c[0], c[1] + 0.4 * 1, c[2] + 0.4]);
    const r = app.viewer.canvas.getBoundingClientRect();
    return app.viewer.gizmoHit([s.x - r.left, s.y - r.top]);
  });
  assert.notEqual(hit, 'plane-x');
});

test(`${BACKEND}: a handle drag moves in the plane facing the view, shown, never in depth`, async () => {
  const o = [6, 2, 0.5];
  // The default camera, and one looking down steeply.
  for (const [camera, want] of [[{ yaw: -Math.PI / 3, pitch: 0.6 }, 1], [{ yaw: -Math.PI / 3, pitch: 1.2 }, 2]]) {
    await setup({ origin: o, camera });
    await sb(() => window.screwbender.app.select(-1));
    await waitFrames(page, 1);
    const f = await sb(() => window.screwbender.app.viewer.camera.forward);
    // The plane whose normal is closest to the view direction.
    const axis = [0, 1, 2].reduce((b, k) => (Math.abs(f[k]) > Math.abs(f[b]) ? k : b), 0);
    assert.equal(axis, want);
    const h = await sb(() => window.screwbender.handleOnPage(2));
    let shown;
    await mouseDrag(page, h, 50, -35, { during: async () => (shown = await sb(() => window.screwbender.app.hover)) });
    const p = await pose(2);
    assert.equal(shown, `plane-${'xyz'[axis]}`, 'the plane of the drag is not shown');
    assert.equal(p[axis], o[axis], `depth changed: ${'xyz'[axis]} ${o[axis]} -> ${p[axis]}`);
    assert.ok(Math.hypot(...p.slice(0, 3).map((v, k) => v - o[k])) > 0.3, 'the pose did not move');
  }
  assert.equal(await sb(() => window.screwbender.app.hover), null, 'the plane stays highlighted after the drag');
});

test(`${BACKEND}: presses again on overlapping handles cycle through their poses`, async () => {
  // C1: seven orientations about one centre, all handles on one pixel.
  await setup({ preset: 'rb_sphere7', i: 0 });
  await sb(() => window.screwbender.app.select(-1));
  await waitFrames(page, 1);
  const n = await sb(() => window.screwbender.app.motion.poseCount);
  const before = Array.from(await sb(() => window.screwbender.poses()));
  const h = await sb(() => window.screwbender.handleOnPage(0));
  const seen = [];
  for (let k = 0; k < n + 1; k++) {
    await page.mouse.click(h.x, h.y);
    seen.push(await sb(() => window.screwbender.selected()));
  }
  assert.deepEqual([...new Set(seen.slice(0, n))].sort((a, b) => a - b), [...Array(n).keys()], `presses selected ${seen}`);
  assert.equal(seen[n], seen[0], 'the cycle goes round');
  // Clicks are no edits.
  assert.deepEqual(Array.from(await sb(() => window.screwbender.poses())), before);
  assert.deepEqual(problems, []);
});

test(`${BACKEND}: pose numbers are drawn beside the handles and follow the camera`, async () => {
  await setup({ camera: { yaw: -Math.PI / 3, pitch: 0.6 } });
  const near = async () =>
    sb(() => {
      const app = window.screwbender.app;
      const out = [];
      const labels = [...document.querySelectorAll('#pose-labels .pose-label')].filter((e) => !e.hidden);
      for (const e of labels) {
        const k = Number(e.textContent);
        const r = e.getBoundingClientRect();
        const h = app.viewer.screenOfPose(k);
        out.push({ k, d: Math.hypot(r.left + r.width / 2 - h.x, r.top + r.height / 2 - h.y), on: e.classList.contains('on') });
      }
      return { out, n: app.motion.poseCount, layerHidden: document.getElementById('pose-labels').hidden };
    });
  let s = await near();
  assert.equal(s.layerHidden, false);
  assert.deepEqual(s.out.map((l) => l.k), [...Array(s.n).keys()]);
  // Beside the handle: close to it, not on it (the handle stays clickable).
  for (const l of s.out) assert.ok(l.d > 8 && l.d < 40, `label ${l.k} is ${l.d.toFixed(1)} px from its handle`);
  assert.deepEqual(s.out.filter((l) => l.on).map((l) => l.k), [2], 'the selected pose is marked');
  // An orbit with the mouse: the labels follow.
  await mouseDrag(page, { x: 150, y: 650 }, 120, -40);
  await waitFrames(page, 2);
  s = await near();
  for (const l of s.out) assert.ok(l.d > 8 && l.d < 40, `after the orbit, label ${l.k} is ${l.d.toFixed(1)} px from its handle`);
  // Display › Pose numbers off hides them.
  await sb(() => window.screwbender.app.run('setView', 'showPoseNumbers', false));
  assert.equal((await near()).layerHidden, true);
  await sb(() => window.screwbender.app.run('setView', 'showPoseNumbers', true));
});

test(`${BACKEND}: the gizmo in the pose's own axes (Q) moves and nudges along them`, async () => {
  // Pose 2 turned 90° about z: its own x axis is the world's y.
  const h = Math.SQRT1_2;
  await setup({ origin: [6, 2, 0.5], rotation: [h, 0, 0, h] });
  const world = await sb(() => window.screwbender.gizmoOnPage('axis-x'));
  // Q on the focused view toggles the gizmo's axes (not inside a control).
  await page.locator('#view').focus();
  await page.keyboard.press('q');
  await waitFrames(page, 2);
  assert.equal(await sb(() => window.screwbender.app.view.gizmoLocal), true);
  const local = await sb(() => window.screwbender.gizmoOnPage('axis-x'));
  assert.ok(Math.hypot(local.x - world.x, local.y - world.y) > 10, 'the x arrow did not turn with the pose');
  // A drag of the local x arrow moves along world y only.
  const o = await sb(() => window.screwbender.handleOnPage(2));
  const len = Math.hypot(local.x - o.x, local.y - o.y);
  await mouseDrag(page, local, (60 * (local.x - o.x)) / len, (60 * (local.y - o.y)) / len);
  let p = await pose(2);
  assert.ok(p[1] - 2 > 0.2, `y did not grow: ${p[1]}`);
  assert.ok(Math.abs(p[0] - 6) < 1e-9 && Math.abs(p[2] - 0.5) < 1e-9, `moved off the local x axis: ${p.slice(0, 3)}`);
  // An arrow key nudges along the local x axis too (world y), by one 0.25 step.
  const before = p;
  await page.locator('#view').focus();
  await page.keyboard.press('ArrowRight');
  p = await pose(2);
  assert.ok(Math.abs(p[1] - before[1] - 0.25) < 1e-9 && Math.abs(p[0] - before[0]) < 1e-9, `nudge ${p.slice(0, 3)} from ${before.slice(0, 3)}`);
  // Q again: world axes.
  await page.keyboard.press('q');
  assert.equal(await sb(() => window.screwbender.app.view.gizmoLocal), false);
  assert.deepEqual(problems, []);
});
