// e2e-backends: webgpu (computed on the CPU, the same on either backend: once)
// End-to-end: export buttons (glTF .glb / .gltf + .bin, CSV) and drag-and-drop import of
// .json / .csv / .glb / .gltf + .bin / .obj files, with bad files leaving the session unchanged.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import { waitFrames, playgroundPage, BACKEND } from './lib.mjs';

let play;
let page;
let problems;

before(async () => {
  ({ play, page, problems } = await playgroundPage({ acceptDownloads: true }));
  await page.evaluate(() => window.screwbender.app.run('loadPreset', 'l_cycle_rotated'));
});

after(async () => {
  await play?.close();
});

/** Clicks a lil-gui button of the File folder by its label; returns the download(s). */
async function clickExport(label, count = 1) {
  await page.evaluate(() => window.screwbender.app.ui.gui.folders.find((f) => f._title === 'File').open());
  const downloads = [];
  const got = new Promise((resolve) => {
    page.on('download', function on(d) {
      downloads.push(d);
      if (downloads.length === count) {
        page.off('download', on);
        resolve();
      }
    });
  });
  await page.locator('#panel').getByText(label, { exact: true }).click();
  await got;
  return downloads;
}

/**
 * Drops files {name, bytes (Uint8Array | string)} on the page as a real DataTransfer drop, and
 * waits for the import's outcome: a changed session, a new message or the import dialog (the
 * files are read asynchronously, and the first glTF or CSV fetches the analysis module).
 */
async function drop(files) {
  await page.evaluate(async (list) => {
    const sb = window.screwbender;
    const state = () => JSON.stringify({ ...sb.session(), camera: null });
    const before = state();
    const messages = sb.errors().length;
    const dt = new DataTransfer();
    for (const f of list) dt.items.add(new File([Uint8Array.from(f.bytes)], f.name));
    for (const type of ['dragenter', 'dragover', 'drop']) {
      window.dispatchEvent(new DragEvent(type, { dataTransfer: dt, bubbles: true, cancelable: true }));
    }
    const done = () => sb.errors().length > messages || document.getElementById('reduce-dialog') || state() !== before;
    for (const t0 = performance.now(); !done() && performance.now() - t0 < 20000; ) await new Promise((r) => setTimeout(r, 20));
  }, files.map((f) => ({ name: f.name, bytes: [...(typeof f.bytes === 'string' ? Buffer.from(f.bytes) : f.bytes)] })));
  await waitFrames(page, 1);
}

const poses = () => page.evaluate(() => [...window.screwbender.poses()]);
const session = () => page.evaluate(() => JSON.stringify(window.screwbender.session()));

function assertPosesClose(a, b, tol) {
  assert.equal(a.length, b.length, 'pose count');
  for (let i = 0; i < a.length; i += 7) {
    for (let k = 0; k < 3; k++) assert.ok(Math.abs(a[i + k] - b[i + k]) <= tol, `origin ${i / 7}: ${a[i + k]} vs ${b[i + k]}`);
    // Quaternion sign is free.
    const dot = a[i + 3] * b[i + 3] + a[i + 4] * b[i + 4] + a[i + 5] * b[i + 5] + a[i + 6] * b[i + 6];
    assert.ok(1 - Math.abs(dot) <= tol, `rotation ${i / 7}: |dot| = ${Math.abs(dot)}`);
  }
}

test(`${BACKEND}: Export glTF (.glb) downloads a GLB named for what it holds (…-motion.glb) whose drop restores the control poses to 1e-6`, async () => {
  const before = await poses();
  const [d] = await clickExport('Export glTF (.glb)');
  assert.equal(d.suggestedFilename(), 'l_cycle_rotated-motion.glb');
  const bytes = fs.readFileSync(await d.path());
  assert.equal(bytes.subarray(0, 4).toString('latin1'), 'glTF');
  const toast = await page.locator('#toast').textContent();
  assert.match(toast, /l_cycle_rotated-motion\.glb: \d+ keyframes \(tolerance 0\.0001\)/);
  // Change the motion, then drop the exported file: the control poses come back.
  await page.evaluate(() => window.screwbender.app.run('loadPreset', 'cylinder5'));
  await drop([{ name: 'l_cycle_rotated-motion.glb', bytes }]);
  assertPosesClose(await poses(), before, 1e-6);
  // The file's own object (the preset's, as drawn) comes along as the imported glTF mesh, and a
  // reload restores it from the autosave at once, read by the renderer module itself.
  const object = () => page.evaluate(() => ({ object: window.screwbender.app.view.object, kind: window.screwbender.app.imported?.kind, errors: window.screwbender.errors() }));
  assert.deepEqual(await object(), { object: 'obj', kind: 'gltf', errors: [] });
  await page.reload();
  await page.evaluate(() => window.screwbender.ready);
  await waitFrames(page, 1);
  assert.deepEqual(await object(), { object: 'obj', kind: 'gltf', errors: [] });
  assert.equal(await page.evaluate(() => performance.getEntriesByType('resource').some((r) => r.name.includes('/pkg-full/'))), false, 'the analysis module was fetched to draw the object');
  assertPosesClose(await poses(), before, 1e-6);
  assert.deepEqual(problems, []);
});

