// e2e-backends: webgpu webgl2 (pictures are drawn and read back by each renderer)
// <screw-bender> as a media element and a camera (www/js/element/playback.js): currentTime,
// duration, paused, playbackRate (backwards too), loop, play({repetitions}) and the events play,
// pause, seeked, timeupdate, ended against a scripted sequence; the camera property and
// camera-change from a real drag ('user') and from code ('api'); pictures from code (toBlob,
// toDataURL) at the asked size, 2× drawn (not scaled up), without the gizmo unless asked; the
// element's real observed attributes, members and fired events against its features'
// declarations (www/js/element/features.js).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { EXPECTED_BACKEND, OPEN3, canvasBox, figureFrames, openOnePage, pageHtml } from './element-lib.mjs';

let b;
let page;
let problems;
before(async () => {
  ({ b, page, problems } = await openOnePage(pageHtml(`<main style="width: 800px">
<screw-bender id="f" editable loading="eager" show="control trajectories grid triads">
<script type="application/json">${JSON.stringify(OPEN3)}</script>Figure.</screw-bender>
<button id="after">after</button></main>`)));
  await page.evaluate(async () => {
    const el = document.getElementById('f');
    await el.ready;
    // Every event type the element dispatches, however it does so (checked against the
    // declarations by the last test).
    window.__fired = new Set();
    const dispatch = el.dispatchEvent.bind(el);
    el.dispatchEvent = (e) => {
      window.__fired.add(e.type);
      return dispatch(e);
    };
    window.__events = [];
    for (const t of ['play', 'pause', 'ended', 'seeked', 'timeupdate', 'ratechange', 'camera-change', 'error']) {
      el.addEventListener(t, (e) => window.__events.push({ type: t, t: el.currentTime, detail: e.detail }));
    }
  });
});
after(async () => {
  await b?.close();
});

const events = () => page.evaluate(() => window.__events.splice(0));
const types = (list, keep = (t) => t !== 'timeupdate') => list.map((e) => e.type).filter(keep);

