// The 3-D view on its own: a wasm Renderer on a canvas, an orbit camera with its pointer
// gestures, the frame loop, and the drawing and picking of a motion model.
//
// It imports nothing of the editor (panel, dock, toolbar, timeline) and looks up no element of
// the page, so the same view can be embedded elsewhere (a <screw-bender> element); the editor
// drives it through this class and hears back through the hooks of the options.
//
//   const viewer = new Viewer(canvas, wasm, { model, webgl2, warn, onTime, onPlay });
//   await viewer.start();           // renderer (WebGPU, else WebGL2), resize observer, frame loop
//   viewer.meshesChanged(); viewer.rebuild(); viewer.frameAll();
//   viewer.bindPointer(tool);       // camera gestures; `tool` (optional) takes presses on content
//   viewer.setVisible(false);       // off screen: no frames drawn (an IntersectionObserver's call)
//   viewer.isShown = () => bool;    // optional: false skips drawing (a hidden slide, opacity 0)
//   viewer.dispose();               // stops the loop and observers, frees the renderer's GPU data
//
// `wasm` is the initialised wasm-bindgen module (Renderer, Motion, DragSession, scenes). The
// model is read afresh on every rebuild, never copied, so its owner edits it in place and then
// calls the matching rebuild (see newModel for its fields).
import { OrbitCamera } from './camera.js';
import { SLOT, BACKGROUND } from './slots.js';
import { Drawing } from './drawing.js';
import * as picking from './picking.js';
import { bindPointer } from './pointer.js';

/**
 * The display settings the viewer draws by (the playground's App adds its own to them).
 * @typedef {object} ViewSettings
 * @property {string} scene preset id: the object drawn for 'scene' and its body points
 * @property {string} object 'scene', a named shape (bar, block, …) or 'obj' (the imported mesh)
 * @property {number} strobe
 * @property {boolean} showStrobe
 * @property {boolean} showControl
 * @property {boolean} showTrajectories
 * @property {boolean} showPolyscrew
 * @property {boolean} showPolygon
 * @property {boolean} showTriads
 * @property {boolean} showGrid
 * @property {boolean} [gizmoLocal] the gizmo in the selected pose's own axes
 */

/**
 * What a viewer draws and plays (its `model`): newModel() for a figure of its own; the
 * playground's App hands its state in through App.viewerModel(). The viewer writes only `anim`
 * (its frame loop advances the playhead).
 * @typedef {object} Model
 * @property {any} motion the wasm Motion
 * @property {ViewSettings} view
 * @property {number} selected selected control pose (gets the gizmo), or -1
 * @property {'translate' | 'rotate'} mode
 * @property {{playing: boolean, u: number, t?: number, tu?: number, speed: number, loop: boolean, visible: boolean, passes?: number | null}} anim
 * @property {{kind: string, data: string | Uint8Array} | null} imported
 * @property {string | null} hover gizmo part under the pointer
 * @property {number} [hoverPose] control pose under the pointer (-1: none)
 * @property {{part: string} | null} drag the drag in progress: its `part` is drawn highlighted
 */

/**
 * The options of `new Viewer(canvas, wasm, options)` (see the constructor).
 * @typedef {object} ViewerOptions
 * @property {Model} [model]
 * @property {boolean} [webgl2]
 * @property {(message: string) => void} [warn]
 * @property {(u: number, a: number, b: number, playhead: {t: number, start: number, end: number}) => void} [onTime]
 * @property {(playing: boolean) => void} [onPlay]
 * @property {() => void} [onEnded]
 * @property {(source: string) => void} [onCamera]
 * @property {() => void} [onDraw]
 * @property {boolean} [wheelNeedsFocus]
 * @property {string} [what]
 */

/**
 * A model with nothing selected and the default display; `motion` must be set (a wasm Motion)
 * before the first rebuild. The editor's App is a model too: it has these fields.
 */
