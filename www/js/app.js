// The playground application: motion state, renderer feeding, interaction, persistence.
import init, { Motion, Renderer, DragSession, scenes as listScenes, limits } from '../pkg/screwbender.js';
import { OrbitCamera } from './camera.js';
import { poseMatrix, length, sub, add, scale, raySphere } from './math.js';
import {
  SLOT, LAYER, COLORS, INSTANCE, SEGMENT, MAX_MORPH_STROBE, instances, mix, Segments, poseOf, track, matricesOf,
  gridSegments,
} from './scene.js';
import { gizmoGeometry, hitGizmo, startDrag, gizmoPoint, project } from './gizmo.js';
import { History, encodeHash, decodeHash, loadSaved, save, SESSION_VERSION } from './state.js';
import { buildUi } from './ui.js';
import { Dock } from './dock.js';
import { bindDrop, download, IMPORT_SIZE } from './files.js';

/** The largest strobe count (instances of the object along the motion). */
export const MAX_STROBE = 20000;
/** Largest mesh file accepted by the page (the core also checks MAX_OBJ_BYTES / MAX_GLTF_BYTES). */
export const MAX_MESH_BYTES = 32 << 20;
/** Imported meshes up to this size are kept in the autosave and share links. */
const MAX_SAVED_MESH = 1 << 20;
/** Scale of the control-pose and animated objects relative to the strobe (avoids z-fighting). */
const CONTROL_SCALE = 1.01;
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

/** Named objects (mirrors named_shape in src/web/render/mod.rs) with body points to trace. */
const OBJECT_POINTS = {
  bar: [[0, 0, 0], [2, 0, 0]],
  block: [[0, 0, 0], [0.6, 0.3, 0.2]],
  cylinder: [[0, 0, 0], [0.4, 0, 0.8]],
  cone: [[0, 0, -0.7], [0, 0, 0.7]],
  sphere: [[0, 0, 0], [0.5, 0, 0]],
  star: [[0, 0, 0], [0, 0.8, 0]],
  pendulum: [[0, 0, 0], [0, 0, 4]],
  wedge: [[0, 0, 0], [1.2, 0, 0]],
  obj: [[0, 0, 0], [0.8, 0, 0]],
};

/** Body points of a scene Shape (origin and a characteristic far point). */
function shapePoints(shape) {
  switch (shape.kind) {
    case 'bar': return [[0, 0, 0], [shape.length, 0, 0]];
    case 'block': return [[0, 0, 0], [shape.size[0] / 2, shape.size[1] / 2, shape.base ? shape.size[2] : shape.size[2] / 2]];
    case 'cylinder': return [[0, 0, 0], [shape.radius, 0, shape.height / 2]];
    case 'cone': return [[0, 0, -shape.height / 2], [0, 0, shape.height / 2]];
    case 'sphere': return [[0, 0, 0], [shape.radius, 0, 0]];
    case 'starPrism': return [[0, 0, 0], [0, shape.outer, 0]];
    case 'pendulum': return [[0, 0, 0], [0, 0, shape.rod]];
    case 'wedge': return [[0, 0, 0], [shape.size[0], 0, 0]];
    case 'triangle': return [[0, 0, 0], shape.x, shape.y];
    case 'iBeam': return [[0, 0, 0], [shape.flange[0] / 2, 0, (shape.web + shape.flange[2]) / 2]];
    case 'molecule': return [[0, 0, 0], [shape.ring * 1.9, 0, 0]];
    default: return [[0, 0, 0]];
  }
}

