// WebAssembly benchmark of the comparison methods (the playground's build, www/pkg/, which has
// the `methods` feature; build it first: BUILD_ONLY=1 ./scripts/serve.sh).
//
//   node benches/wasm/methods.mjs
//
// Times, in Node's V8, what the Methods view computes: Ramamoorthi–Barr on scene C1 (7
// keyframes, α = 1000, S = 5) with 4 variable frames (the paper needed 4 s; the target is
// ≤ 10 ms), each other method built on the same poses, and a full metrics row.
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const pkg = path.join(repo, 'www/pkg');
const sb = await import(pathToFileURL(path.join(pkg, 'screwbender.js')).href);
await sb.default({ module_or_path: fs.readFileSync(path.join(pkg, 'screwbender_bg.wasm')) });

/** Median milliseconds of `f` over `runs` runs after `warm` warm-up runs. */
function median(f, runs = 31, warm = 5) {
  for (let k = 0; k < warm; k++) f();
  const t = [];
  for (let k = 0; k < runs; k++) {
    const t0 = performance.now();
    f();
    t.push(performance.now() - t0);
  }
  t.sort((a, b) => a - b);
  return t[runs >> 1];
}

console.log(`node ${process.version}, screwbender ${sb.version()} (www/pkg)`);
const m = sb.Motion.fromScene('rb_sphere7');
// quaternionSpline fits twice (without and with optimisation) and samples EL 600 times; the
// optimised fit alone is what the Methods view's overlay (methodSample) costs.
const rb4 = median(() => m.quaternionSpline({ variableFrames: 4, samples: 2 }));
const rbInitial = median(() => m.quaternionSpline({ variableFrames: 0, samples: 2 }));
console.log(`Ramamoorthi–Barr rb_sphere7, 7 keyframes + 4 variable frames: ${rb4.toFixed(2)} ms (incl. the unoptimised spline); keyframe velocities only: ${rbInitial.toFixed(2)} ms`);
for (const id of ['polyscrew', 'fourpoint', 'slerp', 'decoupled', 'kks', 'rb', 'cc0', 'cc1']) {
  const ms = median(() => m.methodSample(id, 2), 11, 2);
  console.log(`  build ${id.padEnd(10)} ${ms.toFixed(3)} ms`);
}
const metrics = median(() => m.compareMethods(['rb', 'slerp', 'jarek']), 5, 1);
console.log(`metrics table of rb, slerp, jarek: ${metrics.toFixed(1)} ms`);
m.free();
