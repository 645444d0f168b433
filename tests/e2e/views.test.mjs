// e2e-backends: webgpu (computed on the CPU, the same on either backend: once)
// End-to-end: the analysis views Plots, Metrics, Timing and Methods open from the dock, follow
// edits and drags, compute what they claim, and log no console error.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { waitFrames, mouseDrag, playgroundPage, ROOT, BACKEND } from './lib.mjs';

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

/** Opens view `id` by clicking its tab (the dock opens with the toolbar button first). */
async function openView(id, preset = 'l_cycle_rotated') {
  await sb((p) => window.screwbender.app.run('loadPreset', p), preset);
  if (!(await sb(() => !!window.screwbender.app.view.dock))) await page.locator('#t-dock').click();
  const tab = page.locator(`#dock .tabs button[data-view=${id}]`);
  if (!(await tab.evaluate((b) => b.classList.contains('on')))) {
    // A tab that does not fit the row is in the dock's "More" menu.
    if (await tab.isVisible()) await tab.click();
    else {
      await page.locator('#dock .more').click();
      await page.locator(`#dock .tab-menu [data-view=${id}]`).click();
    }
  }
  await sb(() => window.screwbender.flushViews());
  assert.equal(await sb(() => window.screwbender.app.view.dock), id);
  assert.ok(await page.locator(`#dock section[data-view=${id}]`).isVisible());
}

/** Drags control pose 1's handle by (dx, dy) with the mouse (the gizmo is avoided). */
async function dragPose(dx, dy) {
  await sb(() => window.screwbender.app.select(-1));
  await waitFrames(page, 1);
  const h = await sb(() => window.screwbender.handleOnPage(1));
  await mouseDrag(page, h, dx, dy, {
    during: async () => {
      // Mid-drag, the open view has already followed (live views).
      await sb(() => window.screwbender.flushViews());
    },
  });
  await sb(() => window.screwbender.flushViews());
}

test(`${BACKEND}: Plots shows all schemes over time and follows a drag`, async () => {
  await openView('plots');
  const data = () =>
    sb(() => {
      const v = window.screwbender.app.dock.current;
      return Object.fromEntries(Object.entries(v.data).map(([k, d]) => [k, Array.from(d)]));
    });
  const before = await data();
  assert.deepEqual(Object.keys(before).sort(), ['bspline', 'fourpoint', 'jarek', 'polyscrew']);
  for (const d of Object.values(before)) assert.ok(d.every(Number.isFinite));
  // The 4-point curve and the polyscrew pass through the control pose at t = i: the body point
  // (2,0,0) of pose 1 at t = 1 (sample 80 of 480 over 6 s).
  const pose1 = await sb(() => window.screwbender.app.motion.pose(1));
  const q = pose1.rotation;
  const x = 1 - 2 * (q[2] * q[2] + q[3] * q[3]);
  const y = 2 * (q[1] * q[2] + q[0] * q[3]);
  const want = [pose1.origin[0] + 2 * x, pose1.origin[1] + 2 * y];
  for (const id of ['fourpoint', 'polyscrew']) {
    const d = before[id];
    assert.ok(Math.abs(d[80 * 16] - 1) < 1e-12, 'sample 80 is at t = 1');
    assert.ok(Math.abs(d[80 * 16 + 1] - want[0]) < 1e-9 && Math.abs(d[80 * 16 + 2] - want[1]) < 1e-9, `${id} at pose 1`);
  }
  // Velocity is the derivative of position: central differences of the plotted positions agree
  // with the plotted velocities of the B-spline limit curve ('limit' derivatives, smooth).
  await sb(() => {
    const v = window.screwbender.app.dock.current;
    v.derivatives = 'limit';
    v.update('edit');
  });
  const lim = (await data()).bspline;
  const dt = lim[16] - lim[0];
  let worst = 0;
  for (let k = 1; k < 479; k++) {
    for (let a = 0; a < 3; a++) {
      const fd = (lim[(k + 1) * 16 + 1 + a] - lim[(k - 1) * 16 + 1 + a]) / (2 * dt);
      worst = Math.max(worst, Math.abs(fd - lim[k * 16 + 4 + a]));
    }
  }
  assert.ok(worst < 0.05, `velocity vs differences of positions: ${worst}`);
  await dragPose(60, -40);
  const after = await data();
  assert.notDeepEqual(after.bspline, lim, 'the plots follow the drag');
  await page.screenshot({ path: path.join(ARTIFACTS, 'view-plots.png') });
  assert.deepEqual(problems, []);
});

