// The problem list of the lesson editor: every problem of the lesson being written, each naming
// its step and field, a click jumping to the field. The problems come from the lesson format's
// validator (format.js lessonProblems).
import * as format from '../format.js';
import { el } from '../../dom.js';

/**
 * One problem of a lesson: `path` as in `steps[2].exercise.checks[0].max`, `step` its step
 * index (null for the lesson's own fields), `field` the last part of the path.
 * @typedef {{path: string, step: number | null, field: string, message: string}} Problem
 */

/**
 * Every problem of `lesson` (in file form) against the page's `ctx` (format.js parseLesson).
 * The lesson is not changed (the validator writes parsed fields into what it checks: it gets a
 * copy).
 * @returns {Problem[]}
 */
export function problemsOf(lesson, ctx) {
  return format.lessonProblems(structuredClone(lesson), ctx);
}

/**
 * Fills the list `box` with `problems`; a click on one calls `jump(problem)`.
 * @param {HTMLElement} box
 * @param {Problem[]} problems
 * @param {(p: Problem) => void} jump
 */
export function renderProblems(box, problems, jump) {
  box.replaceChildren();
  box.classList.toggle('ok', problems.length === 0);
  const head = el('h3', {}, problems.length ? `${problems.length} problem${problems.length > 1 ? 's' : ''}` : 'No problems: the lesson is ready');
  box.append(head);
  if (!problems.length) return;
  const list = el('ul');
  for (const p of problems) {
    const b = el('button', { class: 'le-problem' });
    b.type = 'button';
    b.dataset.problem = p.path;
    b.append(el('b', {}, p.step === null ? 'Lesson' : `Step ${p.step + 1}`), ` · ${p.field || 'file'}: ${p.message}`);
    b.addEventListener('click', () => jump(p));
    const li = el('li');
    li.append(b);
    list.append(li);
  }
  box.append(list);
}
