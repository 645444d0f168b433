// Motion.keyframeTracks (cargo feature `tracks`: the npm package's `screwbender/full` entry,
// not its light main module) played by the real three.js (the npm package `three`, a devDependency):
// the tracks go into a VectorKeyframeTrack and a QuaternionKeyframeTrack, an AnimationClip and
// an AnimationMixer on an Object3D; at many times the object's matrix, applied to points of the
// object, is compared with the motion itself (motion.posesAt at u = p(t), the motion's own
// timing through timingMap). The error must stay within the stated tolerance plus an explicit
// f32 allowance, and a deliberately coarse clip must not (so the comparison can fail).
import assert from 'node:assert/strict';
import { describe, it } from 'node:test';

import * as THREE from 'three';

import { prng } from './prng.mjs';
import { sb } from './full-package.mjs';

const { Motion, timingMap } = sb;

/**
 * What f32 storage adds to the sampler's bound, in scene units: positions and quaternion
 * components rounded to f32 (relative 6e-8, on coordinates and radii of at most ~10 units here)
 * and the key times rounded to f32 (the object moves at most a few units per second). 2e-5 is
 * about 30 times that estimate and 50 times below the tolerances tested.
 */
const F32_SLACK = 2e-5;

/** Points of a body within `radius` of its origin: the origin, the axes' ends, random ones. */
function bodyPoints(radius, count, seed) {
  const rand = prng(seed);
  const points = [[0, 0, 0], [radius, 0, 0], [0, radius, 0], [0, 0, radius]];
  while (points.length < count) {
    const p = [rand() * 2 - 1, rand() * 2 - 1, rand() * 2 - 1];
    const len = Math.hypot(...p);
    if (len > 1e-3 && len <= 1) points.push(p.map((x) => (x * radius) / Math.max(len, 0.5)));
  }
  return points.filter((p) => Math.hypot(...p) <= radius * (1 + 1e-12));
}

/** `tracks` with keys 0, k, 2k, … and the last only. */
function everyKth(tracks, k) {
  const n = tracks.times.length;
  const keep = [];
  for (let i = 0; i < n - 1; i += k) keep.push(i);
  keep.push(n - 1);
  const pick = (values, width) => Float32Array.from(keep.flatMap((i) => [...values.subarray(width * i, width * i + width)]));
  return { ...tracks, times: pick(tracks.times, 1), positions: pick(tracks.positions, 3), quaternions: pick(tracks.quaternions, 4) };
}

/** The clip of `tracks` on a fresh Object3D, and a function that poses it at time `t`. */
function player(tracks) {
  const object = new THREE.Object3D();
  const clip = new THREE.AnimationClip('motion', tracks.duration, [
    new THREE.VectorKeyframeTrack('.position', tracks.times, tracks.positions),
    new THREE.QuaternionKeyframeTrack('.quaternion', tracks.times, tracks.quaternions),
  ]);
  assert.equal(clip.validate(), true, 'three.js accepts the tracks');
  const mixer = new THREE.AnimationMixer(object);
  const action = mixer.clipAction(clip);
  action.setLoop(THREE.LoopOnce, 1);
  action.clampWhenFinished = true;
  action.play();
  return (t) => {
    mixer.setTime(t);
    object.updateMatrix();
    return object.matrix;
  };
}

/**
 * The largest distance, over `count` uniform times of the motion's clock and the given body
 * points, between the three.js object and the motion (`posesAt` at `u = p(t)`).
 */
function largestError(motion, tracks, points, count) {
  const n = motion.poseCount;
  const closed = motion.closed;
  const times = motion.times ?? Array.from({ length: n + (closed ? 1 : 0) }, (_, i) => i);
  const velocities = motion.velocities ?? undefined;
  const map = timingMap(times, n, closed, count, velocities);
  const us = new Float64Array(count);
  for (let k = 0; k < count; k++) us[k] = map[3 * k + 1];
  const poses = motion.posesAt(us);
  const pose = player(tracks);
  let worst = 0;
  const v = new THREE.Vector3();
  const truth = new THREE.Vector3();
  const q = new THREE.Quaternion();
  for (let k = 0; k < count; k++) {
    const m = pose(map[3 * k] - tracks.startTime);
    const o = poses.subarray(7 * k, 7 * k + 7);
    // The project's quaternions are [w, x, y, z]; three.js takes (x, y, z, w).
    q.set(o[4], o[5], o[6], o[3]);
    for (const p of points) {
      v.set(...p).applyMatrix4(m);
      truth.set(...p).applyQuaternion(q).add(new THREE.Vector3(o[0], o[1], o[2]));
      worst = Math.max(worst, v.distanceTo(truth));
    }
  }
  return worst;
}

