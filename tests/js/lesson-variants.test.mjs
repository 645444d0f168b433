// Lesson variants and problems without a browser (www/js/lessons/variants.js, format.js,
// checks.js): the seeded generator is deterministic, a step's parameters are drawn from their
// ranges by the seed alone, references are replaced in texts and numbers, and the validator lists
// every problem of a lesson at once with its step and field (unknown parameters included). The
// variants in the page: tests/e2e/lesson-variants.test.mjs.
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { describe, it } from 'node:test';
import { fileURLToPath } from 'node:url';
import { drawParams, fnv1a, mulberry32, paramValues, substitute } from '../../www/js/lessons/variants.js';
import { LessonError, SAMPLE_MOTION_NAMES, lessonProblems, lessonVariant, parseLesson, validateLesson } from '../../www/js/lessons/format.js';
import { evaluateCheck } from '../../www/js/lessons/checks.js';
import { SAMPLE_MOTIONS, generateSamples, stepSamples } from '../../www/js/lessons/samples.js';
import { variantSeed } from '../../www/js/lessons/lms.js';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const LESSONS = path.join(ROOT, 'www/lessons');
const schema = JSON.parse(fs.readFileSync(path.join(LESSONS, 'schema.json'), 'utf8'));
/** What the page offers the validator (player.js), with a motion check that refuses a zero quaternion. */
const ctx = {
  scenes: schema.$defs.step.properties.scene.enum,
  views: schema.$defs.step.properties.dock.enum.filter((v) => v),
  panel: ['Preset', 'Scheme', 'J_s', 'Rules', 'Levels', 'Closed cycle', 'Strobe count'],
  checkMotion: (doc) => {
    doc.poses.forEach((p, k) => {
      if (p.rotation.every((x) => x === 0)) throw new Error(`poses[${k}].rotation: a zero quaternion`);
    });
  },
};
const read = (f) => fs.readFileSync(path.join(LESSONS, f), 'utf8');
const TWO_POSES = { closed: false, poses: [{ origin: [0, 0, 0], rotation: [1, 0, 0, 0] }, { origin: [3, 1, 0], rotation: [Math.SQRT1_2, 0, 0, Math.SQRT1_2] }] };

describe('the seeded generator', () => {
  it('gives the same sequence for the same seed, another for another seed, all in [0, 1)', () => {
    for (const seed of [0, 1, 42, 0xffffffff]) {
      const a = mulberry32(seed);
      const b = mulberry32(seed);
      const c = mulberry32(seed + 1);
      let same = 0;
      for (let k = 0; k < 1000; k++) {
        const x = a();
        assert.equal(x, b());
        assert.ok(x >= 0 && x < 1, String(x));
        if (x === c()) same++;
      }
      assert.ok(same < 5, `seeds ${seed} and ${seed + 1} agree ${same} times in 1000`);
    }
  });

  it('is roughly uniform: each tenth of [0, 1) gets 10 % ± 1.5 % of 20,000 draws', () => {
    const r = mulberry32(7);
    const bins = new Array(10).fill(0);
    for (let k = 0; k < 20000; k++) bins[Math.floor(r() * 10)]++;
    for (const n of bins) assert.ok(Math.abs(n / 20000 - 0.1) < 0.015, bins.join(' '));
  });

  it('the LMS seed is the same for the same learner and lesson, another for another learner', () => {
    assert.equal(variantSeed('s-17', 'screw'), variantSeed('s-17', 'screw'));
    assert.notEqual(variantSeed('s-17', 'screw'), variantSeed('s-18', 'screw'));
    assert.notEqual(variantSeed('s-17', 'screw'), variantSeed('s-17', 'frames'));
    assert.equal(variantSeed('a', 'b'), fnv1a('a\u0000b'));
  });
});

