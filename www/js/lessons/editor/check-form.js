// An exercise's checks in the editor: each check as a row of fields, and the form that makes a
// new check from what is on the page now — a pose's origin (or one coordinate of it, where the
// format has single-coordinate pose checks) or its rotation, a span's angle, slide or pitch, the
// scheme and levels, a metric's threshold, the number of control poses — with the tolerance the teacher sets ("pose 1 within
// 0.1 of where it is now", "the velocity jump at most its value now + 0.01"). The check kinds and fields are the lesson format's
// (format.js CHECK_FIELDS, www/lessons/README.md).
import { CHECK_FIELDS, METRIC_FIELDS } from '../format.js';
import { el } from '../../dom.js';

const DEG = 180 / Math.PI;
/** Rounds what the page measured to what a teacher would write (6 significant digits). */
const round = (x) => Number(x.toPrecision(6));
/** A pose check may test one coordinate where the format has its `coordinate` and `value` fields. */
const ONE_COORDINATE = CHECK_FIELDS.pose.includes('coordinate') && CHECK_FIELDS.pose.includes('value');

/** The kinds of check the form makes from the page: value → words. */
export const FROM_PAGE = {
  origin: "a pose's origin (x, y, z)",
  ...(ONE_COORDINATE ? { x: "a pose's x", y: "a pose's y", z: "a pose's z" } : {}),
  rotation: "a pose's rotation",
  angle: "a span's angle (degrees)",
  slide: "a span's slide",
  pitch: "a span's pitch",
  options: 'the scheme and levels',
  controlPoses: 'at most: the number of control poses',
  ...Object.fromEntries(METRIC_FIELDS.map((f) => [`metric:${f}`, `at most: ${f.replace(/_/g, ' ')}`])),
};

/**
 * A check of kind `what` (a key of FROM_PAGE) from the page now: pose or span `index`, within
 * `tol` (degrees for a rotation or an angle). Throws where the page has no such pose or span.
 * @param {import('../../app.js').App} app
 */
export function checkFromPage(app, what, index, tol) {
  const m = app.motion;
  if (!(tol > 0)) throw new Error('the tolerance must be a number above 0');
  if (['origin', 'x', 'y', 'z', 'rotation'].includes(what)) {
    if (!(Number.isInteger(index) && index >= 0 && index < m.poseCount)) throw new Error(`there is no pose ${index} (the motion has ${m.poseCount} poses)`);
    const p = m.pose(index);
    if (what === 'origin') return { kind: 'pose', pose: index, origin: p.origin.map(round), tolerance: tol };
    if (what === 'rotation') return { kind: 'pose', pose: index, rotation: p.rotation.map(round), angleTolerance: tol };
    return { kind: 'pose', pose: index, coordinate: what, value: round(p.origin['xyz'.indexOf(what)]), tolerance: tol };
  }
  if (what === 'controlPoses') return { kind: 'controlPoses', max: m.poseCount };
  if (what === 'options') {
    const o = m.options();
    return { kind: 'options', scheme: o.scheme, levels: o.levels };
  }
  if (what.startsWith('metric:')) {
    // Present once the analysis module has loaded (see checksForm).
    if (typeof m.motionMetrics !== 'function') throw new Error('the analysis functions are not loaded yet');
    const field = what.slice('metric:'.length);
    const r = m.motionMetrics(undefined);
    const v = field === 'fourPointGap' ? r.fourPointGap : r.row[field];
    if (typeof v !== 'number' || !Number.isFinite(v)) throw new Error(`${field} cannot be measured on this motion (${r.row.notes?.join('; ') ?? 'no value'})`);
    return { kind: 'metric', field, max: round(v + tol) };
  }
  const spans = m.spanScrews();
  if (!(Number.isInteger(index) && index >= 0 && index < spans.length)) throw new Error(`there is no span ${index} (the motion has ${spans.length} spans)`);
  const s = spans[index];
  const v = what === 'angle' ? s.angle * DEG : what === 'slide' ? s.slide : s.pitch;
  if (!Number.isFinite(v)) throw new Error(`span ${index}'s ${what} is not a finite number now (a pure translation has no pitch)`);
  return { kind: 'spanScrew', span: index, [what]: { min: round(v - tol), max: round(v + tol) } };
}

/** An input for a number at `path`; `set(x)` on change (NaN where it is not a number). */
function numberInput(label, path, value, set) {
  const l = el('label', { class: 'le-num' }, `${label} `);
  const i = el('input');
  i.type = 'number';
  i.step = 'any';
  i.value = typeof value === 'number' ? String(value) : '';
  i.dataset.path = path;
  i.addEventListener('change', () => set(i.value.trim() === '' ? undefined : Number(i.value)));
  l.append(i);
  return l;
}

