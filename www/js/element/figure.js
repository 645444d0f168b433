// One figure: the viewer (view/viewer.js) on a canvas in a shadow root, with its chrome, its
// source and its options; what the element <screw-bender> and mount() (screw-bender.js) drive.
// Its parts: options.js (names and checks), sources.js (where the motion comes from, the opt-in
// saved copy), chrome.js (shadow tree, control bar, keys), edit-tool.js (editing), labels.js
// (labels on poses), showing.js (lazy start, poster, hidden slides, print), playback.js (the
// media-element API, the camera as state, pictures), wasm.js (the module instance all figures
// share).
import { Viewer, newModel } from '../view/viewer.js';
import { DEFAULT_NAME, bindChrome, buildChrome, onKey, refreshChrome, timeChanged } from './chrome.js';
import { editTool } from './edit-tool.js';
import { Labels } from './labels.js';
import {
  ALIASES, CONTROLS, DEFAULT_SHOW, canonical, LAYERS, LAYER_FIELD, MAX_STROBE, OptionError, THEMES, TOUCH, bool, cameraView, number, oneOf,
  subdivisionOptions,
} from './options.js';
import { Playback, describePose, schemeName } from './playback.js';
import { drawWhenShown, forget, isPrinting, keepStill, printable, showPoster, whenNear } from './showing.js';
import { fetchSource, persist, restorePersisted } from './sources.js';
import { loadWasm, serially } from './wasm.js';

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
    // Set by showing.js: whether the figure is on screen, the wake-up of a lazy start, the
    // timer that suspends an off-screen figure.
    /** @type {boolean | undefined} */
    this.onScreen;
    /** @type {(() => void) | undefined} */
    this.wake;
    /** @type {ReturnType<typeof setTimeout> | undefined} */
    this.suspendTimer;
    this.generation = 0;
    const { root, el } = buildChrome(host);
    this.root = root;
    this.el = el;
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
      const w = await loadWasm({ webgl2: this.opts.backend === 'webgl2' });
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
        onCamera: (source) => this.playback.cameraMoved(source),
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
   * Far from the viewport for a while (showing.js): frees the renderer and its graphics
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
    try {
      return Promise.resolve(f()).catch((e) => this.fail(e.attribute ?? null, e.message, e.value));
    } catch (e) {
      this.fail(e.attribute ?? null, e.message, e.value);
      return Promise.resolve();
    }
  }

  /** Shows `message` inside the figure and fires `error` {attribute, value, message}. */
  fail(attribute, message, value) {
    this.el.msg.textContent = message;
    this.el.msg.hidden = false;
    this.el.fig.classList.add('failed');
    this.emit('error', { attribute, value: value ?? null, message });
  }

  clearMessage() {
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
    this.el.live.textContent = text;
  }

  // ---------------------------------------------------------------- options

  /** Changes options (a partial object); a change of source reloads, the rest applies in place. */
  setOptions(patch) {
    patch = canonical(patch);
    const before = this.opts;
    this.opts = { ...this.opts, ...patch };
    // A current name given alone replaces a former name kept beside it.
    for (const [old, now] of Object.entries(ALIASES)) if (now in patch && !(old in patch)) delete this.opts[old];
    if ('loading' in patch && patch.loading === 'eager') this.wake?.();
    if ('poster' in patch) showPoster(this);
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

  /** Applies every option but the source to the model and the chrome (checks them first). */
  apply(patch = this.opts) {
    const o = this.opts;
    const { model } = this;
    // Check everything before changing anything.
    const sub = subdivisionOptions(o);
    const strobe = o.strobe != null && o.strobe !== '' ? number('strobe', o.strobe, 0, MAX_STROBE, true) : null;
    const speed = o.speed != null && o.speed !== '' ? number('speed', o.speed, 0, 100) : 1;
    const controls = o.controls != null && o.controls !== '' ? oneOf('controls', o.controls, CONTROLS) : 'minimal';
    const theme = o.theme != null && o.theme !== '' ? oneOf('theme', o.theme, THEMES) : 'light';
    const show = String(o.show ?? DEFAULT_SHOW).trim().split(/\s+/).filter(Boolean);
    for (const s of show) if (!LAYERS.includes(s)) throw new OptionError('show', o.show, `unknown layer ${s} (layers: ${LAYERS.join(', ')})`);
    const cam = o.camera != null && o.camera !== '' ? cameraView(o.camera) : null;
    this.applyChrome();
    if (model.motion && Object.keys(sub).length) {
      const old = model.motion.options();
      try {
        model.motion.setOptions(sub);
      } catch (e) {
        model.motion.setOptions(old);
        const key = ['levels', 's', 'scheme', 'rules'].find((k) => k in sub) ?? 'levels';
        throw new OptionError(key, o[key], e.message);
      }
    }
    if (strobe !== null) model.view.strobe = strobe;
    for (const l of LAYERS) model.view[LAYER_FIELD[l]] = show.includes(l);
    if (model.view.strobe === 0) model.view.showStrobe = false;
    // A full apply (a load) sets the rate and loop from the options; a patch only what it names
    // (playbackRate and loop set as properties stay).
    const full = patch === this.opts;
    if (full || 'speed' in patch) model.anim.speed = speed;
    if (full || 'loop' in patch) model.anim.loop = o.loop == null ? true : bool(o.loop);
    this.el.fig.dataset.controls = controls;
    this.el.fig.dataset.theme = theme;
    // The 3-D view's background and line colours follow the chrome.
    this.viewer?.setDark(theme === 'dark');
    if (!this.editable && model.selected >= 0) model.selected = -1;
    if (model.motion) {
      if (cam && ('camera' in patch || patch === this.opts)) {
        this.viewer.frameAll();
        this.viewer.camera.yaw = cam.yaw;
        this.viewer.camera.pitch = cam.pitch;
        if (cam.distance) this.viewer.camera.distance = cam.distance;
        if (cam.target) this.viewer.camera.target = [...cam.target];
        this.viewer.cameraMoved();
      }
      this.viewer.rebuild();
      if ('autoplay' in patch && !full) this.viewer.setPlaying(bool(o.autoplay));
      if (!full && Object.keys(sub).length) {
        const m = model.motion.options();
        this.say(`${schemeName(m)}, ${m.levels} level${m.levels === 1 ? '' : 's'}`);
      }
    }
    this.clearMessage();
    this.refreshChrome();
  }

  /**
   * The options of the chrome alone, which apply before the figure starts: `alt` (the canvas's
   * accessible name) and `touch-action` (what a touch on the unfocused figure leaves to the page).
   */
  applyChrome() {
    const o = this.opts;
    const touch = o['touch-action'] != null && o['touch-action'] !== '' ? oneOf('touch-action', o['touch-action'], TOUCH) : 'pan-y';
    this.el.fig.dataset.touch = touch;
    const alt = o.alt != null && String(o.alt).trim() !== '' ? String(o.alt) : DEFAULT_NAME;
    if (this.el.canvas.getAttribute('aria-label') !== alt) this.el.canvas.setAttribute('aria-label', alt);
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
    this.playback.loaded();
  }

  // ---------------------------------------------------------------- persistence (opt-in)

  /** Saves the motion under the `persist` key, if any (sources.js). */
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

  /** The pointer tool of an editable figure (edit-tool.js). */
  editTool() {
    return editTool(this);
  }
}

