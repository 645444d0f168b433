// The checks of a lesson exercise, evaluated against the app's Motion through the wasm API
// (kinds and fields: www/lessons/README.md). Each returns {ok, got, want}: `got` says what was
// measured, in words the feedback line shows.
import { withS } from './format.js';

export const DEG = 180 / Math.PI;
/** Offset either side of a knot for the velocity on each side (well inside a refined span: ≥ 2^-8). */
const KNOT_EPS = 1e-9;

export const fmt = (x) => (Math.abs(x) >= 1e-3 || x === 0 ? Number(x.toPrecision(4)).toString() : x.toExponential(2));
export const inRange = (x, r) => (typeof r === 'number' ? Math.abs(x - r) <= 1e-9 * Math.max(1, Math.abs(r)) : (r.min === undefined || x >= r.min) && (r.max === undefined || x <= r.max));
export const rangeText = (r) => (typeof r === 'number' ? `= ${fmt(r)}` : r.min !== undefined && r.max !== undefined ? `in [${fmt(r.min)}, ${fmt(r.max)}]` : r.min !== undefined ? `≥ ${fmt(r.min)}` : `≤ ${fmt(r.max)}`);
const norm = (v) => Math.hypot(...v);
const sub = (a, b) => a.map((x, k) => x - b[k]);

/**
 * The velocity jump |v(u⁺) − v(u⁻)| of body point `point` (local) at control pose `i`
 * (docs/math/polyscrew.md §4, metrics.md §3): the kinematics of the refined span that starts at
 * u = i against those of the span that ends there. Throws for the ends of an open motion.
 */
export function velocityJumpAt(motion, i, point = [0, 0, 0]) {
  const n = motion.poseCount;
  if (i >= n) throw new Error(`pose ${i} does not exist (the motion has ${n} poses)`);
  if (!motion.closed && (i === 0 || i === n - 1)) throw new Error(`pose ${i} ends the open motion: it has no velocity on one side`);
  const before = i === 0 ? n - KNOT_EPS : i - KNOT_EPS;
  const a = motion.kinematicsAt(before, point);
  const b = motion.kinematicsAt(i, point);
  return norm(sub(b.velocity, a.velocity));
}

/**
 * Evaluates one check; `answer` is the chosen index of a multiple-choice exercise (or null).
 * `ctx`: what a check of the step's measured poses needs — `samples` (samples.js stepSamples of
 * the step, or null) and `analysis` (the analysis module once loaded, or null).
 */
