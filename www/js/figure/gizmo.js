// The translate / rotate gizmo: drawing (segments + cone instances), screen-space hit testing,
// and the drag maths. World axes or the pose's own (local) axes, as three.js's TransformControls
// offers both; size constant on screen; in world axes snapping goes to the absolute grid and
// absolute angles, in local axes to whole steps along (and about) the pose's axes, since the
// world grid does not lie along them.
import {
  add, sub, scale, dot, cross, normalize, length, qaxis, qmul, qnormalize, rayPlane, lineRayParam,
  segmentDistance2, poseMatrix,
} from '../math.js';
import { COLORS, Segments, circle, INSTANCE } from './slots.js';

const AXES = [[1, 0, 0], [0, 1, 0], [0, 0, 1]];

/**
 * The gizmo's three axes: the world's, or with `local` the pose's own I, J, K (the columns of
 * its rotation; `rotation` is a unit quaternion [w, x, y, z]).
 */
export function gizmoAxes(local, rotation) {
  if (!local || !rotation) return AXES;
  const [w, x, y, z] = rotation;
  return [
    [1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)],
    [2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)],
    [2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)],
  ];
}
const AXIS_COLORS = [COLORS.x, COLORS.y, COLORS.z];
const NAMES = ['x', 'y', 'z'];
/** Snapping steps (Shift held): translation in scene units, rotation in radians. */
export const SNAP_TRANSLATE = 0.25;
export const SNAP_ROTATE = (15 * Math.PI) / 180;
/** Hit tolerance in CSS pixels. */
const HIT_PX = 9;

/** Gizmo size in world units at centre c: a constant fraction of the view height. */
export function gizmoSize(camera, c) {
  const d = length(sub(camera.eye, c));
  return d * Math.tan(camera.fovy / 2) * 0.32;
}

/** |cos| of the angle between the view direction and an axis above which the axis is hidden (it points at the eye). */
const AXIS_HIDE_COS = 0.98;
/** |cos| between the view direction and a plane's normal below which the plane is hidden (seen edge-on). */
const PLANE_HIDE_COS = 0.2;

/**
 * Parts of the gizmo as {part, kind, axis, points} for drawing and hit testing. Parts seen
 * edge-on (an arrow pointing at the eye, a square seen from its side) are left out: they would
 * be a dot or a line that grabs the wrong motion.
 */
function parts(mode, c, s, camera, axes = AXES) {
  const AXES = axes;
  const out = [];
  const view = normalize(sub(c, camera.eye));
  if (mode === 'translate') {
    AXES.forEach((a, i) => {
      if (Math.abs(dot(a, view)) > AXIS_HIDE_COS) return;
      out.push({ part: 'axis-' + NAMES[i], kind: 'axis', i, points: [add(c, scale(a, s * 0.18)), add(c, scale(a, s))] });
    });
    AXES.forEach((n, i) => {
      if (Math.abs(dot(n, view)) < PLANE_HIDE_COS) return;
      const u = AXES[(i + 1) % 3];
      const v = AXES[(i + 2) % 3];
      const p = (a, b) => add(c, add(scale(u, a * s), scale(v, b * s)));
      out.push({ part: 'plane-' + NAMES[i], kind: 'plane', i, points: [p(0.28, 0.28), p(0.5, 0.28), p(0.5, 0.5), p(0.28, 0.5)] });
    });
  } else {
    AXES.forEach((a, i) => out.push({ part: 'ring-' + NAMES[i], kind: 'ring', i, points: circle(c, a, s * 0.85, 72) }));
    out.push({ part: 'trackball', kind: 'trackball', i: -1, points: circle(c, camera.forward, s * 1.0, 72) });
  }
  return out;
}

