// The lesson file format (www/lessons/schema.json, www/lessons/README.md): validation that lists
// every problem of a lesson, each naming its step and field, the variants of randomised steps
// (variants.js), and the small text markup of the lesson texts (paragraphs, **bold**, *italic*,
// `code`, $inline$ and $$display$$ math typeset by KaTeX as MathML, which needs no inline styles
// under the page's CSP).
import katex from '../../vendor/katex.min.mjs';
import { MAX_LEVELS } from '../element/options.js';
import { drawParams, extremeParams, fnv1a, paramProblems, references, substitute } from './variants.js';

/** Fields of a step's `samples` (its measured poses: samples.js), and their defaults (null: required). */
export const SAMPLE_FIELDS = { motion: null, count: null, duration: 10, noise: 0, angleNoise: 0, outliers: 0, outlierSize: 1 };
/** The smooth motions `samples.motion` may name (samples.js SAMPLE_MOTIONS). */
export const SAMPLE_MOTION_NAMES = ['helix', 'wave'];
/** Fewest and most samples a step may ask for (more than the import dialog's 64, so it opens). */
export const MIN_SAMPLES = 65;
export const MAX_SAMPLES = 5000;
/** Largest share of outliers. */
export const MAX_OUTLIERS = 0.5;

/** Largest lesson file accepted, in bytes. */
export const MAX_LESSON_BYTES = 512 * 1024;
/** Most steps in one lesson. */
export const MAX_STEPS = 200;

/** The check kinds of an exercise (evaluated in checks.js) and the fields each accepts. */
export const CHECK_FIELDS = {
  spanScrew: ['span', 'screw', 'angle', 'slide', 'pitch'],
  pose: ['pose', 'origin', 'coordinate', 'value', 'rotation', 'tolerance', 'angleTolerance'],
  options: ['scheme', 'rules', 'levels', 's', 'j', 'closed'],
  velocityJump: ['pose', 'point', 'min', 'max'],
  metric: ['field', 'min', 'max', 'points'],
  controlPoses: ['min', 'max'],
  residuals: ['rmsPosition', 'maxPosition', 'rmsAngle', 'maxAngle', 'inliers'],
  choice: ['answer'],
};
/** The fields of a `residuals` check: the FitReport field each reads, and its unit (angles in degrees). */
export const RESIDUAL_FIELDS = {
  rmsPosition: { label: 'RMS distance', unit: '' },
  maxPosition: { label: 'largest distance', unit: '' },
  rmsAngle: { label: 'RMS angle', unit: '°' },
  maxAngle: { label: 'largest angle', unit: '°' },
};

/** The origin coordinates a `pose` check may test one at a time (`coordinate`). */
export const COORDINATES = ['x', 'y', 'z'];
/** Metrics fields a `metric` check may read (MetricsRow of Motion.motionMetrics). */
export const METRIC_FIELDS = [
  'velocity_jump', 'angular_velocity_jump', 'acceleration_jump', 'angular_acceleration_jump',
  'angular_acceleration_energy', 'interpolation_error', 'fourPointGap',
];
const SCHEMES = ['bspline', 'fourpoint', 'jarek', 'j'];

/**
 * Options (of a step or an `options` check) with the J_s parameter under its name `s`: `j`, its
 * former name, still reads for one release. Validated files never give both with different values.
 * Always a copy.
 */
export function withS(o) {
  const { j, ...rest } = o;
  return j === undefined ? rest : { ...rest, s: rest.s ?? j };
}
const RULES = ['direct', 'split'];
const SCREW_KINDS = ['identity', 'translation', 'general'];
/** Display settings a step may set (App.view keys) and their types. */
export const DISPLAY_FIELDS = {
  object: 'string', strobe: 'number', showStrobe: 'boolean', showControl: 'boolean', showTriads: 'boolean',
  showTrajectories: 'boolean', showPolyscrew: 'boolean', showPolygon: 'boolean', showGrid: 'boolean',
};
const STEP_FIELDS = ['title', 'text', 'params', 'scene', 'document', 'samples', 'options', 'display', 'timing', 'camera', 'dock', 'stepsAt', 'select', 'highlight', 'exercise'];
const HIGHLIGHT_KINDS = ['control', 'panel', 'pose', 'gizmo'];
const GIZMO_PARTS = ['axis-x', 'axis-y', 'axis-z', 'plane-x', 'plane-y', 'plane-z', 'ring-x', 'ring-y', 'ring-z', 'trackball'];