describe('parameters', () => {
  it('a range lists its values rounded to its decimals; a list is itself', () => {
    assert.deepEqual(paramValues({ min: 0.3, max: 1.2, step: 0.1 }), [0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1, 1.1, 1.2]);
    assert.deepEqual(paramValues({ min: -1, max: 1, step: 0.25 }), [-1, -0.75, -0.5, -0.25, 0, 0.25, 0.5, 0.75, 1]);
    assert.deepEqual(paramValues({ min: 2, max: 2, step: 1 }), [2]);
    assert.deepEqual(paramValues({ values: [3, 4, 6] }), [3, 4, 6]);
  });

  it('the seed alone picks the values; every value of a range turns up; steps and names draw apart', () => {
    const params = { h: { min: 0.3, max: 1.2, step: 0.1 }, n: { values: [3, 4, 6] } };
    const grid = paramValues(params.h);
    const seen = new Set();
    let differ = 0;
    for (let seed = 0; seed < 300; seed++) {
      const v = drawParams(params, seed, 3);
      assert.deepEqual(drawParams(params, seed, 3), v, `seed ${seed} drew twice differently`);
      assert.ok(grid.includes(v.h), `h = ${v.h} is not on the grid`);
      assert.ok([3, 4, 6].includes(v.n), `n = ${v.n}`);
      seen.add(v.h);
      // Another step of the same lesson draws its own values.
      if (drawParams(params, seed, 4).h !== v.h) differ++;
      // Adding a parameter leaves the others' values as they were.
      assert.equal(drawParams({ ...params, extra: { min: 0, max: 9, step: 1 } }, seed, 3).h, v.h);
    }
    assert.equal(seen.size, grid.length, `values drawn: ${[...seen].sort()}`);
    assert.ok(differ > 200, `steps 3 and 4 agree in ${300 - differ} of 300 seeds`);
  });

  it('references are replaced in texts and numbers, with scale and offset', () => {
    const step = {
      text: 'Pitch $h = {{h}}$, {{ n }} poses; $\\frac{{a}}{b}$ stays.',
      document: { poses: [{ origin: [0, 0, { param: 'h', scale: 2, offset: 0.5 }] }] },
      checks: [{ min: { param: 'h', offset: -0.02 }, max: { param: 'h', offset: 0.02 } }],
    };
    const out = substitute(step, { h: 0.7, n: 4, a: 1 });
    assert.equal(out.text, 'Pitch $h = 0.7$, 4 poses; $\\frac1{b}$ stays.');
    assert.ok(Math.abs(out.document.poses[0].origin[2] - 1.9) < 1e-12);
    assert.ok(Math.abs(out.checks[0].min - 0.68) < 1e-12 && Math.abs(out.checks[0].max - 0.72) < 1e-12);
    // The original is untouched.
    assert.deepEqual(step.checks[0].min, { param: 'h', offset: -0.02 });
  });
});

/** A small valid lesson: a randomised step with a one-coordinate pose check, and a multiple choice. */
function goodLesson() {
  return {
    id: 'variant-test',
    title: 'Variants',
    steps: [
      {
        title: 'Height {{z}}',
        text: 'Move pose 1 to height $z = {{z}}$.',
        params: { z: { min: 0.5, max: 2, step: 0.5 } },
        document: structuredClone(TWO_POSES),
        exercise: {
          task: 'Pose 1 at $z = {{z}}$.',
          checks: [{ kind: 'pose', pose: 1, coordinate: 'z', value: { param: 'z' }, tolerance: 0.05 }],
        },
      },
      {
        title: 'Choose',
        text: 'Which?',
        scene: 'pendulum',
        exercise: { task: 'Pick.', choices: ['a', { text: 'b', why: 'because' }], checks: [{ kind: 'choice', answer: 1 }] },
      },
    ],
  };
}

