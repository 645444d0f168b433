// e2e-backends: webgpu (figures in a deck on the page's default backend)
// The reveal.js deck www/examples/slides.html: figures on several slides, picked and dragged with
// real mouse events under the deck's scaling (a transform: ×1.1 at 1280×800, ×0.37 at 390×844),
// under CSS zoom and in fullscreen; a figure on a hidden slide draws nothing until its slide is
// shown; a focused figure keeps the keys it uses from the deck (ArrowRight, Space, Escape) while
// unfocused keys turn the slides; reveal's print view shows every figure as a picture of what it
// shows on screen.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import zlib from 'node:zlib';
import { EXPECTED_BACKEND, shotPath, startPlayground } from './lib.mjs';

const DECK = 'examples/slides.html';
const SLIDE = { title: 0, screw: 1, edit: 2, compare: 3 };

let play;
before(async () => {
  play = await startPlayground();
});
after(async () => {
  await play?.close();
});

/** Opens the deck at `viewport` (slide `h`), collecting errors; waits for that slide's figures. */
async function openDeck({ viewport = { width: 1280, height: 800 }, h = 0, query = '' } = {}) {
  const context = await play.browser.newContext({ viewport });
  const page = await context.newPage();
  const problems = [];
  page.on('console', (m) => {
    if (m.type() === 'error') problems.push(`console: ${m.text()}`);
  });
  page.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
  await page.goto(`${play.url}${DECK}${query}${query ? '' : `#/${h}`}`);
  await page.waitForFunction(() => window.deck?.isReady() && customElements.get('screw-bender'));
  if (!query) await showSlide(page, h);
  return {
    page,
    problems,
    close: () => context.close(),
  };
}

/** Goes to slide `h` and waits until its figures drew two more frames. */
async function showSlide(page, h) {
  await page.evaluate((i) => {
    window.deck.slide(i);
    // Narrow screens get reveal's scroll view (slides one under the other): the slide's figure
    // is scrolled to.
    if (window.deck.isScrollView()) document.querySelectorAll('.reveal .slides section')[i].querySelector('screw-bender')?.scrollIntoView({ block: 'center' });
  }, h);
  // reveal's slide transition (a transform) ends before the positions are read.
  await page.waitForFunction(() => !document.querySelector('.reveal .slides section.present')?.getAnimations?.({ subtree: true }).some((a) => a.playState === 'running'));
  await page.waitForTimeout(900);
  await page.evaluate(async () => {
    const figs = [...document.querySelectorAll('.reveal .slides section.present screw-bender')];
    await Promise.all(figs.map((f) => f.ready));
    const start = figs.map((f) => f.viewer.frames);
    for (const f of figs) f.viewer.requestDraw();
    await new Promise((res) => {
      const tick = () => (figs.every((f, k) => f.viewer.frames >= start[k] + 2) ? res() : (figs.forEach((f) => f.viewer.requestDraw()), requestAnimationFrame(tick)));
      requestAnimationFrame(tick);
    });
  });
}

/**
 * Where control pose k of figure `id` is on screen, computed from the canvas's box as the browser
 * lays it out (getBoundingClientRect, which includes every transform and zoom) and the pose's
 * projection as a fraction of the canvas: independent of the size the figure measured last.
 */
function poseOnScreen(page, id, k) {
  return page.evaluate(([i, kk]) => {
    const v = document.getElementById(i).viewer;
    const p = v.screenOfPose(kk);
    const { cssW, cssH } = v.pixelSize();
    const r = v.canvas.getBoundingClientRect();
    return { x: r.left + ((p.x - r.left) / cssW) * r.width, y: r.top + ((p.y - r.top) / cssH) * r.height, scale: r.width / v.canvas.offsetWidth };
  }, [id, k]);
}

/** Records the select and change events of figure `id` into window.__events. */
function recordEvents(page, id) {
  return page.evaluate((i) => {
    window.__events = [];
    const el = document.getElementById(i);
    el.addEventListener('select', (e) => window.__events.push({ type: 'select', index: e.detail.index }));
    el.addEventListener('change', (e) => window.__events.push({ type: 'change', index: e.detail.index }));
  }, id);
}

/**
 * Clicks control pose 1 of the editable figure (it must be selected), then drags it by (dx, dy)
 * screen pixels: the pose follows the pointer (its handle ends within a few pixels of where the
 * drag ended), and the deck stays on its slide.
 */
async function pickAndDrag(page, label, { dx = 60, dy = -40 } = {}) {
  const id = 'fig-edit';
  await recordEvents(page, id);
  const h = await poseOnScreen(page, id, 1);
  await page.mouse.click(h.x, h.y);
  await page.waitForFunction(() => window.__events.some((e) => e.type === 'select'), null, { timeout: 5000 }).catch(() => {});
  const picked = await page.evaluate(() => window.__events);
  assert.deepEqual(picked, [{ type: 'select', index: 1 }], `${label}: a click on pose 1 (at ${h.x.toFixed(1)}, ${h.y.toFixed(1)}; scale ${h.scale.toFixed(2)}) selects it`);
  // A click on the canvas's empty corner deselects; a drag that starts on an unselected pose moves
  // it in the view plane (the gizmo of a selected one would hold it to an axis).
  const corner = await page.evaluate((i) => {
    const r = document.getElementById(i).viewer.canvas.getBoundingClientRect();
    return { x: r.left + 0.04 * r.width, y: r.top + 0.06 * r.height };
  }, id);
  await page.mouse.click(corner.x, corner.y);
  await page.waitForFunction(() => window.__events.length >= 2, null, { timeout: 5000 }).catch(() => {});
  assert.deepEqual(await page.evaluate(() => window.__events.slice(1)), [{ type: 'select', index: -1 }], `${label}: a click beside the poses deselects`);
  await page.evaluate(() => {
    window.__events = [];
  });
  const from = await poseOnScreen(page, id, 1);
  await page.mouse.move(from.x, from.y);
  await page.mouse.down();
  for (let k = 1; k <= 10; k++) await page.mouse.move(from.x + (dx * k) / 10, from.y + (dy * k) / 10);
  await page.mouse.up();
  await page.waitForFunction(() => window.__events.some((e) => e.type === 'change'), null, { timeout: 5000 }).catch(() => {});
  const events = await page.evaluate(() => window.__events);
  assert.deepEqual(events.map((e) => e.type), ['select', 'change'], `${label}: the drag changes the motion`);
  assert.equal(events[1].index, 1);
  const to = await poseOnScreen(page, id, 1);
  const miss = Math.hypot(to.x - (from.x + dx), to.y - (from.y + dy));
  assert.ok(miss < 6, `${label}: the pose follows the pointer (ends ${miss.toFixed(1)} px from it)`);
  assert.equal(await page.evaluate(() => window.deck.getIndices().h), SLIDE.edit, `${label}: the slide stays`);
}

test('the deck: figures on their slides on the expected backend; a figure on a hidden slide draws nothing until shown and stops when it leaves', async () => {
  const deck = await openDeck();
  const { page } = deck;
  try {
    assert.equal(await page.evaluate(() => document.getElementById('fig-title').backend), EXPECTED_BACKEND);
    assert.equal(await page.evaluate(() => document.querySelectorAll('.reveal screw-bender').length), 5);
    const framesOf = () => page.evaluate(() => document.getElementById('fig-edit').viewer?.frames ?? 0);
    const f0 = await framesOf();
    await page.waitForTimeout(800);
    assert.equal(await framesOf(), f0, 'the figure on slide 3 draws nothing while slide 1 is shown');
    await showSlide(page, SLIDE.edit);
    assert.ok((await framesOf()) >= f0 + 2, 'shown, it draws');
    await page.screenshot({ path: shotPath('slides/deck-edit.png') });
    await page.evaluate(() => document.getElementById('fig-edit').play());
    await showSlide(page, SLIDE.compare);
    const f1 = await framesOf();
    await page.waitForTimeout(800);
    assert.equal(await framesOf(), f1, 'playing, it stops drawing when its slide leaves');
    // The two-figure slide fits the window side by side, at both common desktop widths.
    for (const viewport of [{ width: 1280, height: 800 }, { width: 1920, height: 1080 }]) {
      await page.setViewportSize(viewport);
      // reveal lays the deck out again on its resize event; now, not whenever that comes.
      await page.evaluate(() => window.deck.layout());
      await page.waitForFunction(() => !document.querySelector('.reveal .slides section.present')?.getAnimations?.({ subtree: true }).some((a) => a.playState === 'running'));
      const boxes = await page.evaluate(() => ['fig-bspline', 'fig-fourpoint'].map((id) => document.getElementById(id).getBoundingClientRect().toJSON()));
      const [a, b] = boxes;
      const at = `${viewport.width}×${viewport.height}: ${JSON.stringify(boxes.map((r) => [Math.round(r.left), Math.round(r.right)]))}`;
      assert.ok(a.left >= 0 && b.right <= viewport.width, `the compare slide's figures leave the window at ${at}`);
      assert.ok(a.right <= b.left && a.width > 0.3 * viewport.width, `the figures overlap or shrank at ${at}`);
    }
    assert.deepEqual(deck.problems, []);
  } finally {
    await deck.close();
  }
});

test('picking and drags under the deck\'s scaling: ×1.1 at 1280×800, ×0.37 at 390×844, and under CSS zoom', async () => {
  for (const viewport of [{ width: 1280, height: 800 }, { width: 390, height: 844 }]) {
    const deck = await openDeck({ viewport, h: SLIDE.edit });
    try {
      const scale = await deck.page.evaluate(() => window.deck.getScale());
      assert.ok(Math.abs(scale - 1) > 0.05, `the deck is scaled (${scale})`);
      await pickAndDrag(deck.page, `${viewport.width}×${viewport.height}, deck scale ${scale}`);
      await deck.page.screenshot({ path: shotPath(`slides/deck-${viewport.width}x${viewport.height}.png`) });
      assert.deepEqual(deck.problems, []);
    } finally {
      await deck.close();
    }
  }
  // CSS zoom on the deck (as reveal.js itself scaled slides up to version 5, and as pages zoom).
  const deck = await openDeck({ h: SLIDE.edit });
  try {
    await deck.page.evaluate(() => {
      document.querySelector('.reveal .slides').style.zoom = '0.8';
    });
    await showSlide(deck.page, SLIDE.edit);
    await pickAndDrag(deck.page, 'zoom 0.8', { dx: 40, dy: 30 });
    assert.deepEqual(deck.problems, []);
  } finally {
    await deck.close();
  }
});

test('fullscreen (reveal\'s F key): the deck rescales and picking and drags still work', async () => {
  const deck = await openDeck({ h: SLIDE.edit });
  const { page } = deck;
  try {
    const before = await page.evaluate(() => window.deck.getScale());
    await page.locator('#s-edit p').click();
    await page.keyboard.press('f');
    await page.waitForFunction(() => document.fullscreenElement !== null, null, { timeout: 5000 });
    await page.waitForTimeout(600);
    const inFull = await page.evaluate(() => ({ scale: window.deck.getScale(), w: innerWidth, h: innerHeight }));
    await pickAndDrag(page, `fullscreen ${inFull.w}×${inFull.h}, deck scale ${before} → ${inFull.scale}`);
    await page.evaluate(() => document.exitFullscreen());
    assert.deepEqual(deck.problems, []);
  } finally {
    await deck.close();
  }
});

test('deck keys: a focused figure keeps ArrowRight, Space and Escape from the deck; unfocused, ArrowRight turns the slide', async () => {
  const deck = await openDeck({ h: SLIDE.edit });
  const { page } = deck;
  try {
    await recordEvents(page, 'fig-edit');
    const where = () => page.evaluate(() => ({ h: window.deck.getIndices().h, overview: window.deck.isOverview() }));
    await page.locator('#fig-edit canvas').focus();
    await page.keyboard.press('ArrowRight');
    await page.waitForTimeout(300);
    assert.deepEqual(await page.evaluate(() => window.__events), [{ type: 'select', index: 0 }], 'ArrowRight selects the first pose');
    assert.deepEqual(await where(), { h: SLIDE.edit, overview: false }, 'after ArrowRight in the focused figure the slide is unchanged');
    await page.keyboard.press(' ');
    await page.waitForTimeout(300);
    assert.equal(await page.locator('#fig-edit .play').getAttribute('aria-label'), 'Pause', 'Space plays the figure');
    assert.deepEqual(await where(), { h: SLIDE.edit, overview: false }, 'Space does not turn the slide');
    await page.keyboard.press(' ');
    await page.keyboard.press('Escape');
    await page.waitForTimeout(300);
    assert.deepEqual(await where(), { h: SLIDE.edit, overview: false }, 'Escape in the figure does not open the overview');
    // A key the figure does not use is the deck's, focused or not: O opens the overview.
    await page.locator('#fig-edit canvas').focus();
    await page.keyboard.press('o');
    await page.waitForFunction(() => window.deck.isOverview(), null, { timeout: 5000 });
    await page.keyboard.press('o');
    await page.waitForFunction(() => !window.deck.isOverview(), null, { timeout: 5000 });
    // Focus leaves the figure (a click on the slide's text): the deck's keys are the deck's.
    await page.locator('#s-edit p').click();
    await page.keyboard.press('ArrowRight');
    await page.waitForFunction((h) => window.deck.getIndices().h === h, SLIDE.compare, { timeout: 5000 });
    assert.deepEqual(deck.problems, []);
  } finally {
    await deck.close();
  }
});

/** The images of a PDF file: each image XObject's size and, decoded, the spread of its pixels. */
/**
 * Grey-level signatures (SIG_W × SIG_H, decoded by the page's own image decoder) of `images`:
 * each either encoded bytes (`{bytes, type}`: PNG, JPEG) or raw samples (`{raw: {px, n}, w, h}`,
 * 1 or 3 per pixel, as a PDF's Flate image holds them).
 */
const SIG_W = 40;
const SIG_H = 28;
async function signatures(page, images) {
  const items = images.map((i) => (i.raw ? { w: i.w, h: i.h, n: i.raw.n, px: i.raw.px.toString('base64') } : { type: i.type, b64: Buffer.from(i.bytes).toString('base64') }));
  return page.evaluate(
    async ({ items, W, H }) => {
      const unbase64 = (b) => Uint8Array.from(atob(b), (c) => c.charCodeAt(0));
      const out = [];
      for (const it of items) {
        let source;
        if (it.px) {
          const px = unbase64(it.px);
          const rgba = new Uint8ClampedArray(it.w * it.h * 4);
          for (let k = 0; k < it.w * it.h; k++) {
            for (let c = 0; c < 3; c++) rgba[4 * k + c] = px[k * it.n + (it.n >= 3 ? c : 0)];
            rgba[4 * k + 3] = 255;
          }
          source = await createImageBitmap(new ImageData(rgba, it.w, it.h));
        } else {
          source = await createImageBitmap(new Blob([unbase64(it.b64)], { type: it.type }));
        }
        const c = new OffscreenCanvas(W, H);
        const g = c.getContext('2d');
        g.drawImage(source, 0, 0, W, H);
        const d = g.getImageData(0, 0, W, H).data;
        const sig = [];
        for (let i = 0; i < d.length; i += 4) sig.push((d[i] + d[i + 1] + d[i + 2]) / 3);
        out.push(sig);
      }
      return out;
    },
    { items, W: SIG_W, H: SIG_H },
  );
}

/** The correlation of two signatures: 1 for the same picture up to brightness and contrast, 0 against a blank one. */
function correlation(a, b) {
  const mean = (x) => x.reduce((s, v) => s + v, 0) / x.length;
  const ma = mean(a);
  const mb = mean(b);
  let ab = 0;
  let aa = 0;
  let bb = 0;
  for (let i = 0; i < a.length; i++) {
    ab += (a[i] - ma) * (b[i] - mb);
    aa += (a[i] - ma) ** 2;
    bb += (b[i] - mb) ** 2;
  }
  return aa > 0 && bb > 0 ? ab / Math.sqrt(aa * bb) : 0;
}

function pdfImages(pdf) {
  const text = pdf.toString('latin1');
  const images = [];
  const re = /<<((?:(?!>>\s*stream)[\s\S])*?\/Subtype\s*\/Image[\s\S]*?)>>\s*stream\r?\n/g;
  let m;
  while ((m = re.exec(text))) {
    const dict = m[1];
    const len = Number(dict.match(/\/Length\s+(\d+)/)?.[1]);
    const w = Number(dict.match(/\/Width\s+(\d+)/)?.[1]);
    const h = Number(dict.match(/\/Height\s+(\d+)/)?.[1]);
    const start = m.index + m[0].length;
    const bytes = pdf.subarray(start, start + len);
    let spread = null;
    let raw = null;
    if (/\/FlateDecode/.test(dict) && !/\/DecodeParms/.test(dict)) {
      try {
        const px = zlib.inflateSync(bytes);
        raw = { px, n: Math.round(px.length / (w * h)) };
        // Samples per pixel from the size (the colour space may be an ICC profile's).
        const n = Math.round(px.length / (w * h));
        const lum = [];
        for (let i = 0; i + n <= px.length; i += n * 7) lum.push(px.subarray(i, i + Math.min(n, 3)).reduce((a, b) => a + b, 0) * (3 / Math.min(n, 3)));
        lum.sort((a, b) => a - b);
        spread = lum[Math.floor(lum.length * 0.98)] - lum[Math.floor(lum.length * 0.02)];
      } catch {
        spread = null;
      }
    }
    images.push({ w, h, jpeg: /\/DCTDecode/.test(dict), spread, bytes, raw });
  }
  return images;
}

test('reveal\'s print view (?print-pdf): every figure prints as a picture of its frame', async () => {
  const deck = await openDeck({ query: '?print-pdf' });
  const { page } = deck;
  try {
    await page.waitForFunction(() => document.documentElement.classList.contains('reveal-print') || document.querySelector('.reveal.print-pdf, html.print-pdf'), null, { timeout: 10000 }).catch(() => {});
    // Every figure is scrolled to once (a lazy figure starts near the viewport) and draws; the
    // playing one is paused, so that what it prints is the frame it shows.
    await page.evaluate(async () => {
      for (const f of document.querySelectorAll('screw-bender')) {
        f.scrollIntoView({ block: 'center' });
        await f.ready;
        f.pause();
        await new Promise((res) => requestAnimationFrame(() => requestAnimationFrame(res)));
      }
    });
    // What each figure shows on screen: its canvas, as the browser composites it.
    const ids = await page.evaluate(() => [...document.querySelectorAll('screw-bender')].map((f) => f.id));
    const shown = [];
    for (const id of ids) {
      const canvas = page.locator(`#${id} canvas`).first();
      await canvas.scrollIntoViewIfNeeded();
      shown.push({ type: 'image/png', bytes: await canvas.screenshot() });
    }
    await page.evaluate(() => window.scrollTo(0, 0));
    await page.emulateMedia({ media: 'print' });
    await page.waitForTimeout(1500);
    const pdf = await page.pdf({ width: '1000px', height: '700px', printBackground: true });
    const images = pdfImages(pdf);
    // What each figure showed, for the message: its renderer, whether it was suspended, its
    // print picture.
    const states = await page.evaluate(() =>
      [...document.querySelectorAll('screw-bender')].map((f) => ({
        id: f.id,
        renderer: !!f.viewer?.renderer,
        suspended: !!f.viewer?.suspended,
        still: f.shadowRoot?.querySelector('[part=still]') ? 'shown' : 'none',
      })),
    );
    // A figure's picture is at least a quarter of its slide's width and 150 px high (the deck
    // has other images, under 100 px high). Each figure must have one that holds its pixels: the
    // picture's signature correlates with that of the figure's canvas on screen (a blank box, a
    // grey frame or a picture of another slide's figure does not).
    const pictures = images.filter((i) => i.w >= 250 && i.h >= 150).map((i) => ({ ...i, type: 'image/jpeg' }));
    const listed = JSON.stringify(images.map(({ w, h, jpeg, spread }) => ({ w, h, jpeg, spread })));
    assert.equal(pictures.length, ids.length, `one picture per figure (images: ${listed}; figures: ${JSON.stringify(states)})`);
    const seen = await signatures(page, shown);
    const printed = await signatures(page, pictures);
    const best = seen.map((sig) => Math.max(...printed.map((p) => correlation(sig, p))));
    const named = ids.map((id, k) => `${id} ${best[k].toFixed(2)}`).join(', ');
    for (let k = 0; k < ids.length; k++) assert.ok(best[k] >= 0.8, `${ids[k]}: no printed picture has its pixels (best correlation per figure: ${named}; figures: ${JSON.stringify(states)})`);
    assert.deepEqual(deck.problems, []);
  } finally {
    await deck.close();
  }
});
