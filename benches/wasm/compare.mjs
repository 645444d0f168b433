// Interleaved comparisons of the npm module's JS `subdivide()` of 32 random poses by 6 levels
// (2048 refined poses) per scheme, direct rules.
//
// A/B of two builds in one process, alternating bursts of the two modules, so that a drifting
// machine affects both alike:
//
//   PKG_DIR=/tmp/before FULL=0 VIEWER=0 PACK=0 ./scripts/build-pkg.sh   # the "before" build
//   node benches/wasm/compare.mjs /tmp/before pkg [--browser]
//
// Prints, per scheme, the min / median / max ms per call of each build (the minimum is the least
// disturbed by other processes) and the min / median / max of the per-burst ratios (after /
// before): for `subdivide()` alone, for `subdivide()` then one `poseAt()` (the motion ready to
// evaluate), and for `subdivideInto(out)` with a kept `out` (`subdivide()` in a build without
// it). In Node, or with --browser in headless Chromium (whose clock has 0.1 ms steps: each burst
// times 20 calls; the builds must then lie inside the repo, which the page is served from).
// CHUNKS=… (default 6) sets the number of 10-burst chunks per row.
//
// wasm vs native for the same work (the same subdivision of the same poses, the refined poses
// checked bit for bit):
//
//   cargo build --release -p screwbender --example subdivide_timing
//   node benches/wasm/compare.mjs --native pkg [--browser]
//
// Two processes cannot be interleaved burst by burst, so rounds alternate: a round of bursts in
// the wasm module (`subdivide()`, then `subdivideInto(out)`), then a round of the native example
// (crates/screwbender/examples/subdivide_timing.rs), and so on (ROUNDS=…, default 15). Prints
// the min / median / max ms per call of each over all bursts, and the min / median / max over
// rounds of wasm / native (each round's median bursts). The native side uses the widest lanes
// the processor has (8 with AVX-512, 4 with AVX2); wasm SIMD has 2 per instruction. To compare
// at the same width, build the example with the measuring feature and cap its lanes:
//
//   cargo build --release -p screwbender --example subdivide_timing --features lane-cap
//   SCREWBENDER_MAX_LANES=2 node benches/wasm/compare.mjs --native pkg [--browser]
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { pathToFileURL } from 'node:url';
import { repo, withBrowserPage } from './bench.mjs';

const args = process.argv.slice(2);
const browser = args.includes('--browser');
const native = args.includes('--native');
const dirs = args.filter((a) => !a.startsWith('--')).map((d) => path.resolve(d));
const usage =
  'usage: node benches/wasm/compare.mjs BEFORE_PKG AFTER_PKG [--browser]\n' +
  '       node benches/wasm/compare.mjs --native PKG [--browser]   (each built by scripts/build-pkg.sh)';
if (dirs.length !== (native ? 1 : 2) || !dirs.every((d) => fs.existsSync(path.join(d, 'node.js')))) {
  console.error(usage);
  process.exit(1);
}
for (const d of dirs) {
  if (!d.startsWith(repo + path.sep) && browser) {
    console.error(`--browser serves the repo root only: ${d} is outside ${repo} (copy it into the repo, e.g. target/)`);
    process.exit(1);
  }
}

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
const triple = (v, digits = 3) => stats(v).map((x) => x.toFixed(digits)).join(' / ');
const schemes = ['bspline', 'fourpoint', 'jarek'];
const reps = 20;
/** A/B: chunks of 10 bursts per row. */
const chunks = Number(process.env.CHUNKS ?? 6);

/**
 * The timing body, run in Node or in the page: for each module in `modules`, a motion of the
 * control poses; `bursts(count, evaluate)` then alternates `count` bursts of `reps` calls over
 * the modules and returns the ms per call, one list per module. (Self-contained: the page
 * receives its source.)
 */
function makeRunner(modules, control, scheme, reps) {
  const motions = modules.map((sb) => sb.Motion.fromPoses(control, true, { scheme, rules: 'direct', levels: 6 }));
  const outs = motions.map((m) => new Float64Array(7 * m.refinedCount));
  return {
    results: () => motions.map((m) => Array.from(m.subdivide())),
    /** `kind`: 'subdivide', 'poseAt' (subdivide() then poseAt(0.5)) or 'into' (subdivideInto(out), kept `out`; subdivide() in a build without it). */
    bursts(count, kind) {
      const times = motions.map(() => []);
      for (let burst = 0; burst < count; burst++) {
        motions.forEach((m, i) => {
          const into = kind === 'into' && typeof m.subdivideInto === 'function';
          const t0 = performance.now();
          for (let r = 0; r < reps; r++) {
            m.setLevels(6);
            if (into) m.subdivideInto(outs[i]);
            else m.subdivide();
            if (kind === 'poseAt') m.poseAt(0.5);
          }
          times[i].push((performance.now() - t0) / reps);
        });
      }
      return times;
    },
    free: () => motions.forEach((m) => m.free()),
  };
}

/**
 * Runs `body(run)` where `run(scheme, method, ...args)` calls the runner of `scheme` (over the
 * modules in `dirs`) in Node or in the page.
 */
