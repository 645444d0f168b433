// e2e-backends: webgpu webgl2 (each backend draws the figures, and each has its own renderer and wasm module to leak)
// The embeddable figure <screw-bender> as drawn on each backend, on the course example page
// (www/examples/course.html): four figures start on the expected backend (one WebGPU device for
// all of them), draw distinct non-empty pictures under a strict CSP, and figures created and
// removed 50 times leave no errors, flat wasm memory and a flat JS heap. What no backend decides
// (storage, events, picking, attributes, layout) is viewer.test.mjs.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { EXPECTED_BACKEND } from './lib.mjs';
import { COURSE, FIGURES, coursePlayground, openFigures, signature } from './course-lib.mjs';

let play;
/** The course page both tests share (opened by the first). */
let course;
before(async () => {
  play = await coursePlayground();
});
after(async () => {
  await play?.close();
});

/** The shared course page and its problems. */
async function sharedCourse() {
  course ??= await openFigures(play, COURSE);
  return course;
}

const meanAbsDiff = (a, b) => a.reduce((s, x, i) => s + Math.abs(x - b[i]), 0) / a.length;

test('the course page: four figures on the expected backend, distinct and non-empty, under a strict CSP', async () => {
  const { page, problems } = await sharedCourse();
  const ids = await page.evaluate(() => [...document.querySelectorAll('screw-bender')].map((e) => e.id));
  assert.deepEqual(ids, FIGURES);
  for (const id of FIGURES) {
    assert.equal(await page.evaluate((i) => document.getElementById(i).backend, id), EXPECTED_BACKEND, id);
  }
  const sigs = {};
  for (const id of FIGURES) {
    sigs[id] = await signature(page, id);
    // Strobe, trajectories and control poses cover a visible part of each figure.
    assert.ok(sigs[id].nonBackground > 0.03, `${id}: only ${sigs[id].nonBackground} of the pixels are drawn`);
  }
  // The three kinds of figure (screw, polyscrew vs 4-point, B-spline) differ from each other.
  for (const [a, b] of [['fig-screw', 'fig-fourpoint'], ['fig-screw', 'fig-bspline'], ['fig-fourpoint', 'fig-bspline']]) {
    const d = meanAbsDiff(sigs[a].grey, sigs[b].grey);
    assert.ok(d > 3, `${a} and ${b} look alike (mean grey difference ${d.toFixed(2)})`);
  }
  const errorsShown = await page.evaluate(() =>
    [...document.querySelectorAll('screw-bender')].map((e) => e.shadowRoot.querySelector('.msg').hidden),
  );
  assert.deepEqual(errorsShown, FIGURES.map(() => true), 'no figure shows a message');
  assert.deepEqual(await page.evaluate(() => window.__csp), [], 'no CSP violation');
  // One GPU device for all four figures (WebGL2 has one context per canvas by nature).
  if (EXPECTED_BACKEND === 'WebGPU') assert.equal(await page.evaluate(() => window.__devices), 1);
  assert.deepEqual(problems, []);
});

