// The embeddable figure: the custom element <screw-bender> and mount(element, options) for
// frameworks, built from the playground's view (view/viewer.js: one renderer, camera, picking
// and drawing path; this file only adds the figure's chrome, its sources and its manners).
//
//   <script type="module" src=".../element/screw-bender.js"></script>
//   <screw-bender scene="l_cycle_rotated" levels="4" autoplay>caption text</screw-bender>
//
// Sources (the first present wins): `src` (URL of a motion .json or .glb), `share` (a share-link
// payload, the part after `#s=`), an inline <script type="application/json"> child (a motion
// document), `scene` (a preset id). Options: scheme, levels, j, rules, strobe, show (layers:
// strobe control trajectories polyscrew polygon triads grid), autoplay, loop, speed, editable,
// controls (none | minimal | full), camera (iso | front | side | top, or "yaw pitch [distance]"
// in degrees and scene units), theme (light | dark), persist (a localStorage key; without it the
// figure never touches storage). Properties: document, options, motion (read-only), backend,
// ready (a Promise); methods play(), pause(), seek(t) (seconds); events change {poses}, select
// {index}, time {t, u, start, end} (seconds and parameter), error {attribute, value, message}
// (they do not bubble out of the figure as exceptions: every failure is a message inside the
// figure plus an `error` event).
//
// Good guest manners: one wasm module instance for all figures (a module-level promise); no
// listener outside the figure's own shadow tree; the wheel zooms only while the figure has the
// focus; keys only while focused; frames only while on screen (IntersectionObserver); removing
// the element frees its GPU data and observers; no inline script or style (the stylesheet is
// css/screw-bender.css beside this folder), so a strict CSP with 'wasm-unsafe-eval' suffices.
import { Viewer, newModel } from '../view/viewer.js';
import { beginPoseDrag, dragTarget, hoverPoseTool, redrawPoseDrag, setDragPose } from '../view/pose-drag.js';
import { loadMain, loadGl } from './modules.js';

/** Attributes the element watches (each maps onto an option of mount()). */
export const ATTRIBUTES = [
  'scene', 'src', 'share', 'scheme', 'levels', 'j', 'rules', 'strobe', 'show', 'autoplay', 'loop',
  'speed', 'editable', 'controls', 'camera', 'theme', 'persist',
];
/** Layers of the `show` option, and those shown by default. */
export const LAYERS = ['strobe', 'control', 'trajectories', 'polyscrew', 'polygon', 'triads', 'grid'];
const DEFAULT_SHOW = 'strobe control trajectories polygon triads grid';
const LAYER_FIELD = {
  strobe: 'showStrobe', control: 'showControl', trajectories: 'showTrajectories', polyscrew: 'showPolyscrew',
  polygon: 'showPolygon', triads: 'showTriads', grid: 'showGrid',
};
const SCHEMES = ['bspline', 'fourpoint', 'jarek', 'j'];
const RULES = ['direct', 'split'];
const CONTROLS = ['none', 'minimal', 'full'];
const THEMES = ['light', 'dark'];
/** Named camera views: yaw and pitch in degrees. */
const VIEWS = { iso: [-60, 34], front: [-90, 5], side: [0, 5], top: [-90, 89] };
const MAX_STROBE = 20000;
/** Largest motion file `src` may name (bytes); larger ones are refused before parsing. */
const MAX_SRC_BYTES = 32 << 20;

let wasmReady = null;
/**
 * The one wasm module instance all figures share (initialised on first use): the main module,
 * or the WebGL2 module when there is one and WebGPU offers no usable adapter.
 */
function loadWasm() {
  wasmReady ??= (async () => {
    let adapter = null;
    if (loadGl && navigator.gpu) {
      try {
        adapter = await navigator.gpu.requestAdapter();
      } catch {
        adapter = null;
      }
    }
    const m = await (loadGl && !adapter ? loadGl() : loadMain());
    await m.default();
    return m;
  })();
  return wasmReady;
}

/** Figures open their renderers one after another, so the first one's WebGPU device is shared. */
let startChain = Promise.resolve();
function serially(f) {
  const run = startChain.then(f, f);
  startChain = run.catch(() => {});
  return run;
}

/** An error naming the option (attribute) and the value that caused it. */
class OptionError extends Error {
  constructor(attribute, value, message) {
    super(`${attribute}="${String(value).slice(0, 120)}": ${message}`);
    this.attribute = attribute;
    this.value = value;
  }
}

