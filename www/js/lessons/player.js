// The lesson player: opens a lesson by URL (?lesson=…), by name, file or paste, steps through
// it and closes it, and starts the short first-visit tour (www/lessons/tour.json). Lesson files:
// www/lessons/README.md. Its parts: the card (card.js) with its exercise (exercise.js, checks in
// checks.js), what a step does to the app (apply.js), the highlight ring (highlight.js), the
// Lessons button and menu (menu.js), saved progress (progress.js), lesson URLs (urls.js).
//
// startLessons(app) returns the player; main.js exposes it as window.screwbender.lessons:
//   ready: Promise               settles once ?lesson= or the first-visit tour has been handled
//   open(name, {resume, progress, seed}): Promise<boolean>   loads lesson <name>: an id of lessons/index.json (`screw`),
//                                a file name (`01-screw`, `01-screw.json`); false: a banner says why
//   openText(text, source, {resume, progress, seed}): boolean   the same from a file's text (pasted,
//                                dropped); `progress` (progress.js) replaces the saved progress;
//                                `seed` picks the variant of randomised steps (else the page's
//                                ?seed=, else the one kept in the progress, else a new one, kept)
//   openMenu()                   shows the Lessons menu
//   lesson, step                 the open lesson object and step index (null / -1 when closed);
//                                a randomised lesson's steps are the student's variant
//   variant                      of a randomised lesson: {seed, values} (format.js lessonVariant;
//                                values[i] the parameters of step i, or null); else null
//   go(i), next(), prev(), close()  (next() after the last step shows the summary; once more closes)
//   summary                      {solved, total} while the summary shows, else null
//   choose(k)                    picks answer k of the step's multiple choice
//   check(): {ok, results}       runs the step's checks as the Check button does
//   progress(id)                 the saved progress of lesson `id`
//   spot(): {x, y, w, h} | null  where the highlight ring is (page px)
//   events: EventTarget          what the learner does, for a host that records it (lms.js via
//                                launch.js); each a CustomEvent whose detail has the lesson's `id`
//                                and its `progress` ({step, solved, answers}, progress.js):
//     'open'    a lesson was opened
//     'step'    step `step` is shown
//     'check'   the exercise of step `step` was checked: `ok`, `answer` (the chosen answer or
//               null), `results` (checks.js)
//     'finish'  the summary after the last step is shown: `solved`, `total`
import { VIEW_IDS } from '../dock/index.js';
import { hasParams, lessonVariant, parseLesson } from './format.js';
import { isSeed, newSeed } from './variants.js';
import { readProgress, writeProgress, markTourSeen, tourSeen } from './progress.js';
import { BASE, lessonUrl, resolveLessonName } from './urls.js';
import { applyStep, loadSamples } from './apply.js';
import { createCard } from './card.js';
import { createExercise } from './exercise.js';
import { createHighlight } from './highlight.js';
import { createMenu } from './menu.js';
import { foldPanelOnSmallScreens } from '../editor/fold.js';

export { lessonUrl };

