// e2e-backends: webgpu (storage, events, picking, attributes and layout are computed on the CPU, the same on either backend: once)
// The embeddable figure <screw-bender> (www/js/element/screw-bender.js) on the course example
// page (www/examples/course.html) and on pages built around it: figures never touch storage
// unless asked to persist, read-only figures ignore drags, an editable one emits `change`, the
// wheel scrolls the page until a figure has the focus, bad attributes, a fault in a gesture and
// a stylesheet that did not load are named inside their figure, a figure starts only once
// styled, off-screen figures draw nothing, and the control bar's layout on phones. Most tests
// share one course page, so the order matters: the editable figure's first drag selects its pose
// (later drags of a selected pose emit no `select`), the storage test comes before `persist`
// writes to the context's storage, and the bad attributes, whose 404s are console errors, come
// last. What
// each backend draws, and that figures come and go without growing memory, is
// viewer-render.test.mjs.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { COURSE, FIGURES, coursePlayground, openFigures, showFigure, signature } from './course-lib.mjs';

let play;
/** The course page most tests share (opened by the first of them). */
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

/** The poses of figure `id` (a plain array). */
const posesOf = (page, id) => page.evaluate((i) => Array.from(document.getElementById(i).motion.poses()), id);

/** Page position of control pose k's handle in figure `id` (after showing it). */
async function handleOf(page, id, k) {
  await showFigure(page, id);
  return page.evaluate(([i, kk]) => document.getElementById(i).viewer.screenOfPose(kk), [id, k]);
}

async function drag(page, from, dx, dy, steps = 8) {
  await page.mouse.move(from.x, from.y);
  await page.mouse.down();
  for (let k = 1; k <= steps; k++) await page.mouse.move(from.x + (dx * k) / steps, from.y + (dy * k) / steps);
  await page.mouse.up();
}

test('an editable figure: a real drag of a pose emits select and change with the moved pose', async () => {
  const { page, problems } = await sharedCourse();
  const id = 'fig-jarek';
  const before = await posesOf(page, id);
  await page.evaluate((i) => {
    window.__events = [];
    const el = document.getElementById(i);
    el.addEventListener('select', (e) => window.__events.push({ type: 'select', index: e.detail.index }));
    el.addEventListener('change', (e) => window.__events.push({ type: 'change', index: e.detail.index, poses: Array.from(e.detail.poses) }));
  }, id);
  const h = await handleOf(page, id, 1);
  await drag(page, h, 40, -30);
  const events = await page.evaluate(() => window.__events);
  assert.deepEqual(events.map((e) => e.type), ['select', 'change']);
  assert.equal(events[0].index, 1);
  const after = events[1].poses;
  assert.deepEqual(after, await posesOf(page, id), 'change carries the figure poses');
  const moved = Math.hypot(after[7] - before[7], after[8] - before[8], after[9] - before[9]);
  assert.ok(moved > 0.05, `pose 1 moved (by ${moved})`);
  // Only pose 1 changed.
  for (let k = 0; k < before.length / 7; k++) {
    if (k !== 1) assert.deepEqual(after.slice(k * 7, k * 7 + 7), before.slice(k * 7, k * 7 + 7), `pose ${k} unchanged`);
  }
  assert.deepEqual(problems, []);
});

test('figures never touch localStorage (no persist attribute)', async () => {
  const { page, problems } = await sharedCourse();
  // Interact: play, orbit and drag in the editable figure.
  await page.evaluate(() => document.getElementById('fig-screw').play());
  const h = await handleOf(page, 'fig-jarek', 1);
  await drag(page, h, 30, -20);
  await showFigure(page, 'fig-fourpoint');
  // Paused again: the shared page's later tests would draw its frames for nothing.
  await page.evaluate(() => document.getElementById('fig-screw').pause());
  assert.deepEqual(await page.evaluate(() => window.__storage), []);
  assert.equal(await page.evaluate(() => localStorage.length), 0);
  assert.deepEqual(problems, []);
});

test('a read-only figure ignores drags of its poses (the camera orbits instead)', async () => {
  const { page, problems } = await sharedCourse();
  const id = 'fig-bspline';
  const before = await posesOf(page, id);
  const yaw0 = await page.evaluate((i) => document.getElementById(i).viewer.camera.yaw, id);
  await page.evaluate((i) => {
    window.__events = [];
    for (const t of ['change', 'select']) document.getElementById(i).addEventListener(t, (e) => window.__events.push(t));
  }, id);
  const h = await handleOf(page, id, 2);
  await drag(page, h, 60, 30);
  assert.deepEqual(await posesOf(page, id), before, 'the poses did not move');
  assert.deepEqual(await page.evaluate(() => window.__events), []);
  const yaw1 = await page.evaluate((i) => document.getElementById(i).viewer.camera.yaw, id);
  assert.ok(Math.abs(yaw1 - yaw0) > 0.05, `the drag orbited the camera (yaw ${yaw0} -> ${yaw1})`);
  assert.deepEqual(problems, []);
});