export class App {
  constructor() {
    this.canvas = document.getElementById('view');
    this.banner = document.getElementById('banner');
    this.history = new History();
    this.camera = new OrbitCamera();
    this.selected = -1;
    this.mode = 'translate';
    this.hover = null;
    this.drag = null;
    this.dirty = true;
    this.frames = 0;
    this.stats = { updateMs: 0, frameMs: 0, renderMs: 0 };
    this.errors = [];
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
      showGrid: true,
      snap: false,
      /** The open analysis view ('' = dock closed). */
      dock: '',
      /** Control-pose times in seconds (the Timing view), or null for one second per span. */
      times: null,
    };
    this.anim = { playing: false, u: 0, speed: 1, loop: true, visible: false };
    /** The imported mesh: {kind: 'obj', data: text} or {kind: 'gltf', data: base64}. */
    this.imported = null;
  }

  // ---------------------------------------------------------------- startup

  async start() {
    await init();
    this.scenes = listScenes();
    this.limits = limits();
    const params = new URLSearchParams(location.search);
    const forceGl = params.get('backend') === 'webgl2';
    const hasGpu = !!navigator.gpu;
    const { w, h } = this.pixelSize();
    const noGraphics = (e) =>
      new Error(`This browser offers neither WebGPU nor WebGL2, so the playground cannot draw. (${e.message})`);
    try {
      this.renderer = await Renderer.create(this.canvas, !forceGl, w, h);
    } catch (e) {
      if (forceGl || !hasGpu) throw noGraphics(e);
      // A failed WebGPU start falls back to WebGL2 on a fresh canvas.
      this.replaceCanvas();
      try {
        this.renderer = await Renderer.create(this.canvas, false, w, h);
      } catch (e2) {
        throw noGraphics(e2);
      }
      this.showError(`WebGPU failed to start (${e.message}); using WebGL2.`, 'warn');
    }
    this.backend = this.renderer.backend;
    if (!forceGl && hasGpu && this.backend !== 'WebGPU') {
      this.showError('WebGPU is present but has no usable adapter; using WebGL2.', 'warn');
    }
    document.getElementById('backend').textContent =
      `${this.backend}${this.renderer.samples > 1 ? ` · MSAA ${this.renderer.samples}×` : ''}`;
    this.renderer.setMesh(SLOT.handle, 'unit-sphere', true);
    this.renderer.setMesh(SLOT.arrow, 'unit-cone', true);

    this.restoreInitial();
    this.ui = buildUi(this);
    this.dock = new Dock(this);
    if (this.view.dock) this.openView(this.view.dock);
    this.bindInput();
    bindDrop(this);
    new ResizeObserver(() => {
      this.sizeCache = null;
      this.requestDraw();
    }).observe(this.canvas);
    window.addEventListener('beforeunload', () => this.autosave());
    this.loop = this.loop.bind(this);
    requestAnimationFrame(this.loop);
    this.ready = true;
  }

  replaceCanvas() {
    const fresh = this.canvas.cloneNode(false);
    this.canvas.replaceWith(fresh);
    this.canvas = fresh;
  }

  /** Canvas size (physical and CSS pixels), measured once per frame (layout reads are slow). */
  pixelSize() {
    if (!this.sizeCache) this.sizeCache = this.measure();
    return this.sizeCache;
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

  /** Share link > autosave > default preset. */
  restoreInitial() {
    const hash = location.hash.match(/^#s=(.+)$/);
    if (hash) {
      try {
        this.applySession(decodeHash(hash[1]));
        history.replaceState(null, '', location.pathname + location.search);
        this.autosave();
        return;
      } catch (e) {
        this.showError(`The shared link could not be opened: ${e.message}`);
      }
    }
    const saved = loadSaved();
    if (saved) {
      try {
        this.applySession(saved);
        return;
      } catch (e) {
        this.showError(`The autosaved session could not be restored: ${e.message}`);
      }
    }
    this.loadPreset(DEFAULT_SCENE, false);
  }

  // ---------------------------------------------------------------- state

  /** The serializable session (what autosave, share links and undo store). */
  session(withCamera = true) {
    const s = {
      version: SESSION_VERSION,
      document: this.motion.toDocument(),
      options: this.motion.options(),
      view: { ...this.view },
      selected: this.selected,
      mode: this.mode,
      anim: { u: this.anim.u, speed: this.anim.speed, loop: this.anim.loop },
    };
    if (this.imported && this.imported.data.length <= MAX_SAVED_MESH) s.mesh = this.imported;
    if (withCamera) s.camera = this.camera.toJSON();
    return s;
  }

  /** Replaces the whole state by a session; throws (leaving everything as it was) if invalid. */
  applySession(s) {
    if (!s || typeof s !== 'object') throw new Error('not a session object');
    const motion = new Motion(s.document, s.options); // validates everything
    if (s.mesh) {
      this.setImportedMesh(SLOT.strobe, s.mesh); // validates the mesh
      this.imported = s.mesh;
    }
    this.motion?.free();
    this.motion = motion;
    const v = s.view ?? {};
    for (const k of Object.keys(this.view)) {
      // Undo and imports do not switch the open analysis view (only the initial restore does).
      if (k === 'dock' && this.dock) continue;
      if (k in v && typeof v[k] === typeof this.view[k]) this.view[k] = v[k];
    }
    this.view.strobe = Math.max(1, Math.min(MAX_STROBE, Math.round(this.view.strobe)));
    const t = this.view.times;
    if (t !== null && !(Array.isArray(t) && t.length <= 1e5 && t.every(Number.isFinite))) this.view.times = null;
    if (this.view.object === 'obj' && !this.imported) this.view.object = 'scene';
    this.selected = Number.isInteger(s.selected) && s.selected < motion.poseCount ? s.selected : -1;
    this.mode = s.mode === 'rotate' ? 'rotate' : 'translate';
    if (s.anim) {
      if (Number.isFinite(s.anim.u)) this.anim.u = s.anim.u;
      if (Number.isFinite(s.anim.speed)) this.anim.speed = s.anim.speed;
      if (typeof s.anim.loop === 'boolean') this.anim.loop = s.anim.loop;
    }
    if (s.camera) this.camera.load(s.camera);
    else this.frameAll();
    this.meshesChanged();
    this.changed(false);
  }

  /** A snapshot for undo (no camera: undo does not move the view). */
  snapshot() {
    return JSON.stringify(this.session(false));
  }

  /** Records the current state before an edit. */
  beginEdit() {
    this.history.push(this.snapshot());
  }

  /**
   * Runs `f` as one undoable edit; errors go to the banner and leave the state unchanged.
   * Edits with the same `coalesce` key less than a second apart (a slider being dragged) make
   * one undo step.
   */
  edit(f, coalesce = null) {
    const before = this.snapshot();
    try {
      const r = f();
      const now = performance.now();
      const merge = coalesce !== null && coalesce === this.lastEdit?.key && now - this.lastEdit.time < 1000;
      if (!merge) this.history.push(before);
      this.lastEdit = { key: coalesce, time: now };
      this.changed();
      return r;
    } catch (e) {
      this.showError(e.message);
      return undefined;
    }
  }

  undo() {
    const s = this.history.undo(this.snapshot());
    if (s) this.restoreSnapshot(s);
  }

  redo() {
    const s = this.history.redo(this.snapshot());
    if (s) this.restoreSnapshot(s);
  }

  restoreSnapshot(text) {
    const cam = this.camera.toJSON();
    this.applySession({ ...JSON.parse(text), camera: cam });
    this.ui?.refresh();
  }

  /** After any change of motion/options/view: rebuild GPU data, autosave, redraw. */
  changed(save = true) {
    this.rebuildMotion();
    this.rebuildControls();
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

  /** Opens analysis view `id` in the dock ('' or null closes it); returns its instance. */
  openView(id) {
    let inst = null;
    const wasOpen = !!this.dock.active;
    try {
      inst = this.dock.open(id || null);
      // The 3-D view changes size when the dock opens or closes (wide screens): re-frame.
      if (wasOpen !== !!this.dock.active) {
        this.foldPanelForDock(!!this.dock.active);
        this.sizeCache = null;
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

  autosave() {
    if (!this.motion) return;
    const err = save(this.session());
    if (err) this.showError(err, 'warn');
  }

  loadPreset(id, undoable = true) {
    const info = this.scenes.find((s) => s.id === id);
    if (!info) return this.showError(`unknown preset ${id}`);
    const apply = () => {
      const motion = Motion.fromScene(id);
      this.motion?.free();
      this.motion = motion;
      this.view.scene = id;
      this.view.object = 'scene';
      this.view.strobe = PRESET_STROBE[id] ?? DEFAULT_STROBE;
      // The editing scene (A3) starts with its top-left pose selected, ready to drag.
      this.selected = PRESELECT[id] ?? -1;
      this.anim.u = 0;
      this.meshesChanged();
      this.frameAll();
    };
    if (undoable) this.edit(apply);
    else {
      apply();
      this.changed();
    }
  }

  get sceneInfo() {
    return this.scenes.find((s) => s.id === this.view.scene) ?? this.scenes[0];
  }

  /** Body points whose trajectories are drawn. */
  bodyPoints() {
    if (this.view.object === 'scene') return shapePoints(this.sceneInfo.shape);
    return OBJECT_POINTS[this.view.object] ?? [[0, 0, 0]];
  }

  /** Uploads the object meshes for the current object choice. */
  meshesChanged() {
    const r = this.renderer;
    const name = this.view.object === 'scene' ? `scene:${this.view.scene}` : this.view.object;
    if (name === 'obj') {
      for (const slot of [SLOT.strobe, SLOT.control, SLOT.anim]) this.setImportedMesh(slot, this.imported);
    } else {
      for (const slot of [SLOT.strobe, SLOT.control, SLOT.anim]) r.setMesh(slot, name, false);
    }
    // Morph scene: a different shape at each control pose.
    const morph = this.view.object === 'scene' ? this.sceneInfo.morphShapes : [];
    this.morphCount = morph.length;
    for (let k = 0; k < 16; k++) {
      if (k < morph.length) r.setMesh(SLOT.morph + k, `morph:${this.view.scene}:${k}`, false);
      else if (this.morphSlots > k) r.setInstances(SLOT.morph + k, new Float32Array(0));
    }
    this.morphSlots = Math.max(this.morphSlots ?? 0, morph.length);
  }

  // ---------------------------------------------------------------- GPU data

  /** Refined motion → strobe instances, trajectories, polyscrew. */
  rebuildMotion() {
    const t0 = performance.now();
    const r = this.renderer;
    const m = this.motion;
    const v = this.view;
    const closed = m.closed;
    const strobeColor = (k, n) => mix(COLORS.strobeA, COLORS.strobeB, n > 1 ? k / (n - 1) : 0);
    if (v.showStrobe && !this.morphing) {
      r.setInstances(SLOT.strobe, instances(m.sampleMatrices(v.strobe), strobeColor));
    } else r.setInstances(SLOT.strobe, new Float32Array(0));
    this.rebuildMorphStrobe(strobeColor);

    const { dpr } = this.pixelSize();
    const seg = new Segments();
    if (v.showTrajectories) {
      const refined = m.subdivide();
      for (const p of this.bodyPoints()) seg.polyline(track(refined, p), closed, COLORS.trajectory, 2 * dpr, 0.92, 0.002);
    }
    r.setLines(LAYER.trajectories, seg.array(), false);

    const poly = new Segments();
    if (v.showPolyscrew) {
      // The unsmoothed polyscrew: the screw motions between control poses (level 0).
      const coarse = new Motion(m.toDocument(), { ...m.options(), levels: 0 });
      const count = Math.min(4096, 48 * m.poseCount);
      const arr = coarse.sample(count);
      coarse.free();
      for (const p of this.bodyPoints()) poly.polyline(track(arr, p), closed, COLORS.polyscrew, 2 * dpr, 0.9, 0.002);
    }
    r.setLines(LAYER.polyscrew, poly.array(), false);
    this.updateAnim();
    this.stats.updateMs = performance.now() - t0;
    this.requestDraw();
  }

  /** True when the object morphs between per-pose shapes (scene A8 with its own object). */
  get morphing() {
    return this.view.object === 'scene' && this.sceneInfo.morphShapes.length > 0;
  }

  /**
   * The morphing strobe (scene A8): one mesh slot per instance, each holding the Minkowski
   * combination of the control shapes at that instance's parameter (meshes depend only on the
   * parameter, so they are rebuilt only when the count or the cycle changes).
   */
  rebuildMorphStrobe(color) {
    const r = this.renderer;
    const m = this.motion;
    const n = this.morphing && this.view.showStrobe ? Math.min(this.view.strobe, MAX_MORPH_STROBE) : 0;
    const key = n ? `${this.view.scene}:${m.closed}:${m.poseCount}:${n}` : '';
    const [a, b] = m.domain();
    const us = Array.from({ length: n }, (_, k) => a + ((b - a) * k) / (m.closed ? n : Math.max(1, n - 1)));
    if (key !== this.morphKey) {
      us.forEach((u, k) => r.setMorphMesh(SLOT.morphStrobe + k, this.view.scene, m.closed, u));
      this.morphKey = key;
    }
    const mats = n ? m.sampleMatrices(n) : new Float32Array(0);
    for (let k = 0; k < Math.max(n, this.morphStrobeSlots ?? 0); k++) {
      const data = k < n ? instances(mats.subarray(k * 16, k * 16 + 16), () => color(k, n)) : new Float32Array(0);
      r.setInstances(SLOT.morphStrobe + k, data);
    }
    this.morphStrobeSlots = Math.max(n, this.morphStrobeSlots ?? 0);
  }

  /** Control poses: red objects, handles, triads, the control polygon. */
  rebuildControls(withGrid = true) {
    const r = this.renderer;
    const m = this.motion;
    const v = this.view;
    const poses = m.poses();
    const n = m.poseCount;
    // Slightly enlarged so the red control objects enclose the coinciding strobe instances
    // (no z-fighting where the scheme interpolates).
    const mats = matricesOf(poses, CONTROL_SCALE);
    const color = (k) => (k === this.selected ? COLORS.selected : COLORS.control);
    this.ctl = { poses: Float64Array.from(poses), control: null, triads: null, polygon: null };
    if (this.morphCount > 0) {
      r.setInstances(SLOT.control, new Float32Array(0));
      for (let k = 0; k < this.morphCount; k++) {
        const data = k < n && v.showControl ? instances(mats.subarray(k * 16, k * 16 + 16), () => color(k)) : new Float32Array(0);
        r.setInstances(SLOT.morph + k, data);
      }
    } else {
      this.ctl.control = v.showControl ? instances(mats, color) : new Float32Array(0);
      r.setInstances(SLOT.control, this.ctl.control);
    }
    this.rebuildHandles(poses);

    const { dpr } = this.pixelSize();
    const tri = new Segments();
    const sceneScale = this.sceneScale(poses);
    if (v.showTriads) {
      const L = sceneScale * 0.07;
      const mm = new Float32Array(16);
      for (let k = 0; k < n; k++) {
        const { origin, rotation } = poseOf(poses, k);
        poseMatrix(origin, rotation, 1, mm);
        [COLORS.x, COLORS.y, COLORS.z].forEach((c, a) => {
          const dir = [mm[a * 4], mm[a * 4 + 1], mm[a * 4 + 2]];
          tri.push(origin, add(origin, scale(dir, L)), c, 2.5 * dpr, 1, 0.01);
        });
      }
    }
    this.ctl.triads = tri.array();
    r.setLines(LAYER.triads, this.ctl.triads, false);
    const pg = new Segments();
    if (v.showPolygon) {
      const pts = [];
      for (let k = 0; k < n; k++) pts.push(poseOf(poses, k).origin);
      pg.polyline(pts, m.closed, COLORS.polygon, 1.3 * dpr, 0.8);
    }
    this.ctl.polygon = pg.array();
    r.setLines(LAYER.polygon, this.ctl.polygon, false);
    if (withGrid) {
      const { grid, axes } = gridSegments(sceneScale * 0.8 + 2, dpr);
      r.setLines(LAYER.grid, v.showGrid ? grid : new Float32Array(0), false);
      r.setLines(LAYER.axes, v.showGrid ? axes : new Float32Array(0), false);
    }
    this.requestDraw();
  }

  /**
   * Drag fast path: rewrites only what depends on control pose i in the cached control
   * instances, handle, triads and control polygon (rebuildControls fills the caches).
   */
  updateControlPose(i, pose) {
    const c = this.ctl;
    const n = this.motion.poseCount;
    if (!c || this.morphCount > 0 || c.poses.length !== n * 7) return this.rebuildControls(false);
    const r = this.renderer;
    c.poses.set([...pose.origin, ...pose.rotation], i * 7);
    if (c.control.length) {
      poseMatrix(pose.origin, pose.rotation, CONTROL_SCALE, c.control, i * INSTANCE);
      r.setInstances(SLOT.control, c.control);
    }
    if (this.handleData) {
      const s = this.handleRadius(pose.origin) * (i === this.selected ? 1.25 : 1);
      poseMatrix(pose.origin, [1, 0, 0, 0], s, this.handleData, i * INSTANCE);
      r.setInstances(SLOT.handle, this.handleData);
    }
    const setEnds = (data, k, a, b) => {
      data.set(a, k * SEGMENT);
      data.set(b, k * SEGMENT + 4);
    };
    if (c.triads.length) {
      const L = this.sceneScale(c.poses) * 0.07;
      const mm = poseMatrix(pose.origin, pose.rotation);
      for (let a = 0; a < 3; a++) {
        const dir = [mm[a * 4], mm[a * 4 + 1], mm[a * 4 + 2]];
        setEnds(c.triads, 3 * i + a, pose.origin, add(pose.origin, scale(dir, L)));
      }
      r.setLines(LAYER.triads, c.triads, false);
    }
    if (c.polygon.length) {
      const segs = c.polygon.length / SEGMENT;
      const o = (k) => poseOf(c.poses, ((k % n) + n) % n).origin;
      if (i < segs) setEnds(c.polygon, i, o(i), o(i + 1));
      const prev = (i - 1 + n) % n;
      if (prev < segs) setEnds(c.polygon, prev, o(prev), o(prev + 1));
      r.setLines(LAYER.polygon, c.polygon, false);
    }
    this.rebuildGizmo(c.poses);
  }

  /** Handle radius in world units at p (constant on screen). */
  handleRadius(p, eye = this.camera.eye) {
    return length(sub(eye, p)) * Math.tan(this.camera.fovy / 2) * 0.022;
  }

  rebuildHandles(poses = this.motion.poses()) {
    const n = poses.length / 7;
    const data = new Float32Array(n * INSTANCE);
    const eye = this.camera.eye;
    for (let k = 0; k < n; k++) {
      const { origin } = poseOf(poses, k);
      const s = this.handleRadius(origin, eye) * (k === this.selected ? 1.25 : 1);
      poseMatrix(origin, [1, 0, 0, 0], s, data, k * INSTANCE);
      const c = k === this.selected ? COLORS.selected : k === this.hoverPose ? COLORS.hover : COLORS.handle;
      data.set([...c, 1], k * INSTANCE + 16);
    }
    this.renderer.setInstances(SLOT.handle, data);
    this.handleData = data;
    this.rebuildGizmo(poses);
  }

  rebuildGizmo(poses) {
    const r = this.renderer;
    if (this.selected < 0 || this.selected >= this.motion.poseCount) {
      r.setLines(LAYER.gizmo, new Float32Array(0), true);
      r.setInstances(SLOT.arrow, new Float32Array(0));
      return;
    }
    const { origin } = poseOf(poses ?? this.motion.poses(), this.selected);
    const { dpr } = this.pixelSize();
    const g = gizmoGeometry(this.mode, origin, this.camera, this.drag?.part ?? this.hover, dpr);
    r.setLines(LAYER.gizmo, g.segments, true);
    r.setInstances(SLOT.arrow, g.cones);
  }

  updateAnim() {
    const [a, b] = this.motion.domain();
    const span = b - a;
    if (this.anim.u > b || this.anim.u < a) this.anim.u = a + ((((this.anim.u - a) % span) + span) % span);
    if (!this.anim.visible) {
      this.renderer.setInstances(SLOT.anim, new Float32Array(0));
      return;
    }
    const p = this.motion.poseAt(this.anim.u);
    // The morphing object changes shape as it moves.
    if (this.morphing) this.renderer.setMorphMesh(SLOT.anim, this.view.scene, this.motion.closed, this.anim.u);
    const mat = poseMatrix(p.origin, p.rotation, CONTROL_SCALE * CONTROL_SCALE);
    this.renderer.setInstances(SLOT.anim, instances(mat, () => COLORS.anim));
    this.ui?.setTime(this.anim.u, a, b);
  }

  /** Size of the scene (control polygon bounding box diagonal, at least 2). */
  sceneScale(poses) {
    const { lo, hi } = this.bounds(poses);
    return Math.max(2, length(sub(hi, lo)));
  }

  bounds(poses = this.motion.poses()) {
    const lo = [Infinity, Infinity, Infinity];
    const hi = [-Infinity, -Infinity, -Infinity];
    for (let k = 0; k < poses.length / 7; k++)
      for (let i = 0; i < 3; i++) {
        lo[i] = Math.min(lo[i], poses[k * 7 + i]);
        hi[i] = Math.max(hi[i], poses[k * 7 + i]);
      }
    return { lo, hi };
  }

  frameAll() {
    const { lo, hi } = this.bounds();
    const pad = 1.2;
    const { cssW, cssH } = this.pixelSize();
    this.camera.aspect = cssW / Math.max(1, cssH);
    this.camera.frame(lo.map((x) => x - pad), hi.map((x) => x + pad));
    this.cameraMoved();
  }

  cameraMoved() {
    if (this.motion) this.rebuildHandles();
    this.requestDraw();
  }

  // ---------------------------------------------------------------- frame loop

  requestDraw() {
    this.dirty = true;
  }

  loop(now) {
    requestAnimationFrame(this.loop);
    if (this.anim.playing) {
      const dt = this.lastNow ? Math.min(0.5, (now - this.lastNow) / 1000) : 0;
      const [a, b] = this.motion.domain();
      let u = this.anim.u + dt * this.anim.speed;
      if (u > b) {
        if (this.motion.closed || this.anim.loop) u = a + ((u - a) % (b - a));
        else {
          u = b;
          this.setPlaying(false);
        }
      }
      this.anim.u = u;
      this.updateAnim();
      this.dirty = true;
    }
    this.lastNow = now;
    if (this.dirty) this.draw();
  }

  draw() {
    const t0 = performance.now();
    this.sizeCache = this.measure();
    const { w, h, cssW, cssH } = this.sizeCache;
    this.renderer.resize(w, h);
    this.camera.aspect = cssW / Math.max(1, cssH);
    const vp = this.camera.viewProj();
    this.vp = vp;
    this.renderer.setCamera(Float32Array.from(vp), Float32Array.from(this.camera.eye));
    const t1 = performance.now();
    if (this.renderer.render()) this.dirty = false;
    const t2 = performance.now();
    this.stats.renderMs = t2 - t1;
    this.stats.frameMs = t2 - t0;
    this.frames++;
  }

  setPlaying(on) {
    this.anim.playing = on;
    this.anim.visible = true;
    this.lastNow = undefined;
    this.ui?.refresh();
  }

  // ---------------------------------------------------------------- editing

  select(k) {
    this.selected = k;
    this.rebuildControls();
    this.ui?.refresh();
  }

  setMode(mode) {
    this.mode = mode;
    this.rebuildGizmo();
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

  setJ(j) {
    const named = { 1: 'bspline', 0: 'fourpoint', 0.5: 'jarek' }[j];
    this.edit(() => this.motion.setOptions(named ? { scheme: named } : { scheme: 'j', j }), 'option:j');
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

  // ---------------------------------------------------------------- import / export

  importJson(text, fileName = 'JSON') {
    if (text.length > this.limits.maxDocumentBytes) {
      return this.showError(`${fileName} is ${text.length} bytes; the limit is ${this.limits.maxDocumentBytes} bytes. Nothing was changed.`);
    }
    let motion;
    try {
      const trimmed = text.trim();
      // A full session (from Export) or a plain motion document.
      // Invalid JSON falls through to the core's parser, whose message names line and column.
      let obj = null;
      try {
        obj = JSON.parse(trimmed);
      } catch {
        obj = null;
      }
      if (obj && obj.version === SESSION_VERSION && obj.document) {
        new Motion(obj.document, obj.options).free();
        this.edit(() => this.applySession({ ...obj, camera: undefined }));
        return true;
      }
      motion = Motion.fromJson(trimmed, this.motion.options());
    } catch (e) {
      this.showError(`Import failed, nothing was changed: ${fileName}: ${e.message}`);
      return false;
    }
    return this.replaceMotion(motion);
  }

  /** Imports a motion document (from importMotionFile); the subdivision options are kept. */
  importDocument(doc, fileName) {
    let motion;
    try {
      motion = new Motion(doc, this.motion.options());
    } catch (e) {
      this.showError(`Import failed, nothing was changed: ${fileName}: ${e.message}`);
      return false;
    }
    const ok = this.replaceMotion(motion);
    if (ok) this.ui?.toast(`${fileName}: ${motion.poseCount} control poses (${motion.closed ? 'cycle' : 'open'})`);
    return ok;
  }

  /** Replaces the motion by `motion` as one undoable edit (the view frames the new poses). */
  replaceMotion(motion) {
    this.edit(() => {
      this.motion.free();
      this.motion = motion;
      this.selected = -1;
      this.frameAll();
    });
    return true;
  }

  /**
   * Control-pose times in seconds for export and plots (null: one second per span): the timing
   * table's times while they match the pose count (an insert or delete returns to uniform).
   */
  times() {
    const t = this.view.times;
    const want = this.motion.poseCount + (this.motion.closed ? 1 : 0);
    return Array.isArray(t) && t.length === want ? t : null;
  }

  exportJson() {
    download(`${this.motion.name ?? this.view.scene ?? 'motion'}.json`, this.motion.toJson(), 'application/json');
  }

  /** Puts an imported mesh ({kind, data}) into a renderer slot; throws on bad data. */
  setImportedMesh(slot, mesh) {
    if (mesh.kind === 'gltf') {
      const bin = atob(mesh.data);
      this.renderer.setGltfMesh(slot, Uint8Array.from(bin, (c) => c.charCodeAt(0)), IMPORT_SIZE);
    } else this.renderer.setObjMesh(slot, mesh.data, IMPORT_SIZE);
  }

  /** Imports a mesh file: OBJ text or glTF (`.gltf` text / `.glb` bytes as a Uint8Array). */
  importMesh(kind, data, fileName = 'mesh', failure = null) {
    const size = typeof data === 'string' ? data.length : data.byteLength;
    if (size > MAX_MESH_BYTES) {
      this.showError(`The mesh file is over ${MAX_MESH_BYTES >> 20} MiB. Nothing was changed.`);
      return false;
    }
    let mesh;
    if (kind === 'gltf') {
      const bytes = typeof data === 'string' ? new TextEncoder().encode(data) : data;
      let bin = '';
      for (let i = 0; i < bytes.length; i += 0x8000) bin += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
      mesh = { kind: 'gltf', data: btoa(bin) };
    } else mesh = { kind: 'obj', data };
    try {
      // Validate into the animation slot first; on failure nothing changed.
      this.setImportedMesh(SLOT.anim, mesh);
    } catch (e) {
      this.meshesChanged();
      this.showError(failure ? `${failure}; read as a mesh: ${e.message}` : `Mesh import failed, nothing was changed: ${fileName}: ${e.message}`);
      return false;
    }
    this.edit(() => {
      this.imported = mesh;
      this.view.object = 'obj';
      this.meshesChanged();
    });
    if (mesh.data.length > MAX_SAVED_MESH) {
      this.showError('The mesh is too large to be autosaved or shared; it will be lost on reload.', 'warn');
    }
    return true;
  }

  importObj(text) {
    return this.importMesh('obj', text);
  }

  shareLink() {
    return `${location.origin}${location.pathname}${location.search}#s=${encodeHash(this.session())}`;
  }

  // ---------------------------------------------------------------- errors

  showError(message, level = 'error') {
    this.errors.push(message);
    const b = this.banner;
    b.querySelector('.msg').textContent = message;
    b.className = `banner ${level}`;
    b.hidden = false;
    clearTimeout(this.bannerTimer);
    if (level !== 'fatal') this.bannerTimer = setTimeout(() => (b.hidden = true), 9000);
  }

  // ---------------------------------------------------------------- input

  /** CSS-pixel position of a pointer event relative to the canvas. */
  local(e) {
    const r = this.canvas.getBoundingClientRect();
    return [e.clientX - r.left, e.clientY - r.top];
  }

  ray(pt) {
    const { cssW, cssH } = this.pixelSize();
    return this.camera.ray(pt[0], pt[1], cssW, cssH);
  }

  /** The control pose whose handle the ray hits (nearest), else -1. */
  pickPose(pt) {
    const { o, d } = this.ray(pt);
    const poses = this.motion.poses();
    let best = -1;
    let bestT = Infinity;
    for (let k = 0; k < poses.length / 7; k++) {
      const c = poseOf(poses, k).origin;
      // The hit radius is a little larger than the drawn handle, for easy grabbing.
      const t = raySphere(o, d, c, this.handleRadius(c) * 1.6);
      if (t !== null && t < bestT) {
        bestT = t;
        best = k;
      }
    }
    return best;
  }

  gizmoHit(pt) {
    if (this.selected < 0 || !this.vp) return null;
    const { cssW, cssH } = this.pixelSize();
    const { origin } = this.motion.pose(this.selected);
    return hitGizmo(this.mode, origin, this.camera, this.vp, cssW, cssH, pt);
  }

  beginPoseDrag(part, pt, e) {
    const pose = this.motion.pose(this.selected);
    const drag = startDrag(part, pose, this.camera, this.ray(pt), pt);
    if (!drag) return false;
    this.drag = { part, drag, index: this.selected, moved: false, before: this.snapshot(), session: this.dragSession() };
    this.canvas.setPointerCapture?.(e.pointerId);
    this.rebuildGizmo();
    return true;
  }

  /**
   * A DragSession (src/web/render/local_update.rs) mirroring the motion, so that drag steps
   * re-subdivide only the moved pose's influence window and refresh only the strobe instances
   * and trajectory segments that depend on it. Null when the polyscrew overlay (rebuilt in full)
   * is shown or the session cannot be built; then drags rebuild everything.
   */
  dragSession() {
    const v = this.view;
    // The morphing strobe has one slot per instance: drags rebuild it (its meshes are cached).
    if (this.morphing) return null;
    try {
      const { dpr } = this.pixelSize();
      const points = v.showTrajectories ? this.bodyPoints().flat() : [];
      return new DragSession(
        this.motion.poses(),
        this.motion.closed,
        this.motion.options(),
        v.showStrobe ? v.strobe : 0,
        Float32Array.from([...COLORS.strobeA, ...COLORS.strobeB]),
        Float64Array.from(points),
        Float32Array.from([...COLORS.trajectory, 0.92, 2 * dpr, 0.002]),
      );
    } catch (err) {
      this.showError(`live update unavailable: ${err.message}`, 'warn');
      return null;
    }
  }

  dragMove(pt, snapOn) {
    const d = this.drag;
    const pose = d.drag.move(this.ray(pt), pt, snapOn || this.view.snap);
    if (!pose) return;
    this.applyDragPose(d.index, pose);
  }

  /**
   * One drag step. With a drag session, the pose goes only into the session (validated there);
   * the Motion (the document) receives the final pose on release, so a step costs only the
   * local update. Without one, the Motion is updated and everything rebuilt.
   */
  applyDragPose(index, pose) {
    const d = this.drag;
    const t0 = performance.now();
    const fast = d.session && !this.view.showPolyscrew;
    try {
      if (fast) d.session.setPose(index, Float64Array.from([...pose.origin, ...pose.rotation]));
      // Views that follow drags read the Motion: give it the pose now, not only on release.
      if (!fast || this.dock?.wantsLive) this.motion.setPose(index, pose);
    } catch (err) {
      this.showError(err.message);
      return;
    }
    d.pose = pose;
    if (!d.moved) {
      this.history.push(d.before);
      d.moved = true;
    }
    if (fast) {
      d.pending = true;
      this.renderer.applyDrag(d.session, SLOT.strobe, LAYER.trajectories);
      if (this.anim.visible) {
        const p = d.session.poseAt(this.anim.u);
        this.renderer.setInstances(
          SLOT.anim,
          instances(poseMatrix([p[0], p[1], p[2]], [p[3], p[4], p[5], p[6]], CONTROL_SCALE * CONTROL_SCALE), () => COLORS.anim),
        );
      }
      this.updateControlPose(index, pose);
      this.requestDraw();
    } else {
      this.rebuildMotion();
      this.rebuildControls();
    }
    this.dock?.changed('drag');
    this.stats.dragMs = performance.now() - t0;
  }

  endDrag() {
    if (this.drag?.pending) this.motion.setPose(this.drag.index, this.drag.pose);
    if (this.drag?.moved) {
      this.rebuildMotion();
      this.rebuildControls();
      this.autosave();
      // Views that do not follow drags catch up now.
      this.dock?.changed('edit');
    }
    this.drag?.session?.free();
    this.drag = null;
    this.rebuildGizmo();
    this.requestDraw();
    this.ui?.refresh();
  }

  bindInput() {
    const c = this.canvas;
    const pointers = new Map();
    let gesture = null; // {kind: 'orbit'|'pan'|'pose'|'pinch', ...}
    c.addEventListener('contextmenu', (e) => e.preventDefault());
    c.addEventListener('pointerdown', (e) => {
      c.focus();
      const pt = this.local(e);
      pointers.set(e.pointerId, pt);
      if (pointers.size === 2) {
        // Second finger: cancel any drag, start pinch/pan.
        if (this.drag) this.endDrag();
        const [a, b] = [...pointers.values()];
        gesture = { kind: 'pinch', dist: Math.hypot(a[0] - b[0], a[1] - b[1]), mid: [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2] };
        return;
      }
      if (pointers.size > 2) return;
      const button = e.button;
      if (button === 0 && !e.altKey) {
        const part = this.gizmoHit(pt);
        if (part && this.beginPoseDrag(part, pt, e)) {
          gesture = { kind: 'pose' };
          return;
        }
        const k = this.pickPose(pt);
        if (k >= 0) {
          if (k !== this.selected) this.select(k);
          if (this.beginPoseDrag('view', pt, e)) gesture = { kind: 'pose' };
          return;
        }
      }
      const pan = button === 1 || button === 2 || e.shiftKey;
      gesture = { kind: pan ? 'pan' : 'orbit', last: pt, start: pt, moved: false };
      c.setPointerCapture?.(e.pointerId);
    });
    c.addEventListener('pointermove', (e) => {
      const pt = this.local(e);
      if (pointers.has(e.pointerId)) pointers.set(e.pointerId, pt);
      if (!gesture) {
        const hov = this.gizmoHit(pt);
        const hp = hov ? -1 : this.pickPose(pt);
        if (hov !== this.hover || hp !== this.hoverPose) {
          this.hover = hov;
          this.hoverPose = hp;
          c.style.cursor = hov || hp >= 0 ? 'pointer' : 'grab';
          this.rebuildHandles();
          this.requestDraw();
        }
        return;
      }
      if (gesture.kind === 'pose' && this.drag) {
        this.dragMove(pt, e.shiftKey);
      } else if (gesture.kind === 'pinch' && pointers.size >= 2) {
        const [a, b] = [...pointers.values()];
        const dist = Math.hypot(a[0] - b[0], a[1] - b[1]);
        const mid = [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2];
        if (dist > 0 && gesture.dist > 0) this.camera.zoom(gesture.dist / dist);
        this.camera.pan(mid[0] - gesture.mid[0], mid[1] - gesture.mid[1], this.pixelSize().cssH);
        gesture.dist = dist;
        gesture.mid = mid;
        this.cameraMoved();
      } else if (gesture.kind === 'orbit' || gesture.kind === 'pan') {
        const dx = pt[0] - gesture.last[0];
        const dy = pt[1] - gesture.last[1];
        gesture.last = pt;
        if (Math.hypot(pt[0] - gesture.start[0], pt[1] - gesture.start[1]) > 3) gesture.moved = true;
        if (gesture.kind === 'orbit') this.camera.orbit(dx, dy);
        else this.camera.pan(dx, dy, this.pixelSize().cssH);
        c.style.cursor = 'grabbing';
        this.cameraMoved();
      }
    });
    const up = (e) => {
      pointers.delete(e.pointerId);
      if (!gesture) return;
      if (gesture.kind === 'pose') this.endDrag();
      else if (gesture.kind === 'orbit' && !gesture.moved && e.type === 'pointerup') {
        // A click on empty space deselects.
        if (this.selected >= 0) this.select(-1);
      }
      c.style.cursor = 'grab';
      gesture = pointers.size === 0 ? null : gesture.kind === 'pinch' ? null : gesture;
    };
    c.addEventListener('pointerup', up);
    c.addEventListener('pointercancel', up);
    c.addEventListener(
      'wheel',
      (e) => {
        e.preventDefault();
        const k = e.deltaMode === 1 ? 0.05 : 0.0015;
        this.camera.zoom(Math.exp(e.deltaY * k));
        this.cameraMoved();
      },
      { passive: false },
    );
    window.addEventListener('keydown', (e) => this.onKey(e));
  }

  onKey(e) {
    const t = e.target;
    if (t && (t.tagName === 'INPUT' || t.tagName === 'TEXTAREA' || t.tagName === 'SELECT')) return;
    const k = e.key;
    const mod = e.ctrlKey || e.metaKey;
    let handled = true;
    if (mod && (k === 'z' || k === 'Z')) e.shiftKey ? this.redo() : this.undo();
    else if (mod && (k === 'y' || k === 'Y')) this.redo();
    else if (mod) handled = false;
    else if (k >= '0' && k <= '8') this.setOption('levels', Number(k));
    else if (k === 'b') this.setScheme('bspline');
    else if (k === 'f') this.setScheme('fourpoint');
    else if (k === 'j') this.setScheme('jarek');
    else if (k === 'w' || k === 'W') this.setMode('translate');
    else if (k === 'e' || k === 'E') this.setMode('rotate');
    else if (k === ' ') this.setPlaying(!this.anim.playing);
    else if (k === 'Delete' || k === 'Backspace') this.deleteSelected();
    else if (k === 'Insert' || k === 'i') this.insertAfterSelected();
    else if (k === 'a' || k === 'Home') this.frameAll();
    else if (k === 'ArrowRight' || k === 'Tab') this.select((this.selected + 1) % this.motion.poseCount);
    else if (k === 'ArrowLeft') this.select((this.selected - 1 + this.motion.poseCount) % this.motion.poseCount);
    else if (k === 'Escape') {
      if (!document.getElementById('help').hidden) this.ui.toggleHelp(false);
      else this.select(-1);
    } else if (k === '?' || k === 'h') this.ui.toggleHelp();
    else if (k === 'v' || k === 'V') document.getElementById('t-dock').click();
    else handled = false;
    if (handled) e.preventDefault();
  }

  // ---------------------------------------------------------------- inspection (tests)

  /** CSS-pixel position (page coordinates) of control pose k's handle. */
  screenOfPose(k) {
    const { origin } = this.motion.pose(k);
    return this.toPage(origin);
  }

  toPage(p) {
    const { cssW, cssH } = this.pixelSize();
    const s = project(this.camera.viewProj(), p, cssW, cssH);
    const r = this.canvas.getBoundingClientRect();
    return s ? { x: s[0] + r.left, y: s[1] + r.top } : null;
  }

  /** Page position of a point on a gizmo part of the selected pose. */
  screenOfGizmo(part) {
    if (this.selected < 0) return null;
    const { cssW, cssH } = this.pixelSize();
    const { origin } = this.motion.pose(this.selected);
    const p = gizmoPoint(this.mode, part, origin, this.camera, this.camera.viewProj(), cssW, cssH);
    const r = this.canvas.getBoundingClientRect();
    return p ? { x: p[0] + r.left, y: p[1] + r.top } : null;
  }
}