/**
 * A lesson file error: `path` names the field (e.g. `steps[2].exercise.checks[0].max`),
 * `reason` says what is wrong with it (the message is both). A JSON syntax error has the
 * `line` and `column` (1-based) where the parser stopped; the error validateLesson throws has
 * all the lesson's `problems` (see lessonProblems).
 */
export class LessonError extends Error {
  constructor(path, message) {
    super(path ? `${path}: ${message}` : message);
    this.path = path;
    this.reason = message;
    /** @type {number | null} */
    this.line = null;
    /** @type {number | null} */
    this.column = null;
    /** @type {LessonProblem[] | null} */
    this.problems = null;
  }
}

/**
 * One problem of a lesson (lessonProblems): `path` as LessonError's, `step` the step's index
 * (null outside the steps), `field` the path's last part (`max`, `checks[0]`, `text`), and
 * `message` what is wrong with it.
 * @typedef {{path: string, step: number | null, field: string, message: string}} LessonProblem
 */

/** The LessonProblem of error `e`. */
function problemOf(e) {
  const step = /^steps\[(\d+)\]/.exec(e.path);
  return { path: e.path, step: step ? Number(step[1]) : null, field: e.path.split('.').at(-1), message: e.reason };
}

const isObj = (v) => v !== null && typeof v === 'object' && !Array.isArray(v);
const isNum = (v) => typeof v === 'number' && Number.isFinite(v);
const fail = (path, message) => {
  throw new LessonError(path, message);
};
/**
 * Runs `f`; a LessonError it throws is added to the problems `P` instead, so one check that
 * fails does not hide the next one. Each call covers one field: a field has one problem at most.
 */
function guard(P, f) {
  try {
    f();
  } catch (e) {
    if (!(e instanceof LessonError)) throw e;
    P.push(e);
  }
}
const str = (v, path, { empty = false } = {}) => {
  if (typeof v !== 'string' || (!empty && v.trim() === '')) fail(path, 'expected a non-empty string');
};
const num = (v, path) => {
  if (!isNum(v)) fail(path, 'expected a finite number');
};
const oneOf = (v, list, path) => {
  if (!list.includes(v)) fail(path, `${JSON.stringify(v)} is not one of ${list.join(', ')}`);
};
/** Adds a problem to `P` for every field of `o` not among `keys`. */
const onlyKeys = (o, keys, path, P) => {
  for (const k of Object.keys(o)) if (!keys.includes(k)) P.push(new LessonError(path ? `${path}.${k}` : k, `unknown field (expected one of ${keys.join(', ')})`));
};
const vec = (v, n, path) => {
  if (!Array.isArray(v) || v.length !== n || !v.every(isNum)) fail(path, `expected ${n} finite numbers`);
};
/** A bound: a number, or {min?, max?} with min <= max. */
const range = (v, path) => {
  if (isNum(v)) return;
  if (!isObj(v)) fail(path, 'expected a number or {min, max}');
  const P = [];
  onlyKeys(v, ['min', 'max'], path, P);
  if (P.length) throw P[0];
  if (v.min === undefined && v.max === undefined) fail(path, 'give min, max or both');
  if (v.min !== undefined) num(v.min, `${path}.min`);
  if (v.max !== undefined) num(v.max, `${path}.max`);
  if (v.min !== undefined && v.max !== undefined && v.min > v.max) fail(path, 'min is larger than max');
};
const index = (v, path) => {
  if (!Number.isInteger(v) || v < 0) fail(path, 'expected a whole number >= 0');
};

/**
 * The lesson of `text` (JSON) before validation; throws a LessonError when it is too long or not
 * JSON (with the line and column of a syntax error).
 */
function readJson(text) {
  if (typeof text !== 'string') fail('', 'a lesson file is text (JSON)');
  if (text.length > MAX_LESSON_BYTES) fail('', `the file is ${text.length} bytes; a lesson may have at most ${MAX_LESSON_BYTES}`);
  try {
    return JSON.parse(text);
  } catch (e) {
    // Engines name the place as a character offset ("at position 80"), some also as a line and
    // column: a teacher's editor shows lines, so the offset is turned into them.
    const at = /position (\d+)/.exec(e.message);
    const pos = at ? Number(at[1]) : null;
    const before = pos === null ? null : text.slice(0, pos).split('\n');
    const line = before ? before.length : null;
    const column = before ? before.at(-1).length + 1 : null;
    const why = e.message.replace(/\s*\(line \d+ column \d+\)/, '').replace(/ in JSON at position \d+/, '').replace(/^JSON\.parse: /, '');
    const err = new LessonError('', line ? `not valid JSON at line ${line}, column ${column} (${why})` : `not valid JSON (${why})`);
    Object.assign(err, { line, column });
    throw err;
  }
}

