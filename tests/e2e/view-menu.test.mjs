// e2e-backends: webgpu (menus, camera and picking are computed on the CPU, the same on either backend: once)
// End-to-end: the playground's View menu where no drawing decides the result (editor/viewpoint.js,
// editor/media.js): camera presets by key and by menu, the orthographic projection with picking
// by a real click, the menu on screen and by keyboard at phone and desktop size, and the picture
// and video requests that are refused or cancelled (a bad scale or format, cancelling a
// recording, a browser without a video encoder) changing nothing, and the WebM made instead of
// an MP4 in a browser without an H.264 encoder (the encoder's answer for H.264 replaced by
// "unsupported"), with a message saying why. The pictures and videos
// themselves, read back from each backend's canvas, are media.test.mjs and video-export.test.mjs.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import { DESKTOP, downloadFrom, openViewMenu, playgroundPage, waitFrames } from './lib.mjs';
import { webmInfo } from './containers.mjs';

let play;
let page;
let problems;

before(async () => {
  ({ play, page, problems } = await playgroundPage({ acceptDownloads: true }));
  await page.evaluate(() => window.screwbender.app.run('loadPreset', 'l_cycle_rotated'));
  // The first-visit hint moves with the layout; it is not what these tests are about.
  await page.evaluate(() => document.querySelector('#hint .close')?.click());
  await waitFrames(page, 2);
});

after(async () => {
  await play?.close();
});

/** Clicks `item` in the View menu. */
async function menuClick(item) {
  await openViewMenu(page);
  await page.click(item);
}

const camera = () => page.evaluate(() => ({ ...window.screwbender.app.viewer.camera.toJSON() }));

test('camera presets by key and by menu set the view direction', async () => {
  const EPS = 1e-12;
  await page.focus('#view');
  await page.keyboard.press('Shift+T');
  let c = await camera();
  assert.ok(Math.abs(c.yaw + Math.PI / 2) < EPS && Math.abs(c.pitch - Math.PI / 2) < EPS, `top: ${c.yaw}, ${c.pitch}`);
  // Looking straight down, x points right on the screen: pose handles keep their order in x.
  await page.keyboard.press('Shift+F');
  c = await camera();
  assert.ok(Math.abs(c.yaw + Math.PI / 2) < EPS && Math.abs(c.pitch) < EPS, `front: ${c.yaw}, ${c.pitch}`);
  // Lower-case f is still the 4-point scheme (editor/input.js), not a camera view.
  await page.keyboard.press('f');
  assert.equal(await page.evaluate(() => window.screwbender.options().scheme), 'fourpoint');
  assert.equal((await camera()).pitch, c.pitch);
  await menuClick('[data-camera=side]');
  c = await camera();
  assert.ok(Math.abs(c.yaw) < EPS && Math.abs(c.pitch) < EPS, `side: ${c.yaw}, ${c.pitch}`);
  await page.click('[data-camera=iso]');
  c = await camera();
  assert.ok(Math.abs(c.yaw + Math.PI / 4) < EPS && Math.abs(c.pitch - Math.atan(Math.SQRT1_2)) < EPS, `iso: ${c.yaw}, ${c.pitch}`);
  await page.keyboard.press('Escape');
  assert.equal(await page.locator('#view-menu').isHidden(), true, 'Esc closes the menu');
  // The top view is drawn (no degenerate look-at straight down).
  await page.focus('#view');
  await page.keyboard.press('Shift+T');
  await waitFrames(page, 2);
  const vp = await page.evaluate(() => [...window.screwbender.app.viewer.vp]);
  assert.ok(vp.every(Number.isFinite), 'a finite view-projection looking straight down');
});

