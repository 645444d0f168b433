// e2e-backends: webgpu (one WebGPU device per page for many figures)
// <screw-bender> as a guest in a page (www/js/element/chrome.js, showing.js, figure/pointer.js):
// a focused figure takes only the keys it acts on (on a page that listens to keys on document as
// reveal.js does: arrows, Space, Escape, O, F) and Tab and Escape get a keyboard user out; many
// figures start lazily near the viewport (loading="lazy", a poster until then, "eager" at once)
// and stop drawing when scrolled away or on a hidden slide; print media shows a still picture of
// each figure's current frame; a one-finger vertical swipe over an unfocused figure scrolls the
// page (touch-action pan-y, real touch events), unless touch-action="none".
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { EXPECTED_BACKEND, OPEN3, canvasBox, drawnShare, elementBrowser, figureFrames, pageHtml } from './element-lib.mjs';

let b;
before(async () => {
  b = await elementBrowser();
});
after(async () => {
  await b?.close();
});

const doc = `<script type="application/json">${JSON.stringify(OPEN3)}</script>`;

// A host page with its own shortcuts, listening on document like reveal.js (keydown, bubbling).
const HOST = pageHtml(`<main style="width: 800px">
<button id="before">before</button>
<screw-bender id="ro" loading="eager" controls="minimal">${doc}Read-only.</screw-bender>
<screw-bender id="ed" loading="eager" editable>${doc}Editable.</screw-bender>
<button id="after">after</button></main>
<script type="module">
window.__host = [];
document.addEventListener('keydown', (e) => window.__host.push(e.key + (e.defaultPrevented ? '!' : '')));
</script>`);

test(`${EXPECTED_BACKEND}: keys: a focused figure takes only its own keys; unfocused, the page has them all; Tab and Escape leave`, async () => {
  const { page, problems, close } = await b.open(HOST);
  try {
    await page.evaluate(() => Promise.all([...document.querySelectorAll('screw-bender')].map((e) => e.ready)));
    const host = () => page.evaluate(() => window.__host.splice(0));
    const active = () => page.evaluate(() => {
      const a = document.activeElement;
      return a?.id + (a?.shadowRoot?.activeElement ? `>${a.shadowRoot.activeElement.className || a.shadowRoot.activeElement.tagName}` : '');
    });
    // Unfocused: every key of the deck reaches the page.
    await page.focus('#before');
    for (const k of ['ArrowRight', 'ArrowLeft', ' ', 'Escape', 'o', 'f']) await page.keyboard.press(k);
    assert.deepEqual(await host(), ['ArrowRight', 'ArrowLeft', ' ', 'Escape', 'o', 'f']);
    // Read-only figure focused by a click: arrows step between key poses, Space plays; both stop
    // there. O and F (the deck's overview, fullscreen) and Ctrl+A pass on untouched.
    const box = await canvasBox(page, '#ro');
    await page.mouse.click(box.x + 10, box.y + 10);
    assert.equal(await active(), 'ro>CANVAS');
    await page.keyboard.press('ArrowRight');
    assert.equal(await page.evaluate(() => document.getElementById('ro').currentTime), 1);
    await page.keyboard.press('ArrowRight');
    await page.keyboard.press('ArrowLeft');
    assert.equal(await page.evaluate(() => document.getElementById('ro').currentTime), 1);
    await page.keyboard.press(' ');
    assert.equal(await page.evaluate(() => document.getElementById('ro').paused), false);
    await page.keyboard.press(' ');
    await page.keyboard.press('o');
    await page.keyboard.press('f');
    await page.keyboard.press('Control+a');
    assert.deepEqual(await host(), ['o', 'f', 'Control', 'a']);
    // Escape with nothing selected leaves the figure (taken); the next Escape is the page's.
    await page.keyboard.press('Escape');
    assert.equal(await active(), '', 'the focus left the figure');
    await page.keyboard.press('Escape');
    assert.deepEqual(await host(), ['Escape']);
    // The bar's scrubber keeps its arrows from the page.
    await page.evaluate(() => document.getElementById('ro').shadowRoot.querySelector('.scrub').focus());
    const v0 = await page.evaluate(() => document.getElementById('ro').shadowRoot.querySelector('.scrub').value);
    await page.keyboard.press('ArrowRight');
    assert.notEqual(await page.evaluate(() => document.getElementById('ro').shadowRoot.querySelector('.scrub').value), v0);
    await page.keyboard.press('Space');
    assert.equal(await page.evaluate(() => document.getElementById('ro').paused), false, 'Space on the scrubber plays');
    await page.keyboard.press('Space');
    assert.deepEqual(await host(), [], 'the scrubber took its keys');
    // Tab gets out: from the canvas through the bar to the next figure.
    await page.evaluate(() => document.getElementById('ro').shadowRoot.querySelector('canvas').focus());
    let left = false;
    for (let k = 0; k < 5 && !left; k++) {
      await page.keyboard.press('Tab');
      left = !(await active()).startsWith('ro');
    }
    assert.ok(left, `Tab leaves the figure (now ${await active()})`);
    const tabs = await host();
    assert.ok(tabs.length >= 1 && tabs.every((k) => k === 'Tab'), `Tab is never taken: ${tabs}`);
    // Editable: arrows select, Escape deselects (taken), then leaves.
    const eb = await canvasBox(page, '#ed');
    await page.mouse.click(eb.x + 10, eb.y + 10);
    await host();
    await page.keyboard.press('ArrowRight');
    await page.keyboard.press('ArrowRight');
    assert.equal(await page.evaluate(() => document.getElementById('ed').viewer.model.selected), 1);
    await page.keyboard.press('e');
    await page.keyboard.press('Escape');
    assert.equal(await page.evaluate(() => document.getElementById('ed').viewer.model.selected), -1);
    assert.equal(await active(), 'ed>CANVAS');
    await page.keyboard.press('o');
    await page.keyboard.press('Escape');
    assert.equal(await active(), '', 'the focus left the figure');
    assert.deepEqual(await host(), ['o']);
    assert.deepEqual(problems, []);
  } finally {
    await close();
  }
});

