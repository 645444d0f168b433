// e2e-backends: webgpu (computed on the CPU, the same on either backend: once)
// Lessons (www/lessons/, www/js/lessons/): every lesson's steps load without errors, every
// exercise's checks fail on a scripted wrong answer and pass on a scripted right one, the
// multiple-choice answers agree with what the wasm API measures, malformed lesson files are
// refused with a message naming step and field (page unchanged), progress survives a reload,
// ?lesson= and ?tour=1 open by URL. Screenshots of each lesson go to artifacts/e2e-<backend>/lessons/
// (with DOCS_SHOTS=1 to docs/screenshots/lessons/, the committed copies).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { ROOT, BACKEND, startPlayground, openPage, shotPath, waitFrames } from './lib.mjs';

const LESSONS = JSON.parse(fs.readFileSync(path.join(ROOT, 'www/lessons/index.json'), 'utf8')).lessons;
const SHOTS = path.dirname(shotPath('lessons/index.png'));

let play;
let page;
let problems;

before(async () => {
  play = await startPlayground();
  ({ page, problems } = await openPage(play.context, play.url, BACKEND));
  await page.evaluate(() => window.screwbender.lessons);
});

after(async () => {
  await play?.close();
});

/** Runs `f(player, app, arg)` in the page (f must be self-contained, or use answerImport). */
const inPage = (f, arg) => page.evaluate(async ([src, a, answerSrc]) => {
  const L = await window.screwbender.lessons;
  // eslint-disable-next-line no-new-func
  return new Function('L', 'app', 'a', `${answerSrc}\nreturn (${src})(L, app, a);`)(L, window.screwbender.app, a);
}, [f.toString(), arg, answerImport.toString()]);

/**
 * The messages the page showed, less the notes on what an import of a step's measured poses
 * kept, fitted or (moving on) cancelled: the page tells a student that, as for a file.
 */
const pageErrors = async () => (await page.evaluate(() => window.screwbender.errors())).filter((m) => !/^“[^”]+”: (kept|fitted|import cancelled)/.test(m));

/** Opens lesson `name` from its first step; asserts it opened. */
async function openLesson(name) {
  const ok = await inPage((L, app, n) => L.open(n, { resume: false }), name);
  assert.equal(ok, true, `lesson ${name} did not open: ${await page.evaluate(() => window.screwbender.errors().join(' | '))}`);
}

// ------------------------------------------------------------------ scripted answers
// For every exercise `<lesson id>:<step>`: `wrong` leaves the motion so the checks must fail,
// `right` does what a student would do to solve it. Both run in the page (L, app).
const ANSWERS = {
  'screw:2': {
    wrong: () => {},
    right: (L, app) => app.parts.session.edit(() => {
      const p = app.motion.pose(1);
      app.motion.setPose(1, { origin: [p.origin[0], p.origin[1], 0], rotation: p.rotation });
    }),
  },
  // The randomised pitch: pose 1 raised by h·π/2 for this student's h (its variant).
  'screw:3': {
    wrong: () => {},
    right: (L, app) => app.parts.session.edit(() => {
      const p = app.motion.pose(1);
      app.motion.setPose(1, { origin: [p.origin[0], p.origin[1], (L.variant.values[L.step].h * Math.PI) / 2], rotation: p.rotation });
    }),
  },
  'screw:4': {
    wrong: () => {},
    right: (L, app) => app.parts.session.edit(() => app.motion.setPose(1, { origin: app.motion.pose(1).origin, rotation: [1, 0, 0, 0] })),
  },
  'screw:5': { wrong: (L) => L.choose(0), right: (L) => L.choose(1) },
  'polyscrew:2': {
    wrong: () => {},
    // Pose 1 at the screw midpoint of poses 0 and 2: both spans are halves of one screw.
    right: async (L, app) => {
      const wasm = app.wasm;
      app.parts.session.edit(() => app.motion.setPose(1, wasm.screw(app.motion.pose(0), 0.5, app.motion.pose(2))));
    },
  },
  'polyscrew:3': {
    wrong: (L, app) => app.run('setOption', 'levels', 2),
    right: (L, app) => {
      app.run('setScheme', 'bspline');
      app.run('setOption', 'levels', 5);
    },
  },
  'split-tweak:3': {
    wrong: (L, app) => app.run('setScheme', 'jarek') || app.run('setOption', 'rules', 'direct'),
    right: (L, app) => app.run('setOption', 'rules', 'split') || app.run('setScheme', 'jarek'),
  },
  'split-tweak:4': { wrong: (L) => L.choose(0), right: (L) => L.choose(1) },
  'schemes:1': { wrong: (L, app) => app.run('setScheme', 'jarek'), right: (L, app) => app.run('setScheme', 'fourpoint') },
  'schemes:3': { wrong: (L, app) => app.run('setS', 0.9), right: (L, app) => app.run('setS', 1) },
  'schemes:4': { wrong: (L) => L.choose(1), right: (L) => L.choose(2) },
  'frames:2': { wrong: (L) => L.choose(2), right: (L) => L.choose(1) },
  'frames:3': { wrong: (L) => L.choose(1), right: (L) => L.choose(3) },
  'methods:1': { wrong: (L) => L.choose(2), right: (L) => L.choose(1) },
  'methods:2': { wrong: (L) => L.choose(0), right: (L) => L.choose(3) },
  'methods:3': { wrong: (L, app) => app.run('setScheme', 'bspline'), right: (L, app) => app.run('setScheme', 'fourpoint') },
  'methods:4': { wrong: (L) => L.choose(0), right: (L) => L.choose(1) },
  // The measured poses' import dialog is open: Reduce (every k-th, the dialog's default) keeps
  // too many noisy poses; a fit of 12 control poses passes.
  'fitting:2': { wrong: () => answerImport({ how: 'every' }), right: (L) => (L.go(L.step), answerImport({ how: 'fit', controls: 12, robust: 'huber' })) },
  // Outliers: least squares (robust loss none) is dragged off the inliers; Huber is not. The
  // wrong answer's fit closes the dialog, so the step is applied again for the right one.
  'fitting:3': {
    wrong: () => answerImport({ how: 'fit', controls: 14, robust: 'none' }),
    right: (L) => (L.go(L.step), answerImport({ how: 'fit', controls: 14, robust: 'huber' })),
  },
  'fitting:4': { wrong: (L) => L.choose(1), right: (L) => L.choose(0) },
};