describe('the validator', () => {
  it('checks a step\'s camera field by field, all problems at once', () => {
    const l = JSON.parse(read('02-polyscrew.json'));
    l.steps[0].camera = { target: [0, 1, 2], distance: 9, yaw: -1, pitch: 0.5, ortho: true };
    assert.deepEqual(lessonProblems(l, ctx), [], 'a whole camera');
    l.steps[0].camera = { target: [0, 1], distance: 0, yaw: 'x', pitch: 2, zoom: 1 };
    assert.deepEqual(lessonProblems(l, ctx).map((p) => p.path), [
      'steps[0].camera.zoom', 'steps[0].camera.target', 'steps[0].camera.distance', 'steps[0].camera.yaw', 'steps[0].camera.pitch',
    ]);
  });

  it('lists all seven mistakes of a lesson at once, each with its step and field', () => {
    // Lesson 2's steps and the first three of lesson 5: seven steps, valid as they are.
    const l = JSON.parse(read('02-polyscrew.json'));
    l.steps.push(...JSON.parse(read('05-frames.json')).steps.slice(0, 3));
    assert.deepEqual(lessonProblems(l, ctx), [], 'the seven steps as they are');
    l.steps[0].colour = 'red';
    l.steps[1].scene = 'no_such_scene';
    l.steps[2].exercise.checks[1].max = 'small';
    l.steps[3].exercise.checks[0].kind = 'guess';
    l.steps[4].options = { levels: 20 };
    l.steps[5].highlight = { panel: 'Nope' };
    l.steps[6].text = 'unclosed $x';
    const before = JSON.stringify(l);
    const problems = lessonProblems(l, ctx);
    assert.equal(JSON.stringify(l), before, 'lessonProblems changed the lesson');
    assert.deepEqual(problems.map(({ step, field, path: p }) => ({ step, field, path: p })), [
      { step: 0, field: 'colour', path: 'steps[0].colour' },
      { step: 1, field: 'scene', path: 'steps[1].scene' },
      { step: 2, field: 'max', path: 'steps[2].exercise.checks[1].max' },
      { step: 3, field: 'kind', path: 'steps[3].exercise.checks[0].kind' },
      { step: 4, field: 'levels', path: 'steps[4].options.levels' },
      { step: 5, field: 'panel', path: 'steps[5].highlight.panel' },
      { step: 6, field: 'text', path: 'steps[6].text' },
    ]);
    assert.match(problems[2].message, /^expected a finite number$/);
    assert.match(problems[1].message, /"no_such_scene" is not one of/);
    // validateLesson still throws: the first problem, saying how many more there are.
    assert.throws(() => validateLesson(l, ctx), (e) => e instanceof LessonError && /^steps\[0\]\.colour: unknown field .* \(and 6 more problems\)$/.test(e.message) && e.problems.length === 7);
  });

  it('a JSON syntax error names its line and column', () => {
    const text = '{\n  "id": "x",\n  "title" "t"\n}';
    assert.throws(() => parseLesson(text, ctx), /not valid JSON at line 3, column 11/);
    const [p] = lessonProblems(text, ctx);
    assert.deepEqual([p.line, p.column, p.step], [3, 11, null]);
  });

  it('a randomised step is valid; its unknown or badly formed parameters are problems', () => {
    assert.deepEqual(lessonProblems(goodLesson(), ctx), []);
    const l = goodLesson();
    l.steps[0].text = 'Height {{zz}}.';
    l.steps[0].exercise.checks[0].value = { param: 'w' };
    l.steps[0].exercise.checks[0].tolerance = { param: 'z', factor: 2 };
    l.steps[1].exercise.checks.push({ kind: 'pose', pose: 0, coordinate: 'x', value: { param: 'z' } });
    const problems = lessonProblems(l, ctx).map((p) => `${p.path}: ${p.message}`);
    assert.deepEqual(problems, [
      'steps[0].exercise.checks[0].tolerance.factor: unknown field of a parameter reference (expected param, scale, offset)',
      'steps[0].text: unknown parameter "zz" (the step declares z)',
      'steps[0].exercise.checks[0].value.param: unknown parameter "w" (the step declares z)',
      'steps[1].exercise.checks[1].value.param: unknown parameter "z" (the step declares no params)',
    ]);
    const bad = goodLesson();
    bad.steps[0].params = { z: { min: 2, max: 1, step: 0.5 }, '2x': { values: [] } };
    assert.deepEqual(lessonProblems(bad, ctx).map((p) => p.path), ['steps[0].params.z.max', 'steps[0].params.2x', 'steps[0].params.2x.values']);
  });

  it('a randomised step is held to the rules in its lowest and highest variant', () => {
    const l = goodLesson();
    l.steps[0].params.lv = { min: 3, max: 25, step: 1 };
    l.steps[0].options = { levels: { param: 'lv' } };
    assert.deepEqual(lessonProblems(l, ctx).map((p) => `${p.path}: ${p.message}`), ['steps[0].options.levels: expected a whole number from 0 to 19']);
  });

  it('a pose check of one coordinate: its fields are checked, and it measures that coordinate only', () => {
    const l = goodLesson();
    l.steps[0].exercise.checks = [
      { kind: 'pose', pose: 1, coordinate: 'w', value: 1 },
      { kind: 'pose', pose: 1, coordinate: 'z' },
      { kind: 'pose', pose: 1, origin: [0, 0, 0], coordinate: 'z', value: 1 },
      { kind: 'pose', pose: 1, value: 1 },
    ];
    assert.deepEqual(lessonProblems(l, ctx).map((p) => p.path), [
      'steps[0].exercise.checks[0].coordinate', 'steps[0].exercise.checks[1].value', 'steps[0].exercise.checks[2].coordinate', 'steps[0].exercise.checks[3].value',
    ]);
    const motion = { poseCount: 2, pose: () => ({ origin: [5, -3, 2.04], rotation: [1, 0, 0, 0] }) };
    const check = { kind: 'pose', pose: 1, coordinate: 'z', value: 2, tolerance: 0.05 };
    assert.equal(evaluateCheck(check, motion, null).ok, true);
    assert.equal(evaluateCheck({ ...check, tolerance: 0.03 }, motion, null).ok, false);
    assert.equal(evaluateCheck({ ...check, coordinate: 'x' }, motion, null).ok, false);
    assert.match(evaluateCheck({ ...check, tolerance: 0.03 }, motion, null).got, /z = 2\.04/);
  });
});