/** A page of `n` figures, each in its own 420 px tall section. */
const manyPage = (n, attrs = '') =>
  pageHtml(`<main style="width: 700px; margin: 0 auto">${Array.from({ length: n }, (_, k) =>
    `<section style="height: 420px"><screw-bender id="m${k}" scene="${k % 2 ? 'circle4' : 'l_cycle_rotated'}" strobe="24" ${attrs}>Figure ${k}.</screw-bender></section>`).join('\n')}</main>`);

test(`${EXPECTED_BACKEND}: a page of 20 figures starts them near the viewport; the scrolled-away and hidden stop drawing`, async (t) => {
  const t0 = Date.now();
  const { page, problems, close } = await b.open(manyPage(20, 'poster="data:image/svg+xml,%3Csvg xmlns=%22http://www.w3.org/2000/svg%22/%3E"'));
  try {
    await page.evaluate(() => document.getElementById('m0').ready);
    const firstMs = Date.now() - t0;
    const started = () => page.evaluate(() => [...document.querySelectorAll('screw-bender')].map((e) => !!e.viewer));
    await page.waitForTimeout(300);
    let s = await started();
    const n0 = s.filter(Boolean).length;
    assert.ok(n0 >= 2 && n0 <= 4, `near the first viewport only: ${s.map(Number).join('')}`);
    assert.equal(s[19], false);
    const posters = await page.evaluate(() => [...document.querySelectorAll('screw-bender')].map((e) => !e.shadowRoot.querySelector('.poster').hidden));
    assert.equal(posters[0], false, 'a started figure hides its poster');
    assert.equal(posters[19], true, 'a waiting one shows it');
    // Scroll to the end: the last ones start, the first ones stop drawing.
    await page.evaluate(() => document.getElementById('m19').scrollIntoView());
    await page.evaluate(() => document.getElementById('m19').ready);
    s = await started();
    assert.equal(s[19], true);
    assert.equal(s[10], false, 'a figure scrolled past quickly never started');
    const frames = () => page.evaluate(() => {
      const v = document.getElementById('m0').viewer;
      v.requestDraw();
      return v.frames;
    });
    const f0 = await frames();
    await page.waitForTimeout(400);
    assert.equal(await frames(), f0, 'a figure far from the viewport draws nothing');
    const heap = (await (await page.context().newCDPSession(page)).send('Runtime.getHeapUsage')).usedSize;
    t.diagnostic(`20 figures, lazy: first figure drawn ${firstMs} ms after navigation, ${n0} started at first, ${s.filter(Boolean).length} after scrolling to the end; JS heap ${(heap / 1e6).toFixed(1)} MB`);
    // A figure on a hidden slide (visibility, opacity) draws nothing until shown.
    const hid = await page.evaluate(async () => {
      const el = document.getElementById('m19');
      const v = el.viewer;
      const wait = (ms) => new Promise((r) => setTimeout(r, ms));
      /** Frames drawn in `ms` once the section has `style` (after 300 ms to settle). */
      const drawnWith = async (prop, value, ms = 400) => {
        el.parentElement.style[prop] = value;
        await wait(300);
        const f = v.frames;
        await wait(ms);
        el.parentElement.style[prop] = '';
        return v.frames - f;
      };
      el.play();
      return {
        hiddenDrew: await drawnWith('visibility', 'hidden'),
        transparentDrew: await drawnWith('opacity', '0'),
        // A loaded machine's software renderer may draw a few frames a second.
        shownDrew: await drawnWith('color', 'black', 1500),
      };
    });
    assert.equal(hid.hiddenDrew, 0);
    assert.equal(hid.transparentDrew, 0);
    assert.ok(hid.shownDrew >= 2, `drawing again once shown: ${hid.shownDrew}`);
    // loading="eager" starts at once, wherever the figure is.
    const eager = await page.evaluate(async () => {
      const el = document.getElementById('m10');
      el.setAttribute('loading', 'eager');
      await el.ready;
      return !!el.viewer;
    });
    assert.equal(eager, true);
    // A bad value is named, and the figure stays lazy.
    const bad = await page.evaluate(async () => {
      const el = document.createElement('screw-bender');
      el.setAttribute('loading', 'soon');
      const ev = [];
      el.addEventListener('error', (e) => ev.push(e.detail.attribute));
      document.querySelector('main').prepend(el);
      await new Promise((r) => setTimeout(r, 50));
      return ev;
    });
    assert.deepEqual(bad, ['loading']);
    assert.deepEqual(problems, []);
  } finally {
    await close();
  }
});

