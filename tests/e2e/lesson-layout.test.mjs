// e2e-backends: webgpu (layout and hit tests, computed on the CPU: the same on either backend)
// The lesson layout (www/css/lessons.css, www/js/lessons/highlight.js): every step of every
// lesson and of the tour, at 1280×800, 390×844 (touch) and 844×390 (touch), one page per size.
// For each step: the control it highlights is found and hittable at its centre
// (document.elementFromPoint gives it or one of its descendants; a pose or a gizmo handle: the
// 3-D view's canvas) or offered on the card by a stand-in button that is itself hittable; an
// exercise's Check is hittable as the step opens (no scrolling by hand); after a real click on
// Check the feedback has text, lies inside the window and nothing covers it. A highlight that
// cannot be found fails the step. The card covers neither the highlight, nor the open dock, nor
// the selected pose's handle; its Back / Next / close buttons are on screen; its text has no
// untypeset `$`; the ring pulses as it points at something new and stops within 5 s (WCAG
// 2.2.2). Each lesson shows no error message, and no page breaks its content security policy.
// Screenshots of lesson 1 step 4 and of an exercise after Check at each size go to
// artifacts/e2e-<backend>/lesson-layout/.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { ROOT, BACKEND, serveWww, launch, shotPath } from './lib.mjs';

const LESSONS = [...JSON.parse(fs.readFileSync(path.join(ROOT, 'www/lessons/index.json'), 'utf8')).lessons.map((l) => l.file), 'tour'];
const SIZES = [
  { width: 1280, height: 800, touch: false },
  { width: 390, height: 844, touch: true },
  { width: 844, height: 390, touch: true },
];

let server;
let browser;

before(async () => {
  server = await serveWww();
  browser = await launch(BACKEND);
});

after(async () => {
  await browser?.close();
  server?.stop();
});

/**
 * In the page: what a student meets at the open step. The highlight's target (found or not,
 * hittable or not, offered on the card or not) and the Check button (hittable or not).
 */
function inspectStep() {
  const L = window.__player;
  const { app } = window.screwbender;
  const s = L.lesson.steps[L.step];
  const rectOf = (e) => {
    const r = e.getBoundingClientRect();
    return { x: r.left, y: r.top, w: r.width, h: r.height };
  };
  const inside = (r) => r.w > 0 && r.h > 0 && r.x >= -0.5 && r.y >= -0.5 && r.x + r.w <= innerWidth + 0.5 && r.y + r.h <= innerHeight + 0.5;
  /** Whether a press at (x, y) reaches `node` (or a descendant). */
  const hitsAt = (node, x, y) => {
    if (x < 0 || y < 0 || x >= innerWidth || y >= innerHeight) return false;
    const hit = document.elementFromPoint(x, y);
    return !!hit && (hit === node || node.contains(hit));
  };
  const centreHits = (node) => {
    const r = rectOf(node);
    return r.w > 0 && r.h > 0 && hitsAt(node, r.x + r.w / 2, r.y + r.h / 2);
  };
  const out = { title: s.title, highlight: s.highlight ?? null, exercise: !!s.exercise };
  // The card: shown, its math typeset, clear of what the step asks the student to look at or
  // press, its own buttons on screen.
  const card = document.getElementById('lesson');
  const box = rectOf(card);
  const meets = (a, b) => a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;
  const spot = L.spot();
  const dock = document.querySelector('#dock.open');
  const sel = app.selected >= 0 ? app.viewer.screenOfPose(app.selected) : null;
  out.card = {
    hidden: card.hidden,
    dollars: card.querySelector('.text').textContent.includes('$'),
    covers: [
      spot && meets(box, spot) ? `the highlight ${JSON.stringify(spot)}` : '',
      dock && meets(box, rectOf(dock)) ? 'the open dock' : '',
      sel && meets(box, { x: sel.x - 12, y: sel.y - 12, w: 24, h: 24 }) ? "the selected pose's handle" : '',
    ].filter(Boolean),
    offscreen: [...card.querySelectorAll('.nav button, .head .close')].map(rectOf).filter((b) => !(b.w > 0 && inside(b))),
  };
  const h = s.highlight;
  if (h) {
    let node = null;
    let point = null;
    if (h.control) node = document.querySelector(h.control);
    else if (h.panel) node = app.ui.gui.controllersRecursive().find((c) => c._name === h.panel)?.domElement ?? null;
    else if (h.pose !== undefined) point = app.viewer.screenOfPose(h.pose);
    else if (h.gizmo !== undefined) point = app.selected >= 0 ? app.viewer.screenOfGizmo(h.gizmo) : null;
    out.found = !!(node && rectOf(node).w > 0) || !!(point && Number.isFinite(point.x) && Number.isFinite(point.y));
    out.ring = !!L.spot();
    if (node) out.hittable = centreHits(node);
    else if (point) out.hittable = hitsAt(app.viewer.canvas, point.x, point.y);
    // What lies there instead (for the message).
    const c = node ? rectOf(node) : null;
    const at = c ? { x: c.x + c.w / 2, y: c.y + c.h / 2 } : point;
    const top = at && document.elementFromPoint(at.x, at.y);
    out.over = top ? `${top.tagName.toLowerCase()}${top.id ? `#${top.id}` : ''}${top.className && typeof top.className === 'string' ? `.${top.className.split(' ').join('.')}` : ''} at ${Math.round(at.x)},${Math.round(at.y)}` : 'nothing';
    const proxy = document.querySelector('#lesson .proxy:not([hidden]) button');
    out.offered = !!proxy && centreHits(proxy);
  }
  const check = document.querySelector('#lesson button.check');
  if (s.exercise) {
    out.check = !!check && inside(rectOf(check)) && centreHits(check);
    if (check) {
      const r = rectOf(check);
      out.checkAt = { x: r.x + r.w / 2, y: r.y + r.h / 2 };
    }
  }
  return out;
}

