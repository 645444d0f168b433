// Methods view: up to three motion methods of the literature overlaid on the same control poses
// (trajectories of the body points in distinct colours), their metrics side by side, and for
// Ramamoorthi–Barr the variable frames and the Euler–Lagrange error before/after optimisation;
// for Chaudhry–Cameron the triangle's vertices x/y/z against time, with end condition (18) or (19).
import { LAYER, Segments, track, poseOf } from '../figure/slots.js';
import { hexLinear, poseMatrix, add, scale } from '../math.js';
import { lineChart, fmt } from './plot.js';
import { el } from '../dom.js';

/** The wasm functions of this view, from the analysis module the dock hands to create(). */
let listMethods;

/** Overlay colours of the three method slots. */
const SLOT_COLORS = ['#0072b2', '#d55e00', '#009e73'];
/** Samples per control span of an overlaid method. */
const SAMPLES_PER_SPAN = 48;
/** Methods shown first for a preset (the paper each scene comes from), else the default. */
const PRESET_METHODS = {
  triangle7: ['cc0', 'cc1', 'fourpoint'],
  rb_sphere7: ['rb', 'slerp', 'jarek'],
  rb_ibeam7: ['rb', 'decoupled', 'jarek'],
  rb_molecule4: ['rb', 'kks', 'jarek'],
};
const DEFAULT_METHODS = ['fourpoint', 'decoupled', 'slerp'];

/** Short human names of the methods (table columns, notes); the menus use the core's titles. */
export const METHOD_NAMES = {
  polyscrew: 'Polyscrew',
  bspline: 'B-spline (ScrewBender)',
  fourpoint: '4-point (ScrewBender)',
  jarek: 'Jarek (ScrewBender)',
  slerp: 'SLERP + linear',
  decoupled: 'Decoupled (Catmull–Rom + Squad)',
  kks: 'Kim–Kim–Shin',
  se3bspline: 'SE(3) B-spline',
  se3interp: 'SE(3) B-spline (interpolating)',
  splitinterp: 'R³×SO(3) B-spline (interpolating)',
  rb: 'Ramamoorthi–Barr',
  cc0: 'Chaudhry–Cameron C⁰',
  cc1: 'Chaudhry–Cameron C¹',
  barr: 'Barr et al.',
};
const nameOf = (id) => METHOD_NAMES[id] ?? id;

/**
 * The metrics rows of the table: [label, unit, tooltip, value of a MetricsRow, better]. The
 * smoothness rows read the converged values (the same derivative route and
 * steps for every method, extrapolated to a vanishing step); `better` is '↓' where a lower
 * value is better whatever the method, '' where it is not (an integral of squared acceleration
 * is lower for a motion that strays from its poses, an approximating method's interpolation
 * error is its design).
 */
/** @type {[string, string, string, (r: any) => any, string][]} */
const METRICS = [
  ['velocity jump', 'units/span', 'Largest jump of a body point’s velocity at the knots', (r) => r.velocity_jump, '↓'],
  ['angular velocity jump', 'rad/span', 'Largest jump of the angular velocity at the knots', (r) => r.angular_velocity_jump, '↓'],
  ['acceleration jump', 'units/span²', 'Largest jump of a body point’s acceleration at the knots', (r) => r.acceleration_jump, '↓'],
  ['angular accel. jump', 'rad/span²', 'Largest jump of the angular acceleration at the knots', (r) => r.angular_acceleration_jump, '↓'],
  ['∫|a|² (first point)', 'units²/span³', 'Integrated squared linear acceleration of the first body point; lower is smoother only between methods that pass through the same poses', (r) => r.acceleration_energy[0], ''],
  ['∫|a|² (second point)', 'units²/span³', 'Integrated squared linear acceleration of the second body point; lower is smoother only between methods that pass through the same poses', (r) => r.acceleration_energy[1], ''],
  ['∫|α|²', 'rad²/span³', 'Integrated squared angular acceleration (4× the covariant acceleration); lower is smoother only between methods that pass through the same poses', (r) => r.angular_acceleration_energy, ''],
  ['interpolation error', 'units + rad', 'Largest distance between a control pose and the motion at its knot: 0 for interpolating methods, by design not for approximating ones (B-spline, Kim–Kim–Shin)', (r) => r.interpolation_error, ''],
  ['frame dependence', 'units', 'Trajectory change when the local frame moves (0: frame-independent)', (r) => r.frame_dependence, '↓'],
  ['line error', 'units', 'Deviation from an exact straight translation sampled by the poses', (r) => r.line_error, '↓'],
  ['circle error', 'units', 'Deviation from an exact rotation about a fixed axis', (r) => r.circle_error, '↓'],
  ['helix error', 'units', 'Deviation from an exact screw (helical) motion', (r) => r.helix_error, '↓'],
];