test(`${EXPECTED_BACKEND}: scrolled far away, figures free their renderers (and WebGL contexts) and draw again when back`, async () => {
  const { page, problems, close } = await b.open(manyPage(20));
  const warnings = [];
  page.on('console', (m) => /WebGL contexts|context lost/i.test(m.text()) && warnings.push(m.text()));
  try {
    // Through every figure of the page, each drawn once.
    for (let k = 0; k < 20; k++) {
      await page.evaluate((i) => document.getElementById(`m${i}`).scrollIntoView({ block: 'center' }), k);
      await page.waitForFunction((i) => document.getElementById(`m${i}`).viewer?.frames > 0, k, { timeout: 60000 });
    }
    // Each figure left behind frees its renderer once it has been far away for a while: on a
    // fast machine the whole page is scrolled through within that while, so wait for it.
    const alive = () => [...document.querySelectorAll('screw-bender')].filter((e) => e.viewer?.renderer).length;
    await page.waitForFunction(() => [...document.querySelectorAll('screw-bender')].filter((e) => e.viewer?.renderer).length <= 6, null, { timeout: 20000 }).catch(() => {});
    const live = await page.evaluate(alive);
    assert.ok(live <= 6, `renderers alive at the end of the page: ${live}`);
    // Print while suspended: the kept still.
    await page.emulateMedia({ media: 'print' });
    assert.equal(await page.evaluate(() => !!document.getElementById('m0').figure.kept), true, 'a suspended figure keeps a picture');
    await page.waitForFunction(() => !document.getElementById('m0').shadowRoot.querySelector('.still').hidden, null, { timeout: 5000 });
    await page.emulateMedia({ media: 'screen' });
    // Back to the first: it draws again, as it was.
    await page.evaluate(() => document.getElementById('m0').scrollIntoView({ block: 'center' }));
    await page.waitForFunction(() => !document.getElementById('m0').viewer.suspended && document.getElementById('m0').viewer.renderer, null, { timeout: 30000 });
    await figureFrames(page, '#m0', 2);
    const drawn = await drawnShare(page, '#m0');
    assert.ok(drawn > 0.03, `the first figure is drawn again: ${drawn}`);
    // Its keys work on the new canvas.
    const box = await canvasBox(page, '#m0');
    await page.mouse.click(box.x + 10, box.y + 10);
    await page.keyboard.press(' ');
    assert.equal(await page.evaluate(() => document.getElementById('m0').paused), false);
    assert.deepEqual(warnings, []);
    assert.deepEqual(problems, []);
  } finally {
    await close();
  }
});