test('a src motion file loads; figures created and removed 50 times leave no errors and flat memory', async (t) => {
  const { page, problems } = await sharedCourse();
  const loaded = await page.evaluate(async () => {
    const el = document.createElement('screw-bender');
    el.setAttribute('loading', 'eager');
    el.setAttribute('src', 'two-poses.json');
    document.querySelector('main').append(el);
    await el.ready;
    const n = el.motion.poseCount;
    el.remove();
    return n;
  });
  assert.equal(loaded, 3);
  // A playground share-link payload: the figure shows the session's poses and options.
  const shared = await page.evaluate(async () => {
    const { encodeHash } = await import('../js/share-link.js');
    const doc = { closed: true, poses: [
      { origin: [0, 0, 0], rotation: [1, 0, 0, 0] },
      { origin: [2, 0, 0], rotation: [0, 1, 0, 0] },
      { origin: [1, 2, 0], rotation: [0.5, 0.5, 0.5, 0.5] },
    ] };
    const payload = encodeHash({ version: 1, document: doc, options: { scheme: 'jarek', levels: 3, j: 0.5, rules: 'direct' }, view: { strobe: 12 } });
    const el = document.createElement('screw-bender');
    el.setAttribute('loading', 'eager');
    el.setAttribute('share', `https://example.org/screwbender/#s=${payload}`);
    document.querySelector('main').append(el);
    await el.ready;
    const r = { poses: Array.from(el.motion.poses()), options: el.motion.options(), hidden: el.shadowRoot.querySelector('.msg').hidden };
    el.remove();
    return r;
  });
  assert.equal(shared.hidden, true);
  assert.deepEqual(shared.poses, [0, 0, 0, 1, 0, 0, 0, 2, 0, 0, 0, 1, 0, 0, 1, 2, 0, 0.5, 0.5, 0.5, 0.5]);
  assert.equal(shared.options.scheme, 'jarek');
  assert.equal(shared.options.levels, 3);
  const round = () =>
    page.evaluate(async (gl) => {
      const box = document.createElement('div');
      document.querySelector('main').append(box);
      // One after another: ten figures starting at once reach a peak of wasm memory that depends
      // on how their starts interleave (wasm memory only grows), so a round after the warm-up
      // could grow it with nothing left behind. Started in turn, every round peaks alike and
      // growth is what figures leave.
      const els = [];
      for (let k = 0; k < 10; k++) {
        const el = document.createElement('screw-bender');
        el.setAttribute('loading', 'eager');
        el.setAttribute('scene', k % 2 ? 'circle4' : 'l_cycle_rotated');
        el.setAttribute('autoplay', '');
        box.append(el);
        els.push(el);
        await el.ready;
      }
      await new Promise((res) => requestAnimationFrame(() => requestAnimationFrame(res)));
      const failed = els.filter((e) => !e.shadowRoot.querySelector('.msg').hidden).length;
      box.remove();
      await new Promise((res) => setTimeout(res, 50));
      // The figures' shared module (element/modules.js): the WebGPU one, or the WebGL2 one.
      const wasm = await (await import(gl ? '../pkg-gl/screwbender.js' : '../pkg-webgpu/screwbender.js')).default();
      return { failed, wasmBytes: wasm.memory.buffer.byteLength, figures: document.querySelectorAll('screw-bender').length };
    }, EXPECTED_BACKEND === 'WebGL2');
  const cdp = await page.context().newCDPSession(page);
  const heap = async () => {
    await cdp.send('HeapProfiler.collectGarbage');
    return (await cdp.send('Runtime.getHeapUsage')).usedSize;
  };
  // Two rounds warm up (the allocator settles: wasm memory grows once, by a page, on round 2).
  const first = await round();
  assert.equal(first.failed, 0);
  assert.equal(first.figures, FIGURES.length, 'removed figures are gone');
  const warm = await round();
  const heap1 = await heap();
  let last = warm;
  const ROUNDS = 3;
  for (let r = 0; r < ROUNDS; r++) {
    last = await round();
    assert.equal(last.failed, 0);
    assert.equal(last.figures, FIGURES.length);
  }
  const heap2 = await heap();
  // wasm memory never shrinks, but freed motions and renderers are reused: what it grows by
  // over the measured rounds is what they leaked (or the allocator could not reuse). The bounds
  // are proportional, 10 % of the wasm memory and of the JS heap after warm-up, so they follow
  // the page's own size; per figure the growth is stated in the log
  // (docs/speed/element-many-figures.md has the measurements).
  const figures = ROUNDS * 10;
  const grown = last.wasmBytes - warm.wasmBytes;
  t.diagnostic(`${EXPECTED_BACKEND}: wasm memory ${warm.wasmBytes} -> ${last.wasmBytes} over ${figures} figures, ${Math.round(grown / figures)} B per figure; JS heap ${heap1} -> ${heap2}, ${Math.round((heap2 - heap1) / figures)} B per figure`);
  assert.ok(grown <= warm.wasmBytes * 0.1, `wasm memory ${warm.wasmBytes} -> ${last.wasmBytes}: ${Math.round(grown / figures)} B per figure`);
  assert.ok(heap2 - heap1 <= heap1 * 0.1, `JS heap ${heap1} -> ${heap2}: ${Math.round((heap2 - heap1) / figures)} B per figure`);
  assert.deepEqual(problems, []);
});
