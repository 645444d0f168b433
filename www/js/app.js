// The playground's state and its signals, as the three.js editor's Editor keeps them. The App
// is the one owner of the editing state (a wasm Motion, the display settings, playback, the
// selection, the imported mesh): the rest of the page reads it and changes it only through the
// named commands of editor/commands.js (`app.run(name, …)`, each one labelled undo step) and the
// setters below, and follows it through `app.on(topic, fn)`. It starts the 3-D view
// (figure/viewer.js) with that state as the view's model and the editor's parts around it; the
// view, the chrome (editor/ui.js), the dock and the parts subscribe to the signals instead of
// being called. Whatever belongs to the view is the viewer's (`app.viewer`), and whatever belongs
// to a part is that part's (`app.parts[id]`).
//
// A part (typedef Part below) reaches everything through the app it is given (none imports
// app.js).
//
// The first frame needs only the renderer's wasm module (editor/modules.js): the dock, its views
// and the analysis module are fetched when a view is first opened (editor/dock-host.js).
import { Viewer, newModel } from './figure/viewer.js';
import { buildUi } from './editor/ui.js';
import { renderModule, glModule, analysisModule, loadedAnalysis } from './editor/modules.js';
import notices from './editor/notices.js';
import session, { History } from './editor/session.js';
import files from './editor/files.js';
import input from './editor/input.js';
import pose from './editor/pose.js';
import presets, { DEFAULT_SCENE } from './editor/presets.js';
import responsive from './editor/responsive.js';
import labels from './editor/labels.js';
import viewpoint from './editor/viewpoint.js';
import theme, { THEMES } from './editor/theme.js';
import media from './editor/media.js';
import drafts from './editor/drafts.js';
import undoMenu from './editor/undo-menu.js';
import dockHost from './editor/dock-host.js';
import { runCommand } from './editor/commands.js';

const PARTS = [notices, drafts, session, files, input, pose, presets, responsive, labels, viewpoint, theme, media, undoMenu, dockHost];

/**
 * The display settings (app.view): saved with the session, undoable through the setView command.
 * @typedef {object} ViewState
 * @property {string} scene the preset last loaded
 * @property {string} object the moving object: 'scene' (the preset's), a shape, or 'obj' (imported)
 * @property {number} strobe copies of the object along the motion
 * @property {boolean} showStrobe
 * @property {boolean} showControl
 * @property {boolean} showTrajectories
 * @property {boolean} showPolyscrew
 * @property {boolean} showPolygon
 * @property {boolean} showTriads
 * @property {boolean} showPoseNumbers pose numbers beside the handles (editor/labels.js)
 * @property {boolean} gizmoLocal the gizmo's axes: the world's (false) or the selected pose's own
 * @property {boolean} showGrid
 * @property {boolean} snap
 * @property {string} theme 'auto' (the system's prefers-color-scheme), 'light' or 'dark' (editor/theme.js)
 * @property {string} dock the open analysis view ('' = dock closed)
 */

/**
 * Playback (app.anim; figure/viewer.js advances it while playing): u the parameter shown, t its
 * time in seconds (unknown until derived from u: tu is the u that t belongs to).
 * @typedef {object} Playback
 * @property {boolean} playing
 * @property {number} u
 * @property {number} [t]
 * @property {number} [tu]
 * @property {number} speed
 * @property {boolean} loop
 * @property {boolean} visible whether the animated object is shown
 * @property {number | null} [passes] the viewer's count of passes left (element playback)
 */

/**
 * What the App announces to `app.on(topic, fn)`: 'motion' (the Motion, its options or the
 * display changed, `changed`: {save}, save false where the change is no edit to keep; the view
 * rebuilds first), 'view' (display settings: fn gets the names changed), 'playback' (playhead,
 * speed, loop; from the view's frame loop with {u, a, b, playhead} as the playhead moves,
 * {play: true} as playback starts or stops), 'selection' (the selected pose or the gizmo mode:
 * {what: 'pose' | 'mode', redraw}, redraw false while a session is applied, which redraws
 * everything), 'layout' (the part of the window the 3-D view and the dock share: a lesson
 * opened or closed).
 * @typedef {'motion' | 'view' | 'playback' | 'selection' | 'layout'} Topic
 */

/**
 * An editor part: a module's default export. `create` returns the instance the App keeps as
 * app.parts[id]; an instance with `bind()` attaches its listeners once the view runs.
 * @typedef {object} Part
 * @property {string} id
 * @property {(app: App) => any} create
 */

/**
 * A read-only face of one of the App's state objects: reading works as on the object, any
 * write throws and names the App's operation to use instead.
 * @template {object} T
 * @param {T} target
 * @param {string} name the state's name in messages
 * @param {string} instead the operation that changes it
 * @returns {Readonly<T>}
 */
function readOnly(target, name, instead) {
  const refuse = (key) => {
    throw new TypeError(`app.${name}.${String(key)} is read-only: change it with ${instead}`);
  };
  return /** @type {Readonly<T>} */ (new Proxy(/** @type {object} */ (target), {
    set: (_, key) => refuse(key),
    defineProperty: (_, key) => refuse(key),
    deleteProperty: (_, key) => refuse(key),
  }));
}