/** In the page, after Check: the feedback's text, whether it lies inside the window and whether anything covers it. */
function inspectFeedback() {
  const fb = document.querySelector('#lesson .feedback');
  if (!fb) return { text: '', inside: false, uncovered: false };
  const r = fb.getBoundingClientRect();
  const inside = r.width > 0 && r.height > 0 && r.left >= -0.5 && r.top >= -0.5 && r.right <= innerWidth + 0.5 && r.bottom <= innerHeight + 0.5;
  // Its corners (2 px in) and centre: each hit test reaches the feedback.
  const pts = [[r.left + 2, r.top + 2], [r.right - 2, r.top + 2], [r.left + 2, r.bottom - 2], [r.right - 2, r.bottom - 2], [r.left + r.width / 2, r.top + r.height / 2]];
  const over = pts.map(([x, y]) => document.elementFromPoint(x, y)).filter((hit) => !hit || !(hit === fb || fb.contains(hit)));
  const name = (e) => (e ? `${e.tagName.toLowerCase()}${e.id ? `#${e.id}` : ''}.${String(e.className).split(' ').join('.')}` : 'nothing');
  return {
    text: fb.textContent.trim(),
    inside,
    uncovered: over.length === 0,
    over: `${over.map(name).join(', ')} over ${[r.left, r.top, r.width, r.height].map(Math.round)}`,
    live: fb.getAttribute('aria-live') ?? fb.getAttribute('role'),
  };
}

for (const size of SIZES) {
  const label = `${size.width}x${size.height}`;
  test(`${label}: every step of every lesson and the tour keeps its highlight reachable, Check in reach and the feedback in view`, async () => {
    const context = await browser.newContext({ viewport: { width: size.width, height: size.height }, hasTouch: size.touch });
    await context.addInitScript(() => {
      window.__csp = [];
      document.addEventListener('securitypolicyviolation', (e) => window.__csp.push(`${e.violatedDirective}: ${e.blockedURI}`));
    });
    const page = await context.newPage();
    const problems = [];
    page.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
    page.on('console', (m) => m.type() === 'error' && problems.push(`console: ${m.text()}`));
    await page.goto(server.url);
    await page.evaluate(async () => {
      await window.screwbender.ready;
      window.__player = await window.screwbender.lessons;
    });
    const failures = [];
    let steps = 0;
    let seenErrors = 0;
    for (const name of LESSONS) {
      const n = await page.evaluate((f) => window.__player.open(f, { resume: false }).then((ok) => (ok ? window.__player.lesson.steps.length : 0)), name);
      assert.ok(n > 0, `${label}: lesson ${name} did not open`);
      for (let i = 0; i < n; i++) {
        // The step applied, an analysis view it opens loaded, the layout settled and a frame
        // drawn with it.
        const pulse = await page.evaluate(async (k) => {
          const L = window.__player;
          if (L.step !== k) L.go(k);
          // A step's measured poses open the import dialog as it applies.
          if (L.lesson.steps[k].samples && !document.getElementById('reduce-dialog')) throw new Error(`step ${k + 1}: its measured poses opened no import dialog`);
          // The ring's pulses as the step opens (they restart for each new target).
          const ring = L.spot() ? document.getElementById('lesson-spot').getAnimations().map((a) => ({ t: a.currentTime, end: a.effect.getComputedTiming().endTime, state: a.playState })) : [];
          const sb = window.screwbender;
          while (sb.app.parts.dockHost.loading) await sb.app.parts.dockHost.loading;
          sb.app.dock?.flush();
          const frame = () => new Promise((r) => requestAnimationFrame(r));
          await frame();
          await frame();
          const f0 = sb.frames();
          sb.app.viewer.requestDraw();
          while (sb.frames() <= f0) await frame();
          return ring;
        }, i);
        const at = `${label} ${name} step ${i + 1}`;
        // A step's measured poses open the import dialog: closed by Esc, as a student would to
        // read the card (lessons.test.mjs answers it).
        if (await page.locator('#reduce-dialog').count()) {
          await page.keyboard.press('Escape');
          await page.locator('#reduce-dialog').waitFor({ state: 'detached' });
        }
        const g = await page.evaluate(inspectStep);
        steps++;
        if (g.card.hidden) failures.push(`${at}: the card is hidden`);
        if (g.card.dollars) failures.push(`${at}: an untypeset $ in the card's text`);
        for (const what of g.card.covers) failures.push(`${at}: the card covers ${what}`);
        for (const b of g.card.offscreen) failures.push(`${at}: a button of the card is off screen ${JSON.stringify(b)}`);
        for (const a of pulse) {
          if (!(a.end <= 5000)) failures.push(`${at}: the highlight pulses for ${a.end} ms (at most 5 s)`);
          if (!(a.state === 'running' && a.t < 1000)) failures.push(`${at}: the highlight's pulse did not start again (${a.state} at ${a.t} ms)`);
        }
        if (g.highlight) {
          if (!g.found) failures.push(`${at}: the highlighted ${JSON.stringify(g.highlight)} is not on the page`);
          else if (!g.ring) failures.push(`${at}: no ring around ${JSON.stringify(g.highlight)}`);
          else if (!g.hittable && !g.offered) failures.push(`${at}: ${JSON.stringify(g.highlight)} is covered (by ${g.over}) or off screen, and not offered on the card`);
        }
        if (g.exercise) {
          if (!g.check) {
            failures.push(`${at}: Check is covered, clipped or off screen`);
            continue;
          }
          // A real click where Check is drawn.
          await page.mouse.click(g.checkAt.x, g.checkAt.y);
          await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
          const f = await page.evaluate(inspectFeedback);
          if (!f.text) failures.push(`${at}: a click on Check showed no feedback`);
          else if (!f.inside || !f.uncovered) failures.push(`${at}: the feedback "${f.text.slice(0, 40)}…" is ${f.inside ? `covered (${f.over})` : 'outside the window'}`);
          if (f.live !== 'polite' && f.live !== 'status') failures.push(`${at}: the feedback is no live region`);
          if (name.startsWith('02-polyscrew') && i === 3) await page.screenshot({ path: shotPath(`lesson-layout/${label}-checked.png`) });
        }
        if (name.startsWith('01-screw') && i === 3) await page.screenshot({ path: shotPath(`lesson-layout/${label}-01-step4.png`) });
      }
      await page.evaluate(() => window.__player.close());
      // Messages shown while the lesson ran, less the notes on what an import of a step's
      // measured poses kept, fitted or (Esc) cancelled: the page tells a student that, as for a file.
      const all = await page.evaluate(() => window.screwbender.errors());
      const shown = all.slice(seenErrors).filter((m) => !/^“[^”]+”: (kept|fitted|import cancelled)/.test(m));
      seenErrors = all.length;
      for (const m of shown) failures.push(`${label} ${name}: the page showed "${m}"`);
    }
    assert.ok(steps >= 30, `only ${steps} steps swept`);
    assert.deepEqual(failures, []);
    assert.deepEqual(problems, []);
    assert.deepEqual(await page.evaluate(() => window.__csp), []);
    await context.close();
  });
}
