// A lesson package for an LMS (SCORM 1.2 or SCORM 2004 4th edition): which files it holds, its
// imsmanifest.xml, its launch page and its course file. One ES module for both builders, the
// page's dialog (package-dialog.js) and `node scripts/lesson-package.mjs`, so the two make the
// same zip of the same lessons byte for byte: each reads the files its own way (fetch, fs) and
// hands them to packageZip with fflate's zipSync.
//
// What goes in: the playground's files listed by the build (www/pkg-lesson/files.json, made by
// scripts/serve.d/70-lesson-package.mjs) in groups: `page` (the page's code and styles, the
// first-frame renderer modules, KaTeX), `analysis` (the analysis module, only when a lesson
// opens an analysis view or measures with a `metric` check) and `bunny` (the Stanford bunny,
// only when a lesson shows its preset); then the lessons, lessons/index.json (the course's
// menu), lessons/course.json (launch.js reads it), the launch page lesson.html (the
// playground's index.html that also runs launch.js) and imsmanifest.xml. Every path is
// relative inside the package: the page requests nothing outside its folder.

/** The package formats: SCORM 1.2, and SCORM 2004 4th edition. */
export const FORMATS = { scorm12: 'SCORM 1.2', scorm2004: 'SCORM 2004 4th edition' };

/** Where the build lists the playground's files (relative to www/). */
export const FILE_LIST = 'pkg-lesson/files.json';

/** The launch page in the package. */
export const LAUNCH = 'lesson.html';

/** The preset whose object is the Stanford bunny (figure/drawing.js loads its mesh). */
const BUNNY_PRESET = 'bunny6';

/**
 * Every file of the zip gets this time, so the same lessons make the same bytes: the earliest a
 * zip entry can hold (its DOS time starts in 1980), in local time because the zip stores local
 * time, so every machine writes the same fields.
 */
const ZIP_MTIME = new Date(1980, 0, 1);

/**
 * The build's file list (www/pkg-lesson/files.json): the playground's version, the page
 * template and the files of each group (paths relative to www/).
 * @typedef {{version: string, template: string, groups: Record<string, string[]>}} FileList
 */

/**
 * A file of the package: `path` in the zip and either `www` (a file of the playground to copy)
 * or `text` (made here).
 * @typedef {{path: string, www?: string, text?: string}} PackageFile
 */

const xml = (s) => String(s).replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;').replace(/"/g, '&quot;');

/** FNV-1a of `text` as 8 hex digits: a version tag that changes with the lessons. */
function tag(text) {
  let h = 0x811c9dc5;
  for (let i = 0; i < text.length; i++) h = Math.imul(h ^ text.charCodeAt(i), 0x01000193) >>> 0;
  return h.toString(16).padStart(8, '0');
}

/**
 * Reads lesson file `text` (named `file` in messages): the lesson object. Throws an Error naming
 * the file when it is not JSON or not a lesson; the page checks the rest when it opens it.
 */
export function readLesson(file, text) {
  let l;
  try {
    l = JSON.parse(text);
  } catch (e) {
    throw new Error(`${file}: not JSON (${e.message})`);
  }
  if (!l || typeof l !== 'object' || Array.isArray(l)) throw new Error(`${file}: not a lesson (expected an object with id, title and steps)`);
  if (typeof l.id !== 'string' || !/^[A-Za-z0-9_-]{1,64}$/.test(l.id)) throw new Error(`${file}: id: expected 1 to 64 letters, digits, _ or -`);
  if (typeof l.title !== 'string' || !l.title.trim()) throw new Error(`${file}: title: expected a non-empty string`);
  if (!Array.isArray(l.steps) || l.steps.length === 0) throw new Error(`${file}: steps: expected a non-empty list`);
  if (l.steps.some((s) => !s || typeof s !== 'object')) throw new Error(`${file}: steps: expected objects`);
  return l;
}

/** What lesson `l` needs besides the page: the analysis module, the bunny. */
export function lessonNeeds(l) {
  return {
    analysis: l.steps.some((s) => (typeof s.dock === 'string' && s.dock !== '') || s.exercise?.checks?.some((c) => c.kind === 'metric')),
    bunny: l.steps.some((s) => s.scene === BUNNY_PRESET),
  };
}

