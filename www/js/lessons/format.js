// The lesson file format (www/lessons/schema.json, www/lessons/README.md): validation with
// messages that name the step and the field, and the small text markup of the lesson texts
// (paragraphs, **bold**, *italic*, `code`, $inline$ and $$display$$ math typeset by KaTeX as
// MathML, which needs no inline styles under the page's CSP).
import katex from '../../vendor/katex.min.mjs';
import { MAX_LEVELS } from '../element/options.js';

/** Largest lesson file accepted, in bytes. */
export const MAX_LESSON_BYTES = 512 * 1024;
/** Most steps in one lesson. */
export const MAX_STEPS = 200;

/** The check kinds of an exercise (evaluated in checks.js) and the fields each accepts. */
export const CHECK_FIELDS = {
  spanScrew: ['span', 'screw', 'angle', 'slide', 'pitch'],
  pose: ['pose', 'origin', 'rotation', 'tolerance', 'angleTolerance'],
  options: ['scheme', 'rules', 'levels', 's', 'j', 'closed'],
  velocityJump: ['pose', 'point', 'min', 'max'],
  metric: ['field', 'min', 'max', 'points'],
  choice: ['answer'],
};
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
const STEP_FIELDS = ['title', 'text', 'scene', 'document', 'options', 'display', 'timing', 'dock', 'stepsAt', 'select', 'highlight', 'exercise'];
const HIGHLIGHT_KINDS = ['control', 'panel', 'pose', 'gizmo'];
const GIZMO_PARTS = ['axis-x', 'axis-y', 'axis-z', 'plane-x', 'plane-y', 'plane-z', 'ring-x', 'ring-y', 'ring-z', 'trackball'];

/** A lesson file error: `path` names the field (e.g. `steps[2].exercise.checks[0].max`). */
export class LessonError extends Error {
  constructor(path, message) {
    super(path ? `${path}: ${message}` : message);
    this.path = path;
  }
}

const isObj = (v) => v !== null && typeof v === 'object' && !Array.isArray(v);
const isNum = (v) => typeof v === 'number' && Number.isFinite(v);
const fail = (path, message) => {
  throw new LessonError(path, message);
};
const str = (v, path, { empty = false } = {}) => {
  if (typeof v !== 'string' || (!empty && v.trim() === '')) fail(path, 'expected a non-empty string');
};
const num = (v, path) => {
  if (!isNum(v)) fail(path, 'expected a finite number');
};
const oneOf = (v, list, path) => {
  if (!list.includes(v)) fail(path, `${JSON.stringify(v)} is not one of ${list.join(', ')}`);
};
const onlyKeys = (o, keys, path) => {
  for (const k of Object.keys(o)) if (!keys.includes(k)) fail(`${path}.${k}`, `unknown field (expected one of ${keys.join(', ')})`);
};
const vec = (v, n, path) => {
  if (!Array.isArray(v) || v.length !== n || !v.every(isNum)) fail(path, `expected ${n} finite numbers`);
};
/** A bound: a number, or {min?, max?} with min <= max. */
const range = (v, path) => {
  if (isNum(v)) return;
  if (!isObj(v)) fail(path, 'expected a number or {min, max}');
  onlyKeys(v, ['min', 'max'], path);
  if (v.min === undefined && v.max === undefined) fail(path, 'give min, max or both');
  if (v.min !== undefined) num(v.min, `${path}.min`);
  if (v.max !== undefined) num(v.max, `${path}.max`);
  if (v.min !== undefined && v.max !== undefined && v.min > v.max) fail(path, 'min is larger than max');
};
const index = (v, path) => {
  if (!Number.isInteger(v) || v < 0) fail(path, 'expected a whole number >= 0');
};

/**
 * Parses and validates a lesson file. `text` is the file's text, `ctx` what the page offers:
 * {scenes: ids, views: ids, panel: controller names, checkMotion(doc, path)}. Returns the lesson;
 * throws a LessonError naming the step and field. Every text is typeset here once, so a KaTeX
 * error is a load error too.
 */
export function parseLesson(text, ctx) {
  if (typeof text !== 'string') fail('', 'a lesson file is text (JSON)');
  if (text.length > MAX_LESSON_BYTES) fail('', `the file is ${text.length} bytes; a lesson may have at most ${MAX_LESSON_BYTES}`);
  let lesson;
  try {
    lesson = JSON.parse(text);
  } catch (e) {
    fail('', `not valid JSON (${e.message})`);
  }
  validateLesson(lesson, ctx);
  return lesson;
}

