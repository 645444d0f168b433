// Timing view (paper §1, docs/math/timing.md): per-control-pose times in a small table. The motion is
// retimed by a C¹ monotone piecewise-cubic map u = p(t) (the path is unchanged, only the speed
// along it); the Plots view and glTF / CSV export use these times.
import { timingMap } from '../../pkg/screwbender.js';
import { lineChart, el, fmt } from './plot.js';

class TimingView {
  constructor(app, root) {
    this.app = app;
    this.root = root;
    root.append(
      el('p', { class: 'note' },
        'Time (seconds) at which each control pose is reached. Times must increase; the map from time to the motion parameter is C¹ and monotone, ',
        'so the object never moves backwards and a C¹ motion stays C¹ in time. Inserting or deleting a pose returns to one second per span.'),
      el('div', { class: 'row' },
        el('button', { class: 'act', onclick: () => this.apply(null) }, 'Uniform (1 s per span)'),
        el('button', { class: 'act', title: 'Slow near the first and last poses', onclick: () => this.ease() }, 'Ease in / out'),
      ),
    );
    this.message = el('div', { class: 'note', role: 'status' });
    this.table = el('table');
    root.append(this.message, this.table);
    this.chart = null;
  }

  show(on) {
    if (on && !this.chart) {
      this.chart = lineChart(this.root, {
        title: 'motion parameter u = p(t) and its rate du/dt',
        x: 't (s)',
        series: [
          { label: 'u', color: '#1d2230', width: 2 },
          { label: 'du/dt', color: '#d55e00' },
        ],
        height: 160,
      });
    }
  }

  /** The times in use (uniform when none are set). */
  current() {
    const m = this.app.motion;
    return this.app.times() ?? Array.from({ length: m.poseCount + (m.closed ? 1 : 0) }, (_, i) => i);
  }

  /** Sets the times (null: uniform) as one undoable edit, after checking them. */
  apply(times) {
    const m = this.app.motion;
    if (times) {
      try {
        timingMap(times, m.poseCount, m.closed, 2);
      } catch (e) {
        this.message.textContent = `Not applied: ${e.message}`;
        this.message.classList.add('error');
        return false;
      }
    }
    this.message.textContent = '';
    this.message.classList.remove('error');
    this.app.edit(() => (this.app.view.times = times ? [...times] : null), 'view:times');
    return true;
  }

  /** Twice as long for the first and last spans. */
  ease() {
    const n = this.current().length;
    const t = [0];
    for (let i = 1; i < n; i++) t.push(t[i - 1] + (i === 1 || i === n - 1 ? 2 : 1));
    this.apply(t);
  }

  /** Refills the table: one number input per time, the span to the previous one beside it. */
  fillTable(m, times) {
    const rows = [el('tr', {}, el('th', {}, 'pose'), el('th', {}, 'time (s)'), el('th', {}, 'span (s)'))];
    times.forEach((t, i) => {
      const input = el('input', {
        type: 'number', step: '0.1', value: String(t), style: 'width:90px',
        'aria-label': `time of pose ${i % m.poseCount}`,
        onchange: () => {
          const next = [...times];
          next[i] = Number(input.value);
          if (!Number.isFinite(next[i])) {
            this.message.textContent = `Not applied: time ${i} is not a number.`;
            this.message.classList.add('error');
          } else if (this.apply(next)) {
            return;
          }
          // Refused: the input shows the time still in use again, the message says why.
          input.value = String(t);
        },
      });
      const label = i < m.poseCount ? String(i) : '0 (again, end of cycle)';
      rows.push(el('tr', {}, el('td', {}, label), el('td', {}, input), el('td', {}, i > 0 ? fmt(t - times[i - 1]) : '–')));
    });
    this.table.replaceChildren(...rows);
  }

  update() {
    const m = this.app.motion;
    const times = this.current();
    // Rebuild the table only when the times change: a rebuild between a user's typing and the
    // input's `change` event would throw the typed value away with the old input.
    const key = `${m.poseCount}|${m.closed}|${times.join(',')}`;
    if (key !== this.tableKey) {
      this.tableKey = key;
      this.fillTable(m, times);
    }
    if (this.chart) {
      const d = timingMap(times, m.poseCount, m.closed, 400);
      const t = [];
      const u = [];
      const du = [];
      for (let k = 0; k < d.length; k += 3) {
        t.push(d[k]);
        u.push(d[k + 1]);
        du.push(d[k + 2]);
      }
      this.chart.resize(this.root.clientWidth - 4);
      this.chart.set(t, [u, du], times);
    }
  }
}

export default {
  id: 'timing',
  title: 'Timing',
  hint: 'Per-pose times: retime the motion by a C¹ monotone map (paper §1)',
  live: false,
  create: (app, root) => new TimingView(app, root),
};