test(`${EXPECTED_BACKEND}: play, pause, seek while paused, rate −1, ended on an open motion, repetitions`, async () => {
  assert.equal(await page.evaluate(() => document.getElementById('f').backend), EXPECTED_BACKEND);
  const st = await page.evaluate(() => {
    const el = document.getElementById('f');
    return { paused: el.paused, duration: el.duration, currentTime: el.currentTime, rate: el.playbackRate, loop: el.loop };
  });
  assert.deepEqual(st, { paused: true, duration: 2, currentTime: 0, rate: 1, loop: true });
  // play: a play event, then time runs forward.
  await page.evaluate(() => document.getElementById('f').play());
  await page.waitForFunction(() => document.getElementById('f').currentTime > 0.3, null, { timeout: 20000 });
  await page.evaluate(() => document.getElementById('f').pause());
  let ev = await events();
  assert.deepEqual(types(ev), ['play', 'pause']);
  assert.ok(ev.filter((e) => e.type === 'timeupdate').length >= 2, 'timeupdate while playing');
  const ts = ev.filter((e) => e.type === 'timeupdate').map((e) => e.t);
  assert.ok(ts.every((t, i) => i === 0 || t >= ts[i - 1]), `time runs forward: ${ts}`);
  assert.equal(await page.evaluate(() => document.getElementById('f').paused), true);
  // Seek while paused: the object moves there, the figure stays paused; seek(t) is the same.
  const seek = await page.evaluate(() => {
    const el = document.getElementById('f');
    el.currentTime = 1.5;
    const a = { t: el.currentTime, u: el.viewer.model.anim.u, want: el.motion.parameterAt(1.5), paused: el.paused };
    el.seek(0.25);
    return { ...a, t2: el.currentTime };
  });
  assert.equal(seek.t, 1.5);
  assert.ok(Math.abs(seek.u - seek.want) < 1e-12, `u ${seek.u} vs ${seek.want}`);
  assert.equal(seek.paused, true);
  assert.equal(seek.t2, 0.25);
  ev = await events();
  assert.deepEqual(types(ev), ['seeked', 'seeked']);
  assert.ok(ev.some((e) => e.type === 'timeupdate' && e.t === 1.5), 'timeupdate at the seek');
  // Rate −1 without loop: backwards from 1.5 s to the start, then pause and ended.
  await page.evaluate(() => {
    const el = document.getElementById('f');
    el.loop = false;
    el.currentTime = 1.5;
    el.playbackRate = -1;
    el.play();
  });
  await page.waitForFunction(() => document.getElementById('f').paused, null, { timeout: 30000 });
  ev = await events();
  assert.deepEqual(types(ev), ['seeked', 'ratechange', 'play', 'pause', 'ended']);
  const back = ev.filter((e) => e.type === 'timeupdate').map((e) => e.t);
  assert.ok(back.length >= 3 && back.every((t, i) => i === 0 || t <= back[i - 1]), `time runs backwards: ${back}`);
  assert.equal(ev.at(-1).t, 0, 'ended at the start');
  // Forwards at 4× to the end of the open motion: ended at the duration; play again starts over.
  await page.evaluate(() => {
    const el = document.getElementById('f');
    el.playbackRate = 4;
    el.play();
  });
  await page.waitForFunction(() => document.getElementById('f').paused, null, { timeout: 30000 });
  ev = await events();
  assert.deepEqual(types(ev), ['ratechange', 'play', 'pause', 'ended']);
  assert.equal(ev.at(-1).t, 2, 'ended at the end');
  await page.evaluate(() => document.getElementById('f').play());
  await page.waitForFunction(() => document.getElementById('f').paused, null, { timeout: 30000 });
  ev = await events();
  assert.ok(ev.find((e) => e.type === 'timeupdate').t < 1, 'a new play from the end starts over');
  // Repetitions with loop on: three passes (two wraps), then ended, whatever loop says.
  await page.evaluate(() => {
    const el = document.getElementById('f');
    el.loop = true;
    el.currentTime = 0;
    el.playbackRate = 2;
    el.play({ repetitions: 3 });
  });
  await page.waitForFunction(() => document.getElementById('f').paused, null, { timeout: 30000 });
  ev = await events();
  assert.deepEqual(types(ev), ['seeked', 'ratechange', 'play', 'pause', 'ended']);
  const rep = ev.filter((e) => e.type === 'timeupdate').map((e) => e.t);
  const wraps = rep.filter((t, i) => i > 0 && t < rep[i - 1]).length;
  assert.equal(wraps, 2, `wraps in ${rep}`);
  assert.equal(ev.at(-1).t, 2);
  // Bad values: an error event naming them, nothing changed, nothing thrown into the page.
  const bad = await page.evaluate(async () => {
    const el = document.getElementById('f');
    el.playbackRate = Number.NaN;
    el.currentTime = 'soon';
    el.play({ repetitions: 0 });
    await new Promise((r) => setTimeout(r, 50));
    return { rate: el.playbackRate, t: el.currentTime, paused: el.paused };
  });
  assert.deepEqual(bad, { rate: 2, t: 2, paused: true });
  ev = await events();
  assert.deepEqual(ev.filter((e) => e.type === 'error').map((e) => e.detail.attribute), ['playbackRate', 'currentTime', 'repetitions']);
  await page.evaluate(() => {
    const el = document.getElementById('f');
    el.playbackRate = 1;
    el.shadowRoot.querySelector('.msg').hidden = true;
  });
  await events();
  assert.deepEqual(problems, []);
});

test(`${EXPECTED_BACKEND}: camera-change says 'user' for a real drag and 'api' for a property set`, async () => {
  await figureFrames(page, '#f');
  const box = await canvasBox(page, '#f');
  await events();
  const yaw0 = await page.evaluate(() => document.getElementById('f').camera.yaw);
  // A drag on empty space near the top left corner orbits the camera.
  const from = { x: box.x + 30, y: box.y + 30 };
  await page.mouse.move(from.x, from.y);
  await page.mouse.down();
  for (let k = 1; k <= 6; k++) await page.mouse.move(from.x + 10 * k, from.y + 3 * k);
  await page.mouse.up();
  let ev = (await events()).filter((e) => e.type === 'camera-change');
  assert.ok(ev.length >= 3, `camera-change events: ${ev.length}`);
  assert.ok(ev.every((e) => e.detail.source === 'user'));
  const after = await page.evaluate(() => document.getElementById('f').camera);
  assert.ok(Math.abs(after.yaw - yaw0) > 0.1, `yaw ${yaw0} -> ${after.yaw}`);
  assert.deepEqual(ev.at(-1).detail.camera, after);
  // A property set: one 'api' event with the camera as set.
  const set = await page.evaluate(() => {
    const el = document.getElementById('f');
    el.camera = { yaw: 1, pitch: 0.25, distance: 9, target: [1, 0.5, 0.25], projection: 'orthographic' };
    return { cam: el.camera, ortho: el.viewer.camera.ortho };
  });
  assert.deepEqual(set.cam, { yaw: 1, pitch: 0.25, distance: 9, target: [1, 0.5, 0.25], projection: 'orthographic' });
  assert.equal(set.ortho, true);
  ev = (await events()).filter((e) => e.type === 'camera-change');
  assert.deepEqual(ev.map((e) => e.detail.source), ['api']);
  // A bad camera changes nothing and names the field.
  const bad = await page.evaluate(async () => {
    const el = document.getElementById('f');
    el.camera = { yaw: 2, pitch: 3 };
    el.camera = { target: [0, 0] };
    el.camera = { fov: 1 };
    await new Promise((r) => setTimeout(r, 30));
    return el.camera;
  });
  assert.deepEqual(bad, set.cam);
  ev = await events();
  assert.deepEqual(ev.map((e) => `${e.type}:${e.detail.attribute ?? ''}`), ['error:camera.pitch', 'error:camera.target', 'error:camera']);
  // As frameworks pass attributes' strings to properties: the camera attribute's value, loop "false".
  const strings = await page.evaluate(() => {
    const el = document.getElementById('f');
    el.camera = 'top';
    el.loop = 'false';
    const r = { pitch: el.camera.pitch, loop: el.loop };
    el.loop = true;
    return r;
  });
  assert.ok(Math.abs(strings.pitch - (89 * Math.PI) / 180) < 1e-9, `camera "top": pitch ${strings.pitch}`);
  assert.equal(strings.loop, false);
  await page.evaluate(() => {
    const el = document.getElementById('f');
    el.camera = 'iso';
    el.camera = { projection: 'perspective' };
    el.shadowRoot.querySelector('.msg').hidden = true;
  });
  await events();
  assert.deepEqual(problems, []);
});