/**
 * Parses and validates a lesson file. `text` is the file's text, `ctx` what the page offers:
 * {scenes: ids, views: ids, panel: controller names, checkMotion(doc, path)}. Returns the lesson;
 * throws a LessonError naming the step and field of the first problem (and how many more there
 * are). Every text is typeset here once, so a KaTeX error is a load error too. The steps with
 * parameters stay as written: lessonVariant gives a student's variant of the lesson.
 */
export function parseLesson(text, ctx) {
  const lesson = readJson(text);
  validateLesson(lesson, ctx);
  return lesson;
}

/**
 * Validates a parsed lesson object (see parseLesson): throws the first problem, its message
 * saying how many more there are, with all of them in the error's `problems`. Normalises the
 * exercises' choices in place (exercise.choices the texts, exercise.why the explanations).
 */
export function validateLesson(lesson, ctx) {
  const P = [];
  checkLesson(lesson, ctx, P);
  if (!P.length) return;
  const more = P.length - 1;
  const err = new LessonError(P[0].path, more ? `${P[0].reason} (and ${more} more problem${more > 1 ? 's' : ''})` : P[0].reason);
  err.problems = P.map(problemOf);
  throw err;
}

/**
 * Every problem of a lesson at once (an empty list when there is none): `lesson` is the parsed
 * object or the file's text (a syntax error is then the one problem, with its `line` and
 * `column`). The lesson given is not changed. See LessonProblem.
 * @returns {LessonProblem[]}
 */
export function lessonProblems(lesson, ctx) {
  let obj = lesson;
  if (typeof lesson === 'string') {
    try {
      obj = readJson(lesson);
    } catch (e) {
      if (!(e instanceof LessonError)) throw e;
      return [{ ...problemOf(e), ...(e.line ? { line: e.line, column: e.column } : {}) }];
    }
  } else {
    obj = structuredClone(lesson);
  }
  const P = [];
  checkLesson(obj, ctx, P);
  return P.map(problemOf);
}

function checkLesson(lesson, ctx, P) {
  if (!isObj(lesson)) return P.push(new LessonError('', 'a lesson is a JSON object'));
  onlyKeys(lesson, ['$schema', 'id', 'title', 'summary', 'tour', 'steps'], '', P);
  guard(P, () => {
    str(lesson.id, 'id');
    if (!/^[A-Za-z0-9_-]{1,64}$/.test(lesson.id)) fail('id', 'use 1-64 letters, digits, - or _');
  });
  guard(P, () => str(lesson.title, 'title'));
  if (lesson.summary !== undefined) guard(P, () => str(lesson.summary, 'summary'));
  if (lesson.tour !== undefined && typeof lesson.tour !== 'boolean') P.push(new LessonError('tour', 'expected true or false'));
  if (!Array.isArray(lesson.steps) || lesson.steps.length === 0) return P.push(new LessonError('steps', 'expected a non-empty list of steps'));
  if (lesson.steps.length > MAX_STEPS) return P.push(new LessonError('steps', `at most ${MAX_STEPS} steps`));
  lesson.steps.forEach((s, i) => checkStep(s, `steps[${i}]`, ctx, P));
}

/**
 * A step's problems. A step with `params` is checked in its lowest and its highest variant (its
 * references replaced), which holds it to the same rules as a step written with numbers; its
 * parameters and references are checked as written.
 */
