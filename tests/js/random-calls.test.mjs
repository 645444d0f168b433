// No panic across the wasm boundary: random calls of the JS API with random (mostly bad)
// arguments, a fixed number of them (so that a slow machine tests as much as a fast one).
// Every failure must be a thrown `Error` that is not a wasm trap
// (a Rust panic surfaces as `WebAssembly.RuntimeError: unreachable`), a failed call must leave
// the motion exactly as it was, and the module must keep working throughout.
//
//   node --test tests/js/random-calls.test.mjs
//   RANDOM_CALLS=500000 RANDOM_CALLS_SEED=1234 node --test tests/js/random-calls.test.mjs
//
// The seed is printed at the start and in every failure message; rerun with it to reproduce.
import assert from 'node:assert/strict';
import { it } from 'node:test';

import { sb } from './package.mjs';
import { prng } from './prng.mjs';

const { Motion } = sb;

/** Calls in all, in bursts of 50 between health checks. */
const CALLS = Number(process.env.RANDOM_CALLS ?? 50_000);
const SEED = Number(process.env.RANDOM_CALLS_SEED ?? (Date.now() % 2 ** 31));

const rand = prng(SEED);
const pick = (xs) => xs[Math.floor(rand() * xs.length)];
const int = (n) => Math.floor(rand() * n);

const PRESETS = sb.presets().map((s) => s.id);
const H = Math.SQRT1_2;

// ---- random values: valid ones, near-valid ones and garbage ----------------------------------

function number() {
  return pick([
    0, -0, 1, -1, 0.5, 2, 3, 7, 1e-300, 1e300, -1e300, 2 ** 31, 2 ** 53 + 1, Number.MAX_VALUE,
    Number.MIN_VALUE, NaN, Infinity, -Infinity, rand() * 10 - 5, int(30), -int(30),
  ]);
}

function garbage() {
  return pick([
    undefined, null, true, false, '', 'x', '3', 'bspline', 'j', '{"poses":[]}', [], {}, [1, 2],
    [NaN], { origin: 1 }, 10n, Symbol('s'), () => 1, new Float32Array(7), new BigInt64Array(2),
    new Uint8Array(14), new ArrayBuffer(8), new Date(0), /re/, new Map(), Object.create(null),
    new Proxy({}, { get() { throw new Error('proxy trap'); }, ownKeys() { throw new Error('proxy keys'); } }),
    Object.defineProperty({}, 'origin', { enumerable: true, get() { throw new Error('getter'); } }),
  ]);
}

function quaternion() {
  if (rand() < 0.5) {
    const a = rand() * 2 * Math.PI;
    const v = [rand() - 0.5, rand() - 0.5, rand() - 0.5];
    const n = Math.hypot(...v) || 1;
    return [Math.cos(a / 2), ...v.map((x) => (x / n) * Math.sin(a / 2))];
  }
  return pick([[1, 0, 0, 0], [0, 0, 0, 1], [H, 0, 0, H], [0, 0, 0, 0], [2, 0, 0, 0], [1, 0, 0], [1, 0, 0, 0, 0], [NaN, 0, 0, 0], [number(), number(), number(), number()]]);
}

function vec3() {
  return rand() < 0.7 ? [rand() * 8 - 4, rand() * 8 - 4, rand() * 8 - 4] : pick([[0, 0], [0, 0, 0, 0], [number(), number(), number()], 'xyz']);
}

function pose() {
  const r = rand();
  if (r < 0.6) return { origin: vec3(), rotation: quaternion() };
  if (r < 0.75) return { origin: vec3(), basis: pick([[[1, 0, 0], [0, 1, 0], [0, 0, 1]], [[1, 0, 0], [0, 1, 0], [0, 0, -1]], [[1, 0, 0], [0.5, 1, 0], [0, 0, 1]], [[0, 0, 0], [0, 0, 0], [0, 0, 0]]]) };
  if (r < 0.85) return { origin: vec3(), rotation: quaternion(), basis: [[1, 0, 0], [0, 1, 0], [0, 0, 1]] };
  return garbage();
}

