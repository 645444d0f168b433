// e2e-backends: webgpu (picking, drags, keys, files and links are computed on the CPU, the same on either backend: once)
// End-to-end tests of editing in the playground in headless Chromium (playwright-core + Debian
// chromium): selecting and dragging poses and gizmo parts, undo and redo, shortcuts, playback,
// the autosave across a reload, a share link in a fresh context, bad input, export, touch.
//
//   node --test tests/e2e/playground.test.mjs
//
// Serves www/ with scripts/serve.mjs on a free port, drives the page with real mouse and keyboard
// events, and reads the state back through window.screwbender (documented in www/js/main.js).
// What the page draws on each backend is playground-render.test.mjs.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { BACKEND, DESKTOP, ROOT, mouseDrag, openPage, startPlayground, waitFrames } from './lib.mjs';

const ARTIFACTS = path.join(ROOT, 'artifacts', `e2e-${BACKEND}`);

let play;
let url;
let context;
let page;
let problems;

before(async () => {
  fs.mkdirSync(ARTIFACTS, { recursive: true });
  play = await startPlayground({ viewport: DESKTOP, acceptDownloads: true });
  ({ url, context } = play);
  ({ page, problems } = await openPage(context, url, BACKEND));
});

after(async () => {
  await play?.close();
});

const sb = (f, arg) => page.evaluate(f, arg);
const poses = () => sb(() => Array.from(window.screwbender.poses()));
const refined = () => sb(() => Array.from(window.screwbender.refined()));
const maxDiff = (a, b) => Math.max(...a.map((x, i) => Math.abs(x - b[i])));

const drag = (from, dx, dy, opts) => mouseDrag(page, from, dx, dy, opts);

/** Opens the lil-gui "File" folder (whatever state an earlier test left it in). */
async function openFileFolder() {
  await sb(() => window.screwbender.app.ui.gui.folders.find((f) => f._title === 'File').open());
}

async function fresh(preset = 'l_cycle_rotated') {
  await sb((id) => {
    window.screwbender.app.run('loadPreset', id);
    window.screwbender.app.select(-1);
    window.screwbender.app.setMode('translate');
  }, preset);
  await waitFrames(page, 1);
}

test(`${BACKEND}: click selects a pose; dragging it moves it and re-subdivides live`, async () => {
  await fresh();
  const p0 = await poses();
  const r0 = await refined();
  const h = await sb(() => window.screwbender.handleOnPage(2));
  let mid;
  let localVsFull;
  await drag(h, 60, -40, {
    during: async () => {
      mid = await refined();
      // The drag session's locally updated motion equals a full re-subdivision.
      localVsFull = await sb(() => {
        const app = window.screwbender.app;
        // A full re-subdivision of the session's control poses, through the JS Motion API.
        const Motion = app.motion.constructor;
        const full = Motion.fromPoses(app.drag.session.poses(), app.motion.closed, app.motion.options());
        let worst = 0;
        for (let k = 0; k < 97; k++) {
          const u = (6 * k) / 97;
          const a = app.drag.session.poseAt(u);
          const b = full.poseAt(u);
          const fp = [...b.origin, ...b.rotation];
          const sign = Math.sign(a[3] * fp[3] + a[4] * fp[4] + a[5] * fp[5] + a[6] * fp[6]) || 1;
          for (let i = 0; i < 7; i++) worst = Math.max(worst, Math.abs(a[i] - (i > 2 ? sign : 1) * fp[i]));
        }
        full.free();
        return worst;
      });
    },
  });
  assert.ok(localVsFull < 1e-12, `local update differs from a full rebuild by ${localVsFull}`);
  assert.equal(await sb(() => window.screwbender.selected()), 2);
  const p1 = await poses();
  const moved = Math.hypot(p1[14] - p0[14], p1[15] - p0[15], p1[16] - p0[16]);
  assert.ok(moved > 0.2, `pose 2 moved only ${moved}`);
  for (const k of [0, 1, 3, 4, 5]) assert.deepEqual(p1.slice(k * 7, k * 7 + 7), p0.slice(k * 7, k * 7 + 7), `pose ${k} moved`);
  assert.ok(maxDiff(mid, r0) > 0.05, 'the refined motion did not change during the drag');
  assert.ok(maxDiff(await refined(), r0) > 0.1, 'the refined motion did not change');
});