/** The mastery score `m` checked: null (no pass / fail) or a number in 0…1. */
export function checkMastery(m) {
  if (m === null || m === undefined || m === '') return null;
  const v = Number(m);
  if (!Number.isFinite(v) || v < 0 || v > 1) throw new Error(`mastery: expected a number from 0 to 1, got ${JSON.stringify(m)}`);
  return v;
}

/**
 * The files of a package of `lessons` ([{file, text}], in course order) in `format` (a key of
 * FORMATS) with `mastery` (0…1 or null), given the build's file `list` (FileList) and its
 * `template` (the text of index.html). `title` and `description` default to the lesson's (a
 * course: "ScrewBender course: N lessons" and the lesson titles). Returns {title, files}.
 * Throws an Error naming the problem (format, mastery, a lesson file, two lessons with one id).
 */
export function planPackage({ lessons, format, mastery = null, title = '', description = '', list, template }) {
  if (!FORMATS[format]) throw new Error(`format: expected one of ${Object.keys(FORMATS).join(', ')}, got ${JSON.stringify(format)}`);
  mastery = checkMastery(mastery);
  if (!lessons.length) throw new Error('no lesson given');
  const read = lessons.map(({ file, text }) => ({ file: file.split(/[\\/]/).pop(), text, lesson: readLesson(file, text) }));
  const ids = new Set();
  const names = new Set();
  for (const r of read) {
    if (ids.has(r.lesson.id)) throw new Error(`${r.file}: id "${r.lesson.id}" is already the id of another lesson of the package`);
    if (names.has(r.file) || r.file === 'index.json' || r.file === 'course.json' || r.file === 'tour.json') throw new Error(`${r.file}: another file of the package has this name`);
    ids.add(r.lesson.id);
    names.add(r.file);
  }
  const single = read.length === 1;
  title = title || (single ? read[0].lesson.title : `ScrewBender course: ${read.length} lessons`);
  description = description || (single ? read[0].lesson.summary ?? read[0].lesson.steps[0].title : read.map((r) => r.lesson.title).join('; '));
  const needs = read.map((r) => lessonNeeds(r.lesson));

  /** @type {PackageFile[]} */
  const files = [];
  const groups = ['page', ...(needs.some((n) => n.analysis) ? ['analysis'] : []), ...(needs.some((n) => n.bunny) ? ['bunny'] : [])];
  for (const g of groups) for (const p of list.groups[g] ?? []) files.push({ path: p, www: p });
  for (const r of read) files.push({ path: `lessons/${r.file}`, text: r.text });
  const course = {
    format,
    mastery,
    title,
    lessons: read.map((r) => ({
      id: r.lesson.id,
      file: r.file,
      title: r.lesson.title,
      steps: r.lesson.steps.length,
      exercises: r.lesson.steps.map((s, k) => (s.exercise ? k : -1)).filter((k) => k >= 0),
    })),
  };
  const index = { lessons: read.map((r) => ({ id: r.lesson.id, file: r.file, title: r.lesson.title, ...(r.lesson.summary ? { summary: r.lesson.summary } : {}) })) };
  files.push({ path: 'lessons/index.json', text: `${JSON.stringify(index, null, 2)}\n` });
  files.push({ path: 'lessons/course.json', text: `${JSON.stringify(course, null, 2)}\n` });
  files.push({ path: LAUNCH, text: launchPage(template, title) });
  const version = tag(read.map((r) => r.text).join('\n') + format + mastery);
  const paths = [...files.map((f) => f.path)].sort();
  files.push({ path: 'imsmanifest.xml', text: manifest({ format, mastery, title, description, version, playground: list.version, ids: [...ids], paths }) });
  return { title, files };
}

/** The launch page: the playground's index.html, titled `title`, that also runs launch.js. */
export function launchPage(template, title) {
  const tagMain = '<script type="module" src="js/main.js"></script>';
  const at = template.indexOf(tagMain);
  if (at < 0 || template.indexOf(tagMain, at + 1) >= 0) throw new Error(`index.html no longer has exactly one ${tagMain}; update www/js/lessons/package.js`);
  const page = `${template.slice(0, at + tagMain.length)}\n<script type="module" src="js/lessons/launch.js"></script>${template.slice(at + tagMain.length)}`;
  return page.replace(/<title>[^<]*<\/title>/, `<title>${xml(title)} — ScrewBender</title>`);
}