test(`${BACKEND}: Metrics of the current motion: 4-point interpolates, B-spline is smoother`, async () => {
  await openView('metrics');
  const last = () => sb(() => window.screwbender.app.dock.current.last);
  const four = await last();
  assert.ok(four.fourPointGap < 1e-12, `4-point gap ${four.fourPointGap}`);
  assert.ok(four.row.interpolation_error < 1e-12);
  await sb(() => window.screwbender.app.run('setScheme', 'bspline'));
  await sb(() => window.screwbender.flushViews());
  const bs = await last();
  assert.ok(bs.row.interpolation_error > 0.1, 'B-spline does not interpolate');
  assert.ok(bs.row.acceleration_jump < four.row.acceleration_jump / 5, `${bs.row.acceleration_jump} vs ${four.row.acceleration_jump}`);
  // More levels: smaller jumps (the limit is C²).
  await sb(() => window.screwbender.app.run('setOption', 'levels', 7));
  await sb(() => window.screwbender.flushViews());
  const fine = await last();
  assert.ok(fine.row.acceleration_jump < bs.row.acceleration_jump, `${fine.row.acceleration_jump} < ${bs.row.acceleration_jump}`);
  const text = await page.locator('#dock section[data-view=metrics] table').textContent();
  assert.match(text, /max velocity jump/);
  await dragPose(-50, 30);
  assert.notEqual((await last()).row.velocity_jump, fine.row.velocity_jump);
  assert.deepEqual(problems, []);
});

test(`${BACKEND}: Timing retimes the plots; bad times are refused and change nothing`, async () => {
  await openView('timing');
  // Let the view finish any update it has scheduled: a rebuild of its table between the `fill`
  // and the `change` below would send the change to a fresh, empty input.
  await sb(() => window.screwbender.flushViews());
  const inputs = page.locator('#dock section[data-view=timing] input[aria-label^="time of pose"]');
  assert.equal(await inputs.count(), 7); // 6 poses of a cycle + the time back at pose 0
  await inputs.nth(6).fill('12');
  await inputs.nth(6).dispatchEvent('change');
  await sb(() => window.screwbender.flushViews());
  assert.deepEqual(await sb(() => window.screwbender.app.times()), [0, 1, 2, 3, 4, 5, 12]);
  // Out of order: refused with a message; the session keeps the previous times.
  const s0 = await sb(() => JSON.stringify(window.screwbender.session()));
  await inputs.nth(2).fill('0.5');
  await inputs.nth(2).dispatchEvent('change');
  assert.match(await page.locator('#dock section[data-view=timing] [role=status]').textContent(), /times\[2\]/);
  assert.equal(await inputs.nth(2).inputValue(), '2', 'a refused time shows the time in use again');
  assert.equal(await sb(() => JSON.stringify(window.screwbender.session())), s0);
  // The plots run over the new duration.
  await page.locator('#dock .tabs button[data-view=plots]').click();
  await sb(() => window.screwbender.flushViews());
  const last = await sb(() => {
    const d = window.screwbender.app.dock.current.data.fourpoint;
    return d[d.length - 16];
  });
  assert.ok(last > 11.9 && last < 12, `last sample at t = ${last}`);
  // The glTF export uses the times: the animation lasts 12 s.
  const duration = await sb(async () => {
    const { exportMotion } = await import('./js/editor/files.js');
    const f = await exportMotion(window.screwbender.app, 'gltf', {}, { save: false });
    const json = JSON.parse(new TextDecoder().decode(f.data));
    const input = json.animations[0].samplers[0].input;
    return json.accessors[input].max[0];
  });
  assert.ok(Math.abs(duration - 12) < 1e-6, `glTF duration ${duration}`);
  // Inserting a pose keeps the timing: the new key is reached halfway between its neighbours.
  await sb(() => {
    window.screwbender.app.select(2);
    window.screwbender.app.run('insertPose');
  });
  assert.deepEqual(await sb(() => window.screwbender.app.times()), [0, 1, 2, 2.5, 3, 4, 5, 12]);
  // Deleting it takes its time along.
  await sb(() => window.screwbender.app.run('deletePose'));
  assert.deepEqual(await sb(() => window.screwbender.app.times()), [0, 1, 2, 3, 4, 5, 12]);
  assert.deepEqual(problems, []);
});

