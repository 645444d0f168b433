// The pose panel: the selected control pose in numbers (origin, quaternion [w, x, y, z],
// axis–angle, Euler angles in a selectable order, rotation matrix), editable with validation,
// and a readout at the playhead (pose, speed, angular speed, the current span's screw). It
// lives in a "Pose" folder of the settings panel (editor/panel.js and editor/ui.js call `build`, `refresh` and
// `setTime`). An edit is one undoable step; a bad value shows a message beside its group and
// changes nothing. Conventions (docs/math/conventions.md): quaternions [w, x, y, z], rotations
// act on column vectors, Euler angles are intrinsic (the order names the axes from the world
// frame inwards, as in three.js: 'XYZ' is R = Rx Ry Rz).
import { qaxis, qmul } from '../math.js';
import { el } from '../dom.js';

/** The Euler orders the panel offers. */
export const EULER_ORDERS = ['XYZ', 'XZY', 'YXZ', 'YZX', 'ZXY', 'ZYX'];
/** Relative tolerance on the length of a typed quaternion below which it is normalised silently. */
const UNIT_TOLERANCE = 1e-6;
const DEG = 180 / Math.PI;
const AXIS_INDEX = { X: 0, Y: 1, Z: 2 };

/** Row-major 3×3 rotation matrix of the unit quaternion q = [w, x, y, z]. */
export function quatToMatrix(q) {
  const [w, x, y, z] = q;
  return [
    [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
    [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
    [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
  ];
}

/** Axis (unit) and angle in [0, π] of the unit quaternion q; the x axis for no rotation. */
export function quatToAxisAngle(q) {
  const s = q[0] < 0 ? -1 : 1;
  const v = [s * q[1], s * q[2], s * q[3]];
  const n = Math.hypot(...v);
  if (n < 1e-15) return { axis: [1, 0, 0], angle: 0 };
  return { axis: v.map((c) => c / n), angle: 2 * Math.atan2(n, s * q[0]) };
}

/** The unit quaternion of intrinsic Euler angles `angles` (radians) in `order`. */
export function eulerToQuat(angles, order) {
  let q = [1, 0, 0, 0];
  for (let k = 0; k < 3; k++) {
    const axis = [0, 0, 0];
    axis[AXIS_INDEX[order[k]]] = 1;
    q = qmul(q, qaxis(axis, angles[k]));
  }
  return q;
}

/**
 * Intrinsic Euler angles (radians) in `order` of the row-major rotation matrix m: the angles
 * [a, b, c] with R = R_i(a) R_j(b) R_k(c). The middle angle is in [-π/2, π/2]; in gimbal lock
 * (|sin b| = 1) the last angle is 0.
 */
export function matrixToEuler(m, order) {
  const [i, j, k] = [...order].map((c) => AXIS_INDEX[c]);
  // +1 for the cyclic orders (XYZ, YZX, ZXY), -1 for the others.
  const s = (j - i + 3) % 3 === 1 ? 1 : -1;
  // atan2 rather than asin: accurate near ±π/2 as well.
  const cb = Math.hypot(m[i][i], m[i][j]);
  const b = Math.atan2(s * m[i][k], cb);
  if (cb > 1e-12) {
    return [Math.atan2(-s * m[j][k], m[k][k]), b, Math.atan2(-s * m[i][j], m[i][i])];
  }
  return [Math.atan2(s * m[k][j], m[j][j]), b, 0];
}

/** A number for a field: at most 6 decimals, no "-0". */
function show(v) {
  const r = Number(v.toFixed(6));
  return String(Object.is(r, -0) ? 0 : r);
}

/** @type {import('../app.js').Part} */
export default {
  id: 'pose',
  create(app) {
    /** The groups of fields: id → {fields, message, ...}. */
    const groups = {};
    let root = null;
    let order = 'XYZ';
    let spans = null;

    /** A group of number fields with a legend and an inline message. */
    function group(id, legend, labels, extra = []) {
      const fields = labels.map((l) =>
        el('input', { type: 'text', inputMode: 'decimal', autocomplete: 'off', spellcheck: false, 'aria-label': `${legend}: ${l}`, class: 'pp-num' }),
      );
      const cells = labels.map((l, k) => el('label', { class: 'pp-cell' }, [el('span', { 'aria-hidden': 'true' }, [l]), fields[k]]));
      const message = el('p', { class: 'pp-msg', role: 'alert', hidden: true });
      const box = el('fieldset', { class: `pp-group pp-${id}` }, [el('legend', {}, [legend]), ...extra, el('div', { class: 'pp-row' }, cells), message]);
      // A group applies when the focus leaves it (Tab between its fields does not) or on Enter,
      // so a quaternion is read whole, not normalised field by field.
      box.addEventListener('focusout', (e) => {
        if (!box.contains(e.relatedTarget)) apply(id);
      });
      for (const f of fields) {
        f.addEventListener('keydown', (e) => {
          if (e.key === 'Enter') apply(id);
          else if (e.key === 'Escape') {
            refresh(true);
            f.blur();
          }
        });
      }
      groups[id] = { fields, message, box };
      return box;
    }

    /** The numbers of group `id`: a typed value where a field was changed, `current` elsewhere. */
    function read(id, current) {
      const g = groups[id];
      const out = [];
      for (let k = 0; k < g.fields.length; k++) {
        const f = g.fields[k];
        if (f.value === f.dataset.shown) {
          out.push(current[k]);
          continue;
        }
        const text = f.value.trim();
        const v = Number(text);
        if (text === '' || !Number.isFinite(v)) throw new Error(`${f.getAttribute('aria-label')}: “${f.value}” is not a number`);
        out.push(v);
      }
      return out;
    }

    function fail(id, message) {
      const g = groups[id];
      g.message.textContent = message;
      g.message.hidden = false;
      g.box.classList.add('bad');
    }

    function clearMessages() {
      for (const g of Object.values(groups)) {
        g.message.hidden = true;
        g.message.textContent = '';
        g.box.classList.remove('bad');
      }
    }

    /** Applies the fields of group `id` to the selected pose (one undoable edit). */
    function apply(id) {
      const i = app.selected;
      if (i < 0 || !app.motion || i >= app.motion.poseCount) return;
      // Enter and then the change event on blur: the second finds nothing typed.
      if (groups[id].fields.every((f) => f.value === f.dataset.shown)) return;
      const pose = app.motion.pose(i);
      const q0 = [...pose.rotation];
      let origin = [...pose.origin];
      let rotation = q0;
      try {
        if (id === 'origin') origin = read(id, origin);
        else if (id === 'quat') {
          const q = read(id, q0);
          const n = Math.hypot(...q);
          if (!(n > 1e-12)) throw new Error('the quaternion is zero: it is no rotation; nothing was changed');
          if (!Number.isFinite(n)) throw new Error('the quaternion is too large; nothing was changed');
          rotation = q.map((c) => c / n);
          if (Math.abs(n - 1) > UNIT_TOLERANCE) app.ui?.toast(`Quaternion normalised to unit length (its length was ${show(n)}).`);
        } else if (id === 'axis') {
          const cur = quatToAxisAngle(q0);
          const [x, y, z, deg] = read(id, [...cur.axis, cur.angle * DEG]);
          const n = Math.hypot(x, y, z);
          if (!Number.isFinite(n)) throw new Error('the axis is too large; nothing was changed');
          if (!(n > 1e-12)) {
            if (deg !== 0) throw new Error('the axis is zero: give it a direction; nothing was changed');
            rotation = [1, 0, 0, 0];
          } else rotation = qaxis([x / n, y / n, z / n], deg / DEG);
        } else if (id === 'euler') {
          const cur = matrixToEuler(quatToMatrix(q0), order).map((a) => a * DEG);
          const a = read(id, cur);
          rotation = eulerToQuat(a.map((d) => d / DEG), order);
        }
      } catch (e) {
        fail(id, e.message);
        return;
      }
      const before = app.errors.length;
      app.run('setPose', i, { origin, rotation });
      // The typed values are now the pose's (or, refused, replaced by them again).
      refresh(true);
      // The Motion refused the pose (a value out of its range): say so here as well.
      if (app.errors.length > before) fail(id, app.errors[app.errors.length - 1]);
    }

    /** Writes numbers into a group's fields (and remembers them, to see which ones change). */
    function fill(id, values, force) {
      groups[id].fields.forEach((f, k) => {
        // A field being typed in keeps its text when something else changes.
        if (!force && document.activeElement === f && f.value !== f.dataset.shown) return;
        f.value = f.dataset.shown = show(values[k]);
      });
    }

    let which;
    let matrixCells;
    let editor;
    let readout;

    function build(container) {
      which = el('p', { class: 'pp-which' });
      const orderSel = el(
        'select',
        { class: 'pp-order', 'aria-label': 'Euler angle order (intrinsic)' },
        EULER_ORDERS.map((o) => el('option', { value: o }, [o])),
      );
      orderSel.addEventListener('change', () => {
        order = orderSel.value;
        groups.euler.fields.forEach((f, k) => f.setAttribute('aria-label', `Euler angle ° about ${order[k]}`));
        groups.euler.box.querySelectorAll('.pp-cell > span').forEach((s, k) => (s.textContent = order[k]));
        refresh();
      });
      matrixCells = [];
      const rows = [0, 1, 2].map((r) =>
        el(
          'tr',
          {},
          [0, 1, 2].map((c) => {
            const td = el('td');
            matrixCells.push(td);
            return td;
          }),
        ),
      );
      editor = el('div', { class: 'pp-editor' }, [
        group('origin', 'Origin', ['x', 'y', 'z']),
        group('quat', 'Quaternion [w, x, y, z]', ['w', 'x', 'y', 'z']),
        group('axis', 'Axis–angle', ['x', 'y', 'z', 'angle °']),
        group('euler', 'Euler angles °', ['X', 'Y', 'Z'], [el('label', { class: 'pp-orderlabel' }, ['order ', orderSel])]),
        el('table', { class: 'pp-matrix' }, [el('caption', {}, ['Rotation matrix']), el('tbody', {}, rows)]),
      ]);
      groups.euler.fields.forEach((f, k) => f.setAttribute('aria-label', `Euler angle ° about ${order[k]}`));
      readout = el('dl', { class: 'pp-readout', 'aria-live': 'off' });
      root = el('div', { class: 'pose-panel' }, [which, editor, el('h3', { class: 'pp-h' }, ['At the playhead']), readout]);
      container.append(root);
      refresh();
    }

    /**
     * Shows the selected pose (or says how to select one) and clears the messages; `force`
     * also overwrites a field that is being typed in.
     */
    function refresh(force = false) {
      if (!root || !app.motion) return;
      spans = null;
      clearMessages();
      const i = app.selected;
      const has = i >= 0 && i < app.motion.poseCount;
      editor.hidden = !has;
      which.textContent = has
        ? `Pose ${i} of ${app.motion.poseCount} (0-based)`
        : 'No pose selected: click a white handle, or press N with the 3-D view focused.';
      if (has) {
        const { origin, rotation } = app.motion.pose(i);
        fill('origin', origin, force);
        fill('quat', rotation, force);
        const aa = quatToAxisAngle(rotation);
        fill('axis', [...aa.axis, aa.angle * DEG], force);
        const m = quatToMatrix(rotation);
        fill('euler', matrixToEuler(m, order).map((a) => a * DEG), force);
        m.flat().forEach((v, k) => (matrixCells[k].textContent = show(v)));
      }
      setTime(app.anim.u);
    }

    /** The playhead readout at parameter u. */
    function setTime(u) {
      if (!readout || !app.motion || root.closest('.lil-closed')) return;
      let rows;
      try {
        const p = app.motion.poseAt(u);
        const k = app.motion.kinematicsAt(u);
        spans ??= app.motion.spanScrews();
        const n = app.motion.poseCount;
        const s = Math.min(Math.floor(u), spans.length - 1);
        const sc = spans[Math.max(0, s)];
        const fmt = (v) => `[${v.map((c) => c.toFixed(3)).join(', ')}]`;
        let screw;
        if (!sc || sc.kind === 'identity') screw = 'none (the poses are equal)';
        else if (sc.kind === 'translation') screw = `translation along ${fmt(sc.direction)}, slide ${sc.slide.toFixed(3)}`;
        else screw = `axis ${fmt(sc.direction)} through ${fmt(sc.point)}, angle ${(sc.angle * DEG).toFixed(2)}°, slide ${sc.slide.toFixed(3)}, pitch ${sc.pitch.toFixed(3)}`;
        rows = [
          ['u', u.toFixed(3)],
          ['origin', fmt(p.origin)],
          ['quaternion', fmt(p.rotation)],
          ['speed', `${Math.hypot(...k.velocity).toFixed(3)} units per unit u`],
          ['angular speed', `${(Math.hypot(...k.angularVelocity) * DEG).toFixed(2)}° per unit u`],
          [`span ${Math.max(0, s)}→${(Math.max(0, s) + 1) % n}`, screw],
        ];
      } catch (e) {
        rows = [['', e.message]];
      }
      readout.replaceChildren(...rows.flatMap(([k, v]) => [el('dt', {}, [k]), el('dd', {}, [v])]));
    }

    return { build, refresh, setTime };
  },
};
