// The JS API of the built package (pkg/, from scripts/build-pkg.sh), method by method:
//
//   node --test tests/js/                      # what scripts/test.d/js-api.sh runs
//   SCREWBENDER_PKG=/path/to/node.js node --test tests/js/
//
// Typed-array layouts are checked against the object forms, the numbers against closed forms
// (circle, helix, the screw example A of docs/math/screw.md §7), and every bad input against both its message and
// the unchanged state of the object (JSON and options before/after, and it keeps working).
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { describe, it } from 'node:test';

import { MAX_LEVELS } from '../../www/js/element/options.js';
import { entry, sb } from './package.mjs';

const { Motion } = sb;

// ---- helpers ----------------------------------------------------------------------------------

const H = Math.SQRT1_2;
const ID = [1, 0, 0, 0];
const rz = (a) => [Math.cos(a / 2), 0, 0, Math.sin(a / 2)];

function near(actual, expected, tol, what = 'value') {
  assert.equal(actual.length, expected.length, `${what}: length`);
  for (let k = 0; k < expected.length; k++) {
    assert.ok(
      Math.abs(actual[k] - expected[k]) <= tol,
      `${what}[${k}]: got ${actual[k]}, expected ${expected[k]} (tol ${tol})\n  got [${Array.from(actual)}]\n  expected [${expected}]`,
    );
  }
}

/** q and −q are the same rotation. */
function nearQuat(q, e, tol, what = 'quaternion') {
  const dot = q[0] * e[0] + q[1] * e[1] + q[2] * e[2] + q[3] * e[3];
  near(Array.from(q, (v) => (dot < 0 ? -v : v)), e, tol, what);
}

function nearPose(p, o, q, tol, what = 'pose') {
  near(p.origin, o, tol, `${what}.origin`);
  nearQuat(p.rotation, q, tol, `${what}.rotation`);
}

/** The pose at `k` of a 7-stride array as an object. */
function poseOf(array, k) {
  const a = array.subarray(7 * k, 7 * k + 7);
  return { origin: [a[0], a[1], a[2]], rotation: [a[3], a[4], a[5], a[6]] };
}

/** Rotation matrix columns of a quaternion [w, x, y, z]. */
function quatColumns([w, x, y, z]) {
  return [
    [1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)],
    [2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)],
    [2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)],
  ];
}

const doc2 = () => ({
  closed: true,
  poses: [
    { origin: [0, 0, 0], rotation: ID },
    { origin: [4, 0, 0], rotation: [H, 0, 0, H] },
    { origin: [4, 4, 1], rotation: [0, 0, 0, 1] },
  ],
});

/** Everything observable about a motion's state. */
function snapshot(m) {
  return {
    json: m.toJson(),
    options: m.options(),
    closed: m.closed,
    name: m.name,
    poseCount: m.poseCount,
    refined: checksum(m.subdivide()),
  };
}

/** Length and a position-weighted sum: equal arrays give equal checksums (cheap for 7 M numbers). */
function checksum(array) {
  let sum = 0;
  for (let k = 0; k < array.length; k++) sum += array[k] * ((k % 1021) + 1);
  return [array.length, sum];
}

/** Asserts that `fn` throws an Error matching `message` and leaves `m` exactly as it was. */
function throwsUnchanged(m, fn, message) {
  const before = snapshot(m);
  assert.throws(fn, (e) => {
    assert.ok(e instanceof Error, `not an Error: ${e}`);
    if (message instanceof RegExp) assert.match(e.message, message);
    else assert.equal(e.message, message);
    return true;
  });
  assert.deepEqual(snapshot(m), before, 'state changed after the error');
  // …and the object keeps working.
  assert.ok(m.poseAt(0.5).origin.every(Number.isFinite));
}

// ---- module-level functions ------------------------------------------------------------------