/** imsmanifest.xml of the package (see planPackage); `paths` are every file but the manifest. */
export function manifest({ format, mastery, title, description, version, playground, ids, paths }) {
  const id = `screwbender-${ids.join('-')}`.replace(/[^\w.-]/g, '_').slice(0, 200);
  const v12 = format === 'scorm12';
  const fileList = paths.map((p) => `      <file href="${xml(p)}"/>`).join('\n');
  const versionText = `${version} (ScrewBender ${playground})`;
  if (v12) {
    const masteryEl = mastery === null ? '' : `\n        <adlcp:masteryscore>${Math.round(mastery * 100)}</adlcp:masteryscore>`;
    return `<?xml version="1.0" encoding="UTF-8"?>
<manifest identifier="${xml(id)}" version="${version}"
  xmlns="http://www.imsproject.org/xsd/imscp_rootv1p1p2"
  xmlns:adlcp="http://www.adlnet.org/xsd/adlcp_rootv1p2"
  xmlns:imsmd="http://www.imsglobal.org/xsd/imsmd_rootv1p2p1">
  <metadata>
    <schema>ADL SCORM</schema>
    <schemaversion>1.2</schemaversion>
    <imsmd:lom>
      <imsmd:general>
        <imsmd:title><imsmd:langstring xml:lang="en">${xml(title)}</imsmd:langstring></imsmd:title>
        <imsmd:description><imsmd:langstring xml:lang="en">${xml(description)}</imsmd:langstring></imsmd:description>
      </imsmd:general>
      <imsmd:lifecycle>
        <imsmd:version><imsmd:langstring xml:lang="en">${xml(versionText)}</imsmd:langstring></imsmd:version>
      </imsmd:lifecycle>
    </imsmd:lom>
  </metadata>
  <organizations default="course">
    <organization identifier="course">
      <title>${xml(title)}</title>
      <item identifier="lesson" identifierref="player" isvisible="true">
        <title>${xml(title)}</title>${masteryEl}
      </item>
    </organization>
  </organizations>
  <resources>
    <resource identifier="player" type="webcontent" adlcp:scormtype="sco" href="${LAUNCH}">
${fileList}
    </resource>
  </resources>
</manifest>
`;
  }
  const masteryEl = mastery === null ? '' : `
        <imsss:sequencing>
          <imsss:objectives>
            <imsss:primaryObjective objectiveID="mastery" satisfiedByMeasure="true">
              <imsss:minNormalizedMeasure>${mastery}</imsss:minNormalizedMeasure>
            </imsss:primaryObjective>
          </imsss:objectives>
        </imsss:sequencing>`;
  return `<?xml version="1.0" encoding="UTF-8"?>
<manifest identifier="${xml(id)}" version="${version}"
  xmlns="http://www.imsglobal.org/xsd/imscp_v1p1"
  xmlns:adlcp="http://www.adlnet.org/xsd/adlcp_v1p3"
  xmlns:adlseq="http://www.adlnet.org/xsd/adlseq_v1p3"
  xmlns:adlnav="http://www.adlnet.org/xsd/adlnav_v1p3"
  xmlns:imsss="http://www.imsglobal.org/xsd/imsss">
  <metadata>
    <schema>ADL SCORM</schema>
    <schemaversion>2004 4th Edition</schemaversion>
    <lom xmlns="http://ltsc.ieee.org/xsd/LOM">
      <general>
        <title><string language="en">${xml(title)}</string></title>
        <description><string language="en">${xml(description)}</string></description>
      </general>
      <lifeCycle>
        <version><string language="en">${xml(versionText)}</string></version>
      </lifeCycle>
    </lom>
  </metadata>
  <organizations default="course">
    <organization identifier="course">
      <title>${xml(title)}</title>
      <item identifier="lesson" identifierref="player" isvisible="true">
        <title>${xml(title)}</title>${masteryEl}
      </item>
    </organization>
  </organizations>
  <resources>
    <resource identifier="player" type="webcontent" adlcp:scormType="sco" href="${LAUNCH}">
${fileList}
    </resource>
  </resources>
</manifest>
`;
}

/**
 * The zip of `files` (PackageFile[] with their bytes: {path, data: Uint8Array}), made with
 * `zipSync` (fflate's). Deflated at level 9, every entry dated ZIP_MTIME, in path order.
 */
export function packageZip(files, zipSync) {
  const tree = {};
  for (const f of [...files].sort((a, b) => (a.path < b.path ? -1 : a.path > b.path ? 1 : 0))) tree[f.path] = [f.data, { level: 9, mtime: ZIP_MTIME }];
  return zipSync(tree);
}