/** Decodes a picture (a data: URL) in the page: size, share of non-background pixels, corner alpha, pair steps. */
const decode = (url) =>
  page.evaluate(async (u) => {
    const bmp = await createImageBitmap(await (await fetch(u)).blob());
    const c = new OffscreenCanvas(bmp.width, bmp.height);
    const g = c.getContext('2d');
    g.drawImage(bmp, 0, 0);
    const d = g.getImageData(0, 0, c.width, c.height).data;
    const bg = [d[0], d[1], d[2]];
    let differ = 0;
    for (let i = 0; i < d.length; i += 4) if (Math.abs(d[i] - bg[0]) + Math.abs(d[i + 1] - bg[1]) + Math.abs(d[i + 2] - bg[2]) > 30) differ++;
    // Neighbours within a pair of columns that differ strongly: none in a 2× scale-up.
    let steps = 0;
    for (let y = 0; y < c.height; y += 3) {
      for (let x = 0; x + 1 < c.width; x += 2) {
        const i = (y * c.width + x) * 4;
        const l = (k) => d[k] + d[k + 1] + d[k + 2];
        if (Math.abs(l(i) - l(i + 4)) > 240) steps++;
      }
    }
    return { width: c.width, height: c.height, differ: differ / (d.length / 4), alpha: d[3], steps };
  }, url);

/** The share of pixels (of two pictures of one size, data: URLs) that differ by more than 40 in a channel. */
const pixelsApart = (a, c) =>
  page.evaluate(async ([u, v]) => {
    const data = async (x) => {
      const bmp = await createImageBitmap(await (await fetch(x)).blob());
      const cv = new OffscreenCanvas(bmp.width, bmp.height);
      const g = cv.getContext('2d');
      g.drawImage(bmp, 0, 0);
      return g.getImageData(0, 0, cv.width, cv.height).data;
    };
    const [p, q] = [await data(u), await data(v)];
    let n = 0;
    for (let i = 0; i < p.length; i += 4) if (Math.max(Math.abs(p[i] - q[i]), Math.abs(p[i + 1] - q[i + 1]), Math.abs(p[i + 2] - q[i + 2])) > 40) n++;
    return n / (p.length / 4);
  }, [a, c]);

const blobUrl = (opts) =>
  page.evaluate(async (o) => {
    const blob = await document.getElementById('f').toBlob(o);
    const r = new FileReader();
    return { type: blob.type, url: await new Promise((res) => { r.onload = () => res(r.result); r.readAsDataURL(blob); }) };
  }, opts);