test('the wheel scrolls the page over an unfocused figure and zooms a focused one', async () => {
  const { page, problems } = await sharedCourse();
  const id = 'fig-fourpoint';
  await showFigure(page, id);
  const box = await page.locator(`#${id}`).boundingBox();
  const at = { x: box.x + box.width / 2, y: box.y + box.height / 3 };
  const state = () =>
    page.evaluate((i) => ({ scroll: window.scrollY, distance: document.getElementById(i).viewer.camera.distance }), id);
  const s0 = await state();
  await page.mouse.move(at.x, at.y);
  await page.mouse.wheel(0, 200);
  await page.waitForFunction((y) => window.scrollY !== y, s0.scroll, { timeout: 5000 });
  const s1 = await state();
  assert.ok(s1.scroll > s0.scroll, `the page scrolled (${s0.scroll} -> ${s1.scroll})`);
  assert.equal(s1.distance, s0.distance, 'the camera did not zoom');
  // A click focuses the figure; then the wheel zooms and the page stays.
  await showFigure(page, id);
  const box2 = await page.locator(`#${id}`).boundingBox();
  const at2 = { x: box2.x + box2.width / 2, y: box2.y + box2.height / 3 };
  await page.mouse.click(at2.x, at2.y);
  const s2 = await state();
  await page.mouse.wheel(0, 200);
  await page.waitForFunction(([i, d]) => document.getElementById(i).viewer.camera.distance > d, [id, s2.distance]);
  const s3 = await state();
  assert.equal(s3.scroll, s2.scroll, 'the page did not scroll');
  assert.ok(s3.distance > s2.distance * 1.05, `the camera zoomed out (${s2.distance} -> ${s3.distance})`);
  assert.deepEqual(problems, []);
});

test('the J_s parameter: attribute s, its former name j (alone, or agreeing with s), and s and j that disagree named', async () => {
  const { page, problems } = await sharedCourse();
  const cases = [{ s: '0.3' }, { j: '0.3' }, { s: '0.3', j: '.3' }, { s: '0.3', j: '0.4' }];
  const results = await page.evaluate(async (list) => {
    const out = [];
    for (const attrs of list) {
      const el = document.createElement('screw-bender');
      el.setAttribute('loading', 'eager');
      el.setAttribute('preset', 'l_cycle_rotated');
      const events = [];
      el.addEventListener('error', (e) => events.push(e.detail.attribute));
      for (const [k, v] of Object.entries(attrs)) el.setAttribute(k, v);
      document.querySelector('main').append(el);
      await el.ready;
      const msg = el.shadowRoot.querySelector('.msg');
      out.push({ options: el.motion?.options() ?? null, message: msg.hidden ? null : msg.textContent, events });
      el.remove();
    }
    // Changed later: the attribute j and the options property with j both set s.
    const el = document.createElement('screw-bender');
    el.setAttribute('loading', 'eager');
    el.setAttribute('preset', 'l_cycle_rotated');
    el.setAttribute('s', '0.3');
    document.querySelector('main').append(el);
    await el.ready;
    el.setAttribute('j', '0.6');
    await new Promise((res) => setTimeout(res, 100));
    const byAttribute = el.motion.options().s;
    el.options = { j: 0.2 };
    await new Promise((res) => setTimeout(res, 100));
    const { s, j } = el.options;
    el.remove();
    out.push({ byAttribute, s, j });
    return out;
  }, cases);
  for (const k of [0, 1, 2]) {
    const r = results[k];
    assert.equal(r.message, null, `${JSON.stringify(cases[k])}: no message`);
    assert.deepEqual(r.events, []);
    assert.equal(r.options.scheme, 'j');
    assert.ok(Math.abs(r.options.s - 0.3) < 1e-12, `${JSON.stringify(cases[k])}: s = ${r.options.s}`);
    assert.equal('j' in r.options, false, 'options() names the parameter s only');
  }
  const bad = results[3];
  assert.deepEqual(bad.events, ['s']);
  assert.ok(bad.message.includes('s="0.3"') && bad.message.includes('j="0.4"'), `names both: ${bad.message}`);
  const later = results[4];
  assert.ok(Math.abs(later.byAttribute - 0.6) < 1e-12, `attribute j set s: ${later.byAttribute}`);
  assert.ok(Math.abs(later.s - 0.2) < 1e-12, `options {j} set s: ${later.s}`);
  assert.equal(later.j, undefined);
  assert.deepEqual(problems, []);
});