/**
 * In the page: answers the open import dialog as the options `o` say (`how`: a choice's value;
 * for a fit its number of `controls` and its `robust` loss) and resolves once it has closed.
 */
async function answerImport(o) {
  // The dialog opens once the step's samples module is there (fetched as the step opens).
  const until = (done) => new Promise((resolve, reject) => {
    const t0 = performance.now();
    const poll = () => (done() ? resolve() : performance.now() - t0 > 10000 ? reject(new Error('no import dialog is open')) : setTimeout(poll, 20));
    poll();
  });
  await until(() => document.getElementById('reduce-dialog'));
  const d = document.getElementById('reduce-dialog');
  d.querySelector(`#reduce-${o.how}`).click();
  if (o.controls) d.querySelector('#reduce-fit-n').value = String(o.controls);
  if (o.robust) d.querySelector('#reduce-robust').value = o.robust;
  d.querySelector('button[type=submit]').click();
  await until(() => !document.getElementById('reduce-dialog'));
}

// Every step of every lesson applied, at three sizes, its card's math typeset, clear of its
// highlight and with no error shown: lesson-layout.test.mjs walks them all.
test('every lesson has typeset math', () => {
  for (const { file } of LESSONS) {
    const text = fs.readFileSync(path.join(ROOT, 'www/lessons', file), 'utf8');
    assert.match(text, /\$[^$]+\$/, `${file} has no math`);
  }
});

test('every exercise fails on a scripted wrong answer and passes on a right one; solved state is saved', async () => {
  const seen = new Set();
  for (const { file, id } of LESSONS) {
    await openLesson(file.replace(/\.json$/, ''));
    const exercises = await inPage((L) => L.lesson.steps.map((s, k) => (s.exercise ? k : -1)).filter((k) => k >= 0));
    assert.ok(exercises.length >= 1, `${id} has no exercise`);
    // Steps run in order (an exercise may build on the steps before it).
    const n = await inPage((L) => L.lesson.steps.length);
    for (let i = 0; i < n; i++) {
      await inPage((L, app, k) => L.go(k), i);
      if (!exercises.includes(i)) continue;
      const key = `${id}:${i}`;
      seen.add(key);
      const a = ANSWERS[key];
      assert.ok(a, `no scripted answers for exercise ${key}`);
      await inPage(a.wrong);
      const bad = await inPage((L) => L.check());
      assert.equal(bad.ok, false, `${key}: the wrong answer passed`);
      const fb = await page.locator('#lesson .feedback').textContent();
      assert.match(fb, /Not yet|Not this one/, `${key}: feedback ${fb}`);
      await inPage(a.right);
      const good = await inPage((L) => L.check());
      assert.equal(good.ok, true, `${key}: the right answer failed: ${JSON.stringify(good.results)}`);
      assert.ok((await inPage((L, app, lid) => L.progress(lid).solved, id)).includes(i), `${key}: solved state not saved`);
    }
  }
  assert.deepEqual([...seen].sort(), Object.keys(ANSWERS).sort(), 'every scripted answer belongs to an exercise');
  assert.deepEqual(await pageErrors(), []);
});

