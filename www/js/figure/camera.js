// Orbit camera (z up): yaw/pitch around a target, distance; mouse, wheel and touch controls.
// Perspective or orthographic: the orthographic view shows, at every depth, what the
// perspective one shows in the plane of the target (same framing, zoom and pan).
import { add, cross, lookAt, mmul, normalize, perspective, scale, sub } from '../math.js';

/**
 * The named views (yaw around z from +x, pitch): front looks along +y (x right, z up), side
 * along −x (y right, z up), top down the −z axis (x right, y up), iso from (1, −1, 1).
 */
export const CAMERA_PRESETS = {
  front: { yaw: -Math.PI / 2, pitch: 0 },
  side: { yaw: 0, pitch: 0 },
  top: { yaw: -Math.PI / 2, pitch: Math.PI / 2 },
  iso: { yaw: -Math.PI / 4, pitch: Math.atan(Math.SQRT1_2) },
};

export class OrbitCamera {
  constructor() {
    this.target = [0, 0, 0];
    this.distance = 12;
    this.yaw = -Math.PI / 3; // around z, from +x
    this.pitch = 0.6; // elevation
    this.fovy = (38 * Math.PI) / 180;
    this.aspect = 1;
    /** Orthographic projection (true) or perspective (false). */
    this.ortho = false;
  }

  toJSON() {
    return { target: this.target, distance: this.distance, yaw: this.yaw, pitch: this.pitch, ortho: this.ortho };
  }

  load(s) {
    if (!s) return;
    const ok = (v) => typeof v === 'number' && Number.isFinite(v);
    if (Array.isArray(s.target) && s.target.length === 3 && s.target.every(ok)) this.target = [...s.target];
    if (ok(s.distance) && s.distance > 0) this.distance = s.distance;
    if (ok(s.yaw)) this.yaw = s.yaw;
    if (ok(s.pitch)) this.pitch = Math.max(-Math.PI / 2, Math.min(Math.PI / 2, s.pitch));
    if (typeof s.ortho === 'boolean') this.ortho = s.ortho;
  }

  /** Turns to the named view of CAMERA_PRESETS (target and distance kept); false when unknown. */
  preset(name) {
    const p = Object.hasOwn(CAMERA_PRESETS, name) ? CAMERA_PRESETS[name] : null;
    if (!p) return false;
    this.yaw = p.yaw;
    this.pitch = p.pitch;
    return true;
  }

  /**
   * Half the depth of the orthographic view around the target (scene units): deep enough for
   * the framed scene, shallow enough that the lines' depth bias (crates/screwbender-web/src/
   * render/line.wgsl) stays about as large as in perspective.
   */
  get orthoDepth() {
    return 4 * this.distance + 20;
  }

  /** Half the height of the view in the plane of the target (scene units). */
  get halfHeight() {
    return this.distance * Math.tan(this.fovy / 2);
  }

  get eye() {
    const cp = Math.cos(this.pitch);
    const dir = [cp * Math.cos(this.yaw), cp * Math.sin(this.yaw), Math.sin(this.pitch)];
    return add(this.target, scale(dir, this.distance));
  }

  get forward() {
    return normalize(sub(this.target, this.eye));
  }

  /** Camera right and up vectors (world); from the yaw alone, so a view straight down works. */
  basis() {
    const f = this.forward;
    const right = [-Math.sin(this.yaw), Math.cos(this.yaw), 0];
    return { right, up: cross(right, f), forward: f };
  }

  view() {
    return lookAt(this.eye, this.target, this.basis().up);
  }

  proj() {
    const far = this.distance * 50 + 100;
    if (this.ortho) {
      // Depth 0..1 over the slab of the target ± orthoDepth (what lies behind the eye of a
      // zoomed-in view stays visible, as it should orthographically).
      const h = this.halfHeight;
      const w = h * this.aspect;
      const s = this.orthoDepth;
      return Float64Array.from([1 / w, 0, 0, 0, 0, 1 / h, 0, 0, 0, 0, -1 / (2 * s), 0, 0, 0, (s - this.distance) / (2 * s), 1]);
    }
    const near = Math.max(this.distance * 0.01, 0.01);
    return perspective(this.fovy, this.aspect, near, far);
  }

  viewProj() {
    return mmul(this.proj(), this.view());
  }

  orbit(dx, dy) {
    this.yaw -= dx * 0.008;
    // A preset's view straight down may sit past the orbit's limit: it moves back inside.
    this.pitch = Math.max(-1.55, Math.min(1.55, this.pitch + dy * 0.008));
  }

  /** Pans by a screen displacement (CSS pixels) for a viewport of `height` CSS pixels. */
  pan(dx, dy, height) {
    const { right, up } = this.basis();
    const k = (2 * this.distance * Math.tan(this.fovy / 2)) / height;
    this.target = add(this.target, add(scale(right, -dx * k), scale(up, dy * k)));
  }

  zoom(factor) {
    this.distance = Math.max(0.2, Math.min(5000, this.distance * factor));
  }

  /**
   * World ray through CSS pixel (x, y) of a w×h viewport: {o, d}. Orthographic: parallel to
   * the view direction, from the pixel's point on the nearest plane the projection sees (hits
   * in front of `o` are then all the visible ones).
   */
  ray(x, y, w, h) {
    const { right, up, forward } = this.basis();
    const t = Math.tan(this.fovy / 2);
    const nx = ((2 * x) / w - 1) * t * this.aspect;
    const ny = (1 - (2 * y) / h) * t;
    if (this.ortho) {
      const side = add(scale(right, nx * this.distance), scale(up, ny * this.distance));
      return { o: add(add(this.eye, side), scale(forward, this.distance - this.orthoDepth)), d: forward };
    }
    return { o: this.eye, d: normalize(add(forward, add(scale(right, nx), scale(up, ny)))) };
  }

  /** Frames the axis-aligned box [lo, hi]. */
  frame(lo, hi) {
    this.target = scale(add(lo, hi), 0.5);
    const r = Math.max(0.5, Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]) / 2);
    const half = Math.min(this.fovy, this.fovy * this.aspect) / 2;
    this.distance = (r / Math.sin(half)) * 1.05;
  }
}