test('off-screen figures draw no frames', async () => {
  const { page, problems } = await sharedCourse();
  // fig-jarek has drawn (it has a renderer); then it goes below the fold, where only its being
  // off screen can keep it from drawing.
  await showFigure(page, 'fig-jarek');
  await page.evaluate(() => window.scrollTo(0, 0));
  const frames = () => page.evaluate(() => ['fig-screw', 'fig-jarek'].map((i) => document.getElementById(i).viewer.frames));
  await page.evaluate(() => ['fig-screw', 'fig-jarek'].forEach((i) => document.getElementById(i).play()));
  // Once the playing on-screen figure drew two more frames, anything play() itself asked of the
  // off-screen one is done; then it must stay still while the other draws three more.
  const start = await frames();
  await page.waitForFunction((n) => document.getElementById('fig-screw').viewer.frames >= n, start[0] + 2);
  const f0 = await frames();
  await page.waitForFunction((n) => document.getElementById('fig-screw').viewer.frames >= n, f0[0] + 3);
  const f1 = await frames();
  // fig-screw (on screen, playing) draws; fig-jarek (below the fold, playing) does not.
  assert.ok(f1[0] >= f0[0] + 2, `on-screen figure drew ${f1[0] - f0[0]} frames`);
  assert.equal(f1[1], f0[1], 'the off-screen figure drew nothing');
  await page.evaluate(() => ['fig-screw', 'fig-jarek'].forEach((i) => document.getElementById(i).pause()));
  assert.deepEqual(problems, []);
});

test('an error in a hover or press on an editable figure is shown in that figure, never thrown into the page', async () => {
  const { page, problems } = await sharedCourse();
  const before = problems.length;
  await page.evaluate(async () => {
    const el = document.createElement('screw-bender');
    el.id = 'press-fails';
    el.setAttribute('loading', 'eager');
    el.setAttribute('preset', 'l_cycle_edit');
    el.setAttribute('editable', '');
    window.__errors = [];
    el.addEventListener('error', (e) => window.__errors.push(e.detail.message));
    document.querySelector('main').append(el);
    await el.ready;
    // A fault inside the press (here: the pick of a pose) stands for any the figure's code might meet.
    el.viewer.pickPose = () => {
      throw new Error('the pick failed');
    };
  });
  const h = await handleOf(page, 'press-fails', 1);
  await drag(page, h, 20, 10);
  const r = await page.evaluate(() => {
    const el = document.getElementById('press-fails');
    const msg = el.shadowRoot.querySelector('.msg');
    const out = { errors: window.__errors, message: msg.hidden ? null : msg.textContent };
    el.remove();
    return out;
  });
  // The hover on the way in, the press and each hover after it met the fault: each said so.
  assert.ok(r.errors.length >= 2, `${r.errors.length} error events`);
  assert.deepEqual(new Set(r.errors), new Set(['the pick failed']));
  assert.equal(r.message, 'the pick failed');
  assert.deepEqual(problems.slice(before), []);
});