/** @returns {Model} */
export function newModel(scene = '') {
  return {
    motion: null,
    view: {
      scene, // preset id: the object drawn for 'scene' and its body points
      object: 'scene', // 'scene', a named shape (bar, block, …) or 'obj' (the imported mesh)
      strobe: 64,
      showStrobe: true,
      showControl: true,
      showTrajectories: true,
      showPolyscrew: false,
      showPolygon: true,
      showTriads: true,
      showGrid: true,
    },
    selected: -1, // selected control pose (gets the gizmo), or -1
    mode: 'translate', // gizmo: 'translate' | 'rotate'
    // Playback: u the parameter shown, t its time in seconds (tu: the u that t belongs to;
    // unknown t is derived from u by playTime).
    // speed: seconds of motion time per real second (negative plays backwards); passes: the
    // passes left to play before playback ends (null: as loop and closed say).
    anim: { playing: false, u: 0, t: undefined, tu: undefined, speed: 1, loop: true, visible: false, passes: null },
    imported: null, // {kind: 'obj', data: text} or {kind: 'gltf', data: base64}
    hover: null, // gizmo part under the pointer
    hoverPose: undefined, // control pose under the pointer (-1: none)
    drag: null, // the drag in progress: its `part` is drawn highlighted
  };
}

export class Viewer {
  /**
   * options: model (default newModel()); webgl2: true to skip WebGPU; warn(message): non-fatal
   * problems (a backend fallback, drags without live update); onTime(u, a, b, playhead): the
   * animated object moved (u in the parameter interval [a, b]; playhead as playhead() gives it,
   * in seconds); onPlay(playing): playback started or stopped; onEnded(): playback stopped at
   * an end by itself (an open motion without loop, or the last of `anim.passes`); onCamera(source):
   * the camera moved ('user': a gesture or key, 'api': code); onDraw(): a frame was drawn (the
   * last frame's view-projection is `vp`); wheelNeedsFocus: true to let
   * wheel events over an unfocused canvas scroll the page (an embedded figure), false to zoom
   * always (the playground, whose view fills the page); what: the subject of the no-graphics
   * message ('the playground', 'this figure').
   * @param {HTMLCanvasElement} canvas
   * @param {any} wasm the renderer's wasm module
   * @param {ViewerOptions} [options]
   */
  constructor(canvas, wasm, { model = newModel(), webgl2 = false, warn, onTime, onPlay, onEnded, onCamera, onDraw, wheelNeedsFocus = false, what = 'the playground' } = {}) {
    this.canvas = canvas;
    this.wasm = wasm;
    this.model = model;
    this.webgl2 = webgl2;
    this.warn = warn ?? ((m) => console.warn(m));
    const timeHook = onTime ?? (() => {});
    this.onTime = (u, a, b) => timeHook(u, a, b, this.playhead());
    this.onPlay = onPlay ?? (() => {});
    const none = () => {};
    this.onEnded = onEnded ?? none;
    this.onCamera = onCamera ?? none;
    this.onDraw = onDraw ?? none;
    this.isShown = () => true;
    this.wheelNeedsFocus = wheelNeedsFocus;
    this.what = what;
    this.scenes = wasm.presets();
    this.camera = new OrbitCamera();
    this.drawing = new Drawing(this);
    this.dirty = true;
    this.frames = 0;
    this.stats = { updateMs: 0, frameMs: 0, renderMs: 0 };
  }

  /** Starts the renderer (throws when the browser can draw neither way) and the frame loop. */
  async start() {
    const hasGpu = !!navigator.gpu;
    const { w, h } = this.pixelSize();
    const noGraphics = (e) =>
      new Error(`This browser offers neither WebGPU nor WebGL2, so ${this.what} cannot draw. (${e.message})`);
    const { Renderer } = this.wasm;
    try {
      this.renderer = await Renderer.create(this.canvas, !this.webgl2, w, h);
    } catch (e) {
      if (this.webgl2 || !hasGpu) throw noGraphics(e);
      // A failed WebGPU start falls back to WebGL2 on a fresh canvas (a canvas keeps the first
      // kind of context it gave out).
      this.replaceCanvas();
      try {
        this.renderer = await Renderer.create(this.canvas, false, w, h);
      } catch (e2) {
        throw noGraphics(e2);
      }
      this.warn(`WebGPU failed to start (${e.message}); using WebGL2.`);
    }
    this.backend = this.renderer.backend;
    if (!this.webgl2 && hasGpu && this.backend !== 'WebGPU') {
      this.warn('WebGPU is present but has no usable adapter; using WebGL2.');
    }
    this.loop = this.loop.bind(this);
    this.visible = true;
    this.rendererOpened();
  }

