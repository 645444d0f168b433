// Smoothness plots (paper Fig. 8 of V1 / Fig. 7 of V2): a body point's coordinate, speed and
// acceleration, and the body's angular velocity and acceleration, over time, for the three
// schemes and the plain polyscrew side by side, with the control-pose times marked. On phones
// one chart at a time, picked from a list, fills the dock (nothing to scroll); the body point,
// the derivatives and the note show under an Options button.
import { lineChart, inkSwatch } from './plot.js';
import { el } from '../dom.js';

/** The wasm functions of this view, from the analysis module the dock hands to create(). */
let Motion;

/**
 * The paper's colours: B-spline red, 4-point blue, Jarek green; the polyscrew grey. Drawn through
 * seriesInk (plot.js), which lightens or darkens those short of 3:1 on the theme's card.
 */
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

/** The charts: id, title, y-axis label with its unit, and the value of sample k of a kinematics array. */
/** @type {[string, (axis: number) => string, (axis: number) => string, (d: Float64Array, k: number, axis?: number) => number][]} */
const CHARTS = [
  ['coord', (axis) => `position ${'xyz'[axis]} of the body point`, (axis) => `${'xyz'[axis]} (units)`, (d, k, axis) => d[k * STRIDE + 1 + axis]],
  ['speed', () => 'speed |v|', () => '|v| (units/s)', (d, k) => norm(d, k, 4)],
  ['accel', () => 'acceleration |a|', () => '|a| (units/s²)', (d, k) => norm(d, k, 7)],
  ['omega', () => 'angular velocity |ω|', () => '|ω| (rad/s)', (d, k) => norm(d, k, 10)],
  ['alpha', () => 'angular acceleration |α|', () => '|α| (rad/s²)', (d, k) => norm(d, k, 13)],
];
/**
 * Kinematic values at most this large are zero up to rounding: the charts draw them on a 0..1
 * axis and say "= 0". Each span of a polyscrew is a screw with a constant angular velocity, so
 * its |α| at uniform timing is 0, computed as ~1e-15 rad/s²; scenes are a few units across, so
 * a real value of 1e-9 is far below what a chart of them could show anyway.
 */
const ZERO_BELOW = 1e-9;
/** Height of a chart's title line (CSS px, style.css `.plot-grid .u-title`). */
const TITLE_PX = 16;
/** Gap between charts of the grid (CSS px, style.css `.plot-grid`). */
const GAP_PX = 6;
/** A chart is never lower than this (CSS px); below, the dock scrolls. */
const MIN_CHART_PX = 150;
/** The one chart shown on phones is never lower than this (CSS px). */
const MIN_ONE_CHART_PX = 110;
/** Phones (the breakpoints of style.css): one chart at a time. */
const PHONE = '(max-width: 760px), (max-height: 500px)';
/** The entries of the phones' chart list: a chart, and for the coordinate chart its axis. */
/** @type {{chart: number, axis?: number, label: string}[]} */
const PICKS = [
  ...[0, 1, 2].map((axis) => ({ chart: 0, axis, label: `position ${'xyz'[axis]}` })),
  { chart: 1, label: 'speed |v|' },
  { chart: 2, label: 'acceleration |a|' },
  { chart: 3, label: 'angular velocity |ω|' },
  { chart: 4, label: 'angular acceleration |α|' },
];

