// The lesson editor: a column of the page (the lesson card's place, css/lesson-editor.css) where a
// teacher writes a lesson without writing JSON. It holds the lesson in file form (the format of
// www/lessons/README.md), lists every problem of it at once (problems.js), and keeps each change
// as one undoable edit: its own Undo/Redo (History of editor/session.js, over snapshots of the
// lesson, so no edit needs an inverse), apart from the page's, whose edits the teacher makes
// on the page to set a step up. Every change is kept as a draft (lessons/drafts.js). Its parts:
// the step list (step-list.js), the step form (step-form.js) with the text fields
// (text-field.js), the highlight picking (pick.js), the exercise (exercise-form.js) and its
// checks (check-form.js), a step's setup from the page (capture.js). Output: preview as a
// student (the lesson player; the progress a student had under the lesson's id is put back
// after it), the .json file, the lesson link (lessons/link.js), and a SCORM
// package (package-dialog.js).
import { VIEW_IDS } from '../../dock/index.js';
import { History } from '../../editor/session.js';
import { applyStep } from '../apply.js';
import { el, button } from '../../dom.js';
import { newDraftId, saveDraft } from '../drafts.js';
import { lessonFromLink, lessonLink } from '../link.js';
import { MAX_LESSON_BYTES } from '../format.js';
import { readProgress, writeProgress } from '../progress.js';
import { capture } from './capture.js';
import { problemsOf, renderProblems } from './problems.js';
import { stepList } from './step-list.js';
import { stepForm } from './step-form.js';

/**
 * A lesson as its file holds it, from a lesson the player parsed (format.js turns each answer
 * `{text, why}` into the text, and keeps the `why`s apart).
 */
export function fileForm(parsed) {
  const lesson = structuredClone(parsed);
  for (const s of lesson.steps ?? []) {
    const x = s.exercise;
    if (!x || !Array.isArray(x.why)) continue;
    x.choices = x.choices.map((t, k) => (x.why[k] ? { text: t, why: x.why[k] } : t));
    delete x.why;
  }
  return lesson;
}

/** A new lesson: one step, set up as the page is now. */
export function newLesson(app) {
  return { id: 'my-lesson', title: 'My lesson', steps: [{ title: 'Step 1', text: '', ...capture(app) }] };
}

/** The lesson's file text. */
export const lessonText = (lesson) => `${JSON.stringify(lesson, null, 2)}\n`;

/**
 * Creates the (hidden) lesson editor of `app`; `player` is the lesson player (player.js), which
 * previews the lesson. Returns {open(lesson, {draftId}), close(), element, doc, undo(), redo()}.
 * @param {import('../../app.js').App} app
 */