test('lesson 7 as a student does it: the dialog opens on the measured poses; Reduce fails Check, a fit of 12 passes', async () => {
  await inPage((L) => {
    localStorage.removeItem('screwbender.lesson.fitting');
    return L.open('07-fitting', { resume: false, seed: 5 });
  });
  const dialog = page.locator('#reduce-dialog');
  const card = page.locator('#lesson');
  // Steps 1 and 2 by Next; step 3 opens the import dialog on this student's 240 poses.
  await card.locator('button.next').click();
  await card.locator('button.next').click();
  await dialog.waitFor();
  assert.match(await dialog.locator('h2').textContent(), /^240 poses in /);
  // Reduce (every k-th, the dialog's default): too many control poses, still noisy.
  await dialog.locator('#reduce-every').check();
  await dialog.getByRole('button', { name: 'Import' }).click();
  await dialog.waitFor({ state: 'detached' });
  await card.locator('button.check').click();
  const fb = card.locator('.feedback');
  assert.match(await fb.textContent(), /^Not yet: 3[01] control poses; wanted a count ≤ 12\./);
  assert.equal(await fb.getAttribute('class'), 'feedback no again');
  // The card's Measured poses… opens the dialog once more: the fit of 12 control poses, Import.
  await card.getByRole('button', { name: 'Measured poses…' }).click();
  await dialog.waitFor();
  await dialog.locator('#reduce-fit').check();
  await dialog.locator('#reduce-fit-n').fill('12');
  await dialog.locator('#reduce-fit-run').click();
  await page.waitForFunction(() => /12 control poses fitted to 240 poses/.test(document.getElementById('reduce-report')?.textContent ?? ''));
  await dialog.getByRole('button', { name: 'Import' }).click();
  await dialog.waitFor({ state: 'detached' });
  await card.locator('button.check').click();
  await page.waitForFunction(() => document.querySelector('#lesson .feedback')?.classList.contains('ok'));
  const r = await inPage((L, app) => ({ n: app.motion.poseCount, scheme: app.motion.options().scheme, solved: L.progress('fitting').solved }));
  assert.deepEqual(r, { n: 12, scheme: 'bspline', solved: [2] });
  assert.deepEqual(await pageErrors(), []);
});

