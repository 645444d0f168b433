// What the renderer's buffers hold and how they are filled: its mesh slots and line layers, the
// layouts of an instance (matrix + colour) and a line segment, the palettes, and the builders of
// those typed arrays from poses (instances, segments, tracks, the grid).
import { add, hexLinear, poseMatrix, qrot, scale, cross, normalize, dot } from '../math.js';

/** Floats per mesh instance (matrix + RGBA) and per line segment (see crates/screwbender-web/src/render/gpu.rs). */
export const INSTANCE = 20;
export const SEGMENT = 12;

/** Mesh slots and line layers of the page. */
export const SLOT = {
  strobe: 0, control: 1, anim: 2, handle: 3, arrow: 4, morph: 10,
  // Analysis views (www/js/dock/): split/tweak ghosts, method overlays, morphing strobe.
  steps: 5, stepsGhost: 6, methods: 7, morphStrobe: 32,
};
/** Morphing strobe instances get one slot each (a different mesh per instance). */
export const MAX_MORPH_STROBE = 48;
export const LAYER = {
  grid: 0, axes: 1, trajectories: 2, polyscrew: 3, polygon: 4, triads: 5, gizmo: 6,
  // Analysis views: screw axes, split/tweak arrows, method overlays, frame-independence traces.
  screwAxes: 7, steps: 8, methods: 9, frame: 10,
};

export const COLORS = {
  strobeA: hexLinear('#46678c'),
  strobeB: hexLinear('#a7c0da'),
  control: hexLinear('#d1202f'),
  selected: hexLinear('#ff9d1c'),
  anim: hexLinear('#f5c542'),
  trajectory: hexLinear('#1f2433'),
  polyscrew: hexLinear('#e0602f'),
  polygon: hexLinear('#7d8597'),
  grid: hexLinear('#9aa3b2'),
  x: hexLinear('#e03c3c'),
  y: hexLinear('#3aa845'),
  z: hexLinear('#3a6fe0'),
  hover: hexLinear('#ffd400'),
  handle: hexLinear('#ffffff'),
};

/**
 * What changes on a dark background (the viewer's `dark`): the lines drawn in dark ink on the
 * light one turn light, the grid dimmer, so that each keeps its contrast.
 */
export const DARK_COLORS = {
  trajectory: hexLinear('#e9edf5'),
  polygon: hexLinear('#a3abba'),
  grid: hexLinear('#7d8699'),
  strobeA: hexLinear('#5a86b8'),
};

/** The background colours as displayed (sRGB components; the page's and the element's CSS use the same). */
export const BACKGROUND = {
  light: [0.91, 0.925, 0.945], // #e8ecf1
  dark: [0.106, 0.122, 0.153], // #1b1f27
};

/** The colours of a light (false) or dark (true) background: COLORS with DARK_COLORS over them. */
export function palette(dark) {
  return dark ? { ...COLORS, ...DARK_COLORS } : COLORS;
}

/** Interleaves `count` column-major matrices (16 floats each) with colours from colorAt(k). */
export function instances(matrices, colorAt, alpha = 1) {
  const n = matrices.length / 16;
  const out = new Float32Array(n * INSTANCE);
  for (let k = 0; k < n; k++) {
    out.set(matrices.subarray(k * 16, k * 16 + 16), k * INSTANCE);
    const c = colorAt(k, n);
    out[k * INSTANCE + 16] = c[0];
    out[k * INSTANCE + 17] = c[1];
    out[k * INSTANCE + 18] = c[2];
    out[k * INSTANCE + 19] = alpha;
  }
  return out;
}

/** Mixes two colours. */
export const mix = (a, b, t) => [0, 1, 2].map((i) => a[i] + (b[i] - a[i]) * t);