/** Segments and arrow-head instances of the gizmo at pose centre c. */
export function gizmoGeometry(mode, c, camera, hover, dpr, axes = AXES) {
  const s = gizmoSize(camera, c);
  const seg = new Segments();
  const cones = [];
  for (const p of parts(mode, c, s, camera, axes)) {
    const hot = p.part === hover;
    const col = hot ? COLORS.hover : p.i >= 0 ? AXIS_COLORS[p.i] : [0.35, 0.37, 0.42];
    if (p.kind === 'axis') {
      seg.push(p.points[0], p.points[1], col, (hot ? 5 : 3.5) * dpr);
      cones.push({ at: p.points[1], axis: axes[p.i], col, r: s * 0.065, h: s * 0.2 });
    } else if (p.kind === 'plane') {
      seg.polyline(p.points, true, col, (hot ? 3.5 : 2.2) * dpr, 0.95);
      // Hatch the square so it reads as a surface.
      seg.push(p.points[0], p.points[2], col, 1.2 * dpr, 0.5);
    } else {
      seg.polyline(p.points, true, col, (hot ? 4.5 : p.kind === 'trackball' ? 1.6 : 3) * dpr, p.kind === 'trackball' ? 0.7 : 1);
    }
  }
  const inst = new Float32Array(cones.length * INSTANCE);
  cones.forEach((k, j) => {
    // Cone mesh: apex at +z, base at z = 0, radius 1: scale non-uniformly via basis.
    const z = k.axis;
    const x = Math.abs(z[2]) < 0.9 ? normalize(cross(z, [0, 0, 1])) : normalize(cross(z, [1, 0, 0]));
    const y = cross(z, x);
    const m = inst.subarray(j * INSTANCE, j * INSTANCE + 16);
    m.set([...scale(x, k.r), 0, ...scale(y, k.r), 0, ...scale(z, k.h), 0, ...k.at, 1]);
    inst.set([...k.col, 1], j * INSTANCE + 16);
  });
  return { segments: seg.array(), cones: inst };
}

/** Projects world p to CSS pixels. */
function project(vp, p, w, h) {
  const x = vp[0] * p[0] + vp[4] * p[1] + vp[8] * p[2] + vp[12];
  const y = vp[1] * p[0] + vp[5] * p[1] + vp[9] * p[2] + vp[13];
  const ww = vp[3] * p[0] + vp[7] * p[1] + vp[11] * p[2] + vp[15];
  if (ww <= 1e-6) return null;
  return [((x / ww + 1) * w) / 2, ((1 - y / ww) * h) / 2];
}

function inPolygon(pt, poly) {
  let inside = false;
  for (let i = 0, j = poly.length - 1; i < poly.length; j = i++) {
    const [xi, yi] = poly[i];
    const [xj, yj] = poly[j];
    if (yi > pt[1] !== yj > pt[1] && pt[0] < ((xj - xi) * (pt[1] - yi)) / (yj - yi) + xi) inside = !inside;
  }
  return inside;
}

/** The gizmo part under CSS pixel `pt`, or null. */
export function hitGizmo(mode, c, camera, vp, w, h, pt, axes = AXES) {
  const s = gizmoSize(camera, c);
  let best = null;
  let bestD = HIT_PX;
  let inside = null;
  for (const p of parts(mode, c, s, camera, axes)) {
    const sp = p.points.map((q) => project(vp, q, w, h));
    if (sp.some((q) => q === null)) continue;
    if (p.kind === 'plane') {
      if (inPolygon(pt, sp) && !best) inside = inside ?? p.part;
      continue;
    }
    const closed = p.kind !== 'axis';
    for (let k = 0; k + 1 < sp.length + (closed ? 1 : 0); k++) {
      const d = segmentDistance2(pt, sp[k], sp[(k + 1) % sp.length]);
      if (d < bestD) {
        bestD = d;
        best = p.part;
      }
    }
    if (p.kind === 'trackball' && !best && inPolygon(pt, sp)) inside = inside ?? 'trackball';
  }
  return best ?? inside;
}

/** A CSS-pixel point on a gizmo part (for tests): the tip region of an axis, a point of a ring. */
export function gizmoPoint(mode, part, c, camera, vp, w, h, axes = AXES) {
  const s = gizmoSize(camera, c);
  const p = parts(mode, c, s, camera, axes).find((q) => q.part === part);
  if (!p) return null;
  let world;
  if (p.kind === 'axis') world = add(p.points[0], scale(sub(p.points[1], p.points[0]), 0.7));
  else if (p.kind === 'plane') world = scale(add(p.points[0], p.points[2]), 0.5);
  else {
    // The ring point that is most visible (largest screen distance from the centre).
    const cs = project(vp, c, w, h);
    let bestP = null;
    let bestD = -1;
    for (const q of p.points) {
      const sq = project(vp, q, w, h);
      const d = Math.hypot(sq[0] - cs[0], sq[1] - cs[1]);
      if (d > bestD) {
        bestD = d;
        bestP = sq;
      }
    }
    return bestP;
  }
  return project(vp, world, w, h);
}

const snap = (x, step) => Math.round(x / step) * step;

