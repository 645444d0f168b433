// Key times and velocities on Motion (docs/math/timing.md §3), honest export file names, the
// reduction of dense imports and a dropped glTF's title and mesh. Uses the npm package's
// `screwbender/full` entry (cargo feature `files`), like files.test.mjs.
import assert from 'node:assert/strict';
import { describe, it } from 'node:test';
import { sb } from './full-package.mjs';

const { Motion, importMotionFile, reducePoses, fitPoses, importedMesh, timingMap } = sb;

describe('Motion key times and velocities', () => {
  it('are stored, drive timedKinematics and appear in the document; older documents are unchanged', () => {
    const m = Motion.fromPreset('l_cycle_rotated');
    const plain = m.toJson();
    assert.equal(m.times, undefined);
    assert.equal(m.velocities, undefined);
    assert.ok(!plain.includes('times'));
    m.setTimes([0, 1, 3, 4, 6, 7, 9]);
    m.setVelocities([null, 0, 0.8, null, null, null]);
    assert.deepEqual(Array.from(m.times), [0, 1, 3, 4, 6, 7, 9]);
    assert.deepEqual(m.velocities, [null, 0, 0.8, null, null, null]);
    const doc = m.toDocument();
    assert.deepEqual(doc.times, [0, 1, 3, 4, 6, 7, 9]);
    // toDocument() gives free velocities as undefined: the object is accepted back as it is.
    assert.equal(new Motion(doc).toJson(), m.toJson());
    const again = new Motion(JSON.parse(m.toJson()));
    assert.equal(again.toJson(), m.toJson());
    // Without explicit times, timedKinematics follows the motion's own: the first number of each
    // sample is t, over [0, 9).
    const k = m.timedKinematics(90);
    assert.equal(k[0], 0);
    assert.ok(Math.abs(k[16 * 89] - 8.9) < 1e-12, `last t ${k[16 * 89]}`);
    m.setTimes(null);
    m.setVelocities(null);
    assert.equal(m.toJson(), plain);
  });

  it('timingMap holds a given velocity at its key and reaches key i at T_i', () => {
    const times = [0, 1, 3, 4, 6];
    const n = 401;
    const map = timingMap(times, 4, true, n, [null, 0.25, null, null]);
    for (let j = 0; j < n; j++) {
      const [t, u, du] = map.subarray(3 * j, 3 * j + 3);
      for (let i = 0; i < 4; i++) if (t === times[i]) assert.ok(Math.abs(u - i) < 1e-9, `p(${t}) = ${u}`);
      if (t === 1) assert.ok(Math.abs(du - 0.25) < 1e-12, `p'(1) = ${du}`);
      assert.ok(du >= -1e-12, `rate ${du} at ${t}`);
    }
    assert.throws(() => timingMap(times, 4, true, 10, [null, 9, null, null]), /velocities\[1\].*backwards/);
  });

  it('refuses bad times and velocities with the element named, and changes nothing', () => {
    const m = Motion.fromPreset('circle4');
    m.setTimes([0, 1, 2, 3, 5]);
    const before = m.toJson();
    const bad = [
      [() => m.setTimes([0, 1, 1, 3, 5]), /times\[2\]/],
      [() => m.setTimes([0, 1, 2]), /times: 3 times given, expected 5/],
      [() => m.setTimes([0, NaN, 2, 3, 5]), /times/],
      [() => m.setVelocities([null, -1, null, null]), /velocities\[1\]/],
      [() => m.setVelocities([null, null, Infinity, null]), /velocities\[2\]/],
      [() => m.setVelocities([null, null]), /velocities: 2 velocities given, expected 4/],
      [() => m.setVelocities([null, 50, null, null]), /velocities\[1\].*backwards/],
      [() => m.setVelocities('fast'), /velocities/],
    ];
    for (const [call, re] of bad) {
      assert.throws(call, (e) => e instanceof Error && re.test(e.message), String(call));
      assert.equal(m.toJson(), before);
    }
    // Inserting and removing poses keeps the times valid.
    m.insertPose(1);
    assert.equal(m.times.length, 6);
    m.removePose(0);
    assert.equal(m.times.length, 5);
    m.setClosed(false);
    assert.equal(m.times.length, 4);
  });
});

