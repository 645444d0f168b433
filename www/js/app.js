// The playground editor. The App holds the editing state (a wasm Motion and the settings around
// it), runs the 3-D view (view/viewer.js) with itself as the view's model, and puts the editor
// around it: panel, toolbar and timeline (editor/ui.js), the analysis dock (editor/dock.js) and
// the parts below.
//
// A part module default-exports { id, create(app) }, as the dock's views do (without an
// element): `create` returns the part's instance, kept as app.parts[id]. A part reaches
// everything through the app it is given (none imports app.js), and an instance with `bind()`
// attaches its listeners once the view runs. The App methods that only forward to a part or to
// the viewer are the API that ui.js, the analysis views, main.js and the tests use.
//
// The first frame needs only the renderer's wasm module (editor/modules.js): the dock, its views
// and the analysis module are fetched when a view is first opened, with "loading…" in the dock
// meanwhile; a failed fetch is a message, and the editor goes on without the dock.
import { Viewer } from './view/viewer.js';
import { buildUi } from './editor/ui.js';
import { renderModule, glModule, analysisModule, lazy } from './editor/modules.js';
import notices from './editor/notices.js';
import session, { History } from './editor/session.js';
import files from './editor/files.js';
import input from './editor/input.js';
import pose from './editor/pose.js';
import presets from './editor/presets.js';
import responsive from './editor/responsive.js';
import labels from './editor/labels.js';
import viewpoint from './editor/viewpoint.js';
import theme from './editor/theme.js';
import media from './editor/media.js';

// A retry asks for the modules under another URL (see editor/modules.js).
const loadDockModule = lazy('the analysis dock', (a) => import(a ? `./editor/dock.js?retry=${a}` : './editor/dock.js'));
const loadViewModules = lazy('the analysis views', (a) =>
  import(a ? `./views/index.js?retry=${a}` : './views/index.js').then((m) => m.loadViews(a)),
);

const PARTS = [notices, session, files, input, pose, presets, responsive, labels, viewpoint, theme, media];

/** Strobe count when a preset loads: fewer copies where the object is bulky (readable, as in the paper). */
const PRESET_STROBE = {
  spinning_block: 14, pendulum: 18, cylinder5: 36, pip_morph5: 36, circle4: 40,
  triangle7: 40, rb_sphere7: 20, rb_ibeam7: 30, rb_molecule4: 24,
};
const DEFAULT_STROBE = 64;
/** Pose selected when a preset loads (scenes.md A3: "drag or rotate the top-left pose"). */
const PRESELECT = { l_cycle_edit: 4 };
/** Default preset on a first visit. */
const DEFAULT_SCENE = 'l_cycle_rotated';

export class App {
  constructor() {
    this.history = new History();
    this.errors = [];
    // The fields the viewer reads (the model of view/viewer.js), then the editor's own.
    this.motion = null;
    this.selected = -1;
    this.mode = 'translate';
    this.hover = null;
    // Unknown until the pointer first moves (that first move then sets the cursor).
    this.hoverPose = undefined;
    this.drag = null;
    this.view = {
      scene: DEFAULT_SCENE,
      object: 'scene',
      strobe: 64,
      showStrobe: true,
      showControl: true,
      showTrajectories: true,
      showPolyscrew: false,
      showPolygon: true,
      showTriads: true,
      /** Pose numbers beside the handles (editor/labels.js). */
      showPoseNumbers: true,
      gizmoLocal: false, // the gizmo's axes: the world's (false) or the selected pose's own
      showGrid: true,
      snap: false,
      /** 'auto' (the system's prefers-color-scheme), 'light' or 'dark' (editor/theme.js). */
      theme: 'auto',
      /** The open analysis view ('' = dock closed). */
      dock: '',
    };
    // The key times live in the Motion (motion.times): `view.times` remains only as a
    // non-enumerable alias for older callers (lesson steps), outside sessions and undo.
    Object.defineProperty(this.view, 'times', {
      enumerable: false,
      get: () => this.times(),
      set: (t) => this.motion.setTimes(t ?? null),
    });
    // Playback (view/viewer.js): u the parameter shown, t its time in seconds.
    // (t is unknown until the first motion: view/viewer.js playTime derives it from u.)
    this.anim = { playing: false, u: 0, t: undefined, tu: undefined, speed: 1, loop: true, visible: false };
    /** The imported mesh: {kind: 'obj', data: text} or {kind: 'gltf', data: base64}. */
    this.imported = null;
    this.parts = {};
    for (const p of PARTS) this.parts[p.id] = p.create(this);
  }