test(`${BACKEND}: Methods overlays three methods with metrics; the papers' claims hold`, async () => {
  await openView('methods', 'triangle7');
  const table = () => sb(() => window.screwbender.app.dock.current.lastTable);
  let t = await table();
  const row = (id) => t.rows.find((r) => r.method === id);
  assert.deepEqual(t.rows.map((r) => r.method), ['cc0', 'cc1', 'fourpoint']);
  // Chaudhry–Cameron: C⁰ has velocity kinks, C¹ none; both interpolate the triangle poses.
  assert.ok(row('cc0').velocity_jump.limit === 'value' && row('cc0').velocity_jump.value > 1e-2);
  assert.equal(row('cc1').velocity_jump.limit, 'zero');
  assert.ok(row('cc1').interpolation_error < 1e-9);
  // ScrewBender is frame-independent and reproduces circles and helices exactly; CC does not.
  assert.ok(row('fourpoint').frame_dependence < 1e-9 && row('cc0').frame_dependence > 1e-3);
  assert.ok(row('fourpoint').circle_error < 1e-9 && row('cc1').circle_error > 1e-3);
  await page.screenshot({ path: path.join(ARTIFACTS, 'view-methods-b1.png') });
  // Ramamoorthi–Barr on C1: variable frames, the EL error drops, |q| stays near 1.
  await openView('methods', 'rb_sphere7');
  t = await table();
  assert.deepEqual(t.rows.map((r) => r.method), ['rb', 'slerp', 'jarek']);
  const rb = await sb(() => {
    const r = window.screwbender.app.dock.current.rb;
    const max = (a) => Math.max(...a);
    return { frames: r.frameTimes.length, before: max(r.elBefore), after: max(r.elAfter), dev: r.unitDeviationAfter, stages: r.stages.map((s) => s.objective) };
  });
  assert.equal(rb.frames, 4);
  assert.ok(rb.after < rb.before / 3, `EL ${rb.before} → ${rb.after}`);
  for (let k = 1; k < rb.stages.length; k++) assert.ok(rb.stages[k] <= rb.stages[k - 1] * (1 + 1e-12), 'objective never increases');
  assert.ok(rb.dev < 0.01, `| |q| − 1 | = ${rb.dev}`);
  assert.ok(t.rows[0].angular_acceleration_energy.value < t.rows[2].angular_acceleration_energy.value * 3);
  // Choosing another method redraws; a method that does not apply to a cycle is disabled.
  await page.locator('#dock section[data-view=methods] select').nth(1).selectOption('kks');
  await sb(() => window.screwbender.flushViews());
  assert.deepEqual((await table()).rows.map((r) => r.method), ['rb', 'kks', 'jarek']);
  await sb(() => window.screwbender.app.run('loadPreset', 'circle4'));
  await sb(() => window.screwbender.flushViews());
  assert.equal(await page.locator('#dock section[data-view=methods] option[value=cc1]').first().evaluate((o) => o.disabled), true);
  await dragPose(40, 40);
  await page.screenshot({ path: path.join(ARTIFACTS, 'view-methods-c1.png') });
  assert.deepEqual(problems, []);
  assert.deepEqual(await sb(() => window.screwbender.errors()), []);
});

test(`${BACKEND}: the open view survives a reload; V closes the dock`, async () => {
  await openView('metrics');
  await page.reload();
  await page.evaluate(() => window.screwbender.ready);
  await waitFrames(page, 2);
  assert.equal(await sb(() => window.screwbender.app.view.dock), 'metrics');
  assert.ok(await page.locator('#dock').isVisible());
  await page.locator('#view').focus();
  await page.keyboard.press('v');
  assert.equal(await sb(() => window.screwbender.app.view.dock), '');
  assert.ok(!(await page.locator('#dock').isVisible()));
  // Pressed while the dock may still be loading after the reload: it stays closed after.
  await sb(async () => {
    while (window.screwbender.app.parts.dockHost.loading) await window.screwbender.app.parts.dockHost.loading;
  });
  assert.equal(await sb(() => window.screwbender.app.view.dock), '');
  assert.ok(!(await page.locator('#dock').isVisible()));
  assert.deepEqual(problems, []);
});

test(`${BACKEND}: the morph scene (A8) strobes PIP morphs of the pose shapes`, async () => {
  await sb(() => window.screwbender.app.run('loadPreset', 'pip_morph5'));
  await waitFrames(page, 2);
  const state = await sb(() => {
    const app = window.screwbender.app;
    // Triangle counts of morph meshes: at the star's pose its six convex pieces (a pentagonal
    // core prism, 16 triangles, and five triangular point prisms, 8 each); in between every
    // pair of pieces of the star and the block, combined.
    const r = app.viewer.renderer;
    return {
      morphing: app.viewer.drawing.morphing, slots: app.viewer.drawing.morphStrobeSlots, key: app.viewer.drawing.morphKey,
      star: r.setMorphMesh(60, 'pip_morph5', true, 1), between: r.setMorphMesh(60, 'pip_morph5', true, 1.5),
    };
  });
  assert.equal(state.morphing, true);
  assert.equal(state.slots, 36);
  assert.match(state.key, /^pip_morph5:true:5:36$/);
  assert.equal(state.star, 16 + 5 * 8);
  assert.ok(state.between > state.star, `${state.between} triangles between the star and the block`);
  // A drag rebuilds the strobe (meshes cached) without errors; bad input to the mesh is refused.
  await dragPose(30, 20);
  await assert.rejects(sb(() => window.screwbender.app.viewer.renderer.setMorphMesh(60, 'nope', true, 0)), /unknown scene/);
  await assert.rejects(sb(() => window.screwbender.app.viewer.renderer.setMorphMesh(60, 'pip_morph5', true, NaN)), /finite/);
  await page.screenshot({ path: path.join(ARTIFACTS, 'view-morph.png') });
  assert.deepEqual(problems, []);
});