test(`${BACKEND}: Export glTF (.gltf + .bin) downloads both; dropping them together imports`, async () => {
  await page.evaluate(() => window.screwbender.app.run('loadPreset', 'cylinder5'));
  const before = await poses();
  const [g, b] = await clickExport('Export glTF (.gltf + .bin)', 2);
  assert.equal(g.suggestedFilename(), 'cylinder5-motion.gltf');
  assert.equal(b.suggestedFilename(), 'cylinder5-motion.bin');
  const gltf = fs.readFileSync(await g.path());
  const json = JSON.parse(gltf.toString());
  assert.equal(json.buffers[0].uri, 'cylinder5-motion.bin');
  assert.ok(json.animations.length >= 1);
  await page.evaluate(() => window.screwbender.app.run('loadPreset', 'l_cycle_rotated'));
  const sBefore = await session();
  // The .gltf alone cannot be read: its buffer is missing. Nothing changes.
  await drop([{ name: 'cylinder5-motion.gltf', bytes: gltf }]);
  assert.match(await page.locator('#banner .msg').textContent(), /cylinder5-motion\.gltf: .*cylinder5-motion\.bin/);
  assert.equal(await session(), sBefore);
  await drop([
    { name: 'cylinder5-motion.gltf', bytes: gltf },
    { name: 'cylinder5-motion.bin', bytes: fs.readFileSync(await b.path()) },
  ]);
  assertPosesClose(await poses(), before, 1e-6);
});

test(`${BACKEND}: Export CSV (control poses) writes the design, times and velocities, and its drop gives the same document`, async () => {
  await page.evaluate(() => {
    const app = window.screwbender.app;
    app.run('loadPreset', 'cylinder5');
    // A cycle of 5 poses: 6 key times (pose 0 again at the end).
    app.run('setTimes', [0, 0.5, 2, 2.5, 4, 5]);
    app.run('setVelocities', [0, null, 1.5, null, 0]);
  });
  const before = await page.evaluate(() => window.screwbender.app.motion.toDocument());
  assert.equal(before.closed, true);
  assert.deepEqual(before.times, [0, 0.5, 2, 2.5, 4, 5], 'the times were taken');
  const [d] = await clickExport('Export CSV (control poses)');
  assert.equal(d.suggestedFilename(), 'cylinder5-control-poses.csv');
  const text = fs.readFileSync(await d.path(), 'utf8');
  const lines = text.trim().split('\n');
  assert.equal(lines[0], 'x,y,z,qw,qx,qy,qz,time,velocity');
  assert.equal(lines.length, 1 + before.poses.length + 1, 'one row per control pose, and pose 0 again at the end of the cycle');
  assert.match(await page.locator('#toast').textContent(), /5 control poses/);
  await page.evaluate(() => window.screwbender.app.run('loadPreset', 'l_cycle_rotated'));
  await drop([{ name: 'cylinder5-control-poses.csv', bytes: text }]);
  const after = await page.evaluate(() => window.screwbender.app.motion.toDocument());
  assert.equal(after.poses.length, before.poses.length);
  assert.equal(after.closed, before.closed);
  assert.deepEqual(after.times, before.times);
  assert.deepEqual(after.velocities, before.velocities);
  after.poses.forEach((p, i) => {
    const q = before.poses[i];
    p.origin.forEach((v, k) => assert.ok(Math.abs(v - q.origin[k]) <= 1e-12, `pose ${i} origin`));
    const dot = p.rotation.reduce((acc, v, k) => acc + v * q.rotation[k], 0);
    assert.ok(1 - Math.abs(dot) <= 1e-12, `pose ${i} rotation`);
  });
  assert.deepEqual(problems, []);
});