  // ---------------------------------------------------------------- startup

  async start() {
    const params = new URLSearchParams(location.search);
    await this.startViewer(params.get('backend') === 'webgl2');
    this.limits = this.wasm.limits();
    this.scenes = this.viewer.scenes;
    const { backend, renderer } = this.viewer;
    document.getElementById('backend').textContent = `${backend}${renderer.samples > 1 ? ` · MSAA ${renderer.samples}×` : ''}`;

    // Share link > autosave > default preset.
    if (!this.parts.session.restoreInitial()) this.loadPreset(DEFAULT_SCENE, false);
    this.ui = buildUi(this);
    if (this.view.dock) this.openView(this.view.dock);
    this.parts.input.bind();
    this.parts.files.bind();
    this.parts.presets.bind();
    this.parts.responsive.bind();
    this.parts.labels.bind();
    this.parts.viewpoint.bind();
    this.parts.theme.bind();
    this.parts.media.bind();
    window.addEventListener('beforeunload', () => this.autosave());
    this.ready = true;
  }

  /**
   * Starts the viewer with the renderer module (editor/modules.js) as `this.wasm`, the module
   * every Motion of the editor comes from. Where the WebGPU module's renderer fails to start,
   * the WebGL2 module takes over on a fresh canvas (the WebGPU module has no GL backend).
   */
  async startViewer(webgl2) {
    const { wasm, gl } = await renderModule(webgl2);
    const viewer = (module) =>
      new Viewer(document.getElementById('view'), module, {
        model: this,
        webgl2,
        // WebGPU without an adapter is no fault of the page or the browser: neutral information.
        warn: (message) => this.showError(message, /no usable adapter/.test(message) ? 'info' : 'warn'),
        onTime: (u, a, b, playhead) => this.ui?.setTime(u, a, b, playhead),
        onPlay: () => this.ui?.refresh(),
      });
    this.wasm = wasm;
    this.viewer = viewer(wasm);
    try {
      await this.viewer.start();
    } catch (e) {
      if (gl) throw e;
      this.viewer.dispose();
      this.viewer.replaceCanvas();
      this.wasm = await glModule();
      this.viewer = viewer(this.wasm);
      await this.viewer.start();
      this.showError('WebGPU failed to start; using WebGL2.', 'warn');
    }
  }

  /** The analysis module (editor/modules.js), fetched on first use; rejects with a message. */
  analysis() {
    return analysisModule(this.wasm.Motion);
  }

  // ---------------------------------------------------------------- the view

  get canvas() {
    return this.viewer?.canvas;
  }

  get renderer() {
    return this.viewer?.renderer;
  }

  get camera() {
    return this.viewer?.camera;
  }

  get backend() {
    return this.viewer?.backend;
  }

  get frames() {
    return this.viewer?.frames;
  }

  get stats() {
    return this.viewer?.stats;
  }

  get sceneInfo() {
    return this.viewer.drawing.sceneInfo;
  }

  get morphing() {
    return this.viewer.drawing.morphing;
  }

  get morphKey() {
    return this.viewer.drawing.morphKey;
  }

  get morphStrobeSlots() {
    return this.viewer.drawing.morphStrobeSlots;
  }

  requestDraw() {
    this.viewer.requestDraw();
  }

  pixelSize() {
    return this.viewer.pixelSize();
  }

  bodyPoints() {
    return this.viewer.bodyPoints();
  }

  meshesChanged() {
    this.viewer.meshesChanged();
  }

  setImportedMesh(slot, mesh) {
    this.viewer.setImportedMesh(slot, mesh);
  }

  updateAnim() {
    this.viewer.updateAnim();
  }

  /** Frames the control poses in the part of the view the page's cards and bars leave free (editor/viewpoint.js). */
  frameAll() {
    if (this.parts?.viewpoint) this.parts.viewpoint.fit();
    else this.viewer.frameAll();
  }

  setPlaying(on) {
    this.viewer.setPlaying(on);
  }

  toPage(p) {
    return this.viewer.toPage(p);
  }

  screenOfPose(k) {
    return this.viewer.screenOfPose(k);
  }

  screenOfGizmo(part) {
    return this.viewer.screenOfGizmo(part);
  }

  // ---------------------------------------------------------------- session (editor/session.js)

  session(withCamera) {
    return this.parts.session.session(withCamera);
  }

  applySession(s) {
    this.parts.session.applySession(s);
  }

  snapshot() {
    return this.parts.session.snapshot();
  }

  beginEdit() {
    this.parts.session.beginEdit();
  }

  edit(f, coalesce) {
    return this.parts.session.edit(f, coalesce);
  }

