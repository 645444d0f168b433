// The controls: lil-gui panel, toolbar, timeline, help overlay, paste dialog.
import GUI from '../../vendor/lil-gui.esm.min.js';
import { exportMotion, importFiles } from './files.js';
import { VIEW_IDS } from '../views/index.js';
import { presetName, presetSubtitle } from './presets.js';
import { openShareDialog } from './share-dialog.js';
import { smallScreen } from './fold.js';

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
    set scheme(v) { v === 'j' ? app.setS(0.25) : app.setScheme(v); },
    get s() { return app.motion.s; },
    set s(v) { app.setS(v); },
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
  fMotion.add(p, 's', 0, 1, 0.01).name('J_s').onFinishChange(() => {});
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
    exportControlCsv: () => app.parts.files.exportControlCsv(),
    exportCsv: () => exportMotion(app, 'csv', { tolerance: exportOpts.tolerance }),
    exportTrajectory: () => {
      const pts = app.bodyPoints();
      exportMotion(app, 'csv', { tolerance: exportOpts.tolerance, point: pts[pts.length - 1] });
    },
    importJson: () => $('json-file').click(),
    pasteJson: () => openPaste(),
    exportJson: () => app.exportJson(),
    importObj: () => $('obj-file').click(),
    share: () => openShareDialog(app),
    reset: () => app.loadPreset(app.view.scene),
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
  tool('t-frame', () => app.parts.viewpoint.frame());
  tool('t-help', () => toggleHelp());
  tool('m-share', () => {
    app.parts.viewpoint.menu.close();
    openShareDialog(app, $('t-view'));
  });
  tool('t-snap', () => app.setView('snap', !app.view.snap));
  $('help').querySelector('.help-close').onclick = () => toggleHelp(false);
  tool('t-dock', () => app.openView(app.view.dock ? '' : app.lastView ?? firstView()));
  tool('play', () => app.setPlaying(!app.anim.playing));
  $('banner').querySelector('.close').onclick = () => ($('banner').hidden = true);

  // Timeline: the scrubber runs over the playback interval in seconds (the motion's own key
  // times); the key markers above it retime the motion.
  const scrub = $('scrub');
  scrub.addEventListener('input', () => {
    const [a, b] = app.motion.timeDomain();
    app.seekTime(a + (b - a) * (scrub.value / 1000));
  });
  const keyMarkers = buildKeyMarkers(app, $('keys'));
  const speed = $('speed');
  speed.addEventListener('input', () => (app.anim.speed = Number(speed.value)));
  const loop = $('loop');
  loop.addEventListener('change', () => (app.anim.loop = loop.checked));

  function firstView() {
    return document.querySelector('#dock .tabs button')?.dataset.view ?? VIEW_IDS[0];
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
    // A file's motion is described by the preset it names, if any: not by the last preset
    // loaded, whose figure and words would be stale.
    const described = fileName ? fileScene : named;
    $('scene-title').textContent = fileName
      ? (fileScene ? presetName(fileScene) : fileName)
      : named && app.view.object === 'scene' ? presetName(named) : `${info.label} · ${info.figure}`;
    $('scene-fig').textContent = described ? presetSubtitle(described) : '';
    presetCtrl.name(`Preset: ${described ? presetName(described) : fileName ? 'none' : info.label} …`);
    $('scene-desc').textContent = fileName ? (fileScene?.description ?? '') : info.description;
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
    keyMarkers.place();
    const [a, b] = m.domain();
    setTime(app.anim.u, a, b, app.viewer.playhead());
    app.parts.pose.refresh();
  }

  /** The playhead moved: u in [a, b], and `playhead` {t, start, end} in seconds. */
  function setTime(u, a, b, playhead) {
    const { t, start, end } = playhead;
    scrub.value = String(Math.round(((t - start) / (end - start)) * 1000));
    $('time').textContent = `t = ${t.toFixed(2)} s · u = ${u.toFixed(2)}`;
    $('time').title = `Time ${t.toFixed(3)} s of ${start.toFixed(2)}–${end.toFixed(2)} s; motion parameter u = ${u.toFixed(3)} of ${a}–${b}`;
    scrub.setAttribute('aria-valuetext', `${t.toFixed(2)} seconds, u = ${u.toFixed(2)}`);
    app.parts.pose.setTime(u);
  }

  // Small screens: start with the panel folded so the view stays visible.
  if (smallScreen()) gui.close();
  refresh();
  return { gui, refresh, setTime, toggleHelp, toast };
}