/**
 * A converged metric as a cell: zero, an impulse, a divergence, or the value with as many
 * significant digits as its error bound allows (at most 4): halving the step changes none.
 */
export function convergedCell(c) {
  if (c === undefined || c === null) return { text: '–', title: 'not measured' };
  if (typeof c === 'number') return { text: fmt(c), title: '' };
  const est = `estimates ${c.estimates.map((v) => fmt(v, 4)).join(', ')} at steps ½⁷, ½⁸, ½⁹ of a span`;
  switch (c.limit) {
    case 'zero':
      return { text: '0', title: `tends to 0 as the step shrinks (${est})` };
    case 'impulse':
      return { text: '∞ (impulse)', title: `impulse at the knots: the velocity jumps by ${fmt(c.value)} there, so the acceleration is an impulse, with no finite jump or integral` };
    case 'diverges':
      return { text: '∞ (diverges)', title: `grows as the step shrinks: no such derivative (${est})` };
    default: {
      const digits = c.error > 0 && c.value > 0 ? Math.max(1, Math.min(4, Math.floor(Math.log10(c.value / (2 * c.error))) + 1)) : 4;
      return { text: fmt(c.value, digits), title: `${est}; extrapolated ${fmt(c.value, 6)} ± ${fmt(c.error, 2)}` };
    }
  }
}

class MethodsView {
  constructor(app, root) {
    this.app = app;
    this.all = listMethods();
    this.chosen = null;
    this.scene = null;
    root.append(
      el('p', { class: 'note' },
        'Overlay up to three methods on the same control poses: their body-point paths are drawn in the colours below. ',
        'Every method is measured the same way: its poses sampled at steps of ½⁷, ½⁸ and ½⁹ of a span (ScrewBender refined to match), the same differences taken, ',
        'and the three estimates extrapolated to a vanishing step. A motion whose velocity jumps has an impulse of acceleration at the knots: ∞ (impulse). ',
        '↓ marks the rows where lower is better for any method; units: scene units, radians and spans of the motion parameter (one per control pose).'),
    );
    this.pickers = el('div', { class: 'row' });
    root.append(this.pickers);
    this.selects = SLOT_COLORS.map((c, k) => {
      const sel = el('select', { 'aria-label': `Method ${k + 1}`, onchange: () => this.pick() });
      sel.append(el('option', { value: '' }, '— none —'));
      for (const m of this.all) sel.append(el('option', { value: m.id }, m.title));
      this.pickers.append(el('label', {}, el('span', { class: 'swatch', style: `background:${c}` }), sel));
      return sel;
    });
    this.status = el('div', { class: 'note' });
    // Methods that could not be drawn (drawOverlay), e.g. a method that rejects these poses.
    this.overlayStatus = el('div', { class: 'note error' });
    this.table = el('table', { class: 'metrics' });
    root.append(this.status, this.overlayStatus, this.table);
    this.rbBox = el('div');
    this.ccBox = el('div', { class: 'cc' });
    this.barrBox = el('div', { class: 'barr' });
    root.append(this.rbBox, this.barrBox, this.ccBox);
  }

  /** The selected method ids (in slot order, empty slots left out). */
  get methods() {
    return this.selects.map((s) => s.value).filter(Boolean);
  }

  pick() {
    this.chosen = this.selects.map((s) => s.value);
    this.update('edit');
  }

  /** Selects methods (tests and presets): an array of up to three ids. */
  select(ids) {
    this.chosen = [0, 1, 2].map((k) => ids[k] ?? '');
    this.update('edit');
  }

  show(on) {
    if (!on) this.app.viewer.renderer.setLines(LAYER.methods, new Float32Array(0), false);
  }

  applyDefaults() {
    const scene = this.app.view.scene;
    if (this.chosen && this.scene === scene) return;
    this.scene = scene;
    this.chosen = [...(PRESET_METHODS[scene] ?? DEFAULT_METHODS)];
  }

  update(reason) {
    this.applyDefaults();
    const m = this.app.motion;
    // Methods that do not apply to a cycle are disabled (cc1).
    this.selects.forEach((s, k) => {
      for (const o of s.options) {
        const info = this.all.find((x) => x.id === o.value);
        o.disabled = !!info && m.closed && !info.supportsClosed;
      }
      s.value = this.chosen[k] ?? '';
      if (s.selectedOptions[0]?.disabled) s.value = '';
    });
    // During a drag the variable frames of the last fit would be stale; otherwise the fit
    // (drawRb) comes first so that the overlay, with its triads, is sampled once.
    if (reason === 'drag') this.rbTriads = null;
    else {
      this.drawTable();
      this.drawRb();
      this.drawBarr();
      this.drawCc();
    }
    this.drawOverlay();
  }