/**
 * Starts a drag of `part` for the pose {origin, rotation}; returns an object whose
 * `move(ray, pt, snapOn)` gives the new pose, or null when the drag cannot start.
 */
export function startDrag(part, pose, camera, ray, pt, local = false) {
  const c0 = pose.origin;
  const q0 = pose.rotation;
  const AXES = gizmoAxes(local, q0);
  // In world axes snapping is absolute: a moved coordinate lands on the world grid (multiples of
  // SNAP_TRANSLATE), whatever it was when the drag started; coordinates the drag does not move
  // stay. In local axes the displacement along each of the pose's axes is a whole number of steps.
  const translate = (delta, snapOn) => {
    if (snapOn && local) {
      const moved = AXES.reduce((acc, a) => add(acc, scale(a, snap(dot(delta, a), SNAP_TRANSLATE))), [0, 0, 0]);
      return { origin: add(c0, moved), rotation: q0 };
    }
    return {
      origin: c0.map((x, k) => (snapOn && Math.abs(delta[k]) > 1e-12 ? snap(x + delta[k], SNAP_TRANSLATE) : x + delta[k])),
      rotation: q0,
    };
  };
  // A turn about a world axis snaps the pose's angle about that axis (its twist, the angle of
  // the rotation's component about the axis) to multiples of SNAP_ROTATE.
  const twist = (axis) => 2 * Math.atan2(dot(axis, [q0[1], q0[2], q0[3]]), q0[0]);
  const rotate = (axis, angle, snapOn, absolute = true) => {
    let a = angle;
    if (snapOn) a = absolute ? snap(twist(axis) + angle, SNAP_ROTATE) - twist(axis) : snap(angle, SNAP_ROTATE);
    return { origin: c0, rotation: qnormalize(qmul(qaxis(axis, a), q0)) };
  };
  const [kind, name] = part.split('-');
  const i = NAMES.indexOf(name);
  if (kind === 'axis') {
    const a = AXES[i];
    const t0 = lineRayParam(c0, a, ray.o, ray.d);
    if (t0 === null) return null;
    return {
      move(r, _pt, snapOn) {
        const t = lineRayParam(c0, a, r.o, r.d);
        return t === null ? null : translate(scale(a, t - t0), snapOn);
      },
    };
  }
  if (kind === 'plane' || kind === 'view') {
    const n = kind === 'plane' ? AXES[i] : camera.forward;
    const h0 = rayPlane(ray.o, ray.d, c0, n);
    if (!h0) return null;
    return {
      move(r, _pt, snapOn) {
        const h = rayPlane(r.o, r.d, c0, n);
        return h ? translate(sub(h, h0), snapOn) : null;
      },
    };
  }
  if (kind === 'ring') {
    const a = AXES[i];
    const edgeOn = Math.abs(dot(ray.d, a)) < 0.2;
    if (!edgeOn) {
      const h0 = rayPlane(ray.o, ray.d, c0, a);
      if (h0) {
        const v0 = sub(h0, c0);
        return {
          move(r, _pt, snapOn) {
            const h = rayPlane(r.o, r.d, c0, a);
            if (!h) return null;
            const v = sub(h, c0);
            const angle = Math.atan2(dot(a, cross(v0, v)), dot(v0, v));
            return rotate(a, angle, snapOn, !local);
          },
        };
      }
    }
    // Ring seen edge-on: the screen displacement along the view's right/up turns it.
    return {
      move(_r, p, snapOn) {
        const { right, up } = camera.basis();
        const tangent = normalize(cross(a, camera.forward));
        const d = [p[0] - pt[0], p[1] - pt[1]];
        const along = d[0] * dot(tangent, right) - d[1] * dot(tangent, up);
        return rotate(a, along * 0.012, snapOn, !local);
      },
    };
  }
  if (kind === 'trackball') {
    return {
      move(_r, p, snapOn) {
        const { right, up } = camera.basis();
        const d = [p[0] - pt[0], p[1] - pt[1]];
        const mag = Math.hypot(d[0], d[1]);
        if (mag < 1e-9) return { origin: c0, rotation: q0 };
        // Rotate about the screen axis perpendicular to the mouse motion.
        const axis = normalize(add(scale(up, d[0]), scale(right, d[1])));
        // A free turn has no world axis to count from: its angle snaps from the drag start.
        return rotate(axis, mag * 0.012, snapOn, false);
      },
    };
  }
  return null;
}

export { project, poseMatrix };