/** Validates a parsed lesson object (see parseLesson). */
export function validateLesson(lesson, ctx) {
  if (!isObj(lesson)) fail('', 'a lesson is a JSON object');
  onlyKeys(lesson, ['$schema', 'id', 'title', 'summary', 'tour', 'steps'], '');
  str(lesson.id, 'id');
  if (!/^[A-Za-z0-9_-]{1,64}$/.test(lesson.id)) fail('id', 'use 1-64 letters, digits, - or _');
  str(lesson.title, 'title');
  if (lesson.summary !== undefined) str(lesson.summary, 'summary');
  if (lesson.tour !== undefined && typeof lesson.tour !== 'boolean') fail('tour', 'expected true or false');
  if (!Array.isArray(lesson.steps) || lesson.steps.length === 0) fail('steps', 'expected a non-empty list of steps');
  if (lesson.steps.length > MAX_STEPS) fail('steps', `at most ${MAX_STEPS} steps`);
  lesson.steps.forEach((s, i) => validateStep(s, `steps[${i}]`, ctx));
}

function validateStep(s, p, ctx) {
  if (!isObj(s)) fail(p, 'a step is a JSON object');
  onlyKeys(s, STEP_FIELDS, p);
  str(s.title, `${p}.title`);
  str(s.text, `${p}.text`);
  typeset(s.text, `${p}.text`);
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
  if (s.options !== undefined) validateOptions(s.options, `${p}.options`, false);
  if (s.display !== undefined) {
    if (!isObj(s.display)) fail(`${p}.display`, 'expected an object');
    onlyKeys(s.display, Object.keys(DISPLAY_FIELDS), `${p}.display`);
    for (const [k, v] of Object.entries(s.display)) {
      if (typeof v !== DISPLAY_FIELDS[k]) fail(`${p}.display.${k}`, `expected a ${DISPLAY_FIELDS[k]}`);
    }
    if (s.display.strobe !== undefined && !(Number.isInteger(s.display.strobe) && s.display.strobe >= 1 && s.display.strobe <= 10000)) {
      fail(`${p}.display.strobe`, 'expected a whole number from 1 to 10000');
    }
  }
  if (s.timing !== undefined) {
    const t = s.timing;
    if (!isObj(t)) fail(`${p}.timing`, 'expected an object');
    onlyKeys(t, ['times', 'speed', 'play', 'u'], `${p}.timing`);
    if (t.times !== undefined && t.times !== null) {
      if (!Array.isArray(t.times) || t.times.length < 2 || !t.times.every(isNum)) fail(`${p}.timing.times`, 'expected a list of at least 2 numbers, or null');
      for (let k = 1; k < t.times.length; k++) if (!(t.times[k] > t.times[k - 1])) fail(`${p}.timing.times[${k}]`, 'times must increase');
    }
    if (t.speed !== undefined && !(isNum(t.speed) && t.speed >= 0.1 && t.speed <= 4)) fail(`${p}.timing.speed`, 'expected a number from 0.1 to 4');
    if (t.play !== undefined && typeof t.play !== 'boolean') fail(`${p}.timing.play`, 'expected true or false');
    if (t.u !== undefined) num(t.u, `${p}.timing.u`);
  }
  if (s.dock !== undefined && s.dock !== '') oneOf(s.dock, ctx.views, `${p}.dock`);
  if (s.stepsAt !== undefined) {
    index(s.stepsAt, `${p}.stepsAt`);
    if (s.stepsAt > 9) fail(`${p}.stepsAt`, 'the Split & tweak view has steps 0 to 9 (five levels)');
    if (s.dock !== 'steps') fail(`${p}.stepsAt`, 'needs "dock": "steps" in the same step');
  }
  if (s.select !== undefined && s.select !== -1) index(s.select, `${p}.select`);
  if (s.highlight !== undefined) validateHighlight(s.highlight, `${p}.highlight`, ctx);
  if (s.exercise !== undefined) validateExercise(s.exercise, `${p}.exercise`);
}