  /** The renderer's fixed meshes and background, the resize observer and the frame loop. */
  rendererOpened() {
    if (this.dark) this.renderer.setBackground(...BACKGROUND.dark);
    this.renderer.setMesh(SLOT.handle, 'unit-sphere', true);
    this.renderer.setMesh(SLOT.arrow, 'unit-cone', true);
    // A resize observer also reports when its observation starts, which comes right after the
    // first frame: a frame is drawn only for a size other than the last one drawn.
    this.drawnSize = null;
    this.resizeObserver = new ResizeObserver(() => {
      const m = this.measure();
      const d = this.drawnSize;
      if (d && m.w === d.w && m.h === d.h && m.cssW === d.cssW && m.cssH === d.cssH) return;
      this.sizeCache = null;
      this.requestDraw();
    });
    this.resizeObserver.observe(this.canvas);
    this.requestDraw();
  }

  /**
   * Frees the renderer (its GPU data, and the canvas's WebGL context, of which a browser keeps
   * only a few alive) and stops drawing, keeping the model, camera and playhead; resume() draws
   * again on a fresh canvas. False when there is no renderer to free.
   */
  suspend() {
    if (!this.renderer) return false;
    if (this.raf) cancelAnimationFrame(this.raf);
    this.raf = 0;
    this.resizeObserver?.disconnect();
    this.resizeObserver = null;
    this.renderer.free();
    this.renderer = null;
    // A WebGL canvas holds its context until it is lost or collected (a WebGPU one gives null).
    this.canvas.getContext('webgl2')?.getExtension('WEBGL_lose_context')?.loseContext();
    this.suspended = true;
    return true;
  }

  /** After suspend(): a renderer of the same backend on a fresh canvas, everything rebuilt. */
  async resume() {
    if (!this.suspended) return;
    this.replaceCanvas();
    this.sizeCache = null;
    const { w, h } = this.pixelSize();
    this.renderer = await this.wasm.Renderer.create(this.canvas, this.backend === 'WebGPU', w, h);
    this.suspended = false;
    this.rendererOpened();
    this.meshesChanged();
    this.rebuild();
    this.updateAnim();
  }

  /**
   * Shown (true) or off screen (false): an invisible viewer draws nothing and stops its frame
   * loop until it is shown again (playback resumes where it was).
   */
  setVisible(on) {
    this.visible = on;
    if (on && !this.raf && this.renderer) {
      this.lastNow = undefined;
      this.requestDraw();
    }
  }

  /** Stops the frame loop and the resize observer and frees the renderer (GPU buffers, surface). */
  dispose() {
    if (this.raf) cancelAnimationFrame(this.raf);
    this.raf = 0;
    this.visible = false;
    this.resizeObserver?.disconnect();
    this.resizeObserver = null;
    this.renderer?.free();
    this.renderer = null;
  }

  replaceCanvas() {
    const fresh = /** @type {HTMLCanvasElement} */ (this.canvas.cloneNode(false));
    this.canvas.replaceWith(fresh);
    this.canvas = fresh;
  }

  /** Camera gestures on the canvas; `tool` gets the presses on scene content (see pointer.js). */
  bindPointer(tool) {
    bindPointer(this, tool);
  }

  // ---------------------------------------------------------------- size and frame loop

  /** Canvas size (physical and CSS pixels), measured once per frame (layout reads are slow). */
  pixelSize() {
    if (!this.sizeCache) this.sizeCache = this.measure();
    return this.sizeCache;
  }

  /** Forgets the measured size (the canvas changed size outside a resize observation). */
  invalidateSize() {
    this.sizeCache = null;
  }

  measure() {
    const dpr = window.devicePixelRatio || 1;
    const r = this.canvas.getBoundingClientRect();
    return {
      w: Math.max(1, Math.round(r.width * dpr)),
      h: Math.max(1, Math.round(r.height * dpr)),
      cssW: r.width,
      cssH: r.height,
      dpr,
    };
  }

  requestDraw() {
    this.dirty = true;
    this.wake();
  }

  /**
   * Starts the frame loop unless it runs. It stops by itself when nothing is due (paused, the
   * last frame drawn), so that a page showing a still figure asks the processor for nothing
   * between changes.
   */
  wake() {
    if (!this.raf && this.visible && this.renderer) this.raf = requestAnimationFrame(this.loop);
  }

