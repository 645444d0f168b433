// Interleaved A/B of two builds of the npm module in one Node process: JS `subdivide()` of 32
// random poses by 6 levels (2048 refined poses) per scheme, alternating bursts of the two
// modules, so that a drifting machine affects both alike.
//
//   PKG_DIR=/tmp/before ./scripts/build-pkg.sh   # in a worktree of the "before" revision
//   node benches/wasm/compare.mjs /tmp/before pkg
//
// Prints, per scheme, the median ms of each build and the min / median / max of the per-burst
// ratios (after / before): for `subdivide()` alone, and for `subdivide()` then one `poseAt()`
// (the motion ready to evaluate: since the span screws are computed on first use, that is
// where they are paid).
import fs from 'node:fs';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

const [before, after] = process.argv.slice(2).map((d) => path.resolve(d));
if (!before || !after || ![before, after].every((d) => fs.existsSync(path.join(d, 'node.js')))) {
  console.error('usage: node benches/wasm/compare.mjs BEFORE_PKG AFTER_PKG (each built by scripts/build-pkg.sh)');
  process.exit(1);
}
const load = async (dir) => import(pathToFileURL(path.join(dir, 'node.js')).href);
const modules = [await load(before), await load(after)];

/** mulberry32, as bench-core.mjs: the same 32 poses every run. */
function rng(seed) {
  return () => {
    seed = (seed + 0x6d2b79f5) | 0;
    let t = Math.imul(seed ^ (seed >>> 15), 1 | seed);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}
const random = rng(20);
const control = new Float64Array(7 * 32);
for (let k = 0; k < 32; k++) {
  const q = [random() - 0.5, random() - 0.5, random() - 0.5, random() - 0.5];
  const n = Math.hypot(...q);
  control.set([10 * random() - 5, 10 * random() - 5, 10 * random() - 5, ...q.map((v) => v / n)], 7 * k);
}
const stats = (v) => {
  const s = [...v].sort((a, b) => a - b);
  return [s[0], s[s.length >> 1], s[s.length - 1]];
};

console.log(`node ${process.version}; before ${before}, after ${after}`);
for (const [scheme, evaluate] of ['bspline', 'fourpoint', 'jarek'].flatMap((s) => [[s, false], [s, true]])) {
  const motions = modules.map((sb) => sb.Motion.fromPoses(control, true, { scheme, rules: 'direct', levels: 6 }));
  const same = motions.map((m) => m.subdivide());
  if (!same[0].every((v, i) => Object.is(v, same[1][i]))) throw new Error(`${scheme}: the builds disagree`);
  const times = [[], []];
  const ratios = [];
  const reps = 20;
  for (let burst = 0; burst < 60; burst++) {
    const t = motions.map((m) => {
      const t0 = performance.now();
      for (let r = 0; r < reps; r++) {
        m.setLevels(6);
        m.subdivide();
        if (evaluate) m.poseAt(0.5);
      }
      return (performance.now() - t0) / reps;
    });
    times[0].push(t[0]);
    times[1].push(t[1]);
    ratios.push(t[1] / t[0]);
  }
  const [r0, r1, r2] = stats(ratios);
  console.log(
    `subdivide 32 × 6${evaluate ? ' + poseAt' : ''}, ${scheme} direct: before ${stats(times[0])[1].toFixed(3)} ms, after ${stats(times[1])[1].toFixed(3)} ms; ` +
      `after / before ${r0.toFixed(2)} / ${r1.toFixed(2)} / ${r2.toFixed(2)} (min / median / max)`,
  );
  motions.forEach((m) => m.free());
}
