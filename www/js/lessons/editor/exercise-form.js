// A step's exercise in the editor, built from forms: the task, a multiple-choice question (each
// answer with an optional `why`, the right one picked by its radio button, which writes the
// exercise's `choice` check), the checks (check-form.js), the hints and the success text.
import { button, el } from '../../dom.js';
import { checksForm } from './check-form.js';
import { textField } from './text-field.js';

/** The index of the exercise's `choice` check, or -1. */
const choiceCheck = (x) => (x.checks ?? []).findIndex((c) => c.kind === 'choice');

/**
 * The multiple-choice part of exercise `x` of step `i`.
 * @param {any} ed the editor (panel.js)
 */
function choicesForm(ed, i, x) {
  const box = el('div', { class: 'le-choices' });
  const base = `steps[${i}].exercise.choices`;
  box.dataset.path = base;
  box.append(el('h4', {}, 'Multiple choice'));
  const k0 = choiceCheck(x);
  const right = k0 >= 0 ? x.checks[k0].answer : -1;
  (x.choices ?? []).forEach((c, k) => {
    const row = el('div', { class: 'le-choice' });
    const r = el('input');
    r.type = 'radio';
    r.name = `le-right-${i}`;
    r.checked = k === right;
    r.title = 'The right answer';
    r.setAttribute('aria-label', `Answer ${k + 1} is the right one`);
    r.addEventListener('change', () =>
      ed.edit(`Make answer ${k + 1} the right one`, (d) => {
        const ex = d.steps[i].exercise;
        const at = choiceCheck(ex);
        if (at >= 0) ex.checks[at].answer = k;
        else ex.checks = [...(ex.checks ?? []), { kind: 'choice', answer: k }];
      }),
    );
    const text = typeof c === 'string' ? c : c.text;
    const why = typeof c === 'string' ? '' : c.why ?? '';
    const setChoice = (key) => (v) =>
      ed.edit(`Edit answer ${k + 1}`, (d) => {
        const list = d.steps[i].exercise.choices;
        const cur = typeof list[k] === 'string' ? { text: list[k] } : { ...list[k] };
        cur[key] = v;
        if (key === 'why' && v.trim() === '') delete cur.why;
        list[k] = cur;
      }, { merge: `choice:${i}:${k}:${key}`, rerender: false });
    const fields = el('div', { class: 'le-choice-fields' });
    fields.append(
      textField(`Answer ${k + 1}`, `${base}[${k}]${typeof c === 'string' ? '' : '.text'}`, text, setChoice('text'), { rows: 1, preview: false }),
      textField('Why (shown when this answer is checked)', `${base}[${k}].why`, why, setChoice('why'), { rows: 1, preview: false }),
    );
    const del = button('✕', `Delete answer ${k + 1}`, () =>
      ed.edit(`Delete answer ${k + 1}`, (d) => {
        const ex = d.steps[i].exercise;
        ex.choices.splice(k, 1);
        const at = choiceCheck(ex);
        if (at >= 0 && ex.checks[at].answer === k) ex.checks.splice(at, 1);
        else if (at >= 0 && ex.checks[at].answer > k) ex.checks[at].answer--;
        if (!ex.choices.length) delete ex.choices;
      }), 'le-del');
    row.append(r, fields, del);
    box.append(row);
  });
  box.append(button('Add an answer', '', () =>
    ed.edit('Add an answer', (d) => {
      const ex = d.steps[i].exercise;
      ex.choices = [...(ex.choices ?? []), { text: '' }];
    }), 'le-add-choice'));
  return box;
}

/**
 * The exercise part of step `i`: "Add an exercise" where it has none.
 * @param {any} ed the editor (panel.js)
 */
export function exerciseForm(ed, i) {
  const box = el('section', { class: 'le-exercise' });
  const s = ed.doc.steps[i];
  box.dataset.path = `steps[${i}].exercise`;
  if (!s.exercise) {
    box.append(button('Add an exercise', '', () => ed.edit('Add an exercise', (d) => (d.steps[i].exercise = { task: '', checks: [] })), 'le-add-exercise'));
    return box;
  }
  const x = s.exercise;
  const p = `steps[${i}].exercise`;
  const head = el('div', { class: 'le-row' });
  head.append(el('h3', {}, 'Exercise'), button('Remove the exercise', '', () => ed.edit('Remove the exercise', (d) => delete d.steps[i].exercise), 'le-remove-exercise'));
  box.append(head);
  box.append(textField('Task', `${p}.task`, x.task, (v) => ed.edit('Edit the task', (d) => (d.steps[i].exercise.task = v), { merge: `task:${i}`, rerender: false }), { rows: 2 }));
  box.append(choicesForm(ed, i, x));
  box.append(checksForm(ed, i));
  const hints = el('div', { class: 'le-hints' });
  hints.dataset.path = `${p}.hints`;
  hints.append(el('h4', {}, 'Hints (one per click on Hint)'));
  (x.hints ?? []).forEach((h, k) => {
    const row = el('div', { class: 'le-row' });
    row.append(
      textField(`Hint ${k + 1}`, `${p}.hints[${k}]`, h, (v) => ed.edit(`Edit hint ${k + 1}`, (d) => (d.steps[i].exercise.hints[k] = v), { merge: `hint:${i}:${k}`, rerender: false }), { rows: 2 }),
      button('✕', `Delete hint ${k + 1}`, () =>
        ed.edit(`Delete hint ${k + 1}`, (d) => {
          d.steps[i].exercise.hints.splice(k, 1);
          if (!d.steps[i].exercise.hints.length) delete d.steps[i].exercise.hints;
        }), 'le-del'),
    );
    hints.append(row);
  });
  hints.append(button('Add a hint', '', () => ed.edit('Add a hint', (d) => (d.steps[i].exercise.hints = [...(d.steps[i].exercise.hints ?? []), '']))));
  box.append(hints);
  box.append(textField('Success text (shown when solved)', `${p}.success`, x.success ?? '', (v) =>
    ed.edit('Edit the success text', (d) => {
      if (v.trim() === '') delete d.steps[i].exercise.success;
      else d.steps[i].exercise.success = v;
    }, { merge: `success:${i}`, rerender: false }), { rows: 2 }));
  return box;
}