  drawOverlay() {
    const app = this.app;
    const m = app.motion;
    const { dpr } = app.viewer.pixelSize();
    const seg = new Segments();
    const errors = [];
    const spans = m.closed ? m.poseCount : m.poseCount - 1;
    const count = Math.min(8192, SAMPLES_PER_SPAN * spans + (m.closed ? 0 : 1));
    this.selects.forEach((s, k) => {
      if (!s.value) return;
      try {
        const arr = m.methodSample(s.value, count);
        const color = hexLinear(SLOT_COLORS[k]);
        for (const p of app.viewer.bodyPoints()) seg.polyline(track(arr, p), m.closed, color, 2.4 * dpr, 0.95, 0.003);
      } catch (e) {
        errors.push(`${s.value}: ${e.message}`);
      }
    });
    // Ramamoorthi–Barr's variable frames (drawRb) ride on the same layer.
    const base = seg.array();
    const triads = this.rbTriads ?? new Float32Array(0);
    const all = new Float32Array(base.length + triads.length);
    all.set(base);
    all.set(triads, base.length);
    app.viewer.renderer.setLines(LAYER.methods, all, false);
    this.overlayStatus.textContent = errors.length ? `Not drawn: ${errors.join(' ')}` : '';
  }

  drawTable() {
    const m = this.app.motion;
    const ids = this.methods;
    this.table.replaceChildren();
    if (ids.length === 0) {
      this.status.textContent = 'Choose a method above.';
      return;
    }
    const t0 = performance.now();
    let table;
    try {
      table = m.compareMethods(ids, this.app.viewer.bodyPoints().slice(0, 2));
    } catch (e) {
      this.status.textContent = `Metrics unavailable: ${e.message}`;
      return;
    }
    const ms = performance.now() - t0;
    const head = el('tr', {}, el('th', { title: '↓: lower is better for any method' }, 'metric'), el('th', { title: '↓: lower is better for any method' }, ''), el('th', {}, 'unit'));
    ids.forEach((id) => {
      const k = this.selects.findIndex((s) => s.value === id);
      head.append(el('th', { title: this.all.find((x) => x.id === id)?.title ?? id, 'data-method': id }, el('span', { class: 'swatch', style: `background:${SLOT_COLORS[k]}` }), nameOf(id)));
    });
    this.table.append(head);
    for (const [label, unit, tip, get, better] of METRICS) {
      const row = el('tr', {}, el('td', { title: better ? `${tip}; lower is better` : tip }, label), el('td', { class: 'better', title: better ? 'lower is better' : 'lower is not better as such' }, better), el('td', {}, unit));
      for (const r of table.rows) {
        const c = convergedCell(get(r));
        row.append(el('td', { title: c.title, 'data-limit': get(r)?.limit ?? '' }, c.text));
      }
      this.table.append(row);
    }
    const notes = table.rows.flatMap((r) => r.notes.map((n) => `${nameOf(r.method)}: ${n}`));
    this.status.textContent =
      `${table.pose_count} control poses, ${table.closed ? 'cycle' : 'open'}; computed in ${ms.toFixed(0)} ms.` +
      (notes.length ? ` Notes: ${notes.join(' ')}` : '');
    this.lastTable = table;
  }

