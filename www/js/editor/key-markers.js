// The timeline's key markers: the motion's key times above the scrubber, to drag or move by keys.
import { reasonOf } from './commands.js';

/** Arrow-key steps of a focused key marker (seconds): plain and with Shift. */
const KEY_STEP = 0.1;
const KEY_STEP_FINE = 0.01;
/** Marker drags snap to this step (seconds). */
const DRAG_SNAP = 0.01;

/**
 * The key markers of the timeline: one per key time (a cycle's last is its return to pose 0),
 * placed on the scrubber's scale. Dragging one (mouse, pen or touch) retimes that key with a
 * live preview and makes one undoable edit on release; arrow keys move a focused marker by 0.1 s
 * (Shift: 0.01 s), a run of presses on one marker making one undo step (a new step after a
 * second idle (session.js MERGE_IDLE_MS), a blur or another marker, as editors merge typing). Times must keep
 * increasing: a move past a neighbouring key is refused with a message and changes nothing (a
 * drag is then over until the next press).
 *
 * Touch: each marker's hit box is 44 px (style.css), wider than the gap between close keys;
 * where boxes overlap, a press goes to the marker whose centre is nearest to it (the boxes are
 * in effect split at the midpoints between neighbours), not to the one drawn on top.
 *
 * Returns {place()}, which follows the key times (not during a drag).
 * @param {import('../app.js').App} app
 * @param {HTMLElement} root
 */