test('the multiple-choice answers agree with what the wasm API measures', async () => {
  const r = await page.evaluate(async () => {
    const wasm = await window.screwbender.app.analysis();
    const circle = wasm.Motion.fromPreset('circle4');
    const frameDep = Object.fromEntries(circle.compareMethods().rows.map((row) => [row.method, row.frame_dependence]));
    // One decoupled 4-point step on the circle: the new origins' radius (lesson 5).
    const d = wasm.subdivideDecoupled(circle.poses(), true, { scheme: 'fourpoint', levels: 1 });
    const radii = [];
    for (let k = 0; k < d.length; k += 7) radii.push(Math.hypot(d[k], d[k + 1]));
    // The 4-point split-then-tweak step: which slots move (lesson 3).
    const st = wasm.splitTweakStep(circle.poses(), true, { scheme: 'fourpoint', rules: 'split' }, 0);
    const sphere = wasm.Motion.fromPreset('rb_sphere7');
    const rows = Object.fromEntries(sphere.compareMethods().rows.map((row) => [row.method, row]));
    const jarek = wasm.Motion.fromPreset('circle4');
    jarek.setScheme('jarek');
    return {
      frameDep, radii, tweaked: Array.from(st.tweaked), jarekS: jarek.options().s,
      vj: Object.fromEntries(Object.entries(rows).map(([k, v]) => [k, v.velocity_jump])),
      fd: Object.fromEntries(Object.entries(rows).map(([k, v]) => [k, v.frame_dependence])),
      jarekInterp: rows.jarek.interpolation_error,
      interp: Object.fromEntries(Object.entries(rows).map(([k, v]) => [k, v.interpolation_error])),
    };
  });
  // Lesson 5 Q2 / lesson 1: screw methods are frame-independent (round-off), Squad + CR is not.
  for (const m of ['polyscrew', 'bspline', 'jarek']) assert.ok(r.frameDep[m] < 1e-12, `${m} ${r.frameDep[m]}`);
  assert.ok(r.frameDep.decoupled > 1e-3 && r.frameDep.slerp > 1e-3, JSON.stringify(r.frameDep));
  // Lesson 5 Q1: odd slots at 10√2/16 R with R = 3.
  for (let k = 1; k < r.radii.length; k += 2) assert.ok(Math.abs(r.radii[k] - (10 * Math.SQRT2 / 16) * 3) < 1e-12, String(r.radii[k]));
  // Lesson 3: the 4-point tweak moves exactly the inserted midpoints.
  r.tweaked.forEach((t, k) => assert.equal(t, k % 2, `slot ${k}`));
  // Lesson 4: Jarek is s = 1/2.
  assert.equal(r.jarekS, 0.5);
  // Lesson 6 Q1: only SLERP jumps (by orders of magnitude); Q2: only ScrewBender is frame-independent.
  // Converged: SLERP's velocity jump is a value, the C¹ methods' tend to zero.
  assert.ok(r.vj.slerp.limit === 'value' && r.vj.slerp.value > 1 && ['decoupled', 'rb', 'cc1'].every((m) => r.vj[m].limit === 'zero'), JSON.stringify(r.vj));
  assert.ok(r.fd.jarek < 1e-12 && r.fd.slerp > 1e-2 && r.fd.decoupled > 1e-2 && r.fd.rb > 1e-2, JSON.stringify(r.fd));
  // Lesson 6 text: Jarek's interpolation error "about 0.17".
  assert.ok(Math.abs(r.jarekInterp - 0.17) < 0.01, String(r.jarekInterp));
  // Lesson 6 Q4: the SE(3) B-spline is frame-independent, Kim–Kim–Shin (split) is not; the SE(3)
  // B-spline's interpolation error is "about 0.31", close to ScrewBender's B-spline's.
  assert.ok(r.fd.se3bspline < 1e-12 && r.fd.kks > 1e-2, JSON.stringify(r.fd));
  assert.ok(Math.abs(r.interp.se3bspline - 0.31) < 0.01 && Math.abs(r.interp.bspline - 0.31) < 0.01, JSON.stringify(r.interp));
});

test('schema.json names what the page accepts; index.json lists every lesson', async () => {
  const schema = JSON.parse(fs.readFileSync(path.join(ROOT, 'www/lessons/schema.json'), 'utf8'));
  const page_ = await page.evaluate(async () => {
    const wasm = await window.screwbender.app.analysis();
    const fmt = await import('./js/lessons/format.js');
    const { VIEW_IDS } = await import('./js/dock/index.js');
    return {
      scenes: wasm.presets().map((s) => s.id),
      views: VIEW_IDS,
      checks: Object.fromEntries(Object.entries(fmt.CHECK_FIELDS).map(([k, v]) => [k, [...v].sort()])),
      metrics: fmt.METRIC_FIELDS,
      display: Object.keys(fmt.DISPLAY_FIELDS).sort(),
    };
  });
  const step = schema.$defs.step.properties;
  assert.deepEqual([...step.scene.enum].sort(), [...page_.scenes].sort());
  assert.deepEqual(step.dock.enum.filter((v) => v).sort(), [...page_.views].sort());
  assert.deepEqual(Object.keys(step.display.properties).sort(), page_.display);
  const kinds = Object.fromEntries(schema.$defs.check.oneOf.map((c) => [c.properties.kind.const, Object.keys(c.properties).filter((k) => k !== 'kind').sort()]));
  assert.deepEqual(kinds, page_.checks);
  const metric = schema.$defs.check.oneOf.find((c) => c.properties.kind.const === 'metric');
  assert.deepEqual(metric.properties.field.enum, page_.metrics);
  const files = fs.readdirSync(path.join(ROOT, 'www/lessons')).filter((f) => f.endsWith('.json') && !['index.json', 'schema.json', 'tour.json'].includes(f));
  assert.deepEqual(LESSONS.map((l) => l.file).sort(), files.sort());
  assert.ok(LESSONS.length >= 6);
  for (const l of LESSONS) assert.equal(JSON.parse(fs.readFileSync(path.join(ROOT, 'www/lessons', l.file), 'utf8')).id, l.id, l.file);
});