test(`${BACKEND}: the translate gizmo's x arrow moves along x only`, async () => {
  await fresh();
  await sb(() => window.screwbender.app.select(1));
  await waitFrames(page, 1);
  const p0 = await poses();
  const a = await sb(() => window.screwbender.gizmoOnPage('axis-x'));
  const c = await sb(() => window.screwbender.handleOnPage(1));
  const dir = [a.x - c.x, a.y - c.y];
  const n = Math.hypot(...dir);
  await drag(a, (dir[0] / n) * 70, (dir[1] / n) * 70);
  const p1 = await poses();
  assert.ok(p1[7] - p0[7] > 0.3, `x moved by ${p1[7] - p0[7]}`);
  assert.ok(Math.abs(p1[8] - p0[8]) < 1e-9 && Math.abs(p1[9] - p0[9]) < 1e-9, 'y/z must not move');
});

test(`${BACKEND}: a ring drag rotates the pose about its origin`, async () => {
  await fresh();
  await sb(() => window.screwbender.app.select(3));
  await page.keyboard.press('e');
  await waitFrames(page, 1);
  const p0 = await poses();
  const ring = await sb(() => window.screwbender.gizmoOnPage('ring-z'));
  const c = await sb(() => window.screwbender.handleOnPage(3));
  // Drag tangentially to the ring.
  const t = [-(ring.y - c.y), ring.x - c.x];
  const n = Math.hypot(...t);
  await drag(ring, (t[0] / n) * 60, (t[1] / n) * 60);
  const p1 = await poses();
  const q0 = p0.slice(24, 28);
  const q1 = p1.slice(24, 28);
  const dot = Math.abs(q0.reduce((s, x, i) => s + x * q1[i], 0));
  const angle = 2 * Math.acos(Math.min(1, dot));
  assert.ok(angle > 0.2, `rotated by only ${angle} rad`);
  assert.deepEqual(p1.slice(21, 24), p0.slice(21, 24), 'a rotation keeps the origin');
  // Rotation about world z: the quaternion's x and y parts relative to the start stay ~0.
  assert.equal(await sb(() => window.screwbender.app.mode), 'rotate');
});

test(`${BACKEND}: undo restores and redo re-applies (keyboard)`, async () => {
  await fresh();
  const p0 = await poses();
  const h = await sb(() => window.screwbender.handleOnPage(4));
  await drag(h, -50, 30);
  const p1 = await poses();
  assert.ok(maxDiff(p1, p0) > 0.1);
  await page.keyboard.press('Control+z');
  await waitFrames(page, 1);
  assert.deepEqual(await poses(), p0);
  await page.keyboard.press('Control+Shift+z');
  await waitFrames(page, 1);
  assert.deepEqual(await poses(), p1);
});

test(`${BACKEND}: shortcuts change levels, scheme, insert and delete`, async () => {
  await fresh();
  await page.keyboard.press('3');
  await page.keyboard.press('b');
  let o = await sb(() => window.screwbender.options());
  assert.equal(o.levels, 3);
  assert.equal(o.scheme, 'bspline');
  assert.equal((await refined()).length / 7, 6 * 8);
  await sb(() => window.screwbender.app.select(2));
  await page.keyboard.press('i');
  assert.equal((await poses()).length / 7, 7);
  assert.equal(await sb(() => window.screwbender.selected()), 3);
  await page.keyboard.press('Delete');
  assert.equal((await poses()).length / 7, 6);
  await page.keyboard.press('j');
  o = await sb(() => window.screwbender.options());
  assert.equal(o.scheme, 'jarek');
});

test(`${BACKEND}: play animates the object along the motion`, async () => {
  await fresh();
  const u0 = await sb(() => window.screwbender.app.anim.u);
  await page.locator('#view').focus();
  await page.keyboard.press(' ');
  await page.waitForFunction((u) => window.screwbender.app.anim.u > u + 0.1, u0, { timeout: 15000 });
  await page.keyboard.press(' ');
  const u1 = await sb(() => window.screwbender.app.anim.u);
  assert.ok(u1 > u0 + 0.1, `u went from ${u0} to ${u1}`);
  assert.equal(await sb(() => window.screwbender.app.anim.playing), false);
});

test(`${BACKEND}: reload restores the autosaved session exactly`, async () => {
  await fresh('cylinder5');
  const h = await sb(() => window.screwbender.handleOnPage(1));
  await drag(h, 40, 25);
  await page.keyboard.press('4');
  const before = await sb(() => JSON.stringify(window.screwbender.session()));
  await page.reload();
  await page.evaluate(() => window.screwbender.ready);
  await waitFrames(page, 1);
  const afterReload = await sb(() => JSON.stringify(window.screwbender.session()));
  assert.equal(afterReload, before);
});