export class App {
  /** @type {any} the wasm Motion being edited (one owner: replaced only through setMotion). */
  #motion = null;
  /** @type {ViewState} */
  #view = { ...newModel(DEFAULT_SCENE).view, showPoseNumbers: true, gizmoLocal: false, snap: false, theme: 'auto', dock: '' };
  /** @type {Playback} (t is unknown until the first motion: figure/viewer.js playTime derives it from u) */
  #anim = { playing: false, u: 0, t: undefined, tu: undefined, speed: 1, loop: true, visible: false };
  #selected = -1;
  /** @type {'translate' | 'rotate'} */
  #mode = 'translate';
  /** @type {{kind: string, data: string} | null} the imported mesh: {kind: 'obj', data: text} or {kind: 'gltf', data: base64} */
  #imported = null;
  /** @type {Map<Topic, Set<Function>>} */
  #listeners = new Map();
  #viewFace = readOnly(this.#view, 'view', "app.run('setView', key, value) (undoable) or app.updateView(patch)");
  #animFace = readOnly(this.#anim, 'anim', 'app.setPlayback(patch), app.viewer.seekTime(t) or app.viewer.setPlaying(on)');

  constructor() {
    this.history = new History();
    this.errors = [];
    // Pointer state the viewer reads while a press is in progress (editor/input.js); hoverPose
    // is unknown until the pointer first moves (that first move then sets the cursor).
    this.hover = null;
    this.hoverPose = undefined;
    this.drag = null;
    /** @type {import('./editor/dock.js').Dock | null} the analysis dock once fetched (its loading: editor/dock-host.js) */
    this.dock = null;
    this.parts = {};
    for (const p of PARTS) this.parts[p.id] = p.create(this);
  }

  // ---------------------------------------------------------------- the state and its signals

  /** The wasm Motion being edited; replace it with `setMotion` (inside an `edit` to undo it). */
  get motion() {
    return this.#motion;
  }

  /** The display settings, read-only: the setView command (undoable) or `updateView` change them. */
  get view() {
    return this.#viewFace;
  }

  /** Playback, read-only: `setPlayback`, and the viewer's `seekTime` and `setPlaying`, change it. */
  get anim() {
    return this.#animFace;
  }

  /** The selected control pose (-1: none); `select` changes it. */
  get selected() {
    return this.#selected;
  }

  /** The gizmo's mode; `setMode` changes it. */
  get mode() {
    return this.#mode;
  }

  /** The imported mesh or null; `setImported` changes it. */
  get imported() {
    return this.#imported;
  }