function checkStep(s, p, ctx, P) {
  if (!isObj(s)) return P.push(new LessonError(p, 'a step is a JSON object'));
  const { params, ...body } = s;
  const refs = references(body, p);
  const known = new Set(params !== undefined && isObj(params) ? Object.keys(params) : []);
  for (const r of refs.problems) P.push(new LessonError(r.path, r.message));
  for (const r of refs.names) {
    // `{{…}}` in a step without parameters is left alone: in TeX it is a group.
    if (r.text && params === undefined) continue;
    if (!known.has(r.name)) P.push(new LessonError(r.path, `unknown parameter ${JSON.stringify(r.name)} (${known.size ? `the step declares ${[...known].join(', ')}` : 'the step declares no params'})`));
  }
  // Without params, a reference is a problem already: its place is checked as a number.
  if (params === undefined) return checkStepBody(refs.names.some((r) => !r.text) ? substitute(s, {}) : s, p, ctx, P);
  const defs = paramProblems(params, `${p}.params`);
  for (const d of defs) P.push(new LessonError(d.path, d.message));
  const variants = defs.length ? [{}] : extremeParams(params);
  const seen = new Set(P.map((e) => e.message));
  for (const values of variants) {
    const Q = [];
    checkStepBody(substitute(body, values), p, ctx, Q);
    for (const e of Q) {
      if (seen.has(e.message)) continue;
      seen.add(e.message);
      P.push(e);
    }
  }
}

function checkStepBody(s, p, ctx, P) {
  onlyKeys(s, STEP_FIELDS, p, P);
  guard(P, () => {
    str(s.title, `${p}.title`);
  });
  guard(P, () => {
    str(s.text, `${p}.text`);
    typeset(s.text, `${p}.text`);
  });
  guard(P, () => {
    if (s.scene !== undefined && s.document !== undefined) fail(`${p}.document`, 'give either scene or document, not both');
    if (s.scene !== undefined) oneOf(s.scene, ctx.scenes, `${p}.scene`);
    if (s.document !== undefined) {
      if (!isObj(s.document)) fail(`${p}.document`, 'expected a motion document object');
      try {
        ctx.checkMotion(s.document);
      } catch (e) {
        fail(`${p}.document`, e.message);
      }
    }
  });
  if (s.options !== undefined) guard(P, () => validateOptions(s.options, `${p}.options`, false, P));
  if (s.display !== undefined) guard(P, () => validateDisplay(s.display, `${p}.display`, P));
  if (s.timing !== undefined) guard(P, () => validateTiming(s.timing, `${p}.timing`, P));
  if (s.camera !== undefined) guard(P, () => validateCamera(s.camera, `${p}.camera`, P));
  guard(P, () => {
    if (s.dock !== undefined && s.dock !== '') oneOf(s.dock, ctx.views, `${p}.dock`);
  });
  if (s.stepsAt !== undefined) {
    guard(P, () => {
      index(s.stepsAt, `${p}.stepsAt`);
      if (s.stepsAt > 9) fail(`${p}.stepsAt`, 'the Split & tweak view has steps 0 to 9 (five levels)');
      if (s.dock !== 'steps') fail(`${p}.stepsAt`, 'needs "dock": "steps" in the same step');
    });
  }
  if (s.select !== undefined && s.select !== -1) guard(P, () => index(s.select, `${p}.select`));
  if (s.highlight !== undefined) guard(P, () => validateHighlight(s.highlight, `${p}.highlight`, ctx));
  if (s.samples !== undefined) guard(P, () => validateSamples(s.samples, `${p}.samples`, P));
  if (s.exercise !== undefined) validateExercise(s.exercise, `${p}.exercise`, P, s.samples !== undefined);
}

/** A step's measured poses (samples.js): a motion, a count, noise and outliers. */
function validateSamples(o, p, P) {
  if (!isObj(o)) fail(p, 'expected {motion, count, noise?, angleNoise?, outliers?, outlierSize?, duration?}');
  onlyKeys(o, Object.keys(SAMPLE_FIELDS), p, P);
  guard(P, () => oneOf(o.motion, SAMPLE_MOTION_NAMES, `${p}.motion`));
  guard(P, () => {
    if (!(Number.isInteger(o.count) && o.count >= MIN_SAMPLES && o.count <= MAX_SAMPLES)) fail(`${p}.count`, `expected a whole number from ${MIN_SAMPLES} to ${MAX_SAMPLES}`);
  });
  const at = (f, ok, what) => {
    if (o[f] !== undefined && !(isNum(o[f]) && ok(o[f]))) P.push(new LessonError(`${p}.${f}`, what));
  };
  at('duration', (x) => x > 0, 'expected a number > 0 (seconds)');
  at('noise', (x) => x >= 0, 'expected a number ≥ 0 (scene units)');
  at('angleNoise', (x) => x >= 0 && x <= 90, 'expected a number from 0 to 90 (degrees)');
  at('outliers', (x) => x >= 0 && x <= MAX_OUTLIERS, `expected a share from 0 to ${MAX_OUTLIERS}`);
  at('outlierSize', (x) => x >= 0, 'expected a number ≥ 0 (scene units)');
}

