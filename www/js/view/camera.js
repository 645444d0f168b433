// Orbit camera (z up): yaw/pitch around a target, distance; mouse, wheel and touch controls.
import { add, cross, lookAt, mmul, normalize, perspective, scale, sub } from '../math.js';

export class OrbitCamera {
  constructor() {
    this.target = [0, 0, 0];
    this.distance = 12;
    this.yaw = -Math.PI / 3; // around z, from +x
    this.pitch = 0.6; // elevation
    this.fovy = (38 * Math.PI) / 180;
    this.aspect = 1;
  }

  toJSON() {
    return { target: this.target, distance: this.distance, yaw: this.yaw, pitch: this.pitch };
  }

  load(s) {
    if (!s) return;
    const ok = (v) => typeof v === 'number' && Number.isFinite(v);
    if (Array.isArray(s.target) && s.target.length === 3 && s.target.every(ok)) this.target = [...s.target];
    if (ok(s.distance) && s.distance > 0) this.distance = s.distance;
    if (ok(s.yaw)) this.yaw = s.yaw;
    if (ok(s.pitch)) this.pitch = s.pitch;
  }

  get eye() {
    const cp = Math.cos(this.pitch);
    const dir = [cp * Math.cos(this.yaw), cp * Math.sin(this.yaw), Math.sin(this.pitch)];
    return add(this.target, scale(dir, this.distance));
  }

  get forward() {
    return normalize(sub(this.target, this.eye));
  }

  /** Camera right and up vectors (world). */
  basis() {
    const f = this.forward;
    const right = normalize(cross(f, [0, 0, 1]));
    return { right, up: cross(right, f), forward: f };
  }

  view() {
    return lookAt(this.eye, this.target, [0, 0, 1]);
  }

  proj() {
    const near = Math.max(this.distance * 0.01, 0.01);
    return perspective(this.fovy, this.aspect, near, this.distance * 50 + 100);
  }

  viewProj() {
    return mmul(this.proj(), this.view());
  }

  orbit(dx, dy) {
    this.yaw -= dx * 0.008;
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

  /** World ray through CSS pixel (x, y) of a w×h viewport: {o, d}. */
  ray(x, y, w, h) {
    const { right, up, forward } = this.basis();
    const t = Math.tan(this.fovy / 2);
    const nx = ((2 * x) / w - 1) * t * this.aspect;
    const ny = (1 - (2 * y) / h) * t;
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