describe('exports name what they hold', () => {
  it('suggests -motion.glb, -poses.csv and -path.csv, and reports the radius the tolerance holds at', () => {
    const m = Motion.fromPreset('l_cycle_rotated');
    const glb = m.exportFile({ format: 'glb' });
    assert.equal(glb.fileName, 'l_cycle_rotated-motion.glb');
    assert.ok(glb.radius > 1 && glb.radius < 3, `radius ${glb.radius}`);
    assert.equal(m.exportFile({ format: 'csv' }).fileName, 'l_cycle_rotated-poses.csv');
    assert.equal(m.exportFile({ format: 'csv', point: [1, 0, 0] }).fileName, 'l_cycle_rotated-path.csv');
    const gltf = m.exportFile({ format: 'gltf' });
    assert.equal(gltf.fileName, 'l_cycle_rotated-motion.gltf');
    assert.equal(gltf.binName, 'l_cycle_rotated-motion.bin');
    // The motion's own key times drive the export (a slower second span needs other keyframes).
    const uniform = m.exportFile({ format: 'csv' });
    m.setTimes([0, 1, 3, 4, 6, 7, 9]);
    const timed = m.exportFile({ format: 'csv' });
    const last = new TextDecoder().decode(timed.data).trim().split('\n').at(-1);
    assert.equal(Number(last.split(',')[0]), 9);
    assert.notEqual(timed.sampleCount, uniform.sampleCount);
  });
});

describe('dense imports and dropped glTF', () => {
  it('a CSV of samples has more than 64 poses; reducePoses keeps every k-th or a fit, and says how many', () => {
    const m = Motion.fromPreset('cylinder5');
    const csv = new TextDecoder().decode(m.exportFile({ format: 'csv' }).data);
    const doc = importMotionFile('cylinder5-poses.csv', csv);
    assert.ok(doc.poses.length > 64, `${doc.poses.length} poses`);
    assert.equal(doc.name, 'cylinder5-poses');
    const every = reducePoses(doc, { every: 8 });
    assert.equal(every.poses.length, Math.ceil(doc.poses.length / 8));
    const fit = reducePoses(doc, { tolerance: 1e-3, radius: 1 });
    assert.ok(fit.poses.length >= 5 && fit.poses.length < doc.poses.length / 2, `${fit.poses.length} kept`);
    assert.ok(reducePoses(doc, { tolerance: 1e-2, radius: 1 }).poses.length < fit.poses.length);
    assert.equal(fit.closed, doc.closed);
    // Kept poses are dense poses, in order.
    let at = 0;
    for (const p of fit.poses) {
      while (at < doc.poses.length && JSON.stringify(doc.poses[at]) !== JSON.stringify(p)) at++;
      assert.ok(at < doc.poses.length, 'a kept pose is not one of the dense poses');
    }
    for (const [how, re] of [
      [{ every: 0 }, /every/],
      [{ every: 1.5 }, /every/],
      [{ tolerance: 0 }, /tolerance/],
      [{ tolerance: 1e-3, radius: -1 }, /radius/],
      [{ every: 2, tolerance: 1e-3 }, /either/],
      [{ often: 2 }, /often/],
    ]) {
      assert.throws(() => reducePoses(doc, how), re, JSON.stringify(how));
    }
  });

  it('fitPoses fits a smooth motion to the samples of a CSV, reports its residuals and names bad options', () => {
    const m = Motion.fromPreset('cylinder5');
    const csv = new TextDecoder().decode(m.exportFile({ format: 'csv' }).data);
    const doc = importMotionFile('cylinder5-poses.csv', csv);
    const n = doc.poses.length;
    const { document, report } = fitPoses(doc, { method: 'se3bspline', controls: 12, robust: 'huber' });
    assert.equal(document.poses.length, 12);
    assert.equal(document.closed, false);
    assert.equal(document.times.length, 12);
    assert.equal(report.controls, 12);
    assert.equal(report.samples, n);
    for (const key of ['rmsPosition', 'maxPosition', 'rmsAngle', 'maxAngle', 'rmsDeviation', 'maxDeviation']) {
      assert.ok(Number.isFinite(report[key]) && report[key] >= 0, `${key} ${report[key]}`);
    }
    assert.ok(report.rmsPosition <= report.maxPosition && report.rmsDeviation <= report.maxDeviation);
    // The tolerance mode picks the count, and meets its tolerance.
    const tol = fitPoses(doc, { method: 'se3bspline', tolerance: 2e-2 });
    assert.ok(tol.report.rmsDeviation <= 2e-2, JSON.stringify(tol.report));
    assert.equal(tol.document.poses.length, tol.report.controls);
    for (const [options, re] of [
      [{ controls: 1 }, /options\.controls/],
      [{ controls: 2.5 }, /options\.controls/],
      [{ controls: n + 1 }, /poses/],
      [{ tolerance: 0 }, /options\.tolerance/],
      [{ controls: 4, tolerance: 1e-3 }, /exactly one/],
      [{ controls: 4, method: 'kks' }, /options\.method/],
      [{ controls: 4, robust: 'l1' }, /options\.robust/],
      [{ controls: 4, radius: -1 }, /options\.radius/],
      [{ controls: 4, robustScale: 0, robust: 'huber' }, /options\.robustScale/],
      [{ controls: 4, often: 2 }, /often/],
    ]) {
      assert.throws(() => fitPoses(doc, options), re, JSON.stringify(options));
    }
  });

  it('a dropped GLB is titled by its scene and gives its mesh', () => {
    const m = Motion.fromPreset('pendulum');
    const f = m.exportFile({ format: 'glb' });
    const doc = importMotionFile(f.fileName, f.data);
    assert.equal(doc.name, 'pendulum');
    const mesh = importedMesh(f.fileName, f.data);
    assert.ok(mesh.positions instanceof Float64Array && mesh.positions.length % 3 === 0);
    assert.ok(mesh.indices instanceof Uint32Array && mesh.indices.length % 3 === 0 && mesh.indices.length > 0);
    assert.ok(Math.abs(mesh.radius - f.radius) < 1e-5, `${mesh.radius} vs ${f.radius}`);
    const empty = '{"asset":{"version":"2.0"},"nodes":[{"name":"a"}]}';
    assert.equal(importedMesh('a.gltf', new TextEncoder().encode(empty)), undefined);
    assert.throws(() => importedMesh('b.glb', new Uint8Array([1, 2, 3])), /b\.glb: /);
  });
});

