// e2e-backends: webgpu (the lesson's numbers and checks, the same on either backend: once)
// Randomised lesson steps (www/lessons/README.md, Variants) in the page: lesson 1's pitch
// exercise under two seeds (?seed=) shows two pitches, each checked by its own numbers (the
// right answer of one fails in the other); the same seed after a reload gives the same variant;
// without ?seed= a student's seed is made once, kept with the progress and used again after a
// reload (a teacher's ?seed= preview keeps none), and a ?seed= that is no seed says so.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { ROOT, BACKEND, startPlayground, openPage } from './lib.mjs';
import { drawParams } from '../../www/js/lessons/variants.js';

const LESSON = JSON.parse(fs.readFileSync(path.join(ROOT, 'www/lessons/01-screw.json'), 'utf8'));
/** The randomised step of lesson 1 (its pitch exercise). */
const STEP = LESSON.steps.findIndex((s) => s.params);

let play;

before(async () => {
  play = await startPlayground();
});

after(async () => {
  await play?.close();
});

/** Opens lesson 1 at `query` in the context's new page, at the randomised step; returns the page and what it shows. */
async function openAt(query) {
  const { page, problems } = await openPage(play.context, play.url, BACKEND, { path: `${BACKEND === 'webgl2' ? '&' : '?'}lesson=01-screw${query}` });
  const shown = await page.evaluate(async (k) => {
    const L = await window.screwbender.lessons;
    await L.ready;
    L.go(k);
    const tex = [...document.querySelectorAll('#lesson .task annotation')].map((a) => a.textContent.trim());
    return { id: L.lesson?.id, variant: L.variant, tex, stored: L.progress('screw').seed ?? null };
  }, STEP);
  assert.equal(shown.id, 'screw');
  return { page, problems, shown, h: shown.variant?.values[STEP]?.h };
}

/** In `page`: raises pose 1 to the slide of pitch `h` over the step's quarter turn, checks, returns {ok, feedback}. */
async function answer(page, h) {
  return page.evaluate(async (d) => {
    const L = await window.screwbender.lessons;
    const app = window.screwbender.app;
    app.parts.session.edit(() => {
      const p = app.motion.pose(1);
      app.motion.setPose(1, { origin: [p.origin[0], p.origin[1], d], rotation: p.rotation });
    });
    const r = L.check();
    return { ok: r.ok, feedback: document.querySelector('#lesson .feedback').textContent };
  }, (h * Math.PI) / 2);
}

test('two seeds give two pitches, each checked by its own; a reload keeps the variant', async () => {
  assert.ok(STEP >= 0, 'lesson 1 has a randomised step');
  const params = LESSON.steps[STEP].params;
  // Seed 1 and the first seed after it whose pitch differs (picked by the page's own draw).
  const seedA = 1;
  let seedB = 2;
  while (drawParams(params, seedB, STEP).h === drawParams(params, seedA, STEP).h) seedB++;

  const a = await openAt(`&seed=${seedA}`);
  const b = await openAt(`&seed=${seedB}`);
  assert.equal(a.shown.variant.seed, seedA);
  assert.equal(b.shown.variant.seed, seedB);
  assert.equal(a.h, drawParams(params, seedA, STEP).h);
  assert.equal(b.h, drawParams(params, seedB, STEP).h);
  assert.ok(Math.abs(a.h - b.h) >= 0.1 - 1e-9, `${a.h} ${b.h}`);
  // The task shows each variant's own pitch (the TeX KaTeX typeset).
  assert.ok(a.shown.tex.includes(`h = ${a.h}`), JSON.stringify(a.shown.tex));
  assert.ok(b.shown.tex.includes(`h = ${b.h}`), JSON.stringify(b.shown.tex));

  // Each page: the other seed's right answer fails (saying what it wants), its own passes.
  for (const [mine, other] of [[a, b], [b, a]]) {
    const wrong = await answer(mine.page, other.h);
    assert.equal(wrong.ok, false, `seed ${mine.shown.variant.seed}: pitch ${other.h} passed for h = ${mine.h}`);
    assert.match(wrong.feedback, /Not yet: span 0 is a general screw, pitch [\d.]+; wanted .*pitch in \[/);
    const right = await answer(mine.page, mine.h);
    assert.equal(right.ok, true, `seed ${mine.shown.variant.seed}: its own answer failed: ${right.feedback}`);
  }

  // The same seed after a reload: the same variant, the same text.
  await b.page.reload();
  await b.page.evaluate(() => window.screwbender.ready);
  const again = await b.page.evaluate(async (k) => {
    const L = await window.screwbender.lessons;
    await L.ready;
    L.go(k);
    return { variant: L.variant, tex: [...document.querySelectorAll('#lesson .task annotation')].map((x) => x.textContent.trim()) };
  }, STEP);
  assert.deepEqual(again.variant, b.shown.variant);
  assert.deepEqual(again.tex, b.shown.tex);
  // A teacher's preview kept no seed for the student.
  assert.equal(a.shown.stored, null);
  for (const p of [a, b]) {
    assert.deepEqual(p.problems, []);
    assert.deepEqual(await p.page.evaluate(() => window.screwbender.errors()), []);
    await p.page.close();
  }
});

test("a student's own seed is kept with the progress: the same numbers after a reload", async () => {
  const first = await openAt('');
  const seed = first.shown.variant.seed;
  assert.ok(Number.isInteger(seed) && seed >= 0 && seed <= 0xffffffff, String(seed));
  assert.equal(first.shown.stored, seed, 'the seed is saved with the progress');
  await first.page.reload();
  await first.page.evaluate(() => window.screwbender.ready);
  const again = await first.page.evaluate(async (k) => {
    const L = await window.screwbender.lessons;
    await L.ready;
    L.go(k);
    return L.variant;
  }, STEP);
  assert.deepEqual(again, first.shown.variant);
  await first.page.close();
  // A ?seed= that is not a seed: a message, and the student's own variant.
  const bad = await openAt('&seed=banana');
  assert.equal(bad.shown.variant.seed, seed);
  assert.match((await bad.page.evaluate(() => window.screwbender.errors())).join(' | '), /\?seed=banana: expected a whole number/);
  assert.deepEqual(bad.problems, []);
  await bad.page.close();
});
