// The settings panel (lil-gui): Motion, Display, Pose and File folders, and the file inputs the
// File folder opens. The panel's controls read the App's state and change it through the App's
// commands (each an undoable edit).
import GUI from '../../vendor/lil-gui.esm.min.js';
import { exportMotion, importFiles } from './files.js';
import { presetName } from './presets.js';
import { openShare } from './modules.js';
import { smallScreen } from './fold.js';
import { describeScene } from './status.js';

/** The largest strobe count the panel offers. */
const STROBE_MAX = 10000;
const SCHEMES = { 'Cubic B-spline': 'bspline', '4-point': 'fourpoint', Jarek: 'jarek', 'J_s (slider)': 'j' };
// The rule sets' display names, as the core's `frontend::rules_display` words them.
const RULES = { 'direct (V2)': 'direct', 'split-then-tweak (V1)': 'split' };
const OBJECTS = {
  "Preset's object": 'scene',
  Bar: 'bar',
  Block: 'block',
  Cylinder: 'cylinder',
  Cone: 'cone',
  Sphere: 'sphere',
  'Star prism': 'star',
  Pendulum: 'pendulum',
  Wedge: 'wedge',
  'Imported mesh': 'obj',
};

/**
 * Builds the panel into #panel; `openPaste(text?, title?)` opens the paste dialog (File → Paste
 * JSON). Returns {gui, refresh}.
 * @param {import('../app.js').App} app
 * @param {{openPaste: (text?: string, title?: string) => void}} dialogs
 */