describe('random calls to the new functions', () => {
  it('throw only Errors (never a wasm trap), leave the motion unchanged, and keep it working', async () => {
    const { prng } = await import('./prng.mjs');
    const rand = prng(18);
    const pick = (a) => a[Math.floor(rand() * a.length)];
    const garbage = () => pick([undefined, null, NaN, -1, 1e308, 'x', {}, [], [NaN], [1, 'a'], new Float64Array(3), 2n, () => 1]);
    const num = () => pick([0, 0.5, 1, 2, 3.5, 4.5, 9, -0.1, 1e-300, 1e300, NaN, Infinity, -Infinity]);
    const list = (n) => Array.from({ length: n }, () => (rand() < 0.4 ? null : num()));
    const increasing = (n) => { let t = rand(); return Array.from({ length: n }, () => (t += rand() < 0.9 ? 0.2 + rand() * 2 : -rand())); };
    const calls = [
      (m) => m.setTimes(rand() < 0.7 ? increasing(m.poseCount + (m.closed ? 1 : 0) + (rand() < 0.2 ? 1 : 0)) : garbage()),
      (m) => m.setVelocities(rand() < 0.7 ? list(m.poseCount + (rand() < 0.2 ? 1 : 0)) : garbage()),
      (m) => m.insertPose(Math.floor(rand() * m.poseCount)),
      (m) => m.removePose(Math.floor(rand() * m.poseCount)),
      (m) => m.setClosed(rand() < 0.5),
      (m) => m.timedKinematics(5),
      (m) => m.exportFile({ format: pick(['csv', 'glb']), tolerance: pick([1e-2, 1e-3]), radius: rand() < 0.8 ? pick([0, 1, 2]) : garbage() }),
      (m) => reducePoses(m.toDocument(), rand() < 0.5 ? { every: pick([1, 2, 3, 0, 1.5, NaN]) } : { tolerance: pick([1e-2, 1e-3, 0, NaN]), radius: pick([0, 1, -1]) }),
      () => timingMap(rand() < 0.7 ? increasing(5) : garbage(), 4, true, 7, rand() < 0.7 ? list(4) : garbage()),
      () => importedMesh('x.glb', rand() < 0.5 ? new Uint8Array([0x67, 0x6c, 0x54, 0x46, 2, 0, 0, 0]) : garbage()),
    ];
    const m = Motion.fromPreset('circle4');
    m.setLevels(3);
    let failures = 0;
    for (let i = 0; i < 3000; i++) {
      const before = m.toJson();
      const call = pick(calls);
      try {
        call(m);
      } catch (e) {
        failures++;
        assert.ok(e instanceof Error && !(e instanceof WebAssembly.RuntimeError), `${call}: ${e}`);
        assert.equal(m.toJson(), before, `${call} changed the motion and threw ${e.message}`);
      }
      // The motion keeps evaluating after every call, with a valid timing.
      const k = m.timedKinematics(3);
      assert.ok(k.every(Number.isFinite));
      if (m.poseCount > 12) m.loadJson(Motion.fromPreset('circle4').toJson());
    }
    assert.ok(failures > 300 && failures < 2900, `${failures} of 3000 calls failed`);
  });
});