class PlotsView {
  constructor(app, root) {
    this.app = app;
    this.point = [2, 0, 0];
    this.axis = 0;
    // The limit motion's derivatives: those of the refined polyscrew are piecewise constant (|α| = 0
    // inside every refined span, its jumps at the refined knots not drawn).
    this.derivatives = 'limit';
    /** The chart shown on phones (index in CHARTS). */
    this.shown = 0;
    const pointInputs = [0, 1, 2].map((i) =>
      el('input', { type: 'number', step: '0.1', value: String(this.point[i]), style: 'width:48px', 'aria-label': `body point ${'xyz'[i]}`, onchange: () => this.readPoint() }),
    );
    this.pointInputs = pointInputs;
    const axisSel = el('select', { 'aria-label': 'coordinate', onchange: (e) => this.setAxis(Number(e.target.value)) },
      ...[0, 1, 2].map((a) => el('option', { value: String(a) }, 'xyz'[a])));
    this.axisSel = axisSel;
    const pickSel = el('select', { 'aria-label': 'chart', class: 'pick', onchange: (e) => this.pick(Number(e.target.value)) },
      ...PICKS.map((p, k) => el('option', { value: String(k) }, p.label)));
    this.pickSel = pickSel;
    const axisLabel = el('span', { title: 'Coordinate of the body point plotted in the first chart' }, 'plot');
    const pickLabel = el('span', { class: 'pick', title: 'The chart shown (one at a time on small screens)' }, 'chart');
    /** Phones: whether the options (body point, derivatives, note) are shown. */
    this.optionsOpen = false;
    const optionsBtn = el('button', { type: 'button', class: 'act pick', 'aria-expanded': 'false', title: 'The body point, the derivatives and a note on these plots', onclick: () => this.toggleOptions() }, 'Options');
    this.optionsBtn = optionsBtn;
    const pointLabel = el('span', { title: 'Body point in the object’s local coordinates (scene units)' }, 'point');
    const derivLabel = el('span', { title: 'How velocities and accelerations are computed' }, 'derivatives');
    const derivSel = el('select', { 'aria-label': 'derivatives', onchange: (e) => { this.derivatives = e.target.value; this.update('edit'); } },
      el('option', { value: 'limit', title: 'Differences of refined poses: the smooth limit motion the subdivision converges to' }, 'limit'),
      el('option', { value: 'analytic', title: 'Exact derivatives of the refined polyscrew: constant angular velocity on each refined span, so |α| = 0 there and ω jumps at the refined knots (not drawn)' }, 'polyscrew'));
    root.append(
      el('div', { class: 'row' },
        pointLabel, ...pointInputs, axisLabel, axisSel, pickLabel, pickSel, optionsBtn, derivLabel, derivSel),
      (this.about = el('details', { class: 'note' },
        el('summary', {}, 'About these plots (units: scene units, seconds, radians)'),
        'Same control poses, rules and levels for every curve; only the scheme differs. Dashed lines mark the control-pose times, ',
        'the solid line is the playhead; hover a plot to see that instant’s pose in 3-D. ',
        'By default the derivatives are those of the limit motion (differences of refined poses, as plotted in the paper). ',
        '“Polyscrew” shows the exact derivatives of the refined polyscrew instead: its angular velocity is constant on each refined span, ',
        'so its |α| is 0 inside every span and its acceleration is an impulse at each refined knot, which a chart of values cannot draw.')),
    );
    /** Shown on wide screens only / on phones only / on phones under Options. */
    this.wide = [axisLabel, axisSel];
    this.narrow = [pickLabel, pickSel, optionsBtn];
    this.options = [pointLabel, ...pointInputs, derivLabel, derivSel, this.about];
    this.legend = el('div', { class: 'row legend' }, ...SCHEME_SERIES.map((s) => el('span', {}, inkSwatch(el('span', { class: 'swatch' }), s.color), s.label)));
    this.grid = el('div', { class: 'plot-grid' });
    root.append(this.grid);
    this.root = root;
    this.charts = null;
    // The dock changed size (window, layout): the charts follow without sampling again.
    this.resizer = new ResizeObserver(() => this.charts && this.layout());
    this.resizer.observe(root);
    this.phone = window.matchMedia(PHONE);
    this.phone.addEventListener('change', () => this.charts && this.layout());
  }

  /** Phones: shows or hides the options (the chart gets the room they leave). */
  toggleOptions() {
    this.optionsOpen = !this.optionsOpen;
    this.optionsBtn.setAttribute('aria-expanded', String(this.optionsOpen));
    if (this.charts) this.layout();
  }

  /** Plots coordinate `axis` (0, 1, 2) of the body point in the first chart. */
  setAxis(axis) {
    this.axis = axis;
    this.axisSel.value = String(axis);
    this.pickSel.value = String(PICKS.findIndex((p) => p.chart === this.shown && (p.axis ?? axis) === axis));
    this.update('edit');
  }

  /** Shows entry `k` of PICKS as the one chart on phones (tests call it too). */
  pick(k) {
    const p = PICKS[k];
    if (!p) return;
    this.shown = p.chart;
    this.pickSel.value = String(k);
    if (p.axis !== undefined && p.axis !== this.axis) this.setAxis(p.axis);
    else if (this.charts) this.layout();
  }

