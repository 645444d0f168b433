// The lesson card (#lesson): its head (lesson title, step counter, close), the bar of step
// dots, the step's title and text with math, the stand-in for an unreachable highlighted control
// (highlight.js), the exercise box (filled by exercise.js) and the Back / Next buttons. Where it
// stands is the page's layout while a lesson is open (css/lessons.css): a column beside the
// 3-D view, or on phones upright a sheet below it.
import { renderText } from './format.js';
import { el } from '../dom.js';

/**
 * Creates the (hidden) lesson card. Returns its parts {card, scroll, proxy, lessonTitle, bar,
 * exercise, closeBtn, prevBtn, nextBtn}, fit() (compact or not, after a change of its content) and render(st, renderExercise), which shows step `st.step` of
 * `st.lesson` with `st.progress` and hands its exercise to `renderExercise`.
 */
export function createCard() {
  const card = el('aside');
  card.id = 'lesson';
  card.hidden = true;
  card.setAttribute('aria-label', 'Lesson');
  const head = el('div', { class: 'head' });
  const lessonTitle = el('span', { class: 'ltitle' });
  const counter = el('span', { class: 'count' });
  const closeBtn = el('button', { class: 'close' }, '×');
  closeBtn.title = 'Close the lesson (progress is kept)';
  closeBtn.setAttribute('aria-label', 'Close the lesson');
  head.append(lessonTitle, counter, closeBtn);
  const bar = el('div', { class: 'bar' });
  const stepTitle = el('h3');
  const body = el('div', { class: 'text' });
  const exercise = el('div', { class: 'exercise' });
  const nav = el('div', { class: 'nav' });
  const prevBtn = el('button', { class: 'prev' }, '◀ Back');
  const nextBtn = el('button', { class: 'next primary' }, 'Next ▶');
  nav.append(prevBtn, nextBtn);
  // Head, step title, the exercise's task, Check, Hint, feedback and Back / Next stay put; the
  // text scrolls between them (and, where the card is very short, the choices scroll inside the
  // exercise), so a student never scrolls to find the button the step asks for.
  const scroll = el('div', { class: 'scroll' });
  // Keyboard users scroll it too (a scrollable region must take the focus).
  scroll.tabIndex = 0;
  scroll.setAttribute('role', 'region');
  scroll.setAttribute('aria-label', 'Step text');
  scroll.append(body);
  // Where a step's highlighted control cannot be reached where it is (highlight.js), a button
  // standing in for it.
  const proxy = el('div', { class: 'proxy' });
  proxy.hidden = true;
  card.append(head, bar, stepTitle, scroll, proxy, exercise, nav);
  document.body.append(card);

  /**
   * Where the card's column or sheet is too short for all of it (a phone, a message above it),
   * it goes compact: the step dots and title fold away and the text keeps two lines, so that
   * the exercise's task, buttons and feedback stay whole.
   */
  function fit() {
    if (card.hidden) return;
    card.classList.remove('compact');
    const over = (e) => e.scrollHeight > e.clientHeight + 1;
    if (over(card) || (!exercise.hidden && over(exercise))) card.classList.add('compact');
  }
  // The card's size follows the window and the banner above it (css/lessons.css); fitted in
  // the next frame, after the layout that changed it.
  let pending = 0;
  new ResizeObserver(() => {
    cancelAnimationFrame(pending);
    pending = requestAnimationFrame(fit);
  }).observe(card, { box: 'border-box' });

  function render({ lesson, step, progress }, renderExercise) {
    const s = lesson.steps[step];
    const n = lesson.steps.length;
    counter.textContent = `${step + 1} / ${n}`;
    bar.replaceChildren(...lesson.steps.map((st, k) => {
      const d = el('i', { class: `${k === step ? 'on' : ''} ${progress.solved.includes(k) ? 'solved' : ''} ${st.exercise ? 'ex' : ''}`.trim() });
      d.title = st.title;
      return d;
    }));
    stepTitle.textContent = s.title;
    body.replaceChildren(renderText(s.text));
    exercise.replaceChildren();
    exercise.hidden = !s.exercise;
    if (s.exercise) renderExercise(s.exercise);
    prevBtn.disabled = step === 0;
    nextBtn.textContent = step === n - 1 ? 'Finish ✓' : 'Next ▶';
    card.classList.remove('summary');
    scroll.scrollTop = 0;
    fit();
  }

  /**
   * The end of a lesson: exercises solved of all, the unsolved ones to go back to (`goTo(k)`),
   * and what to try next (`next`: {title, summary, start()} or null). Next closes the lesson.
   */
  function renderSummary({ lesson, progress }, { next, goTo }) {
    const exercises = lesson.steps.map((s, k) => (s.exercise ? k : -1)).filter((k) => k >= 0);
    const solved = exercises.filter((k) => progress.solved.includes(k));
    counter.textContent = 'done';
    bar.replaceChildren(...lesson.steps.map((st, k) => {
      const d = el('i', { class: `${progress.solved.includes(k) ? 'solved' : ''} ${st.exercise ? 'ex' : ''}`.trim() });
      d.title = st.title;
      return d;
    }));
    stepTitle.textContent = 'Lesson complete';
    const parts = [];
    const score = el('p', { class: 'score' }, exercises.length ? `Exercises solved: ${solved.length} of ${exercises.length}.` : 'This lesson has no exercises.');
    parts.push(score);
    const open = exercises.filter((k) => !progress.solved.includes(k));
    if (open.length) {
      const list = el('ul', { class: 'unsolved' });
      for (const k of open) {
        const li = el('li');
        const b = el('button', { class: 'link' }, `Step ${k + 1}: ${lesson.steps[k].title}`);
        b.addEventListener('click', () => goTo(k));
        li.append(b);
        list.append(li);
      }
      parts.push(el('p', {}, 'Not solved yet:'), list);
    }
    if (next) {
      const p = el('p', { class: 'next-lesson' });
      const b = el('button', { class: 'primary start-next' }, `Start ${next.title}`);
      b.addEventListener('click', () => next.start());
      p.append(el('span', {}, `Try next: ${next.summary}. `), b);
      parts.push(p);
    } else parts.push(el('p', {}, 'That was the last lesson: the Lessons menu lists them all, and any step can be opened again from there.'));
    body.replaceChildren(...parts);
    exercise.replaceChildren();
    exercise.hidden = true;
    prevBtn.disabled = false;
    nextBtn.textContent = 'Close ✓';
    card.classList.add('summary');
    scroll.scrollTop = 0;
    fit();
    return { solved: solved.length, total: exercises.length };
  }

  return { card, scroll, proxy, lessonTitle, bar, exercise, closeBtn, prevBtn, nextBtn, render, renderSummary, fit };
}