test('bad attributes and sources: a message naming attribute and value in that figure, an error event, others unharmed', async () => {
  const { page, problems } = await sharedCourse();
  const cases = [
    ['preset', 'no_such_preset'],
    ['levels', '99'],
    ['scheme', 'cubic'],
    ['controls', 'most'],
    ['src', 'missing.json'],
    ['src', 'course.css'],
    ['share', 'not-a-payload!'],
  ];
  const results = await page.evaluate(async (list) => {
    const out = [];
    for (const [name, value] of list) {
      const el = document.createElement('screw-bender');
      el.setAttribute('loading', 'eager');
      const events = [];
      el.addEventListener('error', (e) => events.push(e.detail));
      el.setAttribute(name, value);
      document.querySelector('main').append(el);
      await el.ready;
      out.push({ message: el.shadowRoot.querySelector('.msg').textContent, hidden: el.shadowRoot.querySelector('.msg').hidden, events });
      el.remove();
    }
    // Inline JSON that is not JSON.
    const el = document.createElement('screw-bender');
    el.setAttribute('loading', 'eager');
    const events = [];
    el.addEventListener('error', (e) => events.push(e.detail));
    const s = document.createElement('script');
    s.type = 'application/json';
    s.textContent = '{"poses": [';
    el.append(s);
    document.querySelector('main').append(el);
    await el.ready;
    out.push({ message: el.shadowRoot.querySelector('.msg').textContent, hidden: el.shadowRoot.querySelector('.msg').hidden, events });
    el.remove();
    return out;
  }, cases);
  cases.forEach(([name, value], k) => {
    const r = results[k];
    assert.equal(r.hidden, false, `${name}=${value}: message shown`);
    assert.ok(r.message.includes(`${name}="${value}"`), `${name}=${value}: message names it: ${r.message}`);
    assert.equal(r.events.length, 1, `${name}=${value}: one error event`);
    assert.equal(r.events[0].attribute, name);
  });
  const inline = results[cases.length];
  assert.equal(inline.hidden, false);
  assert.match(inline.message, /script="application\/json": not JSON/);
  assert.equal(inline.events.length, 1);
  // The course figures still draw and show no message.
  const sig = await signature(page, 'fig-screw');
  assert.ok(sig.nonBackground > 0.03);
  // A bad value set later keeps the figure's motion and names the attribute.
  const r = await page.evaluate(async () => {
    const el = document.getElementById('fig-fourpoint');
    const before = Array.from(el.motion.subdivide());
    const events = [];
    el.addEventListener('error', (e) => events.push(e.detail.attribute));
    el.setAttribute('levels', '-1');
    await new Promise((res) => setTimeout(res, 100));
    return { events, same: Array.from(el.motion.subdivide()).every((x, i) => x === before[i]), levels: el.motion.options().levels };
  });
  assert.deepEqual(r.events, ['levels']);
  assert.equal(r.same, true);
  assert.equal(r.levels, 5);
  // The failed loads logged console errors only for the missing file (the browser's own 404 line).
  assert.deepEqual(problems.filter((p) => !/404|Not Found/.test(p)), []);
});

