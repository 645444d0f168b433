// Small f64 vector / quaternion / matrix helpers for the page (plain arrays).
// Quaternions are [w, x, y, z] (the crate's convention); matrices are column-major Float32Array(16)
// or arrays of 16 numbers.

export const add = (a, b) => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
export const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
export const scale = (a, s) => [a[0] * s, a[1] * s, a[2] * s];
export const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
export const cross = (a, b) => [
  a[1] * b[2] - a[2] * b[1],
  a[2] * b[0] - a[0] * b[2],
  a[0] * b[1] - a[1] * b[0],
];
export const length = (a) => Math.hypot(a[0], a[1], a[2]);
export const normalize = (a) => {
  const l = length(a);
  return l > 0 ? scale(a, 1 / l) : [0, 0, 1];
};

/** Hamilton product a * b of [w, x, y, z] quaternions. */
export function qmul(a, b) {
  const [aw, ax, ay, az] = a;
  const [bw, bx, by, bz] = b;
  return [
    aw * bw - ax * bx - ay * by - az * bz,
    aw * bx + ax * bw + ay * bz - az * by,
    aw * by - ax * bz + ay * bw + az * bx,
    aw * bz + ax * by - ay * bx + az * bw,
  ];
}
export function qnormalize(q) {
  const l = Math.hypot(q[0], q[1], q[2], q[3]);
  return q.map((c) => c / l);
}
/** Rotation by `angle` radians about the unit `axis`. */
export function qaxis(axis, angle) {
  const s = Math.sin(angle / 2);
  return [Math.cos(angle / 2), axis[0] * s, axis[1] * s, axis[2] * s];
}
/** Rotates vector v by quaternion q. */
export function qrot(q, v) {
  const [w, x, y, z] = q;
  const u = [x, y, z];
  const t = scale(cross(u, v), 2);
  return add(add(v, scale(t, w)), cross(u, t));
}

/** Column-major 4x4 of the pose {origin, rotation}, with an optional uniform scale. */
export function poseMatrix(origin, q, s = 1, out = new Float32Array(16), o = 0) {
  const [w, x, y, z] = q;
  out[o + 0] = (1 - 2 * (y * y + z * z)) * s;
  out[o + 1] = 2 * (x * y + w * z) * s;
  out[o + 2] = 2 * (x * z - w * y) * s;
  out[o + 3] = 0;
  out[o + 4] = 2 * (x * y - w * z) * s;
  out[o + 5] = (1 - 2 * (x * x + z * z)) * s;
  out[o + 6] = 2 * (y * z + w * x) * s;
  out[o + 7] = 0;
  out[o + 8] = 2 * (x * z + w * y) * s;
  out[o + 9] = 2 * (y * z - w * x) * s;
  out[o + 10] = (1 - 2 * (x * x + y * y)) * s;
  out[o + 11] = 0;
  out[o + 12] = origin[0];
  out[o + 13] = origin[1];
  out[o + 14] = origin[2];
  out[o + 15] = 1;
  return out;
}

/** a * b for column-major 4x4 arrays. */
export function mmul(a, b) {
  const r = new Float64Array(16);
  for (let c = 0; c < 4; c++)
    for (let rr = 0; rr < 4; rr++) {
      let s = 0;
      for (let k = 0; k < 4; k++) s += a[k * 4 + rr] * b[c * 4 + k];
      r[c * 4 + rr] = s;
    }
  return r;
}

/** Right-handed look-at view matrix. */
export function lookAt(eye, target, up) {
  const f = normalize(sub(target, eye));
  const s = normalize(cross(f, up));
  const u = cross(s, f);
  return Float64Array.from([
    s[0], u[0], -f[0], 0,
    s[1], u[1], -f[1], 0,
    s[2], u[2], -f[2], 0,
    -dot(s, eye), -dot(u, eye), dot(f, eye), 1,
  ]);
}

/** Right-handed perspective projection with depth 0..1 (WebGPU convention). */
export function perspective(fovy, aspect, near, far) {
  const f = 1 / Math.tan(fovy / 2);
  const r = far / (near - far);
  return Float64Array.from([f / aspect, 0, 0, 0, 0, f, 0, 0, 0, 0, r, -1, 0, 0, r * near, 0]);
}

/** Transforms point p by column-major 4x4 m, returning clip coordinates [x, y, z, w]. */
export function transform4(m, p) {
  return [0, 1, 2, 3].map((r) => m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r]);
}

/** Closest distance from point p to segment ab in 2-D. */
export function segmentDistance2(p, a, b) {
  const dx = b[0] - a[0];
  const dy = b[1] - a[1];
  const l2 = dx * dx + dy * dy;
  let t = l2 > 0 ? ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / l2 : 0;
  t = Math.max(0, Math.min(1, t));
  return Math.hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy);
}

/** Intersection parameter of ray (o, d) with sphere (c, r), or null. */
export function raySphere(o, d, c, r) {
  const oc = sub(o, c);
  const b = dot(oc, d);
  const disc = b * b - (dot(oc, oc) - r * r);
  if (disc < 0) return null;
  const t = -b - Math.sqrt(disc);
  return t >= 0 ? t : null;
}

/** Intersection point of ray (o, d) with the plane through p with normal n, or null. */
export function rayPlane(o, d, p, n) {
  const den = dot(d, n);
  if (Math.abs(den) < 1e-9) return null;
  const t = dot(sub(p, o), n) / den;
  return t > 0 ? add(o, scale(d, t)) : null;
}

/** Parameter along the line (p, a) (unit a) of the point closest to the ray (o, d). */
export function lineRayParam(p, a, o, d) {
  const w = sub(p, o);
  const b = dot(a, d);
  const den = 1 - b * b;
  if (Math.abs(den) < 1e-9) return null;
  return (b * dot(d, w) - dot(a, w)) / den;
}

/** sRGB display colour (0..1) to linear. */
export const srgbToLinear = (c) => (c <= 0.04045 ? c / 12.92 : Math.pow((c + 0.055) / 1.055, 2.4));
/** '#rrggbb' to linear [r, g, b]. */
export function hexLinear(hex) {
  const n = parseInt(hex.slice(1), 16);
  return [(n >> 16) & 255, (n >> 8) & 255, n & 255].map((c) => srgbToLinear(c / 255));
}
