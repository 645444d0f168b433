// What the 3-D view draws, as renderer data: the strobe and trajectories of the smoothed motion,
// the control poses with their handles, axes and polygon, the gizmo, and the animated object.
//
// A Drawing belongs to a Viewer and reads the viewer's model afresh on every rebuild (see
// viewer.js for the model's fields), so whoever edits the model only has to say which part
// to rebuild. It keeps copies of the control-pose arrays it uploaded, so that a drag can
// rewrite one pose's entries instead of rebuilding them all.
import { bunnyUrl } from '../assets.js';
import { poseMatrix, length, sub, add, scale } from '../math.js';
import {
  SLOT, LAYER, COLORS, INSTANCE, SEGMENT, MAX_MORPH_STROBE, instances, mix, Segments, poseOf, track, matricesOf,
  gridSegments, palette,
} from './slots.js';
import { gizmoAxes, gizmoGeometry } from './gizmo.js';


/**
 * The trajectories' line style — colour, width (device pixels), alpha and depth bias — defined
 * once for the full rebuild and for the drag session, which draws the same lines in wasm.
 */
function trajectoryLine(dpr, colors = COLORS) {
  return { color: colors.trajectory, width: 2 * dpr, alpha: 0.92, bias: 0.002 };
}

/** Size of the cube an imported mesh is scaled to fit (scene units; exports use it as well). */
export const IMPORT_SIZE = 1.6;
/** The preset of the paper's bunny example (its mesh vendored by scripts/serve.d/30-bunny.sh, found
 * by assets.js) and the size it is scaled to (the wedge's longest side; the core's BUNNY_SIZE). */
export const BUNNY_PRESET = 'bunny6';
const BUNNY_SCENE = `scene:${BUNNY_PRESET}`;
const BUNNY_SIZE = 1.2;
/** @type {Promise<string> | null} */
let bunnyText = null;

/**
 * The Stanford bunny's OBJ text, fetched once for every user (the drawing, the file export,
 * which hands it to the core so that the file carries the mesh drawn); a failed fetch is
 * forgotten, so that the next call tries again.
 * @returns {Promise<string>}
 */
export function fetchBunny() {
  const url = bunnyUrl();
  bunnyText ??= (url ? fetch(url) : Promise.reject(new Error('this build carries no bunny mesh')))
    .then((res) => (res.ok ? res.text() : Promise.reject(new Error(`${res.status} ${res.statusText}`))))
    .catch((e) => {
      bunnyText = null;
      throw e;
    });
  return bunnyText;
}
/** Scale of the control-pose and animated objects relative to the strobe (avoids z-fighting). */
const CONTROL_SCALE = 1.01;

export class Drawing {
  /** `viewer`: the owning Viewer (renderer, camera, model, pixelSize, requestDraw, hooks). */
  constructor(viewer) {
    this.viewer = viewer;
  }

  /** The colours for the viewer's background (slots.js palette). */
  get colors() {
    return palette(!!this.viewer.dark);
  }

  get model() {
    return this.viewer.model;
  }

  get sceneInfo() {
    const { scenes } = this.viewer;
    return scenes.find((s) => s.id === this.model.view.scene) ?? scenes[0];
  }

  /**
   * Body points whose trajectories are drawn: the core's (a preset's `bodyPoints`, a named
   * object's `objectBodyPoints`); an imported mesh's origin and a point at half its fitted size.
   * @returns {number[][]}
   */
  bodyPoints() {
    const v = this.model.view;
    if (v.object === 'scene') return this.sceneInfo.bodyPoints;
    if (v.object === 'obj') return [[0, 0, 0], [IMPORT_SIZE / 2, 0, 0]];
    return this.viewer.wasm.objectBodyPoints(v.object) ?? [[0, 0, 0]];
  }

  /** True when the object morphs between per-pose shapes (scene A8 with its own object). */
  get morphing() {
    return this.model.view.object === 'scene' && this.sceneInfo.morphShapes.length > 0;
  }