describe('a lesson variant', () => {
  it("two seeds give the numbers of their draw in texts and checks; a step's choices read as before", () => {
    const lesson = parseLesson(JSON.stringify(goodLesson()), ctx);
    const grid = [0.5, 1, 1.5, 2];
    const seeds = [];
    for (let s = 1; seeds.length < 2; s++) if (!seeds.length || lessonVariant(lesson, s).values[0].z !== lessonVariant(lesson, seeds[0]).values[0].z) seeds.push(s);
    for (const seed of seeds) {
      const { lesson: v, values } = lessonVariant(lesson, seed);
      const z = values[0].z;
      assert.ok(grid.includes(z));
      assert.equal(values[1], null);
      assert.equal(v.steps[0].title, `Height ${z}`);
      assert.equal(v.steps[0].exercise.task, `Pose 1 at $z = ${z}$.`);
      assert.equal(v.steps[0].exercise.checks[0].value, z);
      assert.equal(v.steps[0].params, undefined);
      assert.deepEqual(v.steps[1].exercise.choices, ['a', 'b']);
      assert.deepEqual(v.steps[1].exercise.why, [null, 'because']);
      assert.deepEqual(lessonVariant(lesson, seed).values, values, 'the same seed again');
    }
    // The lesson as parsed keeps its parameters for the next student.
    assert.ok(lesson.steps[0].params);
  });

  it("lesson 1's randomised exercise: each seed's pitch is in its range and in its check", () => {
    const lesson = parseLesson(read('01-screw.json'), ctx);
    const k = lesson.steps.findIndex((s) => s.params);
    assert.ok(k >= 0, 'lesson 1 has a randomised step');
    for (const seed of [1, 2, 3, 99]) {
      const { lesson: v, values } = lessonVariant(lesson, seed);
      const h = values[k].h;
      const c = v.steps[k].exercise.checks[0].pitch;
      assert.ok(h >= 0.3 && h <= 1.2);
      assert.ok(Math.abs(c.min - (h - 0.02)) < 1e-12 && Math.abs(c.max - (h + 0.02)) < 1e-12, JSON.stringify(c));
      assert.ok(v.steps[k].exercise.task.includes(`$h = ${h}$`), v.steps[k].exercise.task);
      assert.ok(!JSON.stringify(v.steps[k]).includes('{{'), 'a reference was left');
    }
  });
});

