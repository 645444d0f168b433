// Files in and out of the playground: motion documents and sessions (JSON), meshes (OBJ, glTF),
// exports (glTF .glb / .gltf + .bin, CSV of the control poses or of samples, JSON) and
// drag-and-drop import.
//
// Export and import go through the same core functions as `screwbender export` / `import`
// (Motion.exportFile, importMotionFile: the analysis module's, fetched for the first file in or
// out; OBJ and glTF objects the renderer module reads itself), so a file written here equals the
// CLI's. Every import is one undoable edit, and a failed one changes nothing. The functions take the app; the
// default export is the app's part (see app.js for the part contract).
import { IMPORT_SIZE, BUNNY_PRESET, fetchBunny } from '../figure/drawing.js';
import { SLOT } from '../figure/slots.js';
import { MAX_SAVED_MESH } from './session.js';
import { SESSION_VERSION } from '../share-link.js';
import { askReduction, MANY_POSES } from './reduce-dialog.js';
import { showImported } from './commands.js';

/** Largest file the page reads (the core refuses more than 64 MiB as well). */
export const MAX_IMPORT_BYTES = 64 << 20;
/** Largest mesh file accepted by the page (the core also checks MAX_OBJ_BYTES / MAX_GLTF_BYTES). */
export const MAX_MESH_BYTES = 32 << 20;

/** Saves bytes as a download. */
export function download(name, data, type) {
  const url = URL.createObjectURL(new Blob([data], { type }));
  const a = document.createElement('a');
  a.href = url;
  a.download = name;
  a.click();
  setTimeout(() => URL.revokeObjectURL(url), 1000);
}

/** base64 → bytes (imported glTF meshes are kept as base64 in the session). */
function fromBase64(text) {
  const bin = atob(text);
  return Uint8Array.from(bin, (c) => c.charCodeAt(0));
}

/** True when the view draws the Stanford bunny (preset bunny6 with its own object). */
const showsBunny = (app) => app.view.object === 'scene' && app.view.scene === BUNNY_PRESET;

/**
 * The export settings of the current view: the object as drawn (the motion carries its timing).
 * A preset's own object is `scene:<id>`, which the core turns into what the command line draws
 * for that preset (its morph, or the bunny from `bunny`, the OBJ text the view draws it from).
 * @param {any} app
 * @param {string} format
 * @param {Record<string, any>} [extra]
 * @param {string | null} [bunny]
 */
export function exportSettings(app, format, extra = {}, bunny = null) {
  /** @type {Record<string, any>} */
  const s = { format, ...extra };
  if (format !== 'csv') {
    const v = app.view;
    if (v.object === 'obj' && app.imported) {
      const m = app.imported;
      s.mesh = { kind: m.kind, data: m.kind === 'gltf' ? fromBase64(m.data) : m.data, size: IMPORT_SIZE };
    } else s.object = v.object === 'scene' ? `scene:${v.scene}` : v.object;
    if (bunny && showsBunny(app)) s.bunny = bunny;
  }
  // The key times and velocities come with the motion's document (motion.times, .velocities).
  s.name = app.motion.name ?? app.view.scene ?? 'motion';
  return s;
}

/**
 * Exports the motion; resolves to the ExportedFile (tests read it) or null after showing the
 * error. `download: false` only builds the file. Motion.exportFile is the analysis module's
 * (editor/modules.js): the first export fetches it, with a toast meanwhile.
 */
export async function exportMotion(app, format, extra = {}, { save = true } = {}) {
  let file;
  try {
    if (!app.motion.exportFile) {
      app.ui?.toast('Loading the file writer…');
      await app.analysis();
    }
    // The bunny's file is in the HTTP cache once the view drew it; where it cannot be read,
    // the view shows the wedge, and so does the file.
    const bunny = format !== 'csv' && showsBunny(app) ? await fetchBunny().catch(() => null) : null;
    file = app.motion.exportFile(exportSettings(app, format, extra, bunny));
  } catch (e) {
    app.parts.notices.show(`Export failed: ${e.message}`);
    return null;
  }
  if (save) {
    download(file.fileName, file.data, file.mimeType);
    if (file.bin) download(file.binName, file.bin, 'application/octet-stream');
  }
  const what = format === 'csv' ? 'rows' : 'keyframes';
  const how = extra.fps ? `${extra.fps} fps` : `tolerance ${extra.tolerance ?? 1e-4}`;
  app.ui?.toast(`${file.fileName}${file.bin ? ` + ${file.binName}` : ''}: ${file.sampleCount} ${what} (${how})`);
  return file;
}