test(`${BACKEND}: a share link reproduces the session in a fresh browser context, and in the open page`, async () => {
  await fresh('bunny6');
  await page.keyboard.press('2');
  const link = await sb(() => window.screwbender.app.parts.session.shareLink());
  const session = await sb(() => window.screwbender.session());
  const other = await play.browser.newContext({ viewport: DESKTOP });
  const p2 = await other.newPage();
  await p2.goto(BACKEND === 'webgl2' ? link.replace('/#', '/?backend=webgl2#') : link);
  await p2.evaluate(() => window.screwbender.ready);
  const s2 = await p2.evaluate(() => window.screwbender.session());
  // Documents are re-normalized on load: equal to the last bits of the quaternions.
  const flat = (d) => d.poses.flatMap((p) => [...p.origin, ...p.rotation]);
  assert.equal(s2.document.closed, session.document.closed);
  assert.ok(maxDiff(flat(s2.document), flat(session.document)) < 1e-12);
  assert.deepEqual(s2.options, session.options);
  assert.equal(s2.view.scene, 'bunny6');
  await other.close();
  // The same link pasted into the address bar of the open page, which shows something else by
  // then: only the hash changes (no load), and the link opens as one undoable edit.
  await fresh('cylinder5');
  // Undo does not move the view: the session without its camera.
  const shown = await sb(() => JSON.stringify({ ...window.screwbender.session(), camera: null }));
  await sb((l) => {
    location.hash = new URL(l).hash;
  }, link);
  await page.waitForFunction(() => window.screwbender.app.view.scene === 'bunny6');
  const s3 = await sb(() => window.screwbender.session());
  assert.ok(maxDiff(flat(s3.document), flat(session.document)) < 1e-12);
  assert.deepEqual(s3.options, session.options);
  assert.equal(await sb(() => location.hash), '', 'the link stayed in the address');
  assert.equal(await sb(() => window.screwbender.app.history.undoLabels[0]), 'Open the shared link');
  await page.keyboard.press('Control+z');
  assert.equal(await sb(() => JSON.stringify({ ...window.screwbender.session(), camera: null })), shown);
});

