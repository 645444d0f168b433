// The lesson's steps in the editor: one row each (its number and title; a click opens it in the
// step editor and shows its setup on the page), with Move up, Move down, Duplicate and Delete,
// and "Add a step from the page now", which takes the page's setup (capture.js) in one action.
import { button, el } from '../../dom.js';
import { capture } from './capture.js';

/** Moves item `from` of `list` to `to`. */
const move = (list, from, to) => list.splice(to, 0, ...list.splice(from, 1));

/**
 * The step list of the editor.
 * @param {any} ed the editor (panel.js)
 */
export function stepList(ed) {
  const box = el('section', { class: 'le-steps' });
  box.append(el('h3', {}, 'Steps'));
  const list = el('ol');
  const steps = ed.doc.steps;
  steps.forEach((s, i) => {
    const li = el('li', { class: i === ed.step ? 'on' : '' });
    li.dataset.path = `steps[${i}]`;
    const open = button(`${i + 1}. ${s.title || '(no title)'}${s.exercise ? ' ✎' : ''}`, '', () => ed.select(i, true), 'le-step');
    open.setAttribute('aria-current', i === ed.step ? 'step' : 'false');
    const n = steps.length;
    const up = button('↑', `Move step ${i + 1} up`, () => ed.edit(`Move step ${i + 1} up`, (d) => move(d.steps, i, i - 1), { step: i - 1 }));
    up.disabled = i === 0;
    const down = button('↓', `Move step ${i + 1} down`, () => ed.edit(`Move step ${i + 1} down`, (d) => move(d.steps, i, i + 1), { step: i + 1 }));
    down.disabled = i === n - 1;
    const dup = button('Copy', `Duplicate step ${i + 1}`, () => ed.edit(`Duplicate step ${i + 1}`, (d) => d.steps.splice(i + 1, 0, structuredClone(d.steps[i])), { step: i + 1 }));
    const del = button('✕', `Delete step ${i + 1}`, () => ed.edit(`Delete step ${i + 1}`, (d) => d.steps.splice(i, 1), { step: Math.min(i, n - 2) }), 'le-del');
    li.append(open, up, down, dup, del);
    list.append(li);
  });
  box.append(list);
  const add = button('Add a step from the page now', 'A new step after this one, set up as the page is now: motion, options, display, timing, view, selection', () => {
    const at = ed.step + 1;
    ed.edit('Add a step from the page', (d) => d.steps.splice(at, 0, { title: `Step ${d.steps.length + 1}`, text: '', ...capture(ed.app) }), { step: at });
  }, 'primary');
  add.id = 'le-add-step';
  box.append(add);
  return box;
}
