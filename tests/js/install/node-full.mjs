// Node smoke test of the installed package's `screwbender/full` entry (the math plus files,
// comparison methods, three.js keyframe tracks and teaching functions), run from the temporary
// app by scripts/test.d/npm-package.sh: the entry resolves through the package "exports", is
// ready at once (its Node entry instantiates the module), and each of its extra parts answers.
import assert from 'node:assert/strict';
import { Motion, methods, subdividePolygon, importMotionFile } from 'screwbender/full';

const motion = Motion.fromPreset('l_cycle_rotated');
// three.js keyframe arrays: x,y,z per position, x,y,z,w unit quaternions, increasing times.
const tracks = motion.keyframeTracks({ tolerance: 1e-3, radius: 1 });
const keys = tracks.times.length;
assert.ok(keys > 10, `${keys} keys`);
assert.equal(tracks.positions.length, 3 * keys);
assert.equal(tracks.quaternions.length, 4 * keys);
for (let k = 1; k < keys; k++) assert.ok(tracks.times[k] > tracks.times[k - 1]);
for (let k = 0; k < keys; k++) {
  const q = tracks.quaternions.subarray(4 * k, 4 * k + 4);
  assert.ok(Math.abs(Math.hypot(...q) - 1) < 1e-6, `key ${k} quaternion norm`);
}
// A GLB that reads back to the same control poses.
const glb = motion.exportFile({ format: 'glb' });
assert.equal(new TextDecoder().decode(glb.data.subarray(0, 4)), 'glTF');
const back = importMotionFile(glb.fileName, glb.data);
assert.equal(back.poses.length, motion.poseCount);
// The comparison methods and a teaching function are there too.
assert.ok(methods().length >= 5);
assert.ok(subdividePolygon instanceof Function);
console.log(`node smoke (screwbender/full): passed (${keys} keyframes, ${glb.data.length} bytes of GLB)`);