test(`${BACKEND}: Export CSV (samples of the motion) gives sampled poses; a dropped pose CSV sets the control poses`, async () => {
  await page.evaluate(() => window.screwbender.app.run('loadPreset', 'circle4'));
  const [d] = await clickExport('Export CSV (samples of the motion)');
  const text = fs.readFileSync(await d.path(), 'utf8');
  const lines = text.trim().split('\n');
  assert.match(lines[0], /qw/);
  assert.ok(lines.length > 50, `${lines.length} lines`);
  for (const l of lines.slice(1)) for (const v of l.split(',')) assert.ok(Number.isFinite(Number(v)), l);
  const [t] = await clickExport('Export CSV (body-point path)');
  assert.match(fs.readFileSync(await t.path(), 'utf8').split('\n')[0], /x/);
  const csv = 'x,y,z,qw,qx,qy,qz\n0,0,0,1,0,0,0\n3,0,0,0.7071067811865476,0,0,0.7071067811865476\n3,3,1,0,0,0,1\n';
  await drop([{ name: 'walk.csv', bytes: csv }]);
  const p = await poses();
  assert.equal(p.length, 21);
  assertPosesClose(p.slice(7, 14), [3, 0, 0, Math.SQRT1_2, 0, 0, Math.SQRT1_2], 1e-12);
  // Undo brings the previous motion back.
  await page.locator('#t-undo').click();
  assert.equal((await poses()).length, 28);
});

test(`${BACKEND}: bad dropped files name the problem and change nothing`, async () => {
  await page.evaluate(() => window.screwbender.app.run('loadPreset', 'l_cycle_rotated'));
  const s0 = await session();
  const cases = [
    [{ name: 'bad.csv', bytes: 'x,y,z,qw,qx,qy,qz\n0,0,0,1,0,0,0\n1,2,abc,1,0,0,0\n' }, /bad\.csv: .*line 3/],
    [{ name: 'short.csv', bytes: '0,0,0,1,0,0\n1,0,0,1,0,0,0\n' }, /short\.csv: .*line 1/],
    [{ name: 'trunc.glb', bytes: new Uint8Array([0x67, 0x6c, 0x54, 0x46, 2, 0, 0, 0, 200, 0, 0, 0]) }, /trunc\.glb: /],
    [{ name: 'noanim.gltf', bytes: '{"asset":{"version":"2.0"},"nodes":[{"name":"a"}]}' }, /noanim\.gltf: .*(anim|mesh)/i],
    [{ name: 'motion.json', bytes: '{"poses":[{"origin":[0,0,0],"rotation":[0,0,0,0]},{"origin":[1,0,0],"rotation":[1,0,0,0]}]}' }, /motion\.json: poses\[0\]\.rotation: zero quaternion/],
    [{ name: 'notes.txt', bytes: 'hello' }, /notes\.txt: unknown file type/],
  ];
  for (const [file, re] of cases) {
    await page.evaluate(() => window.screwbender.app.errors.splice(0));
    await drop([file]);
    const errors = await page.evaluate(() => window.screwbender.errors());
    assert.ok(errors.some((e) => re.test(e)), `${file.name}: ${JSON.stringify(errors)}`);
    assert.equal(await session(), s0, `${file.name} changed the session`);
  }
  assert.deepEqual(problems, []);
});

test(`${BACKEND}: a dropped OBJ becomes the object's mesh`, async () => {
  const obj = 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n';
  await drop([{ name: 'tet.obj', bytes: obj }]);
  assert.equal(await page.evaluate(() => window.screwbender.app.view.object), 'obj');
  // The export carries the imported mesh: more than the placeholder's 12 triangles is not
  // expected here, but the mesh's 4 triangles must be there.
  const file = await page.evaluate(async () => {
    const { exportMotion } = await import('./js/editor/files.js');
    const f = await exportMotion(window.screwbender.app, 'gltf', {}, { save: false });
    return new TextDecoder().decode(f.data);
  });
  const json = JSON.parse(file);
  const idx = json.meshes[0].primitives[0].indices;
  assert.equal(json.accessors[idx].count, 12);
  assert.deepEqual(problems, []);
});
