// WebAssembly benchmark of the comparison methods, in Node's V8.
//
//   node benches/wasm/methods.mjs                  # the playground's build, www/pkg/
//   node benches/wasm/methods.mjs BEFORE AFTER     # interleaved A/B of two npm builds
//
// With no arguments it times, in the playground's build (which has the `methods` feature; build
// it first: BUILD_ONLY=1 ./scripts/serve.sh), what the Methods view computes: Ramamoorthi–Barr
// on scene C1 (7 keyframes, α = 1000, S = 5) with 4 variable frames, each other method built on
// the same poses, and a full metrics row.
//
// With two npm package directories (each built by scripts/build-pkg.sh; the methods are in the
// `screwbender/full` entry, DIR/full/), it times Ramamoorthi–Barr on scene C1 with 4 variable
// frames, `quaternionSpline({ variableFrames: 4, samples: 2 })`, in both builds loaded in this one
// process, alternating bursts so that a drifting machine affects both alike, compares their
// stages (same frames; the largest change of the objectives), and prints the median ms of each build and the min / median
// / max of the per-burst ratios (after / before):
//
//   PKG_DIR=/tmp/rb-before VIEWER=0 PACK=0 ./scripts/build-pkg.sh   # before the change
//   VIEWER=0 PACK=0 ./scripts/build-pkg.sh                          # after, into pkg/
//   node benches/wasm/methods.mjs /tmp/rb-before pkg
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const dirs = process.argv.slice(2).map((d) => path.resolve(d));

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

const stats = (v) => {
  const s = [...v].sort((a, b) => a - b);
  return [s[0], s[s.length >> 1], s[s.length - 1]];
};

/** Interleaved A/B of `quaternionSpline({ variableFrames: 4 })` in two npm builds. */
async function compare([before, after]) {
  const entry = (d) => path.join(d, 'full', 'node.js');
  if (!before || !after || ![before, after].every((d) => fs.existsSync(entry(d)))) {
    console.error('usage: node benches/wasm/methods.mjs [BEFORE_PKG AFTER_PKG] (each built by scripts/build-pkg.sh)');
    process.exit(1);
  }
  const modules = [];
  for (const d of [before, after]) modules.push(await import(pathToFileURL(entry(d)).href));
  console.log(`node ${process.version}; before ${before}, after ${after}`);
  const motions = modules.map((sb) => (sb.Motion.fromPreset ? sb.Motion.fromPreset('rb_sphere7') : sb.Motion.fromScene('rb_sphere7')));
  const fit = (m) => m.quaternionSpline({ variableFrames: 4, samples: 2 });
  // The same fit in both builds: bit for bit, or (when a change reorders the arithmetic) the
  // largest relative change of the stage objectives and the iteration counts.
  const [a, b] = motions.map(fit);
  if (a.stages.length !== b.stages.length || a.frameTimes.some((t, i) => t !== b.frameTimes[i])) {
    throw new Error(`the builds place different frames: ${a.frameTimes} vs ${b.frameTimes}`);
  }
  const change = Math.max(...a.stages.map((s, i) => Math.abs(b.stages[i].objective - s.objective) / s.objective));
  const iterations = (r) => r.stages.reduce((n, s) => n + s.iterations, 0);
  console.log(
    change === 0
      ? 'stage objectives: the same bits'
      : `stage objectives: largest relative change ${change.toExponential(1)}; L-BFGS iterations ${iterations(a)} before, ${iterations(b)} after`,
  );
  // Wall time, and the process's CPU time (user + system, µs resolution), which does not count
  // the time other processes hold the cores (this machine is shared).
  const cpu = () => {
    const u = process.cpuUsage();
    return (u.user + u.system) / 1000;
  };
  const times = [[], []];
  const cpus = [[], []];
  const ratios = [];
  const cpuRatios = [];
  const reps = 10;
  for (let burst = 0; burst < 80; burst++) {
    const order = burst % 2 ? [1, 0] : [0, 1];
    const t = [0, 0];
    const c = [0, 0];
    for (const i of order) {
      const [t0, c0] = [performance.now(), cpu()];
      for (let r = 0; r < reps; r++) fit(motions[i]);
      t[i] = (performance.now() - t0) / reps;
      c[i] = (cpu() - c0) / reps;
    }
    for (const i of [0, 1]) {
      times[i].push(t[i]);
      cpus[i].push(c[i]);
    }
    ratios.push(t[1] / t[0]);
    cpuRatios.push(c[1] / c[0]);
  }
  const ms = (v) => stats(v).map((x) => x.toFixed(3)).join(' / ');
  const ratio = (v) => stats(v).map((x) => x.toFixed(2)).join(' / ');
  console.log(`Ramamoorthi–Barr rb_sphere7, 7 keyframes + 4 variable frames, ms per fit (min / median / max of ${times[0].length} bursts of ${reps}):`);
  console.log(`  wall: before ${ms(times[0])}; after ${ms(times[1])}; after / before ${ratio(ratios)}`);
  console.log(`  CPU:  before ${ms(cpus[0])}; after ${ms(cpus[1])}; after / before ${ratio(cpuRatios)}`);
  motions.forEach((m) => m.free());
}

/** What the Methods view computes, in the playground's build. */
async function playground() {
  const pkg = path.join(repo, 'www/pkg');
  const sb = await import(pathToFileURL(path.join(pkg, 'screwbender.js')).href);
  await sb.default({ module_or_path: fs.readFileSync(path.join(pkg, 'screwbender_bg.wasm')) });
  console.log(`node ${process.version}, screwbender ${sb.version()} (www/pkg)`);
  const m = (sb.Motion.fromPreset ? sb.Motion.fromPreset('rb_sphere7') : sb.Motion.fromScene('rb_sphere7'));
  // quaternionSpline builds the initial spline (no optimisation: cheap) and the optimised fit,
  // and samples EL and |q| `samples` times; with 2 samples the optimised fit is nearly all of it,
  // and that fit alone is what the Methods view's overlay (methodSample) costs.
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
}

await (dirs.length ? compare(dirs) : playground());