const bool = (v) => v !== undefined && v !== null && v !== false && v !== 'false';

/** Reads and checks one option; throws an OptionError on a bad value. */
function number(name, value, lo, hi, integer = false) {
  const x = typeof value === 'number' ? value : Number(String(value).trim());
  if (String(value).trim() === '' || !Number.isFinite(x)) throw new OptionError(name, value, 'not a number');
  if (integer && !Number.isInteger(x)) throw new OptionError(name, value, 'not a whole number');
  if (x < lo || x > hi) throw new OptionError(name, value, `out of range (${lo} to ${hi})`);
  return x;
}

function oneOf(name, value, list) {
  if (!list.includes(value)) throw new OptionError(name, value, `expected one of ${list.join(', ')}`);
  return value;
}

/** Camera option → {yaw, pitch, distance?} in radians. */
function cameraView(value) {
  const v = String(value).trim();
  if (VIEWS[v]) return { yaw: (VIEWS[v][0] * Math.PI) / 180, pitch: (VIEWS[v][1] * Math.PI) / 180 };
  const parts = v.split(/[\s,]+/).map(Number);
  if ((parts.length === 2 || parts.length === 3) && parts.every(Number.isFinite) && Math.abs(parts[1]) <= 89.9 && !(parts[2] <= 0)) {
    return { yaw: (parts[0] * Math.PI) / 180, pitch: (parts[1] * Math.PI) / 180, distance: parts[2] };
  }
  throw new OptionError('camera', value, `expected ${Object.keys(VIEWS).join(', ')} or "yaw pitch [distance]" (degrees; |pitch| < 90)`);
}

/**
 * A figure in `host` (any element): the viewer on a canvas in a shadow root, its chrome and its
 * source. `options` as the attributes (camelCase not needed: every name is one word); `emit`
 * dispatches the events. Created by mount() and by the element.
 */
class Figure {
  constructor(host, emit) {
    this.host = host;
    this.emit = emit;
    this.opts = {};
    this.model = newModel('');
    this.generation = 0;
    const root = host.shadowRoot ?? host.attachShadow({ mode: 'open' });
    root.replaceChildren();
    const link = document.createElement('link');
    link.rel = 'stylesheet';
    link.href = new URL('../../css/screw-bender.css', import.meta.url).href;
    const fig = document.createElement('div');
    fig.className = 'fig';
    // Built node by node, not from an HTML string: the element must work under a CSP that
    // forbids string-to-HTML sinks (and the page's own test refuses them).
    const node = (tag, attrs = {}, ...children) => {
      const e = document.createElement(tag);
      for (const [k, v] of Object.entries(attrs)) {
        if (k === 'text') e.textContent = v;
        else if (k === 'hidden') e.hidden = v;
        else e.setAttribute(k, v);
      }
      e.append(...children);
      return e;
    };
    const schemes = [['bspline', 'B-spline'], ['fourpoint', '4-point'], ['jarek', 'Jarek']];
    fig.append(
      node('canvas', { tabindex: '0', part: 'canvas', 'aria-label': '3-D figure of a rigid motion' }),
      node('div', { class: 'bar', part: 'controls' },
        node('button', { class: 'play', type: 'button', 'aria-label': 'Play', text: '▶' }),
        node('input', { class: 'scrub', type: 'range', min: '0', max: '1000', value: '0', 'aria-label': 'Playback time' }),
        node('span', { class: 'time', text: 'u = 0' }),
        node('span', { class: 'full' },
          node('select', { class: 'scheme', 'aria-label': 'Scheme' },
            ...schemes.map(([value, label]) => node('option', { value, text: label }))),
          node('label', {}, 'levels ',
            node('input', { class: 'levels', type: 'range', min: '0', max: '7', step: '1', value: '4' })),
          node('button', { class: 'frame', type: 'button', title: 'Frame all (A)', text: 'Frame' }))),
      node('div', { class: 'msg', role: 'alert', hidden: true }),
      node('div', { class: 'caption' }, node('slot')),
    );
    root.append(link, fig);
    this.root = root;
    this.el = {
      fig,
      canvas: fig.querySelector('canvas'),
      bar: fig.querySelector('.bar'),
      play: fig.querySelector('.play'),
      scrub: fig.querySelector('.scrub'),
      time: fig.querySelector('.time'),
      scheme: fig.querySelector('.scheme'),
      levels: fig.querySelector('.levels'),
      frame: fig.querySelector('.frame'),
      msg: fig.querySelector('.msg'),
    };
    this.bindChrome();
  }