  /**
   * The discrete baseline of Barr et al. beside Ramamoorthi–Barr: the objective (3) each reaches
   * on the same keyframes and the time each fit takes here (docs/math/quaternion-splines.md §9).
   */
  drawBarr() {
    const m = this.app.motion;
    if (!this.methods.includes('barr') || m.closed) {
      this.barrBox.replaceChildren();
      return;
    }
    let barr, rb;
    const t0 = performance.now();
    try {
      barr = m.barrBaseline();
    } catch (e) {
      this.barrBox.replaceChildren(el('p', { class: 'note error' }, `Barr et al.: ${e.message}`));
      return;
    }
    const t1 = performance.now();
    try {
      rb = m.quaternionSpline({ samples: 2 });
    } catch (e) {
      this.barrBox.replaceChildren(el('p', { class: 'note error' }, `Ramamoorthi–Barr: ${e.message}`));
      return;
    }
    const t2 = performance.now();
    const last = rb.stages.at(-1);
    const row = (name, objective, ms) => el('tr', {}, el('td', {}, name), el('td', {}, fmt(objective, 7)), el('td', {}, `${ms.toFixed(1)} ms`));
    this.barrBox.replaceChildren(
      el('h4', {}, 'Barr et al. (discrete) beside Ramamoorthi–Barr: objective (3)'),
      el('table', {},
        el('tr', {}, el('th', {}, 'method'), el('th', { title: 'Lower is better' }, 'objective (↓)'), el('th', { title: 'Lower is better' }, 'time (↓)')),
        row(nameOf('barr'), barr.objective, t1 - t0),
        row(nameOf('rb'), last.objective, t2 - t1)),
      el('p', { class: 'note' },
        `barr: ${barr.frames} frames, ${barr.iterations} Gauss–Newton steps; rb: ${last.variable_frames} variable frames (fitted twice: before and after optimisation). `,
        `R–B is ${(100 * (last.objective / barr.objective - 1)).toFixed(2)} % above the dense optimum; time ratio barr/rb ${((t1 - t0) / Math.max(t2 - t1, 1e-3)).toFixed(2)}. `,
        'The paper reports hours against seconds with a gradient optimiser on 600 frames; the band-limited Gauss–Newton solve here is far faster.'),
    );
    this.barr = { barr, rb: last, barrMs: t1 - t0, rbMs: t2 - t1 };
  }

  /**
   * Chaudhry–Cameron: the reference triangle's vertices a, x, y against time (one chart each,
   * x/y/z), C¹ with the chosen end condition (19 straightens the last quaternion segment, 18
   * the first), or C⁰ on a cycle; the C¹ recursion's growth and its warning.
   */
  drawCc() {
    const app = this.app;
    const ids = this.methods;
    if (!ids.includes('cc0') && !ids.includes('cc1')) {
      this.ccCharts?.forEach((c) => c.destroy());
      this.ccCharts = null;
      this.ccBox.replaceChildren();
      return;
    }
    const m = app.motion;
    if (!this.ccCharts) {
      this.ccBox.replaceChildren();
      this.ccEnd = el('select', { 'aria-label': 'Chaudhry–Cameron end condition', onchange: () => this.drawCc() },
        el('option', { value: '18' }, 'end condition (18): straight first segment'),
        el('option', { value: '19' }, 'end condition (19): straight last segment'));
      this.ccInfo = el('p', { class: 'note' });
      this.ccBox.append(el('h4', {}, 'Chaudhry–Cameron: vertices against time'), el('div', { class: 'row' }, this.ccEnd), this.ccInfo);
      this.ccCharts = ['a', 'x', 'y'].map((v) => lineChart(this.ccBox, {
        title: `vertex ${v}`,
        x: 't (key i at t = i)',
        y: `${v} (units)`,
        playhead: 'u',
        height: 120,
        series: [
          { label: `${v}.x`, color: '#d55e00' },
          { label: `${v}.y`, color: '#009e73' },
          { label: `${v}.z`, color: '#0072b2' },
        ],
      }));
    }
    const c1 = !m.closed;
    this.ccEnd.disabled = !c1;
    let r;
    try {
      r = m.rational({ continuity: c1 ? 'c1' : 'c0', end: Number(this.ccEnd.value), samples: 400 });
    } catch (e) {
      this.ccInfo.textContent = `Chaudhry–Cameron: ${e.message}`;
      this.ccInfo.classList.add('error');
      return;
    }
    this.ccInfo.classList.toggle('error', r.warnings.length > 0);
    const n = r.t.length;
    const keys = r.bezier.segments.map((s) => s.t_start).concat(r.bezier.segments.at(-1)?.t_end ?? []);
    this.ccCharts.forEach((chart, v) => {
      const comp = [0, 1, 2].map((c) => Array.from({ length: n }, (_, k) => r.vertices[9 * k + 3 * v + c]));
      chart.set(r.t, comp, keys);
    });
    this.ccInfo.textContent =
      `${r.bezier.continuity}: ${r.bezier.segments.length} rational Bézier segments of degree ${r.bezier.segments[0]?.degree ?? '–'} ` +
      `(dashed lines: keys). Growth of the middle control points ${fmt(r.growth)}, min |Q|² ${fmt(r.minDenominator)}.` +
      (c1 ? '' : ' A cycle is C⁰ only.') +
      (r.warnings.length ? ` Warning: ${r.warnings.join(' ')}` : '');
    this.cc = r;
  }

