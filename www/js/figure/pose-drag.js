// Dragging a control pose with the gizmo or its handle: the steps that the playground's editor
// (editor/input.js) and the <screw-bender> element's edit tool (element/screw-bender.js) share.
// A drag is a plain object {part, drag, index, moved, session}: the gizmo part, the viewer's drag
// of that part (viewer.startDrag), the pose's index, whether it has moved, and the drawing's drag
// session (or null), which redraws only what the one pose changes. What each caller adds around
// these steps (the editor's undo history and autosave, the element's `change` event) stays there.

/**
 * Starts dragging pose `index` of `motion` by the gizmo `part` at the canvas point `pt`, and
 * captures the pointer of the event `e`. Returns the drag, or null when that part cannot be
 * dragged from there (then nothing changed). The caller stores it, then calls
 * viewer.rebuildGizmo() so that the dragged part is highlighted.
 */
export function beginPoseDrag(viewer, motion, index, part, pt, e) {
  const drag = viewer.startDrag(part, motion.pose(index), pt);
  if (!drag) return null;
  const d = { part, drag, index, moved: false, session: viewer.drawing.dragSession() };
  viewer.canvas.setPointerCapture?.(e.pointerId);
  return d;
}

/** The pose that the pointer at `pt` drags `d`'s pose to (null: none), snapping when `snap`. */
export function dragTarget(viewer, d, pt, snap) {
  return d.drag.move(viewer.ray(pt), pt, snap);
}

/**
 * Gives `pose` to the drag. With a drag session and the polyscrew hidden (it is rebuilt in full),
 * the pose goes into the session (validated there), and into `motion` only when `live`; without
 * one it goes into `motion`. Throws what the session or the motion refuses. Returns whether the
 * step is the fast one (then redraw with redrawPoseDrag; else rebuild the whole figure).
 */
export function setDragPose(motion, d, pose, { polyscrew = false, live = false } = {}) {
  const fast = !!d.session && !polyscrew;
  if (fast) d.session.setPose(d.index, Float64Array.from([...pose.origin, ...pose.rotation]));
  if (!fast || live) motion.setPose(d.index, pose);
  return fast;
}

/** Redraws after setDragPose: only what the pose changes (fast), else the whole figure. */
export function redrawPoseDrag(viewer, d, pose, fast) {
  if (fast) viewer.drawing.dragStep(d.session, d.index, pose);
  else viewer.rebuild();
}

/**
 * Hover: `state.hover` becomes the gizmo part under `pt` and `state.hoverPose` the pose handle
 * under it (-1: none); when either changes, the cursor and the highlighted handles follow.
 */
export function hoverPoseTool(viewer, state, pt) {
  const hov = viewer.gizmoHit(pt);
  const hp = hov ? -1 : viewer.pickPose(pt);
  if (hov !== state.hover || hp !== state.hoverPose) {
    state.hover = hov;
    state.hoverPose = hp;
    viewer.canvas.style.cursor = hov || hp >= 0 ? 'pointer' : 'grab';
    viewer.rebuildHandles();
    viewer.requestDraw();
  }
}
