// e2e-backends: webgpu webgl2 (every test encodes and checks frames read back from each backend's canvas)
// End-to-end: videos of one cycle out of the playground (editor/media.js, muxed by mediabunny):
// MP4 with H.264 and WebM, each a real download whose container holds every frame at the motion's
// times (the boxes and elements read here, not by mediabunny) and which a <video> plays with the
// cycle's duration and frame count. Each test records and checks the backend's frames, so the
// file runs on both; what no frame decides (the WebM instead of an MP4 without an H.264 encoder,
// a refused format, cancelling, a browser without an encoder) is view-menu.test.mjs, once.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import { waitFrames, playgroundPage, downloadFrom } from './lib.mjs';
import { FPS, mp4Info, webmInfo } from './containers.mjs';

let play;
let page;
let problems;
/** A blank page (no content security policy) where the videos are played. */
let blank;

/** The light background as displayed (www/js/figure/slots.js BACKGROUND), 0..255. */
const LIGHT = [232, 236, 241];

before(async () => {
  ({ play, page, problems } = await playgroundPage({ acceptDownloads: true }));
  blank = await play.context.newPage();
  await page.bringToFront();
  await page.evaluate(() => window.screwbender.app.run('loadPreset', 'l_cycle_rotated'));
  await page.evaluate(() => document.querySelector('#hint .close')?.click());
  // A small view: software encoding on a loaded machine takes its time.
  await page.setViewportSize({ width: 480, height: 320 });
  await waitFrames(page, 2);
  // Retimed (key times in seconds, 0.4 s per span): the video follows the timeline's seconds.
  assert.equal(await page.evaluate(() => {
    const { app } = window.screwbender;
    const shown = app.errors.length;
    app.run('setTimes', [0, 0.4, 0.8, 1.2, 1.6, 2.0, 2.4]);
    return app.errors.slice(shown).join(' ');
  }), '', 'setTimes applied without a message');
});

after(async () => {
  await play?.close();
});

/** Runs `action` and returns the download it causes (null when none came within `ms`). */
const downloadOf = (action, ms) => downloadFrom(page, action, ms);

/**
 * Plays `bytes` (of MIME `type`) in a <video> of the blank page: its size, duration, a frame a
 * third in (the fraction of pixels that differ from the background) and the frames a fresh
 * player decodes playing it from start to end (getVideoPlaybackQuality: shown or dropped).
 */
function playVideo(bytes, type) {
  return blank.evaluate(async ({ b64, type, bg }) => {
    const blob = new Blob([Uint8Array.from(atob(b64), (ch) => ch.charCodeAt(0))], { type });
    const v = document.createElement('video');
    v.muted = true;
    v.src = URL.createObjectURL(blob);
    document.body.append(v);
    await new Promise((resolve, reject) => {
      v.onloadeddata = resolve;
      v.onerror = () => reject(new Error(`video error ${v.error?.code} ${v.error?.message}`));
    });
    await new Promise((resolve) => {
      v.onseeked = resolve;
      v.currentTime = v.duration / 3;
    });
    const c = new OffscreenCanvas(v.videoWidth, v.videoHeight);
    const g = c.getContext('2d');
    g.drawImage(v, 0, 0);
    const d = g.getImageData(0, 0, c.width, c.height).data;
    let differ = 0;
    for (let i = 0; i < d.length; i += 4) if (Math.abs(d[i] - bg[0]) + Math.abs(d[i + 1] - bg[1]) + Math.abs(d[i + 2] - bg[2]) > 30) differ++;
    v.remove();
    // A fresh player from the start to the end at normal speed: every frame is decoded once.
    const p = document.createElement('video');
    p.muted = true;
    p.src = v.src;
    document.body.append(p);
    const ended = new Promise((resolve) => (p.onended = resolve));
    await p.play();
    await ended;
    const frames = p.getVideoPlaybackQuality().totalVideoFrames;
    p.remove();
    return { width: v.videoWidth, height: v.videoHeight, duration: v.duration, differ: differ / (d.length / 4), frames };
  }, { b64: Buffer.from(bytes).toString('base64'), type, bg: LIGHT });
}

