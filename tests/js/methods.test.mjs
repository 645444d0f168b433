// The comparison methods through JavaScript (cargo feature `methods`: the npm package's
// `screwbender/full` entry): every method on every preset, the metrics table, Ramamoorthi–Barr's report, and
// bad input (clear Error, motion unchanged).
import assert from 'node:assert/strict';
import { describe, it } from 'node:test';
import { sb } from './full-package.mjs';

const { Motion, methods, presets } = sb;

describe('comparison methods', () => {
  it('lists every method with a title', () => {
    const list = methods();
    assert.deepEqual(list.map((m) => m.id), ['polyscrew', 'bspline', 'fourpoint', 'jarek', 'slerp', 'decoupled', 'kks', 'se3bspline', 'se3interp', 'splitinterp', 'rb', 'cc0', 'cc1', 'barr']);
    for (const m of list) assert.ok(m.title.length > 5 && typeof m.supportsClosed === 'boolean');
  });

  it('runs every method on every preset: finite unit poses through the control poses, or a clear refusal', () => {
    const refusals = [];
    for (const s of presets()) {
      const m = Motion.fromPreset(s.id);
      const n = m.poseCount;
      for (const { id, supportsClosed } of methods()) {
        let arr;
        try {
          arr = m.methodSample(id, 8 * n + 1);
        } catch (e) {
          assert.ok(e instanceof Error && e.message.length > 10, `${s.id}/${id}`);
          refusals.push(`${s.id}/${id}: ${e.message}`);
          if (!m.closed || supportsClosed) assert.match(e.message, /denominator|vanish|irregular|not supported|needs/i, `${s.id}/${id}: ${e.message}`);
          continue;
        }
        assert.equal(arr.length, 7 * (8 * n + 1));
        for (let k = 0; k < arr.length; k += 7) {
          assert.ok(arr.subarray(k, k + 7).every(Number.isFinite), `${s.id}/${id} sample ${k / 7}`);
          const q = arr.subarray(k + 3, k + 7);
          assert.ok(Math.abs(Math.hypot(...q) - 1) < 1e-9, `${s.id}/${id}: |q| = ${Math.hypot(...q)}`);
        }
      }
      m.free();
    }
    // Only the C¹ Chaudhry–Cameron motion and the Barr et al. baseline refuse, and only on
    // cycles (no closed form); and the interpolating Lie-group B-splines where poses turn so far
    // that no control poses less than half a turn apart pass through them.
    for (const r of refusals) assert.match(r, /\/(cc1|barr): |\/(se3interp|splitinterp): .*half a turn/, r);
  });

  it('compareMethods on C1 reproduces the papers’ claims', () => {
    const m = Motion.fromPreset('rb_sphere7');
    const t = m.compareMethods(['rb', 'slerp', 'decoupled', 'jarek', 'fourpoint']);
    const row = Object.fromEntries(t.rows.map((r) => [r.method, r]));
    // RB and Squad are C¹ in rotation; SLERP has angular-velocity jumps at every key.
    assert.ok(row.rb.angular_velocity_jump.limit === 'zero' && row.slerp.angular_velocity_jump.value > 0.1);
    // RB minimises covariant acceleration: less than Squad's on the same keys.
    assert.ok(row.rb.angular_acceleration_energy.value < row.decoupled.angular_acceleration_energy.value);
    // Screw schemes are frame-independent; the decoupled ones are not.
    assert.ok(row.jarek.frame_dependence < 1e-9 && row.rb.frame_dependence > 1e-3);
    assert.ok(row.fourpoint.interpolation_error < 1e-12);
  });

  it('quaternionSpline reports stages, frames and a smaller Euler–Lagrange error', () => {
    const m = Motion.fromPreset('rb_sphere7');
    const r = m.quaternionSpline({ variableFrames: 4, samples: 300 });
    assert.equal(r.frameTimes.length, 4);
    assert.deepEqual(r.keyTimes, [0, 1, 2, 3, 4, 5, 6]);
    assert.equal(r.t.length, 300);
    const max = (a) => Math.max(...a);
    assert.ok(max(r.elAfter) < max(r.elBefore));
    for (let k = 1; k < r.stages.length; k++) assert.ok(r.stages[k].objective <= r.stages[k - 1].objective * (1 + 1e-12));
    assert.ok(r.unitDeviationAfter < 0.003, `unit deviation ${r.unitDeviationAfter}`);
  });

  it('refuses bad input with a clear Error and keeps working', () => {
    const m = Motion.fromPreset('circle4');
    const json = m.toJson();
    const bad = [
      [() => m.methodSample('squad', 10), /method: unknown value 'squad'/],
      [() => m.methodSample(42, 10), /method/],
      [() => m.methodSample('cc1', 10), /cc1.continuity: .*open sequence/],
      [() => m.methodSample('rb', -1), /count/],
      [() => m.compareMethods(['rb', 'nope']), /methods\[1\]: unknown value 'nope'/],
      [() => m.compareMethods('rb'), /methods/],
      [() => m.compareMethods(['rb'], [[0, 0, NaN]]), /bodyPoints\[0\]/],
      [() => m.compareMethods(['rb'], []), /bodyPoints/],
      [() => m.quaternionSpline({ alpha: -1 }), /alpha/],
      [() => m.quaternionSpline({ variableFrames: 1.5 }), /variableFrames/],
      [() => m.quaternionSpline({ frames: 2 }), /unknown field `frames`/],
      [() => m.methodKinematics('jarek', 10, [1, 2]), /local/],
    ];
    for (const [f, re] of bad) {
      assert.throws(f, (e) => e instanceof Error && re.test(e.message), String(f));
      assert.equal(m.toJson(), json);
    }
    assert.equal(m.methodSample('jarek', 3).length, 21);
  });
});