  /** Puts an imported mesh ({kind, data}) into a renderer slot; throws on bad data. */
  setImportedMesh(slot, mesh) {
    const r = this.viewer.renderer;
    if (mesh.kind === 'gltf') {
      const bin = atob(mesh.data);
      r.setGltfMesh(slot, Uint8Array.from(bin, (c) => c.charCodeAt(0)), IMPORT_SIZE);
    } else r.setObjMesh(slot, mesh.data, IMPORT_SIZE);
  }

  /**
   * Fetches the vendored Stanford bunny once (the wedge stands in until it arrives, or for good
   * if it cannot be read), then uploads the meshes again.
   */
  loadBunny() {
    if (this.bunnyLoad) return;
    this.bunnyLoad = fetchBunny()
      .then((text) => {
        this.bunny = text;
        this.meshesChanged();
        this.viewer.requestDraw();
      })
      .catch((e) => this.viewer.warn(`the Stanford bunny could not be loaded (${e.message}); showing the wedge`));
  }

  /** Uploads the object meshes for the current object choice. */
  meshesChanged() {
    const r = this.viewer.renderer;
    const { view: v, imported } = this.model;
    const name = v.object === 'scene' ? `scene:${v.scene}` : v.object;
    if (name === 'obj') {
      for (const slot of [SLOT.strobe, SLOT.control, SLOT.anim]) this.setImportedMesh(slot, imported);
    } else if (name === BUNNY_SCENE && this.bunny) {
      // The paper's bunny example with the Stanford bunny (www/vendor/bunny.NOTICE).
      for (const slot of [SLOT.strobe, SLOT.control, SLOT.anim]) this.bunnyTriangles = r.setObjMesh(slot, this.bunny, BUNNY_SIZE);
    } else {
      if (name === BUNNY_SCENE) this.loadBunny();
      for (const slot of [SLOT.strobe, SLOT.control, SLOT.anim]) r.setMesh(slot, name, false);
    }
    // Morph scene: a different shape at each control pose.
    const morph = v.object === 'scene' ? this.sceneInfo.morphShapes : [];
    this.morphCount = morph.length;
    for (let k = 0; k < 16; k++) {
      if (k < morph.length) r.setMesh(SLOT.morph + k, `morph:${v.scene}:${k}`, false);
      else if (this.morphSlots > k) r.setInstances(SLOT.morph + k, new Float32Array(0));
    }
    this.morphSlots = Math.max(this.morphSlots ?? 0, morph.length);
  }

  /** Refined motion → strobe instances, trajectories, polyscrew. */
  rebuildMotion() {
    const t0 = performance.now();
    const r = this.viewer.renderer;
    const { motion: m, view: v } = this.model;
    const closed = m.closed;
    const colors = this.colors;
    const strobeColor = (k, n) => mix(colors.strobeA, colors.strobeB, n > 1 ? k / (n - 1) : 0);
    if (v.showStrobe && !this.morphing) {
      r.setInstances(SLOT.strobe, instances(m.sampleMatrices(v.strobe), strobeColor));
    } else r.setInstances(SLOT.strobe, new Float32Array(0));
    this.rebuildMorphStrobe(strobeColor);

    const { dpr } = this.viewer.pixelSize();
    const seg = new Segments();
    if (v.showTrajectories) {
      const refined = m.subdivide();
      const line = trajectoryLine(dpr, colors);
      for (const p of this.bodyPoints()) seg.polyline(track(refined, p), closed, line.color, line.width, line.alpha, line.bias);
    }
    r.setLines(LAYER.trajectories, seg.array(), false);

    const poly = new Segments();
    if (v.showPolyscrew) {
      // The unsmoothed polyscrew: the screw motions between control poses (level 0).
      const coarse = new this.viewer.wasm.Motion(m.toDocument(), { ...m.options(), levels: 0 });
      const count = Math.min(4096, 48 * m.poseCount);
      const arr = coarse.sample(count);
      coarse.free();
      for (const p of this.bodyPoints()) poly.polyline(track(arr, p), closed, COLORS.polyscrew, 2 * dpr, 0.9, 0.002);
    }
    r.setLines(LAYER.polyscrew, poly.array(), false);
    this.updateAnim();
    this.viewer.stats.updateMs = performance.now() - t0;
    this.viewer.requestDraw();
  }

