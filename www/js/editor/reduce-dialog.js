// The dense-import dialog: a file with more poses than make sense as control poses (a CSV of
// samples, say) asks whether to keep them all, every k-th, or the fewest within a tolerance
// (the core's reducePoses, docs/math/formats.md §7) — or to fit a smooth motion to all of them
// (the full module's fitPoses, docs/math/fitting.md), whose residuals the dialog shows before
// the import. A real modal <dialog>: the rest of the page is inert while it is open (focus stays
// inside), Esc or Cancel changes nothing.
import { el } from '../dom.js';

/** More poses than this in one imported file open the dialog (the core's MANY_POSES). */
export const MANY_POSES = 64;

/** The fit methods as the dialog names them, and the scheme each one's control poses are for. */
const FIT_METHODS = {
  screwbender: { name: 'ScrewBender B-spline', scheme: 'bspline' },
  se3bspline: { name: 'SE(3) B-spline', scheme: null },
};

/**
 * Asks how to import `doc` (a MotionDocument of `doc.poses.length` poses, read from `fileName`).
 * `radius`: the object's size (scene units) the tolerances apply at. Resolves with
 * `{doc, how, fit}` — the document to import, a sentence saying what was kept or fitted, and for
 * a fit `{scheme}` (the scheme to draw it with, or null: keep the current one) — or null when
 * cancelled. A reduction or fit the core refuses shows its message in the dialog, which stays
 * open. `reducePoses`: the wasm module's function of that name; `fitPoses`: an async form of the
 * full module's.
 */
