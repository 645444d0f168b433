// The Lessons button of the toolbar and its menu: the lessons of lessons/index.json with each
// one's saved progress, the tour, opening a lesson file by chooser, drop or paste, the
// "Download for an LMS (SCORM)" dialog (package-dialog.js, fetched when first used; not inside
// a lesson package, whose page has nothing to package from); the L and Esc keys; the lesson
// editor's entries and drafts (editor/menu-section.js), and a lesson carried by the page's
// address (a lesson link, link.js).
import { MAX_LESSON_BYTES } from './format.js';
import { readProgress } from './progress.js';
import { BASE } from './urls.js';
import { el } from '../dom.js';

/**
 * Creates the Lessons button and menu (#lessons-menu) of `app`; `open(name, {resume})`,
 * `openText(text, source)` and `current()` (the open lesson's id or null) are the player's.
 * Returns {open(), hide(), hidden}.
 */
export function createMenu(app, { open, openText, current }) {
  const $ = (id) => document.getElementById(id);
  const button = el('button');
  button.id = 't-lessons';
  button.title = 'Lessons and the tour (L)';
  button.append(el('b', { class: 'icon' }, '∑'), el('span', {}, 'Lessons'));
  $('toolbar').append(button);

  const menu = el('div', { class: 'modal' });
  menu.id = 'lessons-menu';
  menu.hidden = true;
  const mcard = el('div', { class: 'card' });
  const list = el('div', { class: 'lesson-list' });
  const paste = el('textarea');
  paste.rows = 5;
  paste.spellcheck = false;
  paste.placeholder = 'Paste a lesson file (JSON) here, or drop one on this window, or choose one:';
  const fileInput = el('input');
  fileInput.type = 'file';
  fileInput.accept = '.json,application/json';
  fileInput.hidden = true;
  const mrow = el('div', { class: 'row' });
  const chooseBtn = el('button', {}, 'Open a lesson file…');
  const pasteBtn = el('button', { class: 'primary' }, 'Open pasted lesson');
  const mclose = el('button', {}, 'Close');
  const lmsBtn = el('button', { class: 'lms' }, 'Download for an LMS (SCORM)…');
  let packageDialog = null;
  lmsBtn.addEventListener('click', async () => {
    try {
      packageDialog ??= import('./package-dialog.js').then((m) => m.createPackageDialog(app, current));
      menu.hidden = true;
      (await packageDialog).open();
    } catch (e) {
      packageDialog = null;
      app.parts.notices.show(`Could not load the package dialog (${e.message}).`);
    }
  });
  mrow.append(chooseBtn, pasteBtn, mclose);
  // Under the list it packages, on a row of its own.
  const lmsRow = el('div', { class: 'row lms-row' });
  lmsRow.hidden = document.documentElement.dataset.lessonPackage === '1';
  lmsRow.append(lmsBtn);
  const mnote = el('p', { class: 'small' });
  mnote.append('A lesson is a JSON file (format: ', Object.assign(el('a', {}, 'lessons/README.md'), { href: new URL('README.md', BASE).href, target: '_blank' }), '); a link with ', el('code', {}, '?lesson=name'), ' opens lessons/name.json.');
  // The player, whole: the editor previews through it and edits the lesson it shows (main.js
  // exposes it once it has started, which is before the menu is first used).
  const player = () => /** @type {any} */ (window).screwbender?.lessons ?? Promise.resolve(null);
  // The editor's entries and drafts (editor/menu-section.js) are fetched when the menu first
  // opens: a student following a lesson link needs none of them.
  const writeBox = el('div');
  /** @type {Promise<any> | null} */
  let write = null;
  const writeSection = () =>
    (write ??= import('./editor/menu-section.js').then((m) => {
      const w = m.createWriteSection(app, { hideMenu: () => (menu.hidden = true), pasted: () => paste.value, player });
      writeBox.replaceWith(w.element);
      return w;
    }));
  mcard.append(el('h2', {}, 'Lessons'), list, lmsRow, paste, mrow, writeBox, mnote, fileInput);
  menu.append(mcard);
  document.body.append(menu);

  let index = null;

  async function loadIndex() {
    if (index) return index;
    try {
      const r = await fetch(new URL('index.json', BASE), { cache: 'no-store' });
      if (!r.ok) throw new Error(`HTTP ${r.status}`);
      index = await r.json();
    } catch (e) {
      app.parts.notices.show(`Could not load the list of lessons (${e.message}).`);
      index = { lessons: [] };
    }
    return index;
  }

  async function openMenu() {
    const { lessons = [] } = await loadIndex();
    list.replaceChildren();
    for (const item of lessons) {
      const p = readProgress(item.id);
      const b = el('button', { class: 'lesson-item' });
      b.dataset.lesson = item.file.replace(/\.json$/, '');
      const meta = p.step > 0 || p.solved.length ? ` · at step ${p.step + 1}${p.solved.length ? `, ${p.solved.length} exercise${p.solved.length > 1 ? 's' : ''} solved` : ''}` : '';
      b.append(el('b', {}, item.title), el('span', {}, `${item.summary ?? ''}${meta}`));
      b.addEventListener('click', () => open(b.dataset.lesson));
      list.append(b);
    }
    const tour = el('button', { class: 'lesson-item tour' });
    tour.dataset.lesson = 'tour';
    tour.append(el('b', {}, 'Tour of the page'), el('span', {}, 'Six stops: handles, gizmo, levels, scheme, play, Analyse'));
    tour.addEventListener('click', () => open('tour', { resume: false }));
    list.append(tour);
    (await writeSection()).refresh();
    menu.hidden = false;
    list.querySelector('button')?.focus();
  }

  async function openFile(file) {
    if (file.size > MAX_LESSON_BYTES) return app.parts.notices.show(`${file.name} is too large for a lesson (${file.size} bytes). Nothing was changed.`, 'error', 'lesson');
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
  // Keys, as the editor's shortcuts (editor/input.js): L only with the focus on the 3-D view or
  // the page (inside a control keys keep their own meaning); Esc closes the menu from anywhere.
  window.addEventListener('keydown', (e) => {
    const t = e.target;
    const onPage = !t || t === app.viewer.canvas || t === document.body || t === document.documentElement;
    if (e.key === 'Escape' && !menu.hidden) menu.hidden = true;
    else if (onPage && (e.key === 'l' || e.key === 'L') && !e.ctrlKey && !e.metaKey && !e.altKey) {
      if (menu.hidden) openMenu();
      else menu.hidden = true;
    } else return;
    e.preventDefault();
  });

  // A lesson carried by the page's address (`#lesson=…`, editor/menu-section.js reads it): at
  // load, or pasted into the address bar of the open page (only the hash changes, no load).
  const openLinked = () => {
    if (location.hash.startsWith('#lesson=')) {
      player().then(async (p) => (await import('./editor/menu-section.js')).openLinkedLesson(app, openText, p?.ready));
    }
  };
  openLinked();
  window.addEventListener('hashchange', openLinked);

  return {
    open: openMenu,
    hide() {
      menu.hidden = true;
    },
    get hidden() {
      return menu.hidden;
    },
  };
}