/** A growable list of segments. */
export class Segments {
  constructor() {
    this.data = new Float32Array(1024);
    this.n = 0;
  }
  push(a, b, color, width, alpha = 1, bias = 0) {
    if ((this.n + 1) * SEGMENT > this.data.length) {
      const d = new Float32Array(this.data.length * 2);
      d.set(this.data);
      this.data = d;
    }
    const o = this.n * SEGMENT;
    const d = this.data;
    d[o] = a[0]; d[o + 1] = a[1]; d[o + 2] = a[2]; d[o + 3] = width;
    d[o + 4] = b[0]; d[o + 5] = b[1]; d[o + 6] = b[2]; d[o + 7] = bias;
    d[o + 8] = color[0]; d[o + 9] = color[1]; d[o + 10] = color[2]; d[o + 11] = alpha;
    this.n++;
  }
  /** A polyline through `points` (arrays of 3), closed when `closed`. */
  polyline(points, closed, color, width, alpha = 1, bias = 0) {
    const m = points.length;
    for (let k = 0; k + 1 < m; k++) this.push(points[k], points[k + 1], color, width, alpha, bias);
    if (closed && m > 2) this.push(points[m - 1], points[0], color, width, alpha, bias);
  }
  array() {
    return this.data.subarray(0, this.n * SEGMENT);
  }
}

/** Pose k of a 7-per-pose Float64Array: {origin, rotation}. */
export function poseOf(arr, k) {
  const o = k * 7;
  return { origin: [arr[o], arr[o + 1], arr[o + 2]], rotation: [arr[o + 3], arr[o + 4], arr[o + 5], arr[o + 6]] };
}

/** World positions of the local point p at every pose of a 7-per-pose array. */
export function track(arr, p) {
  const n = arr.length / 7;
  const pts = new Array(n);
  for (let k = 0; k < n; k++) {
    const { origin, rotation } = poseOf(arr, k);
    pts[k] = add(origin, qrot(rotation, p));
  }
  return pts;
}

/** Matrices of the poses in a 7-per-pose array (optionally uniformly scaled). */
export function matricesOf(arr, s = 1) {
  const n = arr.length / 7;
  const out = new Float32Array(n * 16);
  for (let k = 0; k < n; k++) {
    const { origin, rotation } = poseOf(arr, k);
    poseMatrix(origin, rotation, s, out, k * 16);
  }
  return out;
}

/** The ground grid (z = 0) and world axes (`colors`: a palette()). */
export function gridSegments(extent, dpr, colors = COLORS) {
  const s = new Segments();
  const n = Math.max(5, Math.ceil(extent));
  for (let i = -n; i <= n; i++) {
    const major = i % 5 === 0;
    const a = major ? 0.55 : 0.28;
    const w = (major ? 1.3 : 1) * dpr;
    if (i !== 0) {
      s.push([i, -n, 0], [i, n, 0], colors.grid, w, a);
      s.push([-n, i, 0], [n, i, 0], colors.grid, w, a);
    } else {
      s.push([0, -n, 0], [0, 0, 0], colors.grid, w, a);
      s.push([-n, 0, 0], [0, 0, 0], colors.grid, w, a);
    }
  }
  const axes = new Segments();
  axes.push([0, 0, 0], [2, 0, 0], COLORS.x, 2.2 * dpr, 0.9);
  axes.push([0, 0, 0], [0, 2, 0], COLORS.y, 2.2 * dpr, 0.9);
  axes.push([0, 0, 0], [0, 0, 2], COLORS.z, 2.2 * dpr, 0.9);
  return { grid: s.array(), axes: axes.array() };
}

/** A circle of radius r around c in the plane normal to n. */
export function circle(c, n, r, steps = 64) {
  let u = Math.abs(n[2]) < 0.9 ? cross(n, [0, 0, 1]) : cross(n, [1, 0, 0]);
  u = normalize(u);
  const v = cross(n, u);
  const pts = [];
  for (let k = 0; k < steps; k++) {
    const a = (2 * Math.PI * k) / steps;
    pts.push(add(c, add(scale(u, r * Math.cos(a)), scale(v, r * Math.sin(a)))));
  }
  return pts;
}

export { dot };
