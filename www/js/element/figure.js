// One figure: the viewer (figure/viewer.js) on a canvas in a shadow root, with its chrome, its
// source and its options; what the element <screw-bender> and mount() (screw-bender.js) drive.
// Its features (features.js) each declare their options and apply them: source.js (where the
// motion comes from, the opt-in saved copy), subdivision.js, display.js (layers, strobe),
// chrome.js (shadow tree, control bar, keys), description.js (accessible name, live region),
// editing.js, camera.js, playback.js (the media-element API), pictures.js, labels.js (labels
// on poses), loading.js (lazy start, poster, hidden slides, print); this file starts, loads and
// stops the figure and hands each change of options to them. wasm.js holds the module instance
// all figures share.
import { Viewer, newModel } from '../figure/viewer.js';
import { cameraMoved } from './camera.js';
import { bindChrome, buildChrome, onKey, refreshChrome, timeChanged } from './chrome.js';
import { describePose, say } from './description.js';
import { editTool } from './editing.js';
import { FEATURES } from './features.js';
import { Labels } from './labels.js';
import { drawWhenShown, forget, isPrinting, keepStill, printable, showPoster, whenNear, whenStyled } from './loading.js';
import { ALIASES, OptionError, bool, canonical, check } from './options.js';
import { Playback } from './playback.js';
import { fetchSource, persist, restorePersisted } from './source.js';
import { loadWasm, serially } from './wasm.js';

/** The features that apply options (checked together before any of them applies). */
const APPLYING = FEATURES.filter((f) => f.apply || f.drawn || f.early);
const EARLY = FEATURES.filter((f) => f.early);

/**
 * A figure in `host` (any element): the viewer on a canvas in a shadow root, its chrome and its
 * source. `options` as the attributes (camelCase not needed: every name is one word); `emit`
 * dispatches the events. Created by mount() and by the element.
 */
export class Figure {
  constructor(host, emit) {
    this.host = host;
    this.emit = emit;
    this.opts = {};
    this.model = newModel('');
    // Set by loading.js: whether the figure is on screen, the wake-up of a lazy start, the
    // timer that suspends an off-screen figure.
    /** @type {boolean | undefined} */
    this.onScreen;
    /** @type {(() => void) | undefined} */
    this.wake;
    /** @type {ReturnType<typeof setTimeout> | undefined} */
    this.suspendTimer;
    /** The camera asked before the motion loaded (camera.js). */
    this.pendingCamera = null;
    this.generation = 0;
    const { root, el } = buildChrome(host);
    this.root = root;
    this.el = el;
    /** The message for a stylesheet that did not load, else null (loading.js). */
    this.unstyled = null;
    /** Resolves once the shadow tree's stylesheet applies (loading.js). */
    this.styled = whenStyled(this);
    bindChrome(this);
    this.labels = new Labels(this);
    this.playback = new Playback(this);
  }

  // ---------------------------------------------------------------- start and stop

  /** Starts the wasm module and the viewer (once); resolves when the first motion is drawn. */
  start(options) {
    this.opts = canonical(options);
    printable(this);
    this.guard(() => this.applyChrome());
    this.ready = this.guard(async () => {
      showPoster(this);
      await whenNear(this);
      if (this.disposed) return;
      // The renderer measures the canvas: it starts once the stylesheet has laid it out (the
      // stylesheet loads beside the module, and is usually there first).
      const [w] = await Promise.all([loadWasm({ webgl2: this.opts.backend === 'webgl2' }), this.styled]);
      if (this.disposed) return;
      this.wasm = w;
      this.limits = w.limits();
      const viewer = new Viewer(this.el.canvas, w, {
        model: this.model,
        webgl2: this.opts.backend === 'webgl2',
        wheelNeedsFocus: true,
        what: 'this figure',
        warn: () => {},
        onTime: (u, a, b, playhead) => this.timeChanged(playhead),
        onPlay: (on) => this.playback.playing(on),
        onEnded: () => this.playback.ended(),
        onCamera: (source) => cameraMoved(this, source),
        onDraw: () => this.drew(),
      });
      drawWhenShown(viewer);
      this.viewer = viewer;
      try {
        await serially(() => (this.disposed ? null : viewer.start()));
      } catch {
        this.viewer = null;
        viewer.dispose();
        this.fail(null, 'This figure needs WebGPU or WebGL2; this browser offers neither.');
        return;
      }
      if (this.disposed) {
        viewer.dispose();
        return;
      }
      // A WebGPU start that fell back to WebGL2 drew on a fresh canvas: keys go to that one.
      this.bindCanvas();
      this.el.fig.dataset.backend = this.viewer.backend;
      this.viewer.setVisible(this.onScreen !== false);
      await this.load();
    });
    return this.ready;
  }