  loop(now) {
    this.raf = 0;
    if (!this.visible || !this.renderer) return;
    const { anim, motion } = this.model;
    // Nothing to draw until the model has a motion (the loop runs from start()).
    if (!motion) {
      this.raf = requestAnimationFrame(this.loop);
      return;
    }
    if (anim.playing) {
      // Real time: t advances in seconds (times the speed, which may be negative); the object
      // shows u = p(t). Past an end, playback wraps while passes remain (a cycle or a looping
      // open motion without a pass count wraps always), else it stops at that end.
      const dt = this.lastNow ? Math.min(0.5, (now - this.lastNow) / 1000) : 0;
      const [a, b] = motion.timeDomain();
      let t = this.playTime() + dt * anim.speed;
      if (t > b || t < a) {
        // A slow frame may cross more than one end (a high speed): each crossing is a pass.
        const span = b - a;
        const crossed = span > 0 ? Math.floor(t > b ? (t - a) / span : (b - t) / span) : Infinity;
        const wrap = span > 0 && (anim.passes == null ? motion.closed || anim.loop : anim.passes > crossed);
        if (wrap) {
          if (anim.passes != null) anim.passes -= crossed;
          t = a + ((((t - a) % span) + span) % span);
        } else {
          t = t > b ? b : a;
          anim.passes = null;
          this.showTime(t);
          this.setPlaying(false);
          this.onEnded();
        }
      }
      if (anim.playing) this.showTime(t);
      this.dirty = true;
    }
    this.lastNow = now;
    if (this.dirty && this.isShown()) this.draw();
    // Playing, or a frame still due (not shown yet, or the surface was not ready): the next
    // display frame looks again. Otherwise the loop rests until requestDraw or setPlaying.
    // (Something in this frame may have started it again already: requestDraw from a callback.)
    if (anim.playing || this.dirty) this.raf ||= requestAnimationFrame(this.loop);
    else if (!this.raf) this.lastNow = undefined;
  }

  draw() {
    const t0 = performance.now();
    this.sizeCache = this.measure();
    const { w, h, cssW, cssH } = this.sizeCache;
    this.renderer.resize(w, h);
    this.camera.aspect = cssW / Math.max(1, cssH);
    const vp = this.camera.viewProj();
    // Kept for picking: gizmo hits are tested against what was last drawn.
    this.vp = vp;
    this.renderer.setCamera(Float32Array.from(vp), Float32Array.from(this.camera.eye));
    const t1 = performance.now();
    // A frame the renderer could not draw (surface not ready) stays due.
    if (this.renderer.render()) {
      this.dirty = false;
      this.drawnSize = this.sizeCache;
    }
    const t2 = performance.now();
    this.stats.renderMs = t2 - t1;
    this.stats.frameMs = t2 - t0;
    this.frames++;
    this.onDraw();
  }

  // ---------------------------------------------------------------- playback in seconds

  /**
   * The playhead's time t in seconds: model.anim.t while it still belongs to the parameter shown
   * (anim.u), else the time at which the motion's own timing reaches anim.u (whoever set u
   * directly: a preset load, a session, a lesson step).
   */
  playTime() {
    const { anim, motion } = this.model;
    if (!(Number.isFinite(anim.t) && anim.tu === anim.u)) {
      anim.t = motion.timeAt(anim.u);
      anim.tu = anim.u;
    }
    return anim.t;
  }

  /** The playhead: time t (s) and parameter u shown, and the playback interval [start, end] (s). */
  playhead() {
    const [start, end] = this.model.motion.timeDomain();
    return { t: this.playTime(), u: this.model.anim.u, start, end };
  }

  /** Moves the animated object to time t (s; a cycle wraps, an open motion holds its ends). */
  showTime(t) {
    const { anim, motion } = this.model;
    const [a, b] = motion.timeDomain();
    const x = motion.closed ? a + ((((t - a) % (b - a)) + (b - a)) % (b - a)) : Math.min(b, Math.max(a, t));
    anim.u = motion.parameterAt(x);
    anim.t = x;
    anim.tu = anim.u;
    this.updateAnim();
  }

  /** Shows the animated object at time t in seconds (a seek: the object becomes visible). */
  seekTime(t) {
    this.model.anim.visible = true;
    this.showTime(t);
    this.requestDraw();
  }

  /**
   * After the motion's timing (or poses) changed: the playhead keeps its time and the object
   * moves to what the new timing shows then.
   */
  retime() {
    const { anim, motion } = this.model;
    if (!motion) return;
    if (Number.isFinite(anim.t) && anim.tu === anim.u) this.showTime(anim.t);
    else this.playTime();
  }

  /** Starts or stops playback; either way the animated object stays shown. */
  setPlaying(on) {
    const { anim } = this.model;
    anim.playing = on;
    anim.visible = true;
    this.lastNow = undefined;
    this.onPlay(on);
    this.requestDraw();
  }

  // ---------------------------------------------------------------- theme and pictures