export function evaluateCheck(check, motion, answer, ctx = {}) {
  switch (check.kind) {
    case 'choice':
      return { kind: 'choice', ok: answer === check.answer, got: answer === null ? 'no answer chosen' : `answer ${answer + 1}`, want: 'the right answer' };
    case 'spanScrew': {
      const spans = motion.spanScrews();
      if (check.span >= spans.length) return { ok: false, got: `span ${check.span} does not exist (${spans.length} spans)`, want: '' };
      const s = spans[check.span];
      const got = [];
      const want = [];
      let ok = true;
      if (check.screw !== undefined) {
        ok &&= s.kind === check.screw;
        got.push(`a ${s.kind === 'general' ? 'general screw' : s.kind}`);
        want.push(`a ${check.screw === 'general' ? 'general screw' : check.screw}`);
      }
      for (const [f, v, unit] of [['angle', s.angle * DEG, '°'], ['slide', s.slide, ''], ['pitch', s.pitch ?? Infinity, '']]) {
        if (check[f] === undefined) continue;
        ok &&= inRange(v, check[f]);
        got.push(`${f} ${Number.isFinite(v) ? fmt(v) : '∞'}${unit}`);
        want.push(`${f} ${rangeText(check[f])}${unit}`);
      }
      return { ok, got: `span ${check.span} is ${got.join(', ')}`, want: want.join(', ') };
    }
    case 'pose': {
      if (check.pose >= motion.poseCount) return { ok: false, got: `pose ${check.pose} does not exist`, want: '' };
      const p = motion.pose(check.pose);
      let ok = true;
      const got = [];
      const want = [];
      if (check.origin) {
        const d = norm(sub(p.origin, check.origin));
        const tol = check.tolerance ?? 0.05;
        ok &&= d <= tol;
        got.push(`origin ${fmt(d)} from the target`);
        want.push(`within ${fmt(tol)}`);
      }
      if (check.coordinate) {
        const k = 'xyz'.indexOf(check.coordinate);
        const d = Math.abs(p.origin[k] - check.value);
        const tol = check.tolerance ?? 0.05;
        ok &&= d <= tol;
        got.push(`${check.coordinate} = ${fmt(p.origin[k])}`);
        want.push(`${check.coordinate} within ${fmt(tol)} of ${fmt(check.value)}`);
      }
      if (check.rotation) {
        const q = check.rotation;
        const qn = norm(q);
        const dot = Math.min(1, Math.abs(p.rotation.reduce((s, x, k) => s + x * q[k], 0)) / qn);
        const angle = 2 * Math.acos(dot) * DEG;
        const tol = check.angleTolerance ?? 2;
        ok &&= angle <= tol;
        got.push(`rotation ${fmt(angle)}° from the target`);
        want.push(`within ${fmt(tol)}°`);
      }
      return { ok, got: `pose ${check.pose}: ${got.join(', ')}`, want: want.join(', ') };
    }
    case 'options': {
      const o = motion.options();
      let ok = true;
      const got = [];
      const want = [];
      for (const f of ['scheme', 'rules']) {
        if (check[f] === undefined) continue;
        ok &&= o[f] === check[f];
        got.push(`${f} ${o[f]}`);
        want.push(`${f} ${check[f]}`);
      }
      if (check.closed !== undefined) {
        ok &&= motion.closed === check.closed;
        got.push(motion.closed ? 'closed' : 'open');
        want.push(check.closed ? 'closed' : 'open');
      }
      const c = withS(check);
      for (const f of ['levels', 's']) {
        if (c[f] === undefined) continue;
        ok &&= inRange(o[f], c[f]);
        got.push(`${f === 's' ? 'J_s' : f} ${fmt(o[f])}`);
        want.push(`${f === 's' ? 'J_s' : f} ${rangeText(c[f])}`);
      }
      return { ok, got: got.join(', '), want: want.join(', ') };
    }
    case 'velocityJump': {
      let jump;
      try {
        jump = velocityJumpAt(motion, check.pose, check.point);
      } catch (e) {
        return { ok: false, got: e.message, want: '' };
      }
      const r = { min: check.min, max: check.max };
      return { ok: inRange(jump, r), got: `the velocity jump at pose ${check.pose} is ${fmt(jump)}`, want: rangeText(r) };
    }
    case 'metric': {
      // Present once the analysis module has loaded (the player fetches it with the lesson).
      if (typeof motion.motionMetrics !== 'function') return { ok: false, got: 'the analysis functions are not loaded yet; check again in a moment', want: '' };
      const m = motion.motionMetrics(check.points);
      const v = check.field === 'fourPointGap' ? m.fourPointGap : m.row[check.field];
      if (typeof v !== 'number') return { ok: false, got: `${check.field} could not be measured (${m.row.notes.join('; ')})`, want: '' };
      const r = { min: check.min, max: check.max };
      return { ok: inRange(v, r), got: `${check.field.replace(/_/g, ' ')} ${fmt(v)}`, want: rangeText(r) };
    }
    case 'controlPoses': {
      const r = { min: check.min, max: check.max };
      return { ok: inRange(motion.poseCount, r), got: `${motion.poseCount} control poses`, want: `a count ${rangeText(r)}` };
    }
    case 'residuals':
      // samples.js's, fetched with the step's measured poses.
      return ctx.samples ? ctx.samples.residuals(check, motion, ctx.analysis ?? null) : { ok: false, got: 'this step has no measured poses', want: '' };
    default:
      return { ok: false, got: `unknown check ${check.kind}`, want: '' };
  }
}

/**
 * Evaluates every check of an exercise: {ok, results}. Errors of the wasm API count as failures.
 * `ctx` as evaluateCheck's.
 */
export function evaluateExercise(exercise, motion, answer, ctx = {}) {
  const results = exercise.checks.map((c) => {
    try {
      return evaluateCheck(c, motion, answer, ctx);
    } catch (e) {
      return { ok: false, got: `could not check: ${e.message}`, want: '' };
    }
  });
  return { ok: results.every((r) => r.ok), results };
}