/** Creates the lesson player of `app` (once the app has started). */
export function startLessons(app) {
  const panelNames = () => app.ui.gui.controllersRecursive().map((c) => c._name);
  const ctx = {
    scenes: app.scenes.map((s) => s.id),
    views: VIEW_IDS,
    panel: panelNames(),
    checkMotion: (doc) => new app.wasm.Motion(doc).free(),
  };

  // The open lesson, its step, the step's chosen answer and hints shown, and its saved progress.
  const st = { lesson: null, step: -1, answer: null, hintShown: 0, progress: null, variant: null, analysis: null, emit };
  const events = new EventTarget();
  /** Tells listeners of player.events about `type` (see the file's head). */
  function emit(type, detail = {}) {
    events.dispatchEvent(new CustomEvent(type, { detail: { id: st.lesson?.id, progress: st.progress, ...detail } }));
  }
  const card = createCard();
  const exercise = createExercise(app, card.exercise, card.bar, st, card.fit);
  const highlight = createHighlight(app, card);
  const menu = createMenu(app, { open, openText, current: () => st.lesson?.id ?? null });

  const player = {
    get lesson() {
      return st.lesson;
    },
    get step() {
      return st.step;
    },
    /** The open lesson's variant, {seed, values}, or null (no lesson, or no randomised step). */
    get variant() {
      return st.variant;
    },
    /** After the last step: {solved, total} of the summary shown, else null. */
    get summary() {
      return st.summary ?? null;
    },
    open,
    openText,
    go,
    next: () => go(st.step + 1),
    prev: () => go(st.step - 1),
    close,
    choose: exercise.choose,
    check: exercise.check,
    progress: readProgress,
    spot: highlight.spot,
    /** Where the card is placed: {x, y, w, h} (page px) or null. */
    box: highlight.box,
    openMenu: menu.open,
    events,
  };

  /**
   * Shows a lesson's error in the banner (above the Lessons menu); the next lesson or step that
   * opens without one takes it away.
   */
  const lessonError = (message) => app.parts.notices.show(message, 'error', 'lesson');

  /** Opens lesson `name`: an id of lessons/index.json or a file (see lessonUrl); false (and a banner) if it cannot. */
  async function open(name, { resume = true, progress = null, seed = null } = {}) {
    const url = lessonUrl(await resolveLessonName(name));
    if (!url) {
      lessonError(`Lesson "${name}": only files under lessons/ on this site can be opened by name. Nothing was changed.`);
      return false;
    }
    let text;
    try {
      const r = await fetch(url, { cache: 'no-store' });
      if (!r.ok) throw new Error(`HTTP ${r.status}`);
      text = await r.text();
    } catch (e) {
      lessonError(`Lesson ${url.pathname.split('/').pop()}: could not load it (${e.message}). Nothing was changed.`);
      return false;
    }
    if (!openText(text, url.pathname.split('/').pop(), { resume, progress, seed })) return false;
    if (st.lesson.steps.some((s) => s.samples)) await loadSamples().catch(() => {});
    // A `metric` or `residuals` check measures in the analysis module: fetched now, before the
    // first Check.
    if (measures(st.lesson)) await analysis().catch((e) => app.parts.notices.show(`${e.message}: this lesson's checks cannot measure the motion.`));
    return true;
  }

  /**
   * True when `lesson` needs the analysis module: a check measures with it (Motion.motionMetrics,
   * measureFit) or a step's measured poses may be fitted (fitPoses).
   */
  function measures(lesson) {
    return lesson.steps.some((s) => s.samples || s.exercise?.checks.some((c) => c.kind === 'metric' || c.kind === 'residuals'));
  }

  /** Loads the analysis module and keeps it for the checks (st.analysis). */
  function analysis() {
    return app.analysis().then((m) => (st.analysis = m));
  }

  /** Opens a lesson from its text; `source` names it in messages. */
  function openText(text, source = 'lesson', { resume = true, progress = null, seed = null } = {}) {
    let parsed;
    try {
      parsed = parseLesson(text, ctx);
    } catch (e) {
      lessonError(`Lesson ${source}: ${e.message}. Nothing was changed.`);
      return false;
    }
    app.parts.notices.clear('lesson');
    menu.hide();
    st.progress = progress ?? readProgress(parsed.id);
    st.variant = null;
    st.lesson = parsed;
    if (hasParams(parsed)) {
      // The variant's seed: the caller's, a teacher's ?seed= preview (not kept), the student's
      // own (kept with the progress: the same numbers after a reload), or a new one, kept.
      let s = isSeed(seed) ? seed : urlSeed;
      if (s === null) {
        if (!isSeed(st.progress.seed)) {
          st.progress.seed = newSeed();
          writeProgress(parsed.id, st.progress);
        }
        s = st.progress.seed;
      }
      const v = lessonVariant(parsed, s);
      st.lesson = v.lesson;
      st.variant = { seed: s, values: v.values };
    }
    const opening = card.card.hidden;
    card.card.hidden = false;
    document.body.classList.add('lesson-open');
    if (opening) relayout();
    card.card.classList.toggle('tour', !!st.lesson.tour);
    card.lessonTitle.textContent = st.lesson.title;
    emit('open');
    // A lesson with measured poses: their code fetched now (open() waits for it), so that a
    // step opens its import dialog as it applies and a Check finds them.
    if (st.lesson.steps.some((s) => s.samples)) loadSamples().catch(() => {});
    go(resume ? Math.min(st.progress.step, st.lesson.steps.length - 1) : 0);
    if (measures(st.lesson)) analysis().catch(() => {});
    return true;
  }

  /** The lesson after the open one in lessons/index.json: {title, summary, start()} or null. */
  async function nextLesson() {
    try {
      const r = await fetch(new URL('index.json', BASE), { cache: 'no-store' });
      const list = (await r.json()).lessons ?? [];
      const k = list.findIndex((l) => l.id === st.lesson?.id);
      const n = k >= 0 ? list[k + 1] : null;
      return n ? { title: n.title, summary: n.summary, start: () => open(n.file, { resume: false }) } : null;
    } catch {
      return null;
    }
  }

  /** After the last step: the summary (a tour just closes); Next on it closes the lesson. */
  async function finish() {
    if (st.lesson.tour) return close();
    st.step = st.lesson.steps.length;
    highlight.set(null);
    const lesson = st.lesson;
    const next = await nextLesson();
    if (st.lesson !== lesson) return;
    st.summary = card.renderSummary(st, { next, goTo: go });
    emit('finish', { ...st.summary });
    card.card.dataset.step = 'summary';
    highlight.place();
  }

  /** Applies step `i`'s scene, options, display, timing, dock and highlight, and shows it. */
  function go(i) {
    if (!st.lesson) return;
    if (i > st.lesson.steps.length) return close();
    if (i === st.lesson.steps.length) return finish();
    if (i < 0) return;
    st.summary = null;
    st.step = i;
    st.answer = st.progress.answers[i] ?? null;
    st.hintShown = 0;
    st.progress.step = i;
    writeProgress(st.lesson.id, st.progress);
    const s = st.lesson.steps[i];
    try {
      applyStep(app, s, highlight.set);
      app.parts.notices.clear('lesson');
    } catch (e) {
      lessonError(`Lesson step ${i + 1}: ${e.message}`);
    }
    card.render(st, exercise.render);
    card.card.dataset.step = String(i);
    emit('step', { step: i });
    // The card's size is the new step's now: place it (and the ring) again.
    highlight.place();
  }

  function close() {
    if (st.lesson?.tour) {
      markTourSeen();
      // Phones: the tour opened the panel to point into it; the 3-D view is what comes next.
      foldPanelOnSmallScreens(app);
    }
    st.lesson = null;
    st.variant = null;
    st.step = -1;
    const closing = !card.card.hidden;
    card.card.hidden = true;
    document.body.classList.remove('lesson-open');
    highlight.set(null);
    if (closing) relayout();
  }

  /**
   * The card took its place in the page's layout, or gave it back (css/lessons.css): the 3-D
   * view and the dock resize (app 'layout'), and the scene is framed in what they leave.
   */
  function relayout() {
    app.viewer.invalidateSize();
    app.emit('layout');
    requestAnimationFrame(() => {
      app.viewer.invalidateSize();
      app.parts.viewpoint.fit();
      highlight.place();
    });
  }

  // While a lesson is open the banner shows at the top of the card's column (css/lessons.css),
  // which makes room for it: its height, kept in --banner-h.
  const banner = document.getElementById('banner');
  if (banner) {
    new ResizeObserver(() => {
      const h = banner.hidden ? 0 : Math.ceil(banner.getBoundingClientRect().height);
      // In the next frame: the card's size changes with it, and the card fits itself then.
      requestAnimationFrame(() => {
        document.body.style.setProperty('--banner-h', `${h}px`);
        card.fit();
      });
    }).observe(banner);
  }

  card.closeBtn.addEventListener('click', close);
  card.prevBtn.addEventListener('click', () => go(st.step - 1));
  card.nextBtn.addEventListener('click', () => go(st.step + 1));

  const params = new URLSearchParams(location.search);
  // ?seed=N: every randomised lesson of this page shows variant N (a teacher's preview).
  let urlSeed = null;
  if (params.has('seed')) {
    const n = Number(params.get('seed'));
    if (params.get('seed') !== '' && isSeed(n)) urlSeed = n;
    else app.parts.notices.show(`?seed=${params.get('seed')}: expected a whole number from 0 to 4294967295; lessons pick their variants as usual.`, 'warn');
  }
  player.ready = (async () => {
    if (params.has('lesson')) return open(params.get('lesson'));
    const seen = tourSeen();
    // First visit: the tour. Automated browsers (navigator.webdriver) only get it with ?tour=1,
    // so scripted pages start as they always did.
    const force = params.get('tour') === '1';
    if (force || (!seen && !navigator.webdriver && params.get('tour') !== '0')) {
      markTourSeen();
      return open('tour', { resume: false });
    }
    return false;
  })();
  return player;
}
