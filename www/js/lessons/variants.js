// Randomised variants of lesson steps (www/lessons/README.md, "Variants"): a step declares
// parameters with ranges in `params`, its texts name them as `{{name}}` and its numbers as
// `{"param": name, "scale"?, "offset"?}`; a seed picks one value of each.
//
// The generator is mulberry32 (one 32-bit word of state, uniform in [0, 1)), written here
// rather than taken from a library: a student's variant is kept as nothing but a seed (in the
// browser's progress, or derived from the learner's id in an LMS), so the exact sequence is part
// of the lesson format and must never change with a dependency's update. mulberry32 uses only
// 32-bit integer operations (Math.imul, shifts), which every JavaScript engine computes
// identically, passes the usual statistical batteries for the few draws a step needs, and is a
// dozen lines. Each parameter gets its own generator, seeded by FNV-1a of the seed, the step's
// index and the parameter's name, so adding a parameter or a step leaves the others' values as
// they were.

/** A parameter's name: a letter, then letters, digits or `_`. */
export const PARAM_NAME = /^[A-Za-z][A-Za-z0-9_]*$/;
/** Most values one parameter may range over. */
export const MAX_PARAM_VALUES = 10000;
/** `{{name}}` in a text (spaces inside the braces allowed). */
const TEXT_REF = /\{\{\s*([^{}]*?)\s*\}\}/g;