  /**
   * The morphing strobe (scene A8): one mesh slot per instance, each holding the Minkowski
   * combination of the control shapes at that instance's parameter (meshes depend only on the
   * parameter, so they are rebuilt only when the count or the cycle changes).
   */
  rebuildMorphStrobe(color) {
    const r = this.viewer.renderer;
    const { motion: m, view: v } = this.model;
    const n = this.morphing && v.showStrobe ? Math.min(v.strobe, MAX_MORPH_STROBE) : 0;
    const key = n ? `${v.scene}:${m.closed}:${m.poseCount}:${n}` : '';
    const [a, b] = m.domain();
    const us = Array.from({ length: n }, (_, k) => a + ((b - a) * k) / (m.closed ? n : Math.max(1, n - 1)));
    if (key !== this.morphKey) {
      us.forEach((u, k) => r.setMorphMesh(SLOT.morphStrobe + k, v.scene, m.closed, u));
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
    const r = this.viewer.renderer;
    const { motion: m, view: v, selected } = this.model;
    const poses = m.poses();
    const n = m.poseCount;
    // Slightly enlarged so the red control objects enclose the coinciding strobe instances
    // (no z-fighting where the scheme interpolates).
    const mats = matricesOf(poses, CONTROL_SCALE);
    const color = (k) => (k === selected ? COLORS.selected : COLORS.control);
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

    const { dpr } = this.viewer.pixelSize();
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
      pg.polyline(pts, m.closed, this.colors.polygon, 1.3 * dpr, 0.8);
    }
    this.ctl.polygon = pg.array();
    r.setLines(LAYER.polygon, this.ctl.polygon, false);
    if (withGrid) {
      const { grid, axes } = gridSegments(sceneScale * 0.8 + 2, dpr, this.colors);
      r.setLines(LAYER.grid, v.showGrid ? grid : new Float32Array(0), false);
      r.setLines(LAYER.axes, v.showGrid ? axes : new Float32Array(0), false);
    }
    this.viewer.requestDraw();
  }

