// The "Download for an LMS (SCORM)" dialog of the Lessons menu: the lessons of lessons/index.json
// to package (one lesson, or several as one course), the format (SCORM 1.2 or 2004), the mastery
// score, and the zip's size, made here as it will be downloaded. The package is package.js's,
// the same as `node scripts/lesson-package.mjs` makes; the zip is fflate's (www/vendor).
import { zipSync } from '../../vendor/fflate.min.mjs';
import { FILE_LIST, FORMATS, packageZip, planPackage } from './package.js';
import { BASE } from './urls.js';
import { el } from '../dom.js';

/** The page's folder (www/): the package's files are fetched from it. */
const WWW = new URL('../../', import.meta.url);

/** Files fetched so far (path → bytes), kept for the next size or download. */
const cache = new Map();

async function bytes(path) {
  if (!cache.has(path)) {
    cache.set(
      path,
      fetch(new URL(path, WWW)).then(async (r) => {
        if (!r.ok) throw new Error(`${path}: HTTP ${r.status}`);
        return new Uint8Array(await r.arrayBuffer());
      }),
    );
    cache.get(path).catch(() => cache.delete(path));
  }
  return cache.get(path);
}

const text = async (path) => new TextDecoder().decode(await bytes(path));

/**
 * Makes the zip of lessons `files` in `format` with `mastery` (0…1 or null): {zip: Uint8Array,
 * title, count}. A lesson is a file name in lessons/, or {file, text}: a lesson of the page (the
 * lesson editor's).
 */
export async function buildPackage(files, format, mastery) {
  const list = JSON.parse(await text(FILE_LIST));
  // Lessons fresh each time (one may be being written); the playground's files from the cache.
  const lessons = await Promise.all(files.map(async (file) => {
    if (typeof file !== 'string') return file;
    const r = await fetch(new URL(`lessons/${file}`, WWW), { cache: 'no-store' });
    if (!r.ok) throw new Error(`lessons/${file}: HTTP ${r.status}`);
    return { file, text: await r.text() };
  }));
  const plan = planPackage({ lessons, format, mastery, list, template: await text(list.template) });
  const enc = new TextEncoder();
  const data = await Promise.all(plan.files.map(async (f) => ({ path: f.path, data: f.text !== undefined ? enc.encode(f.text) : await bytes(f.www) })));
  return { zip: packageZip(data, zipSync), title: plan.title, count: data.length };
}

/**
 * Creates the dialog (#lms-package) of `app`; `current()` is the id of the open lesson (or
 * null), checked first. Returns {open(extra)}: `extra`, where given, is a lesson of the page
 * ({file, text, title}: the lesson editor's), listed first and checked.
 */
