// The selected step in the editor: its title, its text (with the live preview), its setup (taken
// from the page, shown on the page again on request), its highlight (picked on the page,
// pick.js) and its exercise (exercise-form.js).
import { el } from '../../dom.js';
import { capture, describeSetup, SETUP_KEYS } from './capture.js';
import { exerciseForm } from './exercise-form.js';
import { pickTarget } from './pick.js';
import { textField } from './text-field.js';

/** A highlight in words. */
const highlightWords = (h) => (!h ? 'none' : h.pose !== undefined ? `pose ${h.pose}'s handle` : h.gizmo ? `the gizmo's ${h.gizmo}` : h.panel ? `the panel's ${h.panel}` : h.control ? `the control ${h.control}` : JSON.stringify(h));

/**
 * The form of step `i`.
 * @param {any} ed the editor (panel.js)
 */
export function stepForm(ed, i) {
  const s = ed.doc.steps[i];
  const p = `steps[${i}]`;
  const box = el('section', { class: 'le-step-form' });
  box.append(el('h3', {}, `Step ${i + 1}`));
  box.append(textField('Title', `${p}.title`, s.title, (v) => ed.edit('Edit the step title', (d) => (d.steps[i].title = v), { merge: `title:${i}`, rerender: 'list' }), { rows: 1, preview: false }));
  box.append(textField('Text ($…$ for math, **bold**, *italic*; a blank line starts a paragraph)', `${p}.text`, s.text, (v) => ed.edit('Edit the step text', (d) => (d.steps[i].text = v), { merge: `text:${i}`, rerender: false }), { rows: 5 }));

  const setup = el('div', { class: 'le-setup' });
  setup.dataset.path = `${p}.document`;
  const show = el('button', {}, 'Show on the page');
  show.type = 'button';
  show.addEventListener('click', () => ed.showStep(i));
  const retake = el('button', {}, 'Take from the page now');
  retake.type = 'button';
  retake.id = 'le-retake';
  retake.addEventListener('click', () =>
    ed.edit(`Take step ${i + 1}'s setup from the page`, (d) => {
      for (const k of SETUP_KEYS) delete d.steps[i][k];
      Object.assign(d.steps[i], capture(ed.app));
    }),
  );
  setup.append(el('span', {}, `Setup: ${describeSetup(s)}`), show, retake);
  box.append(setup);

  const hl = el('div', { class: 'le-highlight' });
  hl.dataset.path = `${p}.highlight`;
  const pick = el('button', {}, 'Pick on the page');
  pick.type = 'button';
  pick.id = 'le-pick';
  pick.title = 'Then click the control, the pose or the gizmo part the step points at (Esc cancels)';
  pick.addEventListener('click', () => {
    pick.textContent = 'Click what to point at… (Esc cancels)';
    pick.classList.add('armed');
    pickTarget(ed.app, ed.element, (target) => {
      pick.classList.remove('armed');
      pick.textContent = 'Pick on the page';
      if (!target) return ed.say('Nothing picked: the highlight is as it was.');
      ed.edit(`Point step ${i + 1} at ${highlightWords(target)}`, (d) => (d.steps[i].highlight = target));
    });
  });
  const none = el('button', {}, 'No highlight');
  none.type = 'button';
  none.disabled = !s.highlight;
  none.addEventListener('click', () => ed.edit(`Remove step ${i + 1}'s highlight`, (d) => delete d.steps[i].highlight));
  hl.append(el('span', { class: 'le-hl-now' }, `Highlight: ${highlightWords(s.highlight)}`), pick, none);
  box.append(hl);
  box.append(exerciseForm(ed, i));
  return box;
}
