// The bad-input matrix (docs/bad-input.md), JS API column: one test per row. Every entry point
// of the built package that accepts the input (document objects, JSON text, pose arrays, single
// poses, options, the free screw functions) throws an `Error` naming the element, and an
// existing Motion keeps its exact state and keeps working.
//
//   node --test tests/js/bad-input.test.mjs     (after PACK=0 scripts/build-pkg.sh)
import assert from 'node:assert/strict';
import { describe, it } from 'node:test';

import { sb } from './package.mjs';

const { Motion } = sb;

const ID = [1, 0, 0, 0];
const H = Math.SQRT1_2;
const P = (over = {}) => ({ origin: [0, 0, 0], rotation: ID, ...over });
/** A 3-pose document whose `poses[1]` is `pose`. */
const docWith = (pose) => ({ closed: true, poses: [P(), pose, P({ origin: [4, 4, 0], rotation: [H, 0, 0, H] })] });
/** A 3-pose Float64Array whose pose 1 is `seven`. */
const arrayWith = (seven) => Float64Array.from([0, 0, 0, 1, 0, 0, 0, ...seven, 4, 4, 0, H, 0, 0, H]);

const fresh = () =>
  new Motion(
    { name: 'fixture', closed: true, poses: [P(), P({ origin: [4, 0, 0], rotation: [H, 0, 0, H] }), P({ origin: [4, 4, 1], rotation: [0, 0, 0, 1] })] },
    { scheme: 'jarek', levels: 3 },
  );

function snapshot(m) {
  return { json: m.toJson(), options: m.options(), refined: Array.from(m.subdivide()) };
}

/** `fn` throws an Error (not a wasm trap) whose message matches `message`. */
function throwsError(fn, message, what = '') {
  assert.throws(fn, (e) => {
    assert.ok(e instanceof Error, `${what}: not an Error: ${e}`);
    assert.ok(!(e instanceof WebAssembly.RuntimeError), `${what}: a wasm trap (panic): ${e.message}`);
    if (message instanceof RegExp) assert.match(e.message, message, what);
    else assert.equal(e.message, message, what);
    return true;
  });
}

/** As `throwsError`, and `m` is exactly as before and keeps working. */
function throwsUnchanged(m, fn, message, what = '') {
  const before = snapshot(m);
  throwsError(fn, message, what);
  assert.deepEqual(snapshot(m), before, `${what}: state changed after the error`);
  const p = m.poseAt(0.5);
  assert.ok([...p.origin, ...p.rotation].every(Number.isFinite), `${what}: the motion stopped working`);
}

/**
 * One bad pose through every entry point that takes a pose: document object (constructor and
 * loadDocument), JSON text (fromJson and loadJson, when `json` is given), 7-number arrays
 * (fromPoses, when `seven` is given), setPose / insertPose, and the free screw functions.
 */
function poseRow({ pose, message, json, jsonMessage = message, seven, sevenMessage }) {
  const full = (prefix) => (message instanceof RegExp ? new RegExp(`^${prefix.replace(/[[\].]/g, '\\$&')}${message.source}`) : `${prefix}${message}`);
  const m = fresh();
  throwsError(() => new Motion(docWith(pose)), full('poses[1].'), 'constructor');
  throwsUnchanged(m, () => m.loadDocument(docWith(pose)), full('poses[1].'), 'loadDocument');
  throwsUnchanged(m, () => m.setPose(1, pose), full('pose.'), 'setPose');
  throwsUnchanged(m, () => m.insertPose(1, pose), full('pose.'), 'insertPose');
  throwsError(() => sb.screw(P(), 0.5, pose), full('b.'), 'screw');
  throwsError(() => sb.screwPoses(pose, P(), [0.5]), full('a.'), 'screwPoses');
  throwsError(() => sb.screwInfo(P(), pose), full('b.'), 'screwInfo');
  if (json !== undefined) {
    const text = JSON.stringify(docWith('@')).replace('"@"', json);
    throwsError(() => Motion.fromJson(text), jsonMessage, 'fromJson');
    throwsUnchanged(m, () => m.loadJson(text), jsonMessage, 'loadJson');
  }
  if (seven !== undefined) {
    throwsError(() => Motion.fromPoses(arrayWith(seven)), sevenMessage, 'fromPoses');
    throwsError(() => sb.posesToMatrices(arrayWith(seven)), sevenMessage, 'posesToMatrices');
    const a = Float64Array.from([0, 0, 0, 1, 0, 0, 0]);
    throwsError(() => sb.screwPairs(a, Float64Array.from(seven), [0.5]), sevenMessage instanceof RegExp ? new RegExp(sevenMessage.source.replace('^poses\\[1\\]', '^ends\\[0\\]')) : sevenMessage.replace('poses[1]', 'ends[0]'), 'screwPairs');
  }
}

