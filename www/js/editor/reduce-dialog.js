// The dense-import dialog: a file with more poses than make sense as control poses (a CSV of
// samples, say) asks whether to keep them all, every k-th, or the fewest within a tolerance
// (the core's reducePoses, docs/math/formats.md §7). A real modal <dialog>: the rest of the page
// is inert while it is open (focus stays inside), Esc or Cancel changes nothing.
import { el } from '../dom.js';

/** More poses than this in one imported file open the dialog (the core's MANY_POSES). */
export const MANY_POSES = 64;

/**
 * Asks how to import `doc` (a MotionDocument of `doc.poses.length` poses, read from `fileName`).
 * `radius`: the object's size (scene units) the tolerance applies at. Resolves with
 * `{doc, how}` — the document to import and a sentence saying what was kept — or null when
 * cancelled. A reduction the core refuses shows its message in the dialog, which stays open.
 * `reducePoses`: the wasm module's function of that name.
 */
export function askReduction(doc, fileName, radius, reducePoses) {
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
  const preview = el('p', { class: 'note', role: 'status' });
  const error = el('p', { class: 'note error', role: 'alert' });
  const ok = el('button', { type: 'submit', class: 'primary', value: 'ok' }, 'Import');
  const cancel = el('button', { type: 'button', value: 'cancel' }, 'Cancel');
  const choices = [
    radio('all', false), radio('every', true), radio('fit', false),
  ];
  const form = el('form', { method: 'dialog' },
    el('h2', { id: id('title') }, `${n} poses in ${fileName}`),
    el('p', {}, `That is more than ${MANY_POSES}: probably samples of a motion rather than control poses. `,
      'Smoothing every sample gives many more refined poses than needed. Import:'),
    el('div', { class: 'choice' }, choices[0], el('label', { htmlFor: id('all') }, `all ${n} poses`)),
    el('div', { class: 'choice' }, choices[1], el('label', { htmlFor: id('every') }, 'every k-th pose (an open motion keeps its last), k ='), every),
    el('div', { class: 'choice' }, choices[2],
      el('label', { htmlFor: id('fit') }, 'the fewest poses whose screw motions stay within'), tol,
      el('span', {}, `scene units of every pose (at points up to ${+radius.toFixed(3)} from the object's origin)`)),
    preview, error,
    el('div', { class: 'row' }, cancel, ok),
  );
  const dialog = el('dialog', { id: 'reduce-dialog', 'aria-labelledby': id('title') }, form);
  document.body.append(dialog);

  const how = () => choices.find((c) => c.checked).value;
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
      default: {
        const t = Number(tol.value);
        const d = reducePoses(doc, { tolerance: t, radius });
        return { doc: d, how: `kept ${d.poses.length} of ${n} poses (within ${t} scene units)` };
      }
    }
  };
  const refresh = () => {
    error.textContent = '';
    try {
      const r = reduce();
      preview.textContent = `→ ${r.doc.poses.length} control poses.`;
    } catch (e) {
      preview.textContent = '';
      error.textContent = e.message;
    }
  };
  for (const c of [...choices, every, tol]) c.addEventListener('input', refresh);
  // Typing into a number field chooses its option.
  every.addEventListener('focus', () => ((choices[1].checked = true), refresh()));
  tol.addEventListener('focus', () => ((choices[2].checked = true), refresh()));
  refresh();

  return new Promise((resolve) => {
    const done = (value) => {
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
    form.addEventListener('submit', (e) => {
      e.preventDefault();
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
