// Timing view (paper §1, docs/math/timing.md): per-key times and velocities in a small table.
// The motion is retimed by a C¹ monotone piecewise-cubic map u = p(t) (the path is unchanged,
// only the speed along it) through p(T_i) = i and, where given, p'(T_i) = v_i. Times and
// velocities live in the Motion (its document, the session, share links, undo); 3-D playback,
// the timeline, the Plots view and glTF / CSV export all follow them.
import { lineChart, fmt } from './plot.js';
import { el } from '../dom.js';
import { reasonOf } from '../editor/commands.js';

/** The wasm functions of this view, from the analysis module the dock hands to create(). */
let timingMap;

class TimingView {
  constructor(app, root) {
    this.app = app;
    this.root = root;
    root.append(
      el('p', { class: 'note' },
        'Time (seconds) at which each control pose is reached, and optionally its velocity p′ in poses per second (blank: free). ',
        'Times must increase; the map from time to the motion parameter is C¹ and monotone, so the object never moves backwards ',
        'and a C¹ motion stays C¹ in time. An inserted pose is reached halfway between its neighbours (free velocity); a deleted pose takes its time along.'),
      el('div', { class: 'row' },
        el('button', { class: 'act', onclick: () => this.apply(null) }, 'Uniform (1 s per span)'),
        el('button', { class: 'act', title: 'Every key velocity free again', onclick: () => this.applyVelocities(null) }, 'Free velocities'),
        el('button', { class: 'act', title: 'Start and end at rest: velocity 0 at the first and last poses (times unchanged; one undo)', onclick: () => this.ease() }, 'Ease in / out'),
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
    return this.app.keyTimes();
  }

  /** Shows why an edit was refused (null: clears the message). */
  say(error) {
    this.message.textContent = error ? `Not applied: ${error}` : '';
    this.message.classList.toggle('error', !!error);
  }

  /** Sets the times (null: uniform) as one undoable edit; the Motion checks them. */
  apply(times) {
    const error = reasonOf(this.app, 'setTimes', times ? [...times] : null);
    this.say(error);
    return !error;
  }

  /** Sets the key velocities (null: all free) as one undoable edit; the Motion checks them. */
  applyVelocities(velocities) {
    const error = reasonOf(this.app, 'setVelocities', velocities);
    this.say(error);
    return !error;
  }

  /**
   * Ease in / out: the motion starts and ends at rest, through p′ = 0 at the first and last
   * poses (pose 0 of a cycle), the paper's C¹ timing; times and the other velocities stay as
   * they are. One undoable edit; a notice says what changed and how to take it back.
   */
  ease() {
    const m = this.app.motion;
    const n = m.poseCount;
    const before = this.app.velocities();
    const next = Array.from({ length: n }, (_, k) => before?.[k] ?? null);
    const ends = m.closed ? [0] : [0, n - 1];
    const replaced = ends.filter((k) => next[k] !== null && next[k] !== 0);
    for (const k of ends) next[k] = 0;
    if (!this.applyVelocities(next)) return false;
    const which = m.closed ? 'pose 0 (start and end of the cycle)' : `poses 0 and ${n - 1}`;
    const was = replaced.length ? ` (replacing ${replaced.map((k) => `${before[k]} at pose ${k}`).join(', ')})` : '';
    this.app.parts.notices.show(`Ease in / out: velocity 0 at ${which}${was}; times unchanged. Undo (Ctrl+Z) takes it back.`, 'info');
    return true;
  }

  /**
   * Refills the table: per key its time (the span to the previous one beside it) and, one per
   * control pose, its velocity (blank: free). A refused value shows the one in use again.
   */
  fillTable(m, times, velocities) {
    const rows = [el('tr', {}, el('th', {}, 'pose'), el('th', {}, 'time (s)'), el('th', {}, 'span (s)'), el('th', {}, 'velocity (poses/s)'))];
    times.forEach((t, i) => {
      const input = el('input', {
        type: 'number', step: '0.1', value: String(t), style: 'width:80px',
        'aria-label': `time of pose ${i % m.poseCount}`,
        onchange: () => {
          const next = [...times];
          next[i] = Number(input.value);
          if (!Number.isFinite(next[i]) || input.value.trim() === '') this.say(`time ${i} is not a number.`);
          else if (this.apply(next)) return;
          // Refused: the input shows the time still in use again, the message says why.
          input.value = String(t);
        },
      });
      let vcell = el('td', {}, i < m.poseCount ? '' : 'as pose 0');
      if (i < m.poseCount) {
        const v = velocities?.[i] ?? null;
        const vin = el('input', {
          type: 'number', step: '0.1', min: '0', value: v === null ? '' : String(v), placeholder: 'free', style: 'width:70px',
          'aria-label': `velocity of pose ${i} (poses per second; blank: free)`,
          onchange: () => {
            const text = vin.value.trim();
            const value = text === '' ? null : Number(text);
            // A field the browser could not read as a number comes back as '' with badInput.
            if (vin.validity?.badInput || (value !== null && !Number.isFinite(value))) this.say(`velocities[${i}]: not a number.`);
            else {
              const next = Array.from({ length: this.app.motion.poseCount }, (_, k) => velocities?.[k] ?? null);
              next[i] = value;
              if (this.applyVelocities(next.every((x) => x === null) ? null : next)) return;
            }
            vin.value = v === null ? '' : String(v);
          },
        });
        vcell = el('td', {}, vin);
      }
      const label = i < m.poseCount ? String(i) : '0 (again, end of cycle)';
      rows.push(el('tr', {}, el('td', {}, label), el('td', {}, input), el('td', {}, i > 0 ? fmt(t - times[i - 1]) : '–'), vcell));
    });
    this.table.replaceChildren(...rows);
  }

  update() {
    const m = this.app.motion;
    const times = this.current();
    const velocities = this.app.velocities();
    // Rebuild the table only when the timing changes: a rebuild between a user's typing and the
    // input's `change` event would throw the typed value away with the old input.
    const key = `${m.poseCount}|${m.closed}|${times.join(',')}|${velocities?.join(',') ?? ''}`;
    if (key !== this.tableKey) {
      this.tableKey = key;
      this.fillTable(m, times, velocities);
    }
    if (this.chart) {
      // The map the playback uses: through the key times, with the key velocities.
      const d = timingMap(times, m.poseCount, m.closed, 400, velocities ?? undefined);
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

/** @type {import('../editor/dock.js').DockView} */
export default {
  id: 'timing',
  title: 'Timing',
  hint: 'Per-key times and velocities: retime the motion by a C¹ monotone map (paper §1)',
  live: false,
  create: (app, root, wasm) => {
    ({ timingMap } = wasm);
    return new TimingView(app, root);
  },
};