test('malformed lesson files: the message names step and field, and nothing changes', async () => {
  await inPage((L) => L.close());
  const good = JSON.parse(fs.readFileSync(path.join(ROOT, 'www/lessons/02-polyscrew.json'), 'utf8'));
  const variant = (f) => {
    const l = structuredClone(good);
    f(l);
    return JSON.stringify(l);
  };
  const cases = [
    ['{"id": "x", "title": "t", "steps": [', /not valid JSON/],
    [variant((l) => (l.steps[2].exercise.checks[1].max = 'small')), /steps\[2\]\.exercise\.checks\[1\]\.max: expected a finite number/],
    [variant((l) => (l.steps[1].scene = 'no_such_scene')), /steps\[1\]\.scene: "no_such_scene" is not one of/],
    [variant((l) => (l.steps[3].exercise.checks[0].kind = 'guess')), /steps\[3\]\.exercise\.checks\[0\]\.kind: "guess" is not one of/],
    [variant((l) => (l.steps[0].text = 'a formula $\\frac{1}{$ here')), /steps\[0\]\.text: math/],
    [variant((l) => (l.steps[0].text = 'unclosed $x')), /steps\[0\]\.text: unclosed \$/],
    [variant((l) => (l.steps[1].options = { levels: 20 })), /steps\[1\]\.options\.levels: expected a whole number from 0 to 19/],
    [variant((l) => (l.steps[1].options = { s: 0.3, j: 0.4 })), /steps\[1\]\.options\.s: s and j disagree/],
    [variant((l) => (l.steps[1].highlight = { panel: 'Nope' })), /steps\[1\]\.highlight\.panel: "Nope" is not one of/],
    [variant((l) => (l.steps[0].colour = 'red')), /steps\[0\]\.colour: unknown field/],
    [variant((l) => {
      delete l.steps[0].scene;
      l.steps[0].document = { closed: true, poses: [{ origin: [0, 0, 0], rotation: [0, 0, 0, 0] }, { origin: [1, 0, 0], rotation: [1, 0, 0, 0] }] };
    }), /steps\[0\]\.document: .*poses\[0\]\.rotation/],
    [variant((l) => l.steps[4 - 1].exercise.checks.push({ kind: 'choice', answer: 0 })), /steps\[3\]\.exercise\.checks\[2\]: a choice check needs the exercise to list choices/],
    [variant((l) => (l.steps = [])), /steps: expected a non-empty list/],
  ];
  const before = await page.evaluate(() => ({ poses: Array.from(window.screwbender.poses()), options: window.screwbender.options(), view: window.screwbender.app.view.dock }));
  for (const [text, re] of cases) {
    const n = await page.evaluate(() => window.screwbender.errors().length);
    const ok = await inPage((L, app, t) => L.openText(t, 'bad.json'), text);
    assert.equal(ok, false);
    const errs = await page.evaluate(() => window.screwbender.errors());
    assert.equal(errs.length, n + 1);
    assert.match(errs.at(-1), re);
    assert.match(errs.at(-1), /^Lesson bad\.json: .*Nothing was changed\.$/);
  }
  const afterState = await page.evaluate(() => ({ poses: Array.from(window.screwbender.poses()), options: window.screwbender.options(), view: window.screwbender.app.view.dock }));
  assert.deepEqual(afterState, before);
  assert.equal(await page.locator('#lesson').isHidden(), true);
  assert.equal(await inPage((L) => L.lesson), null);
});