test('orthographic: the projection changes, persists, and a real click still selects a pose', async () => {
  await menuClick('#m-ortho');
  await page.keyboard.press('Escape');
  await waitFrames(page, 2);
  const s = await page.evaluate(() => {
    const { app } = window.screwbender;
    const p = app.viewer.camera.proj();
    return { ortho: app.viewer.camera.ortho, p11: p[11], p15: p[15], saved: app.parts.session.session().camera.ortho };
  });
  assert.deepEqual(s, { ortho: true, p11: 0, p15: 1, saved: true });
  assert.equal(await page.locator('#m-ortho').getAttribute('aria-pressed'), 'true');
  await page.evaluate(() => window.screwbender.app.parts.viewpoint.fit());
  await waitFrames(page, 2);
  for (const k of [1, 3]) {
    await page.evaluate(() => window.screwbender.app.select(-1));
    const at = await page.evaluate((i) => window.screwbender.handleOnPage(i), k);
    await page.mouse.click(at.x, at.y);
    await waitFrames(page, 1);
    assert.equal(await page.evaluate(() => window.screwbender.selected()), k, `pose ${k} selected by a click at ${at.x}, ${at.y}`);
  }
  // The orthographic ray is parallel to the view direction at every pixel.
  const rays = await page.evaluate(() => {
    const v = window.screwbender.app.viewer;
    return [v.ray([10, 10]).d, v.ray([300, 200]).d, v.camera.forward];
  });
  for (const d of rays.slice(0, 2)) for (let k = 0; k < 3; k++) assert.ok(Math.abs(d[k] - rays[2][k]) < 1e-12);
  // O toggles back to perspective.
  await page.focus('#view');
  await page.keyboard.press('o');
  assert.equal(await page.evaluate(() => window.screwbender.app.viewer.camera.ortho), false);
  assert.equal(await page.evaluate(() => window.screwbender.app.viewer.camera.proj()[11]), -1);
});

test('the View menu at phone size and at 1280×800: on screen, by keyboard, Esc closes it', async () => {
  for (const size of [{ width: 390, height: 844 }, DESKTOP]) {
    await page.setViewportSize(size);
    await waitFrames(page, 2);
    await page.focus('#t-view');
    await page.keyboard.press('Enter');
    assert.equal(await page.evaluate(() => document.activeElement.dataset.camera), 'front', 'the focus moves into the menu');
    const box = await page.locator('#view-menu').boundingBox();
    assert.ok(box.x >= 0 && box.y >= 0 && box.x + box.width <= size.width && box.y + box.height <= size.height, `on screen: ${JSON.stringify(box)}`);
    for (const id of ['#m-png', '#m-video', '#m-theme']) assert.ok(await page.locator(id).isVisible(), id);
    await page.keyboard.press('Escape');
    assert.equal(await page.locator('#view-menu').isHidden(), true);
    assert.equal(await page.evaluate(() => document.activeElement.id), 't-view', 'the focus goes back to the button');
  }
});

test('a bad picture request changes nothing and says why', async () => {
  const before = await page.evaluate(() => JSON.stringify(window.screwbender.session()));
  const r = await page.evaluate(() => window.screwbender.app.parts.media.savePng({ scale: 3 }));
  assert.equal(r, null);
  const errors = await page.evaluate(() => window.screwbender.errors());
  assert.match(errors.at(-1), /scale: 3 is not 1 or 2/);
  assert.equal(await page.evaluate(() => JSON.stringify(window.screwbender.session())), before);
});


test('a bad video format is refused with a message, and nothing is recorded', async () => {
  let downloads = 0;
  const count = () => downloads++;
  page.on('download', count);
  const r = await page.evaluate(() => window.screwbender.app.parts.media.recordVideo({ format: 'avi' }));
  page.off('download', count);
  assert.equal(r, null);
  assert.equal(downloads, 0);
  assert.match(await page.evaluate(() => window.screwbender.errors().at(-1)), /Video format: "avi" is not mp4 or webm/);
});

