// A course's place, written compactly into one string: what an LMS keeps between launches in
// `suspend_data` (SCORM 1.2 allows 4,096 characters, SCORM 2004 64,000). Written by hand: the
// state is a few small integers and sets, so a fixed layout in base 36 is several times shorter
// than JSON and needs no library.
//
// Layout (version 1), fields separated by `;`:
//   1;<lesson open>;<interaction order>;<lesson 0>;<lesson 1>;…
// * lesson open: index into the course's lessons of the one shown last (base 36).
// * interaction order: the course-wide exercise numbers in the order their interaction records
//   were first written, `.`-separated (base 36), so a record keeps its index across launches.
// * a lesson: `<step>.<finished>.<solved>.<answers>`: the step shown last (base 36); `1` once
//   the lesson's Finish was reached, else empty; the solved steps as a bit set (bit i: step i,
//   base 32); the chosen answers as `step:answer` pairs joined by `,` (base 36).
// A 200-step lesson (the format's largest) with every step a solved multiple choice takes
// under 1,800 characters (tests/js/lesson-package.test.mjs); the six lessons of www/lessons as
// one course, all solved, under 100.
//
// Variants of randomised steps need no room here: their seed is derived from the learner's id
// (lms.js, variantSeed), which the LMS gives again at every launch.

/** Version tag of the layout above. */
const VERSION = '1';

/**
 * The state of one lesson as the player keeps it (progress.js): {step, solved: [step…],
 * answers: {step: choice}} and whether its Finish was reached.
 * @typedef {{step: number, solved: number[], answers: Record<string, number>, finished: boolean}} LessonPlace
 */

/**
 * A course's place: the lesson shown last, the order of the interaction records (course-wide
 * exercise numbers) and each lesson's place.
 * @typedef {{current: number, order: number[], lessons: LessonPlace[]}} CoursePlace
 */

/** An empty place of a course of `n` lessons. */
export function emptyPlace(n) {
  return { current: 0, order: [], lessons: Array.from({ length: n }, () => ({ step: 0, solved: [], answers: {}, finished: false })) };
}

/** Encodes `place` (see CoursePlace) as suspend data. */
export function encodePlace(place) {
  const lessons = place.lessons.map((l) => {
    let bits = 0n;
    for (const s of l.solved) bits |= 1n << BigInt(s);
    const answers = Object.entries(l.answers)
      .filter(([, a]) => Number.isInteger(a) && a >= 0)
      .map(([s, a]) => `${Number(s).toString(36)}:${a.toString(36)}`)
      .join(',');
    return `${l.step.toString(36)}.${l.finished ? '1' : ''}.${bits ? bits.toString(32) : ''}.${answers}`;
  });
  return [VERSION, place.current.toString(36), place.order.map((g) => g.toString(36)).join('.'), ...lessons].join(';');
}

const B36 = /^[0-9a-z]+$/;
const int36 = (s) => (B36.test(s) ? parseInt(s, 36) : NaN);

/**
 * Decodes suspend data `text` for a course whose lessons have `stepCounts[k]` steps and
 * `exercises` exercises in all. Returns the CoursePlace, or null when `text` is empty, of another
 * layout, or does not fit the course (another package's data): the course then starts afresh.
 */
export function decodePlace(text, stepCounts, exercises) {
  if (typeof text !== 'string' || text === '') return null;
  const parts = text.split(';');
  if (parts[0] !== VERSION || parts.length !== 3 + stepCounts.length) return null;
  const current = int36(parts[1]);
  if (!(current >= 0 && current < stepCounts.length)) return null;
  const order = parts[2] === '' ? [] : parts[2].split('.').map(int36);
  if (!order.every((g) => g >= 0 && g < exercises) || new Set(order).size !== order.length) return null;
  const lessons = [];
  for (let k = 0; k < stepCounts.length; k++) {
    const f = parts[3 + k].split('.');
    if (f.length !== 4) return null;
    const step = int36(f[0]);
    if (!(step >= 0 && step < stepCounts[k]) || (f[1] !== '' && f[1] !== '1')) return null;
    const solved = [];
    if (f[2] !== '') {
      if (!/^[0-9a-v]+$/.test(f[2])) return null;
      const digits = [...f[2]].map((c) => BigInt(parseInt(c, 32)));
      const bits = digits.reduce((acc, d) => acc * 32n + d, 0n);
      for (let s = 0; s < stepCounts[k]; s++) if ((bits >> BigInt(s)) & 1n) solved.push(s);
      if (bits >> BigInt(stepCounts[k])) return null;
    }
    const answers = {};
    if (f[3] !== '') {
      for (const pair of f[3].split(',')) {
        const [s, a] = pair.split(':').map(int36);
        if (!(s >= 0 && s < stepCounts[k] && a >= 0)) return null;
        answers[s] = a;
      }
    }
    lessons.push({ step, solved, answers, finished: f[1] === '1' });
  }
  return { current, order, lessons };
}