  /**
   * Drag fast path: rewrites only what depends on control pose i in the cached control
   * instances, handle, triads and control polygon (rebuildControls fills the caches).
   */
  updateControlPose(i, pose) {
    const c = this.ctl;
    const n = this.model.motion.poseCount;
    if (!c || this.morphCount > 0 || c.poses.length !== n * 7) return this.rebuildControls(false);
    const r = this.viewer.renderer;
    c.poses.set([...pose.origin, ...pose.rotation], i * 7);
    if (c.control.length) {
      poseMatrix(pose.origin, pose.rotation, CONTROL_SCALE, c.control, i * INSTANCE);
      r.setInstances(SLOT.control, c.control);
    }
    if (this.handleData) {
      const s = this.handleRadius(pose.origin) * (i === this.model.selected ? 1.25 : 1);
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

  /**
   * A DragSession (crates/screwbender-web/src/render/local_update.rs) mirroring the motion, so that drag steps
   * re-subdivide only the moved pose's influence window and refresh only the strobe instances
   * and trajectory segments that depend on it. Null when the session cannot be built (a
   * warning says so); then drags rebuild everything.
   */
  dragSession() {
    const { motion, view: v } = this.model;
    // The morphing strobe has one slot per instance: drags rebuild it (its meshes are cached).
    if (this.morphing) return null;
    try {
      const { dpr } = this.viewer.pixelSize();
      const points = v.showTrajectories ? this.bodyPoints().flat() : [];
      const line = trajectoryLine(dpr, this.colors);
      return new this.viewer.wasm.DragSession(
        motion,
        v.showStrobe ? v.strobe : 0,
        Float32Array.from([...this.colors.strobeA, ...this.colors.strobeB]),
        Float64Array.from(points),
        Float32Array.from([...line.color, line.alpha, line.width, line.bias]),
      );
    } catch (err) {
      this.viewer.warn(`live update unavailable: ${err.message}`);
      return null;
    }
  }

  /**
   * One drag step on the fast path: the drag session's partial uploads (strobe, trajectories),
   * the animated object at the session's pose, and control pose `index`'s own entries.
   */
  dragStep(session, index, pose) {
    const r = this.viewer.renderer;
    const { anim } = this.model;
    r.applyDrag(session, SLOT.strobe, LAYER.trajectories);
    if (anim.visible) {
      const p = session.poseAt(anim.u);
      r.setInstances(
        SLOT.anim,
        instances(poseMatrix([p[0], p[1], p[2]], [p[3], p[4], p[5], p[6]], CONTROL_SCALE * CONTROL_SCALE), () => COLORS.anim),
      );
    }
    this.updateControlPose(index, pose);
    this.viewer.requestDraw();
  }

  /** Handle radius in world units at p (constant on screen). */
  handleRadius(p, eye = this.viewer.camera.eye) {
    return length(sub(eye, p)) * Math.tan(this.viewer.camera.fovy / 2) * 0.022;
  }

  rebuildHandles(poses = this.model.motion.poses()) {
    const { selected, hoverPose } = this.model;
    const n = poses.length / 7;
    const data = new Float32Array(n * INSTANCE);
    const eye = this.viewer.camera.eye;
    for (let k = 0; k < n; k++) {
      const { origin } = poseOf(poses, k);
      const s = this.handleRadius(origin, eye) * (k === selected ? 1.25 : 1);
      poseMatrix(origin, [1, 0, 0, 0], s, data, k * INSTANCE);
      const c = k === selected ? COLORS.selected : k === hoverPose ? COLORS.hover : COLORS.handle;
      data.set([...c, 1], k * INSTANCE + 16);
    }
    this.viewer.renderer.setInstances(SLOT.handle, data);
    this.handleData = data;
    this.rebuildGizmo(poses);
  }

  rebuildGizmo(poses) {
    const r = this.viewer.renderer;
    const { motion, selected, mode, drag, hover, view } = this.model;
    if (selected < 0 || selected >= motion.poseCount) {
      r.setLines(LAYER.gizmo, new Float32Array(0), true);
      r.setInstances(SLOT.arrow, new Float32Array(0));
      return;
    }
    const { origin, rotation } = poseOf(poses ?? motion.poses(), selected);
    const { dpr } = this.viewer.pixelSize();
    const axes = gizmoAxes(!!view?.gizmoLocal, rotation);
    const g = gizmoGeometry(mode, origin, this.viewer.camera, drag?.part ?? hover, dpr, axes);
    r.setLines(LAYER.gizmo, g.segments, true);
    r.setInstances(SLOT.arrow, g.cones);
  }

  /** The animated object at the model's parameter (wrapped into the motion's domain). */
  updateAnim() {
    const r = this.viewer.renderer;
    const { motion, anim, view } = this.model;
    const [a, b] = motion.domain();
    const span = b - a;
    if (anim.u > b || anim.u < a) anim.u = a + ((((anim.u - a) % span) + span) % span);
    if (!anim.visible) {
      r.setInstances(SLOT.anim, new Float32Array(0));
      return;
    }
    const p = motion.poseAt(anim.u);
    // The morphing object changes shape as it moves.
    if (this.morphing) r.setMorphMesh(SLOT.anim, view.scene, motion.closed, anim.u);
    const mat = poseMatrix(p.origin, p.rotation, CONTROL_SCALE * CONTROL_SCALE);
    r.setInstances(SLOT.anim, instances(mat, () => COLORS.anim));
    this.viewer.onTime(anim.u, a, b);
  }

  /** Size of the scene (control polygon bounding box diagonal, at least 2). */
  sceneScale(poses) {
    const { lo, hi } = this.bounds(poses);
    return Math.max(2, length(sub(hi, lo)));
  }

  bounds(poses = this.model.motion.poses()) {
    const lo = [Infinity, Infinity, Infinity];
    const hi = [-Infinity, -Infinity, -Infinity];
    for (let k = 0; k < poses.length / 7; k++)
      for (let i = 0; i < 3; i++) {
        lo[i] = Math.min(lo[i], poses[k * 7 + i]);
        hi[i] = Math.max(hi[i], poses[k * 7 + i]);
      }
    return { lo, hi };
  }
}
