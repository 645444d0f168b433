// The lesson card (#lesson): its head (lesson title, step counter, close), the bar of step
// dots, the step's title and text with math, the exercise box (filled by exercise.js) and the
// Back / Next buttons.
import { renderText } from './format.js';
import { el } from './dom.js';

/**
 * Creates the (hidden) lesson card. Returns its parts {card, lessonTitle, bar, exercise,
 * closeBtn, prevBtn, nextBtn} and render(st, renderExercise), which shows step `st.step` of
 * `st.lesson` with `st.progress` and hands its exercise to `renderExercise`.
 */
export function createCard() {
  const card = el('aside');
  card.id = 'lesson';
  card.hidden = true;
  card.setAttribute('aria-label', 'Lesson');
  const head = el('div', 'head');
  const lessonTitle = el('span', 'ltitle');
  const counter = el('span', 'count');
  const closeBtn = el('button', 'close', '×');
  closeBtn.title = 'Close the lesson (progress is kept)';
  closeBtn.setAttribute('aria-label', 'Close the lesson');
  head.append(lessonTitle, counter, closeBtn);
  const bar = el('div', 'bar');
  const stepTitle = el('h3');
  const body = el('div', 'text');
  const exercise = el('div', 'exercise');
  const nav = el('div', 'nav');
  const prevBtn = el('button', 'prev', '◀ Back');
  const nextBtn = el('button', 'next primary', 'Next ▶');
  nav.append(prevBtn, nextBtn);
  card.append(head, bar, stepTitle, body, exercise, nav);
  document.body.append(card);

  function render({ lesson, step, progress }, renderExercise) {
    const s = lesson.steps[step];
    const n = lesson.steps.length;
    counter.textContent = `${step + 1} / ${n}`;
    bar.replaceChildren(...lesson.steps.map((st, k) => {
      const d = el('i', `${k === step ? 'on' : ''} ${progress.solved.includes(k) ? 'solved' : ''} ${st.exercise ? 'ex' : ''}`.trim());
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
    card.scrollTop = 0;
  }

  return { card, lessonTitle, bar, exercise, closeBtn, prevBtn, nextBtn, render };
}