  undo() {
    this.parts.session.undo();
  }

  redo() {
    this.parts.session.redo();
  }

  autosave() {
    this.parts.session.autosave();
  }

  shareLink() {
    return this.parts.session.shareLink();
  }

  // ---------------------------------------------------------------- files (editor/files.js)

  importJson(text, fileName) {
    return this.parts.files.importJson(text, fileName);
  }

  importDocument(doc, fileName) {
    return this.parts.files.importDocument(doc, fileName);
  }

  importMesh(kind, data, fileName, failure) {
    return this.parts.files.importMesh(kind, data, fileName, failure);
  }

  importObj(text) {
    return this.importMesh('obj', text);
  }

  exportJson() {
    this.parts.files.exportJson();
  }

  // ---------------------------------------------------------------- notices (editor/notices.js)

  showError(message, level) {
    this.parts.notices.show(message, level);
  }

  /**
   * Where the options give a poor result without an error (Motion.warnings: the V1 4-point and
   * Jarek rules across half a turn, docs/math/subdivision.md §4), a notice naming the span; shown
   * again only when the warnings change.
   */
  warnSubdivision() {
    const w = this.motion.warnings();
    const text = w.join(' ');
    if (text && text !== this.lastWarnings) {
      const more = w.length > 1 ? ` (${w.length - 1} more span${w.length > 2 ? 's' : ''} likewise)` : '';
      this.showError(`Warning: ${w[0]}${more}`, 'warn');
    }
    this.lastWarnings = text;
  }

  // ---------------------------------------------------------------- editing

  /** After any change of motion/options/view: rebuild GPU data, autosave, redraw. */
  changed(save = true) {
    this.viewer.rebuild();
    // The playhead keeps its time in seconds; a retimed motion shows another pose then.
    this.viewer.retime();
    this.warnSubdivision();
    if (save) this.autosave();
    this.ui?.refresh();
    this.dock?.changed('edit');
  }

  /**
   * Up to 1700 px wide, the settings panel would cover the right part of the 3-D view that the
   * open dock leaves: fold it while the dock is open, and unfold it again when it closes (if it
   * was open).
   */
  foldPanelForDock(open) {
    const gui = this.ui?.gui;
    if (!gui || window.innerWidth >= 1700) return;
    if (open) {
      this.panelWasOpen = !gui._closed;
      gui.close();
    } else if (this.panelWasOpen) gui.open();
  }

  /**
   * Opens analysis view `id` in the dock ('' or null closes it); resolves to its instance. The
   * first view opened fetches the dock (with the analysis module): "loading…" in the dock until
   * then, and where the fetch fails a message, the dock closed and the editor as it was.
   */
  async openView(id) {
    if (!this.dock) {
      this.wantView = id || '';
      if (!id) return null;
      this.loadingDock ??= this.loadDock();
      await this.loadingDock;
      // Meanwhile another view may have been asked for, or the dock closed.
      if (!this.dock || this.wantView !== id) return this.dock?.current ?? null;
    }
    return this.openViewNow(id);
  }

  /** Fetches the dock, its views and the analysis module, showing "loading…" in the dock. */
  async loadDock() {
    const root = document.getElementById('dock');
    const body = root.querySelector('.body');
    const note = document.createElement('p');
    note.className = 'note loading';
    note.setAttribute('role', 'status');
    note.textContent = 'Loading the analysis views…';
    body.append(note);
    root.classList.add('open');
    try {
      const [{ Dock }, views, analysis] = await Promise.all([loadDockModule(), loadViewModules(), this.analysis()]);
      this.dock = new Dock(this, views, analysis);
    } catch (e) {
      this.showError(`${e.message}. The editor works on without the analysis views.`);
      this.view.dock = '';
      this.wantView = '';
      this.ui?.refresh();
    } finally {
      note.remove();
      if (!this.dock) root.classList.remove('open');
      this.loadingDock = null;
    }
  }

  openViewNow(id) {
    let inst = null;
    const wasOpen = !!this.dock.active;
    try {
      inst = this.dock.open(id || null);
      // The 3-D view changes size when the dock opens or closes (wide screens): re-frame.
      if (wasOpen !== !!this.dock.active) {
        this.foldPanelForDock(!!this.dock.active);
        this.viewer.invalidateSize();
        this.frameAll();
      }
      this.view.dock = id || '';
    } catch (e) {
      this.view.dock = '';
      this.showError(e.message);
    }
    this.autosave();
    this.ui?.refresh();
    return inst;
  }