test(`${EXPECTED_BACKEND}: toBlob and toDataURL draw the asked size, 2× is drawn (not scaled up), no gizmo unless asked`, async () => {
  await figureFrames(page, '#f');
  const size = await page.evaluate(() => {
    const c = document.getElementById('f').shadowRoot.querySelector('canvas');
    return [c.width, c.height];
  });
  const one = await blobUrl({});
  assert.equal(one.type, 'image/png');
  const p1 = await decode(one.url);
  assert.deepEqual([p1.width, p1.height], size);
  assert.ok(p1.differ > 0.02, `drawn: ${p1.differ}`);
  assert.equal(p1.alpha, 255);
  const two = await blobUrl({ scale: 2 });
  const p2 = await decode(two.url);
  assert.deepEqual([p2.width, p2.height], [2 * size[0], 2 * size[1]]);
  assert.ok(p2.steps > 20, `sharp steps inside column pairs: ${p2.steps} (a scale-up has none)`);
  // The figure draws at its own size again.
  assert.deepEqual(await page.evaluate(() => {
    const c = document.getElementById('f').shadowRoot.querySelector('canvas');
    return [c.width, c.height];
  }), size);
  // Transparent, JPEG and a data: URL.
  const pt = await decode((await blobUrl({ transparent: true })).url);
  assert.equal(pt.alpha, 0, 'transparent background');
  const jpeg = await blobUrl({ type: 'image/jpeg', quality: 0.8 });
  assert.equal(jpeg.type, 'image/jpeg');
  const url = await page.evaluate(() => document.getElementById('f').toDataURL({ scale: 0.5 }));
  assert.match(url, /^data:image\/png;base64,/);
  const ph = await decode(url);
  assert.deepEqual([ph.width, ph.height], [Math.round(size[0] / 2), Math.round(size[1] / 2)]);
  // A selected pose's gizmo is drawn in the figure but left out of the picture unless asked.
  await page.evaluate(() => {
    const el = document.getElementById('f');
    el.shadowRoot.querySelector('canvas').focus();
  });
  await page.keyboard.press('ArrowRight');
  assert.equal(await page.evaluate(() => document.getElementById('f').viewer.model.selected), 0);
  await figureFrames(page, '#f');
  const plain = (await blobUrl({})).url;
  const withGizmo = (await blobUrl({ gizmo: true })).url;
  const same = await pixelsApart(plain, one.url);
  const shown = await pixelsApart(withGizmo, one.url);
  assert.ok(same < 0.0005, `without the gizmo the picture is the unselected one (${same})`);
  assert.ok(shown > 0.003, `with gizmo: true it shows (${shown})`);
  assert.equal(await page.evaluate(() => document.getElementById('f').viewer.model.selected), 0, 'the selection stays');
  // Bad options: a clear error, nothing changed.
  const errs = await page.evaluate(async () => {
    const el = document.getElementById('f');
    const out = [];
    for (const o of [{ scale: 0 }, { scale: 100 }, { type: 'image/gif' }, { type: 'image/jpeg', transparent: true }, { quality: 2 }]) {
      try {
        await el.toBlob(o);
        out.push('resolved');
      } catch (e) {
        out.push(`${e.name}: ${e.message}`);
      }
    }
    try {
      el.toDataURL({ scale: -1 });
    } catch (e) {
      out.push(`${e.name}: ${e.message}`);
    }
    return out;
  });
  assert.equal(errs.length, 6);
  for (const e of errs) assert.match(e, /^RangeError: (scale|type|transparent|quality)/);
  await page.keyboard.press('Escape');
  assert.deepEqual(problems, []);
});

test(`${EXPECTED_BACKEND}: the element watches, has and fires exactly what its features declare`, async () => {
  const r = await page.evaluate(async () => {
    const { FEATURES, ATTRIBUTES, EVENTS } = await import(new URL('../js/element/features.js', location.href).href);
    const el = document.getElementById('f');
    // What the tests above did not fire: ratechange, an error, a selection.
    el.playbackRate = 0.5;
    el.playbackRate = 1;
    el.setAttribute('levels', 'many');
    el.setAttribute('levels', '3');
    el.viewer.model.selected = -1;
    el.figure.select(1);
    el.figure.select(-1);
    await new Promise((resolve) => setTimeout(resolve, 50));
    const El = customElements.get('screw-bender');
    // The element's own members that are not API: the custom-element callbacks and its figure.
    const internal = ['constructor', 'renew', 'connectedCallback', 'disconnectedCallback', 'attributeChangedCallback', 'figure'];
    return {
      observed: [...El.observedAttributes].sort(),
      attributes: [...ATTRIBUTES].sort(),
      members: Object.getOwnPropertyNames(El.prototype).filter((n) => !internal.includes(n)).sort(),
      declared: FEATURES.flatMap((f) => [...(f.properties ?? []), ...(f.methods ?? [])]).map((m) => m.name).sort(),
      fired: [...window.__fired].sort(),
      events: EVENTS,
    };
  });
  assert.deepEqual(r.observed, r.attributes, 'observedAttributes are the declared attributes');
  assert.deepEqual(r.members, r.declared, 'the element\'s properties and methods are the declared ones');
  for (const t of r.fired) assert.ok(r.events.includes(t), `${t} is fired and declared`);
  for (const t of ['play', 'pause', 'ended', 'seeked', 'time', 'timeupdate', 'ratechange', 'camera-change', 'error', 'select']) {
    assert.ok(r.fired.includes(t), `${t} was fired (fired: ${r.fired.join(', ')})`);
  }
});