  /** Ramamoorthi–Barr: variable frames (as ticks on the overlay) and the EL error plot. */
  drawRb() {
    const app = this.app;
    if (!this.methods.includes('rb')) {
      this.rbBox.replaceChildren();
      this.chart?.destroy();
      this.chart = null;
      this.rb = null;
      this.rbTriads = null;
      return;
    }
    let r;
    const t0 = performance.now();
    try {
      r = app.motion.quaternionSpline({ variableFrames: 4 });
    } catch (e) {
      this.rbBox.replaceChildren(el('p', { class: 'note' }, `Ramamoorthi–Barr: ${e.message}`));
      return;
    }
    const ms = performance.now() - t0;
    this.rb = r;
    if (!this.chart) {
      this.rbBox.replaceChildren();
      this.rbInfo = el('p', { class: 'note' });
      this.rbBox.append(el('h4', {}, 'Ramamoorthi–Barr: Euler–Lagrange error'), this.rbInfo);
      this.chart = lineChart(this.rbBox, {
        title: '|EL(t)| before and after optimisation (log scale)',
        x: 't (keyframe i at t = i)',
        y: '|EL(t)| (log)',
        playhead: 'u',
        log: true,
        series: [
          { label: 'initial spline', color: '#999999' },
          { label: 'optimised', color: SLOT_COLORS[this.selects.findIndex((s) => s.value === 'rb')] ?? '#0072b2', width: 2 },
        ],
      });
      this.stageTable = el('table');
      this.rbBox.append(this.stageTable);
    }
    // Log axis: zeros (exact keyframes) are lifted to the smallest positive value.
    const floor = (a) => {
      const pos = Array.from(a).filter((v) => v > 0);
      const min = pos.length ? Math.min(...pos) : 1e-12;
      return Array.from(a, (v) => Math.max(v, min));
    };
    this.chart.set(r.t, [floor(r.elBefore), floor(r.elAfter)], [...r.keyTimes, ...r.frameTimes]);
    this.rbInfo.textContent =
      `${r.frameTimes.length} variable frames at t = ${r.frameTimes.map((t) => t.toFixed(2)).join(', ') || '–'} ` +
      `(dashed lines: keyframes and frames). max ||q|−1|: ${fmt(r.unitDeviationBefore)} → ${fmt(r.unitDeviationAfter)}. ` +
      `Fit in ${ms.toFixed(0)} ms (twice: before and after).`;
    this.stageTable.replaceChildren(el('tr', {}, el('th', {}, 'stage'), el('th', {}, 'variable frames'), el('th', {}, 'inserted at'), el('th', {}, 'objective'), el('th', {}, 'iterations')));
    r.stages.forEach((s, k) => {
      const name = k === 0 ? 'initial' : k === 1 ? 'keyframe velocities' : `+${s.variable_frames} frame(s)`;
      this.stageTable.append(el('tr', {}, el('td', {}, name), el('td', {}, s.variable_frames), el('td', {}, s.inserted_at == null ? '–' : s.inserted_at.toFixed(2)), el('td', {}, fmt(s.objective, 5)), el('td', {}, s.iterations)));
    });
    // The variable frames in 3-D: small rotation triads of the RB motion at the frame times.
    const { dpr } = app.viewer.pixelSize();
    const count = 8 * (app.motion.closed ? app.motion.poseCount : app.motion.poseCount - 1) * 16 + 1;
    let arr;
    try {
      arr = app.motion.methodSample('rb', count);
    } catch {
      return;
    }
    const seg = new Segments();
    const [a, b] = app.motion.domain();
    const n = arr.length / 7;
    const mat = new Float32Array(16);
    for (const t of r.frameTimes) {
      const k = Math.round(((t - a) / (b - a)) * (app.motion.closed ? n : n - 1)) % n;
      const { origin, rotation } = poseOf(arr, k);
      poseMatrix(origin, rotation, 1, mat);
      ['#e03c3c', '#3aa845', '#3a6fe0'].forEach((c, ax) => {
        const dir = [mat[ax * 4], mat[ax * 4 + 1], mat[ax * 4 + 2]];
        seg.push(origin, add(origin, scale(dir, 0.45)), hexLinear(c), 3 * dpr, 1, 0.01);
      });
    }
    this.rbTriads = seg.array().slice();
  }
}

/** @type {import('../editor/dock.js').DockView} */
export default {
  id: 'methods',
  title: 'Methods',
  hint: 'Compare ScrewBender with Chaudhry–Cameron, Ramamoorthi–Barr and classical methods',
  live: true,
  create: (app, root, wasm) => {
    ({ methods: listMethods } = wasm);
    return new MethodsView(app, root);
  },
};