/** A step's camera, as the page's session keeps it (figure/camera.js OrbitCamera.toJSON). */
function validateCamera(c, p, P) {
  if (!isObj(c)) fail(p, 'expected {target, distance, yaw, pitch, ortho?}');
  onlyKeys(c, ['target', 'distance', 'yaw', 'pitch', 'ortho'], p, P);
  guard(P, () => vec(c.target, 3, `${p}.target`));
  guard(P, () => {
    num(c.distance, `${p}.distance`);
    if (c.distance <= 0) fail(`${p}.distance`, 'expected a distance > 0');
  });
  guard(P, () => num(c.yaw, `${p}.yaw`));
  guard(P, () => {
    num(c.pitch, `${p}.pitch`);
    if (Math.abs(c.pitch) > Math.PI / 2) fail(`${p}.pitch`, 'expected a pitch from -π/2 to π/2 (radians)');
  });
  if (c.ortho !== undefined && typeof c.ortho !== 'boolean') fail(`${p}.ortho`, 'expected true or false');
}

function validateDisplay(d, p, P) {
  if (!isObj(d)) fail(p, 'expected an object');
  onlyKeys(d, Object.keys(DISPLAY_FIELDS), p, P);
  for (const [k, v] of Object.entries(d)) {
    if (Object.hasOwn(DISPLAY_FIELDS, k) && typeof v !== DISPLAY_FIELDS[k]) P.push(new LessonError(`${p}.${k}`, `expected a ${DISPLAY_FIELDS[k]}`));
  }
  if (typeof d.strobe === 'number' && !(Number.isInteger(d.strobe) && d.strobe >= 1 && d.strobe <= 10000)) {
    fail(`${p}.strobe`, 'expected a whole number from 1 to 10000');
  }
}

function validateTiming(t, p, P) {
  if (!isObj(t)) fail(p, 'expected an object');
  onlyKeys(t, ['times', 'speed', 'play', 'u'], p, P);
  if (t.times !== undefined && t.times !== null) {
    guard(P, () => {
      if (!Array.isArray(t.times) || t.times.length < 2 || !t.times.every(isNum)) fail(`${p}.times`, 'expected a list of at least 2 numbers, or null');
      for (let k = 1; k < t.times.length; k++) if (!(t.times[k] > t.times[k - 1])) fail(`${p}.times[${k}]`, 'times must increase');
    });
  }
  if (t.speed !== undefined && !(isNum(t.speed) && t.speed >= 0.1 && t.speed <= 4)) P.push(new LessonError(`${p}.speed`, 'expected a number from 0.1 to 4'));
  if (t.play !== undefined && typeof t.play !== 'boolean') P.push(new LessonError(`${p}.play`, 'expected true or false'));
  if (t.u !== undefined) guard(P, () => num(t.u, `${p}.u`));
}

function validateOptions(o, p, isCheck, P) {
  if (!isObj(o)) fail(p, 'expected an object');
  onlyKeys(o, isCheck ? ['kind', ...CHECK_FIELDS.options] : ['scheme', 'rules', 'levels', 's', 'j', 'closed'], p, P);
  if (o.s !== undefined && o.j !== undefined && JSON.stringify(o.s) !== JSON.stringify(o.j)) {
    P.push(new LessonError(`${p}.s`, `s and j disagree (j is the former name of s; give s only)`));
  }
  if (o.scheme !== undefined) guard(P, () => oneOf(o.scheme, SCHEMES, `${p}.scheme`));
  if (o.rules !== undefined) guard(P, () => oneOf(o.rules, RULES, `${p}.rules`));
  if (o.closed !== undefined && typeof o.closed !== 'boolean') P.push(new LessonError(`${p}.closed`, 'expected true or false'));
  if (isCheck) {
    if (o.levels !== undefined) guard(P, () => range(o.levels, `${p}.levels`));
    for (const f of ['s', 'j']) if (o[f] !== undefined) guard(P, () => range(o[f], `${p}.${f}`));
  } else {
    if (o.levels !== undefined && !(Number.isInteger(o.levels) && o.levels >= 0 && o.levels <= MAX_LEVELS)) P.push(new LessonError(`${p}.levels`, `expected a whole number from 0 to ${MAX_LEVELS}`));
    for (const f of ['s', 'j']) if (o[f] !== undefined && !(isNum(o[f]) && Math.abs(o[f]) <= 4)) P.push(new LessonError(`${p}.${f}`, 'expected a number from -4 to 4'));
  }
}