export function buildKeyMarkers(app, root) {
  let markers = [];
  let drag = null;
  /** The arrow-key run in progress: {i, id} (its presses share one undo step), or null. */
  let run = null;
  let runs = 0;
  const round = (t) => Math.round(t / DRAG_SNAP) * DRAG_SNAP;
  const fmt = (t) => `${Number(t.toFixed(3))} s`;

  function name(i, n) {
    return i < n ? `pose ${i}` : 'pose 0 (end of cycle)';
  }

  /** Why `times` with key i at `t` is refused by its neighbours (null: in order). */
  function outOfOrder(times, i, t) {
    const n = app.motion.poseCount;
    if (i > 0 && !(t > times[i - 1])) return `${name(i, n)} cannot move to ${fmt(t)}: at or before ${name(i - 1, n)}'s key (${fmt(times[i - 1])})`;
    if (i < times.length - 1 && !(t < times[i + 1])) return `${name(i, n)} cannot move to ${fmt(t)}: at or after ${name(i + 1, n)}'s key (${fmt(times[i + 1])})`;
    return null;
  }

  function refuse(reason) {
    app.parts.notices.show(`Not retimed: ${reason}. Times must increase; nothing changed.`, 'warn');
  }

  /** Positions and names the markers on the scale [a, b] (default: the key times' own). */
  function place(scale) {
    if (!app.motion) return;
    const times = app.keyTimes();
    const n = app.motion.poseCount;
    if (markers.length !== times.length) {
      markers = times.map((_, i) => {
        const m = document.createElement('div');
        m.className = 'key-marker';
        m.tabIndex = 0;
        m.setAttribute('role', 'slider');
        m.dataset.key = String(i);
        m.addEventListener('pointerdown', (e) => press(e, nearest(e, i)));
        m.addEventListener('keydown', (e) => key(e, i));
        m.addEventListener('blur', () => run?.i === i && (run = null));
        return m;
      });
      root.replaceChildren(...markers);
    }
    const [a, b] = scale ?? [times[0], times[times.length - 1]];
    markers.forEach((m, i) => {
      const t = times[i];
      m.style.setProperty('--at', String((t - a) / (b - a)));
      m.setAttribute('aria-label', `Key time of ${name(i, n)}`);
      m.setAttribute('aria-valuenow', String(t));
      m.setAttribute('aria-valuetext', fmt(t));
      m.setAttribute('aria-valuemin', String(i > 0 ? times[i - 1] : t - 1e6));
      m.setAttribute('aria-valuemax', String(i < times.length - 1 ? times[i + 1] : t + 1e6));
      m.title = `${name(i, n)} at ${fmt(t)}: drag or use the arrow keys (Shift: 0.01 s) to retime`;
    });
  }

  function key(e, i) {
    const dir = { ArrowRight: 1, ArrowUp: 1, ArrowLeft: -1, ArrowDown: -1 }[e.key];
    if (!dir) return;
    e.preventDefault();
    const times = app.keyTimes();
    const step = e.shiftKey ? KEY_STEP_FINE : KEY_STEP;
    // Rounded to the step's decimals, so 0.1 s steps give 1.1, not 1.1000000000000001.
    const t = Number((times[i] + dir * step).toFixed(6));
    const why = outOfOrder(times, i, t);
    if (why) return refuse(why);
    const next = [...times];
    next[i] = t;
    if (run?.i !== i) run = { i, id: ++runs };
    const err = reasonOf(app, 'setTimes', next, `key-marker ${run.id}`);
    if (err) refuse(err);
  }

  /**
   * The marker a press at (e.clientX, e.clientY) on marker `hit` is for: of the markers whose
   * box holds the point, the one whose centre is nearest (ties: `hit`, the one on top).
   */
  function nearest(e, hit) {
    let best = hit;
    let bestDist = Infinity;
    markers.forEach((m, k) => {
      const r = m.getBoundingClientRect();
      if (e.clientX < r.left || e.clientX > r.right || e.clientY < r.top || e.clientY > r.bottom) return;
      const d = Math.abs(e.clientX - (r.left + r.width / 2));
      if (d < bestDist || (d === bestDist && k === hit)) {
        best = k;
        bestDist = d;
      }
    });
    return best;
  }

  /** The time under the pointer on the drag's frozen scale, less the grab offset. */
  function timeAt(e) {
    const { left, width, a, b, offset } = drag;
    return round(a + ((e.clientX - offset - left) / width) * (b - a));
  }

  function press(e, i) {
    if (e.button !== 0 || drag) return;
    e.preventDefault();
    const m = markers[i];
    m.focus();
    m.setPointerCapture?.(e.pointerId);
    const times = app.keyTimes();
    const r = root.getBoundingClientRect();
    // Where on the marker it was grabbed: the key follows the pointer's travel, it does not
    // jump under a finger that pressed beside the mark.
    const mr = m.getBoundingClientRect();
    // The scale stays fixed while dragging (moving the first or last key would rescale it).
    const inset = parseFloat(getComputedStyle(root).getPropertyValue('--key-inset')) || 0;
    drag = {
      i, pointer: e.pointerId, times, before: app.parts.session.snapshot(), moved: false, refused: false,
      left: r.left + inset, width: Math.max(1, r.width - 2 * inset), a: times[0], b: times[times.length - 1],
      offset: e.clientX - (mr.left + mr.width / 2),
      original: app.motion.times ? Array.from(app.motion.times) : null,
    };
    m.classList.add('dragging');
    const move = (ev) => {
      if (!drag || drag.refused || ev.pointerId !== drag.pointer) return;
      const t = timeAt(ev);
      if (t === drag.times[i] && !drag.moved) return;
      const why = outOfOrder(drag.times, i, t);
      if (why) return abort(why);
      const next = [...drag.times];
      next[i] = t;
      try {
        // A live preview: the object at the playhead follows; undo and save come on release.
        app.motion.setTimes(next);
      } catch (err) {
        return abort(err.message);
      }
      drag.moved = true;
      app.viewer.retime();
      app.viewer.requestDraw();
      place([drag.a, drag.b]);
    };
    const up = (ev) => {
      if (!drag || ev.pointerId !== drag.pointer) return;
      const d = drag;
      drag = null;
      m.classList.remove('dragging');
      m.removeEventListener('pointermove', move);
      m.removeEventListener('pointerup', up);
      m.removeEventListener('pointercancel', up);
      if (d.moved && !d.refused) {
        app.history.push(d.before, `Retime key ${d.i}`);
        app.changed();
      } else place();
    };
    /** Refuses the drag: the times in use before it come back; the drag is over. */
    const abort = (why) => {
      drag.refused = true;
      if (drag.moved) {
        app.motion.setTimes(drag.original);
        drag.moved = false;
        app.viewer.retime();
        app.viewer.requestDraw();
      }
      place([drag.a, drag.b]);
      refuse(why);
    };
    m.addEventListener('pointermove', move);
    m.addEventListener('pointerup', up);
    m.addEventListener('pointercancel', up);
  }

  place();
  return { place: () => drag || place() };
}
