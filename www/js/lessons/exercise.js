// The exercise of a lesson step on the card: the task, the multiple choice, the Check and Hint
// buttons, the hints shown so far, and the feedback of a check (checks themselves: checks.js).
import { renderText } from './format.js';
import { evaluateExercise } from './checks.js';
import { writeProgress } from './progress.js';
import { loadSamples, loadedSamples, offerSamples } from './apply.js';
import { el } from '../dom.js';

/**
 * Creates the exercise part of the lesson card in `box`; `bar` is the card's step bar (its dot
 * of a solved step is marked). `st` is the player's state {lesson, step, answer, hintShown,
 * progress, analysis, emit}, read and updated here (a check is told to emit('check', …), player.js);
 * `fit` fits the card again when the box grows. Returns {render(x), choose(k), check()}.
 */
export function createExercise(app, box, bar, st, fit = () => {}) {
  /** Shows exercise `x` of the open step. */
  function render(x) {
    const solved = st.progress.solved.includes(st.step);
    const task = el('div', { class: 'task' });
    task.append(el('b', { class: 'label' }, solved ? 'Exercise ✓ solved' : 'Exercise'), renderText(x.task));
    box.append(task);
    // The choices and the hints shown scroll where the card is short; task, buttons and
    // feedback stay in view.
    const more = el('div', { class: 'ex-scroll' });
    if (x.choices) {
      const fs = el('div', { class: 'choices' });
      fs.setAttribute('role', 'radiogroup');
      fs.setAttribute('aria-label', 'Answers');
      x.choices.forEach((c, k) => {
        const label = el('label');
        const r = el('input');
        r.type = 'radio';
        r.name = 'lesson-choice';
        r.value = String(k);
        r.checked = st.answer === k;
        r.addEventListener('change', () => (st.answer = k));
        const span = el('span');
        span.append(renderText(c));
        label.append(r, span);
        fs.append(label);
      });
      more.append(fs);
    }
    more.append(el('div', { class: 'hints' }));
    const row = el('div', { class: 'row' });
    const checkBtn = el('button', { class: 'check primary' }, 'Check');
    checkBtn.addEventListener('click', () => check());
    row.append(checkBtn);
    // A step's measured poses: the import dialog again (it opened with the step).
    const s = st.lesson.steps[st.step];
    if (s.samples) {
      const again = el('button', { class: 'samples' }, 'Measured poses…');
      again.title = 'Open the import dialog on this step\'s measured poses again';
      again.addEventListener('click', () => offerSamples(app, s));
      row.append(again);
    }
    if (x.hints?.length) {
      const hintBtn = el('button', { class: 'hint' }, 'Hint');
      hintBtn.addEventListener('click', () => showHint(x));
      row.append(hintBtn);
    }
    // A live region: the result of each Check is read out as well as shown.
    const fb = Object.assign(el('div', { class: 'feedback' }), { role: 'status' });
    fb.setAttribute('aria-live', 'polite');
    fb.setAttribute('aria-atomic', 'true');
    box.append(more, row, fb);
    if (solved) setFeedback(true, [x.success ?? 'Solved earlier; check again any time.']);
  }

  function showHint(x) {
    const hints = box.querySelector('.hints');
    if (st.hintShown >= x.hints.length) return;
    const h = el('div', { class: 'hint-text' });
    h.append(el('b', {}, `Hint ${st.hintShown + 1}: `), renderText(x.hints[st.hintShown]));
    hints.append(h);
    st.hintShown++;
    fit();
    h.scrollIntoView({ block: 'nearest' });
  }

  function setFeedback(ok, lines, math = true) {
    const fb = box.querySelector('.feedback');
    fb.className = `feedback ${ok ? 'ok' : 'no'}`;
    fb.replaceChildren();
    for (const line of lines) {
      const d = el('div');
      // {math: text}: a lesson's own text (with math) among measured, plain lines.
      if (math || typeof line === 'object') d.append(renderText(line.math ?? line));
      else d.textContent = line;
      fb.append(d);
    }
    // A new result each time, even when it reads as the last one did.
    fb.classList.remove('again');
    void fb.offsetWidth;
    fb.classList.add('again');
    fb.scrollTop = 0;
    fit();
    fb.scrollIntoView({ block: 'nearest' });
  }

  /** Picks answer `k` of the step's multiple choice. */
  function choose(k) {
    st.answer = k;
    const r = box.querySelector(`input[value="${k}"]`);
    if (r) r.checked = true;
  }

  /** Runs the open step's checks (the Check button); saves a solved state and the answer. */
  function check() {
    const { lesson, step, progress } = st;
    const s = lesson?.steps[step];
    const x = s?.exercise;
    if (!x) return null;
    // A step's measured poses: samples.js, which the step fetched as it opened (a Check that
    // comes first runs once it is there).
    if (s.samples && !loadedSamples()) {
      loadSamples().then(() => check());
      return null;
    }
    const r = evaluateExercise(x, app.motion, st.answer, { samples: s.samples ? loadedSamples().stepSamples(s) : null, analysis: st.analysis });
    if (st.answer !== null) progress.answers[step] = st.answer;
    if (r.ok && !progress.solved.includes(step)) progress.solved.push(step);
    writeProgress(lesson.id, progress);
    st.emit?.('check', { step, ok: r.ok, answer: st.answer, results: r.results });
    if (r.ok) setFeedback(true, [x.success ?? 'Correct.']);
    else {
      // A wrong choice: why that answer is wrong (the lesson's explanation, with math), else
      // that it is not the right one; other checks: what they measured and what they want.
      const why = st.answer !== null ? x.why?.[st.answer] : null;
      const lines = r.results.filter((c) => !c.ok).map((c) => {
        if (c.kind === 'choice') return st.answer === null ? 'Choose an answer first.' : why ? { math: `Not this one: ${why}` } : `Not this one: answer ${st.answer + 1} is not the right one. Read the step again, or take a hint.`;
        return c.want ? `Not yet: ${c.got}; wanted ${c.want}.` : `Not yet: ${c.got}.`;
      });
      setFeedback(false, lines, false);
    }
    box.querySelector('.task .label').textContent = progress.solved.includes(step) ? 'Exercise ✓ solved' : 'Exercise';
    bar.children[step]?.classList.toggle('solved', progress.solved.includes(step));
    return r;
  }

  return { render, choose, check };
}