test('cancelling a recording stops it and downloads nothing', async () => {
  await page.setViewportSize(DESKTOP);
  await waitFrames(page, 2);
  const anim = await page.evaluate(() => ({ u: window.screwbender.app.anim.u, playing: window.screwbender.app.anim.playing }));
  let downloads = 0;
  const count = () => downloads++;
  page.on('download', count);
  await page.click('#t-view');
  await page.click('#m-video');
  await page.waitForFunction(() => !document.getElementById('rec').hidden && document.getElementById('rec-progress').value > 0);
  await page.click('#rec-cancel');
  await page.waitForFunction(() => document.getElementById('rec').hidden);
  // Nothing arrives afterwards either (the muxer's output is dropped).
  await page.waitForTimeout(1500);
  page.off('download', count);
  assert.equal(downloads, 0);
  const after = await page.evaluate(() => ({ u: window.screwbender.app.anim.u, playing: window.screwbender.app.anim.playing }));
  assert.deepEqual(after, anim, 'the playback as before');
  assert.equal(await page.evaluate(() => window.screwbender.app.parts.media.recording), false);
});

test('without a video encoder: a clear message, nothing changes, no exception', async () => {
  const before = await page.evaluate(() => JSON.stringify(window.screwbender.session()));
  const errorsBefore = problems.length;
  await page.evaluate(() => {
    window.__enc = window.VideoEncoder;
    window.VideoEncoder = undefined;
  });
  let downloads = 0;
  const count = () => downloads++;
  page.on('download', count);
  await page.click('#t-view');
  await page.click('#m-video');
  await page.waitForFunction(() => /no video encoder/.test(window.screwbender.errors().at(-1) ?? ''));
  await page.evaluate(() => (window.VideoEncoder = window.__enc));
  page.off('download', count);
  assert.equal(downloads, 0);
  assert.equal(await page.locator('#rec').isHidden(), true);
  assert.equal(await page.locator('#banner').isVisible(), true);
  assert.equal(await page.evaluate(() => JSON.stringify(window.screwbender.session())), before);
  assert.equal(problems.length, errorsBefore, problems.join('\n'));
});

test('MP4 without an H.264 encoder: a WebM instead, and a message saying why', async () => {
  // A small view and a short cycle (0.4 s per span): encoding in software takes its time.
  await page.setViewportSize({ width: 480, height: 320 });
  assert.equal(await page.evaluate(() => {
    const { app } = window.screwbender;
    const shown = app.errors.length;
    app.run('setTimes', [0, 0.4, 0.8, 1.2, 1.6, 2.0, 2.4]);
    return app.errors.slice(shown).join(' ');
  }), '', 'setTimes applied without a message');
  // This browser's encoder is asked for H.264 and says no (as a browser without one does).
  await page.evaluate(() => {
    window.__isConfigSupported = VideoEncoder.isConfigSupported;
    VideoEncoder.isConfigSupported = async (config) =>
      config.codec.startsWith('avc1') ? { supported: false, config } : window.__isConfigSupported.call(VideoEncoder, config);
  });
  try {
    let result;
    const d = await downloadFrom(page, async () => {
      result = await page.evaluate(() => window.screwbender.app.parts.media.recordVideo({ format: 'mp4' }));
    });
    assert.ok(d, `a download (${JSON.stringify(result)})`);
    assert.match(d.suggestedFilename(), /\.webm$/);
    assert.equal(result.format, 'webm');
    const info = webmInfo(fs.readFileSync(await d.path()));
    assert.equal(info.blocks, result.frames);
    const msg = await page.evaluate(() => window.screwbender.errors().at(-1));
    assert.match(msg, /No MP4: this browser has no H\.264 encoder .*which MP4 needs.*\(WebM\) instead/);
    assert.equal(await page.locator('#banner').isVisible(), true);
  } finally {
    await page.evaluate(() => (VideoEncoder.isConfigSupported = window.__isConfigSupported));
  }
});

test('no console error or page error in all of the above', () => {
  assert.deepEqual(problems, []);
});