test('a pasted lesson opens; URLs outside lessons/ are refused; L and Esc open and close the menu', async () => {
  await page.locator('#view').focus();
  await page.keyboard.press('l');
  await page.locator('#lessons-menu').waitFor({ state: 'visible' });
  assert.equal(await page.evaluate(() => document.activeElement.dataset.lesson), '01-screw', 'focus on the first lesson');
  await page.keyboard.press('l');
  assert.equal(await page.locator('#lessons-menu').isVisible(), true, 'L inside the menu is not a shortcut');
  await page.keyboard.press('Escape');
  assert.equal(await page.locator('#lessons-menu').isHidden(), true);
  await page.evaluate(() => document.getElementById('t-lessons').click());
  await page.locator('#lessons-menu').waitFor({ state: 'visible' });
  assert.equal(await page.locator('#lessons-menu .lesson-item').count(), LESSONS.length + 1);
  const mine = { id: 'teacher-1', title: 'My lesson', steps: [{ title: 'Hello', text: 'A screw turns by $\\theta$.', scene: 'pendulum', dock: '' }] };
  // A broken lesson first: its error shows above the menu (a real hit test reaches it) ...
  await page.locator('#lessons-menu textarea').fill(JSON.stringify({ ...mine, steps: [{ ...mine.steps[0], scene: 'nowhere' }] }));
  await page.locator('#lessons-menu button.primary').click();
  const above = await page.evaluate(() => {
    const b = document.getElementById('banner');
    const r = b.getBoundingClientRect();
    const hit = document.elementFromPoint(r.left + r.width / 2, r.top + r.height / 2);
    return { shown: !b.hidden, text: b.textContent, onTop: !!hit && b.contains(hit), menu: !document.getElementById('lessons-menu').hidden };
  });
  assert.ok(above.shown && above.menu, JSON.stringify(above));
  assert.match(above.text, /nowhere/);
  assert.ok(above.onTop, 'the lesson error lies under the Lessons menu');
  // ... and goes once the lesson is fixed.
  await page.locator('#lessons-menu textarea').fill(JSON.stringify(mine));
  await page.locator('#lessons-menu button.primary').click();
  await page.locator('#lesson').waitFor({ state: 'visible' });
  const after = await page.evaluate(() => ({ hidden: document.getElementById('banner').hidden, text: document.getElementById('banner').textContent }));
  assert.ok(after.hidden || !/nowhere/.test(after.text), `the fixed lesson's error still shows: ${after.text}`);
  assert.equal(await inPage((L) => L.lesson.id), 'teacher-1');
  assert.equal(await page.evaluate(() => window.screwbender.app.view.scene), 'pendulum');
  assert.equal(await page.locator('#lesson .text math').count(), 1);
  await inPage((L) => L.close());
  // A lesson written with `j`, the former name of the J_s parameter `s`, still sets it and checks it.
  const old = {
    id: 'teacher-old', title: 'Old names',
    steps: [{ title: 'J_s', text: 'The J_s family.', scene: 'pendulum', options: { j: 0.3 }, exercise: { task: 'Keep s.', checks: [{ kind: 'options', j: { min: 0.29, max: 0.31 } }] } }],
  };
  assert.equal(await inPage((L, app, t) => L.openText(t, 'old.json', { resume: false }), JSON.stringify(old)), true);
  const o = await page.evaluate(() => window.screwbender.options());
  assert.equal(o.scheme, 'j');
  assert.ok(Math.abs(o.s - 0.3) < 1e-12, JSON.stringify(o));
  assert.equal((await inPage((L) => L.check())).ok, true);
  await inPage((L) => L.close());
  for (const bad of ['../index', 'https://example.com/x.json', '/js/main.js', 'lessons/../js/x.json']) {
    assert.equal(await inPage((L, app, b) => L.open(b), bad), false, bad);
    assert.match((await pageErrors()).at(-1), /Nothing was changed/);
  }
});

test("a teacher's dropped lesson: pose checks, hints one at a time, feedback on each attempt", async () => {
  const mine = {
    id: 'teacher-drop',
    title: 'Dropped',
    steps: [{
      title: 'Put pose 2 back',
      text: 'Move pose 2 to $(1, 2, 0)$ without turning it.',
      scene: 'l_cycle_parallel',
      options: { levels: 3 },
      exercise: {
        task: 'Pose 2 at $(1, 2, 0)$, unturned.',
        checks: [{ kind: 'pose', pose: 2, origin: [1, 2, 0], tolerance: 0.01, rotation: [1, 0, 0, 0], angleTolerance: 0.5 }],
        hints: ['First hint.', 'Second hint with $x$.'],
      },
    }],
  };
  await page.evaluate(() => document.getElementById('t-lessons').click());
  await page.locator('#lessons-menu').waitFor({ state: 'visible' });
  // A file dropped while the menu is open is a lesson (not a motion document).
  await page.evaluate((text) => {
    const dt = new DataTransfer();
    dt.items.add(new File([text], 'dropped.json', { type: 'application/json' }));
    document.getElementById('lessons-menu').dispatchEvent(new DragEvent('drop', { dataTransfer: dt, bubbles: true, cancelable: true }));
  }, JSON.stringify(mine));
  await page.locator('#lesson').waitFor({ state: 'visible' });
  assert.equal(await inPage((L) => L.lesson.id), 'teacher-drop');
  assert.equal(await page.locator('#lessons-menu').isHidden(), true);
  assert.equal(await page.evaluate(() => window.screwbender.app.view.scene), 'l_cycle_parallel');
  // Hints one per click, no more than there are.
  for (let k = 1; k <= 3; k++) {
    await page.locator('#lesson button.hint').click();
    assert.equal(await page.locator('#lesson .hint-text').count(), Math.min(k, 2));
  }
  // Wrong: pose 2 moved and turned; each attempt rewrites the feedback.
  await inPage((L, app) => app.parts.session.edit(() => app.motion.setPose(2, { origin: [1.5, 2, 0], rotation: [Math.cos(0.1), 0, 0, Math.sin(0.1)] })));
  await page.locator('#lesson button.check').click();
  let fb = await page.locator('#lesson .feedback').textContent();
  assert.match(fb, /Not yet: pose 2: origin 0\.5 from the target, rotation 11\.46° from the target; wanted within 0\.01, within 0\.5°\./);
  await inPage((L, app) => app.parts.session.edit(() => app.motion.setPose(2, { origin: [1.005, 2, 0], rotation: [Math.cos(0.002), 0, 0, Math.sin(0.002)] })));
  await page.locator('#lesson button.check').click();
  fb = await page.locator('#lesson .feedback').textContent();
  assert.match(fb, /Correct/);
  assert.match(await page.locator('#lesson .task .label').textContent(), /solved/);
  assert.deepEqual(await inPage((L) => L.progress('teacher-drop').solved), [0]);
  // Finish shows the summary (solved of all, nothing after a dropped lesson); Close closes the card.
  await page.locator('#lesson button.next').click();
  await page.locator('#lesson.summary').waitFor({ state: 'visible' });
  assert.match(await page.locator('#lesson .text').textContent(), /Exercises solved: 1 of 1\./);
  assert.deepEqual(await inPage((L) => L.summary), { solved: 1, total: 1 });
  assert.equal(await page.locator('#lesson button.next').textContent(), 'Close ✓');
  await page.locator('#lesson button.next').click();
  assert.equal(await page.locator('#lesson').isHidden(), true);
  assert.deepEqual((await pageErrors()).filter((e) => !/Nothing was changed/.test(e)), []);
});

