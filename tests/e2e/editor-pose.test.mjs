// e2e-backends: webgpu (computed on the CPU, the same on either backend: once)
// End-to-end: the pose panel (www/js/editor/pose.js). Typed origin, quaternion, axis–angle and
// Euler values set the selected pose exactly, as one undo step; a bad value shows a message
// beside its group and changes nothing; a quaternion off unit length is normalised with a
// notice. The playhead readout matches the Motion at the playhead.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { playgroundPage, waitFrames, BACKEND } from './lib.mjs';

let play;
let page;
let problems;

before(async () => {
  ({ play, page, problems } = await playgroundPage());
  await page.evaluate(() => {
    const gui = window.screwbender.app.ui.gui;
    gui.open();
    for (const f of gui.folders) f.close();
    gui.folders.find((f) => f._title === 'Pose').open();
  });
});

after(async () => {
  await play?.close();
});

const sb = (f, arg) => page.evaluate(f, arg);
const poses = async () => Array.from(await sb(() => window.screwbender.poses()));
const field = (label) => page.locator(`.pose-panel input[aria-label="${label}"]`);
const pose = async (i) => (await poses()).slice(7 * i, 7 * i + 7);
const close = (a, b, tol, what) => a.forEach((v, k) => assert.ok(Math.abs(v - b[k]) < tol, `${what}: ${a} != ${b}`));
/** q and -q are one rotation. */
const sameRotation = (a, b, tol, what) => {
  const s = Math.sign(a.reduce((t, v, k) => t + v * b[k], 0)) || 1;
  close(a, b.map((v) => s * v), tol, what);
};

/** Types `text` into a field with the keyboard and presses Enter. */
async function type(label, text) {
  const f = field(label);
  await f.click();
  await f.press('Control+a');
  await page.keyboard.press('Backspace');
  if (text) await page.keyboard.type(text);
  await page.keyboard.press('Enter');
  await waitFrames(page, 1);
}

async function fresh(select = 2) {
  await sb((k) => {
    window.screwbender.app.parts.session.openPreset('l_cycle_rotated');
    window.screwbender.app.select(k);
  }, select);
  await waitFrames(page, 1);
}

test(`${BACKEND}: origin typed in the panel moves the pose exactly; undo restores it`, async () => {
  await fresh();
  const p0 = await poses();
  await type('Origin: x', '7.125');
  const p1 = await poses();
  assert.equal(p1[14], 7.125);
  assert.deepEqual(p1.slice(15, 21), p0.slice(15, 21), 'only x changed');
  for (let k = 0; k < p0.length; k++) if (Math.floor(k / 7) !== 2) assert.equal(p1[k], p0[k]);
  await page.locator('#view').focus();
  await page.keyboard.press('Control+z');
  assert.deepEqual(await poses(), p0);
  assert.equal(await field('Origin: x').inputValue(), String(Number(p0[14].toFixed(6))));
});

test(`${BACKEND}: a bad value shows a message and changes nothing`, async () => {
  await fresh();
  const p0 = await poses();
  const undoable = await sb(() => window.screwbender.app.history.canUndo);
  for (const [label, text] of [['Origin: y', 'abc'], ['Origin: z', ''], ['Quaternion [w, x, y, z]: w', '1e999'], ['Axis–angle: angle °', '9x']]) {
    await type(label, text);
    const msg = page.locator('.pose-panel .pp-msg:not([hidden])');
    assert.equal(await msg.count(), 1, `no message for ${label} = "${text}"`);
    assert.match(await msg.textContent(), /not a number/);
    assert.deepEqual(await poses(), p0, `${label} = "${text}" changed the poses`);
    await page.keyboard.press('Escape');
  }
  // A zero quaternion and a zero axis with an angle are refused too.
  for (const label of ['w', 'x', 'y', 'z']) await field(`Quaternion [w, x, y, z]: ${label}`).fill('0');
  await field('Quaternion [w, x, y, z]: z').press('Enter');
  assert.match(await page.locator('.pp-quat .pp-msg').textContent(), /zero/);
  assert.deepEqual(await poses(), p0);
  await page.keyboard.press('Escape');
  for (const label of ['x', 'y', 'z']) await field(`Axis–angle: ${label}`).fill('0');
  await field('Axis–angle: angle °').fill('30');
  await field('Axis–angle: angle °').press('Enter');
  assert.match(await page.locator('.pp-axis .pp-msg').textContent(), /axis is zero/);
  assert.deepEqual(await poses(), p0);
  await page.keyboard.press('Escape');
  assert.equal(await sb(() => window.screwbender.app.history.canUndo), undoable, 'a refused value made an undo step');
  assert.deepEqual(await sb(() => window.screwbender.errors()), []);
});