export function buildPanel(app, { openPaste }) {
  const $ = (id) => document.getElementById(id);
  const gui = new GUI({ title: 'ScrewBender', container: $('panel') });

  // Proxy object: lil-gui reads/writes these; setters route to the app as undoable edits.
  const p = {
    get scheme() { return app.motion.scheme; },
    set scheme(v) { v === 'j' ? app.run('setS', 0.25) : app.run('setScheme', v); },
    get s() { return app.motion.s; },
    set s(v) { app.run('setS', v); },
    get rules() { return app.motion.rules; },
    set rules(v) { app.run('setOption', 'rules', v); },
    get levels() { return app.motion.levels; },
    set levels(v) { app.run('setOption', 'levels', v); },
    get closed() { return app.motion.closed; },
    set closed(v) { app.run('setClosed', v); },
    get strobe() { return app.parts.responsive.fullStrobe(); },
    set strobe(v) {
      if (Number.isFinite(v)) app.run('setView', 'strobe', Math.min(STROBE_MAX, Math.max(1, Math.round(v))));
    },
    // The slider is logarithmic: 1–10, 10–100, 100–1000 and 1000–10000 each take a quarter.
    get strobeLog() { return Math.log10(app.parts.responsive.fullStrobe()); },
    set strobeLog(v) { this.strobe = 10 ** v; },
    get object() { return app.view.object; },
    set object(v) {
      if (v === 'obj' && !app.imported) {
        $('obj-file').click();
        return;
      }
      app.run('setView', 'object', v);
    },
  };
  /** @type {(key: string) => Record<string, boolean>} */
  const viewFlag = (key) => ({
    get [key]() { return app.view[key]; },
    set [key](v) { app.run('setView', key, v); },
  });

  const fMotion = gui.addFolder('Motion');
  // Presets by human name, with the paper's figure and a description each (editor/presets.js).
  const presetCtrl = fMotion.add({ choose: () => app.parts.presets.open(/** @type {any} */ (presetCtrl).$button) }, 'choose');
  fMotion.add(p, 'scheme', SCHEMES).name('Scheme');
  fMotion.add(p, 's', 0, 1, 0.01).name('J_s').onFinishChange(() => {});
  fMotion.add(p, 'rules', RULES).name('Rules');
  fMotion.add(p, 'levels', 0, 8, 1).name('Levels');
  fMotion.add(p, 'closed').name('Closed cycle');

  const fView = gui.addFolder('Display');
  fView.add(p, 'object', OBJECTS).name('Object');
  const strobeSlider = fView.add(p, 'strobeLog', 0, Math.log10(STROBE_MAX), 0.001).name('Strobe (log scale)');
  strobeSlider.domElement.classList.add('log-slider');
  fView.add(p, 'strobe').name('Strobe count');
  /** @type {[string, string][]} */
  const flags = [
    ['showStrobe', 'Strobe'],
    ['showControl', 'Control poses'],
    ['showTriads', 'Pose axes'],
    ['showPoseNumbers', 'Pose numbers'],
    ['showTrajectories', 'Trajectories'],
    ['showPolyscrew', 'Polyscrew (unsmoothed)'],
    ['showPolygon', 'Control polygon'],
    ['showGrid', 'Grid & axes'],
    ['snap', 'Snap (button, or hold Shift)'],
    ['gizmoLocal', 'Gizmo in the pose\'s own axes (Q)'],
  ];
  for (const [key, label] of flags) fView.add(viewFlag(key), key).name(label);

  // The selected pose in numbers and the playhead readout (editor/pose.js).
  const fPose = gui.addFolder('Pose');
  app.parts.pose.build(fPose.$children);

  const exportOpts = { tolerance: 1e-4 };
  const actions = {
    importFile: () => $('any-file').click(),
    exportGlb: () => exportMotion(app, 'glb', { tolerance: exportOpts.tolerance }),
    exportGltf: () => exportMotion(app, 'gltf', { tolerance: exportOpts.tolerance }),
    exportControlCsv: () => app.parts.files.exportControlCsv(),
    exportCsv: () => exportMotion(app, 'csv', { tolerance: exportOpts.tolerance }),
    exportTrajectory: () => {
      const pts = app.viewer.bodyPoints();
      exportMotion(app, 'csv', { tolerance: exportOpts.tolerance, point: pts[pts.length - 1] });
    },
    importJson: () => $('json-file').click(),
    pasteJson: () => openPaste(),
    exportJson: () => app.parts.files.exportJson(),
    importObj: () => $('obj-file').click(),
    share: () => openShare(app),
    reset: () => app.run('loadPreset', app.view.scene),
  };
  const fFile = gui.addFolder('File');
  fFile.add(actions, 'importFile').name('Import file (JSON, CSV, glTF, OBJ)…');
  fFile.add(actions, 'importJson').name('Import JSON…');
  fFile.add(actions, 'pasteJson').name('Paste JSON…');
  fFile.add(actions, 'exportJson').name('Export JSON');
  fFile.add(actions, 'exportGlb').name('Export glTF (.glb)');
  fFile.add(actions, 'exportGltf').name('Export glTF (.gltf + .bin)');
  fFile.add(actions, 'exportControlCsv').name('Export CSV (control poses)');
  fFile.add(actions, 'exportCsv').name('Export CSV (samples of the motion)');
  fFile.add(actions, 'exportTrajectory').name('Export CSV (body-point path)');
  fFile.add(exportOpts, 'tolerance', { '1 µm': 1e-6, '10 µm': 1e-5, '0.1 mm': 1e-4, '1 mm': 1e-3, '1 cm': 1e-2 }).name('Export tolerance (1 unit = 1 m)');
  fFile.add(actions, 'importObj').name('Import mesh (OBJ, glTF)…');
  fFile.add(actions, 'share').name('Share & embed…');
  fFile.add(actions, 'reset').name('Reset preset');
  fFile.close();

  // File inputs.
  const readFile = (input, f) =>
    input.addEventListener('change', async () => {
      const file = input.files[0];
      input.value = '';
      if (!file) return;
      if (file.size > 64 << 20) return app.parts.notices.show(`${file.name} is too large (${file.size} bytes). Nothing was changed.`);
      f(file);
    });
  readFile($('json-file'), async (file) => app.parts.files.importJson(await file.text(), file.name));
  const any = /** @type {HTMLInputElement} */ ($('any-file'));
  any.addEventListener('change', async () => {
    const files = [...any.files];
    any.value = '';
    await importFiles(app, files);
  });
  readFile($('obj-file'), async (file) => {
    const name = file.name.toLowerCase();
    if (name.endsWith('.glb')) app.parts.files.importMesh('gltf', new Uint8Array(await file.arrayBuffer()));
    else if (name.endsWith('.gltf')) app.parts.files.importMesh('gltf', await file.text());
    else app.parts.files.importMesh('obj', await file.text());
  });

  /** Shows the state: every control's value and the preset button's name. */
  function refresh() {
    for (const c of gui.controllersRecursive()) c.updateDisplay();
    const { described, fileName, info } = describeScene(app);
    presetCtrl.name(`Preset: ${described ? presetName(described) : fileName ? 'none' : info.label} …`);
  }

  // Small screens: start with the panel folded so the view stays visible.
  if (smallScreen()) gui.close();
  return { gui, refresh };
}