  loadPreset(id, undoable = true) {
    const info = this.scenes.find((s) => s.id === id);
    if (!info) return this.showError(`unknown preset ${id}`);
    const apply = () => {
      const motion = this.wasm.Motion.fromPreset(id);
      this.motion?.free();
      this.motion = motion;
      this.view.scene = id;
      this.view.object = 'scene';
      this.view.strobe = PRESET_STROBE[id] ?? DEFAULT_STROBE;
      // The editing scene (A3) starts with its top-left pose selected, ready to drag.
      this.selected = PRESELECT[id] ?? -1;
      this.anim.u = 0;
      this.anim.t = undefined;
      this.meshesChanged();
      this.frameAll();
    };
    if (undoable) this.edit(apply);
    else {
      apply();
      this.changed();
    }
  }

  /**
   * The motion's key times in seconds (motion.times: n for an open motion, n + 1 for a cycle), or
   * null for one second per span. Inserting a pose keeps them (the new key halfway between its
   * neighbours' times, one second after an open motion's last); deleting one drops its time.
   */
  times() {
    const t = this.motion?.times;
    return t ? Array.from(t) : null;
  }

  /** The key times in use: motion.times, or the uniform ones (pose i at i s). */
  keyTimes() {
    const m = this.motion;
    return this.times() ?? Array.from({ length: m.poseCount + (m.closed ? 1 : 0) }, (_, i) => i);
  }

  /** The key velocities p'(T_i) in poses per second (null entries: free), or null when all are free. */
  velocities() {
    return this.motion?.velocities ?? null;
  }

  /** What the view shows: time t in seconds and motion parameter u. */
  playhead() {
    const { t, u } = this.viewer.playhead();
    return { t, u };
  }

  /** Shows the moving object at time t in seconds (the scrubber, tests). */
  seekTime(t) {
    this.viewer.seekTime(t);
  }

  /**
   * Sets the key times (null: uniform) as one undoable edit. Returns null when applied, else the
   * Motion's reason (nothing changed); the caller shows it. `merge` ({key, at}: a coalesce key
   * and the event's time stamp) folds a run of edits into one undo step (session.record).
   */
  setTimes(times, merge = null) {
    return this.retimeEdit(() => this.motion.setTimes(times), merge);
  }

  /** Sets the key velocities (null: all free) as one undoable edit; see setTimes. */
  setVelocities(velocities) {
    return this.retimeEdit(() => this.motion.setVelocities(velocities));
  }

  /** Runs a Motion timing change as one undoable edit: null when done, else the error's message. */
  retimeEdit(f, merge = null) {
    const before = this.snapshot();
    try {
      f();
    } catch (e) {
      return e.message;
    }
    this.parts.session.record(before, merge?.key ?? null, merge?.at);
    this.changed();
    return null;
  }

  select(k) {
    this.selected = k;
    this.viewer.rebuildControls();
    this.ui?.refresh();
  }

  setMode(mode) {
    this.mode = mode;
    this.viewer.rebuildGizmo();
    this.requestDraw();
    this.ui?.refresh();
  }

  insertAfterSelected() {
    const i = this.selected >= 0 ? this.selected : this.motion.poseCount - 1;
    this.edit(() => {
      const closed = this.motion.closed;
      if (!closed && i === this.motion.poseCount - 1) {
        // Open motion: extrapolate one span past the end.
        const [, b] = this.motion.domain();
        const p = this.motion.poseAt(b + 0.5);
        this.selected = this.motion.insertPose(i, p);
      } else this.selected = this.motion.insertPose(i);
    });
  }

  deleteSelected() {
    if (this.selected < 0) return;
    this.edit(() => {
      if (this.motion.poseCount <= 2) throw new Error('a motion keeps at least 2 poses');
      this.motion.removePose(this.selected);
      this.selected = Math.min(this.selected, this.motion.poseCount - 1);
    });
  }

  setOption(key, value) {
    this.edit(() => this.motion.setOptions({ [key]: value }), `option:${key}`);
  }

  setScheme(name) {
    this.edit(() => this.motion.setOptions({ scheme: name }));
  }

  setS(s) {
    const named = { 1: 'bspline', 0: 'fourpoint', 0.5: 'jarek' }[s];
    this.edit(() => this.motion.setOptions(named ? { scheme: named } : { scheme: 'j', s }), 'option:s');
  }

  setClosed(closed) {
    this.edit(() => this.motion.setClosed(closed));
  }

  setView(key, value) {
    this.edit(() => {
      this.view[key] = value;
      if (key === 'object') this.meshesChanged();
    }, `view:${key}`);
  }
}