/** mulberry32 seeded with `seed` (a 32-bit integer): a function returning numbers in [0, 1). */
export function mulberry32(seed) {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/** FNV-1a (32 bits) of `text`'s code points: a well-spread seed from any string. */
export function fnv1a(text) {
  let h = 0x811c9dc5;
  for (const c of text) {
    h ^= c.codePointAt(0);
    h = Math.imul(h, 0x01000193) >>> 0;
  }
  return h;
}

/** A fresh seed for a student who has none yet (crypto's generator where there is one). */
export function newSeed() {
  const c = globalThis.crypto;
  if (c?.getRandomValues) return c.getRandomValues(new Uint32Array(1))[0];
  return Math.floor(Math.random() * 4294967296) >>> 0;
}

export { isSeed } from './progress.js';

/** Decimals of a number written in JSON (`0.25` → 2), at most 10. */
function decimals(x) {
  const m = /(?:\.(\d+))?(?:e([+-]\d+))?$/.exec(String(x));
  return Math.min(10, Math.max(0, (m[1]?.length ?? 0) - Number(m[2] ?? 0)));
}

const isNum = (v) => typeof v === 'number' && Number.isFinite(v);
const isObj = (v) => v !== null && typeof v === 'object' && !Array.isArray(v);

/**
 * The values parameter `def` ranges over: `{min, max, step}` gives min, min + step, … up to
 * max, rounded to the decimals of min and step (so 0.1 steps read 0.3, not 0.30000000000000004);
 * `{values: […]}` the list itself. Assumes `def` is valid (see paramProblems).
 */
export function paramValues(def) {
  if (def.values) return [...def.values];
  const d = Math.max(decimals(def.min), decimals(def.step));
  const n = Math.floor((def.max - def.min) / def.step + 1e-9) + 1;
  return Array.from({ length: n }, (_, k) => Number((def.min + k * def.step).toFixed(d)));
}

/**
 * The problems of a step's `params` declaration: [{path, message}] (`path` below `at`). Each
 * parameter is `{min, max, step}` (min ≤ max, step > 0, at most MAX_PARAM_VALUES values) or
 * `{values: [numbers]}`.
 */
export function paramProblems(params, at) {
  if (!isObj(params) || Object.keys(params).length === 0) return [{ path: at, message: 'expected an object of parameters, e.g. {"h": {"min": 0.5, "max": 2, "step": 0.1}}' }];
  const out = [];
  for (const [name, def] of Object.entries(params)) {
    const p = `${at}.${name}`;
    if (!PARAM_NAME.test(name)) out.push({ path: p, message: 'a parameter name is a letter, then letters, digits or _' });
    if (!isObj(def)) {
      out.push({ path: p, message: 'expected {min, max, step} or {values}' });
      continue;
    }
    const keys = Object.keys(def);
    const allowed = def.values !== undefined ? ['values'] : ['min', 'max', 'step'];
    for (const k of keys) if (!allowed.includes(k)) out.push({ path: `${p}.${k}`, message: `unknown field (expected ${def.values !== undefined ? 'values alone' : 'min, max, step'})` });
    if (def.values !== undefined) {
      if (!Array.isArray(def.values) || def.values.length === 0 || !def.values.every(isNum)) out.push({ path: `${p}.values`, message: 'expected a non-empty list of finite numbers' });
      else if (def.values.length > MAX_PARAM_VALUES) out.push({ path: `${p}.values`, message: `at most ${MAX_PARAM_VALUES} values` });
      continue;
    }
    let ok = true;
    for (const f of ['min', 'max', 'step']) {
      if (!isNum(def[f])) {
        out.push({ path: `${p}.${f}`, message: 'expected a finite number' });
        ok = false;
      }
    }
    if (!ok) continue;
    if (def.step <= 0) out.push({ path: `${p}.step`, message: 'expected a positive number' });
    else if (def.min > def.max) out.push({ path: `${p}.max`, message: 'max is smaller than min' });
    else if ((def.max - def.min) / def.step + 1 > MAX_PARAM_VALUES) out.push({ path: `${p}.step`, message: `the range has more than ${MAX_PARAM_VALUES} values: use a larger step` });
  }
  return out;
}

/**
 * The parameters `value` (a step without its `params`, or any part of it) refers to, and the
 * problems of the references' form: {names: [{path, name, text}], problems: [{path, message}]}
 * (`text`: the reference is `{{name}}` in a string).
 * A reference is `{{name}}` in a string or `{"param": name, "scale"?: number, "offset"?:
 * number}` where a number goes.
 */
export function references(value, at) {
  const names = [];
  const problems = [];
  const walk = (v, p) => {
    if (typeof v === 'string') {
      for (const m of v.matchAll(TEXT_REF)) names.push({ path: p, name: m[1], text: true });
    } else if (Array.isArray(v)) {
      v.forEach((x, k) => walk(x, `${p}[${k}]`));
    } else if (isObj(v)) {
      if (Object.hasOwn(v, 'param')) {
        if (typeof v.param !== 'string') problems.push({ path: `${p}.param`, message: 'expected a parameter name' });
        else names.push({ path: `${p}.param`, name: v.param });
        for (const k of Object.keys(v)) {
          if (!['param', 'scale', 'offset'].includes(k)) problems.push({ path: `${p}.${k}`, message: 'unknown field of a parameter reference (expected param, scale, offset)' });
          else if (k !== 'param' && !isNum(v[k])) problems.push({ path: `${p}.${k}`, message: 'expected a finite number' });
        }
        return;
      }
      for (const [k, x] of Object.entries(v)) walk(x, p ? `${p}.${k}` : k);
    }
  };
  walk(value, at);
  return { names, problems };
}

/**
 * The variant of step number `stepIndex` for `seed`: {name: value} for each parameter of
 * `params` (valid, see paramProblems).
 */
export function drawParams(params, seed, stepIndex) {
  const out = {};
  for (const [name, def] of Object.entries(params)) {
    const values = paramValues(def);
    const r = mulberry32(fnv1a(`${seed >>> 0}:${stepIndex}:${name}`))();
    out[name] = values[Math.min(values.length - 1, Math.floor(r * values.length))];
  }
  return out;
}

/** The lowest and the highest value of every parameter: the variants a validator tries. */
export function extremeParams(params) {
  const lo = {};
  const hi = {};
  for (const [name, def] of Object.entries(params)) {
    const v = paramValues(def);
    lo[name] = Math.min(...v);
    hi[name] = Math.max(...v);
  }
  return [lo, hi];
}

/** A value as a text shows it: the shortest form that reads back as the same number. */
const show = (x) => String(Number(x.toPrecision(12)));

/**
 * A copy of `value` with every reference replaced by `values` (see references): `{{name}}` by
 * the value's text, `{"param", scale, offset}` by scale · value + offset. Names missing from
 * `values` read as 0 (a validator reports them; a valid lesson has none).
 */
export function substitute(value, values) {
  const get = (name) => (Object.hasOwn(values, name) ? values[name] : 0);
  if (typeof value === 'string') return value.replace(TEXT_REF, (_, name) => show(get(name)));
  if (Array.isArray(value)) return value.map((x) => substitute(x, values));
  if (isObj(value)) {
    if (Object.hasOwn(value, 'param')) {
      const x = (isNum(value.scale) ? value.scale : 1) * get(value.param) + (isNum(value.offset) ? value.offset : 0);
      return Number(x.toPrecision(15));
    }
    return Object.fromEntries(Object.entries(value).map(([k, x]) => [k, substitute(x, values)]));
  }
  return value;
}