describe('bad-input matrix: JS API', () => {
  it('NaN', () => {
    poseRow({
      pose: P({ origin: [0, NaN, 0] }),
      message: 'origin: not a finite number (NaN or infinity)',
      // JSON has no NaN: a syntax error at its position.
      json: '{"origin":[0,NaN,0],"rotation":[1,0,0,0]}',
      jsonMessage: /^invalid motion document: expected value at line 1 column \d+$/,
      seven: [0, NaN, 0, 1, 0, 0, 0],
      sevenMessage: 'poses[1].origin: not a finite number (NaN or infinity)',
    });
    const m = fresh();
    throwsUnchanged(m, () => m.setJ(NaN), 'j: not a finite number (NaN or infinity)');
    throwsUnchanged(m, () => m.poseAt(NaN), 'u: not a finite number (NaN or infinity)');
    throwsUnchanged(m, () => m.posesAt([0, NaN]), 'us[1]: not a finite number (NaN or infinity)');
    throwsUnchanged(m, () => m.kinematicsAt(0, [NaN, 0, 0]), 'local: not a finite number (NaN or infinity)');
    throwsUnchanged(m, () => m.setLevels(NaN), 'levels: NaN is out of range (expected a whole number from 0 to 19; more levels never fit the limit of 1048576 refined poses)');
    throwsError(() => sb.screw(P(), NaN, P()), 't: not a finite number (NaN or infinity)');
  });

  it('Infinity', () => {
    poseRow({
      pose: P({ rotation: [1, 0, -Infinity, 0] }),
      message: 'rotation: not a finite number (NaN or infinity)',
      json: '{"origin":[0,0,0],"rotation":[1,0,1e999,0]}',
      jsonMessage: /^invalid motion document: number out of range at line 1 column \d+$/,
      seven: [0, 0, 0, Infinity, 0, 0, 0],
      sevenMessage: 'poses[1].rotation: not a finite number (NaN or infinity)',
    });
    const m = fresh();
    throwsUnchanged(m, () => m.setJ(Infinity), 'j: not a finite number (NaN or infinity)');
    throwsUnchanged(m, () => m.sample(Infinity), 'count: Infinity is out of range (expected a whole number from 0 to 1048576)');
    throwsUnchanged(m, () => m.setLevels(Infinity), 'levels: Infinity is out of range (expected a whole number from 0 to 19; more levels never fit the limit of 1048576 refined poses)');
    throwsError(() => sb.screwPoses(P(), P(), [0, Infinity]), 'ts[1]: not a finite number (NaN or infinity)');
  });

  it('zero quaternion', () => {
    poseRow({
      pose: P({ rotation: [0, 0, 0, 0] }),
      message: 'rotation: zero quaternion',
      json: '{"origin":[0,0,0],"rotation":[0,0,0,0]}',
      jsonMessage: 'poses[1].rotation: zero quaternion',
      seven: [1, 2, 3, 0, 0, 0, 0],
      sevenMessage: 'poses[1].rotation: zero quaternion',
    });
  });

  it('non-unit quaternion', () => {
    const message = /quaternion norm 0\.5 is not 1 \(accepted: within 0\.001 of 1, then normalised\)$/;
    poseRow({
      pose: P({ rotation: [0.5, 0, 0, 0] }),
      message: new RegExp(`rotation: ${message.source}`),
      json: '{"origin":[0,0,0],"rotation":[0.5,0,0,0]}',
      jsonMessage: new RegExp(`^poses\\[1\\]\\.rotation: ${message.source}`),
      seven: [0, 0, 0, 0.5, 0, 0, 0],
      sevenMessage: new RegExp(`^poses\\[1\\]\\.rotation: ${message.source}`),
    });
  });

  it('non-orthonormal basis', () => {
    poseRow({
      pose: { origin: [0, 0, 0], basis: [[1, 0, 0], [0.5, 1, 0], [0, 0, 1]] },
      message: /basis: basis is not orthonormal \(largest \|RᵀR − I\| entry 5\.000e-1, accepted up to 1e-4\)$/,
      json: '{"origin":[0,0,0],"basis":[[1,0,0],[0.5,1,0],[0,0,1]]}',
      jsonMessage: /^poses\[1\]\.basis: basis is not orthonormal/,
    });
  });

  it('left-handed basis', () => {
    poseRow({
      pose: { origin: [0, 0, 0], basis: [[1, 0, 0], [0, 1, 0], [0, 0, -1]] },
      message: 'basis: basis is left-handed (det = −1); a pose needs a right-handed frame',
      json: '{"origin":[0,0,0],"basis":[[1,0,0],[0,1,0],[0,0,-1]]}',
      jsonMessage: 'poses[1].basis: basis is left-handed (det = −1); a pose needs a right-handed frame',
    });
  });

  it('too few poses', () => {
    const m = fresh();
    for (const [n, doc] of [[0, { poses: [] }], [1, { poses: [P()] }]]) {
      const message = `poses: ${n} pose(s) given, at least 2 needed`;
      throwsError(() => new Motion(doc), message);
      throwsUnchanged(m, () => m.loadDocument(doc), message);
      throwsUnchanged(m, () => m.loadJson(JSON.stringify(doc)), message);
      throwsError(() => Motion.fromJson(JSON.stringify(doc)), message);
      throwsError(() => Motion.fromPoses(arrayWith([0, 0, 0, 1, 0, 0, 0]).subarray(0, 7 * n)), message);
    }
    const two = new Motion({ poses: [P(), P({ origin: [1, 0, 0] })] });
    throwsUnchanged(two, () => two.removePose(0), 'poses: 1 pose(s) given, at least 2 needed');
    throwsError(() => sb.screwPairs(new Float64Array(0), new Float64Array(0), [0.5]), /^ends: 0 start poses, 0 end poses and 1 fractions is out of range/);
  });

  it('unknown option values', () => {
    const m = fresh();
    const doc = docWith(P());
    const cases = [
      [{ scheme: 'cubic' }, "scheme: unknown value 'cubic' (expected bspline, fourpoint, jarek, j)"],
      [{ rules: 'v3' }, "rules: unknown value 'v3' (expected direct, split (also split-then-tweak))"],
      [{ levle: 3 }, 'invalid options: unknown field `levle`, expected one of `scheme`, `s`, `j`, `rules`, `levels`'],
      [{ levels: -1 }, 'levels: -1 is out of range (expected a whole number from 0 to 19; more levels never fit the limit of 1048576 refined poses)'],
      [{ levels: 2.5 }, 'levels: 2.5 is out of range (expected a whole number from 0 to 19; more levels never fit the limit of 1048576 refined poses)'],
      [{ scheme: 'j', s: 0.3, rules: 'split' }, 'rules: the J_s family is defined with the direct rules only'],
      ['fast', 'invalid options: expected an object {scheme?, s?, rules?, levels?}, got string'],
    ];
    for (const [options, message] of cases) {
      throwsError(() => new Motion(doc, options), message, JSON.stringify(options));
      throwsError(() => Motion.fromJson(JSON.stringify(doc), options), message, JSON.stringify(options));
      throwsError(() => Motion.fromPoses(arrayWith([0, 0, 0, 1, 0, 0, 0]), true, options), message, JSON.stringify(options));
      throwsUnchanged(m, () => m.setOptions(options), message, JSON.stringify(options));
    }
    throwsUnchanged(m, () => m.setScheme('cubic'), "scheme: unknown value 'cubic' (expected bspline, fourpoint, jarek, j)");
    throwsUnchanged(m, () => m.setRules('v3'), "rules: unknown value 'v3' (expected direct, split (also split-then-tweak))");
    throwsError(() => Motion.fromPreset('nope'), /^preset: unknown value 'nope' \(expected /);
  });

  it('levels beyond the cap', () => {
    const m = fresh();
    const cap = sb.limits().maxRefinedPoses;
    for (const levels of [19, 20, 32, 64, 1000, 2 ** 32, 1e300]) {
      // Up to maxLevels the memory guard counts the poses; beyond it no input fits.
      const message = levels <= sb.limits().maxLevels
        ? /^levels: the result would have \d+ poses, more than the limit of 1048576$/
        : /^levels: \S+ is out of range \(expected a whole number from 0 to 19; more levels never fit the limit of 1048576 refined poses\)$/;
      throwsUnchanged(m, () => m.setLevels(levels), message, `setLevels(${levels})`);
      throwsUnchanged(m, () => m.setOptions({ levels }), message, `setOptions(${levels})`);
      throwsError(() => new Motion(docWith(P()), { levels }), message, `constructor(${levels})`);
    }
    // 4 · 2^18 = 2^20 is allowed (the cap is on the result); that cycle then cannot grow.
    const ring = new Motion({ poses: [...docWith(P()).poses, P({ origin: [0, 4, 0] })] }, { levels: 18 });
    assert.equal(ring.refinedCount, cap);
    throwsUnchanged(ring, () => ring.insertPose(0), 'levels: the result would have 1310720 poses, more than the limit of 1048576');
    throwsUnchanged(ring, () => ring.setClosed(false), /^levels: the result would have \d+ poses, more than the limit of 1048576$/);
    ring.free();
  });

  it('malformed input', () => {
    const m = fresh();
    const texts = [
      ['{"poses": [', /^invalid motion document: EOF while parsing a list at line 1 column 11$/],
      ['{"poses": [{"origin": "here", "rotation": [1,0,0,0]}]}', /^invalid motion document: invalid type: string "here", expected an array of length 3 at line 1 column \d+$/],
      ['{"poses": [], "clossed": true}', /^invalid motion document: unknown field `clossed`/],
      ['', /^invalid motion document: EOF while parsing a value at line 1 column 0$/],
    ];
    for (const [text, message] of texts) {
      throwsError(() => Motion.fromJson(text), message, text);
      throwsUnchanged(m, () => m.loadJson(text), message, text);
    }
    throwsUnchanged(m, () => m.loadJson(42), 'text: expected a string, got number');
    throwsUnchanged(m, () => m.loadDocument({ poses: [P(), 7] }), 'poses[1]: invalid motion document: expected an object {origin, rotation} or {origin, basis}, got number');
    throwsUnchanged(m, () => m.setPose(1, P({ origin: [0, 0] })), 'pose.origin: invalid pose: invalid length 2, expected an array of length 3');
    throwsUnchanged(m, () => m.setPose(1, P({ rotation: ID, basis: [[1, 0, 0], [0, 1, 0], [0, 0, 1]] })), "pose: give either 'rotation' or 'basis', not both");
    throwsError(() => Motion.fromPoses([1, 2, 3]), /^poses: length 3 is out of range \(expected a multiple of 7/);
    throwsError(() => Motion.fromPoses('0,0,0,1,0,0,0'), /^poses: expected a Float64Array or an array of numbers, got string/);
  });

  it('oversized input', () => {
    const m = fresh();
    const max = sb.limits().maxDocumentBytes;
    const big = ' '.repeat(max + 1);
    const message = `document: ${max + 1} bytes is out of range (expected at most ${max} bytes)`;
    throwsError(() => Motion.fromJson(big), message);
    throwsUnchanged(m, () => m.loadJson(big), message);
    const many = new Float64Array(7 * (sb.limits().maxRefinedPoses + 1));
    throwsError(() => Motion.fromPoses(many), /^poses: length \d+ is out of range \(expected .*at most/);
    throwsUnchanged(m, () => m.posesAt(new Float64Array(sb.limits().maxBatch + 1)), /^us: length \d+ is out of range/);
    throwsUnchanged(m, () => m.sample(sb.limits().maxBatch + 1), /^count: \d+ is out of range/);
  });
});