  // ---------------------------------------------------------------- start and stop

  /** Starts the wasm module and the viewer (once); resolves when the first motion is drawn. */
  start(options) {
    this.opts = { ...options };
    this.ready = this.guard(async () => {
      const w = await loadWasm();
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
        onPlay: () => this.refreshChrome(),
      });
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
      this.el.canvas = this.viewer.canvas;
      this.el.canvas.addEventListener('keydown', (e) => this.guard(() => this.onKey(e)));
      this.el.fig.dataset.backend = this.viewer.backend;
      this.viewer.bindPointer(this.editable ? this.editTool() : { click: () => {} });
      this.observer = new IntersectionObserver((entries) => {
        for (const e of entries) this.viewer?.setVisible(e.isIntersecting);
      });
      this.observer.observe(this.host);
      await this.load();
    });
    return this.ready;
  }

  /** Frees the GPU data, the motion and the observers; the figure is done. */
  dispose() {
    this.disposed = true;
    this.generation++;
    this.observer?.disconnect();
    this.observer = null;
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

  // ---------------------------------------------------------------- options

  /** Changes options (a partial object); a change of source reloads, the rest applies in place. */
  setOptions(patch) {
    const before = this.opts;
    this.opts = { ...this.opts, ...patch };
    if (!this.viewer) return this.ready;
    const reload = ['scene', 'src', 'share', 'inline'].some((k) => k in patch && patch[k] !== before[k]);
    if ('editable' in patch && bool(patch.editable) !== bool(before.editable)) {
      // The pointer listeners live on the canvas: a fresh canvas takes the new tool.
      this.model.selected = -1;
      const fresh = this.el.canvas.cloneNode(false);
      this.el.canvas.replaceWith(fresh);
      this.el.canvas = fresh;
      this.observer?.disconnect();
      this.viewer.dispose();
      this.viewer = null;
      return this.start(this.opts);
    }
    return this.guard(() => (reload ? this.load() : this.apply(patch)));
  }

  /** The subdivision options among `o` (checked), for Motion.setOptions. */
  subdivisionOptions(o) {
    const out = {};
    if (o.scheme != null && o.scheme !== '') out.scheme = oneOf('scheme', o.scheme, SCHEMES);
    if (o.j != null && o.j !== '') {
      out.j = number('j', o.j, -4, 4);
      out.scheme ??= 'j';
    }
    if (o.rules != null && o.rules !== '') out.rules = oneOf('rules', o.rules, RULES);
    if (o.levels != null && o.levels !== '') out.levels = number('levels', o.levels, 0, 12, true);
    return out;
  }

  /** Applies every option but the source to the model and the chrome (checks them first). */
  apply(patch = this.opts) {
    const o = this.opts;
    const { model } = this;
    // Check everything before changing anything.
    const sub = this.subdivisionOptions(o);
    const strobe = o.strobe != null && o.strobe !== '' ? number('strobe', o.strobe, 0, MAX_STROBE, true) : null;
    const speed = o.speed != null && o.speed !== '' ? number('speed', o.speed, 0, 100) : 1;
    const controls = o.controls != null && o.controls !== '' ? oneOf('controls', o.controls, CONTROLS) : 'minimal';
    const theme = o.theme != null && o.theme !== '' ? oneOf('theme', o.theme, THEMES) : 'light';
    const show = String(o.show ?? DEFAULT_SHOW).trim().split(/\s+/).filter(Boolean);
    for (const s of show) if (!LAYERS.includes(s)) throw new OptionError('show', o.show, `unknown layer ${s} (layers: ${LAYERS.join(', ')})`);
    const cam = o.camera != null && o.camera !== '' ? cameraView(o.camera) : null;
    if (model.motion && Object.keys(sub).length) {
      const old = model.motion.options();
      try {
        model.motion.setOptions(sub);
      } catch (e) {
        model.motion.setOptions(old);
        const key = ['levels', 'j', 'scheme', 'rules'].find((k) => k in sub) ?? 'levels';
        throw new OptionError(key, o[key], e.message);
      }
    }
    if (strobe !== null) model.view.strobe = strobe;
    for (const l of LAYERS) model.view[LAYER_FIELD[l]] = show.includes(l);
    if (model.view.strobe === 0) model.view.showStrobe = false;
    model.anim.speed = speed;
    model.anim.loop = o.loop == null ? true : bool(o.loop);
    this.el.fig.dataset.controls = controls;
    this.el.fig.dataset.theme = theme;
    if (!this.editable && model.selected >= 0) model.selected = -1;
    if (model.motion) {
      if (cam && ('camera' in patch || patch === this.opts)) {
        this.viewer.frameAll();
        this.viewer.camera.yaw = cam.yaw;
        this.viewer.camera.pitch = cam.pitch;
        if (cam.distance) this.viewer.camera.distance = cam.distance;
        this.viewer.cameraMoved();
      }
      this.viewer.rebuild();
      if ('autoplay' in patch && patch !== this.opts) this.viewer.setPlaying(bool(o.autoplay));
    }
    this.clearMessage();
    this.refreshChrome();
  }

  // ---------------------------------------------------------------- sources

  /** The motion document (and display hints) of the current source. */
  async fetchSource() {
    const o = this.opts;
    const w = this.wasm;
    if (o.src) {
      let url;
      try {
        url = new URL(o.src, document.baseURI);
      } catch {
        throw new OptionError('src', o.src, 'not a URL');
      }
      let res;
      try {
        res = await fetch(url);
      } catch (e) {
        throw new OptionError('src', o.src, `unreachable (${e.message})`);
      }
      if (!res.ok) throw new OptionError('src', o.src, `HTTP ${res.status}`);
      const bytes = new Uint8Array(await res.arrayBuffer());
      if (bytes.length > MAX_SRC_BYTES) throw new OptionError('src', o.src, `${bytes.length} bytes, more than ${MAX_SRC_BYTES}`);
      const name = url.pathname.split('/').pop() || 'motion.json';
      try {
        if (/\.(glb|gltf|csv)$/i.test(name)) return { doc: w.importMotionFile(name, bytes) };
        return { doc: JSON.parse(new TextDecoder().decode(bytes)) };
      } catch (e) {
        throw new OptionError('src', o.src, e.message);
      }
    }
    if (o.share) {
      // Imported only for share payloads (it brings the playground's session code).
      const { decodeHash } = await import('../editor/session.js');
      let s;
      try {
        s = decodeHash(String(o.share).replace(/^.*#s=/, ''));
      } catch (e) {
        const v = String(o.share);
        throw new OptionError('share', v.length > 40 ? `${v.slice(0, 40)}…` : v, e.message);
      }
      return { doc: s.document, options: s.options, view: s.view, camera: s.camera };
    }
    if (o.inline != null) {
      try {
        return { doc: JSON.parse(o.inline) };
      } catch (e) {
        throw new OptionError('script', 'application/json', `not JSON: ${e.message}`);
      }
    }
    const id = o.scene || 'l_cycle_rotated';
    const info = this.viewer.scenes.find((s) => s.id === id);
    if (!info) throw new OptionError('scene', id, `unknown scene (known: ${this.viewer.scenes.map((s) => s.id).join(', ')})`);
    return { scene: id };
  }

  /** Loads the source (a newer load wins over an older one still fetching). */
  async load() {
    const gen = ++this.generation;
    const src = await this.fetchSource();
    if (gen !== this.generation || !this.viewer) return;
    const { model } = this;
    const w = this.wasm;
    let motion;
    const attr = this.opts.src ? 'src' : this.opts.share ? 'share' : this.opts.inline != null ? 'script' : 'scene';
    try {
      motion = src.scene ? w.Motion.fromScene(src.scene) : new w.Motion(src.doc, src.options ?? {});
      if (!src.scene && src.view?.scene) model.view.scene = String(src.view.scene);
    } catch (e) {
      throw new OptionError(attr, attr === 'scene' ? src.scene : attr === 'script' ? 'application/json' : this.opts[attr], e.message);
    }
    const saved = this.restorePersisted();
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
  }

  // ---------------------------------------------------------------- persistence (opt-in)

  restorePersisted() {
    const key = this.opts.persist;
    if (!key) return null;
    try {
      const text = localStorage.getItem(String(key));
      return text ? JSON.parse(text) : null;
    } catch {
      return null;
    }
  }

  persist() {
    const key = this.opts.persist;
    if (!key || !this.model.motion) return;
    try {
      localStorage.setItem(String(key), JSON.stringify({ document: this.model.motion.toDocument(), options: this.model.motion.options() }));
    } catch {
      // Storage full or blocked: the figure still works.
    }
  }

  // ---------------------------------------------------------------- chrome

  bindChrome() {
    const { play, scrub, scheme, levels, frame } = this.el;
    play.addEventListener('click', () => this.guard(() => (this.playing ? this.pause() : this.play())));
    scrub.addEventListener('input', () =>
      this.guard(() => {
        const m = this.model.motion;
        if (!m) return;
        const [a, b] = m.timeDomain();
        this.seek(a + ((b - a) * Number(scrub.value)) / 1000);
      }),
    );
    scheme.addEventListener('change', () => this.guard(() => this.setOptions({ scheme: scheme.value, j: null })));
    levels.addEventListener('input', () => this.guard(() => this.setOptions({ levels: Number(levels.value) })));
    frame.addEventListener('click', () => this.guard(() => this.viewer?.frameAll()));
  }

  /** Keys, only while the canvas has the focus (the listener is on the canvas). */
  onKey(e) {
    if (!this.viewer || !this.model.motion) return;
    const k = e.key;
    const n = this.model.motion.poseCount;
    let handled = true;
    if (k === ' ') this.playing ? this.pause() : this.play();
    else if (k === 'a' || k === 'Home') this.viewer.frameAll();
    else if (this.editable && (k === 'ArrowRight' || k === 'ArrowLeft')) {
      const s = this.model.selected;
      this.select(k === 'ArrowRight' ? (s + 1) % n : (s - 1 + n) % n);
    } else if (this.editable && (k === 'w' || k === 'e')) {
      this.model.mode = k === 'w' ? 'translate' : 'rotate';
      this.viewer.rebuildGizmo();
      this.viewer.requestDraw();
    } else if (this.editable && k === 'Escape') this.select(-1);
    else handled = false;
    if (handled) e.preventDefault();
  }

  refreshChrome() {
    const { play, scheme, levels } = this.el;
    play.textContent = this.playing ? '❚❚' : '▶';
    play.setAttribute('aria-label', this.playing ? 'Pause' : 'Play');
    const m = this.model.motion;
    if (m) {
      const o = m.options();
      scheme.value = o.scheme === 'j' ? '' : o.scheme;
      levels.value = String(o.levels);
    }
  }

  /** The playhead moved: {t, u, start, end}, times in seconds (the motion's own timing). */
  timeChanged({ t, u, start, end }) {
    this.el.scrub.value = String(Math.round(((t - start) / Math.max(1e-12, end - start)) * 1000));
    this.el.time.textContent = `${t.toFixed(2)} s`;
    this.emit('time', { t, u, start, end });
  }

  get playing() {
    return this.model.anim.playing;
  }

  play() {
    if (this.viewer && this.model.motion) this.viewer.setPlaying(true);
  }

  pause() {
    if (this.viewer && this.model.motion) this.viewer.setPlaying(false);
  }

  /**
   * Shows the moving object at time t in seconds (the motion's key times: pose i at
   * motion.times[i], else at i s; a cycle wraps, an open motion holds its end poses).
   */
  seek(t) {
    if (!this.viewer || !this.model.motion) return;
    this.viewer.seekTime(number('seek', t, -1e9, 1e9));
  }

  select(k) {
    this.model.selected = k;
    this.viewer.rebuildControls();
    this.emit('select', { index: k });
  }

  // ---------------------------------------------------------------- editing (editable only)

  /** The pointer tool of an editable figure: select a pose, drag it with the gizmo. */
  editTool() {
    const v = () => this.viewer;
    const begin = (part, pt, e) => {
      const { model } = this;
      const d = beginPoseDrag(v(), model.motion, model.selected, part, pt, e);
      if (!d) return false;
      model.drag = { part };
      this.drag = d;
      v().rebuildGizmo();
      return true;
    };
    const end = () => {
      const d = this.drag;
      if (!d) return;
      this.drag = null;
      this.model.drag = null;
      d.session?.free();
      if (d.moved) {
        this.viewer.rebuild();
        this.persist();
        this.emit('change', { poses: Float64Array.from(this.model.motion.poses()), index: d.index });
      }
      this.viewer.rebuildGizmo();
      this.viewer.requestDraw();
    };
    return {
      press: (pt, e) => {
        const part = v().gizmoHit(pt);
        if (part && begin(part, pt, e)) return 'drag';
        const k = v().pickPose(pt);
        if (k < 0) return null;
        if (k !== this.model.selected) this.select(k);
        return begin('view', pt, e) ? 'drag' : 'taken';
      },
      drag: (pt, e) =>
        this.guard(() => {
          const d = this.drag;
          if (!d) return;
          const pose = dragTarget(v(), d, pt, e.shiftKey);
          if (!pose) return;
          const fast = setDragPose(this.model.motion, d, pose, { polyscrew: this.model.view.showPolyscrew, live: true });
          d.moved = true;
          redrawPoseDrag(v(), d, pose, fast);
        }),
      release: () => this.guard(end),
      cancel: () => this.guard(end),
      hover: (pt) => hoverPoseTool(v(), this.model, pt),
      click: () => {
        if (this.model.selected >= 0) this.select(-1);
      },
    };
  }
}

/** Options from an element's attributes (and its inline JSON child). */
function optionsOf(el) {
  const o = {};
  for (const a of ATTRIBUTES) if (el.hasAttribute(a)) o[a] = el.getAttribute(a);
  for (const b of ['autoplay', 'editable']) if (o[b] === '') o[b] = true;
  const script = el.querySelector(':scope > script[type="application/json"]');
  if (script) o.inline = script.textContent;
  return o;
}

/**
 * Mounts a figure into `element` (any element; its content becomes the caption) with `options`
 * (the attributes' names; numbers and booleans may be given as such, and `document` as a motion
 * document object). Returns a handle {ready, document, options, motion, play(), pause(), seek(u),
 * destroy()}; events are dispatched on `element`. Failures show in the figure (and fire `error`);
 * only an `element` that cannot hold a shadow root throws (a TypeError, as attachShadow does).
 */
export function mount(element, options = {}) {
  const { document: doc, ...rest } = options;
  const fig = new Figure(element, (type, detail) => element.dispatchEvent(new CustomEvent(type, { detail })));
  if (doc !== undefined) rest.inline = JSON.stringify(doc);
  fig.start(rest);
  return handleOf(fig);
}

function handleOf(fig) {
  return {
    get ready() {
      return fig.ready;
    },
    get document() {
      return fig.model.motion?.toDocument() ?? null;
    },
    set document(doc) {
      fig.setOptions({ inline: JSON.stringify(doc), src: null, share: null, scene: null });
    },
    get options() {
      return { ...fig.opts, ...(fig.model.motion ? fig.model.motion.options() : {}) };
    },
    set options(patch) {
      fig.setOptions(patch ?? {});
    },
    get motion() {
      return fig.model.motion;
    },
    get backend() {
      return fig.viewer?.backend ?? null;
    },
    play: () => fig.guard(() => fig.play()),
    pause: () => fig.guard(() => fig.pause()),
    seek: (u) => fig.guard(() => fig.seek(u)),
    destroy: () => fig.dispose(),
    /** The viewer (for tests and advanced use): camera, picking, renderer. */
    get viewer() {
      return fig.viewer;
    },
  };
}

/** The custom element <screw-bender> (see the top of this file). */
export class ScrewBenderElement extends HTMLElement {
  static get observedAttributes() {
    return ATTRIBUTES;
  }

  connectedCallback() {
    // Moving the element in the page (disconnect then connect) keeps its figure.
    if (this.figure) return;
    this.figure = new Figure(this, (type, detail) => this.dispatchEvent(new CustomEvent(type, { detail })));
    this.handle = handleOf(this.figure);
    this.figure.start(optionsOf(this));
  }

  disconnectedCallback() {
    // Disposal waits a task: a move within the page reconnects at once.
    queueMicrotask(() => {
      if (!this.isConnected && this.figure) {
        this.figure.dispose();
        this.figure = null;
      }
    });
  }

  attributeChangedCallback(name, old, value) {
    if (!this.figure || old === value) return;
    const v = (name === 'autoplay' || name === 'editable') && value === '' ? true : value;
    this.figure.setOptions({ [name]: v ?? null });
  }

  get ready() {
    return this.figure?.ready ?? Promise.resolve();
  }

  get document() {
    return this.handle?.document ?? null;
  }

  set document(doc) {
    if (this.handle) this.handle.document = doc;
  }

  get options() {
    return this.handle?.options ?? optionsOf(this);
  }

  set options(patch) {
    if (this.handle) this.handle.options = patch;
  }

  get motion() {
    return this.handle?.motion ?? null;
  }

  get backend() {
    return this.handle?.backend ?? null;
  }

  /** The viewer behind the figure (camera, picking, renderer), for tests and advanced use. */
  get viewer() {
    return this.figure?.viewer ?? null;
  }

  play() {
    return this.handle?.play();
  }

  pause() {
    return this.handle?.pause();
  }

  seek(u) {
    return this.handle?.seek(u);
  }
}

if (!customElements.get('screw-bender')) customElements.define('screw-bender', ScrewBenderElement);