test(`${BACKEND}: a quaternion off unit length is normalised, with a notice`, async () => {
  await fresh();
  for (const [label, v] of [['w', '2'], ['x', '0'], ['y', '0'], ['z', '2']]) await field(`Quaternion [w, x, y, z]: ${label}`).fill(v);
  await field('Quaternion [w, x, y, z]: z').press('Enter');
  await waitFrames(page, 1);
  const h = Math.SQRT1_2;
  sameRotation((await pose(2)).slice(3), [h, 0, 0, h], 1e-15, 'normalised quaternion');
  assert.ok(await page.locator('#toast').isVisible());
  assert.match(await page.locator('#toast').textContent(), /normalised.*2\.828427/);
});

test(`${BACKEND}: axis–angle and Euler angles (each order) set the rotation`, async () => {
  await fresh();
  const o0 = (await pose(2)).slice(0, 3);
  for (const [label, v] of [['x', '0'], ['y', '0'], ['z', '2'], ['angle °', '90']]) await field(`Axis–angle: ${label}`).fill(v);
  await field('Axis–angle: angle °').press('Enter');
  const h = Math.SQRT1_2;
  sameRotation((await pose(2)).slice(3), [h, 0, 0, h], 1e-15, 'axis z, 90°');
  assert.deepEqual((await pose(2)).slice(0, 3), o0, 'a rotation keeps the origin');
  // Euler: intrinsic, R = R_a(α) R_b(β) R_c(γ) for order "abc"; the test composes quaternions itself.
  const qa = (axis, deg) => {
    const t = (deg * Math.PI) / 360;
    const q = [Math.cos(t), 0, 0, 0];
    q[1 + 'XYZ'.indexOf(axis)] = Math.sin(t);
    return q;
  };
  const mul = (a, b) => [
    a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
    a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
    a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
    a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0],
  ];
  const angles = [20, -35, 50];
  for (const order of ['XYZ', 'ZYX', 'YXZ']) {
    await page.locator('.pose-panel select.pp-order').selectOption(order);
    for (let k = 0; k < 3; k++) await field(`Euler angle ° about ${order[k]}`).fill(String(angles[k]));
    await field(`Euler angle ° about ${order[2]}`).press('Enter');
    const want = mul(mul(qa(order[0], angles[0]), qa(order[1], angles[1])), qa(order[2], angles[2]));
    sameRotation((await pose(2)).slice(3), want, 1e-12, `Euler ${order}`);
    // The fields read back the typed angles (within the 6 decimals shown).
    for (let k = 0; k < 3; k++) assert.ok(Math.abs(Number(await field(`Euler angle ° about ${order[k]}`).inputValue()) - angles[k]) < 1e-6);
  }
  // The matrix readout is the pose's rotation matrix: its first column is R e_x.
  const q = (await pose(2)).slice(3);
  const m = await page.locator('.pp-matrix td').allTextContents();
  const col0 = [1 - 2 * (q[2] ** 2 + q[3] ** 2), 2 * (q[1] * q[2] + q[0] * q[3]), 2 * (q[1] * q[3] - q[0] * q[2])];
  close([Number(m[0]), Number(m[3]), Number(m[6])], col0, 1e-6, 'matrix column 0');
});

test(`${BACKEND}: the playhead readout follows the scrubber`, async () => {
  await fresh(-1);
  assert.match(await page.locator('.pose-panel .pp-which').textContent(), /No pose selected/);
  await page.locator('#scrub').focus();
  for (let k = 0; k < 5; k++) await page.keyboard.press('PageUp');
  const u = await sb(() => window.screwbender.app.anim.u);
  assert.ok(u > 0.1, `u = ${u}`);
  const text = await page.locator('.pp-readout').textContent();
  const want = await sb((t) => {
    const m = window.screwbender.app.motion;
    const k = m.kinematicsAt(t);
    return { origin: m.poseAt(t).origin, speed: Math.hypot(...k.velocity), screw: m.spanScrews()[Math.floor(t)] };
  }, u);
  assert.ok(text.includes(`[${want.origin.map((c) => c.toFixed(3)).join(', ')}]`), text);
  assert.ok(text.includes(`${want.speed.toFixed(3)} units per unit u`), text);
  assert.ok(text.includes(`angle ${((want.screw.angle * 180) / Math.PI).toFixed(2)}°`), text);
  assert.deepEqual(problems, []);
});