async function withRunners(body) {
  if (!browser) {
    const modules = await Promise.all(dirs.map((d) => import(pathToFileURL(path.join(d, 'node.js')).href)));
    console.log(`node ${process.version}; ${dirs.join(' vs ')}`);
    const runners = Object.fromEntries(schemes.map((s) => [s, makeRunner(modules, control, s, reps)]));
    await body(async (scheme, method, ...rest) => runners[scheme][method](...rest));
    return;
  }
  await withBrowserPage(async (page, version) => {
    console.log(`headless ${version}; ${dirs.join(' vs ')}`);
    const urls = dirs.map((d) => '/' + path.relative(repo, path.join(d, 'screwbender.js')).split(path.sep).join('/'));
    await page.evaluate(
      async ({ urls, control, schemes, reps, source }) => {
        const modules = [];
        for (const url of urls) {
          const sb = await import(url);
          await sb.default();
          modules.push(sb);
        }
        const makeRunner = new Function(`return (${source})`)();
        const poses = new Float64Array(control);
        window.runners = Object.fromEntries(schemes.map((s) => [s, makeRunner(modules, poses, s, reps)]));
      },
      { urls, control: Array.from(control), schemes, reps, source: makeRunner.toString() },
    );
    await body((scheme, method, ...rest) =>
      page.evaluate(({ scheme, method, rest }) => window.runners[scheme][method](...rest), { scheme, method, rest }),
    );
  });
}

if (!native) {
  await withRunners(async (run) => {
    const label = { subdivide: 'subdivide()', poseAt: 'subdivide() + poseAt', into: 'subdivideInto(out)' };
    for (const [scheme, kind] of schemes.flatMap((s) => ['subdivide', 'poseAt', 'into'].map((k) => [s, k]))) {
      const same = await run(scheme, 'results');
      if (!same[0].every((v, i) => Object.is(v, same[1][i]))) throw new Error(`${scheme}: the builds disagree`);
      // Bursts in chunks (a page call each in Chromium), alternating the two builds.
      const times = [[], []];
      for (let chunk = 0; chunk < chunks; chunk++) {
        const t = await run(scheme, 'bursts', 10, kind);
        times[0].push(...t[0]);
        times[1].push(...t[1]);
      }
      const ratios = times[1].map((t, i) => t / times[0][i]);
      console.log(
        `${label[kind]} 32 × 6, ${scheme} direct: before ${triple(times[0])} ms, after ${triple(times[1])} ms; ` +
          `after / before ${triple(ratios, 2)} (min / median / max)`,
      );
    }
  });
} else {
  const exe = path.join(process.env.CARGO_TARGET_DIR ?? path.join(repo, 'target'), 'release/examples/subdivide_timing');
  if (!fs.existsSync(exe)) {
    console.error(`${exe} is missing: cargo build --release -p screwbender --example subdivide_timing`);
    process.exit(1);
  }
  const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'sb-native-'));
  const posesFile = path.join(tmp, 'poses.txt');
  fs.writeFileSync(posesFile, Array.from(control).join(' ') + '\n');
  const bursts = 10;
  const rounds = Number(process.env.ROUNDS ?? 15);
  try {
    await withRunners(async (run) => {
      for (const scheme of schemes) {
        const out = path.join(tmp, `${scheme}.txt`);
        execFileSync(exe, [posesFile, scheme, '1', '1', out]);
        const want = fs.readFileSync(out, 'utf8').trim().split(/\s+/).map(Number);
        const [got] = await run(scheme, 'results');
        if (got.length !== want.length || !got.every((v, i) => Object.is(v, want[i]))) {
          throw new Error(`${scheme}: wasm and native refined poses differ`);
        }
        const kinds = ['subdivide', 'into'];
        const wasm = { subdivide: [], into: [] };
        const ratios = { subdivide: [], into: [] };
        const nat = [];
        for (let round = 0; round < rounds; round++) {
          const w = {};
          for (const kind of kinds) {
            // The first bursts after a native run are slower (caches and predictors refilled):
            // discarded, as the native side's warm-up calls.
            await run(scheme, 'bursts', bursts, kind);
            [w[kind]] = await run(scheme, 'bursts', bursts, kind);
            wasm[kind].push(...w[kind]);
          }
          const n = execFileSync(exe, [posesFile, scheme, String(reps), String(bursts)], { encoding: 'utf8' })
            .trim()
            .split('\n')
            .map(Number);
          nat.push(...n);
          for (const kind of kinds) ratios[kind].push(stats(w[kind])[1] / stats(n)[1]);
        }
        console.log(`${scheme} direct, 32 × 6 (same bits): native (lanes: ${process.env.SCREWBENDER_MAX_LANES || 'the widest'}) ${triple(nat)} ms`);
        for (const kind of kinds) {
          console.log(
            `  wasm ${kind === 'into' ? 'subdivideInto(out)' : 'subdivide()'} ${triple(wasm[kind])} ms; ` +
              `wasm / native ${triple(ratios[kind], 2)} (min / median / max over ${rounds} rounds)`,
          );
        }
      }
    });
  } finally {
    fs.rmSync(tmp, { recursive: true, force: true });
  }
}