  /** Keys and pointer gestures on the viewer's canvas (a new one after a fallback or a resume). */
  bindCanvas() {
    this.el.canvas = this.viewer.canvas;
    this.el.canvas.addEventListener('keydown', (e) => this.guard(() => this.onKey(e)));
    this.viewer.bindPointer(this.editable ? this.editTool() : { click: () => {} });
  }

  /**
   * Far from the viewport for a while (loading.js): frees the renderer and its graphics
   * context, keeping a still picture for print; not while a pose is dragged, it has the focus or
   * the page prints (the print picture is of the live frame; after print it is asked again).
   */
  suspend() {
    const v = this.viewer;
    if (!v?.renderer || !this.model.motion || this.drag || this.root.activeElement || isPrinting()) return;
    keepStill(this);
    v.suspend();
  }

  /** Near the viewport again: a new renderer on a fresh canvas, drawn as it was left. */
  resume() {
    const v = this.viewer;
    if (!v?.suspended || this.resuming) return;
    this.resuming = this.guard(async () => {
      try {
        await serially(() => (this.viewer === v ? v.resume() : null));
      } finally {
        this.resuming = null;
      }
      if (this.viewer !== v || this.disposed) return;
      this.kept = null;
      this.bindCanvas();
      v.setVisible(this.onScreen !== false);
    });
  }

  /** Frees the GPU data, the motion and the observers; the figure is done. */
  dispose() {
    this.disposed = true;
    this.generation++;
    this.wake?.();
    clearTimeout(this.suspendTimer);
    this.observer?.disconnect();
    this.observer = null;
    this.labels.dispose();
    forget(this);
    this.drag?.session?.free();
    this.drag = null;
    this.viewer?.dispose();
    this.viewer = null;
    this.model.motion?.free();
    this.model.motion = null;
  }

  /** Runs `f` (sync or async) so that nothing it throws reaches the host page. */
  guard(f) {
    return Promise.resolve(this.guardNow(f)).catch((e) => this.failWith(e));
  }

  /**
   * Runs `f` and returns its value at once, for callers that need it so (the pointer tool's
   * press); what it throws is shown in the figure, as guard's, and gives `fallback`.
   */
  guardNow(f, fallback) {
    try {
      return f();
    } catch (e) {
      this.failWith(e);
      return fallback;
    }
  }

  /** Shows a thrown error (an OptionError names its attribute and value) in the figure. */
  failWith(e) {
    this.fail(e.attribute ?? null, e.message, e.value);
  }

  /** Shows `message` inside the figure and fires `error` {attribute, value, message}. */
  fail(attribute, message, value) {
    this.el.msg.textContent = message;
    this.el.msg.hidden = false;
    this.el.fig.classList.add('failed');
    this.emit('error', { attribute, value: value ?? null, message });
  }

  clearMessage() {
    // A stylesheet that did not load (loading.js whenStyled) stays named: no option mends it.
    if (this.unstyled) {
      this.el.msg.textContent = this.unstyled;
      this.el.msg.hidden = false;
      return;
    }
    this.el.msg.hidden = true;
    this.el.msg.textContent = '';
    this.el.fig.classList.remove('failed');
  }

  get editable() {
    return bool(this.opts.editable);
  }

  /** After each frame: the poster goes at the first, the labels follow the view. */
  drew() {
    if (!this.drawn) {
      this.drawn = true;
      showPoster(this);
    }
    this.labels.place();
  }

  /** Says `text` in the figure's polite live region (what changed, in words). */
  say(text) {
    say(this, text);
  }

  // ---------------------------------------------------------------- options

  /** Changes options (a partial object); a change of source reloads, the rest applies in place. */
  setOptions(patch) {
    patch = canonical(patch);
    const before = this.opts;
    this.opts = { ...this.opts, ...patch };
    // A current name given alone replaces a former name kept beside it.
    for (const [old, now] of Object.entries(ALIASES)) if (now in patch && !(old in patch)) delete this.opts[old];
    for (const f of FEATURES) f.changed?.(this, patch);
    if (!this.viewer) return this.guard(() => this.applyChrome());
    const reload = ['preset', 'src', 'share', 'inline'].some((k) => k in patch && patch[k] !== before[k]);
    if ('editable' in patch && bool(patch.editable) !== bool(before.editable)) {
      // The pointer listeners live on the canvas: a fresh canvas takes the new tool.
      this.model.selected = -1;
      const fresh = /** @type {HTMLCanvasElement} */ (this.el.canvas.cloneNode(false));
      this.el.canvas.replaceWith(fresh);
      this.el.canvas = fresh;
      this.observer?.disconnect();
      this.observer = null;
      this.viewer.dispose();
      this.viewer = null;
      return this.start(this.opts);
    }
    return this.guard(() => (reload ? this.load() : this.apply(patch)));
  }