const ext = (name) => (name.toLowerCase().match(/\.([a-z0-9]+)$/) ?? [])[1] ?? '';

/**
 * Imports dropped or chosen files. A .json is a motion document or a saved session; a .csv, or a
 * .glb / .gltf with an animation (or a .gltf with its .bin dropped along), sets the control
 * poses; a .glb / .gltf without animation or an .obj becomes the object's mesh. Every failure
 * shows one message naming the file, and nothing changes. Returns true when something was
 * imported.
 */
export async function importFiles(app, fileList) {
  const files = [...fileList];
  if (files.length === 0) return false;
  for (const f of files) {
    if (f.size > MAX_IMPORT_BYTES) {
      app.parts.notices.show(`${f.name} is ${f.size} bytes; the limit is ${MAX_IMPORT_BYTES} bytes. Nothing was changed.`);
      return false;
    }
  }
  // Buffers (.bin and others) go along with a .gltf; the main file is the first other one.
  const main = files.find((f) => ['json', 'csv', 'glb', 'gltf', 'obj'].includes(ext(f.name)));
  if (!main) {
    app.parts.notices.show(`${files.map((f) => f.name).join(', ')}: unknown file type (expected .json, .csv, .glb, .gltf or .obj). Nothing was changed.`);
    return false;
  }
  const kind = ext(main.name);
  if (kind === 'json') return app.parts.files.importJson(await main.text(), main.name);
  if (kind === 'obj') return app.parts.files.importMesh('obj', await main.text(), main.name);
  const bytes = new Uint8Array(await main.arrayBuffer());
  const buffers = {};
  for (const f of files) if (f !== main) buffers[f.name] = new Uint8Array(await f.arrayBuffer());
  // Reading motions from glTF and CSV is the analysis module's (fetched on the first import).
  let importer;
  try {
    importer = app.loadedAnalysis() ?? (await fetchAnalysis(app));
  } catch (e) {
    app.parts.notices.show(`Import failed, nothing was changed: ${e.message}`);
    return false;
  }
  let doc;
  try {
    doc = importer.importMotionFile(main.name, bytes, buffers);
  } catch (e) {
    // A glTF without animation may be a mesh for the object.
    if (kind !== 'csv' && /anim/i.test(e.message)) {
      const data = kind === 'gltf' ? new TextDecoder().decode(bytes) : bytes;
      return app.parts.files.importMesh('gltf', data, main.name, `Import failed, nothing was changed: ${e.message}`);
    }
    app.parts.notices.show(`Import failed, nothing was changed: ${e.message}`);
    return false;
  }
  // A glTF file's own object comes along (its mesh, if it has one).
  let mesh = null;
  if (kind !== 'csv') {
    try {
      if (importer.importedMesh(main.name, bytes)) mesh = meshOf('gltf', bytes);
    } catch {
      mesh = null; // an animation without a readable mesh: the current object stays
    }
  }
  return importPoses(app, doc, main.name, mesh);
}

/**
 * Imports the poses of `doc` (read from `fileName`; `mesh`: its own object or null): more than
 * MANY_POSES (samples of a motion, an exported CSV, a lesson's measured poses) first ask whether
 * to keep, thin or fit them (editor/reduce-dialog.js). Resolves true when something was imported.
 */