describe('module', () => {
  it('version matches package.json', () => {
    const pkg = JSON.parse(readFileSync(new URL('package.json', entry), 'utf8'));
    assert.equal(sb.version(), pkg.version);
  });

  it('limits', () => {
    assert.deepEqual(sb.limits(), {
      maxRefinedPoses: 1048576,
      maxLevels: 19,
      defaultLevels: 5,
      maxBatch: 1048576,
      maxDocumentBytes: 16777216,
      poseStride: 7,
      matrixStride: 16,
      kinematicsStride: 16,
    });
  });

  it('the element and the lessons cap levels where the core does', () => {
    // One level more than maxLevels never fits maxRefinedPoses, even for two poses.
    assert.equal(2 * 2 ** sb.limits().maxLevels, sb.limits().maxRefinedPoses);
    assert.equal(MAX_LEVELS, sb.limits().maxLevels);
    const two = [0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0];
    assert.equal(Motion.fromPoses(two, true, { levels: MAX_LEVELS }).refinedCount, 2 ** 20);
    assert.throws(() => Motion.fromPoses(two, true, { levels: MAX_LEVELS + 1 }), /levels: 20 is out of range \(expected a whole number from 0 to 19/);
  });

  it('the former preset names are aliases of the new ones', () => {
    assert.deepEqual(sb.scenes(), sb.presets());
    assert.equal(Motion.fromScene('circle4').toJson(), Motion.fromPreset('circle4').toJson());
  });

  it('presets: listed, typed, loadable', () => {
    const list = sb.presets();
    assert.ok(list.length >= 10);
    const dts = readFileSync(new URL('screwbender.d.ts', entry), 'utf8');
    const union = dts.match(/export type PresetId =([^;]*);/)[1];
    const typed = [...union.matchAll(/'([^']+)'/g)].map((x) => x[1]);
    assert.deepEqual(list.map((s) => s.id), typed, 'PresetId in the .d.ts is out of date');
    const kinds = ['bar', 'block', 'cylinder', 'cone', 'sphere', 'starPrism', 'pendulum', 'wedge', 'triangle', 'iBeam', 'molecule'];
    for (const s of list) {
      for (const key of ['id', 'label', 'figure', 'description']) assert.equal(typeof s[key], 'string');
      assert.equal(typeof s.closed, 'boolean');
      assert.ok(['bspline', 'fourpoint', 'jarek'].includes(s.scheme));
      assert.ok(Number.isInteger(s.levels) && s.poseCount >= 2);
      for (const shape of [s.shape, ...s.morphShapes]) assert.ok(kinds.includes(shape.kind), shape.kind);
      const m = Motion.fromPreset(s.id);
      assert.equal(m.poseCount, s.poseCount);
      assert.equal(m.closed, s.closed);
      assert.equal(m.name, s.id);
      assert.deepEqual(m.options(), { scheme: s.scheme, s: { bspline: 1, fourpoint: 0, jarek: 0.5 }[s.scheme], rules: 'direct', levels: s.levels });
      m.free();
    }
    assert.deepEqual(list.find((s) => s.id === 'pip_morph5').morphShapes.length, 5);
  });

  it('presets: how a figure shows each (name, strobe, selection, body points) comes from the core', () => {
    const finite3 = (p) => Array.isArray(p) && p.length === 3 && p.every(Number.isFinite);
    for (const s of sb.presets()) {
      assert.ok(typeof s.name === 'string' && s.name !== s.id, s.id);
      assert.ok(Number.isInteger(s.strobe) && s.strobe >= 1, s.id);
      assert.ok(s.selected === undefined || (Number.isInteger(s.selected) && s.selected < s.poseCount), s.id);
      // The object's origin and at least one far point on it, whose trajectory shows the turning.
      assert.ok(s.bodyPoints.length >= 2 && s.bodyPoints.every(finite3), `${s.id}: ${JSON.stringify(s.bodyPoints)}`);
      assert.ok(s.bodyPoints.some((p) => Math.hypot(...p) > 0), s.id);
    }
    // A named object gets the points of the same table: the bar's are those of a preset bar.
    const bar = sb.presets().find((s) => s.shape.kind === 'bar' && s.shape.length === 2);
    assert.deepEqual(sb.objectBodyPoints('bar'), bar?.bodyPoints);
    for (const name of ['bar', 'block', 'cylinder', 'cone', 'sphere', 'star', 'pendulum', 'wedge']) {
      const points = sb.objectBodyPoints(name);
      assert.ok(points.length >= 2 && points.every(finite3), name);
    }
    assert.equal(sb.objectBodyPoints('teapot'), undefined);
    assert.equal(sb.objectBodyPoints(42), undefined);
  });

  it('screw: example A of docs/math/screw.md §7 (quarter turn about x = y = 1, lift 1)', () => {
    const b = { origin: [2, 0, 1], rotation: rz(Math.PI / 2) };
    const mid = sb.screw({ origin: [0, 0, 0], rotation: ID }, 0.5, b);
    nearPose(mid, [1, -(Math.SQRT2 - 1), 0.5], rz(Math.PI / 4), 1e-15);
    nearPose(sb.screw({ origin: [0, 0, 0], rotation: ID }, 1, b), b.origin, b.rotation, 1e-15);
  });

  it('screwPoses: one screw at many t, 7 numbers per pose', () => {
    const a = { origin: [1, 2, 3], rotation: rz(0.3) };
    const b = { origin: [-2, 0.5, 4], basis: [[0, 1, 0], [-1, 0, 0], [0, 0, 1]] };
    const ts = new Float64Array([0, 0.25, 0.5, 1, 1.5, -0.5]);
    const out = sb.screwPoses(a, b, ts);
    assert.ok(out instanceof Float64Array);
    assert.equal(out.length, 7 * ts.length);
    ts.forEach((t, k) => {
      const p = sb.screw(a, t, b);
      near(out.subarray(7 * k, 7 * k + 7), [...p.origin, ...p.rotation], 1e-14, `t=${t}`);
    });
    nearPose(poseOf(out, 0), a.origin, a.rotation, 1e-15);
    nearPose(poseOf(out, 3), b.origin, rz(Math.PI / 2), 1e-14);
    // Plain arrays are accepted too.
    assert.deepEqual(sb.screwPoses(a, b, [0.25]), out.subarray(7, 14));
    assert.equal(sb.screwPoses(a, b, new Float64Array(0)).length, 0);
  });

  it('screwPairs: full evaluations', () => {
    const starts = new Float64Array([0, 0, 0, ...ID, 1, 1, 1, ...rz(1)]);
    const ends = new Float64Array([2, 0, 1, ...rz(Math.PI / 2), 1, 1, 1, ...rz(2)]);
    const out = sb.screwPairs(starts, ends, new Float64Array([0.5, 0.5]));
    nearPose(poseOf(out, 0), [1, -(Math.SQRT2 - 1), 0.5], rz(Math.PI / 4), 1e-15);
    nearPose(poseOf(out, 1), [1, 1, 1], rz(1.5), 1e-15);
    assert.throws(() => sb.screwPairs(starts, ends, [0.5]), {
      message: 'ends: 2 start poses, 2 end poses and 1 fractions is out of range (expected as many start poses and end poses as fractions)',
    });
    assert.throws(() => sb.screwPairs(starts.subarray(1), ends, [0.5, 0.5]), {
      message: /^starts: length 13 is out of range \(expected a multiple of 7/,
    });
    const zero = starts.slice();
    zero.set([0, 0, 0, 0], 3);
    assert.throws(() => sb.screwPairs(zero, ends, [0.5, 0.5]), { message: 'starts[0].rotation: zero quaternion' });
  });

  it('screwPairs: batches over many chunks equal one screw at a time, bit for bit', () => {
    // 1000 pairs cross several of the chunks the module works in; fractions inside and outside
    // [0, 1], and a few rare pairs (identical poses, a pure translation) among them.
    const n = 1000;
    let seed = 5;
    const random = () => (seed = (seed * 16807) % 2147483647) / 2147483647;
    const pose = () => {
      const q = [random() - 0.5, random() - 0.5, random() - 0.5, random() - 0.5];
      const l = Math.hypot(...q);
      return [10 * random() - 5, 10 * random() - 5, 10 * random() - 5, ...q.map((v) => v / l)];
    };
    const starts = new Float64Array(7 * n);
    const ends = new Float64Array(7 * n);
    const ts = new Float64Array(n);
    for (let k = 0; k < n; k++) {
      const a = pose();
      const b = k % 97 === 3 ? a : k % 89 === 5 ? [a[0] + 1, a[1], a[2], ...a.slice(3)] : pose();
      starts.set(a, 7 * k);
      ends.set(b, 7 * k);
      ts[k] = 3 * random() - 1;
    }
    const out = sb.screwPairs(starts, ends, ts);
    assert.equal(out.length, 7 * n);
    for (let k = 0; k < n; k++) {
      const one = sb.screw(poseOf(starts, k), ts[k], poseOf(ends, k));
      assert.deepEqual(Array.from(out.subarray(7 * k, 7 * k + 7)), [...one.origin, ...one.rotation], `pair ${k}`);
    }
    // A bad pose in a late chunk is named; a bad start is named before a bad end in an
    // earlier chunk, as the arguments are read.
    const badStart = starts.slice();
    badStart[7 * 900 + 3] = NaN;
    assert.throws(() => sb.screwPairs(badStart, ends, ts), { message: /^starts\[900\]\.rotation/ });
    const badEnd = ends.slice();
    badEnd[7 * 10] = Infinity;
    assert.throws(() => sb.screwPairs(badStart, badEnd, ts), { message: /^starts\[900\]\.rotation/ });
    assert.throws(() => sb.screwPairs(starts, badEnd, ts), { message: /^ends\[10\]\.origin/ });
  });

  it('screwInfo: kinds and parameters', () => {
    const o = { origin: [0, 0, 0], rotation: ID };
    assert.deepEqual(sb.screwInfo(o, o), { kind: 'identity', angle: 0, slide: 0 });
    const t = sb.screwInfo(o, { origin: [0, 3, 4], rotation: ID });
    assert.equal(t.kind, 'translation');
    near(t.direction, [0, 0.6, 0.8], 1e-15);
    assert.equal(t.slide, 5);
    const g = sb.screwInfo(o, { origin: [2, 0, 1], rotation: rz(Math.PI / 2) });
    assert.equal(g.kind, 'general');
    near(g.direction, [0, 0, 1], 1e-15, 'direction');
    near([g.angle, g.slide, g.pitch], [Math.PI / 2, 1, 2 / Math.PI], 1e-15, 'angle, slide, pitch');
    near(g.foot, [1, 1, 0], 1e-15, 'foot');
    near(g.point, [1, 1, 0.5], 1e-15, 'point');
  });

  it('posesToMatrices: column-major 4x4 float32', () => {
    const q = [0.5, 0.5, 0.5, 0.5]; // 120° about (1,1,1): x→y→z→x
    const m = sb.posesToMatrices([1, 2, 3, ...q]);
    assert.ok(m instanceof Float32Array);
    near(m, [0, 1, 0, 0, 0, 0, 1, 0, 1, 0, 0, 0, 1, 2, 3, 1], 1e-7);
    assert.throws(() => sb.posesToMatrices([1, 2, 3]), { message: /^poses: length 3 is out of range/ });
  });
});

// ---- Motion -----------------------------------------------------------------------------------

describe('Motion: construction and documents', () => {
  it('from a document object, JSON, poses; round trips', () => {
    const m = new Motion(doc2());
    assert.equal(m.poseCount, 3);
    assert.equal(m.closed, true);
    assert.equal(m.name, undefined);
    assert.deepEqual(m.options(), { scheme: 'fourpoint', s: 0, rules: 'direct', levels: 5 });
    const text = m.toJson();
    assert.equal(JSON.parse(text).poses.length, 3);
    const fromJson = Motion.fromJson(text);
    assert.equal(fromJson.toJson(), text);
    const doc = m.toDocument();
    assert.deepEqual(Object.keys(doc), ['closed', 'poses']);
    assert.deepEqual(doc.poses[1].origin, [4, 0, 0]);
    near(doc.poses[1].rotation, [H, 0, 0, H], 1e-16);
    assert.equal(new Motion(doc).toJson(), text);
    const fromPoses = Motion.fromPoses(m.poses(), true);
    assert.equal(fromPoses.toJson(), text);
    assert.deepEqual(Array.from(fromPoses.subdivide()), Array.from(m.subdivide()));
    assert.equal(Motion.fromPoses(m.poses()).closed, true);
    assert.equal(Motion.fromPoses(m.poses(), false, { levels: 2 }).refinedCount, 9);
  });

  it('basis poses, names, open documents, options argument', () => {
    const m = new Motion(
      {
        name: 'demo',
        closed: false,
        poses: [
          { origin: [0, 0, 0], rotation: ID },
          { origin: [4, 0, 0], basis: [[0, 1, 0], [-1, 0, 0], [0, 0, 1]] },
        ],
      },
      { scheme: 'jarek', rules: 'split', levels: 3 },
    );
    assert.equal(m.name, 'demo');
    assert.equal(m.closed, false);
    nearQuat(m.pose(1).rotation, [H, 0, 0, H], 1e-15);
    assert.deepEqual(m.options(), { scheme: 'jarek', s: 0.5, rules: 'split', levels: 3 });
    assert.equal(m.refinedCount, 9);
    assert.deepEqual(m.domain(), [0, 1]);
    assert.match(m.toJson(), /"name": "demo"/);
    m.setName('other');
    assert.equal(m.name, 'other');
    m.setName(undefined);
    assert.equal(m.name, undefined);
    assert.equal(m.toDocument().name, undefined);
  });

  it('loadJson / loadDocument keep the options', () => {
    const m = Motion.fromPreset('circle4');
    m.setLevels(2);
    m.loadJson(JSON.stringify(doc2()));
    assert.equal(m.poseCount, 3);
    assert.equal(m.levels, 2);
    m.loadDocument({ closed: false, poses: doc2().poses.slice(0, 2) });
    assert.equal(m.poseCount, 2);
    assert.equal(m.closed, false);
    assert.equal(m.refinedCount, 5);
  });
});

describe('Motion: editing', () => {
  it('pose, poses, setPose', () => {
    const m = new Motion(doc2());
    const all = m.poses();
    assert.ok(all instanceof Float64Array);
    assert.equal(all.length, 21);
    near(all.subarray(7, 14), [4, 0, 0, H, 0, 0, H], 1e-16);
    m.setPose(1, { origin: [5, 0, 0], rotation: [1, 0, 0, 0] });
    assert.deepEqual(m.pose(1), { origin: [5, 0, 0], rotation: [1, 0, 0, 0] });
    // Accepts quaternions within 1e-3 of unit length and normalises them.
    m.setPose(1, { origin: [5, 0, 0], rotation: [0.707, 0, 0, 0.707] });
    near(m.pose(1).rotation, [H, 0, 0, H], 1e-15);
  });

  it('setPose during a drag updates the refined motion locally, identical to a rebuild', () => {
    for (const closed of [true, false]) {
      const m = Motion.fromPreset('l_cycle_rotated');
      m.setClosed(closed);
      m.setLevels(4);
      m.subdivide(); // the refined motion exists: setPose takes the local path
      for (let step = 0; step < 6; step += 1) {
        const i = (step * 5) % m.poseCount;
        const p = m.pose(i);
        m.setPose(i, { origin: [p.origin[0] + 0.3, p.origin[1] - 0.2, p.origin[2] + 0.1], rotation: p.rotation });
        const fresh = new Motion(m.toDocument(), m.options());
        assert.deepEqual(Array.from(m.subdivide()), Array.from(fresh.subdivide()), `closed=${closed} step ${step}`);
      }
    }
  });

  it('insertPose: default screw midpoint, explicit pose, cyclic wrap', () => {
    const m = new Motion(doc2());
    const p0 = m.pose(0);
    const p1 = m.pose(1);
    assert.equal(m.insertPose(0), 1);
    assert.equal(m.poseCount, 4);
    nearPose(m.pose(1), sb.screw(p0, 0.5, p1).origin, sb.screw(p0, 0.5, p1).rotation, 1e-15);
    // Last pose of a cycle: between P_{n-1} and P_0.
    const last = m.pose(3);
    assert.equal(m.insertPose(3), 4);
    const mid = sb.screw(last, 0.5, p0);
    nearPose(m.pose(4), mid.origin, mid.rotation, 1e-15);
    assert.equal(m.insertPose(4, { origin: [9, 9, 9], rotation: ID }), 5);
    assert.deepEqual(m.pose(5), { origin: [9, 9, 9], rotation: ID });
    assert.equal(m.poseCount, 6);
    // Open: an explicit pose may follow the last one.
    m.setClosed(false);
    assert.equal(m.insertPose(5, { origin: [1, 1, 1], rotation: ID }), 6);
    assert.equal(m.poseCount, 7);
  });

  it('removePose', () => {
    const m = new Motion(doc2());
    m.removePose(1);
    assert.equal(m.poseCount, 2);
    assert.deepEqual(m.pose(1).origin, [4, 4, 1]);
  });

  it('setClosed changes the domain and the refined count', () => {
    const m = new Motion(doc2(), { levels: 3 });
    assert.deepEqual(m.domain(), [0, 3]);
    assert.equal(m.refinedCount, 24);
    m.setClosed(false);
    assert.deepEqual(m.domain(), [0, 2]);
    assert.equal(m.refinedCount, 17);
    assert.equal(m.subdivide().length, 17 * 7);
  });
});

describe('Motion: options', () => {
  it('setters and getters', () => {
    const m = new Motion(doc2());
    m.setScheme('bspline');
    assert.equal(m.scheme, 'bspline');
    assert.equal(m.s, 1);
    m.setRules('split');
    assert.equal(m.rules, 'split');
    m.setRules('direct');
    m.setS(0.3);
    assert.equal(m.scheme, 'j');
    assert.equal(m.s, 0.3);
    m.setScheme('jarek');
    m.setScheme('j'); // the J_s family with the current parameter
    assert.equal(m.s, 0.5);
    m.setLevels(0);
    assert.equal(m.levels, 0);
    assert.deepEqual(Array.from(m.subdivide()), Array.from(m.poses()));
    m.setOptions({ scheme: 'fourpoint', levels: 4 });
    assert.deepEqual(m.options(), { scheme: 'fourpoint', s: 0, rules: 'direct', levels: 4 });
    // Round trip of options(); several options validated together.
    m.setOptions(m.options());
    m.setRules('split');
    m.setOptions({ scheme: 'j', s: 0.25, rules: 'direct' });
    assert.deepEqual(m.options(), { scheme: 'j', s: 0.25, rules: 'direct', levels: 4 });
    m.setOptions({ s: -1 });
    assert.equal(m.s, -1);
    // `j`, the former name of `s`, still works for one release: setJ, the getter, setOptions.
    m.setJ(0.4);
    assert.equal(m.s, 0.4);
    assert.equal(m.j, 0.4);
    m.setOptions({ j: 0.2 });
    assert.deepEqual(m.options(), { scheme: 'j', s: 0.2, rules: 'direct', levels: 4 });
    m.setOptions({ scheme: 'j', s: 0.6, j: 0.6 }); // both, agreeing
    assert.equal(m.s, 0.6);
    m.setOptions({});
    m.setOptions(undefined);
  });

  it('the J_s family contains the named schemes', () => {
    const m = Motion.fromPreset('bunny6');
    m.setLevels(4);
    for (const [scheme, j, tol] of [['fourpoint', 0, 0], ['jarek', 0.5, 0], ['bspline', 1, 1e-12]]) {
      m.setScheme(scheme);
      const named = m.subdivide();
      m.setS(j);
      near(m.subdivide(), Array.from(named), tol, `J(${j}) vs ${scheme}`);
    }
  });

  it('4-point interpolates, B-spline does not; split rules differ from direct', () => {
    const m = Motion.fromPreset('l_cycle_rotated');
    const control = m.poses();
    const refined = m.subdivide();
    for (let i = 0; i < m.poseCount; i++) {
      near(refined.subarray(7 * 32 * i, 7 * 32 * i + 7), Array.from(control.subarray(7 * i, 7 * i + 7)), 1e-12, `pose ${i}`);
    }
    m.setScheme('bspline');
    const bspline = m.subdivide();
    assert.ok(Math.abs(bspline[7 * 32] - control[7]) > 1e-3);
    m.setRules('split');
    const split = m.subdivide();
    assert.ok(split.some((v, k) => Math.abs(v - bspline[k]) > 1e-6));
  });
});

describe('Motion: evaluation and typed-array layouts', () => {
  const circle = () => Motion.fromPreset('circle4');
  const circlePose = (u) => {
    const a = (Math.PI / 2) * u;
    return [[3 * Math.cos(a), 3 * Math.sin(a), 0], rz(a)];
  };

  it('subdivide: 7 numbers per pose at u = j / 2^levels', () => {
    const m = circle();
    const r = m.subdivide();
    assert.ok(r instanceof Float64Array);
    assert.equal(r.length, 128 * 7);
    assert.equal(m.refinedCount, 128);
    for (const j of [0, 1, 17, 127]) {
      const [o, q] = circlePose(j / 32);
      nearPose(poseOf(r, j), o, q, 1e-12, `refined ${j}`);
      const norm = Math.hypot(...r.subarray(7 * j + 3, 7 * j + 7));
      assert.ok(Math.abs(norm - 1) < 1e-15);
    }
  });

  it('refinedMatrices: column-major, consistent with the poses', () => {
    const m = Motion.fromPreset('cylinder5');
    const poses = m.subdivide();
    const mats = m.refinedMatrices();
    assert.ok(mats instanceof Float32Array);
    assert.equal(mats.length, (poses.length / 7) * 16);
    for (const j of [0, 5, 77]) {
      const p = poseOf(poses, j);
      const cols = quatColumns(p.rotation);
      const expected = [...cols[0], 0, ...cols[1], 0, ...cols[2], 0, ...p.origin, 1];
      near(mats.subarray(16 * j, 16 * j + 16), expected, 1e-5, `matrix ${j}`);
    }
    assert.deepEqual(mats, sb.posesToMatrices(poses));
  });

  it('poseAt, posesAt, domain', () => {
    const m = circle();
    assert.deepEqual(m.domain(), [0, 4]);
    for (const u of [0, 0.3, 1, 2.75, 3.999, 4, 5.5, -1]) {
      const [o, q] = circlePose(u);
      nearPose(m.poseAt(u), o, q, 1e-12, `u=${u}`);
    }
    const us = new Float64Array([0.1, 2.2, 3.3]);
    const batch = m.posesAt(us);
    us.forEach((u, k) => {
      const p = m.poseAt(u);
      near(batch.subarray(7 * k, 7 * k + 7), [...p.origin, ...p.rotation], 0, `posesAt ${u}`);
    });
  });

  it('sample and sampleMatrices: [0, n) closed, [0, m-1] open', () => {
    const m = circle();
    const s = m.sample(8);
    assert.equal(s.length, 56);
    for (let k = 0; k < 8; k++) {
      const [o, q] = circlePose(k / 2);
      nearPose(poseOf(s, k), o, q, 1e-12, `closed sample ${k}`);
    }
    assert.deepEqual(m.sampleMatrices(8), sb.posesToMatrices(s));
    assert.equal(m.sample(0).length, 0);
    const h = Motion.fromPreset('helix_open');
    const hs = h.sample(11);
    for (const k of [0, 3, 10]) {
      const u = k / 2;
      const a = (Math.PI / 4) * u;
      nearPose(poseOf(hs, k), [3 * Math.cos(a), 3 * Math.sin(a), 0.6 * u], rz(a), 1e-11, `open sample ${k}`);
    }
  });

  it('kinematicsAt: the circle’s closed form', () => {
    const m = circle();
    const u = 0.3;
    const a = (Math.PI / 2) * u;
    const w = Math.PI / 2; // rad per parameter unit
    const k = m.kinematicsAt(u);
    near(k.position, [3 * Math.cos(a), 3 * Math.sin(a), 0], 1e-12, 'position');
    near(k.velocity, [-3 * w * Math.sin(a), 3 * w * Math.cos(a), 0], 1e-12, 'velocity');
    near(k.acceleration, [-3 * w * w * Math.cos(a), -3 * w * w * Math.sin(a), 0], 1e-12, 'acceleration');
    near(k.angularVelocity, [0, 0, w], 1e-12, 'angular velocity');
    near(k.angularAcceleration, [0, 0, 0], 0, 'angular acceleration');
    // A body point 1 unit along the local x axis is on the circle of radius 4.
    const k1 = m.kinematicsAt(u, [1, 0, 0]);
    near(k1.position, [4 * Math.cos(a), 4 * Math.sin(a), 0], 1e-12, 'local point');
    near(k1.velocity, [-4 * w * Math.sin(a), 4 * w * Math.cos(a), 0], 1e-12, 'local point velocity');
  });

  it('sampleKinematics: 16 numbers per sample, same as kinematicsAt', () => {
    const m = Motion.fromPreset('bunny6');
    const n = 12;
    const local = [0.5, -0.2, 0.1];
    const ks = m.sampleKinematics(n, local);
    assert.ok(ks instanceof Float64Array);
    assert.equal(ks.length, 16 * n);
    for (const j of [0, 5, 11]) {
      const row = ks.subarray(16 * j, 16 * j + 16);
      const u = (6 * j) / n;
      assert.equal(row[0], u);
      const k = m.kinematicsAt(u, local);
      near(row.subarray(1), [...k.position, ...k.velocity, ...k.acceleration, ...k.angularVelocity, ...k.angularAcceleration], 0, `sample ${j}`);
    }
    assert.equal(m.sampleKinematics(3).length, 48);
  });

  it('spanScrews: one per control span, for display', () => {
    const m = Motion.fromPreset('circle4');
    const screws = m.spanScrews();
    assert.equal(screws.length, 4);
    for (const s of screws) {
      assert.equal(s.kind, 'general');
      near([s.angle, s.slide, s.pitch], [Math.PI / 2, 0, 0], 1e-15);
      near(s.direction, [0, 0, 1], 1e-15);
      near(s.foot, [0, 0, 0], 1e-15);
      near(s.point, [0, 0, 0], 1e-15);
    }
    m.setClosed(false);
    assert.equal(m.spanScrews().length, 3);
    const t = Motion.fromPoses([0, 0, 0, ...ID, 1, 0, 0, ...ID], false).spanScrews();
    assert.deepEqual(t, [{ kind: 'translation', direction: [1, 0, 0], angle: 0, slide: 1 }]);
  });

  it('results are cached and invalidated by changes', () => {
    const m = circle();
    const a = m.subdivide();
    assert.deepEqual(m.subdivide(), a);
    m.setPose(0, { origin: [3, 0, 1], rotation: ID });
    assert.notDeepEqual(m.subdivide(), a);
  });
});

// ---- bad input --------------------------------------------------------------------------------

describe('bad input: clear Error, state unchanged', () => {
  const fresh = () => new Motion(doc2(), { levels: 3 });
  const P = (over) => ({ origin: [0, 0, 0], rotation: ID, ...over });
  const docWith = (pose) => ({ poses: [P(), pose] });

  const documentCases = [
    ['string for a number', docWith(P({ origin: [0, 0, 'x'] })), 'poses[1].origin[2]: invalid motion document: invalid type: string "x", expected f64'],
    ['missing origin', docWith({ rotation: ID }), 'poses[1]: invalid motion document: missing field `origin`'],
    ['3-element quaternion', docWith(P({ rotation: [1, 0, 0] })), 'poses[1].rotation: invalid motion document: invalid length 3, expected an array of length 4'],
    ['5-element quaternion', docWith(P({ rotation: [1, 0, 0, 0, 0] })), 'poses[1].rotation: invalid motion document: invalid length 5, expected an array of length 4'],
    ['NaN origin', docWith(P({ origin: [0, NaN, 0] })), 'poses[1].origin: not a finite number (NaN or infinity)'],
    ['Infinity in a quaternion', docWith(P({ rotation: [1, 0, Infinity, 0] })), 'poses[1].rotation: not a finite number (NaN or infinity)'],
    ['zero quaternion', docWith(P({ rotation: [0, 0, 0, 0] })), 'poses[1].rotation: zero quaternion'],
    ['non-unit quaternion', docWith(P({ rotation: [2, 0, 0, 0] })), /^poses\[1\]\.rotation: quaternion norm 2 is not 1/],
    ['left-handed basis', docWith({ origin: [0, 0, 0], basis: [[1, 0, 0], [0, 1, 0], [0, 0, -1]] }), /^poses\[1\]\.basis: basis is left-handed/],
    ['rotation and basis', docWith(P({ basis: [[1, 0, 0], [0, 1, 0], [0, 0, 1]] })), "poses[1]: give either 'rotation' or 'basis', not both"],
    ['unknown pose field', docWith(P({ rot: 1 })), 'poses[1]: invalid motion document: unknown field `rot`, expected one of `origin`, `rotation`, `basis`'],
    ['unknown document field', { clossed: true, poses: [P(), P()] }, 'invalid motion document: unknown field `clossed`, expected one of `name`, `closed`, `poses`, `times`, `velocities`'],
    ['one pose', { poses: [P()] }, 'poses: 1 pose(s) given, at least 2 needed'],
    ['pose not an object', { poses: [P(), 7] }, 'poses[1]: invalid motion document: expected an object {origin, rotation} or {origin, basis}, got number'],
    ['document not an object', 'hello', 'invalid motion document: expected an object {closed?, name?, poses: [...]}, got string'],
    ['no document', undefined, 'invalid motion document: expected an object {closed?, name?, poses: [...]}, got undefined'],
    ['closed not a boolean', { closed: 'yes', poses: [P(), P()] }, 'closed: invalid motion document: invalid type: string "yes", expected a boolean'],
  ];

  for (const [what, doc, message] of documentCases) {
    it(`constructor and loadDocument: ${what}`, () => {
      assert.throws(() => new Motion(doc), (e) => {
        assert.ok(e instanceof Error);
        if (message instanceof RegExp) assert.match(e.message, message);
        else assert.equal(e.message, message);
        return true;
      });
      const m = fresh();
      throwsUnchanged(m, () => m.loadDocument(doc), message);
    });
  }

  it('the JSON parser words value errors the same way', () => {
    const m = fresh();
    throwsUnchanged(m, () => m.loadJson(JSON.stringify(docWith(P({ rotation: [0, 0, 0, 0] })))), 'poses[1].rotation: zero quaternion');
    throwsUnchanged(m, () => m.loadJson('{"poses": ['), 'invalid motion document: EOF while parsing a list at line 1 column 11');
    throwsUnchanged(m, () => m.loadJson('{"poses": [{"origin": [0,0], "rotation": [1,0,0,0]}]}'), /^invalid motion document: invalid length 2, expected an array of length 3 at line 1/);
    throwsUnchanged(m, () => m.loadJson(42), 'text: expected a string, got number');
    assert.throws(() => Motion.fromJson('not json'), { message: /^invalid motion document: expected ident at line 1 column 2/ });
  });

  const poseCases = [
    ['string for a number', P({ origin: ['1', 0, 0] }), 'pose.origin[0]: invalid pose: invalid type: string "1", expected f64'],
    ['missing origin', { rotation: ID }, 'pose: invalid pose: missing field `origin`'],
    ['3-element quaternion', P({ rotation: [1, 0, 0] }), 'pose.rotation: invalid pose: invalid length 3, expected an array of length 4'],
    ['NaN', P({ origin: [NaN, 0, 0] }), 'pose.origin: not a finite number (NaN or infinity)'],
    ['Infinity', P({ rotation: [Infinity, 0, 0, 0] }), 'pose.rotation: not a finite number (NaN or infinity)'],
    ['zero quaternion', P({ rotation: [0, 0, 0, 0] }), 'pose.rotation: zero quaternion'],
    ['not an object', [0, 0, 0], 'pose: invalid pose: expected an object {origin, rotation} or {origin, basis}, got array'],
    ['null', null, 'pose: invalid pose: expected an object {origin, rotation} or {origin, basis}, got null'],
  ];
  for (const [what, pose, message] of poseCases) {
    it(`setPose / insertPose: ${what}`, () => {
      const m = fresh();
      throwsUnchanged(m, () => m.setPose(1, pose), message);
      if (pose !== null) throwsUnchanged(m, () => m.insertPose(1, pose), message);
    });
  }

  it('indices', () => {
    const m = fresh();
    throwsUnchanged(m, () => m.setPose(3, P()), 'index: 3 is out of range (expected an integer from 0 to 2)');
    throwsUnchanged(m, () => m.setPose(-1, P()), 'index: -1 is out of range (expected an integer from 0 to 2)');
    throwsUnchanged(m, () => m.setPose(1.5, P()), 'index: 1.5 is out of range (expected an integer from 0 to 2)');
    throwsUnchanged(m, () => m.setPose(NaN, P()), 'index: NaN is out of range (expected an integer from 0 to 2)');
    throwsUnchanged(m, () => m.setPose('1', P()), 'index: expected a number, got string');
    throwsUnchanged(m, () => m.removePose(3), 'index: 3 is out of range (expected an integer from 0 to 2)');
    throwsUnchanged(m, () => m.removePose(undefined), 'index: expected a number, got undefined');
    throwsUnchanged(m, () => m.insertPose(3), 'index: 3 is out of range (expected an integer from 0 to 2)');
    throwsUnchanged(m, () => m.pose(7), 'index: 7 is out of range (expected an integer from 0 to 2)');
    m.setClosed(false);
    // Open: no successor of the last pose to take a midpoint with.
    throwsUnchanged(m, () => m.insertPose(2), 'index: 2 is out of range (expected an integer from 0 to 1)');
  });

  it('removing below the minimum of 2 poses', () => {
    const m = fresh();
    m.removePose(0);
    throwsUnchanged(m, () => m.removePose(0), 'poses: 1 pose(s) given, at least 2 needed');
  });

  it('levels: cap checked at once, never stored', () => {
    const m = fresh();
    throwsUnchanged(m, () => m.setLevels(19), 'levels: the result would have 1572864 poses, more than the limit of 1048576');
    throwsUnchanged(m, () => m.setLevels(1e6), /^levels: 1000000 is out of range \(expected a whole number from 0 to 19; more levels never fit the limit of 1048576 refined poses\)$/);
    throwsUnchanged(m, () => m.setLevels(-1), 'levels: -1 is out of range (expected a whole number from 0 to 19; more levels never fit the limit of 1048576 refined poses)');
    throwsUnchanged(m, () => m.setLevels(2.5), 'levels: 2.5 is out of range (expected a whole number from 0 to 19; more levels never fit the limit of 1048576 refined poses)');
    throwsUnchanged(m, () => m.setLevels(NaN), 'levels: NaN is out of range (expected a whole number from 0 to 19; more levels never fit the limit of 1048576 refined poses)');
    throwsUnchanged(m, () => m.setLevels('3'), 'levels: expected a number, got string');
    throwsUnchanged(m, () => m.setOptions({ levels: 40 }), /^levels: 40 is out of range \(expected a whole number from 0 to 19/);
    throwsUnchanged(m, () => m.setOptions({ levels: 19 }), /^levels: the result would have/);
    assert.throws(() => new Motion(doc2(), { levels: 19 }), { message: /^levels: the result would have/ });
    // The cap depends on the pose count and on closed/open: those changes are checked too.
    const ring = Motion.fromPreset('circle4');
    ring.loadDocument({ poses: [...ring.toDocument().poses, ...ring.toDocument().poses] });
    ring.setLevels(17); // 8 · 2^17 = 1048576 poses: exactly the limit
    assert.equal(ring.refinedCount, 1048576);
    throwsUnchanged(ring, () => ring.insertPose(0), 'levels: the result would have 1179648 poses, more than the limit of 1048576');
    throwsUnchanged(ring, () => ring.setClosed(false), 'levels: the result would have 1572864 poses, more than the limit of 1048576');
    ring.free();
  });

  it('unknown scheme / rules strings and bad option combinations', () => {
    const m = fresh();
    throwsUnchanged(m, () => m.setScheme('cubic'), "scheme: unknown value 'cubic' (expected bspline, fourpoint, jarek, j)");
    throwsUnchanged(m, () => m.setScheme(3), 'scheme: expected a string, got number');
    throwsUnchanged(m, () => m.setRules('v3'), "rules: unknown value 'v3' (expected direct, split (also split-then-tweak))");
    throwsUnchanged(m, () => m.setS(NaN), 's: not a finite number (NaN or infinity)');
    throwsUnchanged(m, () => m.setS('0.5'), 's: expected a number, got string');
    throwsUnchanged(m, () => m.setOptions({ scheme: 'fourpoint', s: 0.3 }), "s: s = 0.3 contradicts scheme 'fourpoint' (whose J_s parameter is 0); use scheme 'j' for other values");
    throwsUnchanged(m, () => m.setOptions({ levle: 3 }), 'invalid options: unknown field `levle`, expected one of `scheme`, `s`, `j`, `rules`, `levels`');
    throwsUnchanged(m, () => m.setOptions({ levels: '3' }), 'levels: invalid options: invalid type: string "3", expected f64');
    throwsUnchanged(m, () => m.setOptions('fast'), 'invalid options: expected an object {scheme?, s?, rules?, levels?}, got string');
    throwsUnchanged(m, () => m.setOptions({ scheme: 'jarek', levels: 2, rules: 'nope' }), "rules: unknown value 'nope' (expected direct, split (also split-then-tweak))");
    m.setS(0.2);
    throwsUnchanged(m, () => m.setRules('split'), 'rules: the J_s family is defined with the direct rules only');
    m.setScheme('fourpoint');
    m.setRules('split');
    throwsUnchanged(m, () => m.setS(0.2), 'rules: the J_s family is defined with the direct rules only');
    // The former name `j` of the J_s parameter: its errors name `j`; beside `s` it must agree.
    throwsUnchanged(m, () => m.setJ(NaN), 'j: not a finite number (NaN or infinity)');
    throwsUnchanged(m, () => m.setOptions({ scheme: 'fourpoint', j: 0.3 }), "j: j = 0.3 contradicts scheme 'fourpoint' (whose J_s parameter is 0); use scheme 'j' for other values");
    throwsUnchanged(m, () => m.setOptions({ scheme: 'j', rules: 'direct', s: 0.3, j: 0.4 }), 's: s = 0.3 and j = 0.4 disagree (j is the deprecated name of s; give s only)');
    throwsUnchanged(m, () => m.setOptions({ s: 9 }), 's: 9 is out of range (expected -4 to 4)');
    throwsUnchanged(m, () => m.setClosed('no'), 'closed: expected a boolean, got string');
    throwsUnchanged(m, () => m.setName(5), 'name: expected a string, got number');
  });

  it('evaluation arguments', () => {
    const m = fresh();
    throwsUnchanged(m, () => m.poseAt(NaN), 'u: not a finite number (NaN or infinity)');
    throwsUnchanged(m, () => m.poseAt('1'), 'u: expected a number, got string');
    throwsUnchanged(m, () => m.kinematicsAt(Infinity), 'u: not a finite number (NaN or infinity)');
    throwsUnchanged(m, () => m.kinematicsAt(0.5, [0, NaN, 0]), 'local: not a finite number (NaN or infinity)');
    throwsUnchanged(m, () => m.kinematicsAt(0.5, [0, 0]), 'local: invalid point: invalid length 2, expected an array of length 3');
    throwsUnchanged(m, () => m.posesAt([0, NaN]), 'us[1]: not a finite number (NaN or infinity)');
    throwsUnchanged(m, () => m.posesAt('0.5'), 'us: expected a Float64Array or an array of numbers, got string');
    throwsUnchanged(m, () => m.sample(-1), 'count: -1 is out of range (expected a whole number from 0 to 1048576)');
    throwsUnchanged(m, () => m.sample(2 ** 21), 'count: 2097152 is out of range (expected a whole number from 0 to 1048576)');
    throwsUnchanged(m, () => m.sampleMatrices(1.5), 'count: 1.5 is out of range (expected a whole number from 0 to 1048576)');
    throwsUnchanged(m, () => m.sampleKinematics('3'), 'count: expected a number, got string');
    throwsUnchanged(m, () => Motion.fromPreset('nope'), /^preset: unknown value 'nope' \(expected l_cycle_parallel, /);
    throwsUnchanged(m, () => Motion.fromScene('nope'), /^scene: unknown value 'nope' \(expected l_cycle_parallel, /);
    throwsUnchanged(m, () => Motion.fromPoses([1, 2, 3]), /^poses: length 3 is out of range \(expected a multiple of 7/);
    throwsUnchanged(m, () => Motion.fromPoses([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0]), 'poses[1].rotation: zero quaternion');
    throwsUnchanged(m, () => Motion.fromPoses([0, 0, 0, 1, 0, 0, 0]), 'poses: 1 pose(s) given, at least 2 needed');
  });

  it('free functions', () => {
    const a = P();
    assert.throws(() => sb.screw(a, NaN, a), { message: 't: not a finite number (NaN or infinity)' });
    assert.throws(() => sb.screw(a, 0.5, P({ rotation: [0, 0, 0, 0] })), { message: 'b.rotation: zero quaternion' });
    assert.throws(() => sb.screwPoses(P({ origin: [0, 0] }), a, [0]), { message: 'a.origin: invalid pose: invalid length 2, expected an array of length 3' });
    assert.throws(() => sb.screwPoses(a, a, [0, Infinity]), { message: 'ts[1]: not a finite number (NaN or infinity)' });
    assert.throws(() => sb.screwPoses(a, a, new Float64Array(2 ** 20 + 1)), { message: 'ts: length 1048577 is out of range (expected at most 1048576 numbers per call)' });
    assert.throws(() => sb.screwInfo(a, 'b'), { message: 'b: invalid pose: expected an object {origin, rotation} or {origin, basis}, got string' });
  });

  it('user code that throws inside an argument does not poison the object', () => {
    const m = fresh();
    const getter = { get origin() { throw new Error('getter boom'); }, rotation: ID };
    throwsUnchanged(m, () => m.setPose(0, getter), 'pose: cannot read the argument: getter boom');
    throwsUnchanged(m, () => m.loadDocument({ poses: [getter, getter] }), 'cannot read the argument: getter boom');
    const proxy = new Proxy({ levels: 2 }, { ownKeys() { throw new Error('trap'); } });
    throwsUnchanged(m, () => m.setOptions(proxy), /^cannot read the argument: /);
    throwsUnchanged(m, () => m.posesAt([1n]), 'us[0]: not a finite number (NaN or infinity)');
    throwsUnchanged(m, () => m.posesAt(new BigInt64Array(2)), 'us: expected a Float64Array or an array of numbers, got object');
    throwsUnchanged(m, () => m.setPose(0, () => 1), 'pose: invalid pose: expected an object {origin, rotation} or {origin, basis}, got function');
    throwsUnchanged(m, () => m.posesAt(new Proxy(new Float64Array(2), {})), /^us: cannot read the argument: /);
    // Typed arrays are read through their internal slots: a shadowed `length` changes nothing.
    const us = new Float64Array([0.25, 0.5]);
    Object.defineProperty(us, 'length', { get() { throw new Error('length getter'); } });
    assert.equal(m.posesAt(us).length, 14);
    // A detached buffer reads as empty (its length is 0): no exception from copying it.
    const detached = new Float64Array([0.25, 0.5]);
    structuredClone(detached.buffer, { transfer: [detached.buffer] });
    assert.equal(m.posesAt(detached).length, 0);
    // wasm-bindgen's own borrow bookkeeping is intact: free() works.
    m.free();
  });

  it('a freed motion throws instead of crashing the module', () => {
    const m = fresh();
    m.free();
    assert.throws(() => m.subdivide(), Error);
    const other = fresh();
    assert.equal(other.poseCount, 3);
  });
});