export function askReduction(doc, fileName, radius, reducePoses, fitPoses) {
  const n = doc.poses.length;
  const id = (s) => `reduce-${s}`;
  const radio = (value, checked) =>
    el('input', { type: 'radio', name: 'reduce-how', value, id: id(value), checked });
  const every = el('input', {
    type: 'number', id: id('k'), min: '1', step: '1', value: String(Math.max(2, Math.ceil(n / 32))), 'aria-label': 'keep every k-th pose: k',
  });
  const tol = el('input', {
    type: 'number', id: id('tol'), min: '0', step: 'any', value: '0.001', 'aria-label': 'tolerance in scene units',
  });
  const fitCount = el('input', {
    type: 'number', id: id('fit-n'), min: '0', step: 'any', value: String(Math.min(n, Math.max(4, Math.ceil(n / 16)))), 'aria-label': 'fit: control poses, or the tolerance',
  });
  const fitBy = el('select', { id: id('fit-by'), 'aria-label': 'fit: the number means' },
    el('option', { value: 'controls' }, 'control poses'),
    el('option', { value: 'tolerance' }, 'RMS tolerance'));
  const method = el('select', { id: id('method') },
    ...Object.entries(FIT_METHODS).map(([value, m]) => el('option', { value }, m.name)));
  const robust = el('select', { id: id('robust') },
    el('option', { value: 'none' }, 'none'),
    el('option', { value: 'huber' }, 'Huber'),
    el('option', { value: 'cauchy' }, 'Cauchy'));
  robust.value = 'huber'; // outliers are common in capture data; the loss costs little without them
  const fitButton = el('button', { type: 'button', id: id('fit-run') }, 'Fit');
  const schemeNote = el('p', { class: 'note', id: id('scheme-note') });
  const report = el('p', { class: 'note', id: id('report'), role: 'status' });
  const preview = el('p', { class: 'note', role: 'status' });
  const error = el('p', { class: 'note error', role: 'alert' });
  const ok = el('button', { type: 'submit', class: 'primary', value: 'ok' }, 'Import');
  const cancel = el('button', { type: 'button', value: 'cancel' }, 'Cancel');
  const choices = [
    radio('all', false), radio('every', true), radio('within', false), radio('fit', false),
  ];
  const form = el('form', { method: 'dialog' },
    el('h2', { id: id('title') }, `${n} poses in ${fileName}`),
    el('p', {}, `That is more than ${MANY_POSES}: probably samples of a motion rather than control poses. `,
      'Smoothing every sample gives many more refined poses than needed. Import:'),
    el('div', { class: 'choice' }, choices[0], el('label', { htmlFor: id('all') }, `all ${n} poses`)),
    el('div', { class: 'choice' }, choices[1], el('label', { htmlFor: id('every') }, 'every k-th pose (an open motion keeps its last), k ='), every),
    el('div', { class: 'choice' }, choices[2],
      el('label', { htmlFor: id('within') }, 'the fewest poses whose screw motions stay within'), tol,
      el('span', {}, `scene units of every pose (at points up to ${+radius.toFixed(3)} from the object's origin)`)),
    preview,
    el('div', { class: 'choice' }, choices[3],
      el('label', { htmlFor: id('fit') }, `a smooth motion fitted to all ${n} poses, with`), fitCount, fitBy),
    el('div', { class: 'choice fit-options' },
      el('label', { htmlFor: id('method') }, 'method'), method,
      el('label', { htmlFor: id('robust') }, 'robust loss'), robust, fitButton),
    schemeNote, report, error,
    el('div', { class: 'row' }, cancel, ok),
  );
  const dialog = el('dialog', { id: 'reduce-dialog', 'aria-labelledby': id('title') }, form);
  document.body.append(dialog);

  const how = () => choices.find((c) => c.checked).value;
  /** The fitPoses options the fit controls ask for. */
  const fitOptions = () => ({
    [fitBy.value]: Number(fitCount.value), method: method.value, robust: robust.value, radius,
  });
  /** The last fit: its options (as JSON) and its result, or its error. */
  let fitted = null;
  /** Fits with the current options (once per set of options); the result, or throws. */
  const fit = async () => {
    const key = JSON.stringify(fitOptions());
    if (fitted?.key !== key) {
      const options = fitOptions();
      // The fit runs on this thread (a large file takes a while): the "Fitting…" note is drawn first.
      await new Promise((r) => requestAnimationFrame(() => setTimeout(r, 0)));
      try {
        fitted = { key, result: await fitPoses(doc, options) };
      } catch (e) {
        fitted = { key, error: e };
      }
    }
    if (fitted.error) throw fitted.error;
    return fitted.result;
  };
  const describeFit = () => {
    const m = FIT_METHODS[method.value];
    schemeNote.textContent = m.scheme
      ? `Importing this fit sets the scheme to cubic B-spline: its control poses are that scheme's.`
      : `The SE(3) B-spline's control poses are drawn with the current scheme; compare the two in Analysis → Methods.`;
  };
  /** Runs the fit and shows its residuals; false (and the core's words) when refused. */
  const showFit = async () => {
    error.textContent = '';
    report.textContent = 'Fitting…';
    try {
      const { report: r } = await fit();
      const deg = (a) => +((a * 180) / Math.PI).toPrecision(3);
      const len = (x) => +x.toPrecision(3);
      report.textContent = `→ ${r.controls} control poses fitted to ${r.samples} poses: distance RMS ${len(r.rmsPosition)}, max ${len(r.maxPosition)} scene units; angle RMS ${deg(r.rmsAngle)}°, max ${deg(r.maxAngle)}°.`;
      return true;
    } catch (e) {
      report.textContent = '';
      error.textContent = e.message;
      return false;
    }
  };
  /** The reduced document and its description for the current choice; throws on bad input. */
  const reduce = () => {
    switch (how()) {
      case 'all':
        return { doc, how: `kept all ${n} poses` };
      case 'every': {
        const k = Number(every.value);
        const d = reducePoses(doc, { every: k });
        return { doc: d, how: `kept ${d.poses.length} of ${n} poses (every ${ordinal(k)})` };
      }
      case 'fit':
        throw new Error('a fit is not a reduction');
      default: {
        const t = Number(tol.value);
        const d = reducePoses(doc, { tolerance: t, radius });
        return { doc: d, how: `kept ${d.poses.length} of ${n} poses (within ${t} scene units)` };
      }
    }
  };
  const refresh = () => {
    error.textContent = '';
    describeFit();
    if (how() === 'fit') {
      preview.textContent = '';
      return;
    }
    report.textContent = '';
    try {
      const r = reduce();
      preview.textContent = `→ ${r.doc.poses.length} control poses.`;
    } catch (e) {
      preview.textContent = '';
      error.textContent = e.message;
    }
  };
  for (const c of [...choices, every, tol, method]) c.addEventListener('input', refresh);
  // Typing into a field chooses its option.
  every.addEventListener('focus', () => ((choices[1].checked = true), refresh()));
  tol.addEventListener('focus', () => ((choices[2].checked = true), refresh()));
  for (const c of [fitCount, fitBy, method, robust, fitButton]) {
    c.addEventListener('focus', () => {
      if (choices[3].checked) return;
      choices[3].checked = true;
      refresh();
    });
  }
  fitButton.onclick = () => showFit();
  refresh();

  return new Promise((resolve) => {
    let answered = false;
    const done = (value) => {
      if (answered) return;
      answered = true;
      dialog.close();
      dialog.remove();
      resolve(value);
    };
    cancel.onclick = () => done(null);
    // Esc: the browser's `cancel` event; nothing changes.
    dialog.addEventListener('cancel', (e) => {
      e.preventDefault();
      done(null);
    });
    form.addEventListener('submit', async (e) => {
      e.preventDefault();
      if (how() === 'fit') {
        if (!(await showFit())) return;
        const { document: d, report: r } = await fit();
        const m = FIT_METHODS[method.value];
        done({
          doc: d,
          how: `fitted ${r.controls} control poses (${m.name}) to ${n} poses, distance RMS ${+r.rmsPosition.toPrecision(3)} scene units`,
          fit: { scheme: m.scheme },
        });
        return;
      }
      let r;
      try {
        r = reduce();
      } catch (err) {
        error.textContent = err.message;
        return;
      }
      done(r);
    });
    dialog.showModal();
    choices[1].focus();
  });
}

/** 2 → "2nd", 4 → "4th". */
function ordinal(k) {
  const s = k % 100 >= 11 && k % 100 <= 13 ? 'th' : ['th', 'st', 'nd', 'rd'][k % 10] ?? 'th';
  return `${k}${s}`;
}
