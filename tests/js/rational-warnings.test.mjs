// Warnings where results are silently poor (Motion.warnings, the C¹ Chaudhry–Cameron growth in
// compareMethods and Motion.rational) and the Chaudhry–Cameron motion through JavaScript
// (Motion.rational, Motion.rationalFromTriangles: end conditions (18)/(19), the rational Bézier
// control points, raw triangle input), checked against the CLI's `screwbender rational` — the
// Rust library's numbers. Loads the npm package's `screwbender/full` entry (feature `methods`).
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { existsSync, readFileSync } from 'node:fs';
import { describe, it } from 'node:test';
import { sb } from './full-package.mjs';

const ROOT = new URL('../../', import.meta.url);
const { Motion } = sb;

/** The `screwbender` binary (built once if missing), run with `args` and `input`. */
function cli(args, input) {
  const bin = new URL('target/debug/screwbender', ROOT).pathname;
  if (!existsSync(bin)) execFileSync('cargo', ['build', '-q', '-p', 'screwbender-cli'], { cwd: ROOT.pathname });
  return execFileSync(bin, args, { input, encoding: 'utf8' });
}

/** Every number of `a` and `b` (nested arrays/objects) within `tol`. */
function near(a, b, tol, at = '') {
  if (typeof a === 'number') {
    assert.ok(Math.abs(a - b) <= tol, `${at}: ${a} vs ${b}`);
  } else if (Array.isArray(a) || ArrayBuffer.isView(a)) {
    assert.equal(a.length, b.length, `${at}: length`);
    for (let k = 0; k < a.length; k++) near(a[k], b[k], tol, `${at}[${k}]`);
  } else if (a && typeof a === 'object') {
    assert.deepEqual(Object.keys(a).sort(), Object.keys(b).sort(), at);
    for (const k of Object.keys(a)) near(a[k], b[k], tol, `${at}.${k}`);
  } else {
    assert.equal(a, b, at);
  }
}

/** `n` poses zig-zagging sideways while moving forward (open), 7 numbers each. */
function zigzag(n) {
  const out = [];
  for (let i = 0; i < n; i++) {
    const side = i % 2 === 0 ? 0.3 : -0.3;
    out.push(i, side, 0, Math.cos(side / 2), 0, 0, Math.sin(side / 2));
  }
  return new Float64Array(out);
}

describe('Motion.warnings', () => {
  it('names every span of the four-pose circle with the split 4-point and Jarek rules', () => {
    const m = Motion.fromPreset('circle4');
    for (const scheme of ['fourpoint', 'jarek']) {
      m.setOptions({ scheme, rules: 'split' });
      const w = m.warnings();
      assert.equal(w.length, 4, scheme);
      w.forEach((text, span) => {
        assert.ok(text.startsWith(`span ${span}:`), text);
        assert.ok(text.includes('180.0°'), text);
      });
    }
  });

  it('is empty for the direct rules, the B-spline and five or more poses', () => {
    const m = Motion.fromPreset('circle4');
    m.setOptions({ scheme: 'fourpoint', rules: 'direct' });
    assert.deepEqual(m.warnings(), []);
    m.setOptions({ scheme: 'bspline', rules: 'split' });
    assert.deepEqual(m.warnings(), []);
    const six = Motion.fromPreset('l_cycle_rotated');
    six.setOptions({ scheme: 'jarek', rules: 'split' });
    assert.deepEqual(six.warnings(), []);
  });
});

describe('C¹ Chaudhry–Cameron growth', () => {
  it('is noted in compareMethods and in Motion.rational on a long zig-zag, not a short one', () => {
    const long = Motion.fromPoses(zigzag(60), false);
    const row = long.compareMethods(['cc1']).rows[0];
    assert.ok(row.notes.some((n) => n.startsWith('warning: ') && n.includes('grows without damping')), row.notes.join('\n'));
    const r = long.rational({ samples: 2 });
    assert.equal(r.warnings.length, 1);
    assert.ok(r.growth > 10, `${r.growth}`);
    const short = Motion.fromPoses(zigzag(8), false);
    assert.deepEqual(short.rational({ samples: 2 }).warnings, []);
    assert.ok(!short.compareMethods(['cc1']).rows[0].notes.some((n) => n.startsWith('warning: ')));
  });
});