  /**
   * Sizes the charts to the dock: two columns when it is wide enough (the legend in the sixth
   * cell), and heights that fill the dock's height without scrolling (down to MIN_CHART_PX).
   * Phones: the chart picked in the list alone, without its title, the legend in a row under it.
   */
  layout() {
    const width = this.root.clientWidth;
    if (width === 0) return;
    const one = this.phone.matches;
    this.root.classList.toggle('one-chart', one);
    for (const e of this.wide) e.hidden = one;
    for (const e of this.narrow) e.hidden = !one;
    for (const e of this.options) e.hidden = one && !this.optionsOpen;
    this.charts.forEach((c, k) => (c.box.hidden = one && k !== this.shown));
    const cols = !one && width >= 440 ? 2 : 1;
    const rows = one ? 1 : Math.ceil((CHARTS.length + (cols === 2 ? 1 : 0)) / cols);
    const body = this.root.parentElement;
    const pad = parseFloat(getComputedStyle(body).paddingBottom) || 0;
    let room = body.getBoundingClientRect().bottom - pad - this.grid.getBoundingClientRect().top - 2;
    if (one) room -= this.legend.getBoundingClientRect().height + GAP_PX;
    const h = Math.max(one ? MIN_ONE_CHART_PX : MIN_CHART_PX, Math.floor((room - (rows - 1) * GAP_PX) / rows));
    const w = Math.floor((width - (cols - 1) * GAP_PX) / cols);
    this.grid.style.gridTemplateColumns = `repeat(${cols}, ${w}px)`;
    const key = `${one}|${this.shown}|${this.optionsOpen}|${cols}|${w}|${h}`;
    if (key === this.layoutKey) return;
    this.layoutKey = key;
    // Phones: the list names the chart, which shows no title (style.css).
    for (const c of this.charts) c.resize(w, one ? h : h - TITLE_PX);
  }

  readPoint() {
    const p = this.pointInputs.map((i) => Number(i.value));
    if (p.every(Number.isFinite)) {
      this.point = p;
      this.update('edit');
    } else this.app.parts.notices.show('Plots: the body point needs three numbers.');
  }

  /** Sets the body point (tests). */
  setPoint(p) {
    this.point = p;
    p.forEach((v, i) => (this.pointInputs[i].value = String(v)));
    this.update('edit');
  }

  show(on) {
    if (on && !this.charts) {
      this.charts = CHARTS.map(([id, title, y]) => {
        const c = lineChart(this.grid, {
          title: title(this.axis), x: 't (s)', y: y(this.axis), series: SCHEME_SERIES, height: 140, legend: false, zeroBelow: ZERO_BELOW,
          onHover: (t) => this.app.dock.preview(t),
        });
        c.id = id;
        return c;
      });
      this.grid.append(this.legend);
    }
  }

  /** Kinematics of every scheme: {id → Float64Array}; throws on bad input. */
  sample() {
    const m = this.app.motion;
    const doc = m.toDocument();
    const opts = m.options();
    const out = {};
    for (const s of SCHEME_SERIES) {
      // Same rules and levels; the scheme alone differs (the polyscrew is level 0).
      const o = s.id === 'polyscrew' ? { ...opts, levels: 0 } : { rules: opts.rules, levels: opts.levels, scheme: s.id };
      const motion = new Motion(doc, o);
      try {
        // The document carries the key times and velocities: the motion's own timing.
        out[s.id] = motion.timedKinematics(SAMPLES, this.point, undefined, this.derivatives);
      } finally {
        motion.free();
      }
    }
    return out;
  }

  /** @param {string} [_reason] every reason redraws alike */
  update(_reason) {
    if (!this.charts) return;
    const data = this.sample();
    this.data = data;
    const first = data[SCHEME_SERIES[0].id];
    const ts = Array.from({ length: SAMPLES }, (_, k) => first[k * STRIDE]);
    const times = this.app.keyTimes();
    this.layout();
    CHARTS.forEach(([, title, y, value], c) => {
      const chart = this.charts[c];
      chart.setTitle(title(this.axis));
      chart.setYLabel(y(this.axis));
      const ys = SCHEME_SERIES.map((s) => Array.from({ length: SAMPLES }, (_, k) => value(data[s.id], k, this.axis)));
      chart.set(ts, ys, times);
      // Say so rather than show a flat line without a reason (e.g. |α| of screw spans at uniform timing).
      if (chart.flat) {
        const polyscrew = this.derivatives === 'analytic' && (CHARTS[c][0] === 'alpha' || CHARTS[c][0] === 'accel');
        chart.setTitle(polyscrew ? `${title(this.axis)} = 0 between refined knots (impulses at the knots not drawn)` : `${title(this.axis)} = 0 (to rounding)`);
      }
    });
  }
}

/** @type {import('../editor/dock.js').DockView} */
export default {
  id: 'plots',
  title: 'Plots',
  hint: 'Position, velocity and acceleration of a body point over time for each scheme (paper Fig. 8 / 7)',
  live: true,
  create: (app, root, wasm) => {
    ({ Motion } = wasm);
    return new PlotsView(app, root);
  },
};