test('a figure starts once its stylesheet applies (ready, the first frame at its laid-out size); one that fails is named', async () => {
  const { page, problems } = await sharedCourse();
  const before = problems.length;
  // The stylesheet of the figures made below comes late, then not at all (the course's own
  // figures have theirs).
  let answer = 'late';
  const seen = [];
  await page.route('**/css/screw-bender.css', async (route) => {
    seen.push(answer);
    if (answer === 'late') {
      await new Promise((res) => setTimeout(res, 1500));
      await route.continue();
    } else await route.fulfill({ status: 404, body: '' });
  });
  try {
    const make = () =>
      page.evaluate(async () => {
        const el = document.createElement('screw-bender');
        el.setAttribute('loading', 'eager');
        el.setAttribute('preset', 'l_cycle_edit');
        const errors = [];
        el.addEventListener('error', (e) => errors.push(e.detail.message));
        document.querySelector('main').prepend(el);
        await el.ready;
        const box = el.shadowRoot.querySelector('canvas').getBoundingClientRect();
        const msg = el.shadowRoot.querySelector('.msg');
        const out = {
          styled: !!el.shadowRoot.querySelector('link').sheet,
          canvas: [box.width, box.height],
          host: el.getBoundingClientRect().width,
          drawnAt: el.viewer.pixelSize().cssW,
          errors,
          message: msg.hidden ? null : msg.textContent,
        };
        el.remove();
        return out;
      });
    const late = await make();
    assert.equal(late.styled, true, 'ready waited for the stylesheet');
    // Styled, the canvas spans the figure (unstyled it is the 300 × 150 default).
    assert.ok(Math.abs(late.canvas[0] - late.host) < 1, `canvas ${late.canvas} in a figure ${late.host} wide`);
    assert.equal(late.drawnAt, late.canvas[0], 'the viewer measured the styled canvas');
    assert.deepEqual(late.errors, []);
    answer = 'missing';
    const missing = await make();
    assert.equal(missing.errors.length, 1);
    assert.match(missing.errors[0], /^The figure's stylesheet did not load \(http:.*\/css\/screw-bender\.css\)\.$/);
    assert.equal(missing.message, missing.errors[0]);
    assert.deepEqual(seen, ['late', 'missing']);
  } finally {
    await page.unroute('**/css/screw-bender.css');
  }
  // The only console line is the browser's own for the missing file.
  assert.deepEqual(problems.slice(before).filter((p) => !/404|Not Found/.test(p)), []);
});

test('persist="key": the figure restores its saved motion from that key and saves edits there', async () => {
  const { page, problems } = await openFigures(play, COURSE);
  try {
    const r = await page.evaluate(async () => {
      const saved = { document: { closed: false, poses: [
        { origin: [0, 0, 0], rotation: [1, 0, 0, 0] },
        { origin: [1, 1, 0], rotation: [1, 0, 0, 0] },
        { origin: [2, 0, 0], rotation: [1, 0, 0, 0] },
      ] }, options: { scheme: 'fourpoint', levels: 2, j: 0, rules: 'direct' } };
      localStorage.setItem('course.fig', JSON.stringify(saved));
      const el = document.createElement('screw-bender');
      el.setAttribute('loading', 'eager');
      el.setAttribute('scene', 'circle4');
      el.setAttribute('persist', 'course.fig');
      el.setAttribute('editable', '');
      document.querySelector('main').prepend(el);
      await el.ready;
      return { poses: Array.from(el.motion.poses()), keys: Object.keys(localStorage) };
    });
    assert.deepEqual(r.poses, [0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 0, 0, 0, 2, 0, 0, 1, 0, 0, 0]);
    assert.deepEqual(r.keys, ['course.fig']);
    await page.evaluate(() => window.scrollTo(0, 0));
    const id = await page.evaluate(() => {
      const el = document.querySelector('main > screw-bender');
      el.id = 'persisted';
      return el.id;
    });
    const h = await handleOf(page, id, 1);
    // What the press met (the pose under it, where the handle was then) and the events the drag
    // fired, to name what went wrong when the pose did not move.
    await page.evaluate(() => {
      const el = document.getElementById('persisted');
      window.__seen = { events: [], press: null };
      for (const type of ['select', 'change', 'error']) el.addEventListener(type, () => window.__seen.events.push(type));
      const at = (e) => {
        const r = el.viewer.canvas.getBoundingClientRect();
        const pt = [e.clientX - r.left, e.clientY - r.top];
        window.__seen.press = { pt, pose: el.viewer.pickPose(pt), handle: el.viewer.screenOfPose(1), canvas: [r.left, r.top, r.width, r.height] };
      };
      el.shadowRoot.addEventListener('pointerdown', at, true);
    });
    await drag(page, h, 30, 20);
    const seen = await page.evaluate(() => window.__seen);
    assert.deepEqual(problems, []);
    assert.deepEqual(seen.events, ['select', 'change'], `a drag from the handle at ${h.x},${h.y}: ${JSON.stringify(seen)}`);
    const stored = await page.evaluate(() => JSON.parse(localStorage.getItem('course.fig')).document.poses[1].origin);
    const now = await page.evaluate(() => Array.from(document.getElementById('persisted').motion.pose(1).origin));
    assert.deepEqual(stored, now);
    assert.ok(Math.hypot(now[0] - 1, now[1] - 1, now[2]) > 0.05, `pose 1 moved to ${now}`);
  } finally {
    await page.close();
  }
});

test('phones (320 and 390 px, touch): the control bar shows play, scrubber and a steady time label, with 44 px targets, in both themes', async () => {
  for (const [width, height] of [[390, 844], [320, 640]]) {
    const ctx = await play.browser.newContext({ viewport: { width, height }, hasTouch: true, isMobile: true, deviceScaleFactor: 2 });
    try {
      const page = await ctx.newPage();
      const problems = [];
      page.on('console', (m) => m.type() === 'error' && problems.push(`console: ${m.text()}`));
      page.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
      await page.goto(`${play.url}${COURSE}`);
      await page.waitForFunction(() => customElements.get('screw-bender'));
      await page.evaluate(() => Promise.all([...document.querySelectorAll('screw-bender')].map((e) => {
        e.setAttribute('loading', 'eager');
        return e.ready;
      })));
      /** The boxes of figure `id`'s bar parts and the time label's text, width and colours. */
      const parts = (id) =>
        page.evaluate((i) => {
          const root = document.getElementById(i).shadowRoot;
          const box = (s) => root.querySelector(s).getBoundingClientRect().toJSON();
          const time = root.querySelector('.time');
          const cs = getComputedStyle(time);
          return {
            bar: box('.bar'), play: box('.play'), scrub: box('.scrub'), time: box('.time'),
            text: time.textContent, numerals: cs.fontVariantNumeric, color: cs.color,
            barColor: getComputedStyle(root.querySelector('.bar')).backgroundColor,
          };
        }, id);
      const inside = (a, b) => a.left >= b.left - 0.5 && a.right <= b.right + 0.5 && a.top >= b.top - 0.5 && a.bottom <= b.bottom + 0.5;
      const apart = (a, b) => a.right <= b.left + 0.5 || b.right <= a.left + 0.5 || a.bottom <= b.top + 0.5 || b.bottom <= a.top + 0.5;
      for (const id of FIGURES) {
        await page.evaluate((i) => document.getElementById(i).scrollIntoView({ block: 'center' }), id);
        const p = await parts(id);
        const where = `${id} at ${width} px`;
        assert.ok(p.time.width > 20 && p.time.height > 8, `${where}: time label shown (${p.time.width}×${p.time.height})`);
        assert.ok(inside(p.time, p.bar) && inside(p.play, p.bar) && inside(p.scrub, p.bar), `${where}: parts inside the bar`);
        assert.ok(apart(p.time, p.scrub) && apart(p.play, p.scrub) && apart(p.time, p.play), `${where}: parts do not overlap`);
        // One row: the label beside the scrubber (its middle within the scrubber's height).
        const mid = (b) => b.top + b.height / 2;
        assert.ok(Math.abs(mid(p.time) - mid(p.scrub)) < 2 && Math.abs(mid(p.play) - mid(p.scrub)) < 2, `${where}: one row`);
        assert.ok(p.play.width >= 44 - 0.5 && p.play.height >= 44 - 0.5, `${where}: play ${p.play.width}×${p.play.height}`);
        assert.ok(p.scrub.height >= 44 - 0.5, `${where}: scrubber ${p.scrub.height} px high`);
        // The scrubber takes the rest of the row: play, label and gaps (8 px each) and padding.
        const rest = p.bar.width - 16 - p.play.width - p.time.width - 16;
        assert.ok(Math.abs(p.scrub.width - rest) < 2, `${where}: scrubber ${p.scrub.width} px of ${rest} left`);
        assert.equal(p.numerals, 'tabular-nums');
      }
      // The label keeps its width while the time runs (a cycle: its end is its start again).
      const id = 'fig-fourpoint';
      await page.evaluate((i) => document.getElementById(i).scrollIntoView({ block: 'center' }), id);
      const seen = [];
      for (const f of [0, 0.37, 0.81, 0.99]) {
        await page.evaluate(([i, ff]) => {
          const e = document.getElementById(i);
          const [a, b] = e.motion.timeDomain();
          e.seek(a + ff * (b - a));
        }, [id, f]);
        seen.push(await parts(id));
      }
      assert.equal(new Set(seen.map((p) => p.text)).size, 4, `the label follows the time: ${seen.map((p) => p.text)}`);
      for (const p of seen) assert.ok(/^\d+(\.\d+)? s$/.test(p.text) && p.text.replace(/\D/g, '').length <= 4, `compact label ${p.text}`);
      assert.ok(seen.every((p) => Math.abs(p.time.width - seen[0].time.width) < 0.01 && Math.abs(p.time.left - seen[0].time.left) < 0.01), 'the label does not move');
      // A real tap on play starts the figure; the scrubber follows the playback.
      const pl = seen[0].play;
      await page.touchscreen.tap(pl.x + pl.width / 2, pl.y + pl.height / 2);
      await page.waitForFunction((i) => document.getElementById(i).shadowRoot.querySelector('.play').getAttribute('aria-label') === 'Pause', id);
      await page.waitForFunction((i) => Number(document.getElementById(i).shadowRoot.querySelector('.scrub').value) > 0, id);
      // Dark theme: light label on a dark bar, the same layout.
      await page.evaluate(() => document.querySelectorAll('screw-bender').forEach((e) => e.setAttribute('theme', 'dark')));
      const dark = await parts(id);
      const lum = (rgb) => {
        const [r, g, b] = rgb.match(/[\d.]+/g).map(Number);
        return (0.2126 * r + 0.7152 * g + 0.0722 * b) / 255;
      };
      assert.ok(lum(dark.color) > 0.55 && lum(dark.barColor) < 0.25, `dark: label ${dark.color} on ${dark.barColor}`);
      assert.ok(Math.abs(dark.time.width - seen[0].time.width) < 0.01 && apart(dark.time, dark.scrub));
      await page.evaluate(() => document.querySelectorAll('screw-bender').forEach((e) => e.pause()));
      assert.deepEqual(problems, []);
    } finally {
      await ctx.close();
    }
  }
});