  /**
   * The model the viewer draws (figure/viewer.js): the same state, with playback writable, since
   * the viewer's frame loop is what advances the playhead.
   * @returns {import('./figure/viewer.js').Model}
   */
  viewerModel() {
    const app = this;
    return {
      get motion() { return app.#motion; },
      view: this.#view,
      anim: this.#anim,
      get selected() { return app.#selected; },
      get mode() { return app.#mode; },
      get imported() { return app.#imported; },
      get hover() { return app.hover; },
      get hoverPose() { return app.hoverPose; },
      get drag() { return app.drag; },
    };
  }

  /**
   * Calls `fn(detail)` whenever `topic` changes (see Topic); returns what ends the subscription.
   * @param {Topic} topic
   * @param {(detail?: any) => void} fn
   */
  on(topic, fn) {
    if (!this.#listeners.has(topic)) this.#listeners.set(topic, new Set());
    this.#listeners.get(topic).add(fn);
    return () => this.#listeners.get(topic).delete(fn);
  }

  /**
   * Announces a change of `topic` to its subscribers.
   * @param {Topic} topic
   * @param {any} [detail]
   */
  emit(topic, detail) {
    for (const fn of this.#listeners.get(topic) ?? []) fn(detail);
  }

  /**
   * Takes `motion` as the edited Motion and frees the one before (run it inside `edit` to make
   * it undoable); the selection is cleared unless `selected` names a pose.
   */
  setMotion(motion, selected = -1) {
    if (motion === this.#motion) return;
    this.#motion?.free();
    this.#motion = motion;
    this.#selected = selected;
    this.emit('selection', { what: 'pose', redraw: false });
  }

  /** Sets the imported mesh ({kind, data}, or null). */
  setImported(mesh) {
    this.#imported = mesh;
  }

  /**
   * Sets display settings without an undo step (the setView command is the undoable edit): each
   * key must be a setting and each value of its type, else nothing changes and an error says
   * which. A theme other than 'auto', 'light' or 'dark' keeps the current one. Announces 'view'
   * with the names changed.
   * @param {Partial<ViewState>} patch
   */
  updateView(patch) {
    for (const [k, v] of Object.entries(patch)) {
      if (!(k in this.#view)) throw new Error(`unknown display setting ${k}`);
      if (typeof v !== typeof this.#view[k]) throw new Error(`display setting ${k} must be a ${typeof this.#view[k]}`);
    }
    const changed = [];
    for (const [k, v] of Object.entries(patch)) {
      if (k === 'theme' && !THEMES.includes(String(v))) continue;
      if (this.#view[k] === v) continue;
      this.#view[k] = v;
      changed.push(k);
    }
    if (changed.length) this.emit('view', changed);
  }

  /**
   * Sets playback fields (u, speed, loop, visible; `playing` only as a flag, as a chart's
   * preview pauses: the viewer's `setPlaying` starts and stops playback) without drawing; its
   * `updateAnim` or `seekTime` shows them. The time in seconds follows a new u by itself
   * (figure/viewer.js playTime); `t: undefined` forgets it also where u stays.
   * @param {Partial<Pick<Playback, 'u' | 't' | 'speed' | 'loop' | 'visible' | 'playing'>>} patch
   */
  setPlayback(patch) {
    const bad = Object.keys(patch).find((k) => !['u', 't', 'speed', 'loop', 'visible', 'playing'].includes(k));
    if (bad) throw new Error(`unknown playback setting ${bad}`);
    if ('t' in patch && patch.t !== undefined) throw new Error('playback time: use app.viewer.seekTime(t)');
    Object.assign(this.#anim, patch);
    this.emit('playback');
  }

  /** Selects pose k (-1: none); `redraw` false only records it (a session being applied redraws all). */
  select(k, redraw = true) {
    this.#selected = k;
    this.emit('selection', { what: 'pose', redraw });
  }

  /** Sets the gizmo's mode ('translate' or 'rotate'); `redraw` as for `select`. */
  setMode(mode, redraw = true) {
    this.#mode = mode === 'rotate' ? 'rotate' : 'translate';
    this.emit('selection', { what: 'mode', redraw });
  }

  /**
   * Announces a change of the motion, its options or the display ('motion'): the view
   * rebuilds, the notices warn, the session autosaves (unless `save` is false), then the
   * chrome and the dock follow.
   */
  changed(save = true) {
    this.emit('motion', { save });
  }

  /** Runs command `name` of editor/commands.js as one labelled undo step. */
  run(name, ...args) {
    return runCommand(this, name, ...args);
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

  /** The analysis module (editor/modules.js), fetched on first use; rejects with a message. */
  analysis() {
    return analysisModule(this.wasm.Motion);
  }

  /** The analysis module if it has loaded (analysis()), else null. */
  loadedAnalysis() {
    return loadedAnalysis();
  }

  // ---------------------------------------------------------------- startup

  async start() {
    const params = new URLSearchParams(location.search);
    await this.startViewer(params.get('backend') === 'webgl2');
    // The view follows the motion and the selection first; the notices and the session next
    // (their bind), then the chrome (editor/ui.js) and the dock, which subscribe later.
    this.on('motion', () => {
      this.viewer.rebuild();
      // The playhead keeps its time in seconds; a retimed motion shows another pose then.
      this.viewer.retime();
    });
    this.on('selection', (d) => {
      if (!d?.redraw) return;
      if (d.what === 'mode') {
        this.viewer.rebuildGizmo();
        this.viewer.requestDraw();
      } else this.viewer.rebuildControls();
    });
    for (const id of ['notices', 'session']) this.parts[id].bind();
    this.limits = this.wasm.limits();
    this.scenes = this.viewer.scenes;
    const { backend, renderer } = this.viewer;
    document.getElementById('backend').textContent = `${backend}${renderer.samples > 1 ? ` · MSAA ${renderer.samples}×` : ''}`;

    this.parts.session.openInitial(params);
    this.ui = buildUi(this);
    if (this.view.dock) this.parts.dockHost.open(this.view.dock);
    for (const id of ['input', 'files', 'presets', 'responsive', 'labels', 'viewpoint', 'theme', 'media', 'drafts', 'undoMenu']) this.parts[id].bind();
    window.addEventListener('beforeunload', () => this.parts.session.autosave());
    this.ready = true;
  }

  /**
   * Starts the viewer with the renderer module (editor/modules.js) as `this.wasm`, the module
   * every Motion of the editor comes from. Where the WebGPU module's renderer fails to start,
   * the WebGL2 module takes over on a fresh canvas (the WebGPU module has no GL backend).
   */
  async startViewer(webgl2) {
    const { wasm, gl } = await renderModule(webgl2);
    const show = (message, level) => this.parts.notices.show(message, level);
    const viewer = (module) =>
      new Viewer(/** @type {HTMLCanvasElement} */ (document.getElementById('view')), module, {
        model: this.viewerModel(),
        webgl2,
        // WebGPU without an adapter is no fault of the page or the browser: neutral information.
        warn: (message) => show(message, /no usable adapter/.test(message) ? 'info' : 'warn'),
        onTime: (u, a, b, playhead) => this.emit('playback', { u, a, b, playhead }),
        onPlay: () => this.emit('playback', { play: true }),
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
      show('WebGPU failed to start; using WebGL2.', 'warn');
    }
  }
}
