// Type-checked by scripts/test.d/npm-package.sh in a Node-only TypeScript project
// (tsconfig.node.json: lib es2022, types node, no DOM lib, no skipLibCheck): the math entry's
// types must compile there, init included, and wrong uses must fail.
import { readFileSync } from 'node:fs';
import init, { initSync, Motion, timingMap, type MotionDocument, type Pose } from 'screwbender';
import { Motion as FullMotion, type KeyframeTracks } from 'screwbender/full';

initSync({ module: readFileSync(new URL('./node_modules/screwbender/screwbender_bg.wasm', import.meta.url)) });
await init({ module_or_path: readFileSync('screwbender_bg.wasm') });
const out = await init();
const pages: number = out.memory.grow(0);

const motion = Motion.fromPreset('l_cycle_rotated');
const pose: Pose = motion.poseAt(0.5);
const doc: MotionDocument = motion.toDocument();
const kinematics: Float64Array = motion.timedKinematics(16, [1, 0, 0]);
const map: Float64Array = timingMap([0, 1, 3, 4, 6], 4, true, 8);
// @ts-expect-error: the parameter is a number
motion.poseAt('0.5');
// The `screwbender/full` entry's types compile without the DOM lib too.
const tracks: KeyframeTracks = FullMotion.fromPreset('l_cycle_rotated').keyframeTracks({ tolerance: 1e-3 });
const quaternions: Float32Array = tracks.quaternions;
console.log(quaternions.length);
console.log(pages, pose.rotation[0], doc.poses.length, kinematics.length, map.length);
