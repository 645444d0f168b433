// The controls: lil-gui panel, toolbar, timeline, help overlay, paste dialog.
import GUI from '../../vendor/lil-gui.esm.min.js';
import { exportMotion, importFiles } from './files.js';
import { presetName, presetSubtitle } from './presets.js';

/** The largest strobe count the panel offers. */
const STROBE_MAX = 10000;
const SCHEMES = { 'Cubic B-spline': 'bspline', '4-point': 'fourpoint', Jarek: 'jarek', 'J_s (slider)': 'j' };
const RULES = { 'Direct (V2)': 'direct', 'Split & tweak (V1)': 'split' };
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

export function buildUi(app) {
  const $ = (id) => document.getElementById(id);
  const gui = new GUI({ title: 'ScrewBender', container: $('panel') });

  // Proxy object: lil-gui reads/writes these; setters route to the app as undoable edits.
  const p = {
    get scheme() { return app.motion.scheme; },
    set scheme(v) { v === 'j' ? app.setJ(0.25) : app.setScheme(v); },
    get j() { return app.motion.j; },
    set j(v) { app.setJ(v); },
    get rules() { return app.motion.rules; },
    set rules(v) { app.setOption('rules', v); },
    get levels() { return app.motion.levels; },
    set levels(v) { app.setOption('levels', v); },
    get closed() { return app.motion.closed; },
    set closed(v) { app.setClosed(v); },
    get strobe() { return app.parts.responsive.fullStrobe(); },
    set strobe(v) {
      if (Number.isFinite(v)) app.setView('strobe', Math.min(STROBE_MAX, Math.max(1, Math.round(v))));
    },
    // The slider is logarithmic: 1–10, 10–100, 100–1000 and 1000–10000 each take a quarter.
    get strobeLog() { return Math.log10(app.parts.responsive.fullStrobe()); },
    set strobeLog(v) { this.strobe = 10 ** v; },
    get object() { return app.view.object; },
    set object(v) {
      if (v === 'obj' && !app.imported) return $('obj-file').click();
      app.setView('object', v);
    },
  };
  const viewFlag = (key) => ({
    get [key]() { return app.view[key]; },
    set [key](v) { app.setView(key, v); },
  });

  const fMotion = gui.addFolder('Motion');
  // Presets by human name, with the paper's figure and a description each (editor/presets.js).
  const presetCtrl = fMotion.add({ choose: () => app.parts.presets.open(presetCtrl.$button) }, 'choose');
  fMotion.add(p, 'scheme', SCHEMES).name('Scheme');
  fMotion.add(p, 'j', 0, 1, 0.01).name('J_s').onFinishChange(() => {});
  fMotion.add(p, 'rules', RULES).name('Rules');
  fMotion.add(p, 'levels', 0, 8, 1).name('Levels');
  fMotion.add(p, 'closed').name('Closed cycle');

  const fView = gui.addFolder('Display');
  fView.add(p, 'object', OBJECTS).name('Object');
  const strobeSlider = fView.add(p, 'strobeLog', 0, Math.log10(STROBE_MAX), 0.001).name('Strobe (log scale)');
  strobeSlider.domElement.classList.add('log-slider');
  fView.add(p, 'strobe').name('Strobe count');
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
    exportCsv: () => exportMotion(app, 'csv', { tolerance: exportOpts.tolerance }),
    exportTrajectory: () => {
      const pts = app.bodyPoints();
      exportMotion(app, 'csv', { tolerance: exportOpts.tolerance, point: pts[pts.length - 1] });
    },
    importJson: () => $('json-file').click(),
    pasteJson: () => openPaste(),
    exportJson: () => app.exportJson(),
    importObj: () => $('obj-file').click(),
    share: async () => {
      const link = app.shareLink();
      try {
        await navigator.clipboard.writeText(link);
        toast('Share link copied to the clipboard.');
      } catch {
        openPaste(link, 'Share link (copy it):');
      }
    },
    reset: () => app.loadPreset(app.view.scene),
  };
  const fFile = gui.addFolder('File');
  fFile.add(actions, 'importFile').name('Import file (JSON, CSV, glTF, OBJ)…');
  fFile.add(actions, 'importJson').name('Import JSON…');
  fFile.add(actions, 'pasteJson').name('Paste JSON…');
  fFile.add(actions, 'exportJson').name('Export JSON');
  fFile.add(actions, 'exportGlb').name('Export glTF (.glb)');
  fFile.add(actions, 'exportGltf').name('Export glTF (.gltf + .bin)');
  fFile.add(actions, 'exportCsv').name('Export CSV (poses)');
  fFile.add(actions, 'exportTrajectory').name('Export CSV (body-point path)');
  fFile.add(exportOpts, 'tolerance', { '1 µm': 1e-6, '10 µm': 1e-5, '0.1 mm': 1e-4, '1 mm': 1e-3, '1 cm': 1e-2 }).name('Export tolerance (1 unit = 1 m)');
  fFile.add(actions, 'importObj').name('Import mesh (OBJ, glTF)…');
  fFile.add(actions, 'share').name('Copy share link');
  fFile.add(actions, 'reset').name('Reset preset');
  fFile.close();

  // File inputs.
  const readFile = (input, f) =>
    input.addEventListener('change', async () => {
      const file = input.files[0];
      input.value = '';
      if (!file) return;
      if (file.size > 64 << 20) return app.showError(`${file.name} is too large (${file.size} bytes). Nothing was changed.`);
      f(file);
    });
  readFile($('json-file'), async (file) => app.importJson(await file.text(), file.name));
  const any = $('any-file');
  any.addEventListener('change', async () => {
    const files = [...any.files];
    any.value = '';
    await importFiles(app, files);
  });
  readFile($('obj-file'), async (file) => {
    const name = file.name.toLowerCase();
    if (name.endsWith('.glb')) app.importMesh('gltf', new Uint8Array(await file.arrayBuffer()));
    else if (name.endsWith('.gltf')) app.importMesh('gltf', await file.text());
    else app.importMesh('obj', await file.text());
  });

  // Paste dialog.
  const dlg = $('paste');
  function openPaste(text = '', title = 'Paste a motion document (JSON):') {
    dlg.querySelector('h2').textContent = title;
    const ta = dlg.querySelector('textarea');
    ta.value = text;
    dlg.hidden = false;
    ta.focus();
    ta.select();
  }
  dlg.querySelector('[data-act=load]').onclick = () => {
    if (app.importJson(dlg.querySelector('textarea').value)) dlg.hidden = true;
  };
  dlg.querySelector('[data-act=cancel]').onclick = () => (dlg.hidden = true);

  // Toolbar.
  const tool = (id, f) => ($(id).onclick = f);
  tool('t-translate', () => app.setMode('translate'));
  tool('t-rotate', () => app.setMode('rotate'));
  tool('t-insert', () => app.insertAfterSelected());
  tool('t-delete', () => app.deleteSelected());
  tool('t-undo', () => app.undo());
  tool('t-redo', () => app.redo());
  tool('t-frame', () => app.frameAll());
  tool('t-help', () => toggleHelp());
  tool('t-snap', () => app.setView('snap', !app.view.snap));
  $('help').querySelector('.help-close').onclick = () => toggleHelp(false);
  tool('t-dock', () => app.openView(app.view.dock ? '' : app.lastView ?? firstView()));
  tool('play', () => app.setPlaying(!app.anim.playing));
  $('banner').querySelector('.close').onclick = () => ($('banner').hidden = true);

  // Timeline.
  const scrub = $('scrub');
  scrub.addEventListener('input', () => {
    const [a, b] = app.motion.domain();
    app.anim.u = a + (b - a) * (scrub.value / 1000);
    app.anim.visible = true;
    app.updateAnim();
    app.requestDraw();
  });
  const speed = $('speed');
  speed.addEventListener('input', () => (app.anim.speed = Number(speed.value)));
  const loop = $('loop');
  loop.addEventListener('change', () => (app.anim.loop = loop.checked));

  function firstView() {
    return document.querySelector('#dock .tabs button')?.dataset.view ?? '';
  }

  /** Shows or hides the help overlay; the focus goes to its close button and back. */
  let focusBeforeHelp = null;
  function toggleHelp(show) {
    const h = $('help');
    const wasHidden = h.hidden;
    h.hidden = show === undefined ? !h.hidden : !show;
    if (wasHidden && !h.hidden) {
      focusBeforeHelp = document.activeElement;
      h.querySelector('.help-close').focus();
    } else if (!wasHidden && h.hidden && h.contains(document.activeElement)) {
      (focusBeforeHelp ?? app.canvas)?.focus?.();
    }
  }
  $('help').onclick = (e) => {
    if (e.target === $('help')) toggleHelp(false);
  };

  function toast(msg) {
    const t = $('toast');
    t.textContent = msg;
    t.hidden = false;
    clearTimeout(toast.timer);
    toast.timer = setTimeout(() => (t.hidden = true), 2500);
  }

  function refresh() {
    for (const c of gui.controllersRecursive()) c.updateDisplay();
    const info = app.sceneInfo;
    const named = app.scenes.find((s) => s.id === app.view.scene);
    // A motion from a file (its name is not the preset's) is titled by the file.
    const fileName = app.motion.name && app.motion.name !== app.view.scene ? app.motion.name : null;
    const fileScene = fileName && app.scenes.find((s) => s.id === fileName);
    $('scene-title').textContent = fileName
      ? (fileScene ? presetName(fileScene) : fileName)
      : named && app.view.object === 'scene' ? presetName(named) : `${info.label} · ${info.figure}`;
    $('scene-fig').textContent = named ? presetSubtitle(named) : '';
    presetCtrl.name(`Preset: ${named ? presetName(named) : info.label} …`);
    $('scene-desc').textContent = info.description;
    const m = app.motion;
    $('stats').textContent =
      `${m.poseCount} control poses · ${m.refinedCount.toLocaleString()} refined · ` +
      (app.parts.responsive.reduced
        ? `${app.parts.responsive.fullStrobe().toLocaleString()} strobe (${app.view.strobe.toLocaleString()} while moving)`
        : `${app.view.strobe.toLocaleString()} strobe`) +
      (app.selected >= 0 ? ` · pose ${app.selected} selected` : '');
    $('t-translate').classList.toggle('on', app.mode === 'translate');
    $('t-rotate').classList.toggle('on', app.mode === 'rotate');
    $('t-snap').classList.toggle('on', !!app.view.snap);
    $('t-undo').disabled = !app.history.canUndo;
    $('t-redo').disabled = !app.history.canRedo;
    $('t-delete').disabled = app.selected < 0;
    $('t-dock').classList.toggle('on', !!app.view.dock);
    if (app.view.dock) app.lastView = app.view.dock;
    // Frames follow a change: measure them, and keep the pose numbers on their handles.
    app.parts.responsive.sample();
    app.parts.labels.place();
    $('play').textContent = app.anim.playing ? '❚❚' : '▶';
    $('play').title = app.anim.playing ? 'Pause (Space)' : 'Play (Space)';
    $('play').setAttribute('aria-label', app.anim.playing ? 'Pause' : 'Play');
    for (const id of ['t-translate', 't-rotate', 't-snap', 't-dock']) $(id).setAttribute('aria-pressed', String($(id).classList.contains('on')));
    speed.value = app.anim.speed;
    loop.checked = app.anim.loop;
    loop.disabled = m.closed;
    const [a, b] = m.domain();
    setTime(app.anim.u, a, b);
    app.parts.pose.refresh();
  }

  function setTime(u, a, b) {
    scrub.value = String(Math.round(((u - a) / (b - a)) * 1000));
    $('time').textContent = `u = ${u.toFixed(2)} / ${b}`;
    app.parts.pose.setTime(u);
  }

  // Small screens: start with the panel folded so the view stays visible.
  if (window.innerWidth < 760 || window.innerHeight < 500) gui.close();
  refresh();
  return { gui, refresh, setTime, toggleHelp, toast };
}