describe('Motion.rational and Motion.rationalFromTriangles', () => {
  it('give the CLI’s rational Bézier form with end condition (18) and (19)', () => {
    const doc = cli(['preset', 'helix_open'], '');
    const m = Motion.fromJson(doc);
    for (const end of [18, 19]) {
      const r = m.rational({ end, samples: 50 });
      const want = JSON.parse(cli(['rational', '--end', String(end)], doc));
      near(r.bezier, want, 1e-12, `end ${end}`);
      assert.equal(r.bezier.continuity, `C1 (${end})`);
      assert.equal(r.t.length, 50);
      assert.equal(r.vertices.length, 9 * 50);
    }
  });

  it('fit a raw triangle sequence as the CLI does, and (19) straightens the last segment', () => {
    // The triangle placed by the poses of `triangle7`, read off at the keys (t = 0 … 6).
    const m = Motion.fromPreset('triangle7');
    const n = m.poseCount;
    const r = m.rational({ continuity: 'c0', samples: n });
    const data = [];
    const rows = [];
    for (let k = 0; k < n; k++) {
      const key = [r.t[k], ...r.vertices.subarray(9 * k, 9 * k + 9)];
      data.push(...key);
      rows.push(key.join(','));
    }
    for (const [options, args] of [
      [{ continuity: 'c0' }, ['--continuity', 'c0']],
      [{ end: 18 }, ['--end', '18']],
      [{ end: 19 }, ['--end', '19']],
    ]) {
      const got = Motion.rationalFromTriangles(new Float64Array(data), options);
      const want = JSON.parse(cli(['rational', '--triangles', ...args], `${rows.join('\n')}\n`));
      near(got.bezier, want, 1e-12, JSON.stringify(options));
      // The vertex paths pass through the keys.
      const at = Motion.rationalFromTriangles(data, { ...options, samples: n });
      near(Array.from(at.vertices), data.filter((_, i) => i % 10 !== 0), 1e-9, 'vertices at the keys');
    }
    const straight = (seg) => [0, 1, 2, 3].every((c) => Math.abs(seg.quaternions[1][c] - (seg.quaternions[0][c] + seg.quaternions[2][c]) / 2) < 1e-12);
    const s19 = Motion.rationalFromTriangles(data, { end: 19 }).bezier.segments;
    const s18 = Motion.rationalFromTriangles(data, { end: 18 }).bezier.segments;
    assert.ok(straight(s19.at(-1)) && !straight(s19[0]));
    assert.ok(straight(s18[0]) && !straight(s18.at(-1)));
  });

  it('refuses bad input with a clear Error and leaves the motion unchanged', () => {
    const m = Motion.fromPreset('circle4');
    const before = m.toJson();
    assert.throws(() => m.rational(), (e) => e instanceof Error && /C0 only/.test(e.message));
    assert.throws(() => m.rational({ end: 20 }), (e) => e instanceof Error && /options\.end/.test(e.message));
    assert.throws(() => m.rational({ continuity: 'c2' }), (e) => e instanceof Error && /options\.continuity/.test(e.message));
    assert.throws(() => m.rational({ closingTime: 3 }), (e) => e instanceof Error && /closingTime/.test(e.message));
    assert.equal(m.toJson(), before);
    assert.ok(m.rational({ continuity: 'c0' }).bezier.segments.length === 4);
    assert.throws(() => Motion.rationalFromTriangles([1, 2, 3]), (e) => e instanceof Error && /multiple of 10/.test(e.message));
    const dup = [0, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0];
    assert.throws(() => Motion.rationalFromTriangles(dup), (e) => e instanceof Error && /samples\[1\]\.t/.test(e.message));
    assert.throws(() => Motion.rationalFromTriangles('x'), (e) => e instanceof Error);
  });
});

describe('Motion.barrBaseline', () => {
  it('reaches R–B’s objective from below on scene C1, as the CLI measures', () => {
    const m = Motion.fromPreset('rb_sphere7');
    if (m.closed) m.setClosed(false);
    const b = m.barrBaseline();
    const rb = m.quaternionSpline({ samples: 2 }).stages.at(-1).objective;
    // docs/math/quaternion-splines.md §9: 3.758506 against 3.768051 (0.25 %).
    assert.ok(b.objective <= rb && (rb - b.objective) / b.objective < 0.005, `${b.objective} ${rb}`);
    assert.equal(b.frames, 601);
    assert.ok(b.initialObjective > 10 * b.objective);
    const want = JSON.parse(cli(['compare', '--methods', 'barr', '--open', '--json'], m.toJson())).objectives;
    assert.ok(Math.abs(b.objective / want.barr.objective - 1) < 1e-9, `${b.objective} ${want.barr.objective}`);
    assert.ok(Math.abs(rb / want.rb.objective - 1) < 1e-6, `${rb} ${want.rb.objective}`);
  });

  it('refuses a cycle with a clear Error', () => {
    const m = Motion.fromPreset('circle4');
    assert.throws(() => m.barrBaseline(), (e) => e instanceof Error && /open sequences only/.test(e.message));
  });
});