describe('Motion.keyframeTracks in three.js', () => {
  const cases = [
    { name: 'open preset', make: () => Motion.fromPreset('triangle7'), tolerance: 1e-3 },
    { name: 'cycle', make: () => Motion.fromPreset('l_cycle_rotated'), tolerance: 5e-4 },
    {
      name: 'key times and a key velocity',
      make: () => {
        const m = Motion.fromPreset('l_cycle_rotated');
        const n = m.poseCount + (m.closed ? 1 : 0);
        m.setTimes(Array.from({ length: n }, (_, i) => 0.5 + i * i * 0.4));
        m.setVelocities(Array.from({ length: m.poseCount }, (_, i) => (i === 1 ? 0 : null)));
        return m;
      },
      tolerance: 1e-3,
    },
  ];
  for (const c of cases) {
    it(`stays within the tolerance at the object's points: ${c.name}`, () => {
      const motion = c.make();
      const radius = 1.5;
      const tracks = motion.keyframeTracks({ tolerance: c.tolerance, radius });
      const keys = tracks.times.length;
      assert.ok(keys > 10, `${keys} keys`);
      assert.equal(tracks.positions.length, 3 * keys);
      assert.equal(tracks.quaternions.length, 4 * keys);
      assert.equal(tracks.times[0], 0);
      assert.equal(tracks.radius, radius);
      assert.equal(tracks.tolerance, c.tolerance);
      for (let i = 1; i < keys; i++) {
        assert.ok(tracks.times[i] > tracks.times[i - 1], `time ${i} increases`);
        let dot = 0;
        for (let j = 0; j < 4; j++) dot += tracks.quaternions[4 * i + j] * tracks.quaternions[4 * i - 4 + j];
        assert.ok(dot >= 0, `keys ${i - 1} and ${i}: dot ${dot} (no sign flip)`);
      }
      const error = largestError(motion, tracks, bodyPoints(radius, 24, 7), 997);
      assert.ok(error <= c.tolerance + F32_SLACK, `largest error ${error} > ${c.tolerance} + ${F32_SLACK}`);
      // Every 8th key only (and the last): far off, so the comparison can fail.
      const coarse = everyKth(tracks, 8);
      const coarseError = largestError(motion, coarse, bodyPoints(radius, 24, 7), 997);
      assert.ok(coarseError > c.tolerance + F32_SLACK, `every 8th key: largest error ${coarseError}`);
      motion.free();
    });
  }

  it('takes the radius from points (default 1), and a tighter tolerance gives more keys', () => {
    const motion = Motion.fromPreset('triangle7');
    const points = new Float32Array([0, 0, 0, 3, 4, 0, -1, 0, 0]);
    assert.equal(motion.keyframeTracks({ points }).radius, 5);
    assert.equal(motion.keyframeTracks({ points: [0, 0, 2] }).radius, 2);
    const own = motion.keyframeTracks();
    assert.equal(own.radius, 1);
    assert.equal(own.tolerance, 1e-4);
    const loose = motion.keyframeTracks({ tolerance: 1e-2, radius: 1 }).times.length;
    const tight = motion.keyframeTracks({ tolerance: 1e-5, radius: 1 }).times.length;
    assert.ok(tight > 1.5 * loose, `${tight} keys at 1e-5, ${loose} at 1e-2`);
    // Given key times: the clip runs from 0 to the last time less the first.
    const n = motion.poseCount;
    const timed = motion.keyframeTracks({ times: Array.from({ length: n }, (_, i) => 3 + 2 * i) });
    assert.equal(timed.startTime, 3);
    assert.ok(Math.abs(timed.duration - 2 * (n - 1)) <= 1e-5, `duration ${timed.duration}`);
    motion.free();
  });

  it('refuses bad options naming them, and leaves the motion unchanged', () => {
    const motion = Motion.fromPreset('triangle7');
    const before = motion.toJson();
    const bad = [
      [{ tolerance: -1 }, /tolerance/],
      [{ tolerance: NaN }, /tolerance/],
      [{ radius: -2 }, /radius/],
      [{ radius: 1, points: [0, 0, 1] }, /points/],
      [{ points: [1, 2] }, /points/],
      [{ points: [0, 0, NaN] }, /points/],
      [{ fps: 30 }, /fps/],
      [{ times: [0, 1] }, /times/],
      [{ colour: 'red' }, /colour/],
      ['fast', /options/],
    ];
    for (const [options, message] of bad) {
      assert.throws(() => motion.keyframeTracks(options), message, JSON.stringify(options));
    }
    assert.equal(motion.toJson(), before);
    motion.free();
  });
});
