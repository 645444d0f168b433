// e2e-backends: webgpu webgl2 (frames are read back from each backend's canvas and encoded)
// End-to-end: videos of one cycle out of the playground (editor/media.js, muxed by mediabunny):
// MP4 with H.264 and WebM, each a real download whose container holds every frame at the motion's
// times (the boxes and elements read here, not by mediabunny) and which a <video> plays with the
// cycle's duration and frame count; MP4 in a browser without an H.264 encoder (the encoder's
// answer for H.264 replaced by "unsupported") gives WebM and a message saying why; cancelling a
// recording; a browser without any video encoder.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import { waitFrames, playgroundPage } from './lib.mjs';

let play;
let page;
let problems;
/** A blank page (no content security policy) where the videos are played. */
let blank;

/** Frames per second of the videos (editor/media.js FPS). */
const FPS = 30;
/** The light background as displayed (www/js/view/slots.js BACKGROUND), 0..255. */
const LIGHT = [232, 236, 241];

before(async () => {
  ({ play, page, problems } = await playgroundPage({ acceptDownloads: true }));
  blank = await play.context.newPage();
  await page.evaluate(() => window.screwbender.app.loadPreset('l_cycle_rotated'));
  await page.evaluate(() => document.querySelector('#hint .close')?.click());
  // A small view: software encoding on a loaded machine takes its time.
  await page.setViewportSize({ width: 480, height: 320 });
  await waitFrames(page, 2);
  // Retimed (key times in seconds, 0.4 s per span): the video follows the timeline's seconds.
  assert.equal(await page.evaluate(() => window.screwbender.app.setTimes([0, 0.4, 0.8, 1.2, 1.6, 2.0, 2.4])), null);
});

after(async () => {
  await play?.close();
});

/** Runs `action` and returns the download it causes (null when none came within `ms`). */
async function downloadOf(action, ms = 180000) {
  const got = page.waitForEvent('download', { timeout: ms }).catch(() => null);
  await action();
  return got;
}

/** The boxes of an ISO BMFF (MP4) byte range: [{type, start, end}] (start: after the header). */
function boxes(bytes, from = 0, to = bytes.length) {
  const out = [];
  let pos = from;
  while (pos + 8 <= to) {
    let size = bytes.readUInt32BE(pos);
    const type = bytes.subarray(pos + 4, pos + 8).toString('latin1');
    let head = 8;
    if (size === 1) {
      size = Number(bytes.readBigUInt64BE(pos + 8));
      head = 16;
    } else if (size === 0) size = to - pos;
    out.push({ type, start: pos + head, end: pos + size });
    pos += size;
  }
  return out;
}

/** The box of `path` (types, e.g. ['moov', 'trak', 'mdia', 'mdhd']), or undefined. */
function box(bytes, path) {
  let range = { start: 0, end: bytes.length };
  for (const type of path) {
    range = boxes(bytes, range.start, range.end).find((b) => b.type === type);
    if (!range) return undefined;
  }
  return range;
}

/**
 * What an MP4 file says: its brand, the sample entry (codec), the track's duration (mdhd,
 * seconds), the number of samples (stsz) and the times of the first and last samples from stts.
 */
function mp4Info(bytes) {
  const ftyp = box(bytes, ['ftyp']);
  const stbl = ['moov', 'trak', 'mdia', 'minf', 'stbl'];
  const mdhd = box(bytes, ['moov', 'trak', 'mdia', 'mdhd']);
  const v1 = bytes[mdhd.start] === 1;
  const timescale = bytes.readUInt32BE(mdhd.start + (v1 ? 20 : 12));
  const duration = v1 ? Number(bytes.readBigUInt64BE(mdhd.start + 24)) : bytes.readUInt32BE(mdhd.start + 16);
  const stsd = box(bytes, [...stbl, 'stsd']);
  const entry = bytes.subarray(stsd.start + 12, stsd.start + 16).toString('latin1');
  const stsz = box(bytes, [...stbl, 'stsz']);
  const samples = bytes.readUInt32BE(stsz.start + 8);
  const stts = box(bytes, [...stbl, 'stts']);
  let t = 0;
  let counted = 0;
  const runs = bytes.readUInt32BE(stts.start + 4);
  for (let k = 0; k < runs; k++) {
    const n = bytes.readUInt32BE(stts.start + 8 + 8 * k);
    const delta = bytes.readUInt32BE(stts.start + 12 + 8 * k);
    t += n * delta;
    counted += n;
  }
  return {
    brand: bytes.subarray(ftyp.start, ftyp.start + 4).toString('latin1'),
    entry,
    duration: duration / timescale,
    samples,
    sttsSamples: counted,
    sttsSpan: t / timescale,
  };
}

/**
 * What a WebM file says of its time: `duration` (s) from the Duration element of its Info, and
 * `span` (s) from its blocks (the last block's time minus the first's, plus one frame) and their
 * count, and the codec id. Walks the EBML elements, entering Segment, Info, Tracks and Clusters.
 */
function webmInfo(bytes) {
  const MASTERS = new Set([0x18538067, 0x1549a966, 0x1f43b675, 0x1654ae6b, 0xae, 0xa0]); // Segment, Info, Cluster, Tracks, TrackEntry, BlockGroup
  let pos = 0;
  const vint = (keepMarker) => {
    const first = bytes[pos];
    let len = 1;
    while (len <= 8 && !(first & (0x80 >> (len - 1)))) len++;
    let v = keepMarker ? first : first & (0xff >> len);
    for (let k = 1; k < len; k++) v = v * 256 + bytes[pos + k];
    pos += len;
    return v;
  };
  const uint = (at, n) => {
    let v = 0;
    for (let k = 0; k < n; k++) v = v * 256 + bytes[at + k];
    return v;
  };
  let scale = 1e6; // ns per timecode unit (TimecodeScale's default)
  let duration = NaN;
  let cluster = 0;
  let first = Infinity;
  let last = -Infinity;
  let blocks = 0;
  let codec = '';
  while (pos < bytes.length) {
    const id = vint(true);
    const size = vint(false);
    const start = pos;
    if (MASTERS.has(id)) continue;
    if (id === 0x2ad7b1) scale = uint(start, size);
    else if (id === 0x4489) duration = size === 8 ? bytes.readDoubleBE(start) : bytes.readFloatBE(start);
    else if (id === 0x86) codec = bytes.subarray(start, start + size).toString('latin1');
    else if (id === 0xe7) cluster = uint(start, size);
    else if (id === 0xa3 || id === 0xa1) {
      pos = start;
      vint(false); // track number
      const t = cluster + bytes.readInt16BE(pos);
      first = Math.min(first, t);
      last = Math.max(last, t);
      blocks++;
    }
    pos = start + size;
  }
  return { codec, duration: (duration * scale) / 1e9, span: ((last - first) * scale) / 1e9 + 1 / FPS, blocks };
}

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
  const { w, h } = await page.evaluate(() => window.screwbender.app.pixelSize());
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

test('MP4 without an H.264 encoder: a WebM instead, and a message saying why', async () => {
  // This browser's encoder is asked for H.264 and says no (as a browser without one does).
  await page.evaluate(() => {
    window.__isConfigSupported = VideoEncoder.isConfigSupported;
    VideoEncoder.isConfigSupported = async (config) =>
      config.codec.startsWith('avc1') ? { supported: false, config } : window.__isConfigSupported.call(VideoEncoder, config);
  });
  try {
    let result;
    const d = await downloadOf(async () => {
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
  await page.setViewportSize({ width: 1280, height: 800 });
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