  /**
   * Hands the options to the features: all are checked first (a bad value throws its
   * OptionError and changes nothing), then each applies its own; after the drawing is rebuilt,
   * those that act on it (autoplay, the words said) follow. `patch` is what changed (the whole
   * options on a load).
   */
  apply(patch = this.opts) {
    const change = { patch, full: patch === this.opts };
    const values = APPLYING.map((f) => /** @type {const} */ ([f, check(f, this.opts)]));
    for (const [f, v] of values) f.early?.(this, v);
    for (const [f, v] of values) f.apply?.(this, v, change);
    if (this.model.motion) {
      this.viewer.rebuild();
      for (const [f, v] of values) f.drawn?.(this, v, change);
    }
    this.clearMessage();
    this.refreshChrome();
  }

  /**
   * The options that apply before the figure starts (the canvas's accessible name, what a touch
   * leaves to the page).
   */
  applyChrome() {
    for (const f of EARLY) f.early(this, check(f, this.opts, true));
  }

  // ---------------------------------------------------------------- sources

  /** Loads the source (a newer load wins over an older one still fetching). */
  async load() {
    const gen = ++this.generation;
    const src = await fetchSource(this.opts, this.wasm, this.viewer.scenes);
    if (gen !== this.generation || !this.viewer) return;
    const { model } = this;
    const w = this.wasm;
    let motion;
    const attr = this.opts.src ? 'src' : this.opts.share ? 'share' : this.opts.inline != null ? 'script' : 'preset';
    try {
      motion = src.scene ? w.Motion.fromPreset(src.scene) : new w.Motion(src.doc, src.options ?? {});
      if (!src.scene && src.view?.scene) model.view.scene = String(src.view.scene);
    } catch (e) {
      throw new OptionError(attr, attr === 'preset' ? src.scene : attr === 'script' ? 'application/json' : this.opts[attr], e.message);
    }
    const saved = restorePersisted(this.opts.persist);
    if (saved) {
      try {
        const m = new w.Motion(saved.document, saved.options);
        motion.free();
        motion = m;
      } catch {
        // A stale save is ignored (the source stands).
      }
    }
    model.motion?.free();
    model.motion = motion;
    model.view.scene = src.scene ?? (this.viewer.scenes.some((s) => s.id === model.view.scene) ? model.view.scene : 'l_cycle_rotated');
    model.view.object = src.scene ? 'scene' : 'bar';
    if (src.view && typeof src.view.object === 'string' && src.view.object !== 'obj') model.view.object = src.view.object;
    if (!src.scene && src.view?.object === 'scene') model.view.object = 'scene';
    model.view.strobe = src.view?.strobe ?? 32;
    model.selected = -1;
    model.anim.u = motion.domain()[0];
    this.viewer.meshesChanged();
    try {
      this.apply(this.opts);
    } catch (e) {
      this.viewer.rebuild();
      throw e;
    }
    if (!this.opts.camera) this.viewer.frameAll();
    if (src.camera && !this.opts.camera) {
      this.viewer.camera.load(src.camera);
      this.viewer.cameraMoved();
    }
    this.viewer.setPlaying(bool(this.opts.autoplay));
    this.viewer.updateAnim();
    // What was asked before the motion loaded (the camera, the time, play) takes effect.
    for (const f of FEATURES) f.loaded?.(this);
  }

  // ---------------------------------------------------------------- persistence (opt-in)

  /** Saves the motion under the `persist` key, if any (source.js). */
  persist() {
    persist(this.opts.persist, this.model.motion);
  }

  // ---------------------------------------------------------------- chrome (chrome.js) and playback

  onKey(e) {
    onKey(this, e);
  }

  refreshChrome() {
    refreshChrome(this);
  }

  timeChanged(playhead) {
    timeChanged(this, playhead);
  }

  get playing() {
    return this.model.anim.playing;
  }

  /** Plays (playback.js: `repetitions` passes, else as loop says). */
  play(opts) {
    this.playback.play(opts);
  }

  pause() {
    this.playback.pause();
  }

  /**
   * Shows the moving object at time t in seconds (the motion's key times: pose i at
   * motion.times[i], else at i s; a cycle wraps, an open motion holds its end poses).
   */
  seek(t) {
    this.playback.seek(t);
  }

  /** Steps the playhead to the next (dir 1) or previous (-1) key pose's time (the arrow keys). */
  stepKey(dir) {
    this.playback.stepKey(dir);
  }

  select(k) {
    this.model.selected = k;
    this.viewer.rebuildControls();
    this.say(k >= 0 ? `${describePose(this.model.motion, k)} selected` : 'No pose selected');
    this.emit('select', { index: k });
  }

  // ---------------------------------------------------------------- editing (editable only)

  /** The pointer tool of an editable figure (editing.js). */
  editTool() {
    return editTool(this);
  }
}