function document() {
  const r = rand();
  if (r < 0.8) {
    const n = pick([0, 1, 2, 3, 4, 6, 9]);
    const doc = { poses: Array.from({ length: n }, pose) };
    if (rand() < 0.5) doc.closed = rand() < 0.9 ? rand() < 0.5 : garbage();
    if (rand() < 0.2) doc.name = rand() < 0.8 ? `m${int(100)}` : garbage();
    if (rand() < 0.05) doc.extra = 1;
    return doc;
  }
  return garbage();
}

function posesArray() {
  const n = pick([0, 1, 2, 3, 5]);
  const a = [];
  for (let k = 0; k < n; k++) a.push(...vec3().slice(0, 3), ...quaternion().slice(0, 4));
  if (rand() < 0.2) a.push(number());
  return rand() < 0.5 ? Float64Array.from(a, Number) : rand() < 0.8 ? a : garbage();
}

function options() {
  if (rand() < 0.15) return garbage();
  const o = {};
  if (rand() < 0.5) o.scheme = pick(['bspline', 'fourpoint', 'jarek', 'j', 'J', 'cubic', '', 3]);
  if (rand() < 0.3) o.s = rand() < 0.7 ? rand() * 2 - 0.5 : number();
  if (rand() < 0.1) o.j = rand() < 0.7 ? rand() * 2 - 0.5 : number();
  if (rand() < 0.3) o.rules = pick(['direct', 'split', 'v3', null]);
  if (rand() < 0.6) o.levels = rand() < 0.8 ? int(7) : number();
  if (rand() < 0.05) o.levle = 3;
  return o;
}

const json = () => (rand() < 0.7 ? JSON.stringify(document()) ?? '' : pick(['', '{', '{"poses": [', 'null', '[]', '"x"', ' '.repeat(1000), garbage()]));
const maybe = (f) => (rand() < 0.8 ? f() : garbage());

// ---- the calls ---------------------------------------------------------------------------------

/** Constructors and free functions: [name, () => result]. */
const moduleCalls = [
  ['new Motion', () => new Motion(document(), maybe(options))],
  ['Motion.fromJson', () => Motion.fromJson(json(), maybe(options))],
  ['Motion.fromPoses', () => Motion.fromPoses(posesArray(), maybe(() => rand() < 0.5), maybe(options))],
  ['Motion.fromPreset', () => Motion.fromPreset(rand() < 0.7 ? pick(PRESETS) : garbage())],
  ['screw', () => sb.screw(pose(), maybe(number), pose())],
  ['screwPoses', () => sb.screwPoses(pose(), pose(), maybe(() => Array.from({ length: int(5) }, number)))],
  ['screwPairs', () => sb.screwPairs(posesArray(), posesArray(), maybe(() => Array.from({ length: int(4) }, number)))],
  ['screwInfo', () => sb.screwInfo(pose(), pose())],
  ['posesToMatrices', () => sb.posesToMatrices(posesArray())],
  ['presets', () => sb.presets()],
  ['limits', () => sb.limits()],
];

/** Methods of a motion: [name, (m) => result]. */
const methodCalls = [
  ['loadJson', (m) => m.loadJson(json())],
  ['loadDocument', (m) => m.loadDocument(document())],
  ['setName', (m) => m.setName(rand() < 0.5 ? 'n' : garbage())],
  ['setClosed', (m) => m.setClosed(rand() < 0.7 ? rand() < 0.5 : garbage())],
  ['pose', (m) => m.pose(rand() < 0.7 ? int(m.poseCount + 2) - 1 : number())],
  ['setPose', (m) => m.setPose(rand() < 0.8 ? int(m.poseCount + 1) : number(), pose())],
  ['insertPose', (m) => (rand() < 0.5 ? m.insertPose(int(m.poseCount + 1)) : m.insertPose(maybe(() => int(m.poseCount + 1)), pose()))],
  ['removePose', (m) => m.removePose(rand() < 0.8 ? int(m.poseCount + 1) : garbage())],
  ['setOptions', (m) => m.setOptions(options())],
  ['setScheme', (m) => m.setScheme(pick(['bspline', 'fourpoint', 'jarek', 'j', 'cubic', 4, null]))],
  ['setS', (m) => m.setS(rand() < 0.6 ? rand() * 1.5 - 0.25 : number())],
  ['setJ', (m) => m.setJ(rand() < 0.6 ? rand() * 1.5 - 0.25 : number())],
  ['setRules', (m) => m.setRules(pick(['direct', 'split', 'v3', undefined]))],
  ['setLevels', (m) => m.setLevels(rand() < 0.7 ? int(8) : number())],
  ['subdivide', (m) => m.subdivide()],
  ['refinedMatrices', (m) => m.refinedMatrices()],
  ['poseAt', (m) => m.poseAt(rand() < 0.7 ? rand() * 8 - 2 : maybe(number))],
  ['posesAt', (m) => m.posesAt(maybe(() => Array.from({ length: int(6) }, () => (rand() < 0.9 ? rand() * 5 : number()))))],
  ['sample', (m) => m.sample(rand() < 0.7 ? int(50) : maybe(number))],
  ['sampleMatrices', (m) => m.sampleMatrices(rand() < 0.7 ? int(50) : maybe(number))],
  ['kinematicsAt', (m) => m.kinematicsAt(rand() * 4, rand() < 0.5 ? undefined : maybe(vec3))],
  ['sampleKinematics', (m) => m.sampleKinematics(rand() < 0.7 ? int(20) : maybe(number), rand() < 0.5 ? undefined : maybe(vec3))],
  ['spanScrews', (m) => m.spanScrews()],
  ['toJson', (m) => m.toJson()],
  ['toDocument', (m) => m.toDocument()],
  ['options', (m) => m.options()],
  ['domain', (m) => m.domain()],
];

