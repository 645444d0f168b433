// The measured poses a lesson step hands the student (its `samples` field, www/lessons/README.md):
// a known smooth motion sampled at `count` times, with Gaussian noise in position and angle and
// a share of gross outliers — what a motion-capture or odometry log looks like.
//
// Generated here, in the page, from the step's numbers and the student's seed, with variants.js's
// mulberry32: the sequence is part of the lesson format (a reload, or the same seed anywhere,
// gives the same poses), so no library whose generator might change is used. The normal draws
// are Box–Muller, a few lines on top of it.
//
// Fetched only with a step that has measured poses (apply.js loadSamples): a lesson link without
// one never downloads it. The rules of the `samples` field live with the format (format.js).
import { fnv1a, mulberry32 } from './variants.js';
import { RESIDUAL_FIELDS, SAMPLE_FIELDS } from './format.js';
import { DEG, fmt, inRange, rangeText } from './checks.js';
/** How far an outlier's rotation is turned, in radians, per scene unit of `outlierSize`. */
const OUTLIER_TURN = 0.5;

const TAU = 2 * Math.PI;
/** The quaternion [w, x, y, z] of the rotation vector `v` (radians). */
function qexp(v) {
  const a = Math.hypot(...v);
  if (a < 1e-12) return [1, v[0] / 2, v[1] / 2, v[2] / 2];
  const s = Math.sin(a / 2) / a;
  return [Math.cos(a / 2), v[0] * s, v[1] * s, v[2] * s];
}
/** The product a·b of quaternions [w, x, y, z]. */
function qmul(a, b) {
  return [
    a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
    a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
    a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
    a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0],
  ];
}

/**
 * The smooth motions a step may sample, each a pose at `s ∈ [0, 1]` (the share of the duration):
 * origin and rotation [w, x, y, z].
 */
export const SAMPLE_MOTIONS = {
  // The names are format.js's SAMPLE_MOTION_NAMES (tests/js/lesson-variants.test.mjs compares them).
  /** A body climbing 1¼ turns of a helix of radius 3 and height 2, facing along it, rocking. */
  helix: (s) => {
    const a = 1.25 * TAU * s;
    return { origin: [3 * Math.cos(a), 3 * Math.sin(a), 2 * s], rotation: qmul(qexp([0, 0, a + Math.PI / 2]), qexp([0.3 * Math.sin(2 * a), 0, 0])) };
  },
  /** A body gliding 6 units along x over one and a half waves, pitching with the slope. */
  wave: (s) => {
    const a = 1.5 * TAU * s;
    return { origin: [6 * s - 3, 0, 1.2 * Math.sin(a)], rotation: qexp([0, -Math.atan(1.2 * 1.5 * TAU * Math.cos(a) / 6), 0]) };
  },
};

/** A normal draw (mean 0, deviation 1) from the uniform generator `rand` (Box–Muller). */
function gauss(rand) {
  const u = 1 - rand(); // in (0, 1]: the logarithm is finite
  return Math.sqrt(-2 * Math.log(u)) * Math.cos(TAU * rand());
}

/**
 * The measured poses of a valid `samples` spec for `seed` (a 32-bit whole number, the student's:
 * the lesson's variant seed mixed with the step's index, format.js lessonVariant): `{document,
 * outlier}` — an open motion document of `count` poses at times spread over `duration` seconds,
 * each origin moved by N(0, noise²) per coordinate and each rotation turned by a rotation
 * vector of N(0, angleNoise²) per component (degrees), and `round(outliers · count)` of them,
 * chosen at random, moved `outlierSize` further in a random direction (and turned half a radian
 * per scene unit of it); `outlier[i]` says which.
 */
export function generateSamples(spec, seed = 0) {
  const o = { ...SAMPLE_FIELDS, ...spec };
  const rand = mulberry32(fnv1a(`samples:${seed >>> 0}`));
  const n = o.count;
  const motion = SAMPLE_MOTIONS[o.motion];
  const sigmaA = (o.angleNoise * Math.PI) / 180;
  const poses = [];
  const times = [];
  for (let i = 0; i < n; i++) {
    const s = i / (n - 1);
    const p = motion(s);
    const origin = p.origin.map((x) => x + o.noise * gauss(rand));
    const turn = qexp([sigmaA * gauss(rand), sigmaA * gauss(rand), sigmaA * gauss(rand)]);
    poses.push({ origin, rotation: qmul(p.rotation, turn) });
    times.push(Number((o.duration * s).toPrecision(12)));
  }
  // The outliers: a partial Fisher–Yates shuffle picks them without repeats.
  const outlier = new Array(n).fill(false);
  const order = Array.from({ length: n }, (_, i) => i);
  const k = Math.round(o.outliers * n);
  for (let j = 0; j < k; j++) {
    const r = j + Math.floor(rand() * (n - j));
    [order[j], order[r]] = [order[r], order[j]];
    const i = order[j];
    outlier[i] = true;
    const d = [gauss(rand), gauss(rand), gauss(rand)];
    const len = Math.hypot(...d) || 1;
    const dir = d.map((x) => x / len);
    poses[i].origin = poses[i].origin.map((x, c) => x + o.outlierSize * dir[c]);
    poses[i].rotation = qmul(poses[i].rotation, qexp(dir.map((x) => x * OUTLIER_TURN * o.outlierSize)));
  }
  return { document: { name: `measured-${o.motion}`, closed: false, poses, times }, outlier };
}

/** The samples of each step object, generated once: a Check reads the poses the dialog was given. */
const made = new WeakMap();

/**
 * The measured poses of step `s` (which has `samples`): generateSamples of its spec and seed,
 * with `residuals(check, motion, analysis)`, the evaluation of a `residuals` check against them.
 */
export function stepSamples(s) {
  if (!made.has(s)) {
    const samples = generateSamples(s.samples, s.samples.seed ?? 0);
    samples.residuals = (check, motion, analysis) => residualsCheck(samples, check, motion, analysis);
    made.set(s, samples);
  }
  return made.get(s);
}

/**
 * A `residuals` check (checks.js evaluateCheck hands it here): how far the motion on the page — its control poses at their key times,
 * as the cubic B-spline draws them — is from the step's measured poses (all of them, or with
 * `inliers` those that are no outliers), by the core's measureFit (the report a fit gives).
 */
function residualsCheck(samples, check, motion, analysis) {
  if (!analysis) return { ok: false, got: 'the analysis functions are not loaded yet; check again in a moment', want: '' };
  const scheme = motion.options().scheme;
  if (scheme !== 'bspline') return { ok: false, got: `the motion is drawn with the ${scheme} scheme`, want: 'the cubic B-spline (a fit sets it; or choose it in the panel)' };
  let doc = samples.document;
  if (check.inliers) doc = { ...doc, poses: doc.poses.filter((_, i) => !samples.outlier[i]), times: doc.times.filter((_, i) => !samples.outlier[i]) };
  const report = analysis.measureFit(motion.toDocument(), doc);
  const got = [];
  const want = [];
  let ok = true;
  for (const [f, { label, unit }] of Object.entries(RESIDUAL_FIELDS)) {
    if (check[f] === undefined) continue;
    const v = unit === '°' ? report[f] * DEG : report[f];
    ok &&= inRange(v, check[f]);
    got.push(`${label} ${fmt(v)}${unit}`);
    want.push(`${label} ${rangeText(check[f])}${unit}`);
  }
  const of = check.inliers ? `the ${doc.poses.length} measured poses that are no outliers` : `the ${doc.poses.length} measured poses`;
  return { ok, got: `${got.join(', ')} from ${of}`, want: want.join(', ') };
}

