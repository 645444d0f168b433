// The lesson player: the Lessons button and menu, the lesson card (text with math, exercise,
// feedback, hints, previous/next), the highlight ring that points at a control or a 3-D object,
// progress per lesson in localStorage, opening by URL (?lesson=…), by file or by paste, and the
// short first-visit tour (www/lessons/tour.json). Lesson files: www/lessons/README.md.
//
// startLessons(app) returns the player; main.js exposes it as window.screwbender.lessons:
//   ready: Promise               settles once ?lesson= or the first-visit tour has been handled
//   open(name, {resume}): Promise<boolean>   loads lessons/<name>.json (false: a banner says why)
//   openText(text, source, {resume}): boolean   the same from a file's text (pasted, dropped)
//   openMenu()                   shows the Lessons menu
//   lesson, step                 the open lesson object and step index (null / -1 when closed)
//   go(i), next(), prev(), close()
//   choose(k)                    picks answer k of the step's multiple choice
//   check(): {ok, results}       runs the step's checks as the Check button does
//   progress(id)                 the saved progress of lesson `id`
//   spot(): {x, y, w, h} | null  where the highlight ring is (page px)
import * as wasm from '../../pkg/screwbender.js';
import { VIEWS } from '../views/index.js';
import { parseLesson, renderText, MAX_LESSON_BYTES } from './format.js';
import { evaluateExercise } from './checks.js';

const PROGRESS_PREFIX = 'screwbender.lesson.';
const TOUR_SEEN_KEY = 'screwbender.tour.seen';
const BASE = new URL('../../lessons/', import.meta.url);

const el = (tag, cls, text) => {
  const e = document.createElement(tag);
  if (cls) e.className = cls;
  if (text !== undefined) e.textContent = text;
  return e;
};

function readProgress(id) {
  try {
    const p = JSON.parse(localStorage.getItem(PROGRESS_PREFIX + id) ?? 'null');
    if (p && typeof p === 'object') return { step: Number.isInteger(p.step) ? p.step : 0, solved: Array.isArray(p.solved) ? p.solved : [], answers: p.answers ?? {} };
  } catch {
    // A broken entry counts as no progress.
  }
  return { step: 0, solved: [], answers: {} };
}

function writeProgress(id, p) {
  try {
    localStorage.setItem(PROGRESS_PREFIX + id, JSON.stringify(p));
  } catch {
    // Storage full or disabled: progress is kept for this page only.
  }
}

/**
 * The URL of lesson `name` (`?lesson=` value): a bare name means lessons/<name>.json; any other
 * value must resolve to a same-origin file under lessons/. Returns null if it does not.
 */
export function lessonUrl(name) {
  if (typeof name !== 'string' || name === '') return null;
  const file = /^[\w-]+$/.test(name) ? `${name}.json` : name;
  let url;
  try {
    url = new URL(file, /^[\w-]+(\.json)?$/.test(file) ? BASE : location.href);
  } catch {
    return null;
  }
  if (url.origin !== location.origin || !url.pathname.startsWith(BASE.pathname) || !url.pathname.endsWith('.json')) return null;
  return url;
}