function state(m) {
  return JSON.stringify([m.toJson(), m.options()]);
}

function healthy(m, where) {
  const p = m.poseAt(0.25);
  assert.ok([...p.origin, ...p.rotation].every(Number.isFinite), `${where}: non-finite pose ${JSON.stringify(p)}`);
  const q = m.subdivide();
  for (let k = 0; k < q.length; k++) assert.ok(Number.isFinite(q[k]), `${where}: refined[${k}] = ${q[k]}`);
}

it(`${CALLS} random calls never panic and never corrupt a motion (seed ${SEED})`, () => {
  console.log(`# random-calls: seed ${SEED} (RANDOM_CALLS_SEED=${SEED} to reproduce), ${CALLS} calls`);
  const motions = [Motion.fromPreset(PRESETS[0]), new Motion({ poses: [{ origin: [0, 0, 0], rotation: [1, 0, 0, 0] }, { origin: [2, 0, 0], rotation: [H, 0, 0, H] }] }, { levels: 2 })];
  const stats = { calls: 0, thrown: 0, ok: 0 };
  let call = 0;
  while (call < CALLS) {
    for (let burst = 0; burst < 50; burst++, call++) {
      const onModule = rand() < 0.25;
      const [name, f] = onModule ? pick(moduleCalls) : pick(methodCalls);
      const target = onModule ? null : pick(motions);
      const where = `seed ${SEED}, call ${call} (${name})`;
      const before = target ? state(target) : null;
      let result;
      try {
        result = onModule ? f() : f(target);
        stats.ok++;
      } catch (e) {
        stats.thrown++;
        assert.ok(e instanceof Error, `${where}: threw a non-Error ${String(e)}`);
        assert.ok(!(e instanceof WebAssembly.RuntimeError), `${where}: wasm trap (a Rust panic): ${e.message}`);
        assert.ok(typeof e.message === 'string' && e.message.length > 0, `${where}: empty message`);
        if (target) assert.equal(state(target), before, `${where}: the motion changed although the call failed (${e.message})`);
      }
      stats.calls++;
      if (result instanceof Motion) {
        healthy(result, `${where} result`);
        if (motions.length < 6) motions.push(result);
        else {
          const old = motions.splice(2 + int(motions.length - 2), 1, result)[0];
          old.free();
        }
      }
    }
    // The module keeps working: every live motion, and a fresh one.
    for (const m of motions) healthy(m, `seed ${SEED}, after call ${call}`);
    const probe = Motion.fromPreset(pick(PRESETS));
    healthy(probe, `seed ${SEED}, fresh motion after call ${call}`);
    probe.free();
  }
  console.log(`# random-calls: ${stats.calls} calls, ${stats.thrown} threw an Error, ${stats.ok} succeeded`);
  assert.ok(stats.thrown > 0 && stats.ok > 0);
  for (const m of motions) m.free();
});