async function importPoses(app, doc, fileName, mesh = null) {
  let kept = null;
  let fit = null;
  if (doc.poses.length > MANY_POSES) {
    if (document.getElementById('reduce-dialog')) {
      app.parts.notices.show(`${fileName}: another import is waiting for an answer; nothing was changed.`);
      return false;
    }
    // Thinning and fitting are the analysis module's; where it has loaded (a lesson with
    // measured poses fetches it as it opens) the dialog opens at once, in the same task.
    let analysis = app.loadedAnalysis();
    if (!analysis) {
      try {
        analysis = await fetchAnalysis(app);
      } catch (e) {
        app.parts.notices.show(`Import failed, nothing was changed: ${fileName}: ${e.message}`);
        return false;
      }
      if (document.getElementById('reduce-dialog')) {
        app.parts.notices.show(`${fileName}: another import is waiting for an answer; nothing was changed.`);
        return false;
      }
    }
    const radius = Math.max(1e-3, ...app.viewer.bodyPoints().map((p) => Math.hypot(...p)));
    const fitPoses = async (d, o) => analysis.fitPoses(d, o);
    const choice = await askReduction(doc, fileName, radius, analysis.reducePoses, fitPoses);
    if (!choice) {
      app.parts.notices.show(`${fileName}: import cancelled, nothing was changed.`, 'info');
      return false;
    }
    doc = choice.doc;
    kept = choice.how;
    fit = choice.fit ?? null;
  }
  const ok = importDocument(app, doc, fileName, mesh, fit);
  if (ok && kept) app.parts.notices.show(`${fileName}: ${kept}.`, 'info');
  return ok;
}

/**
 * Fetches the analysis module, which reads motions from files (importMotionFile, importedMesh)
 * and thins or fits many poses, with a toast meanwhile (app.loadedAnalysis() has it once there).
 */
function fetchAnalysis(app) {
  app.ui?.toast('Loading the file reader…');
  return app.analysis();
}

/** The session form of a mesh file: OBJ text, or glTF bytes as base64. */
function meshOf(kind, data) {
  if (kind !== 'gltf') return { kind: 'obj', data };
  const bytes = typeof data === 'string' ? new TextEncoder().encode(data) : data;
  let bin = '';
  for (let i = 0; i < bytes.length; i += 0x8000) bin += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return { kind: 'gltf', data: btoa(bin) };
}

/** Drop target: the whole window, with a highlight while files hover. */
export function bindDrop(app) {
  const overlay = document.getElementById('drop');
  let depth = 0;
  const hasFiles = (e) => [...(e.dataTransfer?.types ?? [])].includes('Files');
  window.addEventListener('dragenter', (e) => {
    if (!hasFiles(e)) return;
    e.preventDefault();
    depth++;
    overlay.hidden = false;
  });
  window.addEventListener('dragover', (e) => {
    if (!hasFiles(e)) return;
    e.preventDefault();
    e.dataTransfer.dropEffect = 'copy';
  });
  window.addEventListener('dragleave', () => {
    depth = Math.max(0, depth - 1);
    if (depth === 0) overlay.hidden = true;
  });
  window.addEventListener('drop', (e) => {
    if (!hasFiles(e)) return;
    e.preventDefault();
    depth = 0;
    overlay.hidden = true;
    importFiles(app, e.dataTransfer.files);
  });
}

/** Imports JSON text: a saved session (from Export) or a plain motion document. */
function importJson(app, text, fileName = 'JSON') {
  if (text.length > app.limits.maxDocumentBytes) {
    return app.parts.notices.show(`${fileName} is ${text.length} bytes; the limit is ${app.limits.maxDocumentBytes} bytes. Nothing was changed.`);
  }
  let motion;
  try {
    const trimmed = text.trim();
    // Invalid JSON falls through to the core's parser, whose message names line and column.
    let obj = null;
    try {
      obj = JSON.parse(trimmed);
    } catch {
      obj = null;
    }
    if (obj && obj.version === SESSION_VERSION && obj.document) {
      // Validated before the edit, so that a bad session is an import error, not an edit error.
      new app.wasm.Motion(obj.document, obj.options).free();
      app.parts.session.edit(() => app.parts.session.applySession({ ...obj, camera: undefined }));
      return true;
    }
    motion = app.wasm.Motion.fromJson(trimmed, app.motion.options());
  } catch (e) {
    app.parts.notices.show(`Import failed, nothing was changed: ${fileName}: ${e.message}`);
    return false;
  }
  return replaceMotion(app, motion);
}