const cycle = () =>
  page.evaluate(() => {
    const { start, end } = window.screwbender.app.viewer.playhead();
    return end - start;
  });

/** Checks what a <video> makes of a recording of `want` frames at the view's size. */
async function checkPlayback(bytes, type, want) {
  const { w, h } = await page.evaluate(() => window.screwbender.app.viewer.pixelSize());
  const video = await playVideo(bytes, type);
  assert.deepEqual([video.width, video.height], [w & ~1, h & ~1], "the view's size (even sides)");
  // The player's duration: the frames' span, to a frame.
  assert.ok(Math.abs(video.duration - want / FPS) <= 1 / FPS, `the player's duration ${video.duration} s for ${want} frames`);
  assert.ok(video.differ > 0.02, `a drawn frame: ${(video.differ * 100).toFixed(1)} % differs from the background`);
  assert.equal(video.frames, want, 'frames decoded by the player from start to end');
}

test('MP4: H.264 from the View menu, every frame of one cycle at its time, plays in a <video>', async () => {
  const cycleS = await cycle();
  assert.ok(Math.abs(cycleS - 2.4) < 1e-12, `cycle ${cycleS} s`);
  // By the menu, with real clicks: MP4 is the default.
  await page.click('#t-view');
  assert.equal(await page.isChecked('#m-video-mp4'), true, 'MP4 is the default');
  const d = await downloadOf(() => page.click('#m-video'));
  assert.ok(d, 'a video download');
  assert.match(d.suggestedFilename(), /^[a-z0-9-]+\.mp4$/);
  const bytes = fs.readFileSync(await d.path());
  const want = Math.round(cycleS * FPS);
  const info = mp4Info(bytes);
  assert.equal(info.entry, 'avc1', 'H.264 samples');
  assert.match(info.brand, /^(isom|mp42|avc1|iso\d)$/, `brand ${info.brand}`);
  assert.equal(info.samples, want, 'every frame is in the file');
  assert.equal(info.sttsSamples, want);
  // Times: frame i at i / FPS, each lasting 1 / FPS (to the file's time units and µs stamps).
  const TOL = 2e-3;
  assert.ok(Math.abs(info.sttsSpan - want / FPS) <= TOL, `samples span ${info.sttsSpan} s`);
  assert.ok(Math.abs(info.duration - want / FPS) <= TOL, `track duration ${info.duration} s`);
  await checkPlayback(bytes, 'video/mp4', want);
  assert.equal(await page.locator('#rec').isHidden(), true);
  assert.deepEqual(problems, []);
});

test('WebM: VP8 / VP9 when chosen in the menu, every frame, plays in a <video>', async () => {
  await page.click('#t-view');
  await page.check('#m-video-webm');
  const d = await downloadOf(() => page.click('#m-video'));
  assert.ok(d, 'a video download');
  assert.match(d.suggestedFilename(), /^[a-z0-9-]+\.webm$/);
  const bytes = fs.readFileSync(await d.path());
  assert.deepEqual([...bytes.subarray(0, 4)], [0x1a, 0x45, 0xdf, 0xa3], 'EBML header');
  assert.ok(bytes.includes(Buffer.from('webm')), 'DocType webm');
  const want = Math.round((await cycle()) * FPS);
  const info = webmInfo(bytes);
  assert.match(info.codec, /^V_VP[89]$/);
  assert.equal(info.blocks, want, 'every frame is in the video');
  // Frame times are whole milliseconds in the file.
  const TOL = 1.5e-3;
  assert.ok(Math.abs(info.duration - want / FPS) <= TOL, `Duration ${info.duration} s`);
  assert.ok(Math.abs(info.span - want / FPS) <= TOL, `blocks span ${info.span} s`);
  await checkPlayback(bytes, 'video/webm', want);
  await page.click('#t-view');
  await page.check('#m-video-mp4');
  await page.keyboard.press('Escape');
  assert.deepEqual(problems, []);
});