function validateOptions(o, p, isCheck) {
  if (!isObj(o)) fail(p, 'expected an object');
  onlyKeys(o, isCheck ? ['kind', ...CHECK_FIELDS.options] : ['scheme', 'rules', 'levels', 's', 'j', 'closed'], p);
  if (o.s !== undefined && o.j !== undefined && JSON.stringify(o.s) !== JSON.stringify(o.j)) {
    fail(`${p}.s`, `s and j disagree (j is the former name of s; give s only)`);
  }
  if (o.scheme !== undefined) oneOf(o.scheme, SCHEMES, `${p}.scheme`);
  if (o.rules !== undefined) oneOf(o.rules, RULES, `${p}.rules`);
  if (o.closed !== undefined && typeof o.closed !== 'boolean') fail(`${p}.closed`, 'expected true or false');
  if (isCheck) {
    if (o.levels !== undefined) range(o.levels, `${p}.levels`);
    for (const f of ['s', 'j']) if (o[f] !== undefined) range(o[f], `${p}.${f}`);
  } else {
    if (o.levels !== undefined && !(Number.isInteger(o.levels) && o.levels >= 0 && o.levels <= MAX_LEVELS)) fail(`${p}.levels`, `expected a whole number from 0 to ${MAX_LEVELS}`);
    for (const f of ['s', 'j']) if (o[f] !== undefined && !(isNum(o[f]) && Math.abs(o[f]) <= 4)) fail(`${p}.${f}`, 'expected a number from -4 to 4');
  }
}

function validateHighlight(h, p, ctx) {
  if (!isObj(h)) fail(p, 'expected an object with one of control, panel, pose, gizmo');
  onlyKeys(h, HIGHLIGHT_KINDS, p);
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

function validateExercise(x, p) {
  if (!isObj(x)) fail(p, 'expected an object');
  onlyKeys(x, ['task', 'choices', 'checks', 'hints', 'success'], p);
  str(x.task, `${p}.task`);
  typeset(x.task, `${p}.task`);
  if (x.choices !== undefined) {
    if (!Array.isArray(x.choices) || x.choices.length < 2) fail(`${p}.choices`, 'expected a list of at least 2 answers');
    // An answer is its text, or {text, why}: `why` says why it is wrong (or right), shown when
    // it is checked. Parsed into x.choices (the texts) and x.why (null where none is given).
    x.why = x.choices.map((c, k) => {
      if (isObj(c)) {
        onlyKeys(c, ['text', 'why'], `${p}.choices[${k}]`);
        if (c.why !== undefined) {
          str(c.why, `${p}.choices[${k}].why`);
          typeset(c.why, `${p}.choices[${k}].why`);
        }
        return c.why ?? null;
      }
      return null;
    });
    x.choices = x.choices.map((c, k) => {
      const text = isObj(c) ? c.text : c;
      const at = isObj(c) ? `${p}.choices[${k}].text` : `${p}.choices[${k}]`;
      str(text, at);
      typeset(text, at);
      return text;
    });
  }
  if (!Array.isArray(x.checks) || x.checks.length === 0) fail(`${p}.checks`, 'expected a non-empty list of checks');
  x.checks.forEach((c, k) => validateCheck(c, `${p}.checks[${k}]`, x));
  if (x.hints !== undefined) {
    if (!Array.isArray(x.hints)) fail(`${p}.hints`, 'expected a list of texts');
    x.hints.forEach((h, k) => {
      str(h, `${p}.hints[${k}]`);
      typeset(h, `${p}.hints[${k}]`);
    });
  }
  if (x.success !== undefined) {
    str(x.success, `${p}.success`);
    typeset(x.success, `${p}.success`);
  }
}

function validateCheck(c, p, x) {
  if (!isObj(c)) fail(p, 'expected a check object');
  if (!Object.hasOwn(CHECK_FIELDS, c.kind)) fail(`${p}.kind`, `${JSON.stringify(c.kind)} is not one of ${Object.keys(CHECK_FIELDS).join(', ')}`);
  if (c.kind === 'options') return validateOptions(c, p, true);
  onlyKeys(c, ['kind', ...CHECK_FIELDS[c.kind]], p);
  switch (c.kind) {
    case 'spanScrew':
      index(c.span, `${p}.span`);
      if (c.screw !== undefined) oneOf(c.screw, SCREW_KINDS, `${p}.screw`);
      for (const f of ['angle', 'slide', 'pitch']) if (c[f] !== undefined) range(c[f], `${p}.${f}`);
      break;
    case 'pose':
      index(c.pose, `${p}.pose`);
      if (c.origin === undefined && c.rotation === undefined) fail(p, 'give origin, rotation or both');
      if (c.origin !== undefined) vec(c.origin, 3, `${p}.origin`);
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
    case 'choice':
      if (!Array.isArray(x.choices)) fail(p, 'a choice check needs the exercise to list choices');
      index(c.answer, `${p}.answer`);
      if (c.answer >= x.choices.length) fail(`${p}.answer`, `there are only ${x.choices.length} choices`);
      break;
    default:
      break;
  }
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

/** Checks that every formula of `text` typesets (a KaTeX error names the field). */
function typeset(text, path) {
  if (typeof document === 'undefined') return;
  for (const t of tokens(text, path)) {
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