/** Arrow-key steps of a focused key marker (seconds): plain and with Shift. */
const KEY_STEP = 0.1;
const KEY_STEP_FINE = 0.01;
/** Marker drags snap to this step (seconds). */
const DRAG_SNAP = 0.01;

/**
 * The key markers of the timeline: one per key time (a cycle's last is its return to pose 0),
 * placed on the scrubber's scale. Dragging one (mouse, pen or touch) retimes that key with a
 * live preview and makes one undoable edit on release; arrow keys move a focused marker by 0.1 s
 * (Shift: 0.01 s), a run of presses on one marker making one undo step (a new step after a
 * second idle (session.js MERGE_IDLE_MS), a blur or another marker, as editors merge typing). Times must keep
 * increasing: a move past a neighbouring key is refused with a message and changes nothing (a
 * drag is then over until the next press).
 *
 * Touch: each marker's hit box is 44 px (style.css), wider than the gap between close keys;
 * where boxes overlap, a press goes to the marker whose centre is nearest to it (the boxes are
 * in effect split at the midpoints between neighbours), not to the one drawn on top.
 */
function buildKeyMarkers(app, root) {
  let markers = [];
  let drag = null;
  /** The arrow-key run in progress: {i, id} (its presses share one undo step), or null. */
  let run = null;
  let runs = 0;
  const round = (t) => Math.round(t / DRAG_SNAP) * DRAG_SNAP;
  const fmt = (t) => `${Number(t.toFixed(3))} s`;

  function name(i, n) {
    return i < n ? `pose ${i}` : 'pose 0 (end of cycle)';
  }

  /** Why `times` with key i at `t` is refused by its neighbours (null: in order). */
  function outOfOrder(times, i, t) {
    const n = app.motion.poseCount;
    if (i > 0 && !(t > times[i - 1])) return `${name(i, n)} cannot move to ${fmt(t)}: at or before ${name(i - 1, n)}'s key (${fmt(times[i - 1])})`;
    if (i < times.length - 1 && !(t < times[i + 1])) return `${name(i, n)} cannot move to ${fmt(t)}: at or after ${name(i + 1, n)}'s key (${fmt(times[i + 1])})`;
    return null;
  }

  function refuse(reason) {
    app.showError(`Not retimed: ${reason}. Times must increase; nothing changed.`, 'warn');
  }

  /** Positions and names the markers on the scale [a, b] (default: the key times' own). */
  function place(scale) {
    if (!app.motion) return;
    const times = app.keyTimes();
    const n = app.motion.poseCount;
    if (markers.length !== times.length) {
      markers = times.map((_, i) => {
        const m = document.createElement('div');
        m.className = 'key-marker';
        m.tabIndex = 0;
        m.setAttribute('role', 'slider');
        m.dataset.key = String(i);
        m.addEventListener('pointerdown', (e) => press(e, nearest(e, i)));
        m.addEventListener('keydown', (e) => key(e, i));
        m.addEventListener('blur', () => run?.i === i && (run = null));
        return m;
      });
      root.replaceChildren(...markers);
    }
    const [a, b] = scale ?? [times[0], times[times.length - 1]];
    markers.forEach((m, i) => {
      const t = times[i];
      m.style.setProperty('--at', String((t - a) / (b - a)));
      m.setAttribute('aria-label', `Key time of ${name(i, n)}`);
      m.setAttribute('aria-valuenow', String(t));
      m.setAttribute('aria-valuetext', fmt(t));
      m.setAttribute('aria-valuemin', String(i > 0 ? times[i - 1] : t - 1e6));
      m.setAttribute('aria-valuemax', String(i < times.length - 1 ? times[i + 1] : t + 1e6));
      m.title = `${name(i, n)} at ${fmt(t)}: drag or use the arrow keys (Shift: 0.01 s) to retime`;
    });
  }

  function key(e, i) {
    const dir = { ArrowRight: 1, ArrowUp: 1, ArrowLeft: -1, ArrowDown: -1 }[e.key];
    if (!dir) return;
    e.preventDefault();
    const times = app.keyTimes();
    const step = e.shiftKey ? KEY_STEP_FINE : KEY_STEP;
    // Rounded to the step's decimals, so 0.1 s steps give 1.1, not 1.1000000000000001.
    const t = Number((times[i] + dir * step).toFixed(6));
    const why = outOfOrder(times, i, t);
    if (why) return refuse(why);
    const next = [...times];
    next[i] = t;
    if (run?.i !== i) run = { i, id: ++runs };
    const err = app.setTimes(next, { key: `key-marker ${run.id}`, at: e.timeStamp });
    if (err) refuse(err);
  }

  /**
   * The marker a press at (e.clientX, e.clientY) on marker `hit` is for: of the markers whose
   * box holds the point, the one whose centre is nearest (ties: `hit`, the one on top).
   */
  function nearest(e, hit) {
    let best = hit;
    let bestDist = Infinity;
    markers.forEach((m, k) => {
      const r = m.getBoundingClientRect();
      if (e.clientX < r.left || e.clientX > r.right || e.clientY < r.top || e.clientY > r.bottom) return;
      const d = Math.abs(e.clientX - (r.left + r.width / 2));
      if (d < bestDist || (d === bestDist && k === hit)) {
        best = k;
        bestDist = d;
      }
    });
    return best;
  }

  /** The time under the pointer on the drag's frozen scale, less the grab offset. */
  function timeAt(e) {
    const { left, width, a, b, offset } = drag;
    return round(a + ((e.clientX - offset - left) / width) * (b - a));
  }

  function press(e, i) {
    if (e.button !== 0 || drag) return;
    e.preventDefault();
    const m = markers[i];
    m.focus();
    m.setPointerCapture?.(e.pointerId);
    const times = app.keyTimes();
    const r = root.getBoundingClientRect();
    // Where on the marker it was grabbed: the key follows the pointer's travel, it does not
    // jump under a finger that pressed beside the mark.
    const mr = m.getBoundingClientRect();
    // The scale stays fixed while dragging (moving the first or last key would rescale it).
    const inset = parseFloat(getComputedStyle(root).getPropertyValue('--key-inset')) || 0;
    drag = {
      i, pointer: e.pointerId, times, before: app.snapshot(), moved: false, refused: false,
      left: r.left + inset, width: Math.max(1, r.width - 2 * inset), a: times[0], b: times[times.length - 1],
      offset: e.clientX - (mr.left + mr.width / 2),
      original: app.motion.times ? Array.from(app.motion.times) : null,
    };
    m.classList.add('dragging');
    const move = (ev) => {
      if (!drag || drag.refused || ev.pointerId !== drag.pointer) return;
      const t = timeAt(ev);
      if (t === drag.times[i] && !drag.moved) return;
      const why = outOfOrder(drag.times, i, t);
      if (why) return abort(why);
      const next = [...drag.times];
      next[i] = t;
      try {
        // A live preview: the object at the playhead follows; undo and save come on release.
        app.motion.setTimes(next);
      } catch (err) {
        return abort(err.message);
      }
      drag.moved = true;
      app.viewer.retime();
      app.requestDraw();
      place([drag.a, drag.b]);
    };
    const up = (ev) => {
      if (!drag || ev.pointerId !== drag.pointer) return;
      const d = drag;
      drag = null;
      m.classList.remove('dragging');
      m.removeEventListener('pointermove', move);
      m.removeEventListener('pointerup', up);
      m.removeEventListener('pointercancel', up);
      if (d.moved && !d.refused) {
        app.history.push(d.before);
        app.changed();
      } else place();
    };
    /** Refuses the drag: the times in use before it come back; the drag is over. */
    const abort = (why) => {
      drag.refused = true;
      if (drag.moved) {
        app.motion.setTimes(drag.original);
        drag.moved = false;
        app.viewer.retime();
        app.requestDraw();
      }
      place([drag.a, drag.b]);
      refuse(why);
    };
    m.addEventListener('pointermove', move);
    m.addEventListener('pointerup', up);
    m.addEventListener('pointercancel', up);
  }

  place();
  return { place: () => drag || place() };
}
