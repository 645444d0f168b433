// Between the screen and the scene: pointer positions to rays, what a ray hits (a control-pose
// handle, a gizmo part), and back from scene points to page positions (which the inspection
// API and the analysis views' labels use). Plain functions of a Viewer.
import { raySphere } from '../math.js';
import { poseOf } from './slots.js';
import { hitGizmo, gizmoAxes, gizmoPoint, project, startDrag } from './gizmo.js';

/** CSS-pixel position of a pointer event relative to the canvas. */
export function local(viewer, e) {
  const r = viewer.canvas.getBoundingClientRect();
  return [e.clientX - r.left, e.clientY - r.top];
}

/**
 * The camera ray through canvas point `pt` (CSS pixels): from the eye in perspective, parallel
 * to the view direction in the orthographic projection (camera.js ray), so every pick below
 * works in both.
 */
export function ray(viewer, pt) {
  const { cssW, cssH } = viewer.pixelSize();
  return viewer.camera.ray(pt[0], pt[1], cssW, cssH);
}

/** The control pose whose handle the ray hits (nearest), else -1. */
export function pickPose(viewer, pt) {
  const { o, d } = ray(viewer, pt);
  const poses = viewer.model.motion.poses();
  let best = -1;
  let bestT = Infinity;
  for (let k = 0; k < poses.length / 7; k++) {
    const c = poseOf(poses, k).origin;
    // The hit radius is a little larger than the drawn handle, for easy grabbing.
    const t = raySphere(o, d, c, viewer.drawing.handleRadius(c) * 1.6);
    if (t !== null && t < bestT) {
      bestT = t;
      best = k;
    }
  }
  return best;
}

/** Every control pose whose handle the ray through `pt` hits, nearest first. */
export function pickPoses(viewer, pt) {
  const { o, d } = ray(viewer, pt);
  const poses = viewer.model.motion.poses();
  const hits = [];
  for (let k = 0; k < poses.length / 7; k++) {
    const c = poseOf(poses, k).origin;
    const t = raySphere(o, d, c, viewer.drawing.handleRadius(c) * 1.6);
    if (t !== null) hits.push({ k, t });
  }
  return hits.sort((a, b) => a.t - b.t || a.k - b.k).map((h) => h.k);
}

/** The gizmo part of the selected pose under `pt`, else null (the last drawn frame's camera). */
export function gizmoHit(viewer, pt) {
  const { motion, selected, mode } = viewer.model;
  if (selected < 0 || !viewer.vp) return null;
  const { cssW, cssH } = viewer.pixelSize();
  const { origin, rotation } = motion.pose(selected);
  return hitGizmo(mode, origin, viewer.camera, viewer.vp, cssW, cssH, pt, gizmoAxes(isLocal(viewer), rotation));
}

/** Whether the gizmo uses the pose's own axes (the model's `view.gizmoLocal`). */
function isLocal(viewer) {
  return !!viewer.model.view?.gizmoLocal;
}

/**
 * The drag of gizmo `part` ('view': in the view plane) of `pose`, grabbed at `pt`: an object
 * whose move(ray, pt, snapOn) returns the dragged pose, or null when the drag cannot start
 * (see gizmo.js).
 */
export function startGizmoDrag(viewer, part, pose, pt) {
  return startDrag(part, pose, viewer.camera, ray(viewer, pt), pt, isLocal(viewer));
}

/** Canvas position (CSS px, from its top left) of scene point p, or null behind the camera. */
export function toCanvas(viewer, p) {
  const { cssW, cssH } = viewer.pixelSize();
  const s = project(viewer.camera.viewProj(), p, cssW, cssH);
  return s ? { x: s[0], y: s[1] } : null;
}

/** Page position (CSS px) of scene point p, or null behind the camera. */
export function toPage(viewer, p) {
  const s = toCanvas(viewer, p);
  const r = viewer.canvas.getBoundingClientRect();
  return s ? { x: s.x + r.left, y: s.y + r.top } : null;
}

/** Page position of control pose k's handle. */
export function screenOfPose(viewer, k) {
  const { origin } = viewer.model.motion.pose(k);
  return toPage(viewer, origin);
}

/** Page position of a point on a gizmo part of the selected pose. */
export function screenOfGizmo(viewer, part) {
  const { motion, selected, mode } = viewer.model;
  if (selected < 0) return null;
  const { cssW, cssH } = viewer.pixelSize();
  const { origin, rotation } = motion.pose(selected);
  const p = gizmoPoint(mode, part, origin, viewer.camera, viewer.camera.viewProj(), cssW, cssH, gizmoAxes(isLocal(viewer), rotation));
  const r = viewer.canvas.getBoundingClientRect();
  return p ? { x: p[0] + r.left, y: p[1] + r.top } : null;
}