/**
 * Imports a motion document (from importMotionFile); the subdivision options are kept. `mesh`
 * (a glTF file's own object, {kind, data}) becomes the object, in the same undoable edit.
 * `fit` ({scheme}: the scheme its control poses were fitted for, or null) marks a fitted
 * document, loaded by the command loadFit (labelled with its control-pose count).
 */
function importDocument(app, doc, fileName, mesh = null, fit = null) {
  let motion;
  try {
    motion = new app.wasm.Motion(doc, app.motion.options());
    // Validated before the edit: a mesh the renderer refuses is left out, not half applied.
    if (mesh) app.viewer.setImportedMesh(SLOT.anim, mesh);
  } catch (e) {
    if (mesh) app.viewer.meshesChanged();
    motion?.free();
    app.parts.notices.show(`Import failed, nothing was changed: ${fileName}: ${e.message}`);
    return false;
  }
  const what = `${motion.poseCount} control poses (${motion.closed ? 'cycle' : 'open'})`;
  let ok;
  if (fit) {
    motion.free();
    ok = app.run('loadFit', doc, fit.scheme, mesh) === true;
  } else ok = replaceMotion(app, motion, mesh);
  if (ok) app.ui?.toast(`${fileName}: ${what}`);
  return ok;
}

/** Replaces the motion by `motion` as one undoable edit (the view frames the new poses). */
function replaceMotion(app, motion, mesh = null) {
  app.parts.session.edit(() => showImported(app, motion, mesh));
  return true;
}

/** Imports a mesh file: OBJ text or glTF (`.gltf` text / `.glb` bytes as a Uint8Array). */
function importMesh(app, kind, data, fileName = 'mesh', failure = null) {
  const size = typeof data === 'string' ? data.length : data.byteLength;
  if (size > MAX_MESH_BYTES) {
    app.parts.notices.show(`The mesh file is over ${MAX_MESH_BYTES >> 20} MiB. Nothing was changed.`);
    return false;
  }
  const mesh = meshOf(kind, data);
  try {
    // Validate into the animation slot first; on failure nothing changed.
    app.viewer.setImportedMesh(SLOT.anim, mesh);
  } catch (e) {
    app.viewer.meshesChanged();
    app.parts.notices.show(failure ? `${failure}; read as a mesh: ${e.message}` : `Mesh import failed, nothing was changed: ${fileName}: ${e.message}`);
    return false;
  }
  app.parts.session.edit(() => {
    app.setImported(mesh);
    app.updateView({ object: 'obj' });
    app.viewer.meshesChanged();
  });
  if (mesh.data.length > MAX_SAVED_MESH) {
    app.parts.notices.show('The mesh is too large to be autosaved or shared; it will be lost on reload.', 'warn');
  }
  return true;
}

function exportJson(app) {
  download(`${app.motion.name ?? app.view.scene ?? 'motion'}.json`, app.motion.toJson(), 'application/json');
}

/**
 * The design as CSV: the control poses with their key times and velocities (a cycle's pose 0
 * again at its end time), which an import reads back to the same document. Returns the text.
 */
function exportControlCsv(app, { save = true } = {}) {
  const text = app.motion.controlPosesCsv();
  const name = `${app.motion.name ?? app.view.scene ?? 'motion'}-control-poses.csv`;
  if (save) download(name, text, 'text/csv');
  const m = app.motion;
  app.ui?.toast(`${name}: ${m.poseCount} control poses${m.closed ? ' (a cycle: pose 0 again at the end)' : ''}, with their times and velocities`);
  return { fileName: name, data: text };
}

/** @type {import('../app.js').Part} */
export default {
  id: 'files',
  create(app) {
    return {
      /** Makes the window a drop target (once the page runs). */
      bind: () => bindDrop(app),
      importJson: (text, fileName) => importJson(app, text, fileName),
      importDocument: (doc, fileName, mesh) => importDocument(app, doc, fileName, mesh),
      importPoses: (doc, fileName, mesh) => importPoses(app, doc, fileName, mesh),
      importMesh: (kind, data, fileName, failure) => importMesh(app, kind, data, fileName, failure),
      exportJson: () => exportJson(app),
      exportControlCsv: (options) => exportControlCsv(app, options),
    };
  },
};