test('?lesson= opens a lesson and resumes it after a reload with its solved exercises; ?tour=1 points at the controls', async () => {
  const q = BACKEND === 'webgl2' ? '?backend=webgl2&' : '?';
  const p2 = await play.context.newPage();
  await p2.goto(`${play.url}${q}lesson=04-schemes`);
  await p2.evaluate(() => window.screwbender.ready);
  const first = await p2.evaluate(async () => {
    const L = await window.screwbender.lessons;
    await L.ready;
    return { id: L.lesson?.id, step: L.step };
  });
  assert.equal(first.id, 'schemes');
  await p2.evaluate(async () => {
    const L = await window.screwbender.lessons;
    L.go(4);
    L.choose(2);
    L.check();
  });
  await p2.reload();
  await p2.evaluate(() => window.screwbender.ready);
  const resumed = await p2.evaluate(async () => {
    const L = await window.screwbender.lessons;
    await L.ready;
    return { step: L.step, solved: L.progress('schemes').solved, label: document.querySelector('#lesson .task .label')?.textContent };
  });
  assert.equal(resumed.step, 4);
  assert.ok(resumed.solved.includes(4));
  assert.match(resumed.label, /solved/);
  await p2.close();

  const p3 = await play.context.newPage();
  await p3.goto(`${play.url}${q}tour=1`);
  await p3.evaluate(() => window.screwbender.ready);
  await p3.evaluate(async () => (await window.screwbender.lessons).ready);
  assert.equal(await p3.evaluate(async () => (await window.screwbender.lessons).lesson?.id), 'tour');
  // The editor's first-visit hint (if the page has one) waits while the tour is open.
  assert.equal(await p3.evaluate(() => { const h = document.getElementById('hint'); return !h || h.hidden || getComputedStyle(h).display === 'none'; }), true);
  const targets = { 2: '#panel', 4: '#play', 5: '#t-dock', 6: '#t-lessons' };
  for (const [k, sel] of Object.entries(targets)) {
    await p3.evaluate(async (i) => (await window.screwbender.lessons).go(i), Number(k));
    await p3.waitForTimeout(100);
    const spot = await p3.evaluate(async () => (await window.screwbender.lessons).spot());
    const box = await p3.locator(sel).boundingBox();
    assert.ok(spot, `tour step ${k}: no highlight`);
    const cx = spot.x + spot.w / 2;
    const cy = spot.y + spot.h / 2;
    assert.ok(cx >= box.x && cx <= box.x + box.width && cy >= box.y && cy <= box.y + box.height, `tour step ${k}: spot ${JSON.stringify(spot)} not on ${sel} ${JSON.stringify(box)}`);
  }
  // The handle step rings control pose 0's handle.
  await p3.evaluate(async () => (await window.screwbender.lessons).go(0));
  await p3.waitForTimeout(100);
  const [spot, handle] = await p3.evaluate(async () => [(await window.screwbender.lessons).spot(), window.screwbender.handleOnPage(0)]);
  assert.ok(Math.hypot(spot.x + spot.w / 2 - handle.x, spot.y + spot.h / 2 - handle.y) < 2, JSON.stringify([spot, handle]));
  assert.deepEqual(await p3.evaluate(() => window.screwbender.errors()), []);
  await p3.close();
});