test(`${EXPECTED_BACKEND}: print media: each started figure shows a still picture of its current frame`, async () => {
  const { page, problems, close } = await b.open(manyPage(2, 'loading="eager"'));
  try {
    await page.evaluate(() => Promise.all([...document.querySelectorAll('screw-bender')].map((e) => e.ready)));
    await figureFrames(page, '#m0');
    await page.evaluate(() => {
      document.getElementById('m0').currentTime = 1.25;
    });
    await figureFrames(page, '#m0');
    await page.emulateMedia({ media: 'print' });
    await page.waitForFunction(() => !document.getElementById('m1').shadowRoot.querySelector('.still').hidden);
    const r = await page.evaluate(() =>
      [...document.querySelectorAll('screw-bender')].map((el) => {
        const root = el.shadowRoot;
        const still = root.querySelector('.still canvas');
        const g = still.getContext('2d');
        const d = g.getImageData(0, 0, still.width, still.height).data;
        const bg = [d[0], d[1], d[2]];
        let differ = 0;
        for (let i = 0; i < d.length; i += 4) if (Math.abs(d[i] - bg[0]) + Math.abs(d[i + 1] - bg[1]) + Math.abs(d[i + 2] - bg[2]) > 30) differ++;
        const c = root.querySelector('canvas[part="canvas"]');
        const box = root.querySelector('.still').getBoundingClientRect();
        return {
          size: [still.width, still.height],
          canvas: [c.width, c.height],
          differ: differ / (d.length / 4),
          canvasVisibility: getComputedStyle(c).visibility,
          stillShown: box.width > 100 && box.height > 50,
          bar: getComputedStyle(root.querySelector('.bar')).visibility,
        };
      }),
    );
    for (const f of r) {
      assert.deepEqual(f.size, f.canvas, 'the still is the canvas\'s size');
      assert.ok(f.differ > 0.02, `the still shows the figure: ${f.differ}`);
      assert.equal(f.canvasVisibility, 'hidden');
      assert.equal(f.stillShown, true);
      assert.equal(f.bar, 'hidden');
    }
    // What the print shows (a screenshot in print media): the figure, not a blank box.
    const shown = await drawnShare(page, '#m0');
    assert.ok(shown > 0.02, `the printed figure shows its picture: ${shown}`);
    await page.emulateMedia({ media: 'screen' });
    await page.waitForFunction(() => document.getElementById('m0').shadowRoot.querySelector('.still').hidden);
    // beforeprint / afterprint (a browser's print dialog) do the same.
    const ev = await page.evaluate(() => {
      window.dispatchEvent(new Event('beforeprint'));
      const on = !document.getElementById('m0').shadowRoot.querySelector('.still').hidden;
      window.dispatchEvent(new Event('afterprint'));
      return [on, document.getElementById('m0').shadowRoot.querySelector('.still').hidden];
    });
    assert.deepEqual(ev, [true, true]);
    assert.deepEqual(problems, []);
  } finally {
    await close();
  }
});

