// Lesson packages for an LMS without a browser: the suspend data's layout (www/js/lessons/resume.js)
// round-trips and stays within SCORM 1.2's 4,096 characters for every lesson here (all of them
// as one course, every exercise solved and every choice answered) and for the format's largest
// lesson; data of another course is refused; the package plan (www/js/lessons/package.js) refuses
// bad input with a message naming it. The packages in an LMS: tests/e2e/lesson-package.test.mjs.
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { describe, it } from 'node:test';
import { fileURLToPath } from 'node:url';
import { decodePlace, emptyPlace, encodePlace } from '../../www/js/lessons/resume.js';
import { planPackage, manifest } from '../../www/js/lessons/package.js';
import { duration2004, timespan12 } from '../../www/js/lessons/lms.js';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const LESSONS = path.join(ROOT, 'www/lessons');
const index = JSON.parse(fs.readFileSync(path.join(LESSONS, 'index.json'), 'utf8')).lessons;
const lessons = index.map((l) => JSON.parse(fs.readFileSync(path.join(LESSONS, l.file), 'utf8')));

/** A place with every exercise of `ls` solved, every choice answered (the last answer), at the last step. */
function fullPlace(ls) {
  let g = 0;
  const order = [];
  const place = {
    current: ls.length - 1,
    order,
    lessons: ls.map((l) => {
      const answers = {};
      const solved = [];
      l.steps.forEach((s, k) => {
        if (!s.exercise) return;
        solved.push(k);
        order.push(g++);
        if (s.exercise.choices) answers[k] = s.exercise.choices.length - 1;
      });
      return { step: l.steps.length - 1, solved, answers, finished: true };
    }),
  };
  order.reverse();
  return place;
}

const counts = (ls) => [ls.map((l) => l.steps.length), ls.reduce((n, l) => n + l.steps.filter((s) => s.exercise).length, 0)];

describe('suspend data', () => {
  it('round-trips every lesson here as one course and fits SCORM 1.2', () => {
    const place = fullPlace(lessons);
    const text = encodePlace(place);
    assert.ok(text.length <= 4096, `${text.length} characters`);
    assert.deepEqual(decodePlace(text, ...counts(lessons)), place);
  });

  it('fits SCORM 1.2 for the largest lesson the format allows (200 steps, each a solved choice of 40)', () => {
    const big = { steps: Array.from({ length: 200 }, () => ({ exercise: { choices: Array(40).fill('a') } })) };
    const place = fullPlace([big]);
    const text = encodePlace(place);
    assert.ok(text.length <= 4096, `${text.length} characters`);
    assert.deepEqual(decodePlace(text, ...counts([big])), place);
  });

  it('starts afresh on empty data, another layout or another course', () => {
    const [steps, total] = counts(lessons.slice(0, 2));
    const text = encodePlace(emptyPlace(2));
    assert.deepEqual(decodePlace(text, steps, total), emptyPlace(2));
    assert.equal(decodePlace('', steps, total), null);
    assert.equal(decodePlace('{"step":2}', steps, total), null);
    assert.equal(decodePlace(text, [5], 3), null, 'one lesson, not two');
    assert.equal(decodePlace('1;0;;9.....;0...', steps, total), null, 'a step past the lesson');
    assert.equal(decodePlace('1;0;zz;0...;0...', steps, total), null, 'an exercise past the course');
  });
});

describe('time spent (session_time)', () => {
  it('is written in each version\'s format', () => {
    assert.equal(timespan12(3723450), '0001:02:03.45');
    assert.equal(duration2004(3723450), 'PT1H2M3.45S');
  });
});

describe('package plan', () => {
  const list = { version: '0.1.0', template: 'index.html', groups: { page: ['js/main.js'], analysis: ['pkg-full/screwbender_bg.wasm'], bunny: ['vendor/bunny.obj'] } };
  const template = '<title>x</title><script type="module" src="js/main.js"></script>';
  const screw = { file: 'www/lessons/01-screw.json', text: fs.readFileSync(path.join(LESSONS, '01-screw.json'), 'utf8') };

  it('holds the lesson, the course, the launch page, the modules it uses and a manifest of them all', () => {
    const { files } = planPackage({ lessons: [screw], format: 'scorm12', mastery: 0.8, list, template });
    const paths = files.map((f) => f.path);
    assert.deepEqual(paths.filter((p) => !p.startsWith('js/')).sort(), ['imsmanifest.xml', 'lesson.html', 'lessons/01-screw.json', 'lessons/course.json', 'lessons/index.json', 'pkg-full/screwbender_bg.wasm']);
    const man = files.find((f) => f.path === 'imsmanifest.xml').text;
    for (const p of paths.filter((q) => q !== 'imsmanifest.xml')) assert.ok(man.includes(`<file href="${p}"/>`), p);
    assert.match(man, /<adlcp:masteryscore>80<\/adlcp:masteryscore>/);
    assert.match(files.find((f) => f.path === 'lesson.html').text, /src="js\/lessons\/launch.js"/);
  });

  it('refuses a bad format, mastery, lesson or two lessons with one id, naming it', () => {
    const plan = (o) => () => planPackage({ lessons: [screw], format: 'scorm12', list, template, ...o });
    assert.throws(plan({ format: 'scorm3' }), /format: expected one of scorm12, scorm2004/);
    assert.throws(plan({ mastery: 1.5 }), /mastery: expected a number from 0 to 1/);
    assert.throws(plan({ lessons: [{ file: 'x.json', text: '{' }] }), /x\.json: not JSON/);
    assert.throws(plan({ lessons: [{ file: 'x.json', text: '{"id":"a b","title":"t","steps":[{}]}' }] }), /x\.json: id/);
    assert.throws(plan({ lessons: [screw, { ...screw, file: 'copy.json' }] }), /copy\.json: id "screw" is already/);
    assert.throws(() => planPackage({ lessons: [screw], format: 'scorm12', list, template: '<title>x</title>' }), /index\.html no longer has exactly one/);
  });

  it('escapes the title in the manifest', () => {
    const text = manifest({ format: 'scorm2004', mastery: null, title: 'A <b> & "c"', description: 'd', version: '00000000', playground: '0', ids: ['x'], paths: [] });
    assert.match(text, /A &lt;b&gt; &amp; &quot;c&quot;/);
    assert.doesNotMatch(text, /imsss:sequencing/);
  });
});