test('axe finds no serious or critical violation in the lesson menu, card and exercises', async () => {
  // axe-core from npm, evaluated through the debugging protocol (the CSP refuses inline scripts).
  await page.evaluate(fs.readFileSync(path.join(ROOT, 'node_modules/axe-core/axe.min.js'), 'utf8'));
  const audit = () => page.evaluate(async () => {
    const r = await window.axe.run(document, { resultTypes: ['violations'] });
    return r.violations.filter((v) => v.impact === 'serious' || v.impact === 'critical').map((v) => `${v.impact} ${v.id}: ${v.nodes.slice(0, 4).map((n) => n.target.join(' ')).join(', ')}`);
  });
  await page.evaluate(async () => (await window.screwbender.lessons).openMenu());
  assert.deepEqual(await audit(), [], 'lesson menu');
  await openLesson('01-screw');
  for (const step of [1, 3, 5]) {
    await inPage((L, app, k) => {
      L.go(k);
      L.check();
      document.querySelector('#lesson button.hint')?.click();
    }, step);
    assert.deepEqual(await audit(), [], `lesson 1 step ${step + 1}`);
  }
});

test('screenshots of each lesson (docs/screenshots/lessons/ with DOCS_SHOTS=1)', async () => {
  fs.mkdirSync(SHOTS, { recursive: true });
  // At the size of the docs' other pictures (scripts/docs-shots.mjs), not the tests' window.
  await page.setViewportSize({ width: 1280, height: 800 });
  // The refused URLs of an earlier test leave their message up for 9 s: dismissed, as a reader
  // would, so that it is not in the pictures.
  // The card may sit over the banner: its close button by keyboard, as a user would reach it.
  if (await page.locator('#banner').isVisible()) {
    await page.locator('#banner .close').focus();
    await page.keyboard.press('Enter');
  }
  const shots = [
    ['01-screw', 1], ['02-polyscrew', 2], ['03-split-tweak', 2], ['04-schemes', 2], ['05-frames', 2], ['06-methods', 0],
  ];
  for (const [name, step] of shots) {
    await openLesson(name);
    await inPage((L, app, k) => {
      L.go(k);
      app.viewer.setPlaying(false);
      app.dock?.flush();
    }, step);
    await waitFrames(page, 3);
    await page.waitForTimeout(300);
    await page.screenshot({ path: path.join(SHOTS, `${name}.png`) });
  }
  // The tour and a lesson exercise on a phone.
  const phone = await play.browser.newContext({ viewport: { width: 390, height: 844 }, deviceScaleFactor: 1 });
  const { page: pp } = await openPage(phone, play.url, BACKEND, { path: BACKEND === 'webgl2' ? '&tour=1' : '?tour=1' });
  await pp.evaluate(async () => (await window.screwbender.lessons).ready);
  await pp.evaluate(async () => (await window.screwbender.lessons).go(4));
  await waitFrames(pp, 2);
  await pp.waitForTimeout(300);
  await pp.screenshot({ path: path.join(SHOTS, 'tour-phone.png') });
  // A panel row is highlighted in the top half: the card moves to the bottom and leaves it visible.
  await pp.evaluate(async () => (await window.screwbender.lessons).go(2));
  await pp.waitForTimeout(300);
  const [spot, card] = await pp.evaluate(async () => [(await window.screwbender.lessons).spot(), document.getElementById('lesson').getBoundingClientRect().toJSON()]);
  assert.ok(spot && spot.y + spot.h <= card.y, `the card covers the highlighted Levels row: ${JSON.stringify([spot, card])}`);
  await pp.screenshot({ path: path.join(SHOTS, 'tour-phone-levels.png') });
  await pp.evaluate(async () => {
    const L = await window.screwbender.lessons;
    await L.open('05-frames', { resume: false });
    L.go(3);
    L.choose(3);
    L.check();
  });
  await waitFrames(pp, 2);
  await pp.waitForTimeout(300);
  await pp.screenshot({ path: path.join(SHOTS, '05-frames-phone.png') });
  await phone.close();
  for (const f of fs.readdirSync(SHOTS)) assert.ok(fs.statSync(path.join(SHOTS, f)).size > 10000, f);
});

test('no content security policy violation and no page error in all of the above (MathML needs no styles)', async () => {
  assert.deepEqual(await page.evaluate(() => window.__csp), []);
  assert.deepEqual(problems, []);
});