export function createPackageDialog(app, current) {
  const modal = el('div', { class: 'modal' });
  modal.id = 'lms-package';
  modal.hidden = true;
  modal.setAttribute('role', 'dialog');
  modal.setAttribute('aria-labelledby', 'lms-package-title');
  const card = el('div', { class: 'card' });
  const title = el('h2', {}, 'Download for an LMS (SCORM)');
  title.id = 'lms-package-title';
  const intro = el('p', { class: 'small' }, 'A zip to upload to Moodle, Canvas, Blackboard or any LMS as a SCORM package. The LMS records completion, the score (exercises solved of all), each answer, and where the learner stopped; nothing else is needed on the server.');
  const lessonsBox = el('fieldset', { class: 'lessons' });
  const formatBox = el('fieldset', { class: 'format' });
  formatBox.append(el('legend', {}, 'Format'));
  for (const [value, label] of Object.entries(FORMATS)) {
    const l = el('label');
    const r = el('input');
    r.type = 'radio';
    r.name = 'lms-format';
    r.value = value;
    r.checked = value === 'scorm12';
    l.append(r, ` ${label}`);
    formatBox.append(l);
  }
  const masteryLabel = el('label', { class: 'mastery' }, 'Pass mark (exercises solved, %; empty: no pass / fail) ');
  const mastery = el('input');
  mastery.type = 'number';
  mastery.min = '0';
  mastery.max = '100';
  mastery.step = '5';
  mastery.value = '80';
  masteryLabel.append(mastery);
  const size = el('p', { class: 'size' });
  size.setAttribute('role', 'status');
  const row = el('div', { class: 'row' });
  const download = el('button', { class: 'primary' }, 'Download .zip');
  const close = el('button', {}, 'Close');
  row.append(download, close);
  card.append(title, intro, lessonsBox, formatBox, masteryLabel, size, row);
  modal.append(card);
  document.body.append(modal);

  /** The choices of the dialog: {files, format, mastery} or an Error's message. */
  function choices() {
    const files = [...lessonsBox.querySelectorAll('input:checked')].map((i) => (i === extraBox ? pageLesson : /** @type {HTMLInputElement} */ (i).value));
    const format = /** @type {HTMLInputElement} */ (formatBox.querySelector('input:checked')).value;
    const m = mastery.value.trim();
    if (m !== '' && !(Number(m) >= 0 && Number(m) <= 100)) return 'The pass mark is a percentage from 0 to 100.';
    if (!files.length) return 'Choose at least one lesson.';
    return { files, format, mastery: m === '' ? null : Number(m) / 100 };
  }

  let run = 0;
  /** The last package made: {key, p} (the choices as JSON, and the package). */
  let last = null;
  /** Makes the package for the dialog's choices and shows its size; resolves to it (or null). */
  async function measure() {
    const c = choices();
    const mine = ++run;
    download.disabled = true;
    if (typeof c === 'string') {
      size.textContent = c;
      return null;
    }
    const key = JSON.stringify({ ...c, files: c.files.map((f) => (typeof f === 'string' ? f : f.text)) });
    if (last?.key === key) {
      download.disabled = false;
      return last.p;
    }
    size.textContent = 'Size: measuring…';
    try {
      const p = await buildPackage(c.files, c.format, c.mastery);
      if (mine !== run) return null;
      last = { key, p };
      size.textContent = `Size: ${(p.zip.length / 1e6).toFixed(2)} MB (${p.count} files), ${FORMATS[c.format]}${c.files.length > 1 ? `, a course of ${c.files.length} lessons` : ''}.`;
      download.disabled = false;
      return p;
    } catch (e) {
      if (mine === run) size.textContent = `Cannot make the package: ${e.message}`;
      return null;
    }
  }

  /** The page's lesson offered by open(extra), and its checkbox. */
  let pageLesson = null;
  let extraBox = null;

  async function open(extra = null) {
    let index;
    try {
      const r = await fetch(new URL('index.json', BASE), { cache: 'no-store' });
      if (!r.ok) throw new Error(`HTTP ${r.status}`);
      index = await r.json();
    } catch (e) {
      return app.parts.notices.show(`Could not load the list of lessons (${e.message}).`);
    }
    const lessons = index.lessons ?? [];
    const now = current();
    lessonsBox.replaceChildren(el('legend', {}, 'Lessons (several make one course)'));
    pageLesson = extra ? { file: extra.file, text: extra.text } : null;
    extraBox = null;
    if (extra) {
      const label = el('label');
      extraBox = el('input');
      extraBox.type = 'checkbox';
      extraBox.value = extra.file;
      extraBox.checked = true;
      label.append(extraBox, ` ${extra.title} (being written)`);
      lessonsBox.append(label);
    }
    lessons.forEach((l, k) => {
      const label = el('label');
      const c = el('input');
      c.type = 'checkbox';
      c.value = l.file;
      c.checked = !extra && (now ? l.id === now : k === 0);
      label.append(c, ` ${l.title}`);
      lessonsBox.append(label);
    });
    modal.hidden = false;
    download.focus();
    // The lessons' files may have changed since the last package (a lesson being written).
    last = null;
    measure();
  }

  card.addEventListener('change', () => measure());
  download.addEventListener('click', async () => {
    const p = await measure();
    if (!p) return;
    const a = el('a');
    a.href = URL.createObjectURL(new Blob([p.zip], { type: 'application/zip' }));
    a.download = `${p.title.replace(/[^\w.-]+/g, '-').replace(/^-+|-+$/g, '') || 'lesson'}-scorm.zip`;
    document.body.append(a);
    a.click();
    a.remove();
    setTimeout(() => URL.revokeObjectURL(a.href), 10000);
  });
  close.addEventListener('click', () => (modal.hidden = true));
  modal.addEventListener('click', (e) => {
    if (e.target === modal) modal.hidden = true;
  });
  modal.addEventListener('keydown', (e) => {
    if (e.key === 'Escape') modal.hidden = true;
  });
  return { open };
}