  /** A dark (true) or light background, with line colours to match (slots.js palette). */
  setDark(on) {
    if (!!on === !!this.dark) return;
    this.dark = !!on;
    this.renderer?.setBackground(...BACKGROUND[this.dark ? 'dark' : 'light']);
    if (this.renderer && this.model.motion) this.rebuild();
    this.requestDraw();
  }

  /**
   * Draws the current view at `scale` times the drawing buffer once per background of
   * `backgrounds` (sRGB triples; null: the theme's), calling read(canvas, i) after each in the
   * same task (a WebGPU canvas is readable only until its frame is presented), then restores
   * the size and background. Throws, changing nothing, when the picture would exceed the
   * device's largest texture or cannot be drawn.
   */
  snapshot(scale, backgrounds, read) {
    const { w, h, cssW, cssH } = this.measure();
    const W = Math.round(w * scale);
    const H = Math.round(h * scale);
    const max = this.renderer.maxSize;
    if (W > max || H > max) throw new Error(`a ${W} × ${H} picture is larger than this graphics device allows (${max} × ${max})`);
    const own = BACKGROUND[this.dark ? 'dark' : 'light'];
    this.camera.aspect = cssW / Math.max(1, cssH);
    try {
      this.renderer.resize(W, H);
      this.renderer.setLineScale(scale);
      this.renderer.setCamera(Float32Array.from(this.camera.viewProj()), Float32Array.from(this.camera.eye));
      backgrounds.forEach((bg, i) => {
        this.renderer.setBackground(...(bg ?? own));
        // A surface that is not ready yet is reconfigured by the failed attempt.
        if (!this.renderer.render() && !this.renderer.render()) throw new Error('the view could not be drawn; try again');
        read(this.canvas, i);
      });
    } finally {
      this.renderer.setBackground(...own);
      this.renderer.setLineScale(1);
      this.renderer.resize(w, h);
      this.requestDraw();
    }
  }

  // ---------------------------------------------------------------- camera

  /** Frames the control poses (with a margin); `source` as cameraMoved's. */
  frameAll(source = 'api') {
    const { lo, hi } = this.drawing.bounds();
    const pad = 1.2;
    const { cssW, cssH } = this.pixelSize();
    this.camera.aspect = cssW / Math.max(1, cssH);
    this.camera.frame(lo.map((x) => x - pad), hi.map((x) => x + pad));
    this.cameraMoved(source);
  }

  /**
   * After the camera moved: handles keep their size on screen, so they are rebuilt. `source`:
   * 'user' for a gesture or key of the reader, 'api' (default) for code (onCamera hears both).
   */
  cameraMoved(source = 'api') {
    if (this.model.motion) this.drawing.rebuildHandles();
    this.requestDraw();
    this.onCamera(source);
  }

  // ---------------------------------------------------------------- drawing (see drawing.js)

  /** After any change of the motion, its options or the display: everything but the meshes. */
  rebuild() {
    this.drawing.rebuildMotion();
    this.drawing.rebuildControls();
  }

  /** After a change of the selection: the control poses, handles and gizmo. */
  rebuildControls() {
    this.drawing.rebuildControls();
  }

  /** After a change of the pointer's hover: the handles (and gizmo). */
  rebuildHandles() {
    this.drawing.rebuildHandles();
  }

  /** After a change of the gizmo mode or of the drag state. */
  rebuildGizmo() {
    this.drawing.rebuildGizmo();
  }

  /** After a change of model.anim (u or visible). */
  updateAnim() {
    this.drawing.updateAnim();
  }

  /** After a change of the object (view.object, view.scene, imported). */
  meshesChanged() {
    this.drawing.meshesChanged();
  }

  setImportedMesh(slot, mesh) {
    this.drawing.setImportedMesh(slot, mesh);
  }

  bodyPoints() {
    return this.drawing.bodyPoints();
  }

  // ---------------------------------------------------------------- picking (see picking.js)

  pickPose(pt) {
    return picking.pickPose(this, pt);
  }

  gizmoHit(pt) {
    return picking.gizmoHit(this, pt);
  }

  ray(pt) {
    return picking.ray(this, pt);
  }

  startDrag(part, pose, pt) {
    return picking.startGizmoDrag(this, part, pose, pt);
  }

  toPage(p) {
    return picking.toPage(this, p);
  }

  toCanvas(p) {
    return picking.toCanvas(this, p);
  }

  screenOfPose(k) {
    return picking.screenOfPose(this, k);
  }

  screenOfGizmo(part) {
    return picking.screenOfGizmo(this, part);
  }
}