describe('measured poses (samples) and the fit checks', () => {
  const spec = { motion: 'helix', count: 400, duration: 10, noise: 0.05, angleNoise: 2, outliers: 0.05, outlierSize: 1.5 };
  const clean = generateSamples({ ...spec, noise: 0, angleNoise: 0, outliers: 0 }, 1);

  it('the format names exactly the motions samples.js can sample', () => {
    assert.deepEqual(Object.keys(SAMPLE_MOTIONS), SAMPLE_MOTION_NAMES);
  });

  it('are the same for the same seed, other for another, with the asked noise and outliers', () => {
    const a = generateSamples(spec, 7);
    assert.deepEqual(generateSamples(spec, 7), a);
    assert.notDeepEqual(generateSamples(spec, 8).document.poses, a.document.poses);
    const { poses, times } = a.document;
    assert.equal(poses.length, 400);
    assert.equal(times[0], 0);
    assert.equal(times.at(-1), 10);
    assert.equal(a.outlier.filter(Boolean).length, 20);
    // The inliers' offsets from the noise-free motion: N(0, 0.05²) per coordinate.
    const d = [];
    poses.forEach((p, i) => {
      if (!a.outlier[i]) p.origin.forEach((x, k) => d.push(x - clean.document.poses[i].origin[k]));
    });
    const sd = Math.sqrt(d.reduce((s, x) => s + x * x, 0) / d.length);
    assert.ok(Math.abs(sd - 0.05) < 0.005, `deviation ${sd}`);
    // Every outlier is 1.5 ± 5 noise deviations off.
    poses.forEach((p, i) => {
      if (!a.outlier[i]) return;
      const off = Math.hypot(...p.origin.map((x, k) => x - clean.document.poses[i].origin[k]));
      assert.ok(Math.abs(off - 1.5) < 0.25, `outlier ${i} is ${off} off`);
    });
    for (const p of poses) assert.ok(Math.abs(Math.hypot(...p.rotation) - 1) < 1e-12);
  });

  it('a student gets their own noise: the variant seeds the samples by the seed and the step', () => {
    const l = JSON.parse(read('07-fitting.json'));
    validateLesson(l, ctx);
    const s = l.steps.findIndex((x) => x.samples);
    const a = lessonVariant(l, 11).lesson.steps[s];
    assert.equal(lessonVariant(l, 11).lesson.steps[s].samples.seed, a.samples.seed);
    assert.notEqual(lessonVariant(l, 12).lesson.steps[s].samples.seed, a.samples.seed);
    assert.notDeepEqual(stepSamples(a).document.poses, stepSamples(lessonVariant(l, 12).lesson.steps[s]).document.poses);
  });

  it('bad samples and fit checks name their step and field', () => {
    const l = JSON.parse(read('07-fitting.json'));
    const s = l.steps.findIndex((x) => x.samples);
    l.steps[s].samples = { motion: 'spiral', count: 10, noise: -1, outliers: 0.9, colour: 1 };
    l.steps[s].exercise.checks = [{ kind: 'controlPoses' }, { kind: 'residuals', rmsPosition: 'small' }, { kind: 'residuals', inliers: 1, maxAngle: 2 }];
    l.steps[0].exercise = { task: 'x', checks: [{ kind: 'residuals', rmsPosition: 1 }, { kind: 'controlPoses', min: 5, max: 2 }] };
    const problems = lessonProblems(l, ctx).map((p) => `${p.path}: ${p.message}`);
    assert.deepEqual(problems, [
      'steps[0].exercise.checks[0]: a residuals check needs the step to give measured poses (samples)',
      'steps[0].exercise.checks[1].max: max is smaller than min',
      `steps[${s}].samples.colour: unknown field (expected one of motion, count, duration, noise, angleNoise, outliers, outlierSize)`,
      `steps[${s}].samples.motion: "spiral" is not one of helix, wave`,
      `steps[${s}].samples.count: expected a whole number from 65 to 5000`,
      `steps[${s}].samples.noise: expected a number ≥ 0 (scene units)`,
      `steps[${s}].samples.outliers: expected a share from 0 to 0.5`,
      `steps[${s}].exercise.checks[0]: give min, max or both`,
      `steps[${s}].exercise.checks[1].rmsPosition: expected a number or {min, max}`,
      `steps[${s}].exercise.checks[2].inliers: expected true or false`,
    ]);
  });

  it('controlPoses counts the control poses; residuals says what it measured against what', () => {
    const motion = { poseCount: 14, options: () => ({ scheme: 'bspline' }), toDocument: () => ({ poses: [] }) };
    assert.deepEqual(evaluateCheck({ kind: 'controlPoses', max: 12 }, motion, null), { ok: false, got: '14 control poses', want: 'a count ≤ 12' });
    assert.equal(evaluateCheck({ kind: 'controlPoses', min: 4, max: 14 }, motion, null).ok, true);
    // A step's samples (stepSamples: with their residuals check), seed 3.
    const samples = stepSamples({ samples: { ...spec, seed: 3 } });
    let given = null;
    const analysis = { measureFit: (doc, s) => ((given = s), { rmsPosition: 0.08, maxPosition: 0.3, rmsAngle: 0.01, maxAngle: 0.05 }) };
    const r = evaluateCheck({ kind: 'residuals', inliers: true, rmsPosition: { max: 0.07 }, maxAngle: { max: 5 } }, motion, null, { samples, analysis });
    assert.equal(given.poses.length, 380);
    assert.equal(r.ok, false);
    assert.equal(r.got, 'RMS distance 0.08, largest angle 2.865° from the 380 measured poses that are no outliers');
    assert.equal(r.want, 'RMS distance ≤ 0.07, largest angle ≤ 5°');
    const other = { ...motion, options: () => ({ scheme: 'fourpoint' }) };
    assert.match(evaluateCheck({ kind: 'residuals', rmsPosition: 1 }, other, null, { samples, analysis }).got, /fourpoint scheme/);
    assert.match(evaluateCheck({ kind: 'residuals', rmsPosition: 1 }, motion, null, { samples, analysis: null }).got, /not loaded yet/);
  });
});