/** One-finger swipe with CDP touch events from (x, y) by (dx, dy). */
async function swipe(page, x, y, dx, dy, steps = 10) {
  const cdp = await page.context().newCDPSession(page);
  const pt = (k) => [{ x: x + (dx * k) / steps, y: y + (dy * k) / steps, id: 1 }];
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: pt(0) });
  for (let k = 1; k <= steps; k++) {
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: pt(k) });
    await page.waitForTimeout(16);
  }
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
  await page.waitForTimeout(300);
}

test(`${EXPECTED_BACKEND}: touch on the course page: a vertical swipe over a figure scrolls the page, a sideways one orbits; touch-action="none" keeps it`, async () => {
  const ctx = await b.play.browser.newContext({ viewport: { width: 390, height: 844 }, hasTouch: true, isMobile: true, deviceScaleFactor: 2 });
  try {
    const page = await ctx.newPage();
    const problems = [];
    page.on('pageerror', (e) => problems.push(e.message));
    await page.goto(`${b.play.url}examples/course.html`);
    await page.waitForFunction(() => customElements.get('screw-bender'));
    await page.evaluate(() => document.getElementById('fig-fourpoint').scrollIntoView({ block: 'center' }));
    await page.evaluate(() => document.getElementById('fig-fourpoint').ready);
    const state = () => page.evaluate(() => {
      const el = document.getElementById('fig-fourpoint');
      const c = el.camera;
      return { y: window.scrollY, yaw: c.yaw, pitch: c.pitch, focused: el.shadowRoot.activeElement?.tagName ?? null };
    });
    const box = await page.evaluate(() => document.getElementById('fig-fourpoint').shadowRoot.querySelector('canvas').getBoundingClientRect().toJSON());
    const cx = box.x + box.width / 2;
    const cy = box.y + box.height / 2;
    const s0 = await state();
    await swipe(page, cx, cy + 60, 0, -160);
    const s1 = await state();
    assert.ok(s1.y - s0.y > 60, `the page scrolled: ${s0.y} -> ${s1.y}`);
    assert.equal(s1.pitch, s0.pitch, 'the figure did not orbit');
    assert.equal(s1.focused, null, 'a scroll does not focus the figure');
    // A sideways swipe orbits the figure (and gives it the focus).
    const box2 = await page.evaluate(() => document.getElementById('fig-fourpoint').shadowRoot.querySelector('canvas').getBoundingClientRect().toJSON());
    await swipe(page, box2.x + 60, box2.y + box2.height / 2, 200, 0);
    const s2 = await state();
    assert.ok(Math.abs(s2.yaw - s1.yaw) > 0.3, `orbit: yaw ${s1.yaw} -> ${s2.yaw}`);
    assert.equal(s2.y, s1.y);
    assert.equal(s2.focused, 'CANVAS');
    // Focused, a vertical swipe orbits.
    await swipe(page, box2.x + box2.width / 2, box2.y + box2.height / 2 + 40, 0, -120);
    const s3 = await state();
    assert.equal(s3.y, s2.y, 'focused: the page stays');
    assert.notEqual(s3.pitch, s2.pitch, 'focused: the swipe orbits');
    // touch-action="none": the figure takes every swipe, focused or not.
    await page.evaluate(() => {
      document.activeElement?.blur();
      document.getElementById('fig-fourpoint').setAttribute('touch-action', 'none');
    });
    const s4 = await state();
    await swipe(page, box2.x + box2.width / 2, box2.y + box2.height / 2 + 40, 0, -120);
    const s5 = await state();
    assert.equal(s5.y, s4.y, 'touch-action none: the page stays');
    assert.notEqual(s5.pitch, s4.pitch);
    assert.deepEqual(problems, []);
  } finally {
    await ctx.close();
  }
});