export function createLessonEditor(app, player) {
  const ctx = {
    scenes: app.scenes.map((s) => s.id),
    views: VIEW_IDS,
    panel: app.ui.gui.controllersRecursive().map((c) => c._name),
    checkMotion: (doc) => new app.wasm.Motion(doc).free(),
  };
  const element = el('aside');
  element.id = 'lesson-editor';
  element.hidden = true;
  element.setAttribute('aria-label', 'Lesson editor');
  const head = el('div', { class: 'le-head' });
  const title = el('h2', {}, 'Lesson editor');
  const undoBtn = button('↶', 'Undo (editor)', () => undo());
  undoBtn.id = 'le-undo';
  const redoBtn = button('↷', 'Redo (editor)', () => redo());
  redoBtn.id = 'le-redo';
  const closeBtn = button('×', 'Close the editor (the draft is kept)', () => close(), 'close');
  head.append(title, undoBtn, redoBtn, closeBtn);
  const say = el('p', { class: 'le-say' });
  say.setAttribute('role', 'status');
  const scroll = el('div', { class: 'le-scroll' });
  const foot = el('div', { class: 'le-foot' });
  const previewBtn = button('Preview as a student', '', () => preview(), 'primary');
  previewBtn.id = 'le-preview';
  const saveBtn = button('Save .json', 'Save the lesson file', () => saveFile());
  saveBtn.id = 'le-save';
  const linkBtn = button('Copy lesson link', 'A link that carries the lesson itself: it opens for a student with no hosting', () => copyLink());
  linkBtn.id = 'le-link';
  const lmsBtn = button('Download for an LMS…', 'A SCORM package of this lesson', () => packageIt());
  lmsBtn.id = 'le-lms';
  lmsBtn.hidden = document.documentElement.dataset.lessonPackage === '1';
  const linkOut = el('input');
  linkOut.id = 'le-link-out';
  linkOut.readOnly = true;
  linkOut.hidden = true;
  linkOut.setAttribute('aria-label', 'The lesson link');
  const fileInput = el('input');
  fileInput.type = 'file';
  fileInput.accept = '.json,application/json';
  fileInput.hidden = true;
  fileInput.id = 'le-file';
  const openFileBtn = button('Open a file…', 'Open a lesson file in the editor', () => fileInput.click());
  const openLink = el('input');
  openLink.id = 'le-open-link';
  openLink.placeholder = 'or paste a lesson link here';
  openLink.setAttribute('aria-label', 'A lesson link to open in the editor');
  foot.append(previewBtn, saveBtn, linkBtn, lmsBtn, linkOut, openFileBtn, openLink, fileInput);
  element.append(head, say, scroll, foot);
  document.body.append(element);

  const back = button('◀ Back to the editor', 'Leave the preview', () => endPreview(), 'primary');
  back.id = 'le-back';
  back.hidden = true;
  document.body.append(back);

  /** The editor's state: the lesson, its draft, the step shown, its undo history. */
  const ed = {
    app,
    element,
    doc: /** @type {any} */ (null),
    draftId: '',
    step: 0,
    /** What the check form remembers between renders (its kind, number and tolerance). */
    ui: {},
    edit,
    select,
    showStep,
    /** Says `m` in the editor's message line; `bad`: as a refusal. */
    say(m, bad = false) {
      say.textContent = m;
      say.classList.toggle('bad', bad);
    },
  };
  const history = new History();
  /** The merge key and history version of the last edit (a run of typing is one undo step). */
  let last = { key: '', version: -1 };

  /**
   * Changes the lesson by `f(doc)` as one undo step named `label`. `merge`: a key that folds a
   * run of the same edit (typing in one field) into one step; `rerender`: false while the field
   * being typed in stays (only the problems are listed again), 'list' for the step list too;
   * `step`: the step to show after it.
   * @param {string} label
   * @param {(doc: any) => any} f
   * @param {{merge?: string, rerender?: boolean | 'list', step?: number}} [opts]
   */
  function edit(label, f, { merge = '', rerender = true, step = ed.step } = {}) {
    const before = JSON.stringify(ed.doc);
    if (!(merge && last.key === merge && last.version === history.version)) history.push(`${ed.step}\n${before}`, label);
    last = { key: merge, version: history.version };
    f(ed.doc);
    ed.step = Math.max(0, Math.min(step, ed.doc.steps.length - 1));
    changed(rerender);
  }

  /**
   * After a change: keep the draft, list the problems, show it.
   * @param {boolean | 'list'} [rerender]
   */
  function changed(rerender = true) {
    saveDraft({ id: ed.draftId, name: ed.doc.title || ed.doc.id || 'Untitled lesson', lesson: ed.doc });
    if (rerender === true) render();
    else if (rerender === 'list') {
      const list = scroll.querySelector('.le-steps');
      list?.replaceWith(stepList(ed));
    }
    problems();
    undoBtn.disabled = !history.canUndo;
    redoBtn.disabled = !history.canRedo;
    undoBtn.title = history.canUndo ? `Undo: ${history.undoLabels[0]}` : 'Nothing to undo';
    redoBtn.title = history.canRedo ? `Redo: ${history.redoLabels[0]}` : 'Nothing to redo';
    element.dataset.undo = history.undoLabels[0] ?? '';
    element.dataset.redo = history.redoLabels[0] ?? '';
  }

  /** Goes back to a snapshot of undo()/redo(). */
  function restore(snapshot) {
    const cut = snapshot.indexOf('\n');
    ed.doc = JSON.parse(snapshot.slice(cut + 1));
    ed.step = Math.min(Number(snapshot.slice(0, cut)) || 0, ed.doc.steps.length - 1);
    last = { key: '', version: -1 };
    changed();
  }

  function undo() {
    const label = history.undoLabels[0];
    const s = history.undo(`${ed.step}\n${JSON.stringify(ed.doc)}`);
    if (s === null) return;
    restore(s);
    ed.say(`Undone: ${label}.`);
  }

  function redo() {
    const label = history.redoLabels[0];
    const s = history.redo(`${ed.step}\n${JSON.stringify(ed.doc)}`);
    if (s === null) return;
    restore(s);
    ed.say(`Redone: ${label}.`);
  }

  const problemBox = el('section', { class: 'le-problems' });
  problemBox.setAttribute('aria-live', 'polite');

  /** The lesson's problems as last listed. */
  let found = [];

  /**
   * True when the lesson has no problems; else says so (what goes to a student must open for
   * them: a lesson with a problem does not).
   */
  function ready(what) {
    if (!found.length) return true;
    ed.say(`${what} needs a lesson without problems: ${found.length} ${found.length > 1 ? 'are' : 'is'} listed above. Save .json keeps it as it is.`, true);
    return false;
  }

  function problems() {
    const list = problemsOf(ed.doc, ctx);
    found = list;
    element.dataset.problems = String(list.length);
    renderProblems(problemBox, list, (p) => jump(p.path, p.step));
  }

  /** Shows the field at `path` (of step `step`) and puts the focus in it. */
  function jump(path, step) {
    if (step !== null && step !== ed.step) select(step, false);
    let target = null;
    // The field itself, else the nearest part of the form that holds it.
    for (let p = path; p && !target; ) {
      target = scroll.querySelector(`[data-path="${CSS.escape(p)}"]`);
      const up = p.replace(/(\.[^.[\]]+|\[\d+\])$/, '');
      if (up === p) break;
      p = up;
    }
    target ??= scroll.querySelector('.le-step-form');
    if (!target) return;
    const focusable = target.matches('input, textarea, select, button') ? target : target.querySelector('input, textarea, select, button');
    target.scrollIntoView({ block: 'center' });
    /** @type {HTMLElement} */ (focusable ?? target).focus();
  }

  /** Shows step `i` in the form; `apply`: sets the page up as the step does, too. */
  function select(i, apply) {
    ed.step = i;
    render();
    if (apply) showStep(i);
  }

  /** Sets the page up as step `i` does (an ordinary edit of the page: its Undo takes it back). */
  function showStep(i) {
    const s = structuredClone(ed.doc.steps[i]);
    try {
      applyStep(app, s, () => {});
    } catch (e) {
      ed.say(`Step ${i + 1} cannot be shown: ${e.message}`, true);
    }
  }

  /** Builds the editor's content again, keeping the focus in the field it was in. */
  function render() {
    const active = /** @type {HTMLElement} */ (document.activeElement);
    const path = element.contains(active) ? active?.dataset?.path : undefined;
    const top = scroll.scrollTop;
    const lesson = el('section', { class: 'le-lesson' });
    lesson.append(
      field('Lesson title', 'title', ed.doc.title, (v) => (ed.doc.title = v)),
      field('Id (letters, digits, - and _; progress is kept under it)', 'id', ed.doc.id, (v) => (ed.doc.id = v)),
      field('Summary (the Lessons menu)', 'summary', ed.doc.summary ?? '', (v) => (v.trim() ? (ed.doc.summary = v) : delete ed.doc.summary)),
    );
    scroll.replaceChildren(lesson, problemBox, stepList(ed), stepForm(ed, ed.step));
    scroll.scrollTop = top;
    if (path) /** @type {HTMLElement | null} */ (scroll.querySelector(`[data-path="${CSS.escape(path)}"]`))?.focus();
  }

  /** A one-line field of the lesson itself. */
  function field(label, path, value, set) {
    const l = el('label', { class: 'le-field' }, label);
    const i = el('input');
    i.type = 'text';
    i.value = value ?? '';
    i.dataset.path = path;
    i.addEventListener('input', () => edit(`Edit the lesson ${path}`, () => set(i.value), { merge: `lesson:${path}`, rerender: false }));
    l.append(i);
    return l;
  }

  /** Opens `lesson` (file form) in the editor as draft `draftId` (a new draft when none). */
  function open(lesson, { draftId = null } = {}) {
    if (!lesson || typeof lesson !== 'object' || !Array.isArray(lesson.steps) || !lesson.steps.length) lesson = { id: 'my-lesson', title: 'My lesson', ...lesson, steps: [{ title: 'Step 1', text: '', ...capture(app) }] };
    ed.doc = structuredClone(lesson);
    ed.draftId = draftId ?? newDraftId();
    ed.step = 0;
    history.undoStack.length = 0;
    history.redoStack.length = 0;
    history.version++;
    element.hidden = false;
    layout(true);
    changed();
    ed.say('Every change is kept as a draft (Lessons menu).');
    scroll.querySelector('input')?.focus();
  }

  function close() {
    element.hidden = true;
    layout(false);
  }

  /** Gives the editor its column of the page (css/lessons.css layout), or gives it back. */
  function layout(on) {
    document.body.classList.toggle('lesson-open', on);
    document.body.classList.toggle('lesson-editing', on);
    app.viewer.invalidateSize();
    app.emit('layout');
    requestAnimationFrame(() => {
      app.viewer.invalidateSize();
      app.parts.viewpoint.fit();
    });
  }

  /** While the player shows the lesson being written. */
  let previewing = false;
  /** The progress kept under the previewed lesson's id before the preview: the preview's own is not a student's. */
  let kept = null;
  // A lesson the player opens otherwise (the Lessons menu, a link) takes the column: the editor
  // steps aside, its draft kept.
  player.events?.addEventListener('open', () => {
    if (!previewing && !element.hidden) close();
  });

  function preview() {
    const text = lessonText(ed.doc);
    previewing = true;
    kept = typeof ed.doc.id === 'string' ? { id: ed.doc.id, progress: readProgress(ed.doc.id) } : null;
    element.hidden = true;
    document.body.classList.remove('lesson-editing');
    if (!player.openText(text, 'being written', { resume: false, progress: { step: 0, solved: [], answers: {} } })) {
      element.hidden = false;
      document.body.classList.add('lesson-editing');
      ed.say('The preview needs a lesson without problems: see the list.');
      previewing = false;
      kept = null;
      return;
    }
    back.hidden = false;
    back.focus();
  }

  function endPreview() {
    back.hidden = true;
    player.close();
    previewing = false;
    if (kept) writeProgress(kept.id, kept.progress);
    kept = null;
    element.hidden = false;
    layout(true);
    previewBtn.focus();
  }

  function saveFile() {
    const a = el('a');
    a.href = URL.createObjectURL(new Blob([lessonText(ed.doc)], { type: 'application/json' }));
    a.download = `${String(ed.doc.id || 'lesson').replace(/[^\w-]+/g, '-')}.json`;
    document.body.append(a);
    a.click();
    a.remove();
    setTimeout(() => URL.revokeObjectURL(a.href), 10000);
    ed.say(`Saved ${a.download}.`);
  }

  async function copyLink() {
    if (!ready('A lesson link')) return;
    const { url, error } = lessonLink(JSON.stringify(ed.doc));
    if (error) {
      linkOut.hidden = true;
      ed.say(error, true);
      return;
    }
    linkOut.value = url;
    linkOut.hidden = false;
    try {
      await navigator.clipboard.writeText(url);
      ed.say(`The lesson link (${url.length} characters) is copied.`);
    } catch {
      linkOut.select();
      ed.say(`The lesson link (${url.length} characters) is below: copy it from there.`);
    }
  }

  let packageDialog = null;
  async function packageIt() {
    if (!ready('A package for an LMS')) return;
    try {
      packageDialog ??= import('../package-dialog.js').then((m) => m.createPackageDialog(app, () => null));
      (await packageDialog).open({ file: `${String(ed.doc.id || 'lesson').replace(/[^\w-]+/g, '-')}.json`, text: lessonText(ed.doc), title: ed.doc.title || 'This lesson' });
    } catch (e) {
      packageDialog = null;
      ed.say(`Could not load the package dialog (${e.message}).`, true);
    }
  }

  /** Opens a lesson file's text in the editor (a new draft); false (and says why) if it is not one. */
  function openText(text, source) {
    let lesson;
    try {
      if (text.length > MAX_LESSON_BYTES) throw new Error(`it is ${text.length} bytes; a lesson may have at most ${MAX_LESSON_BYTES}`);
      lesson = JSON.parse(text);
      if (!lesson || typeof lesson !== 'object' || Array.isArray(lesson)) throw new Error('a lesson is a JSON object');
    } catch (e) {
      ed.say(`${source} cannot be opened: ${e.message}. Nothing was changed.`, true);
      return false;
    }
    open(lesson);
    ed.say(`Opened ${source}; the problems of it are listed.`);
    return true;
  }

  fileInput.addEventListener('change', async () => {
    const f = fileInput.files?.[0];
    fileInput.value = '';
    if (f) openText(await f.text(), f.name);
  });
  openLink.addEventListener('change', () => {
    const v = openLink.value.trim();
    if (!v) return;
    try {
      if (openText(lessonFromLink(v), 'the lesson link')) openLink.value = '';
    } catch (e) {
      ed.say(`The link cannot be opened: ${e.message}. Nothing was changed.`, true);
    }
  });
  // The editor's own Undo and Redo keys while the focus is in it (the page's stay the page's).
  element.addEventListener('keydown', (e) => {
    const k = e.key.toLowerCase();
    if (!(e.ctrlKey || e.metaKey) || e.altKey || (k !== 'z' && k !== 'y')) return;
    e.preventDefault();
    e.stopPropagation();
    if (k === 'y' || e.shiftKey) redo();
    else undo();
  });

  return {
    element,
    open,
    openText,
    close,
    undo,
    redo,
    get doc() {
      return ed.doc;
    },
    get draftId() {
      return ed.draftId;
    },
    get hidden() {
      return element.hidden;
    },
  };
}