test(`${BACKEND}: bad JSON and OBJ input show a message and change nothing`, async () => {
  await fresh();
  const before = await sb(() => JSON.stringify(window.screwbender.session()));
  const bad = [
    '{"poses": [',
    '{"poses":[{"origin":[0,0,0],"rotation":[1,0,0,0]},{"origin":[1,0,0],"rotation":[2,0,0,0]}]}',
    '{"poses":[{"origin":[0,0,0],"rotation":[1,0,0,0]},{"origin":[1,0,"x"],"rotation":[1,0,0,0]}]}',
    '{"poses":[{"origin":[0,0,0],"rotation":[1,0,0,0]}]}',
    'x'.repeat(5_000_000),
  ];
  for (const text of bad) {
    const n0 = (await sb(() => window.screwbender.errors())).length;
    const ok = await sb((t) => window.screwbender.app.parts.files.importJson(t), text);
    assert.ok(!ok);
    const errs = await sb(() => window.screwbender.errors());
    assert.equal(errs.length, n0 + 1, `no message for ${text.slice(0, 40)}`);
    assert.ok(await page.locator('#banner').isVisible());
    assert.equal(await sb(() => JSON.stringify(window.screwbender.session())), before);
  }
  // The paste dialog path with a NaN (not valid JSON) and a non-unit quaternion.
  await openFileFolder();
  await page.locator('#panel').getByText('Paste JSON…').click();
  await page.locator('#paste textarea').fill('{"poses":[{"origin":[0,0,0],"rotation":[1,0,0,0]},{"origin":[1,0,0],"rotation":[0.5,0,0,0]}]}');
  await page.locator('#paste [data-act=load]').click();
  assert.match(await page.locator('#banner .msg').textContent(), /rotation/);
  assert.ok(await page.locator('#paste').isVisible(), 'the dialog stays open to fix the input');
  await page.locator('#paste [data-act=cancel]').click();
  for (const obj of ['v 0 0 0\nf 1 2 3\n', 'v 1 2 nan\n', 'hello']) {
    assert.equal(await sb((t) => window.screwbender.app.parts.files.importMesh('obj', t), obj), false);
  }
  assert.equal(await sb(() => JSON.stringify(window.screwbender.session())), before);
  // A valid OBJ through the file input becomes the object.
  const objPath = path.join(ARTIFACTS, 'pyramid.obj');
  fs.writeFileSync(objPath, 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 0.5 1\nf 4 3 2 1\nf 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\n');
  await page.locator('#obj-file').setInputFiles(objPath);
  await page.waitForFunction(() => window.screwbender.session().view.object === 'obj');
  await page.keyboard.press('Control+z');
  assert.equal(await sb(() => window.screwbender.session().view.object), 'scene');
  // A glTF (embedded buffer) through the same input; then a broken one is refused.
  const buf = Buffer.alloc(48 + 12);
  [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0.5].forEach((v, i) => buf.writeFloatLE(v, 4 * i));
  [0, 1, 2, 0, 2, 3].forEach((v, i) => buf.writeUInt16LE(v, 48 + 2 * i));
  const gltf = {
    asset: { version: '2.0' },
    buffers: [{ byteLength: 60, uri: `data:application/octet-stream;base64,${buf.toString('base64')}` }],
    bufferViews: [{ buffer: 0, byteOffset: 0, byteLength: 48 }, { buffer: 0, byteOffset: 48, byteLength: 12 }],
    accessors: [
      { bufferView: 0, componentType: 5126, count: 4, type: 'VEC3' },
      { bufferView: 1, componentType: 5123, count: 6, type: 'SCALAR' },
    ],
    meshes: [{ primitives: [{ attributes: { POSITION: 0 }, indices: 1 }] }],
  };
  const gltfPath = path.join(ARTIFACTS, 'quad.gltf');
  fs.writeFileSync(gltfPath, JSON.stringify(gltf));
  await page.locator('#obj-file').setInputFiles(gltfPath);
  await page.waitForFunction(() => window.screwbender.session().mesh?.kind === 'gltf');
  const badGltf = path.join(ARTIFACTS, 'bad.gltf');
  fs.writeFileSync(badGltf, JSON.stringify({ ...gltf, accessors: [{ ...gltf.accessors[0], count: 400 }, gltf.accessors[1]] }));
  const nErr = (await sb(() => window.screwbender.errors())).length;
  await page.locator('#obj-file').setInputFiles(badGltf);
  await page.waitForFunction((n) => window.screwbender.errors().length > n, nErr);
  assert.match((await sb(() => window.screwbender.errors())).at(-1), /gltf/);
  assert.equal(await sb(() => window.screwbender.session().mesh?.kind), 'gltf');
  await page.keyboard.press('Control+z');
  // A good document then loads.
  const good = '{"closed":true,"poses":[{"origin":[0,0,0],"rotation":[1,0,0,0]},{"origin":[3,0,0],"rotation":[0.7071067811865476,0,0,0.7071067811865476]},{"origin":[3,3,0],"rotation":[0,0,0,1]}]}';
  assert.equal(await sb((t) => window.screwbender.app.parts.files.importJson(t), good), true);
  assert.equal((await poses()).length / 7, 3);
});

test(`${BACKEND}: Export JSON downloads the motion document`, async () => {
  await fresh('circle4');
  await openFileFolder();
  const [download] = await Promise.all([
    page.waitForEvent('download'),
    page.locator('#panel').getByText('Export JSON').click(),
  ]);
  const file = path.join(ARTIFACTS, 'export.json');
  await download.saveAs(file);
  const doc = JSON.parse(fs.readFileSync(file, 'utf8'));
  assert.equal(doc.poses.length, 4);
  assert.equal(doc.closed, true);
});

test(`${BACKEND}: touch: one finger orbits, two fingers pinch-zoom`, async () => {
  await fresh();
  const cdp = await context.newCDPSession(page);
  const cam0 = await sb(() => window.screwbender.app.viewer.camera.toJSON());
  const touch = (type, points) => cdp.send('Input.dispatchTouchEvent', { type, touchPoints: points.map(([x, y], id) => ({ x, y, id })) });
  // One finger on empty ground (bottom left), dragged sideways.
  const y = DESKTOP.height - 100;
  await touch('touchStart', [[200, y]]);
  for (let k = 1; k <= 5; k++) await touch('touchMove', [[200 + 20 * k, y]]);
  await touch('touchEnd', []);
  const cam1 = await sb(() => window.screwbender.app.viewer.camera.toJSON());
  assert.ok(Math.abs(cam1.yaw - cam0.yaw) > 0.2, `yaw ${cam0.yaw} -> ${cam1.yaw}`);
  // Two fingers moving apart zoom in.
  await touch('touchStart', [[200, y], [260, y]]);
  for (let k = 1; k <= 5; k++) await touch('touchMove', [[200 - 10 * k, y], [260 + 10 * k, y]]);
  await touch('touchEnd', []);
  const cam2 = await sb(() => window.screwbender.app.viewer.camera.toJSON());
  assert.ok(cam2.distance < cam1.distance * 0.8, `distance ${cam1.distance} -> ${cam2.distance}`);
  await cdp.detach();
});

test(`${BACKEND}: no console error or page error in all of the above`, () => {
  assert.deepEqual(problems, []);
});
