// Smoothness plots (paper Fig. 8 of V1 / Fig. 7 of V2): a body point's coordinate, speed and
// acceleration, and the body's angular velocity and acceleration, over time, for the three
// schemes and the plain polyscrew side by side, with the control-pose times marked.
import { Motion } from '../../pkg/screwbender.js';
import { lineChart, el } from './plot.js';

/** The paper's colours: B-spline red, 4-point blue, Jarek green; the polyscrew grey. */
export const SCHEME_SERIES = [
  { id: 'bspline', label: 'B-spline', color: '#d1202f' },
  { id: 'jarek', label: 'Jarek', color: '#2f9e44' },
  { id: 'fourpoint', label: '4-point', color: '#1f5fd1' },
  { id: 'polyscrew', label: 'polyscrew (level 0)', color: '#8a8f9c', dash: [4, 3] },
];
/** Samples per curve. */
const SAMPLES = 480;
/** Floats per kinematics sample: t, position, velocity, acceleration, ω, α (xyz each). */
const STRIDE = 16;

const norm = (d, k, o) => Math.hypot(d[k * STRIDE + o], d[k * STRIDE + o + 1], d[k * STRIDE + o + 2]);

/** The charts: title, and the value of sample k of a kinematics array. */
const CHARTS = [
  ['coord', (axis) => `position ${'xyz'[axis]}`, (d, k, axis) => d[k * STRIDE + 1 + axis]],
  ['speed', () => 'speed |v|', (d, k) => norm(d, k, 4)],
  ['accel', () => 'acceleration |a|', (d, k) => norm(d, k, 7)],
  ['omega', () => 'angular velocity |ω| (rad/s)', (d, k) => norm(d, k, 10)],
  ['alpha', () => 'angular acceleration |α|', (d, k) => norm(d, k, 13)],
];

class PlotsView {
  constructor(app, root) {
    this.app = app;
    this.point = [2, 0, 0];
    this.axis = 0;
    this.derivatives = 'analytic';
    const pointInputs = [0, 1, 2].map((i) =>
      el('input', { type: 'number', step: '0.1', value: String(this.point[i]), style: 'width:56px', 'aria-label': `body point ${'xyz'[i]}`, onchange: () => this.readPoint() }),
    );
    this.pointInputs = pointInputs;
    const axisSel = el('select', { 'aria-label': 'coordinate', onchange: (e) => { this.axis = Number(e.target.value); this.update('edit'); } },
      ...[0, 1, 2].map((a) => el('option', { value: String(a) }, 'xyz'[a])));
    const derivSel = el('select', { 'aria-label': 'derivatives', onchange: (e) => { this.derivatives = e.target.value; this.update('edit'); } },
      el('option', { value: 'analytic' }, 'analytic (refined polyscrew)'),
      el('option', { value: 'limit' }, 'differences of refined poses (limit)'));
    root.append(
      el('div', { class: 'row' }, 'body point (local)', ...pointInputs, 'coordinate', axisSel),
      el('div', { class: 'row' }, 'derivatives', derivSel),
      el('p', { class: 'note' },
        'Same control poses, rules and levels for every curve; only the scheme differs. Dashed lines mark the control-pose times. ',
        'Analytic derivatives are those of the refined polyscrew: its angular velocity is constant on each refined span, so jumps shrink level by level; ',
        'the differences of refined poses approximate the limit motion, as plotted in the paper.'),
    );
    this.legend = el('div', { class: 'row' }, ...SCHEME_SERIES.map((s) => el('span', {}, el('span', { class: 'swatch', style: `background:${s.color}` }), s.label)));
    root.append(this.legend);
    this.root = root;
    this.charts = null;
  }

  readPoint() {
    const p = this.pointInputs.map((i) => Number(i.value));
    if (p.every(Number.isFinite)) {
      this.point = p;
      this.update('edit');
    } else this.app.showError('Plots: the body point needs three numbers.');
  }

  /** Sets the body point (tests). */
  setPoint(p) {
    this.point = p;
    p.forEach((v, i) => (this.pointInputs[i].value = String(v)));
    this.update('edit');
  }

  show(on) {
    if (on && !this.charts) {
      this.charts = CHARTS.map(([id, title]) =>
        lineChart(this.root, { title: title(this.axis), x: 't (s)', series: SCHEME_SERIES, height: 140, legend: false }),
      );
      this.charts.forEach((c, k) => (c.id = CHARTS[k][0]));
    }
  }

  /** Kinematics of every scheme: {id → Float64Array}; throws on bad input. */
  sample() {
    const m = this.app.motion;
    const doc = m.toDocument();
    const opts = m.options();
    const times = this.app.times();
    const out = {};
    for (const s of SCHEME_SERIES) {
      // Same rules and levels; the scheme alone differs (the polyscrew is level 0).
      const o = s.id === 'polyscrew' ? { ...opts, levels: 0 } : { rules: opts.rules, levels: opts.levels, scheme: s.id };
      const motion = new Motion(doc, o);
      try {
        out[s.id] = motion.timedKinematics(SAMPLES, this.point, times ?? undefined, this.derivatives);
      } finally {
        motion.free();
      }
    }
    return out;
  }

  update() {
    if (!this.charts) return;
    const data = this.sample();
    this.data = data;
    const first = data[SCHEME_SERIES[0].id];
    const ts = Array.from({ length: SAMPLES }, (_, k) => first[k * STRIDE]);
    const m = this.app.motion;
    const times = this.app.times() ?? Array.from({ length: m.poseCount + (m.closed ? 1 : 0) }, (_, i) => i);
    CHARTS.forEach(([, title, value], c) => {
      const chart = this.charts[c];
      chart.setTitle(title(this.axis));
      const ys = SCHEME_SERIES.map((s) => Array.from({ length: SAMPLES }, (_, k) => value(data[s.id], k, this.axis)));
      chart.resize(this.root.clientWidth - 4);
      chart.set(ts, ys, times);
    });
  }
}

export default {
  id: 'plots',
  title: 'Plots',
  hint: 'Position, velocity and acceleration of a body point over time for each scheme (paper Fig. 8 / 7)',
  live: true,
  create: (app, root) => new PlotsView(app, root),
};
