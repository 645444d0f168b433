// The Lessons menu's part for writing lessons: New lesson, Edit this lesson, a lesson file or
// link (or pasted text) opened in the editor, and the drafts (lessons/drafts.js) with their
// names and dates, each to open or delete; a deleted draft is one Undo away. The drafts list
// follows other tabs (the storage event). The editor itself (panel.js) is fetched when first
// used.
import { stylesheet } from '../../editor/modules.js';
import { el } from '../../dom.js';
import { deleteDraft, listDrafts, onDraftsChanged, readDraft, restoreDraft } from '../drafts.js';

/**
 * The lesson link's module (link.js), fetched when a link is read: it brings the deflate code,
 * which the page needs for nothing else at start.
 */
const linkModule = () => import('../link.js');
/** Whether `hash` is a lesson link's fragment (link.js LINK_KEY), known without fetching link.js. */
const isLessonLink = (hash) => hash.startsWith('#lesson=');

/**
 * The section; `hideMenu()` closes the Lessons menu, `pasted()` is the text of the menu's paste
 * field, `player()` resolves to the lesson player.
 * Returns {element, refresh(), editor(): Promise<editor>}.
 * @param {import('../../app.js').App} app
 */
export function createWriteSection(app, { hideMenu, pasted, player }) {
  const box = el('section', { class: 'write-lessons' });
  box.id = 'write-lessons';
  // A lesson package's page (an LMS) is for students: nothing to write there.
  box.hidden = document.documentElement.dataset.lessonPackage === '1';
  const row = el('div', { class: 'row' });
  const newBtn = el('button', {}, 'New lesson');
  newBtn.id = 'lesson-new';
  const editBtn = el('button', {}, 'Edit this lesson');
  editBtn.id = 'lesson-edit';
  const fileBtn = el('button', {}, 'Edit a lesson file…');
  fileBtn.id = 'lesson-edit-file';
  const pasteBtn = el('button', {}, 'Edit pasted lesson or link');
  pasteBtn.id = 'lesson-edit-pasted';
  const fileInput = el('input');
  fileInput.type = 'file';
  fileInput.accept = '.json,application/json';
  fileInput.hidden = true;
  row.append(newBtn, editBtn, fileBtn, pasteBtn);
  const drafts = el('ul', { class: 'drafts' });
  drafts.id = 'lesson-drafts';
  const undoRow = el('p', { class: 'draft-undo' });
  undoRow.hidden = true;
  box.append(el('h3', {}, 'Write a lesson'), row, drafts, undoRow, fileInput);

  let editor = null;
  /** The lesson editor, fetched and made once. */
  async function getEditor() {
    try {
      editor ??= Promise.all([import('./panel.js'), player(), stylesheet(new URL('../../../css/lesson-editor.css', import.meta.url))]).then(([m, p]) => ({ m, e: m.createLessonEditor(app, p), p }));
      return await editor;
    } catch (e) {
      editor = null;
      app.parts.notices.show(`Could not load the lesson editor (${e.message}).`);
      return null;
    }
  }

  /** The last deleted draft, for Undo. */
  let deleted = null;

  function refresh() {
    const list = listDrafts();
    drafts.replaceChildren();
    drafts.hidden = list.length === 0;
    for (const d of list) {
      const li = el('li');
      const open = el('button', { class: 'draft' });
      open.dataset.draft = d.id;
      open.append(el('b', {}, d.name || 'Untitled lesson'), el('span', {}, ` draft of ${new Date(d.savedAt).toLocaleString()}`));
      open.addEventListener('click', async () => {
        const ed = await getEditor();
        const now = readDraft(d.id);
        if (!ed || !now) return refresh();
        hideMenu();
        ed.p.close();
        ed.e.open(now.lesson, { draftId: now.id });
      });
      const del = el('button', { class: 'le-del' }, '✕');
      del.title = `Delete the draft ${d.name}`;
      del.setAttribute('aria-label', del.title);
      del.addEventListener('click', () => {
        deleted = deleteDraft(d.id);
        refresh();
        if (!deleted) return;
        const undo = el('button', {}, 'Undo');
        undo.id = 'draft-undo';
        undo.addEventListener('click', () => {
          if (deleted) restoreDraft(deleted);
          deleted = null;
          undoRow.hidden = true;
          refresh();
        });
        undoRow.replaceChildren(`Draft “${deleted.name}” deleted. `, undo);
        undoRow.hidden = false;
        undo.focus();
      });
      li.append(open, del);
      drafts.append(li);
    }
    player().then((p) => (editBtn.disabled = !p?.lesson || !!p.lesson.tour));
  }

  newBtn.addEventListener('click', async () => {
    const ed = await getEditor();
    if (!ed) return;
    hideMenu();
    ed.p.close();
    ed.e.open(ed.m.newLesson(app));
  });
  editBtn.addEventListener('click', async () => {
    const ed = await getEditor();
    if (!ed?.p.lesson) return;
    const lesson = ed.m.fileForm(ed.p.lesson);
    hideMenu();
    ed.p.close();
    ed.e.open(lesson);
  });
  fileBtn.addEventListener('click', () => fileInput.click());
  fileInput.addEventListener('change', async () => {
    const f = fileInput.files?.[0];
    fileInput.value = '';
    const ed = f && (await getEditor());
    if (!ed) return;
    hideMenu();
    ed.p.close();
    ed.e.openText(await f.text(), f.name);
  });
  pasteBtn.addEventListener('click', async () => {
    const text = pasted().trim();
    if (!text) return app.parts.notices.show('Paste a lesson file or a lesson link into the field first.', 'warn', 'lesson');
    let lesson = text;
    if (!text.startsWith('{')) {
      try {
        lesson = (await linkModule()).lessonFromLink(text);
      } catch (e) {
        return app.parts.notices.show(`The pasted text is neither a lesson file nor a lesson link: ${e.message}.`, 'error', 'lesson');
      }
    }
    const ed = await getEditor();
    if (!ed) return;
    hideMenu();
    ed.p.close();
    ed.e.openText(lesson, 'the pasted lesson');
  });
  onDraftsChanged(refresh);
  refresh();
  return { element: box, refresh, editor: getEditor };
}

/**
 * Opens the lesson a lesson link carries (`#lesson=…` in the page's address) with `openText`,
 * once the player has handled its own start (the tour); a banner says what is wrong with a
 * broken link.
 */
export async function openLinkedLesson(app, openText, ready) {
  if (!isLessonLink(location.hash)) return;
  await ready;
  try {
    openText((await linkModule()).lessonFromLink(location.hash), 'from the link', { resume: true });
  } catch (e) {
    app.parts.notices.show(`This page's lesson link cannot be opened: ${e.message}.`, 'error', 'lesson');
  }
}