/**
 * The row of check `k` of step `i`'s exercise: its kind and a field for each of its values (a
 * range as min and max, a list as its numbers), and Delete.
 * @param {any} ed the editor (panel.js)
 */
function checkRow(ed, i, k, c) {
  const row = el('div', { class: 'le-check' });
  const base = `steps[${i}].exercise.checks[${k}]`;
  row.dataset.path = base;
  row.append(el('b', {}, c.kind === 'choice' ? 'the right answer is chosen' : c.kind));
  const set = (key, sub) => (x) =>
    ed.edit(`Change the check's ${key}`, (d) => {
      const ck = d.steps[i].exercise.checks[k];
      if (sub === undefined) ck[key] = x;
      else if (Array.isArray(ck[key])) ck[key][sub] = x;
      else {
        ck[key] = { ...ck[key], [sub]: x };
        if (x === undefined) delete ck[key][sub];
      }
    });
  for (const [key, v] of Object.entries(c)) {
    if (key === 'kind' || c.kind === 'choice') continue;
    const path = `${base}.${key}`;
    if (typeof v === 'number') row.append(numberInput(key, path, v, set(key)));
    else if (Array.isArray(v)) v.forEach((x, j) => row.append(numberInput(`${key}[${j}]`, `${path}[${j}]`, x, set(key, j))));
    else if (v && typeof v === 'object') for (const b of ['min', 'max']) row.append(numberInput(`${key} ${b}`, `${path}.${b}`, v[b], set(key, b)));
    else row.append(el('span', { class: 'le-val' }, `${key} ${v}`));
  }
  const del = el('button', { class: 'le-del' }, '✕');
  del.type = 'button';
  del.title = 'Delete this check';
  del.setAttribute('aria-label', `Delete check ${k + 1}`);
  del.addEventListener('click', () => ed.edit('Delete a check', (d) => d.steps[i].exercise.checks.splice(k, 1)));
  row.append(del);
  return row;
}

/**
 * The checks of step `i`'s exercise and the form adding one from the page.
 * @param {any} ed the editor (panel.js)
 */
export function checksForm(ed, i) {
  const box = el('div', { class: 'le-checks' });
  const x = ed.doc.steps[i].exercise;
  box.dataset.path = `steps[${i}].exercise.checks`;
  box.append(el('h4', {}, 'Checks (all must pass)'));
  (x.checks ?? []).forEach((c, k) => box.append(checkRow(ed, i, k, c)));
  const form = el('div', { class: 'le-from-page' });
  const what = el('select');
  what.id = 'le-check-what';
  what.setAttribute('aria-label', 'What the check measures');
  for (const [v, words] of Object.entries(FROM_PAGE)) what.append(Object.assign(el('option', {}, words), { value: v }));
  what.value = ed.ui.checkWhat ?? 'origin';
  const index = el('input');
  index.id = 'le-check-index';
  index.type = 'number';
  index.min = '0';
  index.step = '1';
  index.value = String(ed.ui.checkIndex ?? Math.max(0, ed.app.selected));
  const indexLabel = el('label', {}, 'number ');
  indexLabel.append(index);
  const tol = el('input');
  tol.id = 'le-check-tol';
  tol.type = 'number';
  tol.min = '0';
  tol.step = 'any';
  tol.value = String(ed.ui.checkTol ?? 0.1);
  const tolLabel = el('label', {}, 'within ± ');
  tolLabel.append(tol);
  const add = el('button', {}, 'Add check from the page now');
  add.id = 'le-check-add';
  add.type = 'button';
  const sync = () => {
    ed.ui.checkWhat = what.value;
    const whole = what.value === 'options' || what.value === 'controlPoses';
    indexLabel.hidden = whole || what.value.startsWith('metric:');
    tolLabel.hidden = whole;
    indexLabel.firstChild.textContent = ['angle', 'slide', 'pitch'].includes(what.value) ? 'span ' : 'pose ';
  };
  what.addEventListener('change', sync);
  index.addEventListener('change', () => (ed.ui.checkIndex = Number(index.value)));
  tol.addEventListener('change', () => (ed.ui.checkTol = Number(tol.value)));
  sync();
  add.addEventListener('click', async () => {
    let c;
    try {
      if (what.value.startsWith('metric:')) await ed.app.analysis();
      c = checkFromPage(ed.app, what.value, Number(index.value), tolLabel.hidden ? 1 : Number(tol.value));
    } catch (e) {
      ed.say(`Cannot make the check: ${e.message}.`, true);
      return;
    }
    ed.edit(`Add a check of ${FROM_PAGE[what.value]}`, (d) => {
      const ex = d.steps[i].exercise;
      ex.checks = [...(ex.checks ?? []), c];
    });
  });
  form.append(what, indexLabel, tolLabel, add);
  box.append(form);
  return box;
}