/** Creates the lesson player of `app` (once the app has started). */
export function startLessons(app) {
  const $ = (id) => document.getElementById(id);
  const panelNames = () => app.ui.gui.controllersRecursive().map((c) => c._name);
  const ctx = {
    scenes: app.scenes.map((s) => s.id),
    views: VIEWS.map((v) => v.id),
    panel: panelNames(),
    checkMotion: (doc) => new wasm.Motion(doc).free(),
  };

  // ---------------------------------------------------------------- DOM
  const button = el('button');
  button.id = 't-lessons';
  button.title = 'Lessons and the tour (L)';
  button.append(el('b', 'icon', '∑'), el('span', '', 'Lessons'));
  $('toolbar').append(button);

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

  const spotEl = el('div');
  spotEl.id = 'lesson-spot';
  spotEl.hidden = true;
  document.body.append(spotEl);

  const menu = el('div', 'modal');
  menu.id = 'lessons-menu';
  menu.hidden = true;
  const mcard = el('div', 'card');
  const list = el('div', 'lesson-list');
  const paste = el('textarea');
  paste.rows = 5;
  paste.spellcheck = false;
  paste.placeholder = 'Paste a lesson file (JSON) here, or drop one on this window, or choose one:';
  const fileInput = el('input');
  fileInput.type = 'file';
  fileInput.accept = '.json,application/json';
  fileInput.hidden = true;
  const mrow = el('div', 'row');
  const chooseBtn = el('button', '', 'Open a lesson file…');
  const pasteBtn = el('button', 'primary', 'Open pasted lesson');
  const mclose = el('button', '', 'Close');
  mrow.append(chooseBtn, pasteBtn, mclose);
  const mnote = el('p', 'small');
  mnote.append('A lesson is a JSON file (format: ', Object.assign(el('a', '', 'lessons/README.md'), { href: new URL('README.md', BASE).href, target: '_blank' }), '); a link with ', el('code', '', '?lesson=name'), ' opens lessons/name.json.');
  mcard.append(el('h2', '', 'Lessons'), list, paste, mrow, mnote, fileInput);
  menu.append(mcard);
  document.body.append(menu);

  // ---------------------------------------------------------------- state
  let lesson = null;
  let step = -1;
  let answer = null;
  let hintShown = 0;
  let progress = null;
  let target = null;
  let raf = 0;
  let index = null;

  const player = {
    get lesson() {
      return lesson;
    },
    get step() {
      return step;
    },
    open,
    openText,
    go,
    next: () => go(step + 1),
    prev: () => go(step - 1),
    close,
    choose(k) {
      answer = k;
      const r = exercise.querySelector(`input[value="${k}"]`);
      if (r) r.checked = true;
    },
    check,
    progress: readProgress,
    spot() {
      if (spotEl.hidden) return null;
      const r = spotEl.getBoundingClientRect();
      return { x: r.left, y: r.top, w: r.width, h: r.height };
    },
    openMenu,
  };

  // ---------------------------------------------------------------- loading

  /** Opens lesson `name` (see lessonUrl); false (and a banner) if it cannot. */
  async function open(name, { resume = true } = {}) {
    const url = lessonUrl(name);
    if (!url) {
      app.showError(`Lesson "${name}": only files under lessons/ on this site can be opened by name. Nothing was changed.`);
      return false;
    }
    let text;
    try {
      const r = await fetch(url, { cache: 'no-store' });
      if (!r.ok) throw new Error(`HTTP ${r.status}`);
      text = await r.text();
    } catch (e) {
      app.showError(`Lesson ${url.pathname.split('/').pop()}: could not load it (${e.message}). Nothing was changed.`);
      return false;
    }
    return openText(text, url.pathname.split('/').pop(), { resume });
  }

  /** Opens a lesson from its text; `source` names it in messages. */
  function openText(text, source = 'lesson', { resume = true } = {}) {
    let parsed;
    try {
      parsed = parseLesson(text, ctx);
    } catch (e) {
      app.showError(`Lesson ${source}: ${e.message}. Nothing was changed.`);
      return false;
    }
    menu.hidden = true;
    lesson = parsed;
    progress = readProgress(lesson.id);
    card.hidden = false;
    document.body.classList.add('lesson-open');
    card.classList.toggle('tour', !!lesson.tour);
    lessonTitle.textContent = lesson.title;
    go(resume ? Math.min(progress.step, lesson.steps.length - 1) : 0);
    return true;
  }

  // ---------------------------------------------------------------- steps

  /** Applies step `i`'s scene, options, display, timing, dock and highlight, and shows it. */
  function go(i) {
    if (!lesson) return;
    if (i >= lesson.steps.length) return close();
    if (i < 0) return;
    step = i;
    answer = progress.answers[i] ?? null;
    hintShown = 0;
    progress.step = i;
    writeProgress(lesson.id, progress);
    const s = lesson.steps[i];
    try {
      applyStep(s);
    } catch (e) {
      app.showError(`Lesson step ${i + 1}: ${e.message}`);
    }
    render();
    // The card's size is the new step's now: place it (and the ring) again.
    if (target) place();
  }

  function applyStep(s) {
    if (s.scene) app.loadPreset(s.scene);
    if (s.document) {
      const motion = new wasm.Motion(s.document, app.motion.options());
      app.edit(() => {
        app.motion.free();
        app.motion = motion;
        app.selected = -1;
        app.anim.u = 0;
        app.frameAll();
      });
    }
    const o = s.options ? { ...s.options } : null;
    if (o || s.display || s.timing?.times !== undefined) {
      app.edit(() => {
        if (o) {
          if (o.closed !== undefined) app.motion.setClosed(o.closed);
          delete o.closed;
          if (o.j !== undefined && o.scheme === undefined) o.scheme = 'j';
          if (Object.keys(o).length) app.motion.setOptions(o);
        }
        if (s.display) {
          Object.assign(app.view, s.display);
          if (s.display.object !== undefined) app.meshesChanged();
        }
        if (s.timing?.times !== undefined) app.view.times = s.timing.times;
      });
    }
    if (s.select !== undefined) app.select(s.select < app.motion.poseCount ? s.select : -1);
    const t = s.timing ?? {};
    if (t.speed !== undefined) app.anim.speed = t.speed;
    if (t.u !== undefined) {
      const [a, b] = app.motion.domain();
      app.anim.u = Math.min(b, Math.max(a, t.u));
      app.anim.visible = true;
      app.updateAnim();
    }
    if (t.play !== undefined) app.setPlaying(t.play);
    if (s.dock !== undefined && s.dock !== (app.view.dock || '')) app.openView(s.dock);
    setTarget(s.highlight ?? null);
    app.ui.refresh();
    app.requestDraw();
  }

  function render() {
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

  function renderExercise(x) {
    const solved = progress.solved.includes(step);
    const task = el('div', 'task');
    task.append(el('b', 'label', solved ? 'Exercise ✓ solved' : 'Exercise'), renderText(x.task));
    exercise.append(task);
    if (x.choices) {
      const fs = el('div', 'choices');
      fs.setAttribute('role', 'radiogroup');
      x.choices.forEach((c, k) => {
        const label = el('label');
        const r = el('input');
        r.type = 'radio';
        r.name = 'lesson-choice';
        r.value = String(k);
        r.checked = answer === k;
        r.addEventListener('change', () => (answer = k));
        const span = el('span');
        span.append(renderText(c));
        label.append(r, span);
        fs.append(label);
      });
      exercise.append(fs);
    }
    const row = el('div', 'row');
    const checkBtn = el('button', 'check primary', 'Check');
    checkBtn.addEventListener('click', () => check());
    row.append(checkBtn);
    if (x.hints?.length) {
      const hintBtn = el('button', 'hint', 'Hint');
      hintBtn.addEventListener('click', () => showHint(x));
      row.append(hintBtn);
    }
    exercise.append(row, el('div', 'hints'), Object.assign(el('p', 'feedback'), { role: 'status' }));
    if (solved) setFeedback(true, [x.success ?? 'Solved earlier; check again any time.']);
  }

  function showHint(x) {
    const box = exercise.querySelector('.hints');
    if (hintShown >= x.hints.length) return;
    const h = el('div', 'hint-text');
    h.append(el('b', '', `Hint ${hintShown + 1}: `), renderText(x.hints[hintShown]));
    box.append(h);
    hintShown++;
  }

  function setFeedback(ok, lines, math = true) {
    const fb = exercise.querySelector('.feedback');
    fb.className = `feedback ${ok ? 'ok' : 'no'}`;
    fb.replaceChildren();
    for (const line of lines) {
      const d = el('div');
      if (math) d.append(renderText(line));
      else d.textContent = line;
      fb.append(d);
    }
  }

  /** Runs the open step's checks (the Check button); saves a solved state and the answer. */
  function check() {
    const x = lesson?.steps[step]?.exercise;
    if (!x) return null;
    const r = evaluateExercise(x, app.motion, answer);
    if (answer !== null) progress.answers[step] = answer;
    if (r.ok && !progress.solved.includes(step)) progress.solved.push(step);
    writeProgress(lesson.id, progress);
    if (r.ok) setFeedback(true, [x.success ?? 'Correct.']);
    else {
      const lines = r.results.filter((c) => !c.ok).map((c) => (c.want ? `Not yet: ${c.got}; wanted ${c.want}.` : `Not yet: ${c.got}.`));
      setFeedback(false, lines, false);
    }
    exercise.querySelector('.task .label').textContent = progress.solved.includes(step) ? 'Exercise ✓ solved' : 'Exercise';
    bar.children[step]?.classList.toggle('solved', progress.solved.includes(step));
    return r;
  }

  function close() {
    if (lesson?.tour) markTourSeen();
    lesson = null;
    step = -1;
    card.hidden = true;
    document.body.classList.remove('lesson-open');
    setTarget(null);
  }

  // ---------------------------------------------------------------- highlight

  function setTarget(h) {
    target = h;
    if (h?.panel) {
      const c = app.ui.gui.controllersRecursive().find((k) => k._name === h.panel);
      app.ui.gui.open();
      c?.parent.open();
    }
    cancelAnimationFrame(raf);
    // Placed now (layout is current) and then every frame while it lasts.
    if (h) place();
    else {
      spotEl.hidden = true;
      placeCard(null);
    }
  }

  /** Where the highlight goes this frame: {x, y, w, h} in page px, or null. */
  function targetRect() {
    if (!target) return null;
    if (target.control || target.panel) {
      const node = target.control ? document.querySelector(target.control) : app.ui.gui.controllersRecursive().find((k) => k._name === target.panel)?.domElement;
      if (!node) return null;
      const r = node.getBoundingClientRect();
      if (r.width === 0 && r.height === 0) return null;
      return { x: r.left - 4, y: r.top - 4, w: r.width + 8, h: r.height + 8 };
    }
    let p = null;
    try {
      if (target.pose !== undefined && target.pose < app.motion.poseCount) p = app.screenOfPose(target.pose);
      if (target.gizmo !== undefined && app.selected >= 0) p = app.screenOfGizmo(target.gizmo);
    } catch {
      p = null;
    }
    if (!p || !Number.isFinite(p.x) || !Number.isFinite(p.y)) return null;
    return { x: p.x - 24, y: p.y - 24, w: 48, h: 48, round: true };
  }

  /**
   * Keeps the target visible. Phones (lessons.css): the card sits at the top, or at the bottom
   * while the target is in the top half. Wider screens: the first of bottom right (the CSS
   * place), top right, and bottom left of the target that does not cover it.
   */
  function placeCard(r) {
    const phone = window.matchMedia('(max-width: 760px)').matches;
    card.classList.toggle('low', !!r && phone && r.y + r.h / 2 < window.innerHeight / 2);
    let pos = { right: '', top: '', bottom: '' };
    if (r && !phone) {
      const W = card.offsetWidth;
      const H = card.offsetHeight;
      const iw = window.innerWidth;
      const ih = window.innerHeight;
      const hits = (x0, y0) => r.x < x0 + W + 8 && r.x + r.w > x0 - 8 && r.y < y0 + H + 8 && r.y + r.h > y0 - 8;
      const candidates = [
        [iw - 12 - W, ih - 70 - H, pos],
        [iw - 12 - W, 12, { right: '', top: '12px', bottom: 'auto' }],
        [r.x - 16 - W, ih - 70 - H, { right: `${iw - r.x + 16}px`, top: '', bottom: '' }],
      ];
      const ok = candidates.find(([x0, y0]) => x0 >= 0 && y0 >= 0 && !hits(x0, y0));
      if (ok) pos = ok[2];
    }
    card.style.right = pos.right;
    card.style.top = pos.top;
    card.style.bottom = pos.bottom;
  }

  function place() {
    const r = targetRect();
    spotEl.hidden = !r;
    placeCard(r);
    if (r) {
      spotEl.style.left = `${r.x}px`;
      spotEl.style.top = `${r.y}px`;
      spotEl.style.width = `${r.w}px`;
      spotEl.style.height = `${r.h}px`;
      spotEl.classList.toggle('round', !!r.round);
    }
    if (target) raf = requestAnimationFrame(place);
  }

  // ---------------------------------------------------------------- menu

  async function loadIndex() {
    if (index) return index;
    try {
      const r = await fetch(new URL('index.json', BASE), { cache: 'no-store' });
      if (!r.ok) throw new Error(`HTTP ${r.status}`);
      index = await r.json();
    } catch (e) {
      app.showError(`Could not load the list of lessons (${e.message}).`);
      index = { lessons: [] };
    }
    return index;
  }

  async function openMenu() {
    const { lessons = [] } = await loadIndex();
    list.replaceChildren();
    for (const item of lessons) {
      const p = readProgress(item.id);
      const b = el('button', 'lesson-item');
      b.dataset.lesson = item.file.replace(/\.json$/, '');
      const meta = p.step > 0 || p.solved.length ? ` · at step ${p.step + 1}${p.solved.length ? `, ${p.solved.length} exercise${p.solved.length > 1 ? 's' : ''} solved` : ''}` : '';
      b.append(el('b', '', item.title), el('span', '', `${item.summary ?? ''}${meta}`));
      b.addEventListener('click', () => open(b.dataset.lesson));
      list.append(b);
    }
    const tour = el('button', 'lesson-item tour');
    tour.dataset.lesson = 'tour';
    tour.append(el('b', '', 'Tour of the page'), el('span', '', 'Six stops: handles, gizmo, levels, scheme, play, Analyse'));
    tour.addEventListener('click', () => open('tour', { resume: false }));
    list.append(tour);
    menu.hidden = false;
    list.querySelector('button')?.focus();
  }

  async function openFile(file) {
    if (file.size > MAX_LESSON_BYTES) return app.showError(`${file.name} is too large for a lesson (${file.size} bytes). Nothing was changed.`);
    openText(await file.text(), file.name);
  }

  button.addEventListener('click', () => (menu.hidden ? openMenu() : (menu.hidden = true)));
  mclose.addEventListener('click', () => (menu.hidden = true));
  menu.addEventListener('click', (e) => {
    if (e.target === menu) menu.hidden = true;
  });
  chooseBtn.addEventListener('click', () => fileInput.click());
  fileInput.addEventListener('change', () => {
    const f = fileInput.files[0];
    fileInput.value = '';
    if (f) openFile(f);
  });
  pasteBtn.addEventListener('click', () => {
    if (openText(paste.value, 'pasted lesson')) paste.value = '';
  });
  // While the menu is open a dropped .json is a lesson, not a motion (capture: before files.js).
  window.addEventListener('drop', (e) => {
    if (menu.hidden) return;
    const f = e.dataTransfer?.files?.[0];
    if (!f) return;
    e.preventDefault();
    e.stopImmediatePropagation();
    $('drop').hidden = true;
    openFile(f);
  }, true);
  closeBtn.addEventListener('click', close);
  prevBtn.addEventListener('click', () => go(step - 1));
  nextBtn.addEventListener('click', () => go(step + 1));
  // Keys, as the editor's shortcuts (editor/input.js): L only with the focus on the 3-D view or
  // the page (inside a control keys keep their own meaning); Esc closes the menu from anywhere.
  window.addEventListener('keydown', (e) => {
    const t = e.target;
    const onPage = !t || t === app.canvas || t === document.body || t === document.documentElement;
    if (e.key === 'Escape' && !menu.hidden) menu.hidden = true;
    else if (onPage && (e.key === 'l' || e.key === 'L') && !e.ctrlKey && !e.metaKey && !e.altKey) {
      if (menu.hidden) openMenu();
      else menu.hidden = true;
    } else return;
    e.preventDefault();
  });

  // ---------------------------------------------------------------- start

  function markTourSeen() {
    try {
      localStorage.setItem(TOUR_SEEN_KEY, '1');
    } catch {
      // Without storage the tour may show again next time.
    }
  }

  const params = new URLSearchParams(location.search);
  player.ready = (async () => {
    if (params.has('lesson')) return open(params.get('lesson'));
    let seen = true;
    try {
      seen = localStorage.getItem(TOUR_SEEN_KEY) !== null;
    } catch {
      seen = true;
    }
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
