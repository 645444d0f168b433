// Metrics view: smoothness and fidelity numbers of the current motion (its scheme, rules and
// levels), measured on the refined poses, for the body points of the object.
import { fmt } from './plot.js';
import { el } from '../dom.js';

/** Human names of the schemes and rule sets (the panel's words). */
export const SCHEME_NAMES = { bspline: 'cubic B-spline', fourpoint: '4-point', jarek: 'Jarek', j: 'J_s', polyscrew: 'polyscrew' };
export const RULE_NAMES = { direct: 'direct rules (V2)', split: 'split & tweak rules (V1)' };

/** The table's rows: label, unit, tooltip, value of a MetricsRow. */
/** @type {[string, string, string, (r: any) => any][]} */
const ROWS = [
  ['max velocity jump', 'units/span', 'Largest jump of a body point’s velocity at the knots (differences of refined poses)', (r) => r.velocity_jump],
  ['max angular velocity jump', 'rad/span', 'Largest jump of the angular velocity at the knots', (r) => r.angular_velocity_jump],
  ['max acceleration jump', 'units/span²', 'Largest jump of a body point’s acceleration at the knots', (r) => r.acceleration_jump],
  ['max angular acceleration jump', 'rad/span²', 'Largest jump of the angular acceleration at the knots', (r) => r.angular_acceleration_jump],
  ['∫ |a|² du (each body point)', 'units²/span³', 'Integrated squared linear acceleration', (r) => r.acceleration_energy.map((v) => fmt(v)).join(' / ')],
  ['∫ |α|² du', 'rad²/span³', 'Integrated squared angular acceleration', (r) => r.angular_acceleration_energy],
  ['distance to control poses', 'units + rad', 'Largest pose distance (origin + angle) between control pose i and the motion at u = i', (r) => r.interpolation_error],
];

class MetricsView {
  constructor(app, root) {
    this.app = app;
    root.append(el('p', { class: 'note' },
      'Measured on the current motion by differences of its refined poses (step: one refined span), at the control-pose knots. ',
      'Jumps shrink towards 0 as levels increase for a C¹ (velocity) or C² (acceleration) limit.'),
    el('p', { class: 'note metrics-legend' },
      'The jumps and the distance to the control poses: lower is better. The integrals: lower means less acceleration overall, smoother only for motions through the same poses. ',
      'Units: scene units, radians, and spans of the motion parameter u (one span per control pose; 1 s at uniform timing). The Methods view compares methods converged, all measured the same way.'));
    this.caption = el('div', { class: 'note' });
    this.table = el('table');
    root.append(this.caption, this.table);
  }

  show() {}

  update() {
    const app = this.app;
    const m = app.motion;
    const points = app.viewer.bodyPoints().slice(0, 4);
    const t0 = performance.now();
    const { row, fourPointGap } = m.motionMetrics(points);
    const ms = performance.now() - t0;
    const o = m.options();
    this.caption.textContent =
      `${SCHEME_NAMES[o.scheme] ?? o.scheme}${o.scheme === 'j' ? ` (s = ${o.s})` : ''} scheme, ${RULE_NAMES[o.rules] ?? `${o.rules} rules`}, ${o.levels} levels; body points ` +
      `${points.map((p) => `(${p.map((v) => +v.toFixed(3)).join(', ')})`).join(', ')}; ${ms.toFixed(0)} ms.`;
    const rows = [el('tr', {}, el('th', {}, 'metric'), el('th', {}, 'value'), el('th', {}, 'unit'))];
    for (const [label, unit, tip, get] of ROWS) {
      const v = get(row);
      rows.push(el('tr', {}, el('td', { title: tip }, label), el('td', {}, typeof v === 'string' ? v : fmt(v)), el('td', {}, unit)));
    }
    rows.push(el('tr', {},
      el('td', { title: 'The 4-point scheme interpolates: this is 0 up to rounding, by construction; lower is better' }, 'max distance 4-point curve ↔ control poses'),
      el('td', {}, fmt(fourPointGap)), el('td', {}, 'units + rad')));
    this.table.replaceChildren(...rows);
    this.last = { row, fourPointGap };
  }
}

/** @type {import('../editor/dock.js').DockView} */
export default {
  id: 'metrics',
  title: 'Metrics',
  hint: 'Velocity and acceleration jumps, integrated accelerations, interpolation error',
  live: true,
  create: (app, root) => new MetricsView(app, root),
};