function validateHighlight(h, p, ctx) {
  if (!isObj(h)) fail(p, 'expected an object with one of control, panel, pose, gizmo');
  const Q = [];
  onlyKeys(h, HIGHLIGHT_KINDS, p, Q);
  if (Q.length) throw Q[0];
  const kinds = Object.keys(h);
  if (kinds.length !== 1) fail(p, 'give exactly one of control, panel, pose, gizmo');
  if (h.control !== undefined) {
    str(h.control, `${p}.control`);
    if (!/^#[A-Za-z][\w-]*$/.test(h.control)) fail(`${p}.control`, 'expected an element id such as "#play"');
  }
  if (h.panel !== undefined) oneOf(h.panel, ctx.panel, `${p}.panel`);
  if (h.pose !== undefined) index(h.pose, `${p}.pose`);
  if (h.gizmo !== undefined) oneOf(h.gizmo, GIZMO_PARTS, `${p}.gizmo`);
}

/** A text field `f` of `o` (when present, or when `required`): a string whose math typesets. */
function text(o, f, p, P, required = false) {
  if (o[f] === undefined && !required) return;
  guard(P, () => {
    str(o[f], p);
    typeset(o[f], p);
  });
}

function validateExercise(x, p, P, hasSamples = false) {
  if (!isObj(x)) return P.push(new LessonError(p, 'expected an object'));
  onlyKeys(x, ['task', 'choices', 'checks', 'hints', 'success'], p, P);
  text(x, 'task', `${p}.task`, P, true);
  let choices = null;
  if (x.choices !== undefined) {
    if (!Array.isArray(x.choices) || x.choices.length < 2) P.push(new LessonError(`${p}.choices`, 'expected a list of at least 2 answers'));
    else {
      // An answer is its text, or {text, why}: `why` says why it is wrong (or right), shown when
      // it is checked.
      x.choices.forEach((c, k) => {
        if (isObj(c)) {
          onlyKeys(c, ['text', 'why'], `${p}.choices[${k}]`, P);
          text(c, 'text', `${p}.choices[${k}].text`, P, true);
          text(c, 'why', `${p}.choices[${k}].why`, P);
        } else {
          text(x.choices, k, `${p}.choices[${k}]`, P, true);
        }
      });
      choices = x.choices.length;
    }
  }
  if (!Array.isArray(x.checks) || x.checks.length === 0) P.push(new LessonError(`${p}.checks`, 'expected a non-empty list of checks'));
  else x.checks.forEach((c, k) => guard(P, () => validateCheck(c, `${p}.checks[${k}]`, x, choices, P, hasSamples)));
  if (x.hints !== undefined) {
    if (!Array.isArray(x.hints)) P.push(new LessonError(`${p}.hints`, 'expected a list of texts'));
    else x.hints.forEach((h, k) => text(x.hints, k, `${p}.hints[${k}]`, P, true));
  }
  text(x, 'success', `${p}.success`, P);
  normaliseChoices(x);
}

/**
 * Parses a validated exercise's choices into x.choices (the texts) and x.why (the explanations,
 * null where none is given). Only once per exercise object.
 */
function normaliseChoices(x) {
  if (!Array.isArray(x.choices) || x.why) return;
  x.why = x.choices.map((c) => (isObj(c) ? (c.why ?? null) : null));
  x.choices = x.choices.map((c) => (isObj(c) ? c.text : c));
}

function validateCheck(c, p, x, choices, P, hasSamples) {
  if (!isObj(c)) fail(p, 'expected a check object');
  if (!Object.hasOwn(CHECK_FIELDS, c.kind)) fail(`${p}.kind`, `${JSON.stringify(c.kind)} is not one of ${Object.keys(CHECK_FIELDS).join(', ')}`);
  if (c.kind === 'options') return validateOptions(c, p, true, P);
  onlyKeys(c, ['kind', ...CHECK_FIELDS[c.kind]], p, P);
  switch (c.kind) {
    case 'spanScrew':
      index(c.span, `${p}.span`);
      if (c.screw !== undefined) oneOf(c.screw, SCREW_KINDS, `${p}.screw`);
      for (const f of ['angle', 'slide', 'pitch']) if (c[f] !== undefined) range(c[f], `${p}.${f}`);
      break;
    case 'pose':
      index(c.pose, `${p}.pose`);
      if (c.value !== undefined && c.coordinate === undefined) fail(`${p}.value`, 'a value needs a coordinate (x, y or z)');
      if (c.origin === undefined && c.coordinate === undefined && c.rotation === undefined) fail(p, 'give origin, or a coordinate and its value, or rotation (or a rotation with either)');
      if (c.origin !== undefined && c.coordinate !== undefined) fail(`${p}.coordinate`, 'give either origin or one coordinate, not both');
      if (c.origin !== undefined) vec(c.origin, 3, `${p}.origin`);
      if (c.coordinate !== undefined) {
        oneOf(c.coordinate, COORDINATES, `${p}.coordinate`);
        if (c.value === undefined) fail(`${p}.value`, `give the value of ${c.coordinate} to reach`);
      }
      if (c.value !== undefined) num(c.value, `${p}.value`);
      if (c.rotation !== undefined) vec(c.rotation, 4, `${p}.rotation`);
      if (c.tolerance !== undefined && !(isNum(c.tolerance) && c.tolerance > 0)) fail(`${p}.tolerance`, 'expected a positive number');
      if (c.angleTolerance !== undefined && !(isNum(c.angleTolerance) && c.angleTolerance > 0)) fail(`${p}.angleTolerance`, 'expected a positive number (degrees)');
      break;
    case 'velocityJump':
      index(c.pose, `${p}.pose`);
      if (c.point !== undefined) vec(c.point, 3, `${p}.point`);
      if (c.min === undefined && c.max === undefined) fail(p, 'give min, max or both');
      if (c.min !== undefined) num(c.min, `${p}.min`);
      if (c.max !== undefined) num(c.max, `${p}.max`);
      break;
    case 'metric':
      oneOf(c.field, METRIC_FIELDS, `${p}.field`);
      if (c.points !== undefined) {
        if (!Array.isArray(c.points) || c.points.length === 0) fail(`${p}.points`, 'expected a list of body points');
        c.points.forEach((q, k) => vec(q, 3, `${p}.points[${k}]`));
      }
      if (c.min === undefined && c.max === undefined) fail(p, 'give min, max or both');
      if (c.min !== undefined) num(c.min, `${p}.min`);
      if (c.max !== undefined) num(c.max, `${p}.max`);
      break;
    case 'controlPoses':
      if (c.min === undefined && c.max === undefined) fail(p, 'give min, max or both');
      for (const f of ['min', 'max']) if (c[f] !== undefined && !(Number.isInteger(c[f]) && c[f] >= 0)) fail(`${p}.${f}`, 'expected a whole number ≥ 0');
      if (c.min !== undefined && c.max !== undefined && c.min > c.max) fail(`${p}.max`, 'max is smaller than min');
      break;
    case 'residuals': {
      if (!hasSamples) fail(p, 'a residuals check needs the step to give measured poses (samples)');
      const given = Object.keys(RESIDUAL_FIELDS).filter((f) => c[f] !== undefined);
      if (given.length === 0) fail(p, `give at least one of ${Object.keys(RESIDUAL_FIELDS).join(', ')}`);
      for (const f of given) range(c[f], `${p}.${f}`);
      if (c.inliers !== undefined && typeof c.inliers !== 'boolean') fail(`${p}.inliers`, 'expected true or false');
      break;
    }
    case 'choice':
      if (!Array.isArray(x.choices)) fail(p, 'a choice check needs the exercise to list choices');
      index(c.answer, `${p}.answer`);
      if (choices !== null && c.answer >= choices) fail(`${p}.answer`, `there are only ${choices} choices`);
      break;
    default:
      break;
  }
}

// ---------------------------------------------------------------- variants

/**
 * Student `seed`'s variant of a validated lesson (parseLesson): every step with `params` gets
 * its values (variants.js drawParams) written into its texts and numbers. Returns {lesson, values}:
 * `lesson` a copy whose steps are as if written with numbers, `values[i]` the values of step i
 * ({name: value}; null for a step without parameters). A lesson without parameters is returned
 * as it is.
 */
export function lessonVariant(lesson, seed) {
  if (!hasParams(lesson)) return { lesson, values: lesson.steps.map(() => null) };
  const values = [];
  const steps = lesson.steps.map((s, i) => {
    // Measured poses are the student's own: their noise is drawn from the seed and the step.
    const own = (step) => (step.samples ? { ...step, samples: { ...step.samples, seed: fnv1a(`${seed >>> 0}:${i}:samples`) } } : step);
    if (!s.params) {
      values.push(null);
      return own(s);
    }
    const v = drawParams(s.params, seed, i);
    values.push(v);
    const step = own(substitute(s, v));
    delete step.params;
    if (step.exercise) normaliseChoices(step.exercise);
    return step;
  });
  return { lesson: { ...lesson, steps }, values };
}

/**
 * Whether a step of `lesson` declares parameters or gives measured poses (so its students get
 * variants: their own numbers, their own noise).
 */
export function hasParams(lesson) {
  return lesson.steps.some((s) => s.params !== undefined || s.samples !== undefined);
}

// ---------------------------------------------------------------- text

/**
 * Renders `tex` with KaTeX as MathML (no inline styles) into a new element; throws the KaTeX
 * parse error.
 */
function renderMath(tex, display) {
  const el = document.createElement(display ? 'div' : 'span');
  el.className = display ? 'math display' : 'math';
  katex.render(tex, el, { output: 'mathml', displayMode: display, throwOnError: true, trust: false, strict: 'ignore' });
  return el;
}

/** Splits a text into tokens: {math, display} or {text}. Throws on an unclosed `$`. */
function tokens(text, path) {
  const out = [];
  let i = 0;
  while (i < text.length) {
    const k = text.indexOf('$', i);
    if (k < 0) {
      out.push({ text: text.slice(i) });
      break;
    }
    if (k > 0 && text[k - 1] === '\\') {
      out.push({ text: text.slice(i, k - 1) + '$' });
      i = k + 1;
      continue;
    }
    if (k > i) out.push({ text: text.slice(i, k) });
    const display = text[k + 1] === '$';
    const close = text.indexOf(display ? '$$' : '$', k + (display ? 2 : 1));
    if (close < 0) fail(path, `unclosed ${display ? '$$' : '$'} at character ${k}`);
    out.push({ math: text.slice(k + (display ? 2 : 1), close), display });
    i = close + (display ? 2 : 1);
  }
  return out;
}

/**
 * Checks that every formula of `text` is closed and typesets (a KaTeX error names the field;
 * without a DOM, as in Node, only the closing `$` are checked).
 */
function typeset(text, path) {
  const parts = tokens(text, path);
  if (typeof document === 'undefined') return;
  for (const t of parts) {
    if (t.math === undefined) continue;
    try {
      renderMath(t.math, t.display);
    } catch (e) {
      fail(path, `math "${t.math}": ${e.message}`);
    }
  }
}

/** Appends plain text with **bold**, *italic* and `code` to `el` (as text nodes: no HTML). */
function inline(el, text) {
  const re = /\*\*([^*]+)\*\*|\*([^*]+)\*|`([^`]+)`/g;
  let last = 0;
  for (let m; (m = re.exec(text)); ) {
    if (m.index > last) el.append(text.slice(last, m.index));
    const tag = m[1] !== undefined ? 'b' : m[2] !== undefined ? 'i' : 'code';
    const e = document.createElement(tag);
    e.textContent = m[1] ?? m[2] ?? m[3];
    el.append(e);
    last = re.lastIndex;
  }
  if (last < text.length) el.append(text.slice(last));
}

/**
 * The DOM of a lesson text: paragraphs split at blank lines, each with inline markup and math;
 * display math ($$…$$) as its own block. Returns a DocumentFragment.
 */
export function renderText(text) {
  const frag = document.createDocumentFragment();
  for (const para of text.split(/\n\s*\n/)) {
    let p = document.createElement('p');
    for (const t of tokens(para.trim(), '')) {
      if (t.math === undefined) inline(p, t.text);
      else if (!t.display) p.append(renderMath(t.math, false));
      else {
        if (p.childNodes.length) frag.append(p);
        frag.append(renderMath(t.math, true));
        p = document.createElement('p');
      }
    }
    if (p.childNodes.length) frag.append(p);
  }
  return frag;
}
