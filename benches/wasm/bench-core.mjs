// The wasm benchmark body, shared by Node (bench.mjs) and headless Chromium (bench.mjs
// --browser): takes the loaded `screwbender` module, returns the figures. Fixed-seed inputs.

/** mulberry32: a small seeded PRNG, so every run times the same inputs. */
function rng(seed) {
  return () => {
    seed = (seed + 0x6d2b79f5) | 0;
    let t = Math.imul(seed ^ (seed >>> 15), 1 | seed);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/** `count` random poses (origins in [-5, 5]³, uniform-ish unit quaternions), 7 numbers each. */
function randomPoses(random, count) {
  const out = new Float64Array(7 * count);
  for (let k = 0; k < count; k++) {
    const q = [random() - 0.5, random() - 0.5, random() - 0.5, random() - 0.5];
    const n = Math.hypot(...q);
    out.set([10 * random() - 5, 10 * random() - 5, 10 * random() - 5, ...q.map((v) => v / n)], 7 * k);
  }
  return out;
}

const poseAt = (a, k) => ({ origin: Array.from(a.subarray(7 * k, 7 * k + 3)), rotation: Array.from(a.subarray(7 * k + 3, 7 * k + 7)) });

/**
 * Runs `fn` until `minMs` have passed and at least 5 samples are taken (after one warm-up call);
 * returns the fastest sample in ms per call (the least disturbed by other processes on a shared
 * machine) and the median. A sample times as many calls as take about 2 ms: browsers round
 * `performance.now()` (Chromium to 0.1 ms), which single calls of 0.2 ms cannot be timed with.
 */
function timeIt(now, fn, minMs = 500) {
  fn();
  let calls = 1;
  for (;;) {
    const t0 = now();
    for (let r = 0; r < calls; r++) fn();
    if (now() - t0 >= 2 || calls >= 1 << 12) break;
    calls *= 2;
  }
  const perCall = [];
  const start = now();
  while (now() - start < minMs || perCall.length < 5) {
    const t0 = now();
    for (let r = 0; r < calls; r++) fn();
    perCall.push((now() - t0) / calls);
  }
  perCall.sort((a, b) => a - b);
  return { best: perCall[0], median: perCall[perCall.length >> 1], runs: perCall.length * calls };
}

const fmt = (t) => `best ${t.best.toFixed(3)} ms, median ${t.median.toFixed(3)} ms`;

/**
 * Runs the benchmark. `now` is a millisecond clock (performance.now).
 * Returns { screwPoses, screwPairs, subdivision: [...] } with rates and times.
 */
export function runBench(sb, now = () => performance.now(), log = () => {}) {
  const random = rng(20261122);
  const results = { version: sb.version() };

  // One screw, many t (logarithm once, then exp per t): the "screwPoses" figure.
  const pair = randomPoses(random, 2);
  const a = poseAt(pair, 0);
  const b = poseAt(pair, 1);
  // 2^16 fractions per call (3.5 MB of output): large enough to amortise the call, small enough
  // that memory bandwidth (56 MB per call at 2^20) does not dominate.
  const n = 1 << 16;
  const ts = new Float64Array(n);
  for (let k = 0; k < n; k++) ts[k] = 2 * random() - 0.5;
  const tPoses = timeIt(now, () => sb.screwPoses(a, b, ts));
  results.screwPoses = { count: n, ...tPoses, screwsPerSecond: (n / tPoses.best) * 1000 };
  log(`screwPoses: ${n} t per call, ${fmt(tPoses)} → ${(n / tPoses.best / 1000).toFixed(2)} M screws/s (best)`);

  // Full evaluations: logarithm + exponential per (a, t, b).
  const m = 1 << 16;
  const starts = randomPoses(random, m);
  const ends = randomPoses(random, m);
  const ts2 = ts.subarray(0, m);
  const tPairs = timeIt(now, () => sb.screwPairs(starts, ends, ts2));
  results.screwPairs = { count: m, ...tPairs, screwsPerSecond: (m / tPairs.best) * 1000 };
  log(`screwPairs: ${m} full screws per call, ${fmt(tPairs)} → ${(m / tPairs.best / 1000).toFixed(2)} M screws/s (best)`);

  // Subdivision of 32 random poses by 6 levels (2048 refined poses), closed, per scheme.
  const control = randomPoses(random, 32);
  results.subdivision = [];
  const configs = [
    ['bspline', 'direct'],
    ['fourpoint', 'direct'],
    ['jarek', 'direct'],
    ['bspline', 'split'],
    ['fourpoint', 'split'],
    ['jarek', 'split'],
    [{ scheme: 'j', j: 0.3 }, 'direct'],
  ];
  for (const [scheme, rules] of configs) {
    const options = typeof scheme === 'string' ? { scheme, rules, levels: 6 } : { ...scheme, rules, levels: 6 };
    const motion = sb.Motion.fromPoses(control, true, options);
    // setLevels invalidates the cached result, so each call subdivides afresh.
    const t = timeIt(now, () => {
      motion.setLevels(6);
      motion.subdivide();
    });
    const name = typeof scheme === 'string' ? scheme : `j(${scheme.j})`;
    results.subdivision.push({ scheme: name, rules, poses: 32, levels: 6, refined: motion.refinedCount, ...t });
    log(`subdivide 32 poses × 6 levels, ${name} ${rules}: ${fmt(t)} (${motion.refinedCount} poses)`);
    if (rules === 'direct' && typeof motion.subdivideInto === 'function') {
      // The same into a kept array: no fresh memory per call.
      const out = new Float64Array(7 * motion.refinedCount);
      const into = timeIt(now, () => {
        motion.setLevels(6);
        motion.subdivideInto(out);
      });
      results.subdivision.push({ scheme: name, rules, into: true, poses: 32, levels: 6, refined: motion.refinedCount, ...into });
      log(`subdivideInto(out) 32 poses × 6 levels, ${name} ${rules}: ${fmt(into)}`);
    }
    motion.free();
  }
  return results;
}
