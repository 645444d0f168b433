// Playback in seconds on Motion (docs/math/timing.md §3): timeDomain, parameterAt(t) and its
// inverse timeAt(u) follow the motion's own key times and velocities; uniform timing is the
// identity exactly; bad input throws naming the argument and changes nothing. Uses the npm
// package's `screwbender/full` entry, like timing-files.test.mjs.
import assert from 'node:assert/strict';
import { describe, it } from 'node:test';
import { prng } from './prng.mjs';
import { sb } from './full-package.mjs';

const { Motion } = sb;

/** A preset motion, opened (`closed: false`) or as it is (a cycle). */
function motion(closed = true) {
  const m = Motion.fromPreset('l_cycle_rotated');
  if (!closed) m.setClosed(false);
  return m;
}

describe('Motion playback in seconds', () => {
  it('uniform timing: u = t exactly, pose i at i s; a cycle wraps, an open motion rests at its ends', () => {
    for (const closed of [true, false]) {
      const m = motion(closed);
      const [a, b] = m.domain();
      assert.deepEqual(Array.from(m.timeDomain()), [a, b]);
      for (let k = 0; k <= 1000; k++) {
        const t = a + ((b - a) * k) / 1000;
        // The last time of a cycle is pose 0 again (u wraps to 0).
        const want = closed && k === 1000 ? 0 : t;
        assert.equal(m.parameterAt(t), want, `p(${t})`);
        assert.equal(m.timeAt(want), closed && k === 1000 ? 0 : t, `p⁻¹(${want})`);
      }
      if (closed) assert.equal(m.parameterAt(b + 1.25), 1.25);
      else {
        assert.equal(m.parameterAt(-3), 0);
        assert.equal(m.parameterAt(b + 3), b);
      }
      m.free();
    }
  });

  it('timed: key i is shown at times[i], timeAt inverts parameterAt, and u never decreases', () => {
    const times = [0.5, 1, 3, 4, 6, 7, 9.5];
    const m = motion();
    m.setTimes(times);
    assert.deepEqual(Array.from(m.timeDomain()), [0.5, 9.5]);
    for (let i = 0; i < 6; i++) {
      assert.ok(Math.abs(m.parameterAt(times[i]) - i) < 1e-12, `p(T_${i}) = ${m.parameterAt(times[i])}`);
      assert.equal(m.timeAt(i), times[i]);
    }
    // The cycle's last key is pose 0 again; one period later everything repeats.
    assert.ok(Math.abs(m.parameterAt(9.5)) < 1e-12);
    const rand = prng(7);
    let last = -Infinity;
    for (let k = 0; k <= 2000; k++) {
      const t = 0.5 + (9 * k) / 2000 - 1e-9;
      const u = m.parameterAt(Math.max(0.5, t));
      assert.ok(u >= last - 1e-12, `u went back at t = ${t}: ${u} < ${last}`);
      last = u;
    }
    for (let k = 0; k < 200; k++) {
      const t = 0.5 + 9 * rand();
      const u = m.parameterAt(t);
      assert.ok(Math.abs(m.timeAt(u) - t) < 1e-9, `timeAt(parameterAt(${t})) = ${m.timeAt(u)}`);
      assert.ok(Math.abs(m.parameterAt(t + 9) - u) < 1e-9, `period at ${t}`);
    }
    m.free();
  });

  it('a key velocity holds: finite differences of u over t at the key match it', () => {
    const m = motion(false);
    m.setTimes([0, 1, 3, 4, 6, 7]);
    m.setVelocities([null, 0.25, null, 2, null, null]);
    // p is C¹ but p'' may jump at the key: the central difference is off by O(h · jump) (about
    // 1e-6 here) plus rounding (1e-16 / h).
    const h = 1e-6;
    for (const [i, v] of [[1, 0.25], [3, 2]]) {
      const T = m.timeAt(i);
      const d = (m.parameterAt(T + h) - m.parameterAt(T - h)) / (2 * h);
      assert.ok(Math.abs(d - v) < 1e-5, `p'(T_${i}) ≈ ${d}, given ${v}`);
    }
    m.free();
  });

  it('bad input throws naming the argument and leaves the motion as it was', () => {
    const m = motion();
    m.setTimes([0, 1, 3, 4, 6, 7, 9]);
    const before = m.toJson();
    for (const bad of [NaN, Infinity, -Infinity, 'x', undefined, null, {}]) {
      assert.throws(() => m.parameterAt(bad), /\bt\b/, `parameterAt(${String(bad)})`);
      assert.throws(() => m.timeAt(bad), /\bu\b/, `timeAt(${String(bad)})`);
    }
    assert.throws(() => m.parameterAt(NaN), { message: 't: not a finite number (NaN or infinity)' });
    assert.throws(() => m.timeAt('1'), { message: 'u: expected a number, got string' });
    assert.equal(m.toJson(), before);
    m.free();
  });
});
